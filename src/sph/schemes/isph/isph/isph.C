/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "isph.H"
#include "fluidProperties.H"
#include "Time.H"
#include "dimensionedScalar.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"
#include "OFstream.H"
#include "vtkParticleFile.H"
#include "vtkWallFile.H"
#include "fieldDictionary.H"
#include "usawOperators.H"
#include "kernelDispatch.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::isph::freeSurfaceMode>
Foam::SPH::isph::freeSurfaceModeNames
({
    { freeSurfaceMode::automatic, "auto" },
    { freeSurfaceMode::yes, "yes" },
    { freeSurfaceMode::no, "no" },
});


const Foam::Enum<Foam::SPH::isph::pressureGradientType>
Foam::SPH::isph::pressureGradientTypeNames
({
    { pressureGradientType::antisymmetric, "antisymmetric" },
    { pressureGradientType::renormalised, "renormalised" },
});


namespace
{
    // The walls' only method in ISPH-USAW
    enum class boundaryMethod { usaw };
    const Foam::Enum<boundaryMethod> boundaryMethodNames
    ({
        { boundaryMethod::usaw, "usaw" },
    });
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::isph::readPhysics()
{
    const fluidProperties fluid(runTime_);
    rho0_ = fluid.rho0;
    nu_ = fluid.nu;
    g_ = fluid.g;
}


void Foam::SPH::isph::readSchemes()
{
    boundaryMethodNames.get("boundaryMethod", schemes_);
    pressureGradient_ = pressureGradientTypeNames.getOrDefault
    (
        "pressureGradient", schemes_, pressureGradientType::renormalised
    );

    shifting_ = schemes_.getOrDefault<bool>("shifting", true);
    // 000_... after eq. (36): "calibrated ... 0.7 for the Wendland kernel"
    shiftCoeff_ = schemes_.getOrDefault<scalar>("shiftCoeff", 0.7);
    if (!(shiftCoeff_ >= 0))
    {
        FatalIOErrorInFunction(schemes_.lookup("shiftCoeff"))
            << "Entry shiftCoeff " << shiftCoeff_ << ": expected >= 0"
            << exit(FatalIOError);
    }
    // Section 3.2: "D{r} <= 1.5 in 2-D"
    freeSurfaceDivR_ = schemes_.getOrDefault<scalar>("freeSurfaceDivR", 1.5);
    if (!(freeSurfaceDivR_ > 0 && freeSurfaceDivR_ < 2))
    {
        FatalIOErrorInFunction(schemes_.lookup("freeSurfaceDivR"))
            << "Entry freeSurfaceDivR " << freeSurfaceDivR_
            << ": expected 0 < freeSurfaceDivR < 2 (D{r} is 2 inside the"
            << " fluid)" << exit(FatalIOError);
    }
    minDeltaTFraction_ = schemes_.getOrDefault<scalar>("minDeltaTFraction", 1e-3);
    // Eq. (39)'s distance of a particle about to hit a wall
    minWallDistance_ =
        schemes_.getOrDefault<scalar>("minWallDistance", kernel_->support()/8);
    if (!(minWallDistance_ >= 0 && minWallDistance_ < dr_))
    {
        FatalIOErrorInFunction(schemes_)
            << "Entry minWallDistance " << minWallDistance_
            << ": expected 0 (off) or a distance below dr = " << dr_
            << exit(FatalIOError);
    }

    CCFL_ = runTime_.controlDict().getOrDefault<scalar>("maxCo", 0.2);
    if (!(CCFL_ > 0))
    {
        FatalIOErrorInFunction(runTime_.controlDict().lookup("maxCo"))
            << "Entry maxCo " << CCFL_ << ": expected C_CFL > 0"
            << exit(FatalIOError);
    }
}


void Foam::SPH::isph::readSolution()
{
    pSolver_ = linearSolver::New
    (
        "p",
        solution_.subDict("solvers").subDict("p")
    );

    const dictionary& controls = solution_.subOrEmptyDict("ISPH");
    stopIfNotConverged_ = controls.getOrDefault<bool>("stopIfNotConverged", true);
    diagonalReinforcement_ =
        controls.getOrDefault<scalar>("diagonalReinforcement", 1e-6);
    if (!(diagonalReinforcement_ >= 0))
    {
        FatalIOErrorInFunction(controls.lookup("diagonalReinforcement"))
            << "Entry diagonalReinforcement " << diagonalReinforcement_
            << ": expected >= 0" << exit(FatalIOError);
    }
    pRefValue_ = controls.getOrDefault<scalar>("pRefValue", 0);
}


void Foam::SPH::isph::readInitialVelocity()
{
    const fieldDictionary Udict
    (
        IOobject
        (
            "U", runTime_.timeName(), runTime_,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    vector2DField& U = parts_.field<vector2D>("U");
    if (!Udict.found("internalField"))
    {
        Info<< "No " << runTime_.timeName()/"U"
            << ": the fluid starts at rest" << nl;
        for (label i = 0; i < nFluid_; ++i)
        {
            U[i] = vector2D::zero;
        }
        return;
    }

    // As a finite-volume field: uniform, or one value per fluid particle
    // in the order of constant/sphMesh/fluid (what sphMapFields writes)
    ITstream& is = Udict.lookup("internalField");
    const word kind(is);
    if (kind == "uniform")
    {
        const vector v(is);
        for (label i = 0; i < nFluid_; ++i)
        {
            U[i] = vector2D(v.x(), v.y());
        }
        Info<< "Initial velocity " << U[0] << " from " << Udict.objectPath() << nl;
    }
    else if (kind == "nonuniform")
    {
        const vectorField values(is);
        if (values.size() != nFluid_)
        {
            FatalIOErrorInFunction(is)
                << "internalField nonuniform holds " << values.size()
                << " vectors: expected one per fluid particle of"
                << " constant/sphMesh/fluid, " << nFluid_ << exit(FatalIOError);
        }
        forAll(values, i)
        {
            U[i] = vector2D(values[i].x(), values[i].y());
        }
        Info<< "Initial velocity per particle from " << Udict.objectPath() << nl;
    }
    else
    {
        FatalIOErrorInFunction(is)
            << "Expected 'internalField uniform (Ux Uy Uz);' or"
            << " 'internalField nonuniform List<vector> N (...);', found "
            << kind << exit(FatalIOError);
    }
}


void Foam::SPH::isph::initialiseFromSphMesh()
{
    particles fluid(runTime_, runTime_.constant(), "sphMesh/fluid", false);
    fluid.read();

    nFluid_ = fluid.size();
    const List<vector2D>& vertices = walls_->points();
    parts_.resize(nFluid_ + vertices.size());

    vector2DField& x = parts_.positions();
    labelField& type = parts_.field<label>("type");
    labelField& patch = parts_.field<label>("patch");
    labelField& id = parts_.field<label>("id");
    forAll(fluid.positions(), i)
    {
        x[i] = fluid.positions()[i];
        type[i] = label(particleKind::fluid);
        patch[i] = -1;
    }
    forAll(vertices, v)
    {
        const label i = nFluid_ + v;
        x[i] = vertices[v];
        type[i] = label(particleKind::wallVertex);
        patch[i] = walls_->pointPatch()[v];
    }
    forAll(id, i)
    {
        id[i] = i;
    }
    readInitialVelocity();
}


void Foam::SPH::isph::initialise()
{
    parts_.add<vector2D>("U");
    parts_.add<scalar>("p");
    parts_.add<label>("id");
    parts_.add<label>("type");
    parts_.add<label>("patch");

    const label nVertices = walls_->points().size();
    if (isFile(parts_.path()/"positions"))
    {
        Info<< "Restarting from " << parts_.path() << nl;
        parts_.read();
        const labelField& type = parts_.field<label>("type");
        nFluid_ = 0;
        while (nFluid_ < type.size() && type[nFluid_] == label(particleKind::fluid))
        {
            ++nFluid_;
        }
        if (parts_.size() - nFluid_ != nVertices)
        {
            FatalErrorInFunction
                << parts_.path() << " holds " << parts_.size() - nFluid_
                << " wall particles after " << nFluid_ << " fluid ones, but"
                << " constant/sphMesh/walls has " << nVertices << " vertices:"
                << " the case was not made for ISPH-USAW (boundaryMethod usaw"
                << " before sphMesh)" << exit(FatalError);
        }
    }
    else
    {
        Info<< "Starting from the particles of constant/sphMesh" << nl;
        initialiseFromSphMesh();
    }

    // Density is rho everywhere (function objects read V_b = m/rho_b)
    parts_.add<scalar>("rho", rho0_, false);

    Info<< "Particles: " << nFluid_ << " fluid, " << nVertices
        << " wall vertices" << nl << endl;
}


void Foam::SPH::isph::decideFreeSurface(const freeSurfaceMode mode)
{
    if (mode != freeSurfaceMode::automatic)
    {
        freeSurface_ = (mode == freeSurfaceMode::yes);
        return;
    }

    // A confined flow fills its walls: D{r} is near 2 everywhere
    findNeighbours();
    dispatch(*kernel_, [&](const auto& K)
    {
        usaw::divPosition(K, nbrs_, *usaw_, V_, divR_);
    });
    nSurface_ = 0;
    for (label i = 0; i < nFluid_; ++i)
    {
        if (divR_[i] <= freeSurfaceDivR_) ++nSurface_;
    }
    freeSurface_ = nSurface_ > 0;
}


void Foam::SPH::isph::readState()
{
    const IOdictionary state
    (
        IOobject
        (
            "isphState", runTime_.timeName(), "uniform", runTime_,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    maxAccel_ = state.getOrDefault<scalar>("maxAcceleration", 0);
    lastDeltaT_ = state.getOrDefault<scalar>("deltaT", -1);
}


void Foam::SPH::isph::writeState() const
{
    // Seventeen digits give the double back exactly
    const fileName dir(runTime_.timePath()/"uniform");
    mkDir(dir);
    OFstream os(dir/"isphState");
    os.precision(17);
    IOobject
    (
        "isphState", runTime_.timeName(), "uniform", runTime_
    ).writeHeader(os, "dictionary");
    os.writeEntry("maxAcceleration", maxAccel_);
    os.writeEntry("deltaT", lastDeltaT_);
    IOobject::writeEndDivider(os);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::isph::isph(Time& runTime)
:
    runTime_(runTime),
    schemes_
    (
        IOobject
        (
            "sphSchemes", runTime.system(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    ),
    solution_
    (
        IOobject
        (
            "sphSolution", runTime.system(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    ),
    rho0_(0), nu_(0), g_(vector2D::zero),
    pressureGradient_(pressureGradientType::renormalised),
    shifting_(true), shiftCoeff_(0.7), freeSurfaceDivR_(1.5),
    minDeltaTFraction_(1e-3), stopIfNotConverged_(true),
    diagonalReinforcement_(1e-6), pRefValue_(0), CCFL_(0.2),
    dr_(0),
    parts_(runTime, runTime.timeName()),
    nFluid_(0),
    nbrs_(true),
    freeSurface_(false),
    maxAccelStart_(0),
    lastDeltaTStart_(-1),
    nSurface_(0),
    maxSpeed_(0), maxAccel_(0), lastDeltaT_(-1), maxShift_(0),
    nHeld_(0), nHeldTotal_(0),
    deltaT0_(-1),
    nSteps_(0),
    nSolverIterations_(0)
{
    readPhysics();
    {
        const IOdictionary meshDict
        (
            IOobject
            (
                "sphMeshDict", runTime.system(), runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            )
        );
        dr_ = meshDict.get<scalar>("dr");
    }
    kernel_ = kernel::New(schemes_, dr_);
    readSchemes();
    readSolution();

    walls_.reset(new wallMesh(runTime));
    motion_.reset(new wallBoundaries(runTime, *walls_));
    initialise();

    walls_->bounds(boxMin_, boxMax_);
    const vector2D margin =
        0.25*(boxMax_ - boxMin_) + vector2D(1, 1)*kernel_->support();
    boxMin_ -= margin;
    boxMax_ += margin;

    cloud_.reset
    (
        new sphCloud
        (
            runTime, parts_, *kernel_, *walls_, nFluid_, dr_, rho0_, g_,
            boxMin_, boxMax_
        )
    );
    usaw_.reset(new usawWalls(*walls_, *kernel_, nFluid_));
    if (!motion_->movesGeometry())
    {
        crossing_.reset(new wallCrossing(*walls_, kernel_->support()));
    }

    const label n = parts_.size();
    // Vertex particles are fluid particles cut by the wall (000_...
    // section 2): the share theta_v/(2 pi) of a particle's volume, so that
    // with the first row dr from the wall the volumes tile the fluid
    V_.setSize(n, dr_*dr_);
    forAll(walls_->pointAngles(), v)
    {
        V_[nFluid_ + v] *= walls_->pointAngles()[v]/constant::mathematical::twoPi;
    }
    Ustar_.setSize(n);
    visc_.setSize(n);
    divU_.setSize(n);
    divR_.setSize(n);
    surface_.setSize(n, 0);
    nearSurface_.setSize(n, 0);
    rowKind_.setSize(n, 0);
    copyFrom_.setSize(n, -1);
    vertexNeighbours_.setSize(walls_->points().size());
    for (const labelPair& e : walls_->segments())
    {
        vertexNeighbours_[e.first()].append(e.second());
        vertexNeighbours_[e.second()].append(e.first());
    }
    gradP_.setSize(n);
    R_.setSize(n, tensor2D::I);
    rows_.resize(n);
    gradC_.setSize(n);
    gradU_.setSize(n);
    wallU_.setSize(walls_->points().size());
    wallX_.setSize(walls_->points().size());
    dAdn_.setSize(walls_->segments().size(), 0);

    moveWalls(runTime.value(), true);
    readState();
    decideFreeSurface
    (
        freeSurfaceModeNames.getOrDefault
        (
            "freeSurface", schemes_, freeSurfaceMode::automatic
        )
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::isph::printStages() const
{
    const bool adjust =
        runTime_.controlDict().getOrDefault<bool>("adjustTimeStep", false);

    Info<< "ISPH-USAW (000_8c7cd3aabddcf18a.txt section 3), stages of each"
        << " time step:" << nl
        << "    half drift          eq. (30)" << nl;
    if (motion_->any())
    {
        Info<< "    moving walls        vertex particles carry the wall"
            << " velocity, segments the mean of theirs" << nl;
        motion_->write(Info, "                            ");
    }
    Info<< "    neighbours          cell-linked list; gamma (56)-(64) and"
        << " grad gamma_as (6) of " << walls_->segments().size()
        << " segments" << nl
        << "    viscous prediction  eqs. (15)-(17), (31): nu " << nu_
        << (nu_ > 0 ? "" : " (none)") << nl;
    if (freeSurface_)
    {
        Info<< "    free surface        D{r} <= " << freeSurfaceDivR_
            << " (section 3.2) with the wall-crossing test (39); p = 0"
            << " there" << nl;
    }
    Info<< "    pressure Poisson    eqs. (41)-(44) for p + rho g z, wall"
        << " condition (43), Laplacian "
        << (
               pressureGradient_ == pressureGradientType::renormalised
             ? "(10) with the particle's own gradient"
             : "(40)"
           )
        << nl << "                        ";
    pSolver_->write(Info);
    Info<< nl;
    if (!freeSurface_)
    {
        Info<< "                        confined flow (no free surface):"
            << " diagonal x (1 + " << diagonalReinforcement_
            << "), mean fluid p = " << pRefValue_ << nl;
    }
    Info<< "                        "
        << (stopIfNotConverged_ ? "a solve that does not converge stops the run"
            : "solves that do not converge are accepted (stopIfNotConverged no)")
        << nl
        << "    projection          eq. (32) with "
        << (
               pressureGradient_ == pressureGradientType::antisymmetric
             ? "G+{p} (5)"
             : "G-{p} (8) renormalised by G-{r}^-1 (pressureGradient"
               " renormalised; beyond 000_...)"
           )
        << ", gravity " << g_ << nl
        << "    drift               eq. (34)" << nl;
    if (shifting_)
    {
        Info<< "    shifting            eqs. (35)-(38): C_shift " << shiftCoeff_
            << (freeSurface_ ? ", off within h q_max/2 of the free surface" : "")
            << nl;
    }
    if (minWallDistance_ > 0)
    {
        Info<< "    wall distance       particles held " << minWallDistance_
            << " (" << minWallDistance_/dr_ << " dr) off the walls, without"
            << " velocity towards them (minWallDistance; beyond 000_...)"
            << nl;
    }
    Info<< "    checks              NaN/Inf, particles leaving the domain"
        << (crossing_ ? " or crossing a wall" : "") << ", deltaT below "
        << minDeltaTFraction_ << " of the first" << nl
        << "    time step           eqs. (48)-(49): C_CFL (maxCo) " << CCFL_
        << ", C_visq " << Cvisc_ << ", C_force " << Cforce_
        << (freeSurface_ ? " with |du/dt| >= |g|" : "")
        << (adjust ? "" : " (adjustTimeStep off: deltaT fixed)") << nl << endl;
}


Foam::scalar Foam::SPH::isph::stableDeltaT() const
{
    const scalar h = kernel_->h();

    // u_ref: the fastest particle, fluid or wall (000_... after eq. (50))
    const vector2DField& U = parts_.field<vector2D>("U");
    scalar uMax2 = 0;
    for (const vector2D& u : U)
    {
        uMax2 = max(uMax2, magSqr(u));
    }

    // Eqs. (48)-(49) with the acceleration of the last step (gravity
    // before the first). A free surface adds at least |g|: still water
    // has no acceleration, but a ripple of a few dr on its surface turns
    // at sqrt(g pi/dr), which an explicit step must follow
    scalar dt = VGREAT;
    if (uMax2 > 0)
    {
        dt = CCFL_*h/std::sqrt(uMax2);
    }
    if (nu_ > 0)
    {
        dt = min(dt, Cvisc_*h*h/nu_);
    }
    const scalar accel =
        (freeSurface_ || maxAccel_ == 0) ? max(maxAccel_, mag(g_)) : maxAccel_;
    if (accel > 0)
    {
        dt = min(dt, Cforce_*std::sqrt(h/accel));
    }
    if (lastDeltaT_ > 0)
    {
        dt = min(dt, 1.2*lastDeltaT_);
    }
    dt = min(dt, runTime_.controlDict().getOrDefault<scalar>("maxDeltaT", VGREAT));
    return dt < VGREAT ? dt : runTime_.deltaTValue();
}


void Foam::SPH::isph::printStep() const
{
    const scalar Co = maxSpeed_*runTime_.deltaTValue()/kernel_->h();
    Info<< "Courant Number max: " << Co << nl;
    lastSolve_.print(Info);
    if (freeSurface_)
    {
        Info<< "Free-surface particles: " << nSurface_ << nl;
    }
    if (shifting_)
    {
        Info<< "Largest shift: " << maxShift_/dr_ << " dr" << nl;
    }
    if (nHeld_ > 0)
    {
        Info<< "Particles held off the walls: " << nHeld_ << nl;
    }
}


void Foam::SPH::isph::write() const
{
    writeVTK();
    writeState();
    // A restart from this time builds a new multigrid hierarchy: so does
    // the run going on
    pSolver_->expirePreconditioner();
}


void Foam::SPH::isph::writeVTK() const
{
    if (!vtk_)
    {
        vtk_.reset
        (
            new vtkCaseWriter
            (
                runTime_.path(), runTime_.caseName().name(),
                motion_->movesGeometry()
              ? vtkCaseWriter::movingWalls
              : vtkCaseWriter::staticWalls
            )
        );
    }
    vtkCaseWriter& vtk = *vtk_;

    vtkParticleFile particleFile(parts_.positions());
    particleFile.addPointField("U", parts_.field<vector2D>("U"));
    particleFile.addPointField("p", parts_.field<scalar>("p"));
    particleFile.addPointField("type", parts_.field<label>("type"));
    particleFile.addPointField("id", parts_.field<label>("id"));
    if (freeSurface_)
    {
        particleFile.addPointField("freeSurface", surface_);
    }
    vtk.writeParticles(particleFile, runTime_.timeIndex(), runTime_.value());

    if (vtk.wallsDue())
    {
        const SubList<vector2D> vertices
        (
            parts_.positions(), walls_->points().size(), nFluid_
        );
        vtkWallFile wallFile(vertices, walls_->segments());
        wallFile.addCellField("normal", usaw_->segmentNormals());
        wallFile.addCellField("patch", walls_->segmentPatch());
        vtk.writeWalls(wallFile, runTime_.timeIndex(), runTime_.value());
    }
}


void Foam::SPH::isph::printTimes() const
{
    const scalar total = times_.total();
    if (nSteps_ == 0 || total <= 0)
    {
        return;
    }
    auto share = [total](const scalar t)
    {
        return label(100*t/total + 0.5);
    };
    Info<< "Time in the steps: " << total << " s, of which neighbours "
        << times_.neighbours << " s (" << share(times_.neighbours)
        << "%), operators " << times_.operators << " s ("
        << share(times_.operators) << "%), matrix assembly "
        << times_.assembly << " s (" << share(times_.assembly)
        << "%), pressure solve " << times_.solve << " s ("
        << share(times_.solve) << "%), other " << times_.other << " s ("
        << share(times_.other) << "%)" << nl
        << "Steps " << nSteps_ << ", pressure solver iterations per step "
        << scalar(nSolverIterations_)/nSteps_ << ", particle-steps per second "
        << nFluid_*nSteps_/total << nl;
    if (pSolver_->nPreconditionerBuilds() > 0)
    {
        Info<< "Multigrid hierarchies built: "
            << pSolver_->nPreconditionerBuilds() << " for " << nSteps_
            << " solves" << nl;
    }
    if (nHeldTotal_ > 0)
    {
        Info<< "Particles held off the walls (minWallDistance): "
            << nHeldTotal_ << " in " << nSteps_ << " steps" << nl;
    }
}


// ************************************************************************* //
