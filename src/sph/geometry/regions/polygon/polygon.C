/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "polygon.H"
#include "addToRunTimeSelectionTable.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(polygon, 0);
    addToRunTimeSelectionTable(region, polygon, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::label;
using Foam::scalar;
using Foam::vector2D;

//- Twice the signed area of triangle (a, b, c): > 0 if c is left of a->b
inline scalar orientation(const vector2D& a, const vector2D& b, const vector2D& c)
{
    return (b - a).perp(c - a);
}


//- True if p, known to be collinear with a and b, lies on the segment a-b
inline bool withinSegment(const vector2D& a, const vector2D& b, const vector2D& p)
{
    return
        p.x() >= Foam::min(a.x(), b.x()) && p.x() <= Foam::max(a.x(), b.x())
     && p.y() >= Foam::min(a.y(), b.y()) && p.y() <= Foam::max(a.y(), b.y());
}


//- True if the closed segments a-b and c-d share at least one point
bool segmentsMeet
(
    const vector2D& a,
    const vector2D& b,
    const vector2D& c,
    const vector2D& d
)
{
    const scalar oc = orientation(a, b, c);
    const scalar od = orientation(a, b, d);
    const scalar oa = orientation(c, d, a);
    const scalar ob = orientation(c, d, b);

    // Proper crossing: each segment's ends lie strictly on both sides of
    // the other's line
    if
    (
        ((oc > 0 && od < 0) || (oc < 0 && od > 0))
     && ((oa > 0 && ob < 0) || (oa < 0 && ob > 0))
    )
    {
        return true;
    }

    // Touching or overlapping: an end point lies on the other segment
    return
        (oc == 0 && withinSegment(a, b, c))
     || (od == 0 && withinSegment(a, b, d))
     || (oa == 0 && withinSegment(c, d, a))
     || (ob == 0 && withinSegment(c, d, b));
}


//- Twice the signed area (shoelace sum), > 0 for anticlockwise points
scalar twiceSignedArea(const Foam::List<vector2D>& points)
{
    scalar sum = 0;

    forAll(points, i)
    {
        const vector2D& a = points[i];
        const vector2D& b = points[points.fcIndex(i)];
        sum += a.x()*b.y() - b.x()*a.y();
    }

    return sum;
}


//- Smallest box holding points
Foam::SPH::boundBox2D boundsOf(const Foam::List<vector2D>& points)
{
    Foam::SPH::boundBox2D bb(points.first(), points.first());

    for (const vector2D& p : points)
    {
        bb.add(Foam::SPH::boundBox2D(p, p));
    }

    return bb;
}


//- True if all points lie exactly on the line through the first two
bool collinear(const Foam::List<vector2D>& points)
{
    for (const vector2D& p : points)
    {
        if (orientation(points[0], points[1], p) != 0)
        {
            return false;
        }
    }

    return true;
}


//- True if edges i and j (i < j) of the closed polygon points share a point
//  other than the corner that neighbouring edges have in common
bool edgesMeet(const Foam::List<vector2D>& points, const label i, const label j)
{
    const label n = points.size();
    const vector2D& a = points[i];
    const vector2D& b = points[points.fcIndex(i)];
    const vector2D& c = points[j];
    const vector2D& d = points[points.fcIndex(j)];

    if (j == i + 1)
    {
        // Neighbours share b (= c): they meet elsewhere only by folding
        // back along one line
        return orientation(a, b, d) == 0 && ((b - a) & (d - c)) < 0;
    }
    if (i == 0 && j == n - 1)
    {
        // Neighbours across the closing edge share a (= d)
        return orientation(c, d, b) == 0 && ((d - c) & (b - a)) < 0;
    }

    return segmentsMeet(a, b, c, d);
}


//- Describe edge i of points for error messages: "edge i (a to b)"
std::string edgeName(const Foam::List<vector2D>& points, const label i)
{
    Foam::OStringStream os;
    os  << "edge " << i << " (" << points[i] << " to "
        << points[points.fcIndex(i)] << ')';
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::string Foam::SPH::polygon::problem(const List<vector2D>& points)
{
    const label n = points.size();
    OStringStream msg;

    if (n < 3)
    {
        msg << "open or degenerate polygon: points holds " << n
            << " point(s), at least 3 are needed (the last point joins the"
            << " first by itself)";
        return msg.str();
    }

    forAll(points, i)
    {
        const label j = points.fcIndex(i);

        if (points[i] == points[j])
        {
            msg << "points " << i << " and " << j << " are both " << points[i]
                << ": consecutive points must differ";
            if (j == 0)
            {
                msg << " (the polygon closes itself: do not repeat the first"
                    << " point at the end)";
            }
            return msg.str();
        }
    }

    // Consecutive points differ, so points[0] and points[1] make a line
    if (collinear(points))
    {
        msg << "zero area: all points lie on one line";
        return msg.str();
    }

    for (label i = 0; i < n; ++i)
    {
        for (label j = i + 1; j < n; ++j)
        {
            if (edgesMeet(points, i, j))
            {
                msg << "self-intersecting polygon: "
                    << edgeName(points, i).c_str() << " and "
                    << edgeName(points, j).c_str() << " meet; the edges of"
                    << " a polygon may only share the corner between"
                    << " neighbours";
                return msg.str();
            }
        }
    }

    // Nearly collinear points that no exact test caught: the area is below
    // the rounding bound of the shoelace sum
    const scalar area = 0.5*mag(twiceSignedArea(points));

    if (area <= n*SMALL*magSqr(boundsOf(points).span()))
    {
        msg << "zero area (" << area << "): the points are nearly collinear";
        return msg.str();
    }

    return string::null;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::polygon::polygon(const word& name, const dictionary& dict)
:
    region(name),
    points_(readPoints(dict, "points")),
    bounds_(vector2D::zero, vector2D::zero),
    area_(0)
{
    const string why(problem(points_));

    if (!why.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Region " << name << ", entry points: " << why.c_str() << nl
            << exit(FatalIOError);
    }

    bounds_ = boundsOf(points_);
    area_ = 0.5*mag(twiceSignedArea(points_));
}


Foam::SPH::polygon::polygon(const word& name, const List<vector2D>& points)
:
    region(name),
    points_(points),
    bounds_(vector2D::zero, vector2D::zero),
    area_(0)
{
    const string why(problem(points_));

    if (!why.empty())
    {
        FatalErrorInFunction
            << "Region " << name << ", points: " << why.c_str() << nl
            << exit(FatalError);
    }

    bounds_ = boundsOf(points_);
    area_ = 0.5*mag(twiceSignedArea(points_));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::SPH::polygon::contains(const vector2D& p) const
{
    if (!bounds_.contains(p))
    {
        return false;
    }

    // Winding number: count edges crossing the horizontal line through p
    // upwards with p on their left (+1) and downwards with p on their
    // right (-1), each edge holding its lower end only
    label winding = 0;

    forAll(points_, i)
    {
        const vector2D& a = points_[i];
        const vector2D& b = points_[points_.fcIndex(i)];

        const scalar side = orientation(a, b, p);

        if (side == 0 && withinSegment(a, b, p))
        {
            return true;
        }

        if (a.y() <= p.y())
        {
            if (b.y() > p.y() && side > 0)
            {
                ++winding;
            }
        }
        else if (b.y() <= p.y() && side < 0)
        {
            --winding;
        }
    }

    return winding != 0;
}


Foam::SPH::boundBox2D Foam::SPH::polygon::bounds() const
{
    return bounds_;
}


Foam::scalar Foam::SPH::polygon::area() const
{
    return area_;
}


// ************************************************************************* //
