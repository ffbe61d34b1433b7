/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The rates of one Runge-Kutta stage with USAW walls, as templates over
    the concrete kernel (kernelDispatch): the operators of SPH::usaw for
    the divergence, pressure gradient and viscous term, and one pair loop
    for what they do not cover (density diffusion, artificial viscosity).

\*---------------------------------------------------------------------------*/

#include "wcsphUsaw.H"
#include "openMPThreshold.H"
#include "wcsphPairTerms.H"
#include "usawOperators.H"
#include "renormalisation.H"
#include "freeSurfaceRegion.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::wcsphUsaw::markTensileParticles(const Kernel& W)
{
    const wcsphWork& w = work_;
    usaw::divPosition(W, w.nbrs, *usaw_, V_, divR_);
    markFreeSurfaceRegion
    (
        w.nbrs, w.nFluid, divR_, freeSurfaceDivR_, 0.5*W.support(),
        nearSurface_
    );
    for (label i = 0; i < w.nFluid; ++i)
    {
        symmetricGradient_[i] = pTotal_[i] < 0 && !nearSurface_[i];
    }
}


template<class Kernel>
void Foam::SPH::wcsphUsaw::pressureGradient(const Kernel& W)
{
    const wcsphWork& w = work_;
    if (tensileControl_)
    {
        markTensileParticles(W);
        usaw::gradTensileControl
        (
            W, w.nbrs, *usaw_, V_, pTotal_, symmetricGradient_, gradP_
        );
        return;
    }
    if (gradientForm_ == projection::gradientForm::renormalised)
    {
        usaw::renormalisation
        (
            W, w.nbrs, *usaw_, V_, w.parts.positions(),
            renormalisation::minMomentDet, R_
        );
    }
    projection::gradient
    (
        gradientForm_, kernel_, w.nbrs, *usaw_, V_, R_, pTotal_, gradP_
    );
}


template<class Kernel>
void Foam::SPH::wcsphUsaw::fluidRates(const Kernel& W)
{
    wcsphWork& w = work_;
    const vector2DField& Uf = w.parts.field<vector2D>("U");
    const scalarField& rhof = w.parts.field<scalar>("rho");

    // V_b = m_b/rho_b; the vertices' density is their pressure's, eq. (4)
    const scalarField& pf = w.parts.field<scalar>("p");
    forAll(V_, a)
    {
        V_[a] = mass_[a]/rhof[a];
        pTotal_[a] = pf[a] + pBackground_;
    }

    // Leroy et al. 2014 eqs. (9), (5), (15)-(17)
    usaw::div(W, w.nbrs, *usaw_, V_, Uf, divU_);
    pressureGradient(W);
    if (w.nut)
    {
        turbulentViscous(Uf);
    }
    else if (w.viscous)
    {
        usaw::laminarViscous(W, w.nbrs, *usaw_, V_, w.rho0*w.nu, Uf, w.dr, viscous_);
    }

    const vector2D* U = Uf.cdata();
    const scalar* rho = rhof.cdata();
    const scalar* c = w.soundSpeed.cdata();
    const scalar* V = V_.cdata();
    const scalar* m = mass_.cdata();
    const scalar* gamma = usaw_->gamma().cdata();
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const vector2D* rij = w.nbrs.rij().cdata();
    const scalar* r = w.nbrs.r().cdata();

    const label nF = w.nFluid;
    const scalar h = W.h(), eta2 = 0.01*h*h, alphaAV = w.alphaAV;
    const bool diffuse = w.densityDiffusion;
    const bool hydrostatic = w.densityDiffusionHydrostatic;
    const vector2D g = w.g;
    scalar* drhodt = w.drhodt.data();
    vector2D* dUdt = w.dUdt.data();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(nF))
    for (label i = 0; i < nF; ++i)
    {
        const scalar rhoI = rho[i], cI = c[i];
        scalar drho = 0;
        vector2D dU(vector2D::zero);
        for (label k = off[i]; k < off[i + 1] && (diffuse || alphaAV > 0); ++k)
        {
            const label j = nbr[k];
            const scalar dWbyR = W.dWdrByR(r[k]);
            if (diffuse)
            {
                const scalar rhoH = wcsphPair::hydrostaticStep
                (
                    hydrostatic, rhoI, rho[j], cI, c[j], g & rij[k]
                );
                drho -= wcsphPair::rusanovFlux
                (
                    rhoI, rho[j], cI, c[j], V[j], dWbyR*r[k], rhoH
                );
            }
            const scalar ur = (U[i] - U[j]) & rij[k];
            if (alphaAV > 0 && ur < 0)
            {
                dU -= m[j]*wcsphPair::monaghanPi
                (
                    alphaAV, h, eta2, ur, r[k], cI, c[j], rhoI, rho[j]
                )*dWbyR*rij[k];
            }
        }
        drhodt[i] = drho/gamma[i] - rhoI*divU_[i];
        dUdt[i] = dU/gamma[i] + (viscous_[i] - gradP_[i])/rhoI + g;
    }
}


// ************************************************************************* //
