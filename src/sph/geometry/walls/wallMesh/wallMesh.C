/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallMesh.H"
#include "DynamicList.H"
#include "IOField.H"
#include "IOList.H"
#include "vector2DIOField.H"
#include "labelIOField.H"
#include "scalarIOField.H"
#include "Time.H"
#include "mathematicalConstants.H"
#include "HashTable.H"

#include <unordered_map>

using Foam::constant::mathematical::pi;

namespace Foam
{
    // Segments are stored as a list of vertex pairs
    defineTemplateTypeNameAndDebugWithName(IOList<labelPair>, "labelPairList", 0);
}

namespace
{
    using namespace Foam;

    //- Cross product z-component
    inline scalar cross2D(const vector2D& a, const vector2D& b)
    {
        return a.x()*b.y() - a.y()*b.x();
    }

    //- The tangent turned by +90 degrees: the normal on the left
    inline vector2D leftNormal(const vector2D& t)
    {
        return vector2D(-t.y(), t.x());
    }

    //- Points a + (j/n) ab, j = 0..n-1 (and n when withEnd), n pieces of
    //- about dr. The edge is given as ab, not as its end: a periodic
    //- wall's pieces then span exactly its period
    void appendPieces
    (
        const vector2D& a,
        const vector2D& ab,
        const scalar dr,
        const bool withEnd,
        const label patchi,
        DynamicList<vector2D>& pts,
        DynamicList<label>& patch
    )
    {
        const label n = max(label(1), label(std::round(mag(ab)/dr)));
        const label nPts = withEnd ? n + 1 : n;
        for (label j = 0; j < nPts; ++j)
        {
            pts.append(a + ab*(scalar(j)/n));
            patch.append(patchi);
        }
    }

