/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "mlsInterpolation.H"
#include "kernelDispatch.H"
#include "DynamicList.H"

#include <Eigen/Dense>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

// A stencil that determines the fit gives a moment matrix whose reciprocal
// condition number is O(1e-3) or more in units of h (a quadratic fit in a
// corner); 1e-8 only rejects stencils where the fit is undetermined (too few
// particles, or all on a line)
const Foam::scalar Foam::SPH::mlsInterpolation::defaultMinRcond = 1e-8;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- The basis p(d) of size N: (1, dx, dy[, dx^2, dx dy, dy^2])
    template<int N>
    Eigen::Matrix<double, N, 1> basis(const Foam::vector2D& d)
    {
        Eigen::Matrix<double, N, 1> p;
        p(0) = 1;
        p(1) = d.x();
        p(2) = d.y();
        if constexpr (N == 6)
        {
            p(3) = d.x()*d.x();
            p(4) = d.x()*d.y();
            p(5) = d.y()*d.y();
        }
        return p;
    }

    //- MLS weights psi_b = w_b p(d_b).M^-1 e0 with a basis of size N;
    //- false (psi untouched) if the fit is undetermined
    template<int N>
    bool fitWeights
    (
        const Foam::UList<Foam::vector2D>& d,
        const Foam::UList<Foam::scalar>& w,
        const Foam::scalar minRcond,
        Foam::List<Foam::scalar>& psi
    )
    {
        if (d.size() < N)
        {
            return false;
        }

        using matrix = Eigen::Matrix<double, N, N>;
        matrix M(matrix::Zero());
        forAll(d, k)
        {
            const Eigen::Matrix<double, N, 1> p(basis<N>(d[k]));
            M += w[k]*p*p.transpose();
        }

        const Eigen::SelfAdjointEigenSolver<matrix> eig(M);
        const auto& lambda = eig.eigenvalues();         // ascending
        if (!(lambda(0) > minRcond*lambda(N - 1)))
        {
            return false;
        }

        // c = M^-1 e0 = V diag(1/lambda) V^T e0
        const matrix& V = eig.eigenvectors();
        const Eigen::Matrix<double, N, 1> c =
            V*(V.row(0).transpose().cwiseQuotient(lambda));

        psi.setSize(d.size());
        forAll(d, k)
        {
            psi[k] = w[k]*basis<N>(d[k]).dot(c);
        }
        return true;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::mlsInterpolation::mlsInterpolation
(
    const UList<vector2D>& positions,
    const scalarField& volumes,
    const labelUList& used,
    const kernel& W,
    const label order,
    const scalar minRcond
)
:
    W_(W),
    used_(used),
    points_(used.size()),
    volumes_(used.size()),
    order_(order),
    minRcond_(minRcond)
{
    if (order_ != 1 && order_ != 2)
    {
        FatalErrorInFunction
            << "MLS order " << order_ << ": 1 (linear) or 2 (quadratic)"
            << nl << exit(FatalError);
    }

    vector2D lo(vector2D::one*GREAT), hi(-vector2D::one*GREAT);
    forAll(used_, k)
    {
        points_[k] = positions[used_[k]];
        volumes_[k] = volumes[used_[k]];
        lo = min(lo, points_[k]);
        hi = max(hi, points_[k]);
    }
    if (used_.empty())
    {
        lo = hi = vector2D::zero;
    }

    // A box a support wider than the particles on every side, so that the
    // cells are never smaller than the search radius
    const vector2D margin(vector2D::one*W_.support());
    cells_.reset(new cellLinkedList(lo - margin, hi + margin, W_.support()));
    cells_->build(points_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::mlsInterpolation::stencils::count
(
    const pointStatus s
) const
{
    label n = 0;
    for (const pointStatus si : status)
    {
        n += (si == s);
    }
    return n;
}


Foam::SPH::mlsInterpolation::pointStatus
Foam::SPH::mlsInterpolation::fit
(
    const UList<vector2D>& d,
    const UList<scalar>& w,
    List<scalar>& psi
) const
{
    if (order_ == 2 && fitWeights<6>(d, w, minRcond_, psi))
    {
        return pointStatus::quadratic;
    }
    if (fitWeights<3>(d, w, minRcond_, psi))
    {
        return pointStatus::linear;
    }

    scalar sumW = 0;
    for (const scalar wk : w)
    {
        sumW += wk;
    }
    psi.setSize(w.size());
    forAll(w, k)
    {
        psi[k] = w[k]/sumW;
    }
    return pointStatus::constant;
}


Foam::SPH::mlsInterpolation::stencils
Foam::SPH::mlsInterpolation::weights(const UList<vector2D>& points) const
{
    stencils st;
    st.offsets.setSize(points.size() + 1);
    st.status.setSize(points.size());

    DynamicList<label> indices;
    DynamicList<scalar> weights;
    DynamicList<label> nbr;
    DynamicList<scalar> w;
    DynamicList<vector2D> d;
    List<scalar> psi;

    const scalar h = W_.h();

    dispatch(W_, [&](const auto& K)
    {
        forAll(points, i)
        {
            const vector2D& x = points[i];
            st.offsets[i] = indices.size();

            // Particles within the support: w_b = V_b W, d_b = (x_b - x)/h
            nbr.clear();
            w.clear();
            d.clear();
            cells_->forEachNeighbour
            (
                x,
                K.support(),
                [&](const label k, const vector2D& rxk, const scalar r2)
                {
                    const scalar wk = volumes_[k]*K.W(std::sqrt(r2));
                    if (wk > 0)
                    {
                        nbr.append(k);
                        w.append(wk);
                        d.append(-rxk/h);
                    }
                }
            );

            if (nbr.empty())
            {
                st.status[i] = pointStatus::none;
                continue;
            }

            st.status[i] = fit(d, w, psi);

            forAll(nbr, k)
            {
                indices.append(used_[nbr[k]]);
                weights.append(psi[k]);
            }
        }
    });

    st.offsets[points.size()] = indices.size();
    st.indices.transfer(indices);
    st.weights.transfer(weights);
    return st;
}


// ************************************************************************* //
