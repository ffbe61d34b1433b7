/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "usawOperators.H"
#include "error.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::SPH::usaw::checkOperands
(
    const char* op,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const label nParticles,
    std::initializer_list<label> fieldSizes,
    const label nSegmentValues,
    const label nResult
)
{
    // O(1) checks, always on: a mismatch here would read past an array in
    // the loops, which have no checks of their own
    const label nTargets = nbrs.size();
    const label nSegments = walls.segmentParticles().size();
    const label vertexEnd = walls.vertexStart() + walls.walls().points().size();

    if (!nbrs.storesGeometry())
    {
        FatalErrorInFunction
            << "usaw::" << op << ": the neighbour list must store r_ab and"
            << " |r_ab| (construct it with neighbourList(true))"
            << exit(FatalError);
    }
    if (walls.size() < nTargets)
    {
        FatalErrorInFunction
            << "usaw::" << op << ": gamma known for " << walls.size()
            << " particles, " << nTargets << " targets: call"
            << " usawWalls::update() with the targets' positions first"
            << exit(FatalError);
    }
    if (nTargets > nParticles || vertexEnd > nParticles)
    {
        FatalErrorInFunction
            << "usaw::" << op << ": " << nParticles << " particles, but "
            << nTargets << " targets and wall vertex particles up to index "
            << vertexEnd - 1 << exit(FatalError);
    }
    label i = 0;
    for (const label size : fieldSizes)
    {
        if (size != nParticles)
        {
            FatalErrorInFunction
                << "usaw::" << op << ": field " << i << " (after V, in argument"
                << " order) has " << size << " values for " << nParticles
                << " particles" << exit(FatalError);
        }
        ++i;
    }
    if (nSegmentValues >= 0 && nSegmentValues != nSegments)
    {
        FatalErrorInFunction
            << "usaw::" << op << ": " << nSegmentValues << " wall values for "
            << nSegments << " segments" << exit(FatalError);
    }
    if (nResult < nTargets)
    {
        FatalErrorInFunction
            << "usaw::" << op << ": result holds " << nResult
            << " values for " << nTargets << " targets" << exit(FatalError);
    }
}


// ************************************************************************* //