    const fileName wallsLocal("sphMesh/walls");
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::SPH::wallMesh::endPoint
(
    const vector2D& p,
    label patchi,
    scalar tol
)
{
    // Chain ends are few: a linear search over the vertices with one segment
    forAll(points_, i)
    {
        if
        (
            (segmentIn_[i] < 0 || segmentOut_[i] < 0)
         && mag(domain_.separation(points_[i], p)) < tol
        )
        {
            return i;
        }
    }
    points_.append(p);
    pointPatch_.append(patchi);
    segmentIn_.append(-1);
    segmentOut_.append(-1);
    return points_.size() - 1;
}


void Foam::SPH::wallMesh::addChain
(
    const wallChain& chain,
    label patchi,
    scalar dr
)
{
    const UList<vector2D>& knots = chain.points;
    const label nEdges = chain.closed ? knots.size() : knots.size() - 1;
    const scalar tol = 1e-6*dr;

    // Split every edge into pieces of length close to dr
    DynamicList<vector2D> pts;
    for (label e = 0; e < nEdges; ++e)
    {
        const vector2D& a = knots[e];
        const vector2D& b = knots[(e + 1) % knots.size()];
        const label n = max(label(1), label(std::round(mag(b - a)/dr)));
        for (label k = 0; k < n; ++k)
        {
            pts.append(a + (b - a)*(scalar(k)/n));
        }
    }
    if (!chain.closed)
    {
        pts.append(knots.last());
    }

    // In a periodic direction every vertex lies in [min, max): an end on
    // the seam at max becomes its image at min, where it meets the chain
    // continuing on the other side
    for (vector2D& p : pts)
    {
        p = domain_.wrap(p);
    }

    // Vertices: the ends of open chains may join other chains
    labelList ids(pts.size());
    forAll(pts, i)
    {
        const bool isEnd = !chain.closed && (i == 0 || i == pts.size() - 1);
        if (isEnd)
        {
            ids[i] = endPoint(pts[i], patchi, tol);
        }
        else
        {
            points_.append(pts[i]);
            pointPatch_.append(patchi);
            segmentIn_.append(-1);
            segmentOut_.append(-1);
            ids[i] = points_.size() - 1;
        }
    }

    const label nSeg = chain.closed ? ids.size() : ids.size() - 1;
    for (label i = 0; i < nSeg; ++i)
    {
        const label a = ids[i];
        const label b = ids[(i + 1) % ids.size()];
        if (segmentOut_[a] >= 0 || segmentIn_[b] >= 0)
        {
            const label v = segmentOut_[a] >= 0 ? a : b;
            FatalErrorInFunction
                << "Wall patches " << patchNames_[segmentPatch_[max(segmentOut_[v], segmentIn_[v])]]
                << " and " << patchNames_[patchi] << " meet at "
                << points_[v] << " with the fluid on opposite sides." << nl
                << "Walls that join must agree on the fluid side: check their"
                << " 'side' entries or the order of their points." << nl
                << exit(FatalError);
        }
        segments_.append(labelPair(a, b));
        segmentPatch_.append(patchi);
        segmentOut_[a] = segments_.size() - 1;
        segmentIn_[b] = segments_.size() - 1;
    }
}


void Foam::SPH::wallMesh::calcGeometry()
{
    segmentNormals_.setSize(segments_.size());
    forAll(segments_, s)
    {
        const vector2D t = segmentVector(s);
        segmentNormals_[s] = leftNormal(t/mag(t));
    }

    pointNormals_.setSize(points_.size());
    pointAngles_.setSize(points_.size());
    forAll(points_, v)
    {
        const label sIn = segmentIn_[v];
        const label sOut = segmentOut_[v];
        if (sIn < 0 || sOut < 0)
        {
            // Free end of an open wall: treated as straight
            pointAngles_[v] = pi;
            pointNormals_[v] = segmentNormals_[max(sIn, sOut)];
            continue;
        }
        const vector2D tIn = leftNormal(segmentNormals_[sIn])*(-1);
        const vector2D tOut = leftNormal(segmentNormals_[sOut])*(-1);

        // Fluid-side angle: pi minus the (signed) turn to the left
        const scalar turn = std::atan2(cross2D(tIn, tOut), tIn & tOut);
        pointAngles_[v] = pi - turn;

        // Bisector pointing into the fluid
        vector2D n = segmentNormals_[sIn] + segmentNormals_[sOut];
        if (mag(n) < 1e-10)
        {
            // Hairpin: the bisector is along the incoming tangent
            n = (pointAngles_[v] > pi) ? tIn : -tIn;
        }
        pointNormals_[v] = n/mag(n);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallMesh::wallMesh
(
    const wordList& patchNames,
    const List<List<wallChain>>& patchChains,
    const scalar dr
)
:
    wallMesh
    (
        patchNames,
        patchChains,
        dr,
        SPH::domain(vector2D::zero, vector2D::zero)
    )
{
    // Not periodic: the box is the walls' own
    vector2D lo, hi;
    bounds(lo, hi);
    domain_ = SPH::domain(lo, hi);
}


Foam::SPH::wallMesh::wallMesh
(
    const wordList& patchNames,
    const List<List<wallChain>>& patchChains,
    const scalar dr,
    const SPH::domain& dom
)
:
    patchNames_(patchNames),
    domain_(dom)
{
    forAll(patchChains, patchi)
    {
        for (const wallChain& c : patchChains[patchi])
        {
            addChain(c, patchi, dr);
        }
    }
    // Only a domain periodic in x and y can do without walls (a
    // Taylor-Green vortex)
    if (segments_.empty() && !(domain_.periodic(0) && domain_.periodic(1)))
    {
        FatalErrorInFunction
            << "No wall segments: at least one wall patch is needed, unless"
            << " the domain is periodic in x and y" << exit(FatalError);
    }
    calcGeometry();
}


Foam::SPH::wallMesh::wallMesh(const SPH::domain& dom)
:
    domain_(dom)
{
    calcGeometry();
}


Foam::SPH::wallMesh::wallMesh(const objectRegistry& db)
:
    domain_(vector2D::zero, vector2D::zero)
{
    const word inst = db.time().constant();
    auto io = [&](const word& name)
    {
        return IOobject(name, inst, wallsLocal, db, IOobject::MUST_READ,
                        IOobject::NO_WRITE, false);
    };

    patchNames_ = IOList<word>(io("patchNames"));
    points_ = List<vector2D>(vector2DIOField(io("points")));
    pointPatch_ = labelList(labelIOField(io("pointPatch")));
    segments_ = List<labelPair>(IOList<labelPair>(io("segments")));
    segmentPatch_ = labelList(labelIOField(io("segmentPatch")));

    segmentIn_ = labelList(points_.size(), -1);
    segmentOut_ = labelList(points_.size(), -1);
    forAll(segments_, s)
    {
        const labelPair& e = segments_[s];
        if (min(e.first(), e.second()) < 0 || max(e.first(), e.second()) >= points_.size())
        {
            FatalErrorInFunction
                << "Segment " << s << " " << e << " in "
                << io("segments").objectPath() << " refers to a vertex outside 0.."
                << points_.size() - 1 << exit(FatalError);
        }
        segmentOut_[e.first()] = s;
        segmentIn_[e.second()] = s;
    }

    vector2D lo, hi;
    bounds(lo, hi);
    domain_ = SPH::domain(db, lo, hi);
    calcGeometry();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallMesh::chainBounds
(
    const List<List<wallChain>>& patchChains,
    vector2D& lo,
    vector2D& hi
)
{
    lo = vector2D(GREAT, GREAT);
    hi = vector2D(-GREAT, -GREAT);
    for (const List<wallChain>& chains : patchChains)
    {
        for (const wallChain& c : chains)
        {
            for (const vector2D& p : c.points)
            {
                lo = min(lo, p);
                hi = max(hi, p);
            }
        }
    }
}


Foam::scalar Foam::SPH::wallMesh::segmentLength(label s) const
{
    return mag(segmentVector(s));
}


Foam::vector2D Foam::SPH::wallMesh::segmentVector(label s) const
{
    return domain_.separation
    (
        points_[segments_[s].second()],
        points_[segments_[s].first()]
    );
}


void Foam::SPH::wallMesh::bounds(vector2D& lo, vector2D& hi) const
{
    lo = vector2D(GREAT, GREAT);
    hi = vector2D(-GREAT, -GREAT);
    for (const vector2D& p : points_)
    {
        lo = min(lo, p);
        hi = max(hi, p);
    }
}


Foam::List<Foam::labelList> Foam::SPH::wallMesh::tracedChains() const
{
    DynamicList<labelList> chains;
    boolList visited(segments_.size(), false);

    auto trace = [&](label s)
    {
        DynamicList<label> verts;
        verts.append(segments_[s].first());
        while (s >= 0 && !visited[s])
        {
            visited[s] = true;
            verts.append(segments_[s].second());
            s = segmentOut_[segments_[s].second()];
        }
        chains.append(verts);
    };

    // Open chains start at vertices with no incoming segment
    forAll(points_, v)
    {
        if (segmentIn_[v] < 0 && segmentOut_[v] >= 0)
        {
            trace(segmentOut_[v]);
        }
    }
    // What is left are closed loops (first vertex repeated at the end)
    forAll(segments_, s)
    {
        if (!visited[s])
        {
            trace(s);
        }
    }
    return List<labelList>(std::move(chains));
}


Foam::List<Foam::vector2D> Foam::SPH::wallMesh::unwrappedChain
(
    const labelList& chain
) const
{
    List<vector2D> u(chain.size());
    u[0] = points_[chain[0]];
    for (label i = 1; i < chain.size(); ++i)
    {
        u[i] = domain_.image(points_[chain[i]], u[i - 1]);
    }
    return u;
}


Foam::labelList Foam::SPH::wallMesh::chainCorners(const labelList& chain) const
{
    const bool closed = chain.first() == chain.last();
    DynamicList<label> corners;
    for (label i = 0; i < chain.size() - 1; ++i)
    {
        const label sIn = segmentIn_[chain[i]];
        const vector2D outNormal(-segmentNormals_[segmentOut_[chain[i]]]);
        if
        (
            (i == 0 && !closed)
         || sIn < 0
         || mag(cross2D(segmentNormals_[sIn], outNormal)) > 1e-8
        )
        {
            corners.append(i);
        }
    }
    if (!closed)
    {
        corners.append(chain.size() - 1);
    }
    return labelList(std::move(corners));
}


Foam::List<Foam::vector2D> Foam::SPH::wallMesh::cornerOffsets
(
    const labelList& chain,
    const labelList& corners,
    const UList<vector2D>& unwrapped,
    const scalar d
) const
{
    const bool closed = chain.first() == chain.last();
    const label nSeg = chain.size() - 1;
    List<vector2D> offset(corners.size());
    forAll(corners, k)
    {
        const label i = corners[k];
        const label sIn = segmentIn_[chain[i]];
        const label sOut = segmentOut_[chain[i]];
        const bool hasIn = sIn >= 0 && (closed || i > 0);
        const bool hasOut = sOut >= 0 && (closed || i < nSeg);
        vector2D m;
        if (hasIn && hasOut)
        {
            // Mitred: the offset lines of both segments meet there; the
            // sharpest corners' mitre is capped at about 4.5 d
            const vector2D m1 = -segmentNormals_[sIn];
            const vector2D m2 = -segmentNormals_[sOut];
            const scalar c = 1 + (m1 & m2);
            m = (c > 0.1) ? (m1 + m2)/c : (m1 + m2)/0.1;
        }
        else
        {
            m = -segmentNormals_[hasIn ? sIn : sOut];
        }
        offset[k] = unwrapped[i] + d*m;
    }
    return offset;
}


bool Foam::SPH::wallMesh::offsetChain
(
    const labelList& chain,
    scalar d,
    scalar dr,
    DynamicList<vector2D>& pts,
    DynamicList<label>& patch
) const
{
    const bool closed = chain.first() == chain.last();
    const label nSeg = chain.size() - 1;
    const List<vector2D> u(unwrappedChain(chain));

    // A closed chain through a periodic seam ends one period from its start
    const vector2D closingShift(closed ? u[nSeg] - u[0] : vector2D::zero);
    const labelList knots(chainCorners(chain));

    // A closed chain without corners is a straight wall through a periodic
    // seam: its one edge runs from the middle of its first segment once
    // round the period, so that its dummies sit opposite the segments'
    // midpoints, where the fluid lattice's columns are
    if (knots.empty())
    {
        const vector2D outNormal(-segmentNormals_[segmentOut_[chain[0]]]);
        const vector2D start(0.5*(u[0] + u[1]) + d*outNormal);
        const label patchi = segmentPatch_[segmentOut_[chain[0]]];
        appendPieces(start, closingShift, dr, false, patchi, pts, patch);
        return mag(closingShift) > 0;
    }

    // Split every offset edge into pieces of about dr. A reversed edge has
    // collapsed: a wall shorter than the offset between two corners turning
    // the same way (the narrow crest of a weir plate). It is left out; its
    // neighbours' offsets overlap there, and the caller drops the overlap.
    const List<vector2D> offset(cornerOffsets(chain, knots, u, d));
    const label nEdges = closed ? knots.size() : knots.size() - 1;
    bool any = false;
    for (label e = 0; e < nEdges; ++e)
    {
        const label k1 = (e + 1) % knots.size();
        const bool closing = closed && k1 == 0;
        const vector2D a = offset[e];
        const vector2D b =
            (closing && domain_.anyPeriodic()) ? offset[k1] + closingShift : offset[k1];
        const vector2D orig = u[closing ? nSeg : knots[k1]] - u[knots[e]];
        if (((b - a) & orig) <= 0)
        {
            continue;
        }
        any = true;
        const label patchi = segmentPatch_[segmentOut_[chain[knots[e]]]];
        const bool lastOfOpen = !closed && e == nEdges - 1;
        appendPieces(a, b - a, dr, lastOfOpen, patchi, pts, patch);
    }
    return any;
}


Foam::labelList Foam::SPH::wallMesh::spacedOutside
(
    const UList<vector2D>& pts,
    const scalar dr
) const
{
    // The grid's cells are dr/2; in a periodic direction they tile the
    // period (a whole number of cells, each at least dr/2) and the
    // neighbour cells wrap, so a point just across the seam is seen too
    const scalar cell = 0.5*dr;
    FixedList<int64_t, 2> nPeriod(int64_t(0));
    vector2D periodCell(cell, cell);
    for (direction k = 0; k < 2; ++k)
    {
        if (domain_.periodic(k))
        {
            nPeriod[k] = max(int64_t(1), int64_t(std::floor(domain_.period()[k]/cell)));
            periodCell[k] = domain_.period()[k]/nPeriod[k];
        }
    }
    auto cellCoord = [&](const vector2D& p, const direction k) -> int64_t
    {
        if (!nPeriod[k])
        {
            return std::floor(p[k]/cell);
        }
        const int64_t c = std::floor((p[k] - domain_.min()[k])/periodCell[k]);
        return min(max(c, int64_t(0)), nPeriod[k] - 1);
    };
    auto wrapCoord = [&](const int64_t c, const direction k) -> int64_t
    {
        return nPeriod[k] ? (c + nPeriod[k]) % nPeriod[k] : c;
    };
    std::unordered_map<int64_t, DynamicList<label>> grid;
    auto key = [](int64_t i, int64_t j) { return (i << 32) ^ (j & 0xffffffff); };

    DynamicList<label> keep;
    forAll(pts, i)
    {
        const vector2D& p = pts[i];
        if (signedDistance(p) > -0.25*dr)
        {
            continue;
        }
        const int64_t ci = cellCoord(p, 0);
        const int64_t cj = cellCoord(p, 1);
        bool clash = false;
        for (int64_t di = -1; di <= 1 && !clash; ++di)
        {
            for (int64_t dj = -1; dj <= 1 && !clash; ++dj)
            {
                auto it = grid.find(key(wrapCoord(ci + di, 0), wrapCoord(cj + dj, 1)));
                if (it == grid.end()) continue;
                for (const label j : it->second)
                {
                    if (mag(domain_.separation(pts[j], p)) < 0.5*dr - 1e-9*dr)
                    {
                        clash = true;
                        break;
                    }
                }
            }
        }
        if (!clash)
        {
            grid[key(ci, cj)].append(i);
            keep.append(i);
        }
    }
    return labelList(std::move(keep));
}


void Foam::SPH::wallMesh::dummyLayers
(
    label nLayers,
    scalar dr,
    List<vector2D>& positions,
    labelList& layer,
    labelList& patch
) const
{
    // Layer k lies (k + 1/2) dr outside the wall: the fluid lattice (dr/2
    // inside) continued through the wall, so the particle density is
    // uniform across it and layer 0, the one next to the wall, repels
    DynamicList<vector2D> pts;
    DynamicList<label> lay;
    DynamicList<label> pat;

    const List<labelList> chains(tracedChains());
    for (label k = 0; k < nLayers; ++k)
    {
        for (const labelList& chain : chains)
        {
            if (offsetChain(chain, (k + 0.5)*dr, dr, pts, pat))
            {
                lay.setSize(pts.size(), k);
            }
        }
    }

    // Offsets of a chain through a periodic seam run past it: back into
    // the box
    for (vector2D& p : pts)
    {
        p = domain_.wrap(p);
    }

    // Where chains meet or overlap, the dummies of both are there
    const labelList keep(spacedOutside(pts, dr));
    positions = UIndirectList<vector2D>(pts, keep);
    layer = UIndirectList<label>(lay, keep);
    patch = UIndirectList<label>(pat, keep);
}


Foam::labelList Foam::SPH::wallMesh::unmatchedSeamEnds(const scalar tol) const
{
    DynamicList<label> ends;
    forAll(points_, v)
    {
        if
        (
            (segmentIn_[v] < 0 || segmentOut_[v] < 0)
         && domain_.onSeam(points_[v], tol)
        )
        {
            ends.append(v);
        }
    }
    return labelList(std::move(ends));
}


Foam::labelList Foam::SPH::wallMesh::seamSegments(const scalar tol) const
{
    DynamicList<label> along;
    forAll(segments_, s)
    {
        const vector2D& a = points_[segments_[s].first()];
        const vector2D b(a + segmentVector(s));
        for (direction k = 0; k < 2; ++k)
        {
            if
            (
                domain_.periodic(k)
             && mag(b[k] - a[k]) <= tol
             && (
                    mag(a[k] - domain_.min()[k]) <= tol
                 || mag(a[k] - domain_.max()[k]) <= tol
                )
            )
            {
                along.append(s);
                break;
            }
        }
    }
    return labelList(std::move(along));
}


void Foam::SPH::wallMesh::patchCounts(labelList& nPoints, labelList& nSegments) const
{
    nPoints.setSize(patchNames_.size(), 0);
    nSegments.setSize(patchNames_.size(), 0);
    for (const label p : pointPatch_) ++nPoints[p];
    for (const label p : segmentPatch_) ++nSegments[p];
}


void Foam::SPH::wallMesh::write
(
    const objectRegistry& db,
    const fileName& local
) const
{
    const word inst = db.time().constant();
    auto io = [&](const word& name)
    {
        return IOobject(name, inst, local/"walls", db, IOobject::NO_READ,
                        IOobject::NO_WRITE, false);
    };

    IOList<word>(io("patchNames"), patchNames_).write();
    vector2DIOField(io("points"), points_).write();
    labelIOField(io("pointPatch"), pointPatch_).write();
    vector2DIOField(io("pointNormals"), pointNormals_).write();
    scalarIOField(io("pointAngles"), pointAngles_).write();
    IOList<labelPair>(io("segments"), segments_).write();
    vector2DIOField(io("segmentNormals"), segmentNormals_).write();
    labelIOField(io("segmentPatch"), segmentPatch_).write();
}


// ************************************************************************* //
