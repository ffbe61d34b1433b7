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
    // The layout first: sphMesh's selection, and its list of valid words
    autoPtr<wallModel> layout(wallModel::New(schemes));
    const word& modelType = layout->type();

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

    autoPtr<wcsphWallModel> model
    (
        cstrIter()(runTime, schemes, walls, W, work)
    );
    model->layout_ = std::move(layout);
    return model;
}


// ************************************************************************* //
