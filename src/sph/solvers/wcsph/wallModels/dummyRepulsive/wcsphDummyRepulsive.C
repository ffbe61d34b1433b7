/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsphDummyRepulsive.H"
#include "wcsphDummyRepulsiveTemplates.C"
#include "wallConditions.H"
#include "kernelDispatch.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wcsphDummyRepulsive, 0);
    addToRunTimeSelectionTable(wcsphWallModel, wcsphDummyRepulsive, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wcsphDummyRepulsive::wcsphDummyRepulsive
(
    const Time& runTime,
    const dictionary& schemes,
    const wallMesh& walls,
    const kernel& W,
    wcsphWork& work
)
:
    wcsphWallModel(runTime, schemes, walls, W, work),
    ks_(schemes.getOrDefault<scalar>("ks", 1.5)),
    // 004_... eq. (11): K = 0.01 b0 gamma/rho0 (= 0.01 c0^2)
    K_(0.01*work.b0*work.gamma/work.rho0),
    wallTension_(schemes.getOrDefault<bool>("wallTension", true))
{
    if (!(ks_ > 0) || ks_*W.h() > W.support() + SMALL)
    {
        FatalIOErrorInFunction(schemes)
            << "Entry ks " << ks_ << ": expected 0 < ks <= "
            << W.support()/W.h()
            << " (the repulsion must lie within the kernel support)"
            << exit(FatalIOError);
    }
    // Entries of the USAW walls' momentum equation
    refuseEntries
    (
        {"backgroundPressure", "pressureGradient", "tensileInstabilityControl"},
        "usaw"
    );
    wallConditions(runTime, walls, "U").allowOnly
    (
        {wallConditions::conditionType::noSlip},
        "the dummy and repulsive walls of wcsphFoam (still walls)"
    );
    wallConditions(runTime, walls, "p");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wcsphDummyRepulsive::rates(const scalar t)
{
    dispatch(kernel_, [&](const auto& W)
    {
        // Eq. (10): the dummies' pressure and density
        shepardWallPressure
        (
            W, work_, 0, nullptr, nullptr, wallTension_ ? -GREAT : 0
        );
        work_.setSoundSpeeds();
        fluidRates(W);
    });
}


void Foam::SPH::wcsphDummyRepulsive::describe
(
    Ostream& os,
    const char* indent
) const
{
    const wcsphWork& w = work_;
    os  << indent << "wall particles     dummy pressure eq. (10)"
        << (wallTension_ ? "" : ", fluid tension read as 0 (wallTension no)")
        << ", density from eq. (4)" << nl
        << indent << "equation of state  Tait eq. (4): c0 " << w.c0 << ", gamma "
        << w.gamma << ", b0 " << w.b0 << nl
        << indent << "continuity         eq. (6)"
        << (w.densityDiffusion ? " with Rusanov density diffusion (7)" : "");
    if (w.densityDiffusion)
    {
        os  << nl << indent << "                   of "
            << (
                   w.densityDiffusionHydrostatic
                 ? "rho - rho_hydrostatic (densityDiffusionHydrostatic yes)"
                 : "rho, as printed (densityDiffusionHydrostatic no)"
               );
    }
    os  << nl << indent << "momentum           Hu-Adams pressure gradient eq. (8),"
        << " gravity " << w.g << nl
        << indent << "repulsion          eqs. (11)-(12): ks " << ks_ << ", K "
        << K_ << nl << indent << "viscosity          ";
    if (w.viscous)
    {
        os  << "Morris, nu " << w.nu << nl;
    }
    else
    {
        os  << "none (nu = " << w.nu << ")" << nl;
    }
}


// ************************************************************************* //
