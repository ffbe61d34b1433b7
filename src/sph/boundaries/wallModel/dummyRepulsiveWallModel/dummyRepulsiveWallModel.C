/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "dummyRepulsiveWallModel.H"
#include "particles.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(dummyRepulsiveWallModel, 0);
    addToRunTimeSelectionTable(wallModel, dummyRepulsiveWallModel, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::dummyRepulsiveWallModel::defaultDummyLayers
(
    const kernel& W,
    const scalar dr
) const
{
    // Layer k sits (k + 1/2) dr outside the wall and the first fluid
    // particle dr/2 inside it: enough layers to fill its kernel support
    return max(label(1), label(std::floor(W.support()/dr + 1e-9)));
}


void Foam::SPH::dummyRepulsiveWallModel::wallParticles
(
    const Time& runTime,
    const wallMesh&,
    DynamicList<vector2D>& x,
    DynamicList<label>& type,
    DynamicList<label>& patch
) const
{
    checkMesh(runTime);
    particles dummy(runTime, runTime.constant(), "sphMesh/dummy", false);
    dummy.add<label>("layer");
    dummy.add<label>("patch");
    dummy.read();
    forAll(dummy.positions(), d)
    {
        x.append(dummy.positions()[d]);
        type.append
        (
            label
            (
                dummy.field<label>("layer")[d] == 0
              ? particleKind::interfacial
              : particleKind::dummy
            )
        );
        patch.append(dummy.field<label>("patch")[d]);
    }
}


// ************************************************************************* //
