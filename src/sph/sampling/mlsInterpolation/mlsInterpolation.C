/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "mlsInterpolation.H"
#include "kernelDispatch.H"
#include "DynamicList.H"

#include <Eigen/Dense>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

// Three non-collinear particles give a moment matrix whose reciprocal
// condition number is O(1e-2) or more in units of h; 1e-8 only rejects
// (nearly) collinear stencils, where the slope across them is undefined
const Foam::scalar Foam::SPH::mlsInterpolation::defaultMinRcond = 1e-8;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::mlsInterpolation::mlsInterpolation
(
    const UList<vector2D>& positions,
    const scalarField& volumes,
    const labelUList& used,
    const kernel& W,
    const scalar minRcond
)
:
    W_(W),
    used_(used),
    points_(used.size()),
    volumes_(used.size()),
    minRcond_(minRcond)
{
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

            // Moment matrix M = sum_b w_b p_b p_b^T, p_b = (1, d_b)
            Eigen::Matrix3d M(Eigen::Matrix3d::Zero());
            forAll(nbr, k)
            {
                const Eigen::Vector3d p(1, d[k].x(), d[k].y());
                M += w[k]*p*p.transpose();
            }

            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
            eig.computeDirect(M);
            const Eigen::Vector3d& lambda = eig.eigenvalues();   // ascending
            const bool linear =
                nbr.size() >= 3 && lambda(0) > minRcond_*lambda(2);

            if (linear)
            {
                // c = M^-1 e0; psi_b = w_b p_b.c
                const Eigen::Matrix3d& V = eig.eigenvectors();
                const Eigen::Vector3d c =
                    V*(V.row(0).transpose().cwiseQuotient(lambda));
                forAll(nbr, k)
                {
                    indices.append(used_[nbr[k]]);
                    weights.append(w[k]*(c(0) + c(1)*d[k].x() + c(2)*d[k].y()));
                }
                st.status[i] = pointStatus::linear;
            }
            else
            {
                // Shepard: w_b/sum w
                scalar sumW = 0;
                for (const scalar wk : w) sumW += wk;
                forAll(nbr, k)
                {
                    indices.append(used_[nbr[k]]);
                    weights.append(w[k]/sumW);
                }
                st.status[i] = pointStatus::constant;
            }
        }
    });

    st.offsets[points.size()] = indices.size();
    st.indices.transfer(indices);
    st.weights.transfer(weights);
    return st;
}


// ************************************************************************* //
