/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The start of an isphFoam run: the particles from constant/sphMesh (or
    the restart time), the initial velocity, the cloud and its domain, the
    USAW walls and the particle volumes, and the free-surface condition.

\*---------------------------------------------------------------------------*/

#include "isph.H"
#include "fluidProperties.H"
#include "Time.H"
#include "OSspecific.H"
#include "initialField.H"
#include "mathematicalConstants.H"
#include "moveWalls.H"
#include "particleChecks.H"
#include "checkedEntry.H"

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
    DynamicList<vector2D> wallX;
    DynamicList<label> wallType, wallPatch;
    wallModel_->wallParticles(runTime_, *walls_, wallX, wallType, wallPatch);
    nFluid_ = sphCloud::layOut(runTime_, parts_, wallX, wallType, wallPatch);
    readInitialVelocity();
}


void Foam::SPH::isph::initialise(const scalar rho0)
{
    parts_.add<vector2D>("U");
    parts_.add<scalar>("p");
    parts_.add<label>("id");
    parts_.add<label>("type");
    parts_.add<label>("patch");

    // Before the restart's fields are read: the model adds its own
    turbulence_ = turbulenceModel::New(runTime_, parts_);
    if (thermalProperties::present(runTime_))
    {
        thermal_.reset(new heatTransfer(runTime_, parts_));
    }
    else
    {
        Info<< "No 0/T: isothermal" << nl;
    }

    const label nVertices = walls_->points().size();
    if (isFile(parts_.path()/"positions"))
    {
        Info<< "Restarting from " << parts_.path() << nl;
        fresh_ = false;
        parts_.read();
        checkRestartParticles(parts_, walls_->patchNames().size(), sphCloud::solverDomain(*walls_, kernel_->support()));
        nFluid_ = sphCloud::countFluid(parts_);
        wallModel_->checkRestart
        (
            *walls_, parts_.path(), nFluid_, parts_.size() - nFluid_
        );
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


void Foam::SPH::isph::ghostCondition(const bool renormalised)
{
    const bool ghost = freeSurfaceConditionNames.getOrDefault
    (
        "freeSurfaceCondition", schemes_, freeSurfaceConditionType::dirichlet
    ) == freeSurfaceConditionType::ghost;
    if (!ghost || !freeSurface_)
    {
        return;
    }
    if (!renormalised)
    {
        FatalIOErrorInFunction(schemes_.lookup("freeSurfaceCondition"))
            << "Entry freeSurfaceCondition ghost needs pressureGradient"
            << " renormalised (its gradient completes G-{p})"
            << exit(FatalIOError);
    }
    isphWork& w = *work_;
    w.ghostSurface = true;
    w.surfaceDistance = 0.5*dr_;
    w.surfaceNormal.setSize(parts_.size(), Zero);
    w.compaction = checkedScalar
    (
        schemes_, "freeSurfaceCompaction", scalar(0), {0, 10},
        "alpha of the free-surface rows' density source (ghost)"
    );
}


void Foam::SPH::isph::readInteriorCompaction()
{
    work_->interiorCompaction = checkedScalar
    (
        schemes_, "interiorCompaction", scalar(0), {0, 10},
        "alpha of the interior rows' density source"
    );
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
    verlet_.reset
    (
        new verletList
        (
            checkedScalar
            (
                schemes_, "neighbourSkin", 0, {0, VGREAT},
                "Verlet skin in h: neighbours listed within support + skin,"
                " searched again when a particle has moved skin/2"
            )*kernel_->h()
        )
    );
    usaw_.reset(new usawWalls(*walls_, *kernel_, nFluid_));
    if (!motion_->movesGeometry())
    {
        crossing_.reset(new wallCrossing(*walls_, kernel_->support()));
    }
    work_.reset
    (
        new isphWork
        (
            fluid.rho0, fluid.nu,
            // With a 0/T, as buoyantBoussinesq*Foam's periodic p_rgh: no
            // gravity along a period, only the Boussinesq force (Leroy et
            // al. 2015, eq. (17)); a fluid at TRef is at rest there
            thermal_ ? cloud_->dom().acrossPeriods(fluid.g) : fluid.g,
            *cloud_, nbrs_, *verlet_, *usaw_, *motion_
        )
    );

    // Vertex particles are fluid particles cut by the wall (000_...
    // section 2): their share theta_v/(2 pi) of a particle's volume, so
    // that with the first row dr from the wall the volumes tile the fluid
    scalarList& V = work_->V;
    V = dr_*dr_;
    const scalarList share
    (
        wallModel_->volumeShares(*walls_, V.size() - nFluid_)
    );
    forAll(share, v)
    {
        V[nFluid_ + v] *= share[v];
    }
    moveWalls::move(*work_, runTime_.value(), true);
    connectTurbulence();
    connectThermal();
}


void Foam::SPH::isph::connectTurbulence()
{
    isphWork& w = *work_;
    turbulence_->connect
    (
        {w.W, w.nbrs, w.usaw, w.V, w.nu, w.nFluid, dr_, w.motion.any()},
        *walls_, fresh_
    );
    w.nut = turbulence_->nut();
    w.wallLaw = turbulence_->wallFunction();
    w.shiftedScalars.append(turbulence_->shiftedFields());
}


// ************************************************************************* //
