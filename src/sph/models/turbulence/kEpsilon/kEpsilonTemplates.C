/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "kEpsilon.H"
#include "usawOperators.H"

#include <cmath>

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::kEpsilon::epsilonDiffusion
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const label nFluid,
    const scalarUList& D,
    const scalarUList& k,
    const scalarUList& eps,
    const scalarUList& noFlux,
    const scalar Cmu,
    const scalar sigmaEps,
    const scalar dr,
    UList<scalar>& result
)
{
    usaw::laplacian(K, nbrs, walls, V, D, eps, noFlux, result);

    // Appendix A: (A.2)-(A.4), the flux of the log layer at mid-distance
    const scalar* gamma = walls.gamma().cdata();
    const label* wOff = walls.offsets().cdata();
    const vector2D* gradGammaAs = walls.gradGammaAs().cdata();
    const scalar* dAs = walls.distances().cdata();
    const scalar c = 4*Cmu/sigmaEps;
    for (label i = 0; i < nFluid; ++i)
    {
        scalar sum = 0;
        for (label m = wOff[i]; m < wOff[i + 1]; ++m)
        {
            sum += mag(gradGammaAs[m])/max(dAs[m], dr);
        }
        result[i] += c*k[i]*k[i]*sum/gamma[i];
    }
}


template<class Kernel>
void Foam::SPH::kEpsilon::vertexValues
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const label nFluid,
    const labelListList& vertexSegments,
    const scalar Cmu,
    const scalar kappa,
    const scalar dr,
    UList<scalar>& k,
    UList<scalar>& eps
)
{
    const label n = nbrs.size();
    const label* off = nbrs.offsets().cdata();
    const label* nbr = nbrs.indices().cdata();
    const vector2D* rij = nbrs.rij().cdata();
    const scalar* r = nbrs.r().cdata();
    const List<vector2D>& normal = walls.segmentNormals();
    const scalar cWall = 4*std::pow(Cmu, 0.75)/kappa;

    for (label v = nFluid; v < n; ++v)
    {
        // (26), and (29) of each segment of v (at most two: a vertex
        // joins two segments), from v's fluid neighbours; the distance of
        // b from the segment's line is -r_vb.n_s, v being on it
        const labelList& segs = vertexSegments[v - nFluid];
        const label nSeg = min(segs.size(), label(2));
        scalar alpha = 0, sumK = 0;
        scalar sumEps[2] = {0, 0};
        for (label j = off[v]; j < off[v + 1]; ++j)
        {
            const label b = nbr[j];
            if (b >= nFluid) continue;
            const scalar Vw = V[b]*K.W(r[j]);
            alpha += Vw;
            sumK += Vw*k[b];
            for (label m = 0; m < nSeg; ++m)
            {
                const scalar d = max(-(rij[j] & normal[segs[m]]), dr);
                sumEps[m] += Vw*(eps[b] + cWall*k[b]*std::sqrt(k[b])/d);
            }
        }
        if (alpha > 0 && nSeg > 0)
        {
            k[v] = sumK/alpha;
            eps[v] = (sumEps[0] + sumEps[1])/(nSeg*alpha);
        }
    }
}


// ************************************************************************* //
