/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "projection.H"
#include "usawOperators.H"
#include "kernelDispatch.H"
#include "ghostSurface.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Kernel>
Foam::vector2D Foam::SPH::projection::ghostGradient
(
    const Kernel& K,
    const isphWork& w,
    const scalarUList& p,
    const label a
)
{
    // Eq. (8) for p and r over the real neighbours and the walls
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const vector2D* rij = w.nbrs.rij().cdata();
    const scalar* r = w.nbrs.r().cdata();
    vector2D Gp(Zero);
    tensor2D Gr(Zero);
    for (label k = off[a]; k < off[a + 1]; ++k)
    {
        const label b = nbr[k];
        const vector2D gradW(K.gradW(rij[k], r[k]));
        Gp -= w.V[b]*(p[a] - p[b])*gradW;
        Gr -= w.V[b]*(gradW*rij[k]);
    }
    const label* wOff = w.usaw.offsets().cdata();
    const label* seg = w.usaw.segments().cdata();
    const vector2D* gradGammaAs = w.usaw.gradGammaAs().cdata();
    const labelPair* ends = w.usaw.segmentParticles().cdata();
    const vector2DField& x = w.parts.positions();
    for (label k = wOff[a]; k < wOff[a + 1]; ++k)
    {
        const labelPair& e = ends[seg[k]];
        Gp += (p[a] - 0.5*(p[e.first()] + p[e.second()]))*gradGammaAs[k];
        Gr +=
            gradGammaAs[k]
           *w.usaw.fromSegment(x[a], x[e.first()], x[e.second()]);
    }

    // The ghosts': -sum_v dr^2 (p_a - p_v) grad w_av with grad w_av =
    // -F r_va, and -sum_v dr^2 r_av (x) grad w_av = -T_g, both along n
    // only (t = n.T_g.n): the tangential gradient comes from the real
    // neighbours, and a normal tilted by theta changes the gradient of a
    // linear pressure at second order in theta (with T_g itself, at first:
    // still water by a wall disordered by the shifting drifted at 3e-4 m/s).
    // Where the real neighbours hardly span the surface's direction (the
    // tip of a jet: det below a tenth of the completed support's), T_g
    // itself: the ghosts' tangential part, without which the tip's
    // gradient is singular
    const tensor2D Tg(w.latticeMoment - ghostSurface::neighbourMoment(K, w, a));
    const vector2D& n = w.surfaceNormal[a];
    const scalar t = n & (Tg & n);
    const scalar pByDelta = p[a]/w.surfaceDistance;
    const tensor2D GrAlongN(Gr - t*(n*n));
    if (det(GrAlongN) > 0.1*det(Gr - Tg))
    {
        return inv(GrAlongN) & (Gp + pByDelta*t*n);
    }
    return inv(Gr - Tg) & (Gp + pByDelta*(Tg & n));
}



void Foam::SPH::projection::pressureGradient
(
    const isphWork& w,
    const bool renormalised,
    UList<vector2D>& gradP
)
{
    const scalarField& p = w.parts.field<scalar>("p");
    dispatch(w.W, [&](const auto& K)
    {
        if (renormalised)
        {
            usaw::gradMinus(K, w.nbrs, w.usaw, w.V, w.R, p, gradP);
            if (w.ghostSurface)
            {
                for (label i = 0; i < w.nFluid; ++i)
                {
                    if (w.surfaceNormal[i] != vector2D::zero)
                    {
                        gradP[i] = ghostGradient(K, w, p, i);
                    }
                }
            }
        }
        else
        {
            usaw::gradPlus(K, w.nbrs, w.usaw, w.V, p, gradP);
        }
    });
}


void Foam::SPH::projection::execute(const scalar dt)
{
    isphWork& w = work_;
    pressureGradient(w, renormalised_, gradP_);

    vector2D* U = w.parts.field<vector2D>("U").data();
    const vector2D g = w.g;
    const scalar rho0 = w.rho0;
    const label nFluid = w.nFluid;
    for (label i = 0; i < nFluid; ++i)
    {
        U[i] = w.Ustar[i] + dt*(g - gradP_[i]/rho0);
    }
}


// ************************************************************************* //
