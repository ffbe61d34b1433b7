/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "isph.H"
#include "Time.H"
#include "vtkParticleFile.H"
#include "vtkWallFile.H"
#include "drift.H"
#include "moveWalls.H"
#include "usawNeighbours.H"
#include "viscousPrediction.H"
#include "implicitViscousPrediction.H"
#include "renormalisation.H"
#include "freeSurface.H"
#include "airPockets.H"
#include "airPocketCoupling.H"
#include "pressurePoisson.H"
#include "projection.H"
#include "shifting.H"
#include "wallDistance.H"
#include "bodyForces.H"
#include "buoyancy.H"
#include "usawWallModel.H"
#include "checkedEntry.H"
#include "timeControls.H"
#include "memberStage.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::isph::freeSurfaceMode>
Foam::SPH::isph::freeSurfaceModeNames
({
    { freeSurfaceMode::automatic, "auto" },
    { freeSurfaceMode::yes, "yes" },
    { freeSurfaceMode::no, "no" },
});


const Foam::Enum<Foam::SPH::isph::freeSurfaceConditionType>
Foam::SPH::isph::freeSurfaceConditionNames
({
    { freeSurfaceConditionType::dirichlet, "dirichlet" },
    { freeSurfaceConditionType::ghost, "ghost" },
});


namespace
{
    // The viscous prediction, eq. (31): explicit (the paper) or implicit
    enum class viscousScheme { explicitEuler, implicitEuler };
    const Foam::Enum<viscousScheme> viscousSchemeNames
    ({
        { viscousScheme::explicitEuler, "explicit" },
        { viscousScheme::implicitEuler, "implicit" },
    });
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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
    verlet_->update
    (
        cloud_->cells(), parts_.positions(), kernel_->support(), nbrs_
    );
    usaw_->update(parts_.positions());
    return freeSurface::countSurface(*work_, divRMax) > 0;
}


void Foam::SPH::isph::selectWallModel()
{
    // sphMesh's selection: the word decided where the fluid was seeded
    if (!schemes_.found("boundaryMethod"))
    {
        FatalIOErrorInFunction(schemes_)
            << "Missing entry boundaryMethod: isphFoam is ISPH-USAW and needs"
            << " boundaryMethod usaw (set before sphMesh lays the particles)"
            << exit(FatalIOError);
    }
    wallModel_ = wallModel::New(schemes_);
    if (!isA<usawWallModel>(*wallModel_))
    {
        FatalIOErrorInFunction(schemes_.lookup("boundaryMethod"))
            << "boundaryMethod " << wallModel_->type() << ": isphFoam is"
            << " ISPH-USAW (Leroy et al. 2014) and takes usaw only; "
            << wallModel_->type() << " is a wall model of wcsphFoam"
            << exit(FatalIOError);
    }
}


void Foam::SPH::isph::addPrediction(const projection::gradientForm gradient)
{
    const bool renormalised =
        gradient == projection::gradientForm::renormalised;
    isphWork& w = *work_;
    const bool forces = !forces_.empty() || w.gPeriodic != vector2D::zero;
    if (implicitViscosity_)
    {
        // The forces and the last pressure's acceleration inside the
        // implicit step (implicitViscousPrediction.H)
        if (renormalised) stages_.add(new renormalisation(w));
        if (forces) stages_.add(new bodyForces(w, forces_, true));
        if (thermal_) stages_.add(new buoyancy(w, *thermal_, !forces));
        stages_.add
        (
            new implicitViscousPrediction
            (
                w, solution_, forces || thermal_.valid()
            )
        );
    }
    else
    {
        stages_.add(new viscousPrediction(w));
        if (forces) stages_.add(new bodyForces(w, forces_));
        if (thermal_) stages_.add(new buoyancy(w, *thermal_, false));
        if (renormalised) stages_.add(new renormalisation(w));
    }
}


