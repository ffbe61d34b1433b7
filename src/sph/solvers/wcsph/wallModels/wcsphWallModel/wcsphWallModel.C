/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsphWallModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wcsphWallModel, 0);
    defineRunTimeSelectionTable(wcsphWallModel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wcsphWallModel::wcsphWallModel
(
    const Time& runTime,
    const dictionary& schemes,
    const wallMesh& walls,
    const kernel& W,
    wcsphWork& work
)
:
    runTime_(runTime),
    schemes_(schemes),
    walls_(walls),
    kernel_(W),
    work_(work)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::wcsphWallModel::refuseEntries
(
    std::initializer_list<word> keys,
    const word& onlyWith
) const
{
    for (const word& key : keys)
    {
        if (schemes_.found(key))
        {
            FatalIOErrorInFunction(schemes_.lookup(key))
                << "Entry " << key << ": only with boundaryMethod " << onlyWith
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wcsphWallModel::initialWalls() const
{
    const wcsphWork& work = work_;
    // Walls at rest at rho0
    vector2D* U = work.parts.field<vector2D>("U").data();
    scalar* p = work.parts.field<scalar>("p").data();
    scalar* rho = work.parts.field<scalar>("rho").data();
    for (label i = work.nFluid; i < work.parts.size(); ++i)
    {
        U[i] = vector2D::zero;
        rho[i] = work.rho0;
        p[i] = 0;
    }
}


void Foam::SPH::wcsphWallModel::fluidVolumes(scalarList& V) const
{
    const scalarField& rho = work_.parts.field<scalar>("rho");
    const scalar m = work_.mass();
    V.setSize(rho.size());
    forAll(V, i)
    {
        V[i] = i < work_.nFluid ? m/rho[i] : 0;
    }
}


// ************************************************************************* //
