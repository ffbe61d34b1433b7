/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallPolygon.H"
#include "addToRunTimeSelectionTable.H"
#include "polygon.H"

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wallPolygon, 0);
    addToRunTimeSelectionTable(wallShape, wallPolygon, dictionary);
    addNamedToRunTimeSelectionTable(wallShape, wallPolygon, dictionary, box);
}
}


Foam::scalar Foam::SPH::wallPolygon::signedArea2(const UList<vector2D>& pts)
{
    scalar a = 0;
    forAll(pts, i)
    {
        const vector2D& p = pts[i];
        const vector2D& q = pts[(i + 1) % pts.size()];
        a += p.x()*q.y() - q.x()*p.y();
    }
    return a;
}


Foam::List<Foam::vector2D> Foam::SPH::wallPolygon::boxPoints() const
{
    const vector2D lo(dict_.get<vector2D>("min"));
    const vector2D hi(dict_.get<vector2D>("max"));
    if (hi.x() <= lo.x() || hi.y() <= lo.y())
    {
        FatalIOErrorInFunction(dict_)
            << "Wall patch " << name_ << ": box max " << hi
            << " must exceed min " << lo << " in x and y"
            << nl << exit(FatalIOError);
    }
    List<vector2D> pts(4);
    pts[0] = lo;
    pts[1] = vector2D(hi.x(), lo.y());
    pts[2] = hi;
    pts[3] = vector2D(lo.x(), hi.y());
    return pts;
}


Foam::SPH::wallPolygon::wallPolygon(const word& name, const dictionary& dict)
:
    wallShape(name, dict),
    points_
    (
        dict.get<word>("type") == "box" ? boxPoints() : readPoints("points", 3)
    )
{
    checkEdges(points_, true);

    // The fluid region's test: at least 3 distinct corners, edges that meet
    // only at the corners between neighbours, some area
    const string why(polygon::problem(points_));
    if (!why.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "Wall patch " << name_ << ", entry points: " << why.c_str()
            << nl << exit(FatalIOError);
    }

    const scalar a2 = signedArea2(points_);
    if (mag(a2) <= SMALL)
    {
        FatalIOErrorInFunction(dict_)
            << "Wall patch " << name_ << ": the polygon encloses no area"
            << nl << exit(FatalIOError);
    }

    // Fluid on the left: counter-clockwise for fluid inside
    const bool fluidInside = readSide("inside", "outside");
    if ((a2 > 0) != fluidInside)
    {
        points_ = List<vector2D>(points_.rbegin(), points_.rend());
    }
}


Foam::List<Foam::SPH::wallChain> Foam::SPH::wallPolygon::chains(const scalar) const
{
    wallChain c;
    c.points = points_;
    c.closed = true;
    return List<wallChain>(1, c);
}


Foam::scalar Foam::SPH::wallPolygon::length() const
{
    return chainLength(points_, true);
}


void Foam::SPH::wallPolygon::bounds(vector2D& lo, vector2D& hi) const
{
    pointBounds(points_, lo, hi);
}


// ************************************************************************* //
