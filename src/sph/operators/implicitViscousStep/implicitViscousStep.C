/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "implicitViscousStep.H"
#include "openMPThreshold.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::implicitViscousStep::implicitViscousStep
(
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const label nFluid
)
:
    walls_(walls),
    nFluid_(nFluid),
    nu_(V.size(), Zero),
    diffusion_(nbrs, walls, V, nFluid),
    component_(V.size(), Zero)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::implicitViscousStep::robinData
(
    const UList<vector2D>& U,
    const direction d
)
{
    // (u^R . t) t = (I - n n) u^R: k_s = 1 - n_d^2 of u_a,d, and the wall
    // velocity's ((I - n n) u_s)_d
    const List<labelPair>& ends = walls_.segmentParticles();
    const List<vector2D>& normal = walls_.segmentNormals();
    scalarList& k = diffusion_.robinK();
    scalarList& g = diffusion_.robinG();
    forAll(k, s)
    {
        const vector2D& n = normal[s];
        const vector2D uS(0.5*(U[ends[s].first()] + U[ends[s].second()]));
        k[s] = 1 - sqr(n[d]);
        g[s] = (uS - (uS & n)*n)[d];
    }
}


void Foam::SPH::implicitViscousStep::wallCoupling
(
    const scalar dr,
    const UList<vector2D>& U,
    const direction d
)
{
    // L{nu, u}_a,d holds +(nu_s + nu_a)/gamma_a sum_s |grad gamma_as|
    // n_d n_e u_a,e/max(d_as, dr) (e the other component)
    const direction e = 1 - d;
    const scalar* gamma = walls_.gamma().cdata();
    const label* wOff = walls_.offsets().cdata();
    const label* seg = walls_.segments().cdata();
    const vector2D* gradGammaAs = walls_.gradGammaAs().cdata();
    const scalar* dAs = walls_.distances().cdata();
    const labelPair* ends = walls_.segmentParticles().cdata();
    const vector2D* normal = walls_.segmentNormals().cdata();
    const scalar* nu = nu_.cdata();
    scalar* rate = diffusion_.explicitRate().data();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(nFluid_))
    for (label a = 0; a < nFluid_; ++a)
    {
        scalar coupling = 0;
        for (label k = wOff[a]; k < wOff[a + 1]; ++k)
        {
            const label s = seg[k];
            const vector2D& n = normal[s];
            const scalar nuS = 0.5*(nu[ends[s].first()] + nu[ends[s].second()]);
            coupling +=
                (nuS + nu[a])*mag(gradGammaAs[k])*n[d]*n[e]/max(dAs[k], dr);
        }
        rate[a] = coupling*U[a][e]/gamma[a];
    }
}


void Foam::SPH::implicitViscousStep::setComponent
(
    const scalar rho,
    const scalar mu,
    const scalar dr,
    const UList<vector2D>& U,
    const direction d
)
{
    nu_ = mu/rho;
    robinData(U, d);
    wallCoupling(dr, U, d);
    forAll(U, i)
    {
        component_[i] = U[i][d];
    }
}


// ************************************************************************* //
