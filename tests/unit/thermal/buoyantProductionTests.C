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

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "buoyantProduction.H"

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


// ************************************************************************* //
