/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "implicitDiffusionStep.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::implicitDiffusionStep::implicitDiffusionStep
(
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const label nFluid
)
:
    nFluid_(nFluid),
    B_(V.size(), Zero),
    Sp_(V.size(), Zero),
    robinK_(walls.segmentParticles().size(), Zero),
    robinG_(walls.segmentParticles().size(), Zero),
    rate_(V.size(), Zero),
    source_(V.size(), Zero),
    lap_(nbrs, walls, V, nFluid)
{
    lap_.coefficient(B_);
    lap_.implicitSource(Sp_);
    labelList& kinds = lap_.kinds();
    for (label i = nFluid; i < kinds.size(); ++i)
    {
        kinds[i] = laplacianMatrix::dirichlet;
    }
}


// ************************************************************************* //
