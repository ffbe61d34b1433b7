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


bool Foam::SPH::particleGenerator::readUsaw(const Time& runTime)
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
    return schemes.getOrDefault<word>("boundaryMethod", word::null) == "usaw";
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

    // USAW walls (000_8c7cd3aabddcf18a.txt) are the vertices and segments
    // alone: no particle behind them
    if (usaw_)
    {
        Info<< "No dummy particles: boundaryMethod usaw in system/sphSchemes"
            << nl;
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

    // Layer k sits (k + 1/2) dr outside the wall and the first fluid
    // particle dr/2 inside it: enough layers to fill its kernel support
    const autoPtr<kernel> k(kernel::New(schemes, dr_));
    return max(label(1), label(std::floor(k->support()/dr_ + 1e-9)));
}


void Foam::SPH::particleGenerator::checkSpacing() const
{
    vector2D lo, hi;
    walls_->bounds(lo, hi);
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
    // row lies dr from them
    vector2D wlo, whi;
    walls_->bounds(wlo, whi);
    const vector2D corner(usaw_ ? wlo - 0.5*vector2D(dr_, dr_) : wlo);
    const vector2D origin(dict_.getOrDefault<vector2D>("latticeOrigin", corner));

    // Lattice indices covering [lo, hi]
    const label i0 = label(std::floor((lo.x() - origin.x())/dr_ - 0.5));
    const label i1 = label(std::ceil((hi.x() - origin.x())/dr_ - 0.5));
    const label j0 = label(std::floor((lo.y() - origin.y())/dr_ - 0.5));
    const label j1 = label(std::ceil((hi.y() - origin.y())/dr_ - 0.5));

    // dr/2 from the walls, less round-off
    const scalar minDist = 0.5*dr_*(1 - 1e-6);

    DynamicList<vector2D> pts;
    label nOutside = 0;
    vector2D example(vector2D::zero);
    for (label j = j0; j <= j1; ++j)
    {
        for (label i = i0; i <= i1; ++i)
        {
            const vector2D p(origin + dr_*vector2D(i + 0.5, j + 0.5));
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
    usaw_(readUsaw(runTime))
{
    Info<< "Particle spacing dr = " << dr_ << nl;

    if (mesh)
    {
        const dictionary& pmDict = dict_.subOrEmptyDict("fromPolyMesh");
        const wordList patches(pmDict.getOrDefault<wordList>("wallPatches", wordList()));
        polyMeshWalls pm(*mesh, patches);
        walls_.reset(new wallMesh(pm.patchNames(), pm.chains(), dr_));
        checkSpacing();

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
        const dictionary& wallsDict = dict_.subDict("walls");
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
        walls_.reset(new wallMesh(names, chains, dr_));
        checkSpacing();

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

    Info<< "Written " << runTime_.path()/inst/"sphMesh" << nl;
}


// ************************************************************************* //
