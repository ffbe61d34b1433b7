/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsph.H"
#include "memberStage.H"
#include "OStringStream.H"
#include "fluidProperties.H"
#include "Time.H"
#include "dimensionedScalar.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"
#include "vtkCaseWriter.H"
#include "vtkParticleFile.H"
#include "vtkWallFile.H"
#include "wallConditions.H"
#include "initialField.H"

#include <cmath>
#include <chrono>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::wcsph::boundaryMethod>
Foam::SPH::wcsph::boundaryMethodNames
({
    { boundaryMethod::dummyRepulsive, "dummyRepulsive" },
});

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
    rho0_ = fluid.rho0;
    nu_ = fluid.nu;
    g_ = fluid.g;
}


void Foam::SPH::wcsph::readSchemes()
{
    boundaryMethodNames.getOrDefault
    (
        "boundaryMethod", schemes_, boundaryMethod::dummyRepulsive
    );

    gamma_ = schemes_.getOrDefault<scalar>("gamma", 7);
    if (schemes_.found("c0"))
    {
        c0_ = schemes_.get<scalar>("c0");
    }
    else if (schemes_.found("Umax"))
    {
        c0_ = schemes_.getOrDefault<scalar>("c0ByUmax", 10)*schemes_.get<scalar>("Umax");
    }
    else
    {
        FatalIOErrorInFunction(schemes_)
            << "Missing entry 'c0' (the numerical speed of sound, m/s), or"
            << " 'Umax' (the expected largest speed; c0 = c0ByUmax Umax with"
            << " c0ByUmax 10 by default)" << nl << exit(FatalIOError);
    }
    if (!(c0_ > 0) || !(gamma_ >= 1))
    {
        FatalIOErrorInFunction(schemes_)
            << "Expected c0 > 0 and gamma >= 1, found c0 " << c0_
            << " and gamma " << gamma_ << exit(FatalIOError);
    }
    b0_ = rho0_*c0_*c0_/gamma_;

    // 004_... eq. (11): K = 0.01 b0 gamma/rho0 (= 0.01 c0^2)
    ks_ = schemes_.getOrDefault<scalar>("ks", 1.5);
    K_ = 0.01*b0_*gamma_/rho0_;
    if (!(ks_ > 0) || ks_*kernel_->h() > kernel_->support() + SMALL)
    {
        FatalIOErrorInFunction(schemes_)
            << "Entry ks " << ks_ << ": expected 0 < ks <= "
            << kernel_->support()/kernel_->h()
            << " (the repulsion must lie within the kernel support)"
            << exit(FatalIOError);
    }

    densityDiffusion_ = schemes_.getOrDefault<bool>("densityDiffusion", true);
    densityDiffusionHydrostatic_ =
        densityDiffusion_
     && schemes_.getOrDefault<bool>("densityDiffusionHydrostatic", true);

    // Not in 004_..., which relies on the density diffusion alone; a small
    // alpha damps the velocity noise of water at rest
    alphaAV_ = schemes_.getOrDefault<scalar>("artificialViscosity", 0);
    if (alphaAV_ < 0)
    {
        FatalIOErrorInFunction(schemes_.lookup("artificialViscosity"))
            << "artificialViscosity (Monaghan's alpha) must be >= 0"
            << exit(FatalIOError);
    }
    viscosity_ = viscosityModelNames.getOrDefault
    (
        "viscosity", schemes_, viscosityModel::Morris
    );
    if (nu_ == 0)
    {
        viscosity_ = viscosityModel::none;
    }
    skinByH_ = schemes_.getOrDefault<scalar>("neighbourSkin", 0.2);
    if (skinByH_ < 0)
    {
        FatalIOErrorInFunction(schemes_)
            << "neighbourSkin " << skinByH_ << ": expected a length in h >= 0"
            << " (0: rebuild the neighbour list at every stage)"
            << exit(FatalIOError);
    }
}


void Foam::SPH::wcsph::initialiseFromSphMesh()
{
    particles fluid(runTime_, runTime_.constant(), "sphMesh/fluid", false);
    fluid.read();
    particles dummy(runTime_, runTime_.constant(), "sphMesh/dummy", false);
    dummy.add<label>("layer");
    dummy.add<label>("patch");
    dummy.read();

    nFluid_ = fluid.size();
    parts_.resize(nFluid_ + dummy.size());
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
    forAll(dummy.positions(), d)
    {
        const label i = nFluid_ + d;
        x[i] = dummy.positions()[d];
        type[i] = label
        (
            dummy.field<label>("layer")[d] == 0
          ? particleKind::interfacial
          : particleKind::dummy
        );
        patch[i] = dummy.field<label>("patch")[d];
    }
    forAll(id, i)
    {
        id[i] = i;
    }
    setInitialFields();
}


