/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The interactions of one Runge-Kutta stage with dummy and repulsive
    walls, as templates over the concrete kernel (kernelDispatch) so the
    per-pair work is inlined.

\*---------------------------------------------------------------------------*/

#include "wcsphDummyRepulsive.H"
#include "openMPThreshold.H"
#include "wcsphPairTerms.H"
#include "wcsphWallPressure.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- K Psi(q)/r^2 of eqs. (11)-(12), Psi = (e^(-3 q^2) - e^(-3 ks^2))
    //- /(1 - e^(-3 ks^2)), eks = e^(-3 ks^2)
    inline Foam::scalar repulsion
    (
        const Foam::scalar K,
        const Foam::scalar eks,
        const Foam::scalar q,
        const Foam::scalar r
    )
    {
        const Foam::scalar psi = (std::exp(-3*q*q) - eks)/(1 - eks);
        return K*psi/(r*r);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::wcsphDummyRepulsive::fluidRates(const Kernel& W)
{
    wcsphWork& w = work_;
    const vector2D* U = w.parts.field<vector2D>("U").cdata();
    const scalar* rho = w.parts.field<scalar>("rho").cdata();
    const scalar* p = w.parts.field<scalar>("p").cdata();
    const label* type = w.parts.field<label>("type").cdata();
    const scalar* c = w.soundSpeed.cdata();
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const vector2D* rij = w.nbrs.rij().cdata();
    const scalar* r = w.nbrs.r().cdata();
    scalar* drhodt = w.drhodt.data();
    vector2D* dUdt = w.dUdt.data();

    const label nF = w.nFluid, interfacial = label(particleKind::interfacial);
    const scalar m = w.mass(), h = W.h(), eta2 = 0.01*h*h;
    const bool diffuse = w.densityDiffusion, hydrostatic = w.densityDiffusionHydrostatic;
    const bool viscous = w.viscous;
    const scalar nu = w.nu, alphaAV = w.alphaAV;
    const vector2D g = w.g;
    // Repulsion, 004_... eqs. (11)-(12)
    const scalar ksh = ks_*h, eks = std::exp(-3*ks_*ks_), K = K_;

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(nF))
    for (label i = 0; i < nF; ++i)
    {
        const scalar rhoI = rho[i], Vi = m/rhoI, cI = c[i];
        scalar drho = 0;
        vector2D dU(vector2D::zero);

        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label j = nbr[k];
            const scalar rhoJ = rho[j], Vj = m/rhoJ;
            // dW/dr / r is finite at r = 0 for every kernel: no branch
            const scalar dWbyR = W.dWdrByR(r[k]);
            const scalar dW = dWbyR*r[k];
            const vector2D gradW = dWbyR*rij[k];
            const vector2D Uij = U[i] - U[j];

            // Continuity, eq. (6), with Rusanov diffusion of the departure
            // from rest (n_ij.gradW = -dW; rho_ij^H: see wcsph.H)
            drho += rhoI*Vj*(Uij & gradW);
            if (diffuse)
            {
                const scalar rhoH =
                    wcsphPair::hydrostaticStep(hydrostatic, rhoI, rhoJ, cI, c[j], g & rij[k]);
                drho -= wcsphPair::rusanovFlux(rhoI, rhoJ, cI, c[j], Vj, dW, rhoH);
            }

            // Hu-Adams pressure gradient, eq. (8)
            dU -= wcsphPair::huAdams(m, rhoI, rhoJ, Vi, Vj, p[i], p[j])*gradW;

            // Laminar viscosity (Morris et al.): wall particles are at rest
            if (viscous)
            {
                dU += wcsphPair::morris(m, nu, rhoI, rhoJ, dW, r[k], eta2)*Uij;
            }

            // Monaghan's artificial viscosity, on approaching pairs only
            const scalar ur = alphaAV > 0 ? (Uij & rij[k]) : 0;
            if (ur < 0)
            {
                dU -= m*wcsphPair::monaghanPi(alphaAV, h, eta2, ur, r[k], cI, c[j], rhoI, rhoJ)*gradW;
            }

            // Soft repulsion from the dummies on the wall, eqs. (11)-(12)
            if (type[j] == interfacial && r[k] < ksh && r[k] > 0)
            {
                dU += repulsion(K, eks, r[k]/h, r[k])*rij[k];
            }
        }
        drhodt[i] = drho;
        dUdt[i] = dU + g;
    }
}


// ************************************************************************* //
