/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "circle.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(circle, 0);
    addToRunTimeSelectionTable(region, circle, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::circle::circle(const word& name, const dictionary& dict)
:
    region(name),
    centre_(readPoint(dict, "centre")),
    radius_(dict.get<scalar>("radius"))
{
    // Written as !(> 0) so that a NaN radius is refused too
    if (!(radius_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Region " << name << ": entry radius " << radius_
            << " must be positive" << nl
            << exit(FatalIOError);
    }
}


Foam::SPH::circle::circle
(
    const word& name,
    const vector2D& centre,
    const scalar radius
)
:
    region(name),
    centre_(centre),
    radius_(radius)
{
    if (!(radius_ > 0))
    {
        FatalErrorInFunction
            << "Region " << name << ": radius " << radius_
            << " must be positive" << nl
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::SPH::circle::contains(const vector2D& p) const
{
    return magSqr(p - centre_) <= sqr(radius_);
}


Foam::SPH::boundBox2D Foam::SPH::circle::bounds() const
{
    const vector2D r(radius_, radius_);
    return boundBox2D(centre_ - r, centre_ + r);
}


Foam::scalar Foam::SPH::circle::area() const
{
    return constant::mathematical::pi*sqr(radius_);
}


// ************************************************************************* //
