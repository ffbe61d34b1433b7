/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sampleSource.H"

// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::sampleSource> Foam::SPH::sampleSource::New
(
    const word& name,
    const dictionary& dict,
    const options& opts
)
{
    const word sourceType(dict.get<word>("type"));

    Info<< "Selecting source " << name << " of type " << sourceType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(sourceType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "sampleSource",
            sourceType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<sampleSource>(cstrIter()(name, dict, opts));
}


// ************************************************************************* //
