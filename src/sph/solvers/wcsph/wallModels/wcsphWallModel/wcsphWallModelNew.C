/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsphWallModel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::wcsphWallModel> Foam::SPH::wcsphWallModel::New
(
    const Time& runTime,
    const dictionary& schemes,
    const wallMesh& walls,
    const kernel& W,
    wcsphWork& work
)
{
    const word modelType
    (
        schemes.getOrDefault<word>("boundaryMethod", "dummyRepulsive")
    );

    Info<< "Selecting wall model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            schemes,
            "boundaryMethod",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<wcsphWallModel>(cstrIter()(runTime, schemes, walls, W, work));
}


// ************************************************************************* //
