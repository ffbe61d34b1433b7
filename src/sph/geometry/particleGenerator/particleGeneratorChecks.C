/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The checks particleGenerator makes before it seeds anything and before
    it writes (issue 12): ranges relative to dr, the estimated counts, the
    names, crossing walls, the fluid regions against the walls, the
    periodic box and seams.

\*---------------------------------------------------------------------------*/

#include "particleGenerator.H"
#include "Time.H"
#include "OSspecific.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Local Data  * * * * * * * * * * * * * * * * //

namespace
{
    //- Coordinates within this many spacings of (0 0): lattice indices
    //- fit a 32-bit label twenty times over
    const Foam::scalar maxSpacings = 1e8;

    //- Default maxParticles
    const Foam::scalar defaultMaxParticles = 5e7;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::particleGenerator::readMaxParticles() const
{
    const scalar n = dict_.getOrDefault<scalar>("maxParticles", defaultMaxParticles);
    if (!(n >= 1 && n <= 2e9))
    {
        FatalIOErrorInFunction(dict_.lookup("maxParticles"))
            << "Entry 'maxParticles' is " << n << "; expected a number of"
            << " particles from 1 to 2e9" << nl << exit(FatalIOError);
    }
    return n;
}


const Foam::dictionary& Foam::SPH::particleGenerator::requireDict
(
    const word& key
) const
{
    if (!dict_.isDict(key))
    {
        if (dict_.found(key))
        {
            FatalIOErrorInFunction(dict_.lookup(key))
                << "Entry '" << key << "' must be a dictionary of named "
                << (key == "walls" ? "wall patches" : "regions") << ", as"
                << nl << "    " << key << " { name { type box; min (0 0);"
                << " max (1 1); } }" << nl << exit(FatalIOError);
        }
        FatalIOErrorInFunction(dict_)
            << "Entry '" << key << "' is missing: expected" << nl
            << "    " << key << " { name { type box; min (0 0); max (1 1); } }"
            << nl << exit(FatalIOError);
    }
    return dict_.subDict(key);
}


void Foam::SPH::particleGenerator::checkRange
(
    const dictionary& d,
    const std::string& what,
    const vector2D& lo,
    const vector2D& hi
) const
{
    const scalar limit = maxSpacings*dr_;
    for (direction k = 0; k < 2; ++k)
    {
        if (!(mag(lo[k]) <= limit && mag(hi[k]) <= limit))
        {
            FatalIOErrorInFunction(d)
                << what.c_str() << " reaches from " << lo << " to " << hi
                << ": beyond " << maxSpacings << " spacings dr ("
                << limit << ") from (0 0), where the particle lattice loses"
                << " its indices and precision." << nl << "Keep every"
                << " coordinate within " << limit << " of the origin, or"
                << " take a larger dr (now " << dr_ << ")" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::SPH::particleGenerator::readShapes
(
    const dictionary& wallsDict,
    wordList& names,
    PtrList<wallShape>& shapes
) const
{
    for (const entry& e : wallsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(wallsDict)
                << "Entry '" << e.keyword() << "' of walls is not a wall"
                << " patch: expected a sub-dictionary " << e.keyword()
                << " { type <shape>; ... }" << nl << exit(FatalIOError);
        }
        sphMeshInput::checkName(e, wallsDict, "wall patch");
        names.append(e.keyword());
        shapes.append(wallShape::New(e.keyword(), e.dict()));

        vector2D lo, hi;
        shapes.last().bounds(lo, hi);
        checkRange(e.dict(), "Wall patch " + e.keyword(), lo, hi);
        shapes.last().checkSpacing(dr_);
    }
}


void Foam::SPH::particleGenerator::checkRegionNames
(
    const dictionary& fluidDict
) const
{
    for (const entry& e : fluidDict)
    {
        sphMeshInput::checkName(e, fluidDict, "fluid region");
    }
}


void Foam::SPH::particleGenerator::estimateCounts
(
    const scalar fluidArea,
    const scalar wallLength,
    const label nShapes,
    const vector2D& latticeLo,
    const vector2D& latticeHi
) const
{
    // Wall vertices about dr apart; dummy layer k about (k + 1/2) dr out,
    // longer by about 8 (k + 1/2) dr round each closed shape
    const scalar nFluid = fluidArea/sqr(dr_);
    const scalar nWall = wallLength/dr_;
    const scalar nDummy = nLayers_*(nWall + 4*nLayers_*nShapes);
    const scalar total = nFluid + nWall + nDummy;
    const vector2D span(latticeHi - latticeLo);
    const scalar nLattice = (span.x()/dr_ + 2)*(span.y()/dr_ + 2);

    Info<< "Estimated: " << nFluid << " fluid particles, " << nWall
        << " wall vertices, " << nDummy << " dummy particles; "
        << nLattice << " lattice points to test" << nl;

    if (total > maxParticles_ || nLattice > 4*maxParticles_)
    {
        FatalIOErrorInFunction(dict_)
            << "The mesh would hold about " << total << " particles ("
            << nFluid << " fluid over an area of " << fluidArea << ", "
            << nWall << " wall vertices along " << wallLength << " of wall, "
            << nDummy << " dummies in " << nLayers_ << " layers) and test "
            << nLattice << " lattice points, more than maxParticles = "
            << maxParticles_ << " (4 maxParticles lattice points)." << nl
            << "Take a larger dr (now " << dr_ << "), a smaller domain, or"
            << " raise the entry 'maxParticles' of sphMeshDict (default "
            << defaultMaxParticles << ")" << nl << exit(FatalIOError);
    }
}


void Foam::SPH::particleGenerator::checkCrossings() const
{
    label s = -1, t = -1;
    bool overlap = false;
    if (!walls_->findCrossing(1e-6*dr_, s, t, overlap))
    {
        return;
    }
    const wallMesh& w = *walls_;
    const word& ps = w.patchNames()[w.segmentPatch()[s]];
    const word& pt = w.patchNames()[w.segmentPatch()[t]];
    auto seg = [&](const label i)
    {
        OStringStream os;
        os  << w.points()[w.segments()[i].first()] << " to "
            << w.points()[w.segments()[i].second()];
        return os.str();
    };
    FatalIOErrorInFunction(patchDict(pt))
        << (ps == pt ? "Wall patch " + ps + " " : "Wall patches " + ps + " and " + pt + " ").c_str()
        << (ps == pt
            ? (overlap ? "overlaps itself" : "crosses itself")
            : (overlap ? "overlap" : "cross"))
        << ": the segment " << seg(s).c_str() << (overlap ? " overlaps " : " crosses ")
        << seg(t).c_str() << "." << nl
        << "Walls may meet at their ends (a corner, a wall end on another"
        << " wall) but not cross or run along each other: a particle between"
        << " them would see two walls in one place" << nl << exit(FatalIOError);
}


void Foam::SPH::particleGenerator::fluidBox(vector2D& lo, vector2D& hi) const
{
    const SPH::domain& dom = walls_->domain();
    walls_->bounds(lo, hi);
    for (direction d = 0; d < 2; ++d)
    {
        if (dom.periodic(d))
        {
            lo[d] = dom.min()[d];
            hi[d] = dom.max()[d];
        }
    }
}


void Foam::SPH::particleGenerator::checkRegions(const fluidRegion& regions) const
{
    vector2D lo, hi;
    fluidBox(lo, hi);
    const scalar tol = 0.5*dr_;
    forAll(regions.regions(), i)
    {
        if (regions.operations()[i] != fluidRegion::operation::add)
        {
            continue;
        }
        const region& r = regions.regions()[i];
        const boundBox2D bb(r.bounds());
        const dictionary& rd = dict_.subDict("fluid").subDict(r.name());
        const scalar across = min(bb.span().x(), bb.span().y());
        if (across < 2*dr_)
        {
            FatalIOErrorInFunction(rd)
                << "Fluid region " << r.name() << " is " << across
                << " across, less than 2 spacings dr = " << dr_ << ": the"
                << " resolution is too coarse (fewer than 2 particles across"
                << " it). Take dr at most " << 0.5*across << nl
                << exit(FatalIOError);
        }
        for (direction d = 0; d < 2; ++d)
        {
            if
            (
                !walls_->domain().periodic(d)
             && (bb.min()[d] > hi[d] + tol || bb.max()[d] < lo[d] - tol)
            )
            {
                FatalIOErrorInFunction(rd)
                    << "Fluid region " << r.name() << " (" << bb.min()
                    << " to " << bb.max() << ") lies entirely outside the"
                    << " walls, whose box is " << lo << " to " << hi << nl
                    << exit(FatalIOError);
            }
        }
    }
}


void Foam::SPH::particleGenerator::checkPeriodic
(
    const SPH::domain& dom,
    const wordList& patchNames,
    const List<List<wallChain>>& patchChains
) const
{
    if (!dom.anyPeriodic())
    {
        return;
    }
    const dictionary& pd = dict_.subDict("periodic");

    // The lattice continues across the seam only if the period is a whole
    // number of spacings
    for (direction d = 0; d < 2; ++d)
    {
        if (!dom.periodic(d))
        {
            continue;
        }
        const scalar L = dom.period()[d];
        const scalar n = L/dr_;
        const scalar nLo = std::floor(n + 1e-6);
        const scalar nHi = nLo + 1;
        if (mag(n - std::round(n)) > 1e-6)
        {
            FatalIOErrorInFunction(pd)
                << "Entry 'periodic': the period in " << SPH::domain::axisNames[d]
                << ", max - min = " << L << ", is " << n << " spacings dr = "
                << dr_ << "; it must be a whole number of them, so that the"
                << " particle lattice continues across the seam." << nl
                << "Nearest valid periods: " << nLo*dr_ << " (" << nLo
                << " dr) or " << nHi*dr_ << " (" << nHi << " dr); or keep the"
                << " period and take dr = " << L/max(nLo, scalar(1)) << " or "
                << L/nHi << nl << exit(FatalIOError);
        }
    }

    // A wall may end on a seam, never run beyond it
    const scalar tol = 1e-6*dr_;
    forAll(patchChains, patchi)
    {
        for (const wallChain& c : patchChains[patchi])
        {
            for (const vector2D& p : c.points)
            {
                for (direction d = 0; d < 2; ++d)
                {
                    if
                    (
                        dom.periodic(d)
                     && (p[d] < dom.min()[d] - tol || p[d] > dom.max()[d] + tol)
                    )
                    {
                        FatalIOErrorInFunction(patchDict(patchNames[patchi]))
                            << "Wall patch " << patchNames[patchi] << ": point "
                            << p << " lies outside the periodic box, "
                            << SPH::domain::axisNames[d] << " from " << dom.min()[d]
                            << " to " << dom.max()[d] << " (entry 'periodic' of "
                            << "system/sphMeshDict). A wall that crosses the"
                            << " seam ends on it and continues from its image"
                            << " on the other side." << nl << exit(FatalIOError);
                    }
                }
            }
        }
    }
}


void Foam::SPH::particleGenerator::checkSeams() const
{
    const SPH::domain& dom = walls_->domain();
    if (!dom.anyPeriodic())
    {
        return;
    }
    const scalar tol = 1e-6*dr_;

    const labelList ends(walls_->unmatchedSeamEnds(tol));
    if (ends.size())
    {
        // Each end as the point in the box and the same point across the
        // seam, the one the user may have written
        auto across = [&](const vector2D& p)
        {
            vector2D other(p);
            for (direction d = 0; d < 2; ++d)
            {
                if (dom.periodic(d) && mag(p[d] - dom.min()[d]) <= tol)
                {
                    other[d] += dom.period()[d];
                }
            }
            return other;
        };
        const label v0 = ends.first();
        const word& patch = walls_->patchNames()[walls_->pointPatch()[v0]];

        FatalIOErrorInFunction(patchDict(patch))
            << "Wall patch " << patch << " ends on a periodic seam where no"
            << " wall continues on the other side. Wall ends on a seam with no"
            << " partner at their image:" << nl;
        for (const label v : ends)
        {
            const vector2D& p = walls_->points()[v];
            FatalIOError
                << "    " << walls_->patchNames()[walls_->pointPatch()[v]]
                << " at " << p << " = " << across(p) << nl;
        }
        FatalIOError
            << "A wall that crosses a periodic seam must continue from its"
            << " image, the same point a period away (the same y on both"
            << " sides of a seam in x), where sphMesh joins the two." << nl
            << exit(FatalIOError);
    }

    const labelList along(walls_->seamSegments(tol));
    if (along.size())
    {
        const label s = along.first();
        const word& patch = walls_->patchNames()[walls_->segmentPatch()[s]];
        FatalIOErrorInFunction(patchDict(patch))
            << "Wall patch " << patch << " runs along a periodic seam (segment"
            << " from " << walls_->points()[walls_->segments()[s].first()]
            << " to " << walls_->points()[walls_->segments()[s].second()]
            << "): it would lie on its own periodic image. Remove the wall"
            << " there or the periodicity (entry 'periodic' of system/sphMeshDict"
            << ")." << nl << exit(FatalIOError);
    }
}


// ************************************************************************* //
