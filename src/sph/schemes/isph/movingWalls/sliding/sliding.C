/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sliding.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace wallMotions
{
    defineTypeNameAndDebug(sliding, 0);
    addToRunTimeSelectionTable(wallMotion, sliding, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallMotions::sliding::sliding
(
    const word& name,
    const dictionary& dict
)
:
    wallMotion(name, dict),
    U_(dict.get<vector2D>("U"))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallMotions::sliding::write(Ostream& os) const
{
    os  << "slides along itself at U " << U_;
    wallMotion::write(os);
}


// ************************************************************************* //
