/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "usawOperators.H"
#include "openMPThreshold.H"

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace usaw
{
namespace detail
{

//- result_a = (sum_b pair(a, b, r_ab, |r_ab|) + sum_s wall(a, s, grad
//- gamma_as, d_as))/gamma_a for every target a: the shape shared by all
//- operators of (5)-(10), (15), (37). The terms are inlined lambdas.
//- ... and result_a = finish(a, that sum) where a result is made from it
template<class Type, class PairTerm, class WallTerm, class Result, class Finish>
inline void sumOverNeighboursAndWalls
(
    const neighbourList& nbrs,
    const usawWalls& walls,
    const PairTerm& pair,
    const WallTerm& wall,
    UList<Result>& result,
    const Finish& finish
)
{
    const label n = nbrs.size();
    const label* off = nbrs.offsets().cdata();
    const label* nbr = nbrs.indices().cdata();
    const vector2D* rab = nbrs.rij().cdata();
    const scalar* r = nbrs.r().cdata();

    const scalar* gamma = walls.gamma().cdata();
    const label* wOff = walls.offsets().cdata();
    const label* seg = walls.segments().cdata();
    const vector2D* gradGammaAs = walls.gradGammaAs().cdata();
    const scalar* dAs = walls.distances().cdata();

    Result* res = result.data();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label a = 0; a < n; ++a)
    {
        Type sum(Zero);
        for (label k = off[a]; k < off[a + 1]; ++k)
        {
            sum += pair(a, nbr[k], rab[k], r[k]);
        }
        for (label k = wOff[a]; k < wOff[a + 1]; ++k)
        {
            sum += wall(a, seg[k], gradGammaAs[k], dAs[k]);
        }
        res[a] = finish(a, sum/gamma[a]);
    }
}


template<class Type, class PairTerm, class WallTerm>
inline void sumOverNeighboursAndWalls
(
    const neighbourList& nbrs,
    const usawWalls& walls,
    const PairTerm& pair,
    const WallTerm& wall,
    UList<Type>& result
)
{
    sumOverNeighboursAndWalls<Type>
    (
        nbrs, walls, pair, wall, result,
        [](const label, const Type& sum) { return sum; }
    );
}


//- Mean of a per-particle field over the two vertex particles of each
//- segment: A_s (000_8c7cd3aabddcf18a.txt after eq. (43))
template<class Type>
inline Type segmentValue
(
    const labelPair* ends,
    const Type* A,
    const label s
)
{
    return 0.5*(A[ends[s].first()] + A[ends[s].second()]);
}


//- finish(a, G-_a{A}), eq. (8) for a scalar
template<class Kernel, class Result, class Finish>
inline void gradMinusThen
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& A,
    UList<Result>& result,
    const Finish& finish
)
{
    const scalar* v = V.cdata();
    const scalar* a = A.cdata();
    const labelPair* ends = walls.segmentParticles().cdata();

    sumOverNeighboursAndWalls<vector2D>
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D& rij, const scalar r)
        {
            return -v[j]*(a[i] - a[j])*K.gradW(rij, r);
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar)
        {
            return (a[i] - segmentValue(ends, a, s))*gradGammaAs;
        },
        result,
        finish
    );
}


//- finish(a, G-_a{u}), eq. (8) for a vector with grad w (x) u_ab:
//- OpenFOAM's (grad u)_ij = d u_j/d x_i
template<class Kernel, class Result, class Finish>
inline void vectorGradMinusThen
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const UList<vector2D>& u,
    UList<Result>& result,
    const Finish& finish
)
{
    const scalar* v = V.cdata();
    const vector2D* U = u.cdata();
    const labelPair* ends = walls.segmentParticles().cdata();

    sumOverNeighboursAndWalls<tensor2D>
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D& rij, const scalar r)
        {
            return -v[j]*(K.gradW(rij, r)*(U[i] - U[j]));
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar)
        {
            return gradGammaAs*(U[i] - segmentValue(ends, U, s));
        },
        result,
        finish
    );
}

//- 1/gamma_a [sum_b V_b (s_a A_a + A_b) grad w_ab - sum_s (s_a A_a + A_s)
//- grad gamma_as]: G+ (5) where s_a = 1, G- (8) where s_a = -1
template<class Kernel, class Sign>
inline void gradSigned
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& A,
    const Sign& sign,
    UList<vector2D>& result
)
{
    const scalar* v = V.cdata();
    const scalar* a = A.cdata();
    const labelPair* ends = walls.segmentParticles().cdata();

    sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D& rij, const scalar r)
        {
            return v[j]*(sign(i)*a[i] + a[j])*K.gradW(rij, r);
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar)
        {
            return -(sign(i)*a[i] + segmentValue(ends, a, s))*gradGammaAs;
        },
        result
    );
}

} // End namespace detail
} // End namespace usaw
} // End namespace SPH
} // End namespace Foam


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::usaw::gradPlus
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& A,
    UList<vector2D>& result
)
{
    checkOperands("gradPlus", nbrs, walls, V.size(), {A.size()}, -1, result.size());
    detail::gradSigned(K, nbrs, walls, V, A, [](const label) { return 1; }, result);
}


