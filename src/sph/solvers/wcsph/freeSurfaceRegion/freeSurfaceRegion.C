/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "freeSurfaceRegion.H"
#include "openMPThreshold.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::markFreeSurfaceRegion
(
    const neighbourList& nbrs,
    const label nFluid,
    const scalarUList& divR,
    const scalar divRMax,
    const scalar reach,
    UList<bool>& near
)
{
    if (nbrs.size() < nFluid || divR.size() < nFluid || near.size() < nFluid)
    {
        FatalErrorInFunction
            << nFluid << " fluid particles, but neighbours of " << nbrs.size()
            << ", " << divR.size() << " D{r} and " << near.size()
            << " flags" << exit(FatalError);
    }
    const label* off = nbrs.offsets().cdata();
    const label* nbr = nbrs.indices().cdata();
    const scalar* r = nbrs.r().cdata();
    const scalar* D = divR.cdata();
    bool* flag = near.data();

    label nSurface = 0;
    #pragma omp parallel for schedule(static) reduction(+:nSurface) \
        if(SPH::worthThreads(nFluid))
    for (label a = 0; a < nFluid; ++a)
    {
        const bool onSurface = D[a] <= divRMax;
        bool nearSurface = onSurface;
        for (label k = off[a]; k < off[a + 1] && !nearSurface; ++k)
        {
            const label b = nbr[k];
            nearSurface = b < nFluid && r[k] < reach && D[b] <= divRMax;
        }
        flag[a] = nearSurface;
        nSurface += onSurface;
    }
    return nSurface;
}


// ************************************************************************* //
