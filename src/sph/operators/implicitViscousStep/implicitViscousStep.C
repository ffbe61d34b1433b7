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
    mu_(V.size(), Zero),
    Sp_(V.size(), Zero),
    robinK_(walls.segmentParticles().size(), Zero),
    robinG_(walls.segmentParticles().size(), Zero),
    source_(V.size(), Zero),
    lap_(nbrs, walls, V, nFluid)
{
    lap_.coefficient(mu_);
    lap_.implicitSource(Sp_);
    labelList& kinds = lap_.kinds();
    for (label i = nFluid; i < kinds.size(); ++i)
    {
        kinds[i] = laplacianMatrix::dirichlet;
    }
}


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
    forAll(robinK_, s)
    {
        const vector2D& n = normal[s];
        const vector2D uS(0.5*(U[ends[s].first()] + U[ends[s].second()]));
        robinK_[s] = 1 - sqr(n[d]);
        robinG_[s] = (uS - (uS & n)*n)[d];
    }
}


void Foam::SPH::implicitViscousStep::setSource
(
    const scalar rhoByDt,
    const scalar dr,
    const UList<vector2D>& U,
    const direction d
)
{
    // L{mu, u}_a,d holds +(mu_s + mu_a)/gamma_a sum_s |grad gamma_as|
    // n_d n_e u_a,e/max(d_as, dr) (e the other component): at u^n, in the
    // source S of L{B, u} + Sp u = S
    const direction e = 1 - d;
    const scalar* gamma = walls_.gamma().cdata();
    const label* wOff = walls_.offsets().cdata();
    const label* seg = walls_.segments().cdata();
    const vector2D* gradGammaAs = walls_.gradGammaAs().cdata();
    const scalar* dAs = walls_.distances().cdata();
    const labelPair* ends = walls_.segmentParticles().cdata();
    const vector2D* normal = walls_.segmentNormals().cdata();
    const scalar* mu = mu_.cdata();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(nFluid_))
    for (label a = 0; a < nFluid_; ++a)
    {
        scalar coupling = 0;
        for (label k = wOff[a]; k < wOff[a + 1]; ++k)
        {
            const label s = seg[k];
            const vector2D& n = normal[s];
            const scalar muS = 0.5*(mu[ends[s].first()] + mu[ends[s].second()]);
            coupling +=
                (muS + mu[a])*mag(gradGammaAs[k])*n[d]*n[e]/max(dAs[k], dr);
        }
        source_[a] = -rhoByDt*U[a][d] - coupling*U[a][e]/gamma[a];
    }
    for (label a = nFluid_; a < source_.size(); ++a)
    {
        source_[a] = 0;
    }
}


// ************************************************************************* //
