/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    One WCSPH time step: the neighbour list, the rates of a Runge-Kutta
    stage (the fluid's equation of state here, the rest the wall
    model's), the classical Runge-Kutta update, the wall bounce and the
    equation of state of the new density.

\*---------------------------------------------------------------------------*/

#include "wcsph.H"
#include "openMPThreshold.H"
#include "wcsphBodyForces.H"
#include "usawWalls.H"

#include <chrono>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wcsph::updateNeighbours()
{
    const vector2DField& x = parts_.positions();

    // The fluid particles decide, and the wall particles when the walls
    // move (they are moved at every stage)
    const label nMoving =
        wallModel_->movesGeometry() ? x.size() : work_.nFluid;
    const domain& dom = cloud_->dom();
    bool valid = listBuilt_;
    const scalar maxMove2 = sqr(0.5*skin_);
    for (label i = 0; i < nMoving && valid; ++i)
    {
        valid =
            magSqr(dom.separation(x[i], positionsAtBuild_[i])) <= maxMove2;
    }

    if (valid)
    {
        nbrs_.refresh(cloud_->cells(), x, x);
        ++nListRefreshes_;
    }
    else
    {
        cloud_->updateCells();
        nbrs_.build(cloud_->cells(), x, kernel_->support() + skin_, true);
        positionsAtBuild_ = SubList<vector2D>(x, nMoving);
        listBuilt_ = skin_ > 0;
        ++nListBuilds_;
    }
}


void Foam::SPH::wcsph::computeRates(const scalar t)
{
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();

    updateNeighbours();

    const auto searched = clock::now();
    timeNeighbours_ += std::chrono::duration<scalar>(searched - start).count();

    // Fluid pressure from density, eq. (4)
    scalar* p = parts_.field<scalar>("p").data();
    const scalar* rho = parts_.field<scalar>("rho").cdata();
    for (label i = 0; i < work_.nFluid; ++i)
    {
        p[i] = work_.pressure(rho[i]);
    }

    wallModel_->rates(t);
    if (bodyForces_)
    {
        bodyForces_->addTo(work_.dUdt);
    }
    rateExtremes();
    ratesCurrent_ = true;
    ++nRateEvaluations_;
    timeInteractions_ += std::chrono::duration<scalar>(clock::now() - searched).count();
}


void Foam::SPH::wcsph::rateExtremes()
{
    const vector2D* U = parts_.field<vector2D>("U").cdata();
    const vector2D* dUdt = work_.dUdt.cdata();
    const scalar* c = work_.soundSpeed.cdata();
    const label nF = work_.nFluid;
    scalar maxU2 = 0, maxA2 = 0, maxC = 0;

    #pragma omp parallel for schedule(static) reduction(max: maxU2, maxA2, maxC) \
        if(SPH::worthThreads(nF))
    for (label i = 0; i < nF; ++i)
    {
        maxU2 = max(maxU2, magSqr(U[i]));
        maxA2 = max(maxA2, magSqr(dUdt[i]));
        maxC = max(maxC, c[i]);
    }
    maxSpeed_ = std::sqrt(maxU2);
    maxAccel_ = std::sqrt(maxA2);
    maxSoundSpeed_ = maxC;
}


void Foam::SPH::wcsph::rungeKutta4(const scalar dt)
{
    // The stages' times: t^n, t^n + dt/2 (twice), t^n + dt
    const scalar t0 = runTime_.value() - dt;
    if (!ratesCurrent_)
    {
        computeRates(t0);
    }

    vector2D* x = parts_.positions().data();
    vector2D* U = parts_.field<vector2D>("U").data();
    scalar* rho = parts_.field<scalar>("rho").data();

    const label nF = work_.nFluid;
    const vector2D* dUdt = work_.dUdt.cdata();
    const scalar* drhodt = work_.drhodt.cdata();
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
            computeRates(t0 + (stage < 3 ? 0.5 : 1.0)*dt);
        }
        const auto start = std::chrono::steady_clock::now();
        const scalar w = weight[stage];
        const scalar a = stage < 3 ? stageFraction[stage]*dt : 0;

        #pragma omp parallel for schedule(static) if(SPH::worthThreads(nF))
        for (label i = 0; i < nF; ++i)
        {
            sumX_[i] += w*U[i];
            sumU_[i] += w*dUdt[i];
            sumRho_[i] += w*drhodt[i];
            if (stage < 3)
            {
                x[i] = x0_[i] + a*U[i];
                U[i] = U0_[i] + a*dUdt[i];
                rho[i] = rhoStart_[i] + a*drhodt[i];
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
        x0_, parts_.positions(), parts_.field<vector2D>("U"), work_.nFluid,
        bounceElasticity_
    );
}


void Foam::SPH::wcsph::holdOffWalls(const scalar dt)
{
    // The walls are at t^{n+1}, their segments near each particle those
    // of the last stage's search
    nHeld_ += wallModel_->operatorWalls()->holdOff
    (
        x0_, parts_.positions(), parts_.field<vector2D>("U"), work_.nFluid,
        minWallDistance_
    );
}


void Foam::SPH::wcsph::equationOfState(const scalar dt)
{
    const scalar* rho = parts_.field<scalar>("rho").cdata();
    scalar* p = parts_.field<scalar>("p").data();
    for (label i = 0; i < work_.nFluid; ++i)
    {
        p[i] = work_.pressure(rho[i]);
    }
}



// ************************************************************************* //
