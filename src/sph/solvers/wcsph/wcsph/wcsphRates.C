/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The interactions of one Runge-Kutta stage, as templates over the
    concrete kernel (kernelDispatch) so the per-pair work is inlined.

\*---------------------------------------------------------------------------*/

#include "wcsph.H"
#include "kernelDispatch.H"

#include <chrono>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::wcsph::dummyPressure(const Kernel& W)
{
    // 004_... eq. (10): a Shepard average over the fluid neighbours of the
    // fluid pressure plus the hydrostatic step to the dummy particle
    const scalar* rho = parts_.field<scalar>("rho").cdata();
    scalar* p = parts_.field<scalar>("p").data();
    scalar* rhoW = parts_.field<scalar>("rho").data();

    const label* off = nbrs_.offsets().cdata();
    const label* nbr = nbrs_.indices().cdata();
    const vector2D* rij = nbrs_.rij().cdata();
    const scalar* r = nbrs_.r().cdata();
    const label nF = nFluid_;
    const label n = parts_.size();
    const scalar m = cloud_->mass();

    #pragma omp parallel for schedule(static)
    for (label s = nF; s < n; ++s)
    {
        scalar sumPW = 0, sumW = 0;
        for (label k = off[s]; k < off[s + 1]; ++k)
        {
            const label a = nbr[k];
            if (a >= nF) continue;
            const scalar VW = m/rho[a]*W.W(r[k]);
            // rij = x_s - x_a, its minimum image across a periodic seam
            sumPW += (p[a] + rho[a]*(g_ & rij[k]))*VW;
            sumW += VW;
        }
        p[s] = sumW > 0 ? sumPW/sumW : 0;
        rhoW[s] = density(p[s]);
    }
}


