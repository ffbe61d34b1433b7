/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "box.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(box, 0);
    addToRunTimeSelectionTable(region, box, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- True if max lies strictly above and to the right of min
bool ordered(const Foam::vector2D& min, const Foam::vector2D& max)
{
    return max.x() > min.x() && max.y() > min.y();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::box::box(const word& name, const dictionary& dict)
:
    region(name),
    min_(readPoint(dict, "min")),
    max_(readPoint(dict, "max"))
{
    if (!ordered(min_, max_))
    {
        FatalIOErrorInFunction(dict)
            << "Region " << name << ": entry max " << max_
            << " must exceed entry min " << min_ << " in both x and y" << nl
            << exit(FatalIOError);
    }
}


Foam::SPH::box::box
(
    const word& name,
    const vector2D& min,
    const vector2D& max
)
:
    region(name),
    min_(min),
    max_(max)
{
    if (!ordered(min_, max_))
    {
        FatalErrorInFunction
            << "Region " << name << ": max " << max_
            << " must exceed min " << min_ << " in both x and y" << nl
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::SPH::box::contains(const vector2D& p) const
{
    return
        p.x() >= min_.x() && p.x() <= max_.x()
     && p.y() >= min_.y() && p.y() <= max_.y();
}


Foam::SPH::boundBox2D Foam::SPH::box::bounds() const
{
    return boundBox2D(min_, max_);
}


Foam::scalar Foam::SPH::box::area() const
{
    const vector2D span(max_ - min_);
    return span.x()*span.y();
}


// ************************************************************************* //
