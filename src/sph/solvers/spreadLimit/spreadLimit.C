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
    const scalar* pAir,
    const label a
)
{
    const label nFluid = cloud.nFluid();
    scalar sum = 0;
    vector2D moment(0, 0);
    bool byWallOrPocket = false;
    cloud.cells().forEachNeighbour
    (
        cloud.parts().positions()[a],
        K.support(),
        [&](const label b, const vector2D& rab, const scalar r2)
        {
            // A particle that faces an air pocket (isphFoam's airPockets)
            // is a surface, even one the moment misses (a film between
            // two pockets): the pocket is room the fluid has
            byWallOrPocket =
                byWallOrPocket || b >= nFluid || (pAir && pAir[b] != 0);
            const scalar w = K.W(std::sqrt(r2));
            sum += w;
            moment += w*rab;
        }
    );
    // A surface within the kernel tilts its first moment (a lattice's is 0)
    return wholeKernelFill
    (
        sum, moment, byWallOrPocket, K.h(), sqr(cloud.dr())/full
    );
}


const Foam::scalar* Foam::SPH::spreadLimit::airPressure
(
    const sphCloud& cloud
)
{
    const particles& parts = cloud.parts();
    return
        parts.found<scalar>("pAir")
      ? parts.field<scalar>("pAir").cdata()
      : nullptr;
}


Foam::scalar Foam::SPH::spreadLimit::meanFill
(
    const sphCloud& cloud,
    label& nWhole
)
{
    const label nFluid = cloud.nFluid();
    const scalar full = cloud.W().latticeSum();
    const scalar* pAir = airPressure(cloud);
    scalar total = 0;
    label n = 0;
    dispatch(cloud.W(), [&](const auto& K)
    {
        #pragma omp parallel for schedule(static) reduction(+:total, n) \
            if(SPH::worthThreads(nFluid))
        for (label a = 0; a < nFluid; ++a)
        {
            const scalar f = fill(cloud, K, full, pAir, a);
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


Foam::label Foam::SPH::spreadLimit::leastFilled(const sphCloud& cloud)
{
    const scalar full = cloud.W().latticeSum();
    const scalar* pAir = airPressure(cloud);
    label aLeast = -1;
    scalar least = VGREAT;
    dispatch(cloud.W(), [&](const auto& K)
    {
        for (label a = 0; a < cloud.nFluid(); ++a)
        {
            const scalar f = fill(cloud, K, full, pAir, a);
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

Foam::SPH::spreadLimit::spreadLimit(const dictionary& schemes)
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
    measuredIndex_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::spreadLimit::spread
(
    const sphCloud& cloud,
    label& nWhole
)
{
    const scalar mean = meanFill(cloud, nWhole);
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
    const label index = runTime.timeIndex();
    if (measuredIndex_ >= 0 && index < measuredIndex_ + interval) return -1;
    measuredIndex_ = index;
    label nWhole = 0;
    const scalar s = spread(cloud, nWhole);
    if (passes(s, runTime.value())) return -1;

    // A retried step (retryOnFailure) is measured again
    measuredIndex_ = -1;
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
