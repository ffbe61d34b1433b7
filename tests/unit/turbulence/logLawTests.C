/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The log-law friction velocity (Leroy et al. 2014, eq. (23)) against its
    closed form: the speed the law gives for a chosen u* is solved back to
    that u*; the sublayer switch at yPlusLam; no failure at u = 0.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "logLaw.H"

#include <cmath>

using namespace Foam;

namespace
{
    // u from u* by eq. (23) itself
    scalar lawSpeed(const SPH::logLaw& law, scalar uStar, scalar y, scalar nu)
    {
        return uStar*(std::log(y*uStar/nu)/law.kappa() + law.B());
    }
}


TEST(logLaw, solvesEquation23BackToTheFrictionVelocity)
{
    const SPH::logLaw law(0.41, 5.2);
    const scalar nu = 1.5625e-3;
    for (const scalar yPlus : {12.0, 32.0, 640.0, 1e4, 1e7})
    {
        for (const scalar uStar : {1e-3, 1.0, 30.0})
        {
            const scalar y = yPlus*nu/uStar;
            const scalar u = lawSpeed(law, uStar, y, nu);
            EXPECT_NEAR(law.uStarLog(u, y, nu), uStar, 1e-12*uStar)
                << "y+ " << yPlus << ", u* " << uStar;
        }
    }
}


TEST(logLaw, yPlusLamIsWhereTheLawMeetsTheSublayer)
{
    const SPH::logLaw law(0.41, 5.2);
    const scalar yl = law.yPlusLam();
    EXPECT_NEAR(yl, std::log(yl)/0.41 + 5.2, 1e-10);
    EXPECT_GT(yl, 10.5);
    EXPECT_LT(yl, 11.5);

    // The two frictions agree where u+ = y+ = yPlusLam
    const scalar nu = 1e-6, uStar = 0.05, y = yl*nu/uStar, u = yl*uStar;
    EXPECT_NEAR(law.uStarSqr(u*(1 - 1e-9), y, nu), uStar*uStar, 1e-6*uStar*uStar);
    EXPECT_NEAR(law.uStarSqr(u*(1 + 1e-9), y, nu), uStar*uStar, 1e-6*uStar*uStar);
}


TEST(logLaw, laminarFrictionInTheSublayer)
{
    const SPH::logLaw law;
    const scalar nu = 1e-3, y = 1e-3, u = 0.5;   // y+ = sqrt(u y/nu) < 1
    EXPECT_DOUBLE_EQ(law.uStarSqr(u, y, nu), nu*u/y);
}


TEST(logLaw, noFlowNoFrictionNoFailure)
{
    const SPH::logLaw law;
    EXPECT_EQ(law.uStarLog(0, 0.05, 1e-6), 0);
    EXPECT_EQ(law.uStarSqr(0, 0.05, 1e-6), 0);
    const scalar tiny = law.uStarSqr(1e-300, 0.05, 1e-6);
    EXPECT_TRUE(std::isfinite(tiny));
    EXPECT_GE(tiny, 0);
}


// ************************************************************************* //