void Foam::SPH::wcsph::hydrostaticPressure(ITstream& is)
{
    const scalar gMag = mag(g_);
    if (mag(g_.x()) > SMALL*gMag)
    {
        FatalIOErrorInFunction(is)
            << "internalField hydrostatic needs gravity along -y"
            << exit(FatalIOError);
    }

    // The top of each lattice column of water is its free surface
    HashTable<scalar, label, Hash<label>> top;
    const vector2DField& x = parts_.positions();
    for (label i = 0; i < nFluid_; ++i)
    {
        const label col = std::lround(x[i].x()/dr_);
        auto it = top.find(col);
        if (!it.found()) top.set(col, x[i].y());
        else *it = max(*it, x[i].y());
    }
    scalarField& p = parts_.field<scalar>("p");
    for (label i = 0; i < nFluid_; ++i)
    {
        const scalar surface = top[std::lround(x[i].x()/dr_)] + 0.5*dr_;
        p[i] = rho0_*gMag*(surface - x[i].y());
    }
}


void Foam::SPH::wcsph::setInitialFields()
{
    const word t0(runTime_.timeName());
    SubList<vector2D> U(parts_.field<vector2D>("U"), nFluid_);
    SubList<scalar> p(parts_.field<scalar>("p"), nFluid_);
    U = vector2D::zero;
    p = 0;

    const initialField U0(runTime_, "U");
    if (!U0.found())
    {
        Info<< "No " << t0/"U" << ": the fluid starts at rest" << nl;
    }
    else if (U0.read(U))
    {
        Info<< "Initial velocity " << U[0] << " from " << U0.path() << nl;
    }
    else
    {
        Info<< "Initial velocity per particle from " << U0.path() << nl;
    }

    const initialField p0(runTime_, "p");
    if (!p0.found())
    {
        Info<< "No " << t0/"p" << ": the fluid starts at p = 0" << nl;
    }
    else if (p0.kind() == "hydrostatic")
    {
        hydrostaticPressure(p0.stream());
        Info<< "Initial pressure hydrostatic (rho0 |g| depth below the top"
            << " of each water column) from " << p0.path() << nl;
    }
    else if (p0.read(p, " or 'internalField hydrostatic;'"))
    {
        Info<< "Initial pressure " << p[0] << " from " << p0.path() << nl;
    }
    else
    {
        Info<< "Initial pressure per particle from " << p0.path() << nl;
    }

    // Density from the equation of state; walls at rest at rho0
    vector2DField& Uall = parts_.field<vector2D>("U");
    scalarField& pAll = parts_.field<scalar>("p");
    scalarField& rho = parts_.field<scalar>("rho");
    for (label i = 0; i < nFluid_; ++i)
    {
        rho[i] = density(pAll[i]);
    }
    for (label i = nFluid_; i < parts_.size(); ++i)
    {
        Uall[i] = vector2D::zero;
        rho[i] = rho0_;
        pAll[i] = 0;
    }
}


void Foam::SPH::wcsph::initialise()
{
    parts_.add<vector2D>("U");
    parts_.add<scalar>("rho");
    parts_.add<scalar>("p");
    parts_.add<label>("id");
    parts_.add<label>("type");
    parts_.add<label>("patch");

    if (isFile(parts_.path()/"positions"))
    {
        Info<< "Restarting from " << parts_.path() << nl;
        parts_.read();
        nFluid_ = 0;
        const labelField& type = parts_.field<label>("type");
        while (nFluid_ < type.size() && type[nFluid_] == label(particleKind::fluid))
        {
            ++nFluid_;
        }
    }
    else
    {
        Info<< "Starting from the particles of constant/sphMesh" << nl;
        initialiseFromSphMesh();
    }

    const label n = parts_.size();
    dUdt_.setSize(nFluid_);
    drhodt_.setSize(nFluid_);
    x0_.setSize(nFluid_);
    U0_.setSize(nFluid_);
    sumX_.setSize(nFluid_);
    sumU_.setSize(nFluid_);
    rhoStart_.setSize(nFluid_);
    sumRho_.setSize(nFluid_);

    Info<< "Particles: " << nFluid_ << " fluid, " << n - nFluid_ << " dummy"
        << nl << endl;
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
    rho0_(0), nu_(0), g_(vector2D::zero),
    c0_(0), gamma_(7), b0_(0), ks_(1.5), K_(0),
    densityDiffusion_(true), densityDiffusionHydrostatic_(true), alphaAV_(0),
    viscosity_(viscosityModel::Morris),
    walls_(new wallMesh(runTime)),
    parts_(runTime, runTime.timeName()),
    nFluid_(0),
    dr_(0),
    nbrs_(true),
    skinByH_(0.2),
    skin_(0),
    listBuilt_(false),
    nListBuilds_(0),
    nListRefreshes_(0),
    nBounced_(0),
    ratesCurrent_(false),
    timeNeighbours_(0), timeInteractions_(0), timeIntegration_(0),
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
        dr_ = meshDict.get<scalar>("dr");
    }
    kernel_ = kernel::New(schemes_, dr_);
    readSchemes();
    wallConditions(runTime, *walls_, "U").allowOnly
    (
        {wallConditions::conditionType::noSlip},
        "the dummy and repulsive walls of wcsphFoam (still walls)"
    );
    wallConditions(runTime, *walls_, "p");
    skin_ = skinByH_*kernel_->h();
    initialise();

    cloud_.reset
    (
        new sphCloud
        (
            runTime, parts_, *kernel_, *walls_, nFluid_, dr_, rho0_, g_,
            sphCloud::solverDomain(*walls_, kernel_->support())
        )
    );

    if (schemes_.getOrDefault<bool>("wallBounce", true))
    {
        crossing_.reset(new wallCrossing(*walls_, kernel_->support()));
    }
    addStages();
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


