/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sphCloud.H"
#include "Time.H"

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(sphCloud, 0);
}
}


Foam::SPH::sphCloud::sphCloud
(
    const Time& runTime,
    particles& parts,
    const kernel& W,
    const wallMesh& walls,
    const label nFluid,
    const scalar dr,
    const scalar rho0,
    const vector2D& g,
    const vector2D& boxMin,
    const vector2D& boxMax
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            runTime.timeName(),
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            true
        )
    ),
    particles_(parts),
    kernel_(W),
    walls_(walls),
    nFluid_(nFluid),
    dr_(dr),
    rho0_(rho0),
    g_(g),
    boxMin_(boxMin),
    boxMax_(boxMax),
    cells_(boxMin, boxMax, W.support())
{
    updateCells();
}


void Foam::SPH::sphCloud::updateCells()
{
    cells_.build(particles_.positions());
}


// ************************************************************************* //