template<class Kernel>
void Foam::SPH::usaw::gradTensileControl
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& A,
    const UList<bool>& symmetric,
    UList<vector2D>& result
)
{
    checkOperands
    (
        "gradTensileControl", nbrs, walls, V.size(), {A.size()}, -1,
        result.size()
    );
    checkOperands
    (
        "gradTensileControl", nbrs, walls, V.size(), {}, -1,
        symmetric.size()
    );
    const bool* minus = symmetric.cdata();
    detail::gradSigned
    (
        K, nbrs, walls, V, A,
        [minus](const label a) { return minus[a] ? -1 : 1; },
        result
    );
}


template<class Kernel>
void Foam::SPH::usaw::gradMinus
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& A,
    UList<vector2D>& result
)
{
    checkOperands("gradMinus", nbrs, walls, V.size(), {A.size()}, -1, result.size());
    detail::gradMinusThen
    (
        K, nbrs, walls, V, A, result,
        [](const label, const vector2D& g) { return g; }
    );
}


template<class Kernel>
void Foam::SPH::usaw::gradMinus
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const UList<vector2D>& u,
    UList<tensor2D>& result
)
{
    checkOperands("gradMinus", nbrs, walls, V.size(), {u.size()}, -1, result.size());
    detail::vectorGradMinusThen
    (
        K, nbrs, walls, V, u, result,
        [](const label, const tensor2D& G) { return G; }
    );
}


template<class Kernel>
void Foam::SPH::usaw::renormalisation
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const UList<vector2D>& x,
    const scalar minDet,
    UList<tensor2D>& result
)
{
    checkOperands("renormalisation", nbrs, walls, V.size(), {x.size()}, -1, result.size());
    const scalar* v = V.cdata();
    const vector2D* X = x.cdata();
    const labelPair* ends = walls.segmentParticles().cdata();

    // G-{r} of eq. (8) with the minimum-image r_ab and r_as, inverted: a
    // particle whose neighbours do not span the plane keeps the identity
    detail::sumOverNeighboursAndWalls<tensor2D>
    (
        nbrs,
        walls,
        [&](const label, const label j, const vector2D& rij, const scalar r)
        {
            return -v[j]*(K.gradW(rij, r)*rij);
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar)
        {
            return gradGammaAs
               *walls.fromSegment(X[i], X[ends[s].first()], X[ends[s].second()]);
        },
        result,
        [minDet](const label, const tensor2D& M)
        {
            return det(M) > minDet ? inv(M) : tensor2D(tensor2D::I);
        }
    );
}


template<class Kernel>
void Foam::SPH::usaw::gradMinus
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const UList<tensor2D>& R,
    const scalarUList& A,
    UList<vector2D>& result
)
{
    checkOperands("gradMinus", nbrs, walls, V.size(), {A.size()}, -1, result.size());
    checkOperands("gradMinus", nbrs, walls, V.size(), {}, -1, R.size());
    const tensor2D* Ra = R.cdata();

    // R . eq. (8)
    detail::gradMinusThen
    (
        K, nbrs, walls, V, A, result,
        [Ra](const label i, const vector2D& g) { return Ra[i] & g; }
    );
}


template<class Kernel>
void Foam::SPH::usaw::div
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const UList<tensor2D>& R,
    const UList<vector2D>& u,
    UList<scalar>& result
)
{
    checkOperands("div", nbrs, walls, V.size(), {u.size()}, -1, result.size());
    checkOperands("div", nbrs, walls, V.size(), {}, -1, R.size());
    const tensor2D* Ra = R.cdata();

    // tr(R . G-{u})
    detail::vectorGradMinusThen
    (
        K, nbrs, walls, V, u, result,
        [Ra](const label i, const tensor2D& G) { return tr(Ra[i] & G); }
    );
}


template<class Kernel>
void Foam::SPH::usaw::div
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const UList<vector2D>& u,
    UList<scalar>& result
)
{
    checkOperands("div", nbrs, walls, V.size(), {u.size()}, -1, result.size());
    const scalar* v = V.cdata();
    const vector2D* U = u.cdata();
    const labelPair* ends = walls.segmentParticles().cdata();

    // Eq. (9)
    detail::sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D& rij, const scalar r)
        {
            return -v[j]*((U[i] - U[j]) & K.gradW(rij, r));
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar)
        {
            return (U[i] - detail::segmentValue(ends, U, s)) & gradGammaAs;
        },
        result
    );
}


template<class Kernel>
void Foam::SPH::usaw::divPosition
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    UList<scalar>& result
)
{
    checkOperands("divPosition", nbrs, walls, V.size(), {}, -1, result.size());
    const scalar* v = V.cdata();

    // Eq. (9) for A = r: r_ab from the neighbour list (minimum image) and
    // r_as . grad gamma_as = d_as |grad gamma_as|, since grad gamma_as is
    // along n_s and the segment's centre is the mean of its vertices
    detail::sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label, const label j, const vector2D& rij, const scalar r)
        {
            return -v[j]*(rij & K.gradW(rij, r));
        },
        [&](const label, const label, const vector2D& gradGammaAs, const scalar d)
        {
            return d*mag(gradGammaAs);
        },
        result
    );
}


// ************************************************************************* //
