/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallShape.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::wallShape> Foam::SPH::wallShape::New
(
    const word& name,
    const dictionary& dict
)
{
    const word shapeType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(shapeType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict, "wall shape", shapeType, *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(name, dict);
}


// ************************************************************************* //
