/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "region.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::region> Foam::SPH::region::New
(
    const word& name,
    const dictionary& dict
)
{
    const word regionType(dict.get<word>("type"));

    Info<< "Selecting region " << regionType << " for " << name << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(regionType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "region",
            regionType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<region>(cstrIter()(name, dict));
}


// ************************************************************************* //