Foam::scalar Foam::SPH::isph::readFreeSurfaceDivR() const
{
    // Section 3.2: "D{r} <= 1.5 in 2-D"
    const scalar divRMax = schemes_.getOrDefault<scalar>("freeSurfaceDivR", 1.5);
    if (!(divRMax > 0 && divRMax < 2))
    {
        FatalIOErrorInFunction(schemes_.lookup("freeSurfaceDivR"))
            << "Entry freeSurfaceDivR " << divRMax
            << ": expected 0 < freeSurfaceDivR < 2 (D{r} is 2 inside the"
            << " fluid)" << exit(FatalIOError);
    }
    return divRMax;
}


Foam::scalar Foam::SPH::isph::readMinWallDistance() const
{
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
    return minWallDistance;
}


void Foam::SPH::isph::addTurbulence()
{
    if (turbulence_->isLaminar()) return;
    if (implicitViscosity_)
    {
        FatalIOErrorInFunction(schemes_.lookup("viscousScheme"))
            << "viscousScheme implicit with the RAS model "
            << turbulence_->type() << ": the implicit step has a uniform"
            << " viscosity; use viscousScheme explicit (the paper's)"
            << exit(FatalIOError);
    }
    stages_.add
    (
        new memberStage<turbulenceModel>
        (
            "turbulence", turbulence_->reads(), turbulence_->writes(),
            turbulence_->description(), *turbulence_,
            &turbulenceModel::correct
        )
    );
}


void Foam::SPH::isph::addPressureSolve
(
    const projection::gradientForm gradient
)
{
    isphWork& w = *work_;
    const bool renormalised =
        gradient == projection::gradientForm::renormalised;
    autoPtr<airPockets> newPockets
    (
        airPockets::New(w, runTime_, dr_, freeSurface_, motion_->any())
    );
    pockets_ = newPockets ? &stages_.add(newPockets.ptr()) : nullptr;
    pressurePoisson& pressure = stages_.add
    (
        new pressurePoisson(w, runTime_, solution_, renormalised, freeSurface_)
    );
    pressure_ = &pressure;
    if (pockets_ && w.ghostSurface)
    {
        stages_.add(new airPocketCoupling(w, *pockets_, pressure, gradient));
    }
}