void Foam::SPH::wcsph::addStages()
{
    OStringStream rates;
    rates
        << "classical Runge-Kutta, eq. (14); at each of its four stages:" << nl
        << "        neighbours         cell-linked list, " << neighbourPolicy().c_str() << nl
        << "        wall particles     dummy pressure eq. (10), density from eq. (4)"
        << nl
        << "        equation of state  Tait eq. (4): c0 " << c0_ << ", gamma "
        << gamma_ << ", b0 " << b0_ << nl
        << "        continuity         eq. (6)"
        << (densityDiffusion_ ? " with Rusanov density diffusion (7)" : "");
    if (densityDiffusion_)
    {
        rates
            << nl << "                           of "
            << (
                   densityDiffusionHydrostatic_
                 ? "rho - rho_hydrostatic (densityDiffusionHydrostatic yes)"
                 : "rho, as printed (densityDiffusionHydrostatic no)"
               );
    }
    rates
        << nl << "        momentum           Hu-Adams pressure gradient eq. (8), gravity "
        << g_ << nl
        << "        repulsion          eqs. (11)-(12): ks " << ks_ << ", K " << K_
        << nl << "        viscosity          ";
    if (viscosity_ == viscosityModel::Morris)
    {
        rates << "Morris, nu " << nu_;
    }
    else
    {
        rates << "none (nu = " << nu_ << ")";
    }
    if (alphaAV_ > 0)
    {
        rates
            << nl << "        artificial viscosity  Monaghan, alpha " << alphaAV_
            << " (not in 004_...)";
    }

    stages_.add
    (
        new memberStage<wcsph>
        (
            "rungeKutta4", {"positions", "U", "rho"}, {"positions", "U", "rho"},
            rates.str(), *this, &wcsph::rungeKutta4, "Runge-Kutta 4"
        )
    );
    if (crossing_)
    {
        stages_.add
        (
            new memberStage<wcsph>
            (
                "wallBounce", {"positions", "U"}, {"positions", "U"},
                "particles that cross a wall in a step bounce back (a safety"
                " net; counted in the log)", *this, &wcsph::wallBounce
            )
        );
    }
    stages_.add
    (
        new memberStage<wcsph>
        (
            "equationOfState", {"rho"}, {"p"},
            "Tait eq. (4): p of the new density", *this, &wcsph::equationOfState
        )
    );
}


void Foam::SPH::wcsph::printSettings() const
{
    if (!crossing_)
    {
        Info<< "    wall crossing       not checked (wallBounce no)" << nl;
    }
    Info<< "    time step           eq. (15), C_n = maxCo "
        << runTime_.controlDict().getOrDefault<scalar>("maxCo", 0.2)
        << (runTime_.controlDict().getOrDefault<bool>("adjustTimeStep", false)
            ? "" : " (adjustTimeStep off: deltaT fixed)")
        << nl;
}


Foam::scalar Foam::SPH::wcsph::maxDeltaT() const
{
    // The rates of the state are those of the coming step's first stage
    if (!ratesCurrent_)
    {
        const_cast<wcsph&>(*this).computeRates();
    }
    const scalar h = kernel_->h();
    const scalar Cn = runTime_.controlDict().getOrDefault<scalar>("maxCo", 0.2);

    // 004_... eq. (15), and the viscous and force limits of 000_... eq. (49)
    scalar dt = Cn*h/max(maxSoundSpeed_, maxSpeed_);
    if (nu_ > 0)
    {
        dt = min(dt, 0.125*h*h/nu_);
    }
    if (maxAccel_ > 0)
    {
        dt = min(dt, 0.25*std::sqrt(h/maxAccel_));
    }
    return min(dt, GREAT);
}


