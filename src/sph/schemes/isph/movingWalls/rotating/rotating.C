/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "rotating.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace wallMotions
{
    defineTypeNameAndDebug(rotating, 0);
    addToRunTimeSelectionTable(wallMotion, rotating, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallMotions::rotating::rotating
(
    const word& name,
    const dictionary& dict
)
:
    wallMotion(name, dict),
    origin_(dict.get<vector2D>("origin")),
    omega_(dict.get<scalar>("omega"))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector2D Foam::SPH::wallMotions::rotating::position
(
    const vector2D& x0,
    const scalar t
) const
{
    const scalar theta = omega_*rampIntegral(t);
    const scalar c = std::cos(theta);
    const scalar s = std::sin(theta);
    const vector2D d(x0 - origin_);
    return origin_ + vector2D(c*d.x() - s*d.y(), s*d.x() + c*d.y());
}


Foam::vector2D Foam::SPH::wallMotions::rotating::velocity
(
    const vector2D& x0,
    const scalar t
) const
{
    const vector2D d(position(x0, t) - origin_);
    return omega_*ramp(t)*vector2D(-d.y(), d.x());
}


void Foam::SPH::wallMotions::rotating::write(Ostream& os) const
{
    os  << "rotates about " << origin_ << " at omega " << omega_ << " rad/s";
    wallMotion::write(os);
}


// ************************************************************************* //
