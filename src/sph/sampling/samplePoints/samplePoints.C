/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "samplePoints.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::samplePoints::setType>
Foam::SPH::samplePoints::setTypeNames
({
    { setType::line, "line" },
    { setType::points, "points" },
    { setType::table, "table" },
    { setType::sourcePoints, "sourcePoints" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::samplePoints::samplePoints(const dictionary& dict)
:
    type_(setTypeNames.get("type", dict))
{
    if (type_ == setType::line)
    {
        const vector2D start(dict.get<vector2D>("start"));
        const vector2D end(dict.get<vector2D>("end"));
        const label n = dict.get<label>("nPoints");
        if (n < 2)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'nPoints' is " << n << "; a line needs at least 2"
                << " points (its start and end)" << nl << exit(FatalIOError);
        }
        if (mag(end - start) <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "The line starts and ends at " << start
                << ": entries 'start' and 'end' must differ" << nl
                << exit(FatalIOError);
        }
        points_.setSize(n);
        forAll(points_, i)
        {
            points_[i] = start + (end - start)*(scalar(i)/(n - 1));
        }
        weights_ = trapezoidalWeights(points_);
    }
    else if (type_ == setType::points)
    {
        points_ = dict.get<List<vector2D>>("points");
        if (points_.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'points' is empty: give at least one point (x y)"
                << nl << exit(FatalIOError);
        }
        weights_ = scalarField(points_.size(), 1.0);
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "A set of type " << setTypeNames[type_]
            << " takes its points from a source; use line or points here"
            << nl << exit(FatalIOError);
    }
    distance_ = polylineDistance(points_);
}


Foam::SPH::samplePoints::samplePoints
(
    const setType type,
    const UList<vector2D>& points,
    const scalarField& weights
)
:
    type_(type),
    points_(points),
    distance_
    (
        type == setType::sourcePoints
      ? scalarField(points.size(), 0.0)     // scattered: no order
      : polylineDistance(points)
    ),
    weights_(weights)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarField Foam::SPH::samplePoints::polylineDistance
(
    const UList<vector2D>& points
)
{
    scalarField d(points.size(), 0.0);
    for (label i = 1; i < points.size(); ++i)
    {
        d[i] = d[i-1] + mag(points[i] - points[i-1]);
    }
    return d;
}


Foam::scalarField Foam::SPH::samplePoints::trapezoidalWeights
(
    const UList<vector2D>& points
)
{
    // Each point carries half of each of its two segments
    scalarField w(points.size(), 0.0);
    for (label i = 1; i < points.size(); ++i)
    {
        const scalar half = 0.5*mag(points[i] - points[i-1]);
        w[i-1] += half;
        w[i] += half;
    }
    return w;
}


// ************************************************************************* //