void Foam::SPH::wcsph::rungeKutta4(const scalar dt)
{
    if (!ratesCurrent_)
    {
        computeRates();
    }

    vector2D* x = parts_.positions().data();
    vector2D* U = parts_.field<vector2D>("U").data();
    scalar* rho = parts_.field<scalar>("rho").data();

    const label nF = nFluid_;
    for (label i = 0; i < nF; ++i)
    {
        x0_[i] = x[i];
        U0_[i] = U[i];
        rhoStart_[i] = rho[i];
        sumX_[i] = vector2D::zero;
        sumU_[i] = vector2D::zero;
        sumRho_[i] = 0;
    }

    // Classical Runge-Kutta, 004_... eq. (14): alpha = 1/2, 1/2, 1, 1/6
    static const scalar stageFraction[3] = {0.5, 0.5, 1.0};
    static const scalar weight[4] = {1.0/6, 1.0/3, 1.0/3, 1.0/6};

    for (label stage = 0; stage < 4; ++stage)
    {
        if (stage > 0)
        {
            computeRates();
        }
        const auto start = std::chrono::steady_clock::now();
        const scalar w = weight[stage];
        const scalar a = stage < 3 ? stageFraction[stage]*dt : 0;

        #pragma omp parallel for schedule(static)
        for (label i = 0; i < nF; ++i)
        {
            sumX_[i] += w*U[i];
            sumU_[i] += w*dUdt_[i];
            sumRho_[i] += w*drhodt_[i];
            if (stage < 3)
            {
                x[i] = x0_[i] + a*U[i];
                U[i] = U0_[i] + a*dUdt_[i];
                rho[i] = rhoStart_[i] + a*drhodt_[i];
            }
            else
            {
                x[i] = x0_[i] + dt*sumX_[i];
                U[i] = U0_[i] + dt*sumU_[i];
                rho[i] = rhoStart_[i] + dt*sumRho_[i];
            }
        }
        timeIntegration_ += std::chrono::duration<scalar>
        (
            std::chrono::steady_clock::now() - start
        ).count();
    }

    // The stages may stray across a periodic seam (the cell list and the
    // pair separations take the minimum image); the step ends inside
    const domain& dom = cloud_->dom();
    if (dom.anyPeriodic())
    {
        for (label i = 0; i < nF; ++i)
        {
            x[i] = dom.wrap(x[i]);
        }
    }
    ratesCurrent_ = false;
}


void Foam::SPH::wcsph::wallBounce(const scalar dt)
{
    nBounced_ += crossing_->bounce
    (
        x0_, parts_.positions(), parts_.field<vector2D>("U"), nFluid_
    );
}


void Foam::SPH::wcsph::equationOfState(const scalar dt)
{
    const scalar* rho = parts_.field<scalar>("rho").cdata();
    scalar* p = parts_.field<scalar>("p").data();
    for (label i = 0; i < nFluid_; ++i)
    {
        p[i] = pressure(rho[i]);
    }
}


void Foam::SPH::wcsph::afterStep(const scalar dt)
{
    // The neighbour search function objects use
    cloud_->updateCells();

    // A restart from this time builds a new list at its first step: so does
    // this run, or the two would sum the pairs in different orders
    if (runTime_.writeTime())
    {
        listBuilt_ = false;
    }
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
                vtkCaseWriter::staticWalls
            )
        );
    }
    vtkCaseWriter& vtk = *vtk_;

    vtkParticleFile particleFile(parts_);
    vtk.writeParticles(particleFile, runTime_.timeIndex(), runTime_.value());

    if (vtk.wallsDue())
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
        Info<< "Within the Runge-Kutta stages: neighbour search " << timeNeighbours_ << " s ("
            << label(100*timeNeighbours_/total + 0.5) << "%), interactions "
            << timeInteractions_ << " s (" << label(100*timeInteractions_/total + 0.5)
            << "%), integration " << timeIntegration_ << " s ("
            << label(100*timeIntegration_/total + 0.5) << "%)" << nl
            << "Neighbour lists: " << nListBuilds_ << " built, "
            << nListRefreshes_ << " refreshed" << nl;
    }
    Info<< "Fluid particles " << nFluid_ << ", total mass " << totalMass()
        << " kg/m" << nl;
}


void Foam::SPH::wcsph::printStep() const
{
    if (nBounced_)
    {
        Info<< "Wall bounces since the last report: " << nBounced_ << nl;
    }
    nBounced_ = 0;
}


Foam::scalar Foam::SPH::wcsph::totalMass() const
{
    return nFluid_*cloud_->mass();
}


// ************************************************************************* //
