/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallMotion.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::wallMotion> Foam::SPH::wallMotion::New
(
    const word& name,
    const dictionary& dict
)
{
    const word motionType(dict.get<word>("type"));
    Info<< "Selecting wall motion " << motionType << " for " << name << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(motionType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "wall motion",
            motionType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<wallMotion>(cstrIter()(name, dict));
}


// ************************************************************************* //
