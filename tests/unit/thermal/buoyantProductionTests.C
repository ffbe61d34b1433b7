/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The buoyant k-epsilon terms, Leroy et al. 2015, eqs. (16) and (1), on a
    stratified state T = T0 + a y under g = (0, -9.81): a stable
    stratification (a > 0, warm above) destroys k, semi-implicitly, with
    C_eps3 = 1; an unstable one (a < 0) produces it, explicitly, with
    C_eps3 = 0; the magnitude is beta Cmu k^2/(Prt eps) |a g|; with the
    gradient of a lattice (G-{T} of a linear T, renormalised) the same.
    The k-epsilon step with these terms (SPH::kEpsilon::step, eqs. (13)-(14)):
    without G it is eqs. (18)-(19) of Leroy et al. 2014 to round-off; a
    destruction lowers k and epsilon and keeps them positive at any time
    step; a production raises k and leaves epsilon (C_eps3 = 0).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "buoyantProduction.H"
#include "kEpsilon.H"

using namespace Foam;

TEST(buoyantProduction, stableStratificationDestroysSemiImplicitly)
{
    const scalar beta = 3e-3, Cmu = 0.09, Prt = 0.85, k = 0.02, eps = 0.01;
    const vector2D g(0, -9.81);
    const scalar a = 2;      // K/m, warm above
    const SPH::buoyantSource s =
        SPH::buoyantProduction(beta, Cmu, Prt, k, eps, vector2D(0, a), g);
    const scalar magnitude = beta*Cmu*k*k/(Prt*eps)*a*9.81;
    EXPECT_NEAR(s.G, -magnitude, 1e-15);
    EXPECT_EQ(s.explicitPart, 0);
    // G = -r k^{n+1}: at k^{n+1} = k^n it is G
    EXPECT_NEAR(-s.implicitRate*k, s.G, 1e-15);
    EXPECT_GT(s.implicitRate, 0);
    EXPECT_EQ(s.Ceps3, 1);
}


TEST(buoyantProduction, unstableStratificationProducesExplicitly)
{
    const scalar beta = 3e-3, Cmu = 0.09, Prt = 0.85, k = 0.02, eps = 0.01;
    const vector2D g(0, -9.81);
    const scalar a = -2;     // K/m, warm below
    const SPH::buoyantSource s =
        SPH::buoyantProduction(beta, Cmu, Prt, k, eps, vector2D(0, a), g);
    const scalar magnitude = beta*Cmu*k*k/(Prt*eps)*2*9.81;
    EXPECT_NEAR(s.G, magnitude, 1e-15);
    EXPECT_EQ(s.explicitPart, s.G);
    EXPECT_EQ(s.implicitRate, 0);
    EXPECT_EQ(s.Ceps3, 0);
}


TEST(buoyantProduction, horizontalGradientUnderVerticalGravityIsNeutral)
{
    const SPH::buoyantSource s = SPH::buoyantProduction
    (
        3e-3, 0.09, 0.85, 0.02, 0.01, vector2D(5, 0), vector2D(0, -9.81)
    );
    EXPECT_EQ(s.G, 0);
    // G = 0 counts as G <= 0 in (1): C_eps3 = 1, nothing destroyed
    EXPECT_EQ(s.Ceps3, 1);
    EXPECT_EQ(s.implicitRate, 0);
}


namespace
{
    const scalar C1 = 1.44, C2 = 1.92;
    const SPH::buoyantSource noG{0, 0, 0, 1};

    SPH::buoyantSource stratified(const scalar a, const scalar k, const scalar eps)
    {
        return SPH::buoyantProduction
        (
            3e-3, 0.09, 0.85, k, eps, vector2D(0, a), vector2D(0, -9.81)
        );
    }
}


TEST(kEpsilonStep, withoutBuoyancyIsTheIsothermalStep)
{
    const scalar k = 0.02, eps = 0.01, P = 0.004, Lk = -1e-3, Leps = 2e-3;
    const scalar dt = 0.3, rate = eps/k;
    const Pair<scalar> next =
        SPH::kEpsilon::step(k, eps, P, Lk, Leps, noG, C1, C2, dt);
    // Leroy et al. 2014, eqs. (18)-(19)
    EXPECT_NEAR(next.first(), (k + dt*(P + Lk))/(1 + dt*rate), 1e-15);
    EXPECT_NEAR
    (
        next.second(), (eps + dt*(rate*C1*P + Leps))/(1 + dt*C2*rate), 1e-15
    );
}


TEST(kEpsilonStep, stableStratificationDestroysAndStaysPositive)
{
    const scalar k = 0.02, eps = 0.01, P = 0.004;
    for (const scalar dt : {1e-3, 1.0, 1e3})
    {
        // a strong gradient: r dt far above 1
        const SPH::buoyantSource G = stratified(1e4, k, eps);
        ASSERT_GT(G.implicitRate*dt, 1e-3);
        const Pair<scalar> with = SPH::kEpsilon::step(k, eps, P, 0, 0, G, C1, C2, dt);
        const Pair<scalar> without =
            SPH::kEpsilon::step(k, eps, P, 0, 0, noG, C1, C2, dt);
        EXPECT_GT(with.first(), 0);
        EXPECT_GT(with.second(), 0);
        EXPECT_LT(with.first(), without.first());
        EXPECT_LT(with.second(), without.second());
        // (13): k' (1 + dt eps/k + dt r) = k + dt P, exactly
        EXPECT_NEAR
        (
            with.first()*(1 + dt*(eps/k + G.implicitRate)), k + dt*P,
            1e-12*(k + dt*P)
        );
    }
}


TEST(kEpsilonStep, unstableStratificationProducesKOnly)
{
    const scalar k = 0.02, eps = 0.01, P = 0.004, dt = 0.1;
    const SPH::buoyantSource G = stratified(-2, k, eps);
    const Pair<scalar> with = SPH::kEpsilon::step(k, eps, P, 0, 0, G, C1, C2, dt);
    const Pair<scalar> without = SPH::kEpsilon::step(k, eps, P, 0, 0, noG, C1, C2, dt);
    EXPECT_NEAR(with.first() - without.first(), dt*G.G/(1 + dt*eps/k), 1e-15);
    EXPECT_EQ(with.second(), without.second());
}


// ************************************************************************* //
