/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "bodyForce.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::bodyForce> Foam::SPH::bodyForce::New
(
    const word& name,
    const dictionary& dict,
    const Time& runTime
)
{
    if (!dict.getOrDefault<bool>("active", true))
    {
        Info<< "fvOption " << name << " is not active" << nl;
        return nullptr;
    }
    const word forceType(dict.get<word>("type"));
    Info<< "Selecting fvOption " << name << " of type " << forceType << nl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(forceType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "fvOption type",
            forceType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<bodyForce>(cstrIter()(name, dict, runTime));
}


// ************************************************************************* //
