/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The buoyant tutorials of Leroy et al. 2015 sections 4.3-4.4 as a user
    runs them, Allrun -test: the FV sides (the lock exchange's with -fv: its
    SPH side is tests/regression/lockExchange's), and the heated lid
    cavity's SPH side.

    - Lock exchange, buoyantBoussinesqPimpleFoam at 5 cells per L (150 x
      10 cells) to t+ = 10: both fronts' Froude number over 4 <= X/L
      <= 6 measured 0.361 (Haertel et al.: 0.406; 0.372, 0.397, 0.403 at
      10, 20, 40 cells per L, README); checked within 0.30-0.42, and the
      two fronts within 0.01 of each other (the problem is symmetric: a
      wrong sign of the buoyancy or of TRef moves one front, not both).
    - Heated lid cavity, Re 1000, Pr 1, Gr 1e4, buoyantBoussinesqSimpleFoam
      at 16^2 and 32^2: the hot wall's mean Nu measured 7.458 and 7.197
      (7.508 at 256^2 and 512^2, README); the 32^2 value checked within
      6 % of 7.508 (a wrong wall type or sign of beta moves it by far
      more), and the lid's Nu must be there and positive.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

using namespace Foam;

namespace
{
    //- A copy of tutorials/heatTransfer/<name> (with the readers its
    //- compare imports from the folder above), cleaned and run with -test
    fileName runTest
    (
        const std::string& name,
        std::string& out,
        const std::string& options = ""
    )
    {
        const fileName dir = sphTest::copyTutorial("heatTransfer/" + name, name);
        EXPECT_EQ
        (
            sphTest::runWithBashrc(dir + "/Allclean && " + dir + "/Allrun -test" + options, out),
            0
        ) << out;
        return dir;
    }
}


TEST(lockExchangeTutorial, fvFrontsNearHaertelsFroudeNumberAndSymmetric)
{
    std::string out;
    const fileName dir = runTest("lockExchange", out, " -fv");

    const auto row = sphTest::tableRow(dir/"results"/"front.dat", {"fv", "5"});
    ASSERT_GE(row.size(), 8u) << out;
    const double frHeavy = std::stod(row[5]);
    const double frLight = std::stod(row[7]);
    EXPECT_GT(frHeavy, 0.30);
    EXPECT_LT(frHeavy, 0.42);
    EXPECT_NEAR(frHeavy, frLight, 0.01);
    EXPECT_TRUE(isFile(dir/"results"/"front.png"));
}


TEST(heatedLidCavityTutorial, fvHotWallNusseltNearTheFineMeshValue)
{
    std::string out;
    const fileName dir = runTest("heatedLidCavity", out);

    const auto row = sphTest::tableRow(dir/"results"/"lid.dat", {"fv", "32"});
    ASSERT_GE(row.size(), 7u) << out;
    const double nuHot = std::stod(row[5]);
    const double nuLid = std::stod(row[6]);
    EXPECT_NEAR(nuHot, 7.508, 0.06*7.508);
    EXPECT_GT(nuLid, 0);
    EXPECT_TRUE(isFile(dir/"results"/"Nu.png"));

    // The SPH side, isphFoam at 16^2 (15 particles a side) to t = 200,
    // compare's figures averaged over the written times of the last half
    // (one snapshot's profiles scatter as the particles move past the
    // lines): the hot bottom's mean Nu measured 7.05-7.27 against FV
    // 32^2's 7.197, checked within 8 % of the fine-mesh 7.508 (without
    // the buoyancy or with the walls' temperatures swapped it is far
    // off); u/U min on x = 1/2 measured -0.18 (sphCompare's quadratic
    // moving least squares, sph/system/sphCompareDict; -0.26 with a linear
    // fit over 2 dr, -0.18 with a Shepard average; the lid drives the
    // vortex: checked below -0.1); profiles within 0.4 U and 0.4 of FV
    // 32^2 (measured 0.20 and 0.23; a linear fit 0.28 and 0.23;
    // with the Shepard average 0.29-0.31 and 0.26-0.28 in two
    // realisations that differ in the last digits of the pressure solve:
    // 15 particles across a Re = 1000 cavity)
    const auto sph = sphTest::tableRow(dir/"results"/"lid.dat", {"sph", "15"});
    ASSERT_GE(sph.size(), 15u) << out;
    EXPECT_NEAR(std::stod(sph[5]), 7.508, 0.08*7.508);
    EXPECT_LT(std::stod(sph[9]), -0.1);
    EXPECT_LT(std::stod(sph[12]), 0.4);
    EXPECT_LT(std::stod(sph[13]), 0.4);
}
