/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "heatTransfer.H"
#include "openMPThreshold.H"
#include "usawOperators.H"

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::heatTransfer::vertexValues
(
    const Kernel& W,
    const neighbourList& nbrs,
    const usawWalls& usaw,
    const scalarUList& V,
    const label nFluid,
    const wallData& walls,
    UList<scalar>& T
)
{
    const label n = nbrs.size();
    const label* off = nbrs.offsets().cdata();
    const label* nbr = nbrs.indices().cdata();
    const vector2D* rij = nbrs.rij().cdata();
    const scalar* r = nbrs.r().cdata();
    const List<vector2D>& normal = usaw.segmentNormals();

    for (label v = nFluid; v < n; ++v)
    {
        const label iv = v - nFluid;
        if (walls.fixed[iv])
        {
            T[v] = walls.value[iv];
            continue;
        }
        // Eq. (32) around v for each of its segments (at most two): the
        // distance of b from the segment's line is -r_vb.n_s, v on it;
        // dT/dn (inward) = -G of the fixedGradient, 0 adiabatic. linear:
        // y_b = T_b - dT/dn d_b fitted as T_v + g_t s_b (s_b along the
        // segment) by weighted least squares, the sums' moments below
        const labelList& segs = walls.vertexSegments[iv];
        const label nSeg = min(segs.size(), label(2));
        vector2D n[2];
        scalar dTdn[2] = {0, 0};
        for (label m = 0; m < nSeg; ++m)
        {
            n[m] = normal[segs[m]];
            if (walls.kind[segs[m]] == fluxImposed)
            {
                dTdn[m] = -walls.gradient[segs[m]];
            }
        }
        scalar alpha = 0;
        scalar sumT[2] = {0, 0}, sumS[2] = {0, 0}, sumSS[2] = {0, 0};
        scalar sumTS[2] = {0, 0};
        for (label j = off[v]; j < off[v + 1]; ++j)
        {
            const label b = nbr[j];
            if (b >= nFluid) continue;
            const scalar Vw = V[b]*W.W(r[j]);
            alpha += Vw;
            for (label m = 0; m < nSeg; ++m)
            {
                const scalar yb = T[b] + dTdn[m]*(rij[j] & n[m]);
                const scalar sb = rij[j].x()*n[m].y() - rij[j].y()*n[m].x();
                sumT[m] += Vw*yb;
                sumS[m] += Vw*sb;
                sumSS[m] += Vw*sb*sb;
                sumTS[m] += Vw*yb*sb;
            }
        }
        if (alpha > 0 && nSeg > 0)
        {
            scalar Tv = 0;
            for (label m = 0; m < nSeg; ++m)
            {
                const scalar det = alpha*sumSS[m] - sqr(sumS[m]);
                Tv +=
                    walls.form == vertexForm::linear
                 && det > minFitDet*alpha*sumSS[m]
                  ? (sumSS[m]*sumT[m] - sumS[m]*sumTS[m])/det
                  : sumT[m]/alpha;
            }
            T[v] = Tv/nSeg;
        }
    }
}


template<class Kernel>
void Foam::SPH::heatTransfer::laplacian
(
    const Kernel& W,
    const neighbourList& nbrs,
    const usawWalls& usaw,
    const scalarUList& V,
    const label nFluid,
    const scalarUList& KE,
    const scalarUList& T,
    const wallData& walls,
    const scalar K,
    const scalar nu,
    const scalar drFloor,
    const turbulentWall& tw,
    UList<scalar>& result
)
{
    // The pair sums of (11): its wall term with zero data, the walls'
    // own terms (31)-(37) below, per particle-segment pair
    const scalarList noFlux(usaw.segmentParticles().size(), Zero);
    usaw::laplacian(W, nbrs, usaw, V, KE, T, noFlux, result);

    const scalar* gamma = usaw.gamma().cdata();
    const label* wOff = usaw.offsets().cdata();
    const label* seg = usaw.segments().cdata();
    const vector2D* gradGammaAs = usaw.gradGammaAs().cdata();
    const scalar* dAs = usaw.distances().cdata();
    const List<labelPair>& ends = usaw.segmentParticles();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(nFluid))
    for (label a = 0; a < nFluid; ++a)
    {
        const scalar ka = tw.k ? (*tw.k)[a] : 0;
        scalar sum = 0;
        for (label m = wOff[a]; m < wOff[a + 1]; ++m)
        {
            const label s = seg[m];
            scalar q = 0;
            switch (walls.kind[s])
            {
                case adiabatic:
                    break;
                case fluxImposed:
                    // (31): K dT/dn along the inward normal = -K G
                    q = -K*walls.gradient[s];
                    break;
                case isothermal:
                {
                    const scalar Ts =
                        0.5*(T[ends[s].first()] + T[ends[s].second()]);
                    q = isothermalFlux
                    (
                        T[a], Ts, dAs[m], drFloor, K, nu, ka, tw
                    );
                    break;
                }
            }
            sum += q*mag(gradGammaAs[m]);
        }
        result[a] -= 2*sum/gamma[a];
    }
}


// ************************************************************************* //
