/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "freeSurface.H"
#include "usawOperators.H"
#include "kernelDispatch.H"
#include "ghostSurface.H"
#include "unitConversion.H"

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


void Foam::SPH::freeSurface::setNormals()
{
    // G{1} (37) over the fluid particles and the wetted walls only: the
    // dry wall above a free surface would count the air beyond it as
    // filled and tilt the normal of a particle by the wall away from it
    // (25 degrees at the corner of still water on a lattice). A vertex
    // particle is dry if it is flagged surface and no fluid particle is
    // within 1.25 dr (the row at the water line has one at dr); a segment
    // with one dry end counts half
    isphWork& w = work_;
    const label nFluid = w.nFluid;
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const vector2D* rij = w.nbrs.rij().cdata();
    const scalar* r = w.nbrs.r().cdata();
    const label* wOff = w.usaw.offsets().cdata();
    const label* seg = w.usaw.segments().cdata();
    const vector2D* gradGammaAs = w.usaw.gradGammaAs().cdata();
    const labelPair* ends = w.usaw.segmentParticles().cdata();
    const label* surface = w.surface.cdata();
    const label n = w.parts.size();
    const scalar wetReach = 1.25*2*w.surfaceDistance;
    wet_.setSize(n);
    for (label v = 0; v < n; ++v)
    {
        wet_[v] = v < nFluid || !surface[v];
        for (label k = off[v]; k < off[v + 1] && !wet_[v]; ++k)
        {
            wet_[v] = nbr[k] < nFluid && r[k] < wetReach;
        }
    }
    dispatch(w.W, [&](const auto& K)
    {
        if (w.latticeMoment == tensor2D::zero)
        {
            w.latticeMoment = ghostSurface::latticeMoment(K, 2*w.surfaceDistance);
            Info<< "    ghost free surface: lattice moment "
                << w.latticeMoment << " (about -I)" << endl;
        }
        for (label i = 0; i < nFluid; ++i)
        {
            if (!surface[i]) continue;
            vector2D sum(Zero);
            for (label k = off[i]; k < off[i + 1]; ++k)
            {
                const label b = nbr[k];
                if (wet_[b])
                {
                    sum += w.V[b]*K.gradW(rij[k], r[k]);
                }
            }
            for (label k = wOff[i]; k < wOff[i + 1]; ++k)
            {
                const labelPair& e = ends[seg[k]];
                const scalar wet =
                    0.5*(wet_[e.first()] + wet_[e.second()]);
                sum -= wet*gradGammaAs[k];
            }
            gradOne_[i] = sum;
        }
    });

    // G{1} points into the fluid; below 0.05/dr (a particle with
    // neighbours all round, or a symmetric sheet) it gives no direction.
    // A normal within 5 degrees of the nearest wall's tangent is put on it
    // (water at rest meets a wall at right angles; the lattice's G{1} by a
    // wall tilts it by 2 degrees, and the ghosts would then hold a corner
    // particle's pressure 0.3 % low and draw it into the wall)
    const scalar minGrad = 0.05/(2*w.surfaceDistance);
    const scalar* dAs = w.usaw.distances().cdata();
    const List<vector2D>& wallNormal = w.usaw.segmentNormals();
    const scalar snap = std::sin(degToRad(5.0));
    w.surfaceNormal = Zero;
    for (label i = 0; i < nFluid; ++i)
    {
        const scalar g = mag(gradOne_[i]);
        if (!surface[i] || g <= minGrad) continue;
        vector2D nI(-gradOne_[i]/g);
        label nearest = -1;
        for (label k = wOff[i]; k < wOff[i + 1]; ++k)
        {
            if (nearest < 0 || mag(dAs[k]) < mag(dAs[nearest])) nearest = k;
        }
        if (nearest >= 0)
        {
            const vector2D& nw = wallNormal[seg[nearest]];
            if (mag(nI & nw) < snap)
            {
                nI -= (nI & nw)*nw;
                nI /= mag(nI);
            }
        }
        w.surfaceNormal[i] = nI;
    }
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

    if (w.ghostSurface)
    {
        setNormals();
    }
}


// ************************************************************************* //
