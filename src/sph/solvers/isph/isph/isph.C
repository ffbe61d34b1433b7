/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "isph.H"
#include "fluidProperties.H"
#include "Time.H"
#include "OSspecific.H"
#include "vtkParticleFile.H"
#include "vtkWallFile.H"
#include "initialField.H"
#include "mathematicalConstants.H"
#include "drift.H"
#include "moveWalls.H"
#include "usawNeighbours.H"
#include "viscousPrediction.H"
#include "renormalisation.H"
#include "freeSurface.H"
#include "pressurePoisson.H"
#include "projection.H"
#include "shifting.H"
#include "wallDistance.H"
#include "bodyForces.H"

#include <cmath>

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

void Foam::SPH::isph::readInitialVelocity()
{
    const initialField U0(runTime_, "U");
    SubList<vector2D> U(parts_.field<vector2D>("U"), nFluid_);
    if (!U0.found())
    {
        Info<< "No " << runTime_.timeName()/"U"
            << ": the fluid starts at rest" << nl;
        U = vector2D::zero;
    }
    else if (U0.read(U))
    {
        Info<< "Initial velocity " << U[0] << " from " << U0.path() << nl;
    }
    else
    {
        Info<< "Initial velocity per particle from " << U0.path() << nl;
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


void Foam::SPH::isph::initialise(const scalar rho0)
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
    parts_.add<scalar>("rho", rho0, false);

    Info<< "Particles: " << nFluid_ << " fluid, " << nVertices
        << " wall vertices" << nl << endl;
}


void Foam::SPH::isph::buildCloud()
{
    const fluidProperties fluid(runTime_);
    initialise(fluid.rho0);

    cloud_.reset
    (
        new sphCloud
        (
            runTime_, parts_, *kernel_, *walls_, nFluid_, dr_, fluid.rho0,
            fluid.g, sphCloud::solverDomain(*walls_, kernel_->support())
        )
    );
    forces_.checkDomain(cloud_->dom());
    usaw_.reset(new usawWalls(*walls_, *kernel_, nFluid_));
    if (!motion_->movesGeometry())
    {
        crossing_.reset(new wallCrossing(*walls_, kernel_->support()));
    }
    work_.reset
    (
        new isphWork
        (
            fluid.rho0, fluid.nu, fluid.g, *cloud_, nbrs_, *usaw_, *motion_
        )
    );

    // Vertex particles are fluid particles cut by the wall (000_...
    // section 2): the share theta_v/(2 pi) of a particle's volume, so that
    // with the first row dr from the wall the volumes tile the fluid
    scalarList& V = work_->V;
    V = dr_*dr_;
    forAll(walls_->pointAngles(), v)
    {
        V[nFluid_ + v] *= walls_->pointAngles()[v]/constant::mathematical::twoPi;
    }
    moveWalls::move(*work_, runTime_.value(), true);
}


bool Foam::SPH::isph::hasFreeSurface(const scalar divRMax)
{
    const freeSurfaceMode mode = freeSurfaceModeNames.getOrDefault
    (
        "freeSurface", schemes_, freeSurfaceMode::automatic
    );
    if (mode != freeSurfaceMode::automatic)
    {
        return mode == freeSurfaceMode::yes;
    }

    // A confined flow fills its walls: D{r} is near 2 everywhere
    work_->cloud.updateCells();
    nbrs_.build(cloud_->cells(), parts_.positions(), kernel_->support(), true);
    usaw_->update(parts_.positions());
    return freeSurface::countSurface(*work_, divRMax) > 0;
}


void Foam::SPH::isph::addStages()
{
    const pressureGradientType gradient = pressureGradientTypeNames.getOrDefault
    (
        "pressureGradient", schemes_, pressureGradientType::renormalised
    );
    const bool renormalised = gradient == pressureGradientType::renormalised;

    // 000_... after eq. (36): "calibrated ... 0.7 for the Wendland kernel"
    const bool shift = schemes_.getOrDefault<bool>("shifting", true);
    const scalar shiftCoeff = schemes_.getOrDefault<scalar>("shiftCoeff", 0.7);
    if (!(shiftCoeff >= 0))
    {
        FatalIOErrorInFunction(schemes_.lookup("shiftCoeff"))
            << "Entry shiftCoeff " << shiftCoeff << ": expected >= 0"
            << exit(FatalIOError);
    }
    // Section 3.2: "D{r} <= 1.5 in 2-D"
    const scalar divRMax = schemes_.getOrDefault<scalar>("freeSurfaceDivR", 1.5);
    if (!(divRMax > 0 && divRMax < 2))
    {
        FatalIOErrorInFunction(schemes_.lookup("freeSurfaceDivR"))
            << "Entry freeSurfaceDivR " << divRMax
            << ": expected 0 < freeSurfaceDivR < 2 (D{r} is 2 inside the"
            << " fluid)" << exit(FatalIOError);
    }
    // Eq. (39)'s distance of a particle about to hit a wall
    const scalar minWallDistance =
        schemes_.getOrDefault<scalar>("minWallDistance", kernel_->support()/8);
    if (!(minWallDistance >= 0 && minWallDistance < dr_))
    {
        FatalIOErrorInFunction(schemes_)
            << "Entry minWallDistance " << minWallDistance
            << ": expected 0 (off) or a distance below dr = " << dr_
            << exit(FatalIOError);
    }
    freeSurface_ = hasFreeSurface(divRMax);

    // 000_... section 3.2, eqs. (30)-(38)
    isphWork& w = *work_;
    const bool moving = motion_->any();
    stages_.add(new drift(parts_, cloud_->dom(), nFluid_, 0.5, "eq. (30)"));
    if (moving) stages_.add(new moveWalls(w, runTime_, false));
    stages_.add(new usawNeighbours(w, ""));
    stages_.add(new viscousPrediction(w));
    if (!forces_.empty() || w.gPeriodic != vector2D::zero)
    {
        stages_.add(new bodyForces(w, forces_));
    }
    if (renormalised) stages_.add(new renormalisation(w));
    if (freeSurface_) stages_.add(new freeSurface(w, divRMax));
    pressure_ = &stages_.add
    (
        new pressurePoisson(w, runTime_, solution_, renormalised, freeSurface_)
    );
    stages_.add(new projection(w, renormalised));
    stages_.add(new drift(parts_, cloud_->dom(), nFluid_, 0.5, "eq. (34)"));
    if (moving) stages_.add(new moveWalls(w, runTime_, true));
    if (shift)
    {
        stages_.add(new usawNeighbours(w, ", at r~ for the shifting"));
        stages_.add(new shifting(w, shiftCoeff, freeSurface_));
    }
    if (minWallDistance > 0)
    {
        wallDistance_ = &stages_.add(new wallDistance(w, minWallDistance));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::isph::isph(Time& runTime)
:
    sphSolver(runTime),
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
    CCFL_(runTime.controlDict().getOrDefault<scalar>("maxCo", 0.2)),
    dr_
    (
        IOdictionary
        (
            IOobject
            (
                "sphMeshDict", runTime.system(), runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            )
        ).get<scalar>("dr")
    ),
    parts_(runTime, runTime.timeName()),
    nFluid_(0),
    nbrs_(true),
    forces_(runTime),
    freeSurface_(false),
    pressure_(nullptr),
    wallDistance_(nullptr),
    maxSpeed_(0),
    maxAccel_(0),
    maxAccelStart_(0),
    UStart_(nullptr),
    nSteps_(0)
{
    if (!(CCFL_ > 0))
    {
        FatalIOErrorInFunction(runTime.controlDict().lookup("maxCo"))
            << "Entry maxCo " << CCFL_ << ": expected C_CFL > 0"
            << exit(FatalIOError);
    }
    boundaryMethodNames.get("boundaryMethod", schemes_);
    kernel_ = kernel::New(schemes_, dr_);
    walls_.reset(new wallMesh(runTime));
    motion_.reset(new wallBoundaries(runTime, *walls_));
    buildCloud();
    addStages();
}


Foam::SPH::isph::~isph()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::isph::printSettings() const
{
    const bool adjust =
        runTime_.controlDict().getOrDefault<bool>("adjustTimeStep", false);
    Info<< "    time step           eqs. (48)-(49): C_CFL (maxCo) " << CCFL_
        << ", C_visq " << Cvisc_ << ", C_force " << Cforce_
        << (freeSurface_ ? " with |du/dt| >= |g|" : "")
        << (adjust ? "" : " (adjustTimeStep off: deltaT fixed)") << nl;
}


Foam::scalar Foam::SPH::isph::maxDeltaT() const
{
    const scalar h = kernel_->h();
    const scalar nu = work_->nu;
    const vector2D g = work_->g + work_->gPeriodic;

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
    if (nu > 0)
    {
        dt = min(dt, Cvisc_*h*h/nu);
    }
    const scalar accel =
        (freeSurface_ || maxAccel_ == 0) ? max(maxAccel_, mag(g)) : maxAccel_;
    if (accel > 0)
    {
        dt = min(dt, Cforce_*std::sqrt(h/accel));
    }
    return dt;
}


void Foam::SPH::isph::saveState(const particles::snapshot& start)
{
    work_->xStart = &start.positions;
    UStart_ = &start.vectors["U"];
    maxAccelStart_ = maxAccel_;
    forces_.save();
}


void Foam::SPH::isph::restoreState()
{
    maxAccel_ = maxAccelStart_;
    forces_.restore();
}


void Foam::SPH::isph::afterStep(const scalar dt)
{
    // The acceleration that limits the next step, eq. (49)
    const vector2D* U = parts_.field<vector2D>("U").cdata();
    const List<vector2D>& U0 = *UStart_;
    scalar maxA2 = 0, maxU2 = 0;
    for (label i = 0; i < nFluid_; ++i)
    {
        maxA2 = max(maxA2, magSqr(U[i] - U0[i]));
        maxU2 = max(maxU2, magSqr(U[i]));
    }
    maxAccel_ = std::sqrt(maxA2)/dt;
    maxSpeed_ = std::sqrt(maxU2);
    ++nSteps_;

    // The cell list that function objects search: the final positions
    cloud_->updateCells();
}


void Foam::SPH::isph::readState(const dictionary& dict)
{
    maxAccel_ = dict.getOrDefault<scalar>("maxAcceleration", 0);
}


void Foam::SPH::isph::writeState(Ostream& os) const
{
    os.writeEntry("maxAcceleration", maxAccel_);
    forces_.write();
}


void Foam::SPH::isph::printStep() const
{
    const scalar Co = maxSpeed_*runTime_.deltaTValue()/kernel_->h();
    Info<< "Courant Number max: " << Co << nl;
    stages_.printStep(Info);
}


void Foam::SPH::isph::write() const
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

    vtkParticleFile particleFile(parts_);
    if (freeSurface_)
    {
        particleFile.addPointField("freeSurface", work_->surface);
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

    // A restart from this time builds a new multigrid hierarchy: so does
    // the run going on
    pressure_->solver().expirePreconditioner();
}


void Foam::SPH::isph::printTimes() const
{
    const scalar total = stages_.seconds();
    if (nSteps_ == 0 || total <= 0)
    {
        return;
    }
    stages_.printTimes(Info);
    Info<< "Steps " << nSteps_ << ", pressure solver iterations per step "
        << scalar(pressure_->nIterations())/nSteps_
        << ", particle-steps per second " << nFluid_*nSteps_/total << nl;
    if (pressure_->solver().nPreconditionerBuilds() > 0)
    {
        Info<< "Multigrid hierarchies built: "
            << pressure_->solver().nPreconditionerBuilds() << " for "
            << nSteps_ << " solves" << nl;
    }
    if (wallDistance_ && wallDistance_->nHeldTotal() > 0)
    {
        Info<< "Particles held off the walls (minWallDistance): "
            << wallDistance_->nHeldTotal() << " in " << nSteps_ << " steps"
            << nl;
    }
}


// ************************************************************************* //
