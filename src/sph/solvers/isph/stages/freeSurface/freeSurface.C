/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "freeSurface.H"
#include "openMPThreshold.H"
#include "usawOperators.H"
#include "kernelDispatch.H"
#include "ghostSurface.H"
#include "freeSurfaceRegion.H"
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


template<class Kernel>
Foam::vector2D Foam::SPH::freeSurface::mirroredGradOne
(
    const Kernel& K,
    const label i
) const
{
    // G{1} (37) over the fluid particles only and, by a wall, their mirror
    // images in the line half a spacing off the nearest segment (where the
    // fluid's volumes end: the first row sits dr off the wall), so that the
    // images continue the fluid's lattice. The walls' own terms (vertex
    // particles and grad gamma_as) count the air beyond a dry wall as
    // filled and tilt the normal of a particle by the wall away from it
    // (25 degrees at the corner of still water); with the wetted walls
    // only, still degrees on a lattice that does not meet the vertices row
    // for row. The images give still water's corner particle a vertical
    // normal on any wall discretisation (a right angle at the wall, the
    // contact the model has anyway). A particle closer than 0.6 dr to the
    // wall has no image (it would fall among the fluid).
    // r_ab' = r_ab + 2 (d_b - delta) n_w to b's image, with
    // d_b = d_a - r_ab.n_w b's distance from the wall's line
    const isphWork& w = work_;
    const label nFluid = w.nFluid;
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const vector2D* rij = w.nbrs.rij().cdata();
    const scalar* r = w.nbrs.r().cdata();
    const label nearest = ghostSurface::nearestSegment(w, i);
    const bool mirror = nearest >= 0;
    const vector2D nw
    (
        mirror
      ? w.usaw.segmentNormals()[w.usaw.segments()[nearest]]
      : vector2D::zero
    );
    const scalar da = mirror ? w.usaw.distances()[nearest] : 0;
    const scalar delta = w.surfaceDistance;
    const scalar support = K.support();
    vector2D sum(Zero);
    bool self = false;
    for (label k = off[i]; k < off[i + 1]; ++k)
    {
        const label b = nbr[k];
        if (b >= nFluid) continue;
        self = self || b == i;
        sum += w.V[b]*K.gradW(rij[k], r[k]);
        const scalar db = da - (rij[k] & nw);
        if (!mirror || db < 1.2*delta) continue;
        const vector2D rImage(rij[k] + 2*(db - delta)*nw);
        const scalar rI = mag(rImage);
        if (rI < support)
        {
            sum += w.V[b]*K.gradW(rImage, rI);
        }
    }
    const scalar rSelf = 2*(da - delta);
    if (mirror && !self && da >= 1.2*delta && rSelf < support)
    {
        sum += w.V[i]*K.gradW(rSelf*nw, rSelf);
    }
    return sum;
}


void Foam::SPH::freeSurface::setNormals()
{
    isphWork& w = work_;
    const label nFluid = w.nFluid;
    const label* seg = w.usaw.segments().cdata();
    const List<vector2D>& wallNormal = w.usaw.segmentNormals();
    label* surface = w.surface.data();
    dispatch(w.W, [&](const auto& K)
    {
        if (w.latticeMoment == tensor2D::zero)
        {
            w.latticeMoment =
                ghostSurface::latticeMoment(K, 2*w.surfaceDistance);
            Info<< "    ghost free surface: lattice moment "
                << w.latticeMoment << " (about -I)" << endl;
        }
        #pragma omp parallel for schedule(static) if(SPH::worthThreads(nFluid))
        for (label i = 0; i < nFluid; ++i)
        {
            gradOne_[i] = surface[i] ? mirroredGradOne(K, i) : vector2D::zero;
        }
    });

    // G{1} points into the fluid; below 0.05/dr (a particle with
    // neighbours all round, or a symmetric sheet) it gives no direction.
    // A normal within 5 degrees of the nearest wall's tangent is put on it
    // (water at rest meets a wall at right angles; a tilt of the corner
    // particle's normal by 2 degrees held its pressure 0.3 % low and drew
    // it into the wall)
    // A droplet (fewer than minDropletNeighbours fluid neighbours in the
    // support: a lone particle or a pair) has no surface to speak of: its
    // normal flips from step to step and its ghost row, fed by the 1/dt
    // sources of its partner's jumps, drove a pair sliding down the 2 mm
    // obstacle's wall to 260 m/s and the time step to collapse (t = 0.78
    // s). It keeps the paper's p = 0. (Below 4 rather than 2: the same
    // cure, 4 mm isolated 0.44 % instead of 0.11 % at t = 0.4 s)
    const scalar minGrad = 0.05/(2*w.surfaceDistance);
    const scalar snap = std::sin(degToRad(5.0));
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    w.surfaceNormal = Zero;
    for (label i = 0; i < nFluid; ++i)
    {
        const scalar g = mag(gradOne_[i]);
        if (!surface[i] || g <= minGrad) continue;
        label nFluidNbrs = 0;
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            nFluidNbrs += nbr[k] < nFluid && nbr[k] != i;
        }
        if (nFluidNbrs < minDropletNeighbours) continue;
        vector2D nI
        (
            ghostSurface::offWalls
            (
                w.usaw, w.parts.positions(), i, -gradOne_[i]/g,
                wallGap*w.surfaceDistance, minOpenPart
            )
        );
        if (nI == vector2D::zero)
        {
            surface[i] = 0;
            --nSurface_;
            continue;
        }
        const label nearest = ghostSurface::nearestSegment(w, i);
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
    markNearSurface
    (
        w.nbrs, nFluid, [=](const label b) { return surface[b] != 0; },
        0.5*w.W.support(), w.nearSurface
    );

    if (w.ghostSurface)
    {
        setNormals();
    }
}


// ************************************************************************* //
