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
#include "OSspecific.H"
#include <unistd.h>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::particleGenerator::readSpacing() const
{
    const scalar dr = dict_.get<scalar>("dr");
    // Written as !(in range) so that NaN is refused too; the bounds keep
    // every ratio and product of lengths finite
    if (!(dr > 0) || !(dr >= 1e-15 && dr <= 1e6))
    {
        // The entry's own stream: the error names its line
        FatalIOErrorInFunction(dict_.lookup("dr"))
            << "Entry 'dr' (particle spacing) is " << dr
            << "; expected a positive length in metres, from 1e-15 to 1e6"
            << nl << exit(FatalIOError);
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
        if (n < 1 || n > 100)
        {
            FatalIOErrorInFunction(dict_.lookup("nDummyLayers"))
                << "Entry 'nDummyLayers' is " << n << "; expected 1 (the"
                << " layer on the wall) to 100 (a kernel support reaches a"
                << " few spacings)" << nl << exit(FatalIOError);
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::particleGenerator::particleGenerator
(
    const Time& runTime,
    const polyMesh* mesh
)
:
    runTime_(runTime),
    reader_(runTime.path()/runTime.system()/"sphMeshDict"),
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
    maxParticles_(0),
    wallModel_(readWallModel(runTime)),
    nLayers_(0)
{
    // Read: the traps back, the numbers checked
    reader_.release();
    sphMeshInput::checkNumbers(dict_);
    maxParticles_ = readMaxParticles();
    Info<< "Particle spacing dr = " << dr_ << nl;
    checkWritable();

    if (mesh)
    {
        const dictionary& pmDict = dict_.subOrEmptyDict("fromPolyMesh");
        const wordList patches(pmDict.getOrDefault<wordList>("wallPatches", wordList()));
        polyMeshWalls pm(*mesh, patches);
        vector2D lo, hi;
        pm.bounds(lo, hi);
        checkRange(dict_, "The mesh in constant/polyMesh", lo, hi);
        makeWalls(pm.patchNames(), pm.chains());
        walls_->buildSearchGrid(2*dr_);
        nLayers_ = dummyLayerCount();
        scalar wallLength = 0;
        forAll(walls_->segments(), s) wallLength += walls_->segmentLength(s);
        estimateCounts
        (
            (hi.x() - lo.x())*(hi.y() - lo.y()), wallLength,
            walls_->patchNames().size(), lo, hi
        );

        if (dict_.found("fluid"))
        {
            const dictionary& fluidDict = requireDict("fluid");
            checkRegionNames(fluidDict);
            const fluidRegion regions(fluidDict);
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
        generateFromShapes();
    }

    if (fluid_.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "No fluid particle: the fluid lies outside every wall, or"
            << " nowhere dr/2 away from them (dr = " << dr_ << ")" << nl
            << exit(FatalIOError);
    }
    perturbFluid();

    Info<< "Dummy particle layers: " << nLayers_ << nl;
    walls_->dummyLayers(nLayers_, dr_, dummy_, dummyLayer_, dummyPatch_);
}


void Foam::SPH::particleGenerator::generateFromShapes()
{
    // A domain periodic in x and y needs no walls
    const FixedList<bool, 2> periodic
    (
        SPH::domain(dict_, vector2D::zero, vector2D::zero).periodic()
    );
    if (const dictionary* pd = dict_.findDict("periodic"))
    {
        const vector2D lo(pd->getOrDefault<vector2D>("min", vector2D::zero));
        const vector2D hi(pd->getOrDefault<vector2D>("max", vector2D::zero));
        checkRange(*pd, "The periodic box", lo, hi);
    }
    const dictionary emptyWalls;
    const dictionary& wallsDict =
        (periodic[0] && periodic[1] && !dict_.found("walls"))
      ? emptyWalls
      : requireDict("walls");

    wordList names;
    PtrList<wallShape> shapes;
    readShapes(wallsDict, names, shapes);
    if (shapes.empty() && !(periodic[0] && periodic[1]))
    {
        FatalIOErrorInFunction(wallsDict)
            << "No wall patch in walls: at least one is needed, unless the"
            << " domain is periodic in x and y (entry 'periodic')" << nl
            << exit(FatalIOError);
    }

    const dictionary& fluidDict = requireDict("fluid");
    checkRegionNames(fluidDict);
    const fluidRegion regions(fluidDict);
    const boundBox2D fb(regions.bounds());
    checkRange(fluidDict, "The fluid", fb.min(), fb.max());
    if (dict_.found("latticeOrigin"))
    {
        const vector2D o(dict_.get<vector2D>("latticeOrigin"));
        checkRange(dict_, "Entry 'latticeOrigin'", o, o);
    }

    // The counts before anything is split or seeded
    nLayers_ = dummyLayerCount();
    scalar fluidArea = 0, wallLength = 0;
    forAll(regions.regions(), i)
    {
        if (regions.operations()[i] == fluidRegion::operation::add)
        {
            fluidArea += regions.regions()[i].area();
        }
    }
    for (const wallShape& w : shapes)
    {
        wallLength += w.length();
    }
    estimateCounts(fluidArea, wallLength, shapes.size(), fb.min(), fb.max());

    List<List<wallChain>> chains(shapes.size());
    forAll(shapes, i)
    {
        chains[i] = shapes[i].chains(dr_);
    }
    makeWalls(names, chains);
    walls_->buildSearchGrid(2*dr_);
    checkCrossings();
    checkRegions(regions);

    // The lattice over the fluid's box, a spacing more each side: every
    // point of the fluid is seeded or counted as outside the walls
    const vector2D grow(dr_, dr_);
    seedFluid
    (
        [&](const vector2D& p) { return regions.contains(p); },
        fb.min() - grow, fb.max() + grow, true
    );
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


// ************************************************************************* //