void Foam::SPH::isph::addStages()
{
    const projection::gradientForm gradient =
        projection::gradientFormNames.getOrDefault
        (
            "pressureGradient", schemes_, projection::gradientForm::renormalised
        );
    const bool renormalised =
        gradient == projection::gradientForm::renormalised;

    // 000_... after eq. (36): "calibrated ... 0.7 for the Wendland kernel"
    const bool shift = schemes_.getOrDefault<bool>("shifting", true);
    const scalar shiftCoeff =
        checkedScalar
        (
            schemes_, "shiftCoeff", 0.7, {0, 10},
            "C of the shift eq. (36); 0.7 calibrated for the Wendland kernel"
        );
    const scalar divRMax = readFreeSurfaceDivR();
    const scalar minWallDistance = readMinWallDistance();
    freeSurface_ = hasFreeSurface(divRMax);
    // Leroy et al. 2015 after eq. (17): confined, the dynamic pressure
    work_->dynamicPressureGradient = !freeSurface_ && !renormalised;
    implicitViscosity_ = viscousSchemeNames.getOrDefault
    (
        "viscousScheme", schemes_, viscousScheme::explicitEuler
    ) == viscousScheme::implicitEuler;

    // 000_... section 3.2, eqs. (30)-(38)
    isphWork& w = *work_;
    const bool moving = motion_->any();
    stages_.add(new drift(parts_, cloud_->dom(), nFluid_, 0.5, "eq. (30)"));
    if (moving) stages_.add(new moveWalls(w, runTime_, false));
    ghostCondition(renormalised);
    readInteriorCompaction();
    stages_.add(new usawNeighbours(w, ""));
    addTurbulence();
    addPrediction(gradient);
    if (freeSurface_) stages_.add(new freeSurface(w, divRMax));
    addPressureSolve(gradient);
    stages_.add(new projection(w, gradient));
    if (thermal_) addHeatTransfer();
    stages_.add(new drift(parts_, cloud_->dom(), nFluid_, 0.5, "eq. (34)"));
    if (moving) stages_.add(new moveWalls(w, runTime_, true));
    if (shift)
    {
        stages_.add(new usawNeighbours(w, ", at r~ for the shifting"));
        stages_.add(new shifting(w, shiftCoeff, freeSurface_));
    }
    if (minWallDistance > 0)
    {
        wallDistance_ = &stages_.add
        (
            new wallDistance(w, minWallDistance, freeSurface_)
        );
    }
    if (thermal_) addDynamicPressure();
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
        checkedScalar
        (
            IOdictionary
            (
                IOobject
                (
                    "sphMeshDict", runTime.system(), runTime,
                    IOobject::MUST_READ, IOobject::NO_WRITE, false
                )
            ),
            "dr", {0, VGREAT, true}, "m"
        )
    ),
    parts_(runTime, runTime.timeName()),
    nFluid_(0),
    nbrs_(true),
    forces_(runTime),
    freeSurface_(false),
    implicitViscosity_(false),
    fresh_(true),
    pressure_(nullptr),
    wallDistance_(nullptr),
    pockets_(nullptr),
    maxSpeed_(0),
    maxAccel_(0),
    maxAccelStart_(0),
    UStart_(nullptr),
    nSteps_(0)
{
    if (!(CCFL_ > 0) || !std::isfinite(CCFL_))
    {
        FatalIOErrorInFunction(runTime.controlDict().lookup("maxCo"))
            << "Entry maxCo " << CCFL_ << ": expected C_CFL > 0"
            << exit(FatalIOError);
    }
    selectWallModel();
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
    Info<< "    time step           eqs. (48)-(49): C_CFL (maxCo) " << CCFL_;
    if (implicitViscosity_)
    {
        Info<< ", C_force " << Cforce_ << " (viscosity implicit: no C_visq"
            << " h^2/nu bound)";
    }
    else
    {
        Info<< ", C_visq " << Cvisc_ << ", C_force " << Cforce_;
    }
    Info<< (freeSurface_ ? " with |du/dt| >= |g|" : "")
        << (adjust ? "" : " (adjustTimeStep off: deltaT fixed)") << nl;
    if (turbulence_->isLaminar())
    {
        Info<< "    turbulence          "
            << turbulence_->description().c_str() << nl;
    }
}


Foam::scalar Foam::SPH::isph::maxDeltaT() const
{
    const scalar h = kernel_->h();
    const scalar nu = work_->nu + turbulence_->maxNut();
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
    if (nu > 0 && !implicitViscosity_)
    {
        dt = min(dt, Cvisc_*h*h/nu);
    }
    // The explicit heat equation, C_visq h^2/K_E
    if (thermal_) dt = min(dt, thermal_->maxDeltaT(h));
    const scalar accel =
        (freeSurface_ || maxAccel_ == 0) ? max(maxAccel_, mag(g)) : maxAccel_;
    if (accel > 0)
    {
        dt = min(dt, Cforce_*std::sqrt(h/accel));
    }
    checkDeltaT
    (
        runTime_, dt, "eqs. (48)-(49): largest speed "
      + std::string(Foam::name(std::sqrt(uMax2))) + " m/s, acceleration "
      + Foam::name(accel) + " m/s^2"
    );
    return dt;
}


void Foam::SPH::isph::saveState(const particles::snapshot& start)
{
    work_->xStart = &start.positions;
    UStart_ = &start.vectors["U"];
    maxAccelStart_ = maxAccel_;
    forces_.save();
    if (pockets_) pockets_->save();
}