template<class Kernel>
void Foam::SPH::wcsph::fluidRates(const Kernel& W)
{
    const vector2D* U = parts_.field<vector2D>("U").cdata();
    const scalar* rho = parts_.field<scalar>("rho").cdata();
    const scalar* p = parts_.field<scalar>("p").cdata();
    const label* type = parts_.field<label>("type").cdata();

    const label* off = nbrs_.offsets().cdata();
    const label* nbr = nbrs_.indices().cdata();
    const vector2D* rij = nbrs_.rij().cdata();
    const scalar* r = nbrs_.r().cdata();

    const label nF = nFluid_;
    const scalar m = cloud_->mass();
    const scalar h = W.h();
    const scalar eta2 = 0.01*h*h;
    const scalar cFactor = std::sqrt(b0_*gamma_/rho0_);
    const scalar cExponent = 0.5*(gamma_ - 1);
    const bool diffuse = densityDiffusion_;
    const bool hydrostatic = densityDiffusionHydrostatic_;
    const vector2D g = g_;
    const bool viscous = viscosity_ == viscosityModel::Morris;
    const scalar nu = nu_;
    const scalar rhoRef = rho0_;
    const label interfacial = label(particleKind::interfacial);
    const scalar alphaAV = alphaAV_;

    // Repulsion, 004_... eqs. (11)-(12)
    const scalar ksh = ks_*h;
    const scalar eks = std::exp(-3*ks_*ks_);
    const scalar K = K_;

    // Sound speed of every particle, eq. (7), once rather than per pair
    const label n = parts_.size();
    soundSpeed_.setSize(n);
    scalar* c = soundSpeed_.data();
    #pragma omp parallel for schedule(static)
    for (label j = 0; j < n; ++j)
    {
        c[j] = cFactor*std::pow(rho[j]/rhoRef, cExponent);
    }

    scalar maxU2 = 0, maxA2 = 0, maxC = 0;

    #pragma omp parallel for schedule(static) reduction(max: maxU2, maxA2, maxC)
    for (label i = 0; i < nF; ++i)
    {
        const scalar rhoI = rho[i];
        const scalar Vi = m/rhoI;
        const scalar cI = c[i];

        scalar drho = 0;
        vector2D dU(vector2D::zero);

        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label j = nbr[k];
            const scalar rhoJ = rho[j];
            const scalar Vj = m/rhoJ;
            // dW/dr / r is finite at r = 0 for every kernel: no branch
            const scalar dWbyR = W.dWdrByR(r[k]);
            const scalar dW = dWbyR*r[k];
            const vector2D gradW = dWbyR*rij[k];
            const vector2D Uij = U[i] - U[j];

            // Continuity, eq. (6), with Rusanov diffusion (n_ij.gradW = -dW)
            // of the departure from rest: rho_ij^H = rho g.(x_j - x_i)/c^2
            // at the pair's mean density and sound speed (see wcsph.H)
            drho += rhoI*Vj*(Uij & gradW);
            if (diffuse)
            {
                const scalar rhoH =
                    hydrostatic
                  ? -(rhoI + rhoJ)/(cI*cI + c[j]*c[j])*(g & rij[k])
                  : 0;
                drho -= max(cI, c[j])*Vj*(rhoJ - rhoI - rhoH)*dW;
            }

            // Hu-Adams pressure gradient, eq. (8)
            const scalar pij = (rhoJ*p[i] + rhoI*p[j])/(rhoI + rhoJ);
            dU -= (Vi*Vi + Vj*Vj)*pij/m*gradW;

            // Laminar viscosity (Morris et al.): wall particles are at rest
            if (viscous)
            {
                dU += m*nu*(rhoI + rhoJ)/(rhoI*rhoJ)*(dW*r[k]/(r[k]*r[k] + eta2))*Uij;
            }

            // Monaghan's artificial viscosity, on approaching pairs only
            if (alphaAV > 0)
            {
                const scalar ur = Uij & rij[k];
                if (ur < 0)
                {
                    const scalar mu = h*ur/(r[k]*r[k] + eta2);
                    const scalar PI = -alphaAV*0.5*(cI + c[j])*mu/(0.5*(rhoI + rhoJ));
                    dU -= m*PI*gradW;
                }
            }

            // Soft repulsion from the dummies on the wall, eqs. (11)-(12)
            if (type[j] == interfacial && r[k] < ksh && r[k] > 0)
            {
                const scalar q = r[k]/h;
                const scalar psi = (std::exp(-3*q*q) - eks)/(1 - eks);
                dU += (K*psi/(r[k]*r[k]))*rij[k];
            }
        }
        dU += g;

        drhodt_[i] = drho;
        dUdt_[i] = dU;
        maxU2 = max(maxU2, magSqr(U[i]));
        maxA2 = max(maxA2, magSqr(dU));
        maxC = max(maxC, cI);
    }

    maxSpeed_ = std::sqrt(maxU2);
    maxAccel_ = std::sqrt(maxA2);
    maxSoundSpeed_ = maxC;
}


void Foam::SPH::wcsph::updateNeighbours()
{
    const vector2DField& x = parts_.positions();

    // Walls do not move: the fluid particles alone decide
    const domain& dom = cloud_->dom();
    bool valid = listBuilt_;
    const scalar maxMove2 = sqr(0.5*skin_);
    for (label i = 0; i < nFluid_ && valid; ++i)
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
        positionsAtBuild_ = SubList<vector2D>(x, nFluid_);
        listBuilt_ = skin_ > 0;
        ++nListBuilds_;
    }
}


void Foam::SPH::wcsph::computeRates()
{
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();

    updateNeighbours();

    const auto searched = clock::now();
    timeNeighbours_ += std::chrono::duration<scalar>(searched - start).count();

    // Fluid pressure from density, eq. (4)
    scalar* p = parts_.field<scalar>("p").data();
    const scalar* rho = parts_.field<scalar>("rho").cdata();
    for (label i = 0; i < nFluid_; ++i)
    {
        p[i] = pressure(rho[i]);
    }

    dispatch(*kernel_, [&](const auto& W)
    {
        dummyPressure(W);
        fluidRates(W);
    });
    ratesCurrent_ = true;
    timeInteractions_ += std::chrono::duration<scalar>(clock::now() - searched).count();
}


// ************************************************************************* //
