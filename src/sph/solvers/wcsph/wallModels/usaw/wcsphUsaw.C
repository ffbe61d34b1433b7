/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsphUsaw.H"
#include "checkedEntry.H"
#include "wcsphUsawTemplates.C"
#include "wcsphWallPressure.H"
#include "kernelDispatch.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wcsphUsaw, 0);
    addToRunTimeSelectionTable(wcsphWallModel, wcsphUsaw, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- The wall conditions these walls support, or an error naming the
    //- file and entry; returns runTime
    const Foam::Time& checkConditions
    (
        const Foam::Time& runTime,
        const Foam::SPH::wallMesh& walls
    )
    {
        using ct = Foam::SPH::wallConditions::conditionType;
        Foam::SPH::wallConditions(runTime, walls, "U").allowOnly
        (
            {
                ct::noSlip, ct::fixedValue, ct::uniformFixedValue,
                ct::movingWallVelocity
            },
            "the usaw walls of wcsphFoam (still, sliding and moving walls)"
        );
        return runTime;
    }

}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wcsphUsaw::wcsphUsaw
(
    const Time& runTime,
    const dictionary& schemes,
    const wallMesh& walls,
    const kernel& W,
    wcsphWork& work
)
:
    wcsphWallModel(runTime, schemes, walls, W, work),
    motion_(checkConditions(runTime, walls), walls),
    pBackground_
    (
        checkedScalar(schemes, "backgroundPressure", 0, {0, VGREAT}, "Pa")
    ),
    viscousWallPressure_
    (
        schemes.getOrDefault<bool>("wallPressureViscous", false)
    ),
    gradientForm_
    (
        projection::gradientFormNames.getOrDefault
        (
            "pressureGradient", schemes,
            projection::gradientForm::antisymmetric
        )
    ),
    tensileControl_
    (
        schemes.getOrDefault<bool>("tensileInstabilityControl", false)
    ),
    freeSurfaceDivR_
    (
        checkedScalar
        (
            schemes, "freeSurfaceDivR", 1.5, {0, 2, true, true},
            "D{r} is 2 inside the fluid"
        )
    ),
    wallX_(walls.points().size()),
    wallU_(walls.points().size()),
    wallAcceleration_(walls.points().size(), vector2D::zero)
{
    if (!(pBackground_ >= 0))
    {
        FatalIOErrorInFunction(schemes.lookup("backgroundPressure"))
            << "Entry backgroundPressure " << pBackground_ << ": expected >= 0"
            << exit(FatalIOError);
    }
    if
    (
        tensileControl_
     && gradientForm_ != projection::gradientForm::antisymmetric
    )
    {
        FatalIOErrorInFunction(schemes.lookup("tensileInstabilityControl"))
            << "tensileInstabilityControl yes switches G+ (5) to G- (8) where"
            << " the pressure is negative, so it needs pressureGradient"
            << " antisymmetric, not "
            << projection::gradientFormNames[gradientForm_]
            << exit(FatalIOError);
    }
    refuseEntries({"ks", "wallTension"}, "dummyRepulsive");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wcsphUsaw::initialWalls() const
{
    wcsphWallModel::initialWalls();
    const_cast<wcsphUsaw&>(*this).setWallVelocity(runTime_.value());
}


void Foam::SPH::wcsphUsaw::setUp()
{
    wcsphWork& w = work_;
    if (w.parts.size() - w.nFluid != walls_.points().size())
    {
        FatalErrorInFunction
            << "Expected " << walls_.points().size() << " wall vertex"
            << " particles after the fluid, found " << w.parts.size() - w.nFluid
            << exit(FatalError);
    }
    usaw_.reset(new usawWalls(walls_, kernel_, w.nFluid, w.cloud->dom()));

    // Vertex particles are fluid particles cut by the wall (Leroy et al.
    // 2014 section 2): their share of a particle's mass
    const label n = w.parts.size();
    mass_.setSize(n, w.mass());
    const scalarList share(layout().volumeShares(walls_, n - w.nFluid));
    forAll(share, v)
    {
        mass_[w.nFluid + v] *= share[v];
    }
    V_.setSize(n);
    pTotal_.setSize(n);
    divU_.setSize(n);
    gradP_.setSize(n);
    if (gradientForm_ == projection::gradientForm::renormalised)
    {
        R_.setSize(n, tensor2D::I);
    }
    viscous_.setSize(n, vector2D::zero);
    if (tensileControl_)
    {
        divR_.setSize(n);
        nearSurface_.setSize(w.nFluid);
        symmetricGradient_.setSize(n, false);
    }

    // A restart's segments where its vertex particles are
    moveWalls(runTime_.value());
}


void Foam::SPH::wcsphUsaw::setWallVelocity(const scalar t)
{
    if (!motion_.any())
    {
        return;
    }
    motion_.vertices(t, wallX_, wallU_);
    vector2D* U = work_.parts.field<vector2D>("U").data();
    forAll(wallU_, v)
    {
        U[work_.nFluid + v] = wallU_[v];
    }
}


void Foam::SPH::wcsphUsaw::moveWalls(const scalar t)
{
    motion_.moveVertexParticles
    (
        t, work_.nFluid, true, work_.parts.positions(),
        work_.parts.field<vector2D>("U"), wallX_, wallU_, *usaw_
    );
    if (motion_.movesGeometry())
    {
        motion_.accelerations(t, wallAcceleration_);
    }
}


void Foam::SPH::wcsphUsaw::rates(const scalar t)
{
    wcsphWork& w = work_;
    moveWalls(t);
    usaw_->update(w.parts.positions());

    // The vertex pressure's hydrostatic step with g - a_w in the frame of
    // a wall that accelerates (zero for still and sliding walls)
    const UList<vector2D>* wallAcceleration =
        motion_.movesGeometry() ? &wallAcceleration_ : nullptr;
    dispatch(kernel_, [&](const auto& W)
    {
        // viscous_: the last rate evaluation's L{mu, u} (a stage old)
        shepardWallPressure
        (
            W, w, 0, wallAcceleration,
            viscousWallPressure_ ? &viscous_ : nullptr
        );
        w.setSoundSpeeds();
        fluidRates(W);
    });
}


void Foam::SPH::wcsphUsaw::turbulentViscous(const vector2DField& U)
{
    const wcsphWork& w = work_;
    turbulentViscosity_.viscousAcceleration
    (
        {kernel_, w.nbrs, *usaw_, V_, w.nu, w.nFluid, w.dr, false},
        *w.nut, *w.wallLaw, U, viscous_
    );
    const scalar rho0 = w.rho0;
    for (vector2D& v : viscous_)
    {
        v *= rho0;
    }
}


void Foam::SPH::wcsphUsaw::fluidVolumes(scalarList& V) const
{
    const scalarField& rho = work_.parts.field<scalar>("rho");
    V.setSize(rho.size());
    forAll(V, i)
    {
        V[i] = mass_[i]/rho[i];
    }
}


void Foam::SPH::wcsphUsaw::describe(Ostream& os, const char* indent) const
{
    const wcsphWork& w = work_;
    os  << indent << "walls              USAW: gamma and grad gamma_as analytical,"
        << " eqs. (56)-(64), (6)" << nl
        << indent << "wall particles     vertex particles, mass rho0 theta/(2 pi)"
        << " dr^2, wall velocity; pressure eq. (10) of 004_..., density"
        << " from eq. (4)" << nl
        << indent << "vertex pressure    Shepard average of p_b + "
        << (
               viscousWallPressure_
             ? "(rho_b (g + f) + L_b{mu, u}).(x_v - x_b)"
             : "rho_b (g + f).(x_v - x_b)"
           )
        << nl
        << indent << "equation of state  Tait eq. (4): c0 " << w.c0 << ", gamma "
        << w.gamma << ", b0 " << w.b0 << nl
        << indent << "continuity         -rho D{u}, eq. (9)";
    if (w.densityDiffusion)
    {
        os  << ", Rusanov density diffusion 004_... (6)-(7) of "
            << (
                   w.densityDiffusionHydrostatic
                 ? "rho - rho_hydrostatic"
                 : "rho, as printed"
               );
    }
    os  << nl << indent << "momentum           -G{p + p_b}/rho, eq. (13), with "
        << projection::formDescription(gradientForm_)
        << (
               tensileControl_
             ? ", G- (8) where p + p_b < 0 away from a free surface (tensile"
               " instability control, Sun et al. 2018)"
             : ""
           )
        << ": background pressure p_b " << pBackground_ << ", gravity " << w.g
        << nl << indent << "viscosity          ";
    if (w.nut)
    {
        os  << "L{mu_E, u}/rho, mu_E = rho0 (nu + nu_T), the log-law wall"
            << " friction and the vertices' slip, eqs. (22)-(24), nu " << w.nu
            << nl;
    }
    else if (w.viscous)
    {
        os  << "L{mu, u}/rho with the wall friction, eqs. (15)-(17), nu "
            << w.nu << nl;
    }
    else
    {
        os  << "none (nu = " << w.nu << ")" << nl;
    }
    if (motion_.movesGeometry())
    {
        os  << indent << "moving walls       vertex particles, segments,"
            << " gamma and grad gamma at each stage's time (t^n, t^n + dt/2"
            << " twice, t^n + dt); vertex pressure with g - a_w:" << nl;
        motion_.write(os, string(indent) + "    ");
    }
    else if (motion_.any())
    {
        os  << indent << "wall velocity      at each stage's time:" << nl;
        motion_.write(os, string(indent) + "    ");
    }
}


// ************************************************************************* //
