/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallModel.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wallModel, 0);
    defineRunTimeSelectionTable(wallModel, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace
{
    const Foam::word layoutName("layout");
}


void Foam::SPH::wallModel::writeLayout
(
    const objectRegistry& db,
    const fileName& local,
    const scalar dr,
    const label nDummyLayers
) const
{
    IOobject io
    (
        layoutName,
        db.time().constant(),
        local,
        db,
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
    io.note() = "how sphMesh laid the walls out; the solvers check it";
    IOdictionary dict(io);
    dict.add("boundaryMethod", word(type()));
    dict.add("dr", dr);
    dict.add("nDummyLayers", nDummyLayers);
    if
    (
        !dict.regIOobject::writeObject
        (
            IOstream::ASCII,
            IOstream::currentVersion,
            IOstream::UNCOMPRESSED,
            true
        )
    )
    {
        FatalErrorInFunction
            << "Cannot write " << io.objectPath() << exit(FatalError);
    }
}


void Foam::SPH::wallModel::checkMesh(const Time& runTime) const
{
    IOobject io
    (
        layoutName,
        runTime.constant(),
        "sphMesh",
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        Info<< "constant/sphMesh has no record of its wall model (made by an"
            << " older sphMesh): taken as made for boundaryMethod " << type()
            << nl;
        return;
    }
    const IOdictionary dict(io);
    const word made(dict.get<word>("boundaryMethod"));
    if (made != type())
    {
        FatalIOErrorInFunction(dict)
            << "constant/sphMesh was made by sphMesh for boundaryMethod "
            << made << ", but this run uses boundaryMethod " << type()
            << " (system/sphSchemes; isphFoam takes usaw only)." << nl
            << "Remake the mesh for it: set boundaryMethod " << type()
            << " in system/sphSchemes and run sphMesh again" << nl
            << exit(FatalIOError);
    }
    Info<< "constant/sphMesh was laid out for boundaryMethod " << made << nl;
}


// ************************************************************************* //
