/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "freeSurface.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::freeSurface::countSurface
(
    isphWork& work,
    const scalar divRMax
)
{
    scalarList divR(work.parts.size());
    dispatch(work.W, [&](const auto& K)
    {
        usaw::divPosition(K, work.nbrs, work.usaw, work.V, divR);
    });
    label n = 0;
    for (label i = 0; i < work.nFluid; ++i)
    {
        if (divR[i] <= divRMax) ++n;
    }
    return n;
}


void Foam::SPH::freeSurface::execute(const scalar dt)
{
    isphWork& w = work_;
    dispatch(w.W, [&](const auto& K)
    {
        usaw::divPosition(K, w.nbrs, w.usaw, w.V, divR_);
    });

    const label n = w.parts.size();
    const label nFluid = w.nFluid;
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const vector2D* rij = w.nbrs.rij().cdata();
    const scalar* r = w.nbrs.r().cdata();
    const vector2D* U = w.parts.field<vector2D>("U").cdata();
    label* surface = w.surface.data();

    // Section 3.2: D{r} <= 1.5 marks the free surface ...
    for (label i = 0; i < n; ++i)
    {
        surface[i] = divR_[i] <= divRMax_;
    }

    // ... except for a particle about to hit a wall and the vertex it
    // would hit, eq. (39): its distance to the vertex after a step at its
    // velocity below h q_max/8
    const scalar reach = w.W.support()/8;
    notSurface_ = 0;
    for (label i = 0; i < nFluid; ++i)
    {
        if (!surface[i]) continue;
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label v = nbr[k];
            if (v < nFluid || r[k] == 0) continue;
            if (r[k] + dt*(U[i] & rij[k])/r[k] < reach)
            {
                notSurface_[i] = 1;
                notSurface_[v] = 1;
            }
        }
    }
    nSurface_ = 0;
    for (label i = 0; i < n; ++i)
    {
        surface[i] = surface[i] && !notSurface_[i];
        if (i < nFluid && surface[i]) ++nSurface_;
    }

    // Particles within h q_max/2 of the free surface are not shifted
    // (section 3.2, after eq. (37))
    const scalar near = 0.5*w.W.support();
    label* nearSurface = w.nearSurface.data();
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < nFluid; ++i)
    {
        label isNear = surface[i];
        for (label k = off[i]; k < off[i + 1] && !isNear; ++k)
        {
            isNear = surface[nbr[k]] && r[k] < near;
        }
        nearSurface[i] = isNear;
    }
}


// ************************************************************************* //
