/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "usawWallModel.H"
#include "particles.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(usawWallModel, 0);
    addToRunTimeSelectionTable(wallModel, usawWallModel, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::usawWallModel::wallParticles
(
    const Time& runTime,
    const wallMesh& walls,
    DynamicList<vector2D>& x,
    DynamicList<label>& type,
    DynamicList<label>& patch
) const
{
    checkMesh(runTime);
    forAll(walls.points(), v)
    {
        x.append(walls.points()[v]);
        type.append(label(particleKind::wallVertex));
        patch.append(walls.pointPatch()[v]);
    }
}


void Foam::SPH::usawWallModel::checkRestart
(
    const wallMesh& walls,
    const fileName& path,
    const label nFluid,
    const label nWall
) const
{
    if (nWall != walls.points().size())
    {
        FatalErrorInFunction
            << path << " holds " << nWall << " wall particles after " << nFluid
            << " fluid ones, but constant/sphMesh/walls has "
            << walls.points().size() << " vertices: the case was not made"
            << " for boundaryMethod usaw (set it before running sphMesh)"
            << exit(FatalError);
    }
}


Foam::scalarList Foam::SPH::usawWallModel::volumeShares
(
    const wallMesh& walls,
    const label nWall
) const
{
    // Leroy et al. 2014 section 2: a vertex particle is a fluid particle
    // cut by the wall, the share theta_v/(2 pi) of its volume on the fluid
    // side
    scalarList share(nWall);
    forAll(share, v)
    {
        share[v] = walls.pointAngles()[v]/constant::mathematical::twoPi;
    }
    return share;
}


// ************************************************************************* //
