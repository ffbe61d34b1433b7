/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "solverMain.H"
#include "BoomerAMG.H"
#include "IOdictionary.H"
#include "OSspecific.H"

#include <cstdlib>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::SPH::checkUnreadFiles
(
    const Time& runTime,
    const bool turbulenceModels
)
{
    const fileName movingWalls(runTime.path()/runTime.constant()/"movingWalls");
    if (isFile(movingWalls))
    {
        FatalErrorInFunction
            << movingWalls << ": the solvers do not read this file (the"
            << " former way to move walls)." << nl
            << "A wall's velocity is its condition in 0/U (e.g. type"
            << " uniformFixedValue; uniformValue table ((0 (0 0 0)) (1 (1 0"
            << " 0)));), a motion of its geometry constant/dynamicMeshDict"
            << " (as OpenFOAM's solidBody motions); move the settings there"
            << " and remove the file" << exit(FatalError);
    }

    const IOdictionary turbulence
    (
        IOobject
        (
            "turbulenceProperties", runTime.constant(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    const word model
    (
        turbulence.getOrDefault<word>("simulationType", "laminar")
    );
    if (model != "laminar" && !turbulenceModels)
    {
        FatalIOErrorInFunction(turbulence.lookup("simulationType"))
            << "simulationType " << model << ": this solver models laminar"
            << " flow only (simulationType laminar, or no file); isphFoam"
            << " has the RAS model kEpsilon" << exit(FatalIOError);
    }
}


void Foam::SPH::finishRun()
{
    BoomerAMG::finalise();
}


void Foam::SPH::exitWithError(const IOerror& err)
{
    Perr<< nl << err << nl << "\nFOAM exiting\n" << endl;
    std::exit(1);
}


void Foam::SPH::exitWithError(const error& err)
{
    Perr<< nl << err << nl << "\nFOAM exiting\n" << endl;
    std::exit(1);
}


void Foam::SPH::exitWithError(const std::exception& err)
{
    Perr<< nl << "--> FOAM FATAL ERROR: " << nl << err.what() << nl
        << "\nFOAM exiting\n" << endl;
    std::exit(1);
}


// ************************************************************************* //
