/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "freeSurfaceRegion.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::markFreeSurfaceRegion
(
    const neighbourList& nbrs,
    const label nFluid,
    const scalarUList& divR,
    const scalar divRMax,
    const scalar reach,
    labelUList& near
)
{
    if (nbrs.size() < nFluid || divR.size() < nFluid || near.size() < nFluid)
    {
        FatalErrorInFunction
            << nFluid << " fluid particles, but neighbours of " << nbrs.size()
            << ", " << divR.size() << " D{r} and " << near.size()
            << " flags" << exit(FatalError);
    }
    const scalar* D = divR.cdata();
    const auto onSurface = [=](const label b)
    {
        return b < nFluid && D[b] <= divRMax;
    };
    markNearSurface(nbrs, nFluid, onSurface, reach, near);

    label nSurface = 0;
    for (label a = 0; a < nFluid; ++a)
    {
        nSurface += onSurface(a);
    }
    return nSurface;
}


// ************************************************************************* //
