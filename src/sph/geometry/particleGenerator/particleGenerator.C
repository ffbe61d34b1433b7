/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "particleGenerator.H"
#include "polyMeshWalls.H"
#include "fluidRegion.H"
#include "kernel.H"
#include "particles.H"
#include "polyMesh.H"
#include "Time.H"
#include "IOmanip.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::particleGenerator::readSpacing() const
{
    const scalar dr = dict_.get<scalar>("dr");
    if (dr <= 0)
    {
        // The entry's own stream: the error names its line
        FatalIOErrorInFunction(dict_.lookup("dr"))
            << "Entry 'dr' (particle spacing) is " << dr
            << "; expected a positive length in metres" << nl
            << exit(FatalIOError);
    }
    return dr;
}


Foam::autoPtr<Foam::SPH::wallModel>
Foam::SPH::particleGenerator::readWallModel(const Time& runTime)
{
    const IOdictionary schemes
    (
        IOobject
        (
            "sphSchemes",
            runTime.system(),
            runTime,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );
    return wallModel::New(schemes);
}


Foam::label Foam::SPH::particleGenerator::dummyLayerCount() const
{
    label n = 0;
    if (dict_.readIfPresent("nDummyLayers", n))
    {
        if (n < 1)
        {
            FatalIOErrorInFunction(dict_.lookup("nDummyLayers"))
                << "Entry 'nDummyLayers' is " << n << "; expected at least 1"
                << " (the layer on the wall)" << nl << exit(FatalIOError);
        }
        return n;
    }

    if (!wallModel_->particlesBehindWalls())
    {
        Info<< "No dummy particles: boundaryMethod " << wallModel_->type()
            << " in system/sphSchemes" << nl;
        return 0;
    }

    IOdictionary schemes
    (
        IOobject
        (
            "sphSchemes",
            runTime_.system(),
            runTime_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    const autoPtr<kernel> k(kernel::New(schemes, dr_));
    return wallModel_->defaultDummyLayers(*k, dr_);
}


const Foam::dictionary& Foam::SPH::particleGenerator::patchDict
(
    const word& patch
) const
{
    const dictionary* walls = dict_.findDict("walls");
    if (walls && walls->findDict(patch))
    {
        return walls->subDict(patch);
    }
    return dict_;
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


void Foam::SPH::particleGenerator::makeWalls
(
    const wordList& patchNames,
    const List<List<wallChain>>& patchChains
)
{
    vector2D lo, hi;
    wallMesh::chainBounds(patchChains, lo, hi);
    const SPH::domain dom(dict_, lo, hi);
    checkPeriodic(dom, patchNames, patchChains);

    walls_.reset(new wallMesh(patchNames, patchChains, dr_, dom));
    walls_->domain().report(Info);
    checkSeams();
    checkSpacing();
}


void Foam::SPH::particleGenerator::checkSpacing() const
{
    // The walls' extent, or the period in a periodic direction (which
    // walls need not span)
    const SPH::domain& dom = walls_->domain();
    vector2D lo, hi;
    walls_->bounds(lo, hi);
    for (direction d = 0; d < 2; ++d)
    {
        if (dom.periodic(d))
        {
            lo[d] = dom.min()[d];
            hi[d] = dom.max()[d];
        }
    }
    const scalar extent = max(hi.x() - lo.x(), hi.y() - lo.y());
    if (dr_ >= extent)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'dr' " << dr_ << " is not smaller than the walls' extent "
            << extent << " (from " << lo << " to " << hi << ")" << nl
            << exit(FatalIOError);
    }
}


void Foam::SPH::particleGenerator::seedFluid
(
    const std::function<bool(const vector2D&)>& isFluid,
    const vector2D& lo,
    const vector2D& hi,
    bool outsideIsError
)
{
    // USAW: the nodes k dr of the walls' corner, so that straight walls
    // through it carry the lattice's edge nodes (the vertex particles,
    // truncated fluid particles of 000_... section 2) and the first fluid
    // row lies dr from them. In a periodic direction the corner is the
    // periodic box's, walls or not
    const SPH::domain& dom = walls_->domain();
    vector2D wlo, whi;
    walls_->bounds(wlo, whi);
    for (direction d = 0; d < 2; ++d)
    {
        if (dom.periodic(d))
        {
            wlo[d] = dom.min()[d];
        }
    }
    const vector2D corner(wallModel_->latticeCorner(wlo, dr_));
    const vector2D origin(dict_.getOrDefault<vector2D>("latticeOrigin", corner));

    // Lattice indices covering [lo, hi]; in a periodic direction exactly
    // one period of them from the first node at or above min, so that the
    // lattice tiles [min, max) and continues across the seam
    FixedList<label, 2> first, last;
    for (direction d = 0; d < 2; ++d)
    {
        if (dom.periodic(d))
        {
            first[d] = label(std::ceil((dom.min()[d] - origin[d])/dr_ - 0.5 - 1e-6));
            last[d] = first[d] + label(std::round(dom.period()[d]/dr_)) - 1;
        }
        else
        {
            first[d] = label(std::floor((lo[d] - origin[d])/dr_ - 0.5));
            last[d] = label(std::ceil((hi[d] - origin[d])/dr_ - 0.5));
        }
    }
    const label i0 = first[0], i1 = last[0];
    const label j0 = first[1], j1 = last[1];

    // dr/2 from the walls, less round-off
    const scalar minDist = 0.5*dr_*(1 - 1e-6);

    DynamicList<vector2D> pts;
    label nOutside = 0;
    vector2D example(vector2D::zero);
    for (label j = j0; j <= j1; ++j)
    {
        for (label i = i0; i <= i1; ++i)
        {
            // Wrapped: a node a rounding below min is min itself
            const vector2D p(dom.wrap(origin + dr_*vector2D(i + 0.5, j + 0.5)));
            if (!isFluid(p))
            {
                continue;
            }
            const scalar d = walls_->signedDistance(p);
            if (d >= minDist)
            {
                pts.append(p);
            }
            else if (d < -minDist && !nOutside++)
            {
                example = p;
            }
        }
    }

    if (outsideIsError && nOutside)
    {
        FatalIOErrorInFunction(dict_.subDict("fluid"))
            << nOutside << " lattice points of the fluid regions lie outside"
            << " the walls, e.g. " << example << " at distance "
            << -walls_->signedDistance(example) << " behind a wall." << nl
            << "The fluid must lie on the fluid side of the walls"
            << " (check the regions and the walls' 'side')." << nl
            << exit(FatalIOError);
    }
    fluid_.transfer(pts);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::particleGenerator::particleGenerator
(
    const Time& runTime,
    const polyMesh* mesh
)
:
    runTime_(runTime),
    dict_
    (
        IOobject
        (
            "sphMeshDict",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    ),
    dr_(readSpacing()),
    wallModel_(readWallModel(runTime))
{
    Info<< "Particle spacing dr = " << dr_ << nl;

    if (mesh)
    {
        const dictionary& pmDict = dict_.subOrEmptyDict("fromPolyMesh");
        const wordList patches(pmDict.getOrDefault<wordList>("wallPatches", wordList()));
        polyMeshWalls pm(*mesh, patches);
        makeWalls(pm.patchNames(), pm.chains());

        vector2D lo, hi;
        pm.bounds(lo, hi);
        if (dict_.found("fluid"))
        {
            const fluidRegion regions(dict_.subDict("fluid"));
            Info<< "Fluid from the regions in " << dict_.name() << nl;
            seedFluid
            (
                [&](const vector2D& p) { return pm.inside(p) && regions.contains(p); },
                lo, hi, false
            );
        }
        else
        {
            const word field(pmDict.getOrDefault<word>("field", "alpha.water"));
            Info<< "Fluid where " << field << " > 0.5 in "
                << runTime.timeName() << "/" << field << nl;
            pm.readFraction(field);
            seedFluid([&](const vector2D& p) { return pm.isFluid(p); }, lo, hi, false);
        }
    }
    else
    {
        // A domain periodic in x and y needs no walls
        const FixedList<bool, 2> periodic
        (
            SPH::domain(dict_, vector2D::zero, vector2D::zero).periodic()
        );
        const dictionary& wallsDict =
            (periodic[0] && periodic[1])
          ? dict_.subOrEmptyDict("walls")
          : dict_.subDict("walls");
        wordList names(wallsDict.toc());
        List<List<wallChain>> chains(names.size());
        label n = 0;
        for (const entry& e : wallsDict)
        {
            if (!e.isDict()) continue;
            names[n] = e.keyword();
            chains[n] = wallShape::New(e.keyword(), e.dict())->chains(dr_);
            ++n;
        }
        names.setSize(n);
        chains.setSize(n);
        makeWalls(names, chains);

        const fluidRegion regions(dict_.subDict("fluid"));
        vector2D lo, hi;
        walls_->bounds(lo, hi);
        const vector2D margin = 0.5*(hi - lo) + vector2D(dr_, dr_);
        seedFluid
        (
            [&](const vector2D& p) { return regions.contains(p); },
            lo - margin, hi + margin, true
        );
    }

    if (fluid_.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "No fluid particle: the fluid lies outside every wall, or"
            << " nowhere dr/2 away from them (dr = " << dr_ << ")" << nl
            << exit(FatalIOError);
    }

    const label nLayers = dummyLayerCount();
    Info<< "Dummy particle layers: " << nLayers << nl;
    walls_->dummyLayers(nLayers, dr_, dummy_, dummyLayer_, dummyPatch_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::particleGenerator::report() const
{
    labelList nPts, nSeg;
    walls_->patchCounts(nPts, nSeg);
    labelList nDummy(nPts.size(), 0);
    for (const label p : dummyPatch_) ++nDummy[p];

    Info<< nl << "Fluid particles: " << fluid_.size() << nl
        << "Wall vertices:   " << walls_->points().size() << nl
        << "Wall segments:   " << walls_->segments().size() << nl
        << "Dummy particles: " << dummy_.size() << nl << nl
        << "    patch               vertices  segments   dummies" << nl;
    forAll(walls_->patchNames(), i)
    {
        Info<< "    " << setw(18) << walls_->patchNames()[i].c_str()
            << setw(10) << nPts[i] << setw(10) << nSeg[i]
            << setw(10) << nDummy[i] << nl;
    }
    Info<< endl;
}


void Foam::SPH::particleGenerator::write() const
{
    const word inst = runTime_.constant();

    particles fluid(runTime_, inst, "sphMesh/fluid", false);
    fluid.resize(fluid_.size());
    fluid.positions() = fluid_;
    fluid.write();

    particles dummy(runTime_, inst, "sphMesh/dummy", false);
    dummy.add<label>("layer");
    dummy.add<label>("patch");
    dummy.resize(dummy_.size());
    dummy.positions() = dummy_;
    dummy.field<label>("layer") = dummyLayer_;
    dummy.field<label>("patch") = dummyPatch_;
    dummy.write();

    walls_->write(runTime_);
    walls_->domain().write(runTime_);

    Info<< "Written " << runTime_.path()/inst/"sphMesh" << nl;
}


// ************************************************************************* //