void Foam::SPH::isph::restoreState()
{
    maxAccel_ = maxAccelStart_;
    forces_.restore();
    if (pockets_) pockets_->restore();
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
    // (none to search without function objects; the neighbour stages
    // keep their own list up to date)
    if (runTime_.functionObjects().size())
    {
        cloud_->updateCells();
    }
}


void Foam::SPH::isph::readState(const dictionary& dict)
{
    maxAccel_ = dict.getOrDefault<scalar>("maxAcceleration", 0);
    if (pockets_) pockets_->readState(dict);
}


void Foam::SPH::isph::writeState(Ostream& os) const
{
    os.writeEntry("maxAcceleration", maxAccel_);
    if (pockets_) pockets_->writeState(os);
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

    // A restart from this time builds new multigrid hierarchies: so does
    // the run going on
    stages_.expireReuse();
}


void Foam::SPH::isph::printCpuSplit() const
{
    // The split of issue 17: neighbours (pairs; the walls' gamma apart),
    // operators, matrix assembly, pressure solve, other (drifts, walls'
    // motion, wall distance)
    scalar pairs = 0, walls = 0, operators = 0, assembly = 0, solve = 0;
    scalar other = 0;
    for (const stage& s : stages_)
    {
        const scalar cpu = s.cpuSeconds();
        if (const auto* nb = dynamic_cast<const usawNeighbours*>(&s))
        {
            walls += nb->wallCpuSeconds();
            pairs += cpu - nb->wallCpuSeconds();
        }
        else if (&s == pressure_)
        {
            solve += pressure_->solveCpuSeconds();
            assembly += cpu - pressure_->solveCpuSeconds();
        }
        else if
        (
            s.name() == "halfDrift" || s.name() == "moveWalls"
         || s.name() == "wallDistance"
        )
        {
            other += cpu;
        }
        else
        {
            operators += cpu;
        }
    }
    const scalar total = pairs + walls + operators + assembly + solve + other;
    if (!(total > 0)) return;
    auto part = [&](const char* name, const scalar t)
    {
        Info<< ' ' << name << ' ' << t << " s ("
            << label(100*t/total + 0.5) << "%)";
    };
    Info<< "CPU time in the steps: " << total << " s:";
    part("neighbours", pairs);
    part("walls", walls);
    part("operators", operators);
    part("matrix assembly", assembly);
    part("pressure solve", solve);
    part("other", other);
    Info<< nl << "Neighbour searches " << verlet_->nBuilds() << " in "
        << nSteps_ << " steps (" << verlet_->nSelections()
        << " selections from the Verlet list), particle-steps per CPU second "
        << nFluid_*nSteps_/total << nl;
}


void Foam::SPH::isph::printTimes() const
{
    const scalar total = stages_.seconds();
    if (nSteps_ == 0 || total <= 0)
    {
        return;
    }
    stages_.printTimes(Info);
    printCpuSplit();
    Info<< "Steps " << nSteps_ << ", pressure solver iterations per step "
        << scalar(pressure_->nIterations())/nSteps_
        << ", particle-steps per second " << nFluid_*nSteps_/total << nl;
    if (pressure_->solver().nPreconditionerBuilds() > 0)
    {
        const linearSolver& s = pressure_->solver();
        Info<< "Multigrid hierarchies built: " << s.nPreconditionerBuilds()
            << " for " << nSteps_ << " solves";
        if (s.preconditionerEntriesKept() < 1)
        {
            Info<< ", on " << round(1000*s.preconditionerEntriesKept())/10
                << " % of the matrix entries (filterTolerance)";
        }
        Info<< nl;
    }
    if (wallDistance_ && wallDistance_->nHeldTotal() > 0)
    {
        Info<< "Particles held off the walls (minWallDistance): "
            << wallDistance_->nHeldTotal() << " in " << nSteps_ << " steps";
        if (freeSurface_)
        {
            Info<< " (" << wallDistance_->nHeldSurfaceTotal()
                << " free-surface rows)";
        }
        Info<< nl;
    }
}


// ************************************************************************* //
