/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearSolver.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::linearSolver> Foam::SPH::linearSolver::New
(
    const word& fieldName,
    const dictionary& dict
)
{
    const word solverType(dict.get<word>("solver"));
    Info<< "Selecting linear solver " << solverType << " for " << fieldName
        << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(solverType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "linear solver",
            solverType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<linearSolver>(cstrIter()(fieldName, dict));
}


// ************************************************************************* //
