/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallPolyline.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wallPolyline, 0);
    addToRunTimeSelectionTable(wallShape, wallPolyline, dictionary);
    addNamedToRunTimeSelectionTable(wallShape, wallPolyline, dictionary, line);
}
}


Foam::SPH::wallPolyline::wallPolyline(const word& name, const dictionary& dict)
:
    wallShape(name, dict),
    points_(readPoints("points", 2))
{
    checkEdges(points_, false);
    if (!readSide("left", "right"))
    {
        points_ = List<vector2D>(points_.rbegin(), points_.rend());
    }
}


Foam::List<Foam::SPH::wallChain> Foam::SPH::wallPolyline::chains(const scalar) const
{
    wallChain c;
    c.points = points_;
    c.closed = false;
    return List<wallChain>(1, c);
}


Foam::scalar Foam::SPH::wallPolyline::length() const
{
    return chainLength(points_, false);
}


void Foam::SPH::wallPolyline::bounds(vector2D& lo, vector2D& hi) const
{
    pointBounds(points_, lo, hi);
}


// ************************************************************************* //
