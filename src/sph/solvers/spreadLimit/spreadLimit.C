/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "spreadLimit.H"
#include "checkedEntry.H"
#include "kernelDispatch.H"
#include "openMPThreshold.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Kernel>
Foam::scalar Foam::SPH::spreadLimit::fill
(
    const sphCloud& cloud,
    const Kernel& K,
    const scalar full,
    const label* surface,
    const label a
)
{
    const label nFluid = cloud.nFluid();
    scalar sum = 0;
    vector2D moment(0, 0);
    bool byWallOrSurface = false;
    cloud.cells().forEachNeighbour
    (
        cloud.parts().positions()[a],
        K.support(),
        [&](const label b, const vector2D& rab, const scalar r2)
        {
            // A particle the method holds at the free surface bounds room
            // the fluid has (air), even where the moment misses it: a film
            // between two voids, a void smaller than the kernel
            byWallOrSurface =
                byWallOrSurface || b >= nFluid || (surface && surface[b]);
            const scalar w = K.W(std::sqrt(r2));
            sum += w;
            moment += w*rab;
        }
    );
    // A surface within the kernel tilts its first moment (a lattice's is 0)
    return wholeKernelFill
    (
        sum, moment, byWallOrSurface, K.h(), sqr(cloud.dr())/full
    );
}


const Foam::label* Foam::SPH::spreadLimit::flags
(
    const sphCloud& cloud,
    const labelList* surface
)
{
    // Flags of another size (particles added or removed since the method
    // set them) say nothing of these particles
    return
        surface && surface->size() == cloud.parts().size()
      ? surface->cdata()
      : nullptr;
}


Foam::scalar Foam::SPH::spreadLimit::meanFill
(
    const sphCloud& cloud,
    const labelList* surfaceFlags,
    label& nWhole
)
{
    const label nFluid = cloud.nFluid();
    const scalar full = cloud.W().latticeSum();
    const label* surface = flags(cloud, surfaceFlags);
    scalar total = 0;
    label n = 0;
    dispatch(cloud.W(), [&](const auto& K)
    {
        #pragma omp parallel for schedule(static) reduction(+:total, n) \
            if(SPH::worthThreads(nFluid))
        for (label a = 0; a < nFluid; ++a)
        {
            const scalar f = fill(cloud, K, full, surface, a);
            if (f >= 0)
            {
                total += f;
                ++n;
            }
        }
    });
    nWhole = n;
    return n > 0 ? total/n : -1;
}


Foam::label Foam::SPH::spreadLimit::leastFilled(const sphCloud& cloud) const
{
    const scalar full = cloud.W().latticeSum();
    const label* surface = flags(cloud, surface_);
    label aLeast = -1;
    scalar least = VGREAT;
    dispatch(cloud.W(), [&](const auto& K)
    {
        for (label a = 0; a < cloud.nFluid(); ++a)
        {
            const scalar f = fill(cloud, K, full, surface, a);
            if (f >= 0 && f < least)
            {
                least = f;
                aLeast = a;
            }
        }
    });
    return aLeast;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::spreadLimit::spreadLimit
(
    const dictionary& schemes,
    const labelList* surface
)
:
    fluidLimit
    (
        checkedScalar
        (
            schemes, "maxSpread", 0.1, {0, VGREAT, true},
            "the largest fraction of room the fluid may take beyond its"
            " particles' volumes (1/mean kernel sum - 1)"
        )
    ),
    surface_(surface)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::spreadLimit::spread
(
    const sphCloud& cloud,
    label& nWhole,
    const labelList* surface
)
{
    const scalar mean = meanFill(cloud, surface, nWhole);
    return nWhole < minWhole ? -1 : 1/mean - 1;
}


Foam::string Foam::SPH::spreadLimit::describe() const
{
    return
        "the fluid spreading more than maxSpread " + Foam::name(limit_)
      + " beyond its particles' volumes";
}


Foam::label Foam::SPH::spreadLimit::find
(
    const sphCloud& cloud,
    const List<vector2D>& start,
    const Time& runTime,
    string& what
) const
{
    // Steps 1, 101, 201, ... of the run, by its time index: a restarted
    // run measures where the run it goes on from would have (a retried
    // step keeps its index, and is measured again)
    const label index = runTime.timeIndex();
    if (index > 1 && (index - 1) % interval != 0) return -1;
    label nWhole = 0;
    const scalar s = spread(cloud, nWhole, surface_);
    if (passes(s, runTime.value())) return -1;

    what =
        "The fluid takes " + Foam::name(1 + s) + " times the room its"
        " particles' volumes fill (mean kernel sum of " + Foam::name(nWhole)
      + " whole kernels " + Foam::name(1/(1 + s)) + " of the lattice's),"
        " a spread of " + Foam::name(s) + ", more than maxSpread "
      + Foam::name(limit_) + " (system/sphSchemes): the particles drift"
        " apart, the shifting most often; least filled:";
    return leastFilled(cloud);
}


void Foam::SPH::spreadLimit::printSummary(Ostream& os) const
{
    // A compressed fluid's spread is below 0; -1 is "never measured"
    if (reached_ <= -1) return;
    os  << "Largest spread of the fluid: " << reached_ << " (t = "
        << tReached_ << " s; 1/mean kernel sum of whole kernels - 1),"
        << " maxSpread " << limit_ << nl;
}


// ************************************************************************* //
