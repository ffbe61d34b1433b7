/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::particleGenerator: the fluid lattice, its range and its seeding.

\*---------------------------------------------------------------------------*/

#include "particleGenerator.H"

#include "Random.H"
#include "mathematicalConstants.H"
#include <cmath>

namespace
{
    using namespace Foam;

    //- The walls' signed distance at the nodes of one lattice row, in
    //- order. With closed walls it is 1-Lipschitz: a node within
    //- |d(q)| - dr/2 of the last node q searched is on q's side, and if
    //- that is the fluid's at least dr/2 from the walls (a margin for
    //- round-off): minDist, or -GREAT on the other side, with no search
    class rowDistance
    {
        const SPH::wallMesh& walls_;
        const bool lipschitz_;
        const scalar minDist_;
        const scalar margin_;
        bool haveQ_ = false;
        vector2D q_ = vector2D::zero;
        scalar dq_ = 0;

    public:

        rowDistance(const SPH::wallMesh& walls, scalar minDist, scalar margin)
        :
            walls_(walls),
            lipschitz_(walls.closedWalls()),
            minDist_(minDist),
            margin_(margin)
        {}

        scalar operator()(const vector2D& p)
        {
            if (lipschitz_ && haveQ_)
            {
                const scalar s = mag(walls_.domain().separation(p, q_));
                if (dq_ > 0 && dq_ - s >= minDist_ + margin_)
                {
                    return minDist_;
                }
                if (dq_ < 0 && dq_ + s < -minDist_ - margin_)
                {
                    return -GREAT;
                }
            }
            haveQ_ = true;
            q_ = p;
            dq_ = walls_.signedDistance(p);
            return dq_;
        }
    };
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector2D Foam::SPH::particleGenerator::latticeRange
(
    const vector2D& lo,
    const vector2D& hi,
    FixedList<label, 2>& first,
    FixedList<label, 2>& last
) const
{
    // USAW: the nodes k dr of the walls' corner, so that straight walls
    // through it carry the lattice's edge nodes (the vertex particles,
    // truncated fluid particles of 000_... section 2) and the first fluid
    // row lies dr from them. In a periodic direction the corner is the
    // periodic box's, walls or not
    const SPH::domain& dom = walls_->domain();
    vector2D wlo, whi;
    walls_->bounds(wlo, whi);
    for (direction d = 0; d < 2; ++d)
    {
        if (dom.periodic(d))
        {
            wlo[d] = dom.min()[d];
        }
    }
    const vector2D corner(wallModel_->latticeCorner(wlo, dr_));
    const vector2D origin(dict_.getOrDefault<vector2D>("latticeOrigin", corner));

    // Lattice indices covering [lo, hi]; in a periodic direction exactly
    // one period of them from the first node at or above min, so that the
    // lattice tiles [min, max) and continues across the seam
    for (direction d = 0; d < 2; ++d)
    {
        if (dom.periodic(d))
        {
            first[d] = label(std::ceil((dom.min()[d] - origin[d])/dr_ - 0.5 - 1e-6));
            last[d] = first[d] + label(std::round(dom.period()[d]/dr_)) - 1;
        }
        else
        {
            first[d] = label(std::floor((lo[d] - origin[d])/dr_ - 0.5));
            last[d] = label(std::ceil((hi[d] - origin[d])/dr_ - 0.5));
        }
    }
    return origin;
}


void Foam::SPH::particleGenerator::fluidOutsideError
(
    const label nOutside,
    const label nKept,
    const vector2D& example
) const
{
    vector2D lo, hi;
    fluidBox(lo, hi);
    FatalIOErrorInFunction(dict_.subDict("fluid"))
        << nOutside << " lattice points of the fluid regions lie outside"
        << " the walls (kept: " << nKept << "), e.g. " << example
        << " at distance " << -walls_->signedDistance(example)
        << " behind a wall (the walls' box is " << lo << " to " << hi
        << ")." << nl
        << "The fluid must lie on the fluid side of the walls"
        << " (check the regions and the walls' 'side'); sphMesh does"
        << " not clip it." << nl
        << exit(FatalIOError);
    std::abort();
}


void Foam::SPH::particleGenerator::seedFluid
(
    const std::function<bool(const vector2D&)>& isFluid,
    const vector2D& lo,
    const vector2D& hi,
    bool outsideIsError
)
{
    const SPH::domain& dom = walls_->domain();
    FixedList<label, 2> first, last;
    const vector2D origin(latticeRange(lo, hi, first, last));
    const label i0 = first[0], i1 = last[0];
    const label j0 = first[1], j1 = last[1];

    // dr/2 from the walls, less round-off
    const scalar minDist = 0.5*dr_*(1 - 1e-6);

    // The box the fluid must lie in, less dr/2 (sphMeshDict's regions)
    vector2D boxLo, boxHi;
    fluidBox(boxLo, boxHi);
    auto beyondBox = [&](const vector2D& p)
    {
        for (direction d = 0; d < 2; ++d)
        {
            if
            (
                !dom.periodic(d)
             && (p[d] < boxLo[d] - 0.5*dr_ || p[d] > boxHi[d] + 0.5*dr_)
            )
            {
                return true;
            }
        }
        return false;
    };

    DynamicList<vector2D> pts;
    label nOutside = 0;
    vector2D example(vector2D::zero);
    for (label j = j0; j <= j1; ++j)
    {
        rowDistance distance(*walls_, minDist, 1e-6*dr_);
        for (label i = i0; i <= i1; ++i)
        {
            // Wrapped: a node a rounding below min is min itself
            const vector2D p(dom.wrap(origin + dr_*vector2D(i + 0.5, j + 0.5)));
            if (!isFluid(p))
            {
                continue;
            }
            if (outsideIsError && beyondBox(p))
            {
                if (!nOutside++) example = p;
                continue;
            }
            const scalar d = distance(p);
            if (d >= minDist)
            {
                pts.append(p);
            }
            else if (d < -minDist && !nOutside++)
            {
                example = p;
            }
        }
    }

    if (outsideIsError && nOutside)
    {
        fluidOutsideError(nOutside, pts.size(), example);
    }
    fluid_.transfer(pts);
}


void Foam::SPH::particleGenerator::perturbFluid()
{
    scalar amplitude = 0;
    if (!dict_.readIfPresent("perturbation", amplitude))
    {
        return;
    }
    // Below dr/2: the lattice keeps dr/2 from the walls, so no particle
    // can be moved onto or through one
    if (!(amplitude >= 0 && amplitude <= 0.45))
    {
        FatalIOErrorInFunction(dict_.lookup("perturbation"))
            << "Entry 'perturbation' is " << amplitude << "; expected a"
            << " fraction of dr from 0 to 0.45 (the lattice is dr/2 from"
            << " the walls)" << nl << exit(FatalIOError);
    }
    Random rnd(dict_.getOrDefault<label>("perturbationSeed", 1));
    const SPH::domain& dom = walls_->domain();
    const scalar radius = amplitude*dr_;
    for (vector2D& p : fluid_)
    {
        // Uniform in the disc of that radius
        const scalar r = radius*std::sqrt(rnd.sample01<scalar>());
        const scalar theta = constant::mathematical::twoPi*rnd.sample01<scalar>();
        p = dom.wrap(p + r*vector2D(std::cos(theta), std::sin(theta)));
    }
    Info<< "Fluid particles moved at random by up to " << amplitude
        << " dr (perturbation)" << nl;
}


// ************************************************************************* //
