/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The second-order time integrators of wcsphFoam beside the classical
    Runge-Kutta of wcsphRates.C (timeScheme in system/sphSchemes):

    symplectic (two rate evaluations per step): the predictor-corrector
    form of the symplectic position Verlet (Leimkuhler, Reich & Skeel
    1996; Monaghan 2005, Rep. Prog. Phys. 68, its time-stepping section),
    the scheme DualSPHysics calls Symplectic (Dominguez et al. 2022, Comp.
    Part. Mech. 9). With the rates a^n = dU/dt, R^n = drho/dt at the
    start of the step (those the time step was chosen from):

        predictor  x^{n+1/2} = x^n + dt/2 U^n
                   U^{n+1/2} = U^n + dt/2 a^n
                   rho^{n+1/2} = rho^n + dt/2 R^n
        rates at t^{n+1/2}: a^{n+1/2}, R^{n+1/2}
        corrector  U^{n+1} = U^n + dt a^{n+1/2}
                   x^{n+1} = x^n + dt/2 (U^n + U^{n+1})
                   rho^{n+1} = rho^n (2 - eps)/(2 + eps),
                   eps = -(R^{n+1/2}/rho^{n+1/2}) dt

    For forces of the positions alone the positions and velocities are
    those of the position Verlet (drift, kick, drift), which is
    symplectic: the energy of an oscillation is kept to O(dt^2) without a
    drift over long times, where Runge-Kutta 4 damps it. The density is
    the trapezoidal rule on d(ln rho)/dt = R/rho (DualSPHysics'
    form): second order, and rho^{n+1} > 0 for any eps > -2. This form,
    not the kick-drift-kick one, because the velocity- and
    density-dependent terms (viscosity, density diffusion, the pressure
    of eq. (4)) then see a consistent mid-step state (x, U, rho)^{n+1/2}.

    leapfrog (one rate evaluation per step): the same steps with the
    predictor's a^n, R^n replaced by the rates of the previous step's
    corrector, a^{n-1/2}, R^{n-1/2} (the position Verlet with velocity and
    density predicted from the last known rates). The error of the
    predicted U^{n+1/2}, rho^{n+1/2} is O(dt^2), so the step stays second
    order; positions are exactly the position Verlet's. The rates are
    evaluated afresh at the start of the step (a symplectic step, two
    evaluations) at the first step of a run, after a write (a restart
    from there does the same, so the two runs agree) and after a
    rolled-back step. The time step of the leapfrog is chosen from the
    extremes of the last evaluation (t^{n-1/2}). The stages after the
    update (wall bounce, shifting, turbulence) change the state those
    rates describe: by a bounce or a shift, small against a step.

    Neither scheme damps: an oscillation the rates do not damp keeps its
    energy, where Runge-Kutta 4 damps it at omega dt ~ 1. In the Zhou
    dam-break a lone particle trapped at the ceiling (the repulsion and
    the dummies' pressure) oscillates with a growing amplitude until its
    density leaves densityBounds; artificialViscosity 0.01 (Monaghan's
    alpha, the value DualSPHysics uses) keeps it quiet
    (tutorials/damBreak/zhou/README.md).

    Both: the time step is 004_... eq. (15), dt = C_n h/max(c, |U|) with
    C_n = maxCo of controlDict, bounded by the viscous and force limits
    (000_... eq. (49)), as with Runge-Kutta 4: maxCo means the same
    number; the stable C_n of each scheme differs (benchmarks/
    wcsphIntegrators measures it). Walls that move are not supported yet
    (the wall model places them at the time of the last evaluation,
    t^{n+1/2}): the solver stops when they are asked for.

\*---------------------------------------------------------------------------*/

#include "wcsph.H"
#include "openMPThreshold.H"
#include "domain.H"

#include <chrono>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wcsph::symplecticPredictor(const scalar dt)
{
    const auto start = std::chrono::steady_clock::now();
    vector2D* x = parts_.positions().data();
    vector2D* U = parts_.field<vector2D>("U").data();
    scalar* rho = parts_.field<scalar>("rho").data();
    const vector2D* dUdt = work_.dUdt.cdata();
    const scalar* drhodt = work_.drhodt.cdata();
    const scalar half = 0.5*dt;
    const label nF = work_.nFluid;

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(nF))
    for (label i = 0; i < nF; ++i)
    {
        x0_[i] = x[i];
        U0_[i] = U[i];
        rhoStart_[i] = rho[i];
        x[i] += half*U[i];
        U[i] += half*dUdt[i];
        rho[i] += half*drhodt[i];
    }
    timeIntegration_ += std::chrono::duration<scalar>
    (
        std::chrono::steady_clock::now() - start
    ).count();
}


void Foam::SPH::wcsph::symplecticCorrector(const scalar dt)
{
    const auto start = std::chrono::steady_clock::now();
    vector2D* x = parts_.positions().data();
    vector2D* U = parts_.field<vector2D>("U").data();
    scalar* rho = parts_.field<scalar>("rho").data();
    const vector2D* dUdt = work_.dUdt.cdata();
    const scalar* drhodt = work_.drhodt.cdata();
    const scalar half = 0.5*dt;
    const label nF = work_.nFluid;

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(nF))
    for (label i = 0; i < nF; ++i)
    {
        U[i] = U0_[i] + dt*dUdt[i];
        x[i] = x0_[i] + half*(U0_[i] + U[i]);
        // rho[i] is rho^{n+1/2}, where the rates were evaluated
        const scalar eps = -drhodt[i]/rho[i]*dt;
        rho[i] = rhoStart_[i]*(2 - eps)/(2 + eps);
    }

    // The predictor may stray across a periodic seam (the cell list and
    // the pair separations take the minimum image); the step ends inside
    const domain& dom = cloud_->dom();
    if (dom.anyPeriodic())
    {
        for (label i = 0; i < nF; ++i)
        {
            x[i] = dom.wrap(x[i]);
        }
    }
    timeIntegration_ += std::chrono::duration<scalar>
    (
        std::chrono::steady_clock::now() - start
    ).count();
}


void Foam::SPH::wcsph::symplectic(const scalar dt)
{
    const scalar t0 = runTime_.value() - dt;
    if (!ratesCurrent_)
    {
        computeRates(t0);
    }
    symplecticPredictor(dt);
    computeRates(t0 + 0.5*dt);
    symplecticCorrector(dt);
    ratesCurrent_ = false;
}


void Foam::SPH::wcsph::leapfrog(const scalar dt)
{
    const scalar t0 = runTime_.value() - dt;
    if (!ratesCurrent_ && !midStepRates_)
    {
        computeRates(t0);
    }
    symplecticPredictor(dt);
    computeRates(t0 + 0.5*dt);
    symplecticCorrector(dt);
    ratesCurrent_ = false;

    // The corrector's rates are the next predictor's
    midStepRates_ = true;
}


// ************************************************************************* //
