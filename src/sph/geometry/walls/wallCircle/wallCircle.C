/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallCircle.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wallCircle, 0);
    addToRunTimeSelectionTable(wallShape, wallCircle, dictionary);
    addNamedToRunTimeSelectionTable(wallShape, wallCircle, dictionary, arc);
}
}


Foam::SPH::wallCircle::wallCircle(const word& name, const dictionary& dict)
:
    wallShape(name, dict),
    centre_(dict.get<vector2D>("centre")),
    radius_(dict.get<scalar>("radius")),
    start_(0),
    end_(constant::mathematical::twoPi),
    closed_(dict.get<word>("type") != "arc"),
    fluidInside_(readSide("inside", "outside"))
{
    // Written as !(> 0) so that a NaN radius is refused too
    if (!(radius_ > 0))
    {
        FatalIOErrorInFunction(dict.lookup("radius"))
            << "Wall patch " << name << ": radius " << radius_
            << " must be positive" << nl << exit(FatalIOError);
    }
    if (!closed_)
    {
        const scalar deg = constant::mathematical::pi/180;
        start_ = deg*dict.get<scalar>("startAngle");
        end_ = deg*dict.get<scalar>("endAngle");
        if (!(end_ > start_) || !(end_ - start_ <= constant::mathematical::twoPi))
        {
            FatalIOErrorInFunction(dict)
                << "Wall patch " << name << ": endAngle must exceed startAngle"
                << " by at most 360 degrees" << nl << exit(FatalIOError);
        }
    }
}


void Foam::SPH::wallCircle::checkSpacing(const scalar dr) const
{
    if (closed_ && radius_ < 0.5*dr)
    {
        FatalIOErrorInFunction(dict_)
            << "Wall patch " << name_ << ": radius " << radius_ << " is less"
            << " than half the spacing dr = " << dr << "; a circle needs a"
            << " radius of at least dr/2 to be made of particles" << nl
            << exit(FatalIOError);
    }
    if (!closed_ && length() < dr)
    {
        FatalIOErrorInFunction(dict_)
            << "Wall patch " << name_ << ": the arc from startAngle "
            << start_*180/constant::mathematical::pi << " to endAngle "
            << end_*180/constant::mathematical::pi << " degrees of radius "
            << radius_ << " is " << length() << " long, less than one spacing"
            << " dr = " << dr << "; an arc must be at least dr long (an angle"
            << " of at least " << dr/radius_*180/constant::mathematical::pi
            << " degrees)" << nl << exit(FatalIOError);
    }
}


Foam::List<Foam::SPH::wallChain> Foam::SPH::wallCircle::chains(const scalar dr) const
{
    // Chords of about dr; at least 8 for a full circle
    const scalar angle = end_ - start_;
    const label nChords =
        max(closed_ ? 8 : 1, label(std::round(radius_*angle/dr)));

    wallChain c;
    c.closed = closed_;
    c.points.setSize(closed_ ? nChords : nChords + 1);
    forAll(c.points, i)
    {
        const scalar phi = start_ + angle*i/nChords;
        c.points[i] = centre_ + radius_*vector2D(std::cos(phi), std::sin(phi));
    }

    // Counter-clockwise has the inside on the left
    if (!fluidInside_)
    {
        c.points = List<vector2D>(c.points.rbegin(), c.points.rend());
    }
    return List<wallChain>(1, c);
}


// ************************************************************************* //
