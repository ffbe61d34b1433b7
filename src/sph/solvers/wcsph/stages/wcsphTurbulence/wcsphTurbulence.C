/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsphTurbulence.H"
#include "wallBoundaries.H"
#include "IOdictionary.H"
#include "Switch.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::turbulenceModel> Foam::SPH::wcsphTurbulence::New
(
    const Time& runTime,
    const wcsphWallModel& wallModel,
    particles& parts
)
{
    const IOdictionary props
    (
        IOobject
        (
            "turbulenceProperties", runTime.constant(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    const word simulationType
    (
        props.getOrDefault<word>("simulationType", "laminar")
    );
    const dictionary* ras = props.findDict("RAS");
    const bool turbulent =
        simulationType != "laminar"
     && (!ras || ras->getOrDefault<Switch>("turbulence", true));
    if (turbulent && wallModel.type() != "usaw")
    {
        FatalIOErrorInFunction(props.lookup("simulationType"))
            << "simulationType " << simulationType << " with boundaryMethod "
            << wallModel.type() << " (system/sphSchemes): the k-epsilon"
            << " model's wall functions are those of the USAW walls (Leroy et"
            << " al. 2014, eqs. (22)-(29)); use boundaryMethod usaw (and"
            << " remake the particles with sphMesh), or a laminar flow"
            << exit(FatalIOError);
    }
    return turbulenceModel::New(runTime, parts);
}


Foam::SPH::usawWalls& Foam::SPH::wcsphTurbulence::usawOf
(
    wcsphWallModel& wallModel,
    const dictionary& schemes
)
{
    usawWalls* walls = wallModel.operatorWalls();
    if (!walls)
    {
        FatalIOErrorInFunction(schemes)
            << "boundaryMethod " << wallModel.type() << ": a RAS model needs"
            << " boundaryMethod usaw" << exit(FatalIOError);
    }
    return *walls;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wcsphTurbulence::wcsphTurbulence
(
    const Time& runTime,
    const dictionary& schemes,
    turbulenceModel& model,
    wcsphWork& work,
    wcsphWallModel& wallModel,
    const wallMesh& walls,
    const bool fresh,
    const std::function<void()>& searchNeighbours
)
:
    stage("turbulence", model.reads(), model.writes()),
    model_(model),
    work_(work),
    wallModel_(wallModel),
    searchNeighbours_(searchNeighbours),
    usaw_(usawOf(wallModel, schemes)),
    V_(work.parts.size(), Zero),
    coupling_
    {
        work.cloud->W(), work.nbrs, usaw_, V_, work.nu, work.nFluid,
        work.dr, wallBoundaries(runTime, walls).any()
    },
    visc_(work.parts.size(), Zero)
{
    model_.connect(coupling_, walls, fresh);
    work.nut = model_.nut();
    work.wallLaw = model_.wallFunction();
    work.shiftedScalars.append(model_.shiftedFields());
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wcsphTurbulence::prepare()
{
    searchNeighbours_();
    usaw_.update(work_.parts.positions());
    wallModel_.fluidVolumes(V_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wcsphTurbulence::describe(Ostream& os) const
{
    os  << model_.description().c_str() << nl
        << "        at the step's new positions, V = m/rho; then the"
        << " vertex particles' slip, eq. (24)";
}


void Foam::SPH::wcsphTurbulence::execute(const scalar dt)
{
    prepare();
    model_.correct(dt);

    // Eq. (24) with nu_T as the model leaves it for the coming step
    vector2DField& U = work_.parts.field<vector2D>("U");
    slip_.viscousAcceleration(coupling_, *work_.nut, *work_.wallLaw, U, visc_);
    slip_.moveVertices(usaw_, work_.nFluid, visc_, dt, U);
}


// ************************************************************************* //
