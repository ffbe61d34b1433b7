/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "bodyForce.H"

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(bodyForce, 0);
    defineRunTimeSelectionTable(bodyForce, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::bodyForce::bodyForce
(
    const word& name,
    const dictionary& dict,
    const Time& runTime
)
:
    name_(name),
    runTime_(runTime),
    coeffs_(dict.optionalSubDict(dict.get<word>("type") + "Coeffs")),
    timeStart_(-VGREAT),
    duration_(-1)
{
    const wordList fields(coeffs_.getOrDefault<wordList>("fields", wordList({"U"})));
    if (!fields.found("U"))
    {
        FatalIOErrorInFunction(dict)
            << "fvOption " << name << " acts on fields " << fields
            << ": a body force acts on U" << exit(FatalIOError);
    }
    const word selection(dict.getOrDefault<word>("selectionMode", "all"));
    if (selection != "all")
    {
        FatalIOErrorInFunction(dict)
            << "fvOption " << name << ": selectionMode " << selection
            << ": expected all (SPH particles are not in cells or cellZones)"
            << exit(FatalIOError);
    }
    if (dict.found("timeStart"))
    {
        timeStart_ = dict.get<scalar>("timeStart");
        duration_ = dict.get<scalar>("duration");
    }
}


// ************************************************************************* //
