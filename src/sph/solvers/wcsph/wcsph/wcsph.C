/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsph.H"
#include "wcsphBodyForces.H"
#include "memberStage.H"
#include "wcsphShifting.H"
#include "wcsphTurbulence.H"
#include "OStringStream.H"
#include "fluidProperties.H"
#include "checkedEntry.H"
#include "timeControls.H"
#include "Time.H"
#include "dimensionedScalar.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"
#include "vtkCaseWriter.H"
#include "vtkParticleFile.H"
#include "vtkWallFile.H"

#include <cmath>
#include <chrono>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::wcsph::viscosityModel>
Foam::SPH::wcsph::viscosityModelNames
({
    { viscosityModel::none, "none" },
    { viscosityModel::Morris, "Morris" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wcsph::readPhysics()
{
    const fluidProperties fluid(runTime_);
    work_.rho0 = fluid.rho0;
    work_.nu = fluid.nu;
    work_.g = fluid.g;

    const IOdictionary transport
    (
        IOobject
        (
            "transportProperties", runTime_.constant(), runTime_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    if (transport.found("airPockets"))
    {
        FatalIOErrorInFunction(transport.subDict("airPockets"))
            << "airPockets: only isphFoam keeps the pressure of enclosed air"
            << " (wcsphFoam's free surface has no condition to carry it)"
            << exit(FatalIOError);
    }
}


void Foam::SPH::wcsph::readSchemes()
{
    scalar& c0 = work_.c0;
    scalar& gamma = work_.gamma;
    gamma = checkedScalar(schemes_, "gamma", 7, {1, VGREAT}, "Tait exponent");
    if (schemes_.found("c0"))
    {
        c0 = checkedScalar(schemes_, "c0", {0, VGREAT, true}, "m/s");
    }
    else if (schemes_.found("Umax"))
    {
        c0 =
            checkedScalar(schemes_, "c0ByUmax", 10, {0, VGREAT, true})
           *checkedScalar(schemes_, "Umax", {0, VGREAT, true}, "m/s");
    }
    else
    {
        FatalIOErrorInFunction(schemes_)
            << "Missing entry 'c0' (the numerical speed of sound, m/s), or"
            << " 'Umax' (the expected largest speed; c0 = c0ByUmax Umax with"
            << " c0ByUmax 10 by default)" << nl << exit(FatalIOError);
    }
    if (!(c0 > 0) || !(gamma >= 1))
    {
        FatalIOErrorInFunction(schemes_)
            << "Expected c0 > 0 and gamma >= 1, found c0 " << c0
            << " and gamma " << gamma << exit(FatalIOError);
    }
    work_.b0 = work_.rho0*c0*c0/gamma;
    if (!std::isfinite(work_.b0) || !std::isfinite(c0))
    {
        FatalIOErrorInFunction(schemes_)
            << "c0 " << c0 << " m/s with rho " << work_.rho0 << " and gamma "
            << gamma << ": the Tait stiffness rho c0^2/gamma is not a finite"
            << " number" << exit(FatalIOError);
    }

    work_.densityDiffusion =
        schemes_.getOrDefault<bool>("densityDiffusion", true);
    work_.densityDiffusionHydrostatic =
        work_.densityDiffusion
     && schemes_.getOrDefault<bool>("densityDiffusionHydrostatic", true);

    // Not in 004_..., which relies on the density diffusion alone; a small
    // alpha damps the velocity noise of water at rest
    work_.alphaAV = checkedScalar
    (
        schemes_, "artificialViscosity", 0, {0, VGREAT}, "Monaghan's alpha"
    );
    // Morris's with dummies, eq. (15) with USAW walls: the wall model's
    const viscosityModel viscosity = viscosityModelNames.getOrDefault
    (
        "viscosity", schemes_, viscosityModel::Morris
    );
    work_.viscous = work_.nu != 0 && viscosity == viscosityModel::Morris;
    skinByH_ = checkedScalar
    (
        schemes_, "neighbourSkin", 0.2, {0, VGREAT},
        "a length in h; 0: rebuild the neighbour list at every stage"
    );
    readTimeScheme();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wcsph::wcsph(Time& runTime)
:
    sphSolver(runTime),
    schemes_
    (
        IOobject
        (
            "sphSchemes", runTime.system(), runTime,
            IOobject::MUST_READ_IF_MODIFIED, IOobject::NO_WRITE, false
        )
    ),
    work_(parts_, nbrs_),
    bounds_(schemes_, work_),
    walls_(new wallMesh(runTime)),
    parts_(runTime, runTime.timeName()),
    dr_(0),
    bodyForces_(nullptr),
    nbrs_(true),
    skinByH_(0.2),
    skin_(0),
    listBuilt_(false),
    nListBuilds_(0),
    nListRefreshes_(0),
    fresh_(false),
    bounceElasticity_(1),
    nBounced_(0),
    minWallDistance_(0),
    nHeld_(0),
    ratesCurrent_(false),
    timeScheme_(timeIntegrator::RungeKutta4),
    midStepRates_(false),
    nRateEvaluations_(0),
    timeNeighbours_(0), timeInteractions_(0), timeIntegration_(0),
    nSteps_(0),
    maxSpeed_(0), maxAccel_(0), maxSoundSpeed_(0)
{
    readPhysics();

    // The spacing sphMesh used: its wall segments are close to dr
    {
        IOdictionary meshDict
        (
            IOobject
            (
                "sphMeshDict", runTime.system(), runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            )
        );
        dr_ = checkedScalar(meshDict, "dr", {0, VGREAT, true}, "m");
        work_.dr = dr_;
    }
    kernel_ = kernel::New(schemes_, dr_);
    readSchemes();

    wallModel_ = wcsphWallModel::New(runTime, schemes_, *walls_, *kernel_, work_);
    skin_ = skinByH_*kernel_->h();
    initialise();

    cloud_.reset
    (
        new sphCloud
        (
            runTime, parts_, *kernel_, *walls_, work_.nFluid, dr_, work_.rho0,
            work_.g, sphCloud::solverDomain(*walls_, kernel_->support())
        )
    );
    work_.cloud = cloud_.get();
    wallModel_->setUp();
    bounds_.checkStart(runTime.timeName());

    // The bounce mirrors in the walls of t = 0 (as isphFoam's check)
    if
    (
        !wallModel_->movesGeometry()
     && schemes_.getOrDefault<bool>("wallBounce", true)
    )
    {
        crossing_.reset(new wallCrossing(*walls_, kernel_->support()));
        bounceElasticity_ = checkedScalar
        (
            schemes_, "wallBounceElasticity", 1, {0, 1},
            "of the normal velocity a wall bounce gives back (1: elastic)"
        );
    }
    else if (schemes_.found("wallBounceElasticity"))
    {
        FatalIOErrorInFunction(schemes_.lookup("wallBounceElasticity"))
            << "Entry wallBounceElasticity: only with wallBounce yes and walls"
            << " that do not move (no wall bounce runs in this case)"
            << exit(FatalIOError);
    }
    // Before the stage list prints gravity, after the step's own stages
    autoPtr<wcsphBodyForces> forces
    (
        wcsphBodyForces::New(runTime, work_, *wallModel_, cloud_->dom())
    );
    addStages();
    if (forces)
    {
        bodyForces_ = &stages_.add(forces.release());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::string Foam::SPH::wcsph::neighbourPolicy() const
{
    if (skin_ > 0)
    {
        return
            "Verlet list within support + " + std::string(Foam::name(skinByH_))
          + " h: refreshed at every stage, rebuilt after every write and"
            " when a particle has moved half the skin";
    }
    return "rebuilt at every stage";
}


std::string Foam::SPH::wcsph::ratesDescription() const
{
    OStringStream rates;
    const char* indent = "        ";
    rates
        << indent << "neighbours         cell-linked list, " << neighbourPolicy().c_str()
        << nl;
    wallModel_->describe(rates, indent);
    if (work_.alphaAV > 0)
    {
        rates
            << indent << "artificial viscosity  Monaghan, alpha " << work_.alphaAV
            << " (not in 004_...)" << nl;
    }
    // The stage's description ends without a newline
    std::string description(rates.str());
    description.pop_back();
    return description;
}


void Foam::SPH::wcsph::addWallSafetyNets()
{
    if (crossing_)
    {
        stages_.add
        (
            new memberStage<wcsph>
            (
                "wallBounce", {"positions", "U"}, {"positions", "U"},
                "particles that cross a wall in a step are mirrored back,"
                " their normal velocity times -"
              + std::string(Foam::name(bounceElasticity_))
              + " (a safety net; counted in the log)", *this,
                &wcsph::wallBounce
            )
        );
    }
    if (wallModel_->movesGeometry())
    {
        // The wall bounce's place for walls that move: isphFoam's net
        minWallDistance_ = checkedScalar
        (
            schemes_, "minWallDistance", kernel_->support()/8, {0, dr_},
            "m (0: off)"
        );
    }
    if (minWallDistance_ > 0)
    {
        stages_.add
        (
            new memberStage<wcsph>
            (
                "wallDistance", {"positions", "U"}, {"positions", "U"},
                "fluid particles held minWallDistance "
              + std::string(Foam::name(minWallDistance_)) + " m off the"
                " moving walls, without velocity towards them (a safety"
                " net, isphFoam's; counted in the log)",
                *this, &wcsph::holdOffWalls
            )
        );
    }
}


void Foam::SPH::wcsph::addStages()
{
    // First: the viscous term the rates describe is the model's
    autoPtr<wcsphTurbulence> turbulence;
    if (!turbulence_->isLaminar())
    {
        turbulence.reset
        (
            new wcsphTurbulence
            (
                runTime_, schemes_, *turbulence_, work_, *wallModel_,
                *walls_, fresh_, [this]() { updateNeighbours(); }
            )
        );
    }
    addIntegratorStage(ratesDescription());
    addWallSafetyNets();
    if (schemes_.getOrDefault<bool>("shifting", false))
    {
        stages_.add
        (
            new wcsphShifting
            (
                schemes_, work_, *wallModel_, *kernel_,
                [this]() { updateNeighbours(); }
            )
        );
    }
    else if (schemes_.found("interiorCompaction"))
    {
        // It gives back the room the shift makes; alone it would do nothing
        FatalIOErrorInFunction(schemes_.lookup("interiorCompaction"))
            << "Entry interiorCompaction is read by wcsphFoam's shifting only:"
            << " set shifting yes, or remove the entry" << exit(FatalIOError);
    }
    stages_.add
    (
        new memberStage<wcsph>
        (
            "equationOfState", {"rho"}, {"p"},
            "Tait eq. (4): p of the new density", *this, &wcsph::equationOfState
        )
    );
    if (turbulence)
    {
        stages_.add(turbulence.release());
    }
}


void Foam::SPH::wcsph::printSettings() const
{
    if (!crossing_)
    {
        Info<< "    wall crossing       not checked ("
            << (wallModel_->movesGeometry() ? "walls move" : "wallBounce no")
            << ")" << nl;
    }
    if (turbulence_->isLaminar())
    {
        Info<< "    turbulence          "
            << turbulence_->description().c_str() << nl;
    }
    Info<< "    time scheme         " << timeIntegratorNames[timeScheme_]
        << " (timeScheme " << timeSchemeWords().c_str() << ")" << nl
        << "    time step           eq. (15), C_n = maxCo "
        << runTime_.controlDict().getOrDefault<scalar>("maxCo", 0.2)
        << (runTime_.controlDict().getOrDefault<bool>("adjustTimeStep", false)
            ? "" : " (adjustTimeStep off: deltaT fixed)")
        << nl;
}


Foam::scalar Foam::SPH::wcsph::maxDeltaT() const
{
    // The rates of the state are those of the coming step's first stage;
    // the leapfrog's step is chosen from its last evaluation, at t^{n-1/2}
    if (!ratesCurrent_ && !midStepRates_)
    {
        const_cast<wcsph&>(*this).computeRates(runTime_.value());
    }
    const scalar h = kernel_->h();
    const scalar Cn = runTime_.controlDict().getOrDefault<scalar>("maxCo", 0.2);

    // 004_... eq. (15), and the viscous and force limits of 000_... eq. (49)
    scalar dt = Cn*h/max(maxSoundSpeed_, maxSpeed_);
    const scalar nuMax = work_.nu + turbulence_->maxNut();
    if (nuMax > 0)
    {
        dt = min(dt, 0.125*h*h/nuMax);
    }
    if (maxAccel_ > 0)
    {
        dt = min(dt, 0.25*std::sqrt(h/maxAccel_));
    }
    checkDeltaT
    (
        runTime_, dt, "eq. (15): largest speed "
      + std::string(Foam::name(maxSpeed_)) + " m/s, sound speed "
      + Foam::name(maxSoundSpeed_) + " m/s, acceleration "
      + Foam::name(maxAccel_) + " m/s^2"
    );
    return min(dt, GREAT);
}


void Foam::SPH::wcsph::afterStep(const scalar dt)
{
    ++nSteps_;
    bounds_.afterStep(runTime_);

    // The neighbour search function objects use
    cloud_->updateCells();

    // A restart from this time builds a new list at its first step: so does
    // this run, or the two would sum the pairs in different orders
    if (runTime_.writeTime())
    {
        listBuilt_ = false;
        midStepRates_ = false;
    }
}


void Foam::SPH::wcsph::particlesReordered(const labelUList& oldOfNew)
{
    listBuilt_ = false;
    // Rates of the state, if any, are evaluated again on the new numbering
    ratesCurrent_ = false;
    // The leapfrog's predictor takes the last corrector's rates: reordered
    // with their particles, not evaluated again (an evaluation is its step)
    particles::reorderField(work_.dUdt, oldOfNew);
    particles::reorderField(work_.drhodt, oldOfNew);
}


void Foam::SPH::wcsph::saveState(const particles::snapshot& start)
{
    if (bodyForces_) bodyForces_->save();
}


void Foam::SPH::wcsph::restoreState()
{
    ratesCurrent_ = false;
    midStepRates_ = false;
    if (bodyForces_) bodyForces_->restore();
}


void Foam::SPH::wcsph::writeState(Ostream& os) const
{
    if (bodyForces_) bodyForces_->write();
    bounds_.writeState(os);
}


void Foam::SPH::wcsph::readState(const dictionary& dict)
{
    bounds_.readState(dict);
}


void Foam::SPH::wcsph::write() const
{
    if (!vtk_)
    {
        vtk_.reset
        (
            new vtkCaseWriter
            (
                runTime_.path(), runTime_.caseName().name(),
                wallModel_->movesGeometry()
              ? vtkCaseWriter::movingWalls
              : vtkCaseWriter::staticWalls
            )
        );
    }
    vtkCaseWriter& vtk = *vtk_;

    vtkParticleFile particleFile(parts_);
    vtk.writeParticles(particleFile, runTime_.timeIndex(), runTime_.value());

    if (vtk.wallsDue() && wallModel_->movesGeometry())
    {
        // Where the vertex particles (after the fluid) have moved them
        const SubList<vector2D> vertices
        (
            parts_.positions(), walls_->points().size(), work_.nFluid
        );
        vtkWallFile wallFile(vertices, walls_->segments());
        wallFile.addCellField
        (
            "normal", wallModel_->operatorWalls()->segmentNormals()
        );
        wallFile.addCellField("patch", walls_->segmentPatch());
        vtk.writeWalls(wallFile, runTime_.timeIndex(), runTime_.value());
    }
    else if (vtk.wallsDue())
    {
        vtkWallFile wallFile(walls_->points(), walls_->segments());
        wallFile.addCellField("normal", walls_->segmentNormals());
        wallFile.addCellField("patch", walls_->segmentPatch());
        vtk.writeWalls(wallFile, runTime_.timeIndex(), runTime_.value());
    }
}


void Foam::SPH::wcsph::printTimes() const
{
    stages_.printTimes(Info);
    const scalar total = timeNeighbours_ + timeInteractions_ + timeIntegration_;
    if (total > 0)
    {
        Info<< "Within the steps: neighbour search " << timeNeighbours_ << " s ("
            << label(100*timeNeighbours_/total + 0.5) << "%), interactions "
            << timeInteractions_ << " s (" << label(100*timeInteractions_/total + 0.5)
            << "%), integration " << timeIntegration_ << " s ("
            << label(100*timeIntegration_/total + 0.5) << "%)" << nl
            << "Neighbour lists: " << nListBuilds_ << " built, "
            << nListRefreshes_ << " refreshed" << nl
            << "Rate (force) evaluations " << nRateEvaluations_ << nl;
    }
    if (nSteps_ > 0 && stages_.seconds() > 0)
    {
        Info<< "Steps " << nSteps_ << ", particle-steps per second "
            << work_.nFluid*nSteps_/stages_.seconds() << nl;
    }
    bounds_.printSummary(Info);
    Info<< "Fluid particles " << work_.nFluid << ", total mass " << totalMass()
        << " kg/m" << nl;
}


void Foam::SPH::wcsph::printStep() const
{
    if (nBounced_)
    {
        Info<< "Wall bounces since the last report: " << nBounced_ << nl;
    }
    nBounced_ = 0;
    if (nHeld_)
    {
        Info<< "Particles held off the walls since the last report: "
            << nHeld_ << nl;
    }
    nHeld_ = 0;
    stages_.printStep(Info);
}


Foam::scalar Foam::SPH::wcsph::totalMass() const
{
    return work_.nFluid*cloud_->mass();
}


// ************************************************************************* //
