/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The particles of wcsphFoam at the start: the fluid of constant/sphMesh
    and the wall particles its wall model expects, with 0/U and 0/p; or a
    restart. The turbulence model first, so that its fields are read back.

\*---------------------------------------------------------------------------*/

#include "wcsph.H"
#include "wcsphTurbulence.H"
#include "Time.H"
#include "OSspecific.H"
#include "initialField.H"
#include "particleChecks.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wcsph::initialiseFromSphMesh()
{
    // The wall particles the wall model expects (dummies, wall vertices)
    DynamicList<vector2D> wallX;
    DynamicList<label> wallType, wallPatch;
    wallModel_->wallParticles(wallX, wallType, wallPatch);
    work_.nFluid =
        sphCloud::layOut(runTime_, parts_, wallX, wallType, wallPatch);
    setInitialFields();
}


void Foam::SPH::wcsph::hydrostaticPressure(ITstream& is)
{
    const scalar gMag = mag(work_.g);
    if (mag(work_.g.x()) > SMALL*gMag)
    {
        FatalIOErrorInFunction(is)
            << "internalField hydrostatic needs gravity along -y"
            << exit(FatalIOError);
    }

    // The top of each lattice column of water is its free surface
    HashTable<scalar, label, Hash<label>> top;
    const vector2DField& x = parts_.positions();
    for (label i = 0; i < work_.nFluid; ++i)
    {
        const label col = std::lround(x[i].x()/dr_);
        auto it = top.find(col);
        if (!it.found()) top.set(col, x[i].y());
        else *it = max(*it, x[i].y());
    }
    scalarField& p = parts_.field<scalar>("p");
    for (label i = 0; i < work_.nFluid; ++i)
    {
        const scalar surface = top[std::lround(x[i].x()/dr_)] + 0.5*dr_;
        p[i] = work_.rho0*gMag*(surface - x[i].y());
    }
}


void Foam::SPH::wcsph::setInitialFields()
{
    const word t0(runTime_.timeName());
    const label nFluid = work_.nFluid;
    SubList<vector2D> U(parts_.field<vector2D>("U"), nFluid);
    SubList<scalar> p(parts_.field<scalar>("p"), nFluid);
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

    // Density from the equation of state; the walls' from the model
    const scalarField& pAll = parts_.field<scalar>("p");
    scalarField& rho = parts_.field<scalar>("rho");
    for (label i = 0; i < nFluid; ++i)
    {
        // Tension beyond -b0 has no density in eq. (4): it is not clamped
        if (!(pAll[i] > -work_.b0) || !std::isfinite(pAll[i]))
        {
            FatalErrorInFunction
                << runTime_.path()/t0/"p" << ": the initial pressure " << pAll[i]
                << " Pa of fluid particle " << i << " is below -rho0 c0^2/gamma"
                << " = " << -work_.b0 << " Pa, the tension eq. (4) can hold"
                << exit(FatalError);
        }
        rho[i] = work_.density(pAll[i]);
    }
    wallModel_->initialWalls();
}


void Foam::SPH::wcsph::initialise()
{
    parts_.add<vector2D>("U");
    parts_.add<scalar>("rho");
    parts_.add<scalar>("p");
    parts_.add<label>("id");
    parts_.add<label>("type");
    parts_.add<label>("patch");

    // Before the particles are read: the model adds its fields (k, ...)
    turbulence_ = wcsphTurbulence::New(runTime_, *wallModel_, parts_);

    fresh_ = !isFile(parts_.path()/"positions");
    if (!fresh_)
    {
        Info<< "Restarting from " << parts_.path() << nl;
        parts_.read();
        checkRestartParticles(parts_, walls_->patchNames().size(), sphCloud::solverDomain(*walls_, kernel_->support()));
        const label nFluid = sphCloud::countFluid(parts_);
        work_.nFluid = nFluid;
        wallModel_->checkRestart(parts_.path(), nFluid, parts_.size() - nFluid);
    }
    else
    {
        Info<< "Starting from the particles of constant/sphMesh" << nl;
        initialiseFromSphMesh();
    }

    const label n = parts_.size();
    work_.dUdt.setSize(work_.nFluid);
    work_.drhodt.setSize(work_.nFluid);
    x0_.setSize(work_.nFluid);
    U0_.setSize(work_.nFluid);
    sumX_.setSize(work_.nFluid);
    sumU_.setSize(work_.nFluid);
    rhoStart_.setSize(work_.nFluid);
    sumRho_.setSize(work_.nFluid);

    Info<< "Particles: " << work_.nFluid << " fluid, " << n - work_.nFluid << " "
        << wallModel_->wallParticleName()
        << nl << endl;
}



// ************************************************************************* //
