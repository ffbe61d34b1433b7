/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The searches of wallMesh: the signed distance to the walls, through a
    grid of the segments when one is built (sphMesh asks it for every
    lattice point and every dummy: a search of all segments for each made
    a wall circle of radius 1e5 at dr 0.1, 6e6 segments, take days), and
    the segments that cross or overlap.

\*---------------------------------------------------------------------------*/

#include "wallMesh.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    inline scalar cross2D(const vector2D& a, const vector2D& b)
    {
        return a.x()*b.y() - a.y()*b.x();
    }

    //- Rings searched around a point before searching every segment
    const int64_t maxRings = 32;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

int64_t Foam::SPH::wallMesh::gridIndex(const scalar x) const
{
    return int64_t(std::floor(x/gridCell_));
}


int64_t Foam::SPH::wallMesh::gridKey(const int64_t i, const int64_t j)
{
    return (i << 32) ^ (j & 0xffffffff);
}


Foam::scalar Foam::SPH::wallMesh::segmentDistance
(
    const vector2D& p,
    label s,
    scalar& sign
) const
{
    // The image of the segment nearest p
    const vector2D a(domain_.image(points_[segments_[s].first()], p));
    const vector2D ab(segmentVector(s));
    const scalar t = min(max(((p - a) & ab)/magSqr(ab), 0.0), 1.0);
    const vector2D d = p - (a + t*ab);
    vector2D n = segmentNormals_[s];
    if (t <= 0) n = pointNormals_[segments_[s].first()];
    else if (t >= 1) n = pointNormals_[segments_[s].second()];
    sign = ((d & n) >= 0) ? 1 : -1;
    return mag(d);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallMesh::buildSearchGrid(const scalar cell)
{
    grid_.clear();
    gridCell_ = 0;
    if (domain_.anyPeriodic() || segments_.empty() || !(cell > 0))
    {
        return;
    }
    gridCell_ = cell;
    forAll(segments_, s)
    {
        const vector2D& a = points_[segments_[s].first()];
        const vector2D& b = points_[segments_[s].second()];
        const vector2D lo(min(a, b)), hi(max(a, b));
        for (int64_t i = gridIndex(lo.x()); i <= gridIndex(hi.x()); ++i)
        {
            for (int64_t j = gridIndex(lo.y()); j <= gridIndex(hi.y()); ++j)
            {
                grid_[gridKey(i, j)].push_back(s);
            }
        }
    }
}


Foam::scalar Foam::SPH::wallMesh::signedDistance(const vector2D& p) const
{
    // The nearest segment, the first of equals in the order of the
    // segments, whichever way they are searched
    scalar best = GREAT;
    scalar sign = 1;
    label bestS = -1;
    auto consider = [&](const label s)
    {
        scalar sg;
        const scalar dist = segmentDistance(p, s, sg);
        if (dist < best || (dist == best && s < bestS))
        {
            best = dist;
            sign = sg;
            bestS = s;
        }
    };

    if (gridCell_ > 0)
    {
        // Rings of cells around p's: after ring r every segment closer
        // than r cells has been seen
        const int64_t ci = gridIndex(p.x());
        const int64_t cj = gridIndex(p.y());
        for (int64_t r = 0; r <= maxRings; ++r)
        {
            for (int64_t i = ci - r; i <= ci + r; ++i)
            {
                const int64_t step = (i == ci - r || i == ci + r) ? 1 : 2*r;
                for (int64_t j = cj - r; j <= cj + r; j += max(step, int64_t(1)))
                {
                    const auto it = grid_.find(gridKey(i, j));
                    if (it == grid_.end()) continue;
                    for (const label s : it->second)
                    {
                        consider(s);
                    }
                }
            }
            if (bestS >= 0 && best < r*gridCell_)
            {
                return sign*best;
            }
        }
    }

    forAll(segments_, s)
    {
        consider(s);
    }
    return sign*best;
}


bool Foam::SPH::wallMesh::closedWalls() const
{
    forAll(points_, v)
    {
        if (segmentIn_[v] < 0 || segmentOut_[v] < 0)
        {
            return false;
        }
    }
    return true;
}


bool Foam::SPH::wallMesh::passesThrough
(
    const label v,
    const label k,
    const scalar tol
) const
{
    auto inner = [&](const label w)
    {
        return segmentIn_[w] >= 0 && segmentOut_[w] >= 0;
    };
    if (!inner(v) || v == segments_[k].first() || v == segments_[k].second())
    {
        return false;
    }
    // On an end of k: a crossing only if that end goes on too (a wall end
    // at a vertex of another wall is a junction)
    for (const label w : {segments_[k].first(), segments_[k].second()})
    {
        if (mag(domain_.separation(points_[v], points_[w])) <= tol)
        {
            return inner(w);
        }
    }
    const vector2D p0(domain_.image(points_[segments_[k].first()], points_[v]));
    const vector2D e(segmentVector(k));
    const scalar u = min(max(((points_[v] - p0) & e)/magSqr(e), 0.0), 1.0);
    return mag(points_[v] - (p0 + u*e)) <= tol;
}


bool Foam::SPH::wallMesh::segmentsCross
(
    const label i,
    const label j,
    const scalar tol,
    bool& overlap
) const
{
    const vector2D a(points_[segments_[i].first()]);
    const vector2D ab(segmentVector(i));
    const vector2D c(domain_.image(points_[segments_[j].first()], a));
    const vector2D cd(segmentVector(j));
    const scalar lab = mag(ab), lcd = mag(cd);
    const scalar eps = 1e-9*max(lab, lcd);
    const scalar oc = cross2D(ab, c - a)/lab;
    const scalar od = cross2D(ab, c + cd - a)/lab;
    if (mag(oc) <= eps && mag(od) <= eps)
    {
        // Along one line: the common part of the two intervals
        const vector2D u(ab/lab);
        const scalar tc = (c - a) & u, td = (c + cd - a) & u;
        const scalar common = min(lab, max(tc, td)) - max(0.0, min(tc, td));
        overlap = true;
        return common > tol;
    }
    const scalar oa = cross2D(cd, a - c)/lcd;
    const scalar ob = cross2D(cd, a + ab - c)/lcd;
    overlap = false;
    if
    (
        ((oc > eps && od < -eps) || (oc < -eps && od > eps))
     && ((oa > eps && ob < -eps) || (oa < -eps && ob > eps))
    )
    {
        return true;
    }

    // A wall going on through a point of the other: they cross or touch
    // there. A wall end on another wall is a junction
    for (const label v : {segments_[i].first(), segments_[i].second()})
    {
        if (passesThrough(v, j, tol)) return true;
    }
    for (const label v : {segments_[j].first(), segments_[j].second()})
    {
        if (passesThrough(v, i, tol)) return true;
    }
    return false;
}


bool Foam::SPH::wallMesh::findCrossing
(
    const scalar tol,
    label& s,
    label& t,
    bool& overlap
) const
{
    if (gridCell_ > 0)
    {
        for (const auto& cell : grid_)
        {
            const std::vector<label>& segs = cell.second;
            for (size_t m = 0; m < segs.size(); ++m)
            {
                for (size_t k = m + 1; k < segs.size(); ++k)
                {
                    s = min(segs[m], segs[k]);
                    t = max(segs[m], segs[k]);
                    if (s != t && segmentsCross(s, t, tol, overlap))
                    {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    // Periodic domains (no grid): every pair, through the minimum image
    for (s = 0; s < segments_.size(); ++s)
    {
        for (t = s + 1; t < segments_.size(); ++t)
        {
            if (segmentsCross(s, t, tol, overlap))
            {
                return true;
            }
        }
    }
    return false;
}


// ************************************************************************* //
