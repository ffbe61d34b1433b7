/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallShape.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wallShape, 0);
    defineRunTimeSelectionTable(wallShape, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallShape::wallShape(const word& name, const dictionary& dict)
:
    name_(name),
    dict_(dict)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::List<Foam::vector2D> Foam::SPH::wallShape::readPoints
(
    const word& key,
    label minSize
) const
{
    List<vector2D> pts(dict_.get<List<vector2D>>(key));
    if (pts.size() < minSize)
    {
        FatalIOErrorInFunction(dict_)
            << "Wall patch " << name_ << ": entry '" << key << "' has "
            << pts.size() << " points; a " << type() << " needs at least "
            << minSize << nl << exit(FatalIOError);
    }
    return pts;
}


bool Foam::SPH::wallShape::readSide(const word& first, const word& second) const
{
    const word side(dict_.getOrDefault<word>("side", first));
    if (side != first && side != second)
    {
        FatalIOErrorInFunction(dict_)
            << "Wall patch " << name_ << ": side " << side
            << " is not valid; expected " << first << " or " << second
            << " (the side of the " << type() << " the fluid is on)"
            << nl << exit(FatalIOError);
    }
    return side == first;
}


void Foam::SPH::wallShape::checkEdges
(
    const List<vector2D>& pts,
    bool closed
) const
{
    const label nEdges = closed ? pts.size() : pts.size() - 1;
    for (label i = 0; i < nEdges; ++i)
    {
        const vector2D& a = pts[i];
        const vector2D& b = pts[(i + 1) % pts.size()];
        if (mag(b - a) <= SMALL*(1 + mag(a)))
        {
            FatalIOErrorInFunction(dict_)
                << "Wall patch " << name_ << ": zero-length segment at point "
                << i << " " << a << "; consecutive points must differ"
                << nl << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::SPH::wallShape::chainLength
(
    const UList<vector2D>& pts,
    bool closed
)
{
    scalar L = 0;
    const label nEdges = closed ? pts.size() : pts.size() - 1;
    for (label i = 0; i < nEdges; ++i)
    {
        L += mag(pts[(i + 1) % pts.size()] - pts[i]);
    }
    return L;
}


void Foam::SPH::wallShape::pointBounds
(
    const UList<vector2D>& pts,
    vector2D& lo,
    vector2D& hi
)
{
    lo = vector2D(VGREAT, VGREAT);
    hi = vector2D(-VGREAT, -VGREAT);
    for (const vector2D& p : pts)
    {
        lo = min(lo, p);
        hi = max(hi, p);
    }
}


// ************************************************************************* //
