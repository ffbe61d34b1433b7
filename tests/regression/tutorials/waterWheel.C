/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The water wheel (Leroy et al. 2014 section 4.4) as a user runs it:
    Allrun -test takes isphFoam and wcsphFoam (USAW walls, the paddles
    turned by constant/dynamicMeshDict) at dr = 5 cm to t = 0.5 s. Each
    must end (End in the log at endTime; wcsphFoam refused
    movingWallVelocity before its USAW walls moved); the pressure force
    on the bucket must be zero until t = 0.2 s (its tip reaches the water
    at t = 0.29 s, omega ramping up over 0.2 s) and above 100 N/m once it
    has dipped in (wallForces must measure the bucket where it has turned
    to: on the walls of t = 0 it stays dry and reads 0); and no fluid
    particle may be lost (the count of isolatedParticles at the first and
    last write). compare's share of the water above the wheel's axis
    must be there for both and below 5 % (the cups begin to lift water).
    wcsphFoam must run with the tensile instability control.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

using namespace Foam;

TEST(waterWheelTutorial, bothSolversEndAndTheBucketFeelsTheWater)
{
    const fileName dir =
        sphTest::copyTutorial("freeSurface/waterWheel", "waterWheel");
    std::string out;
    ASSERT_EQ
    (
        sphTest::runWithBashrc(dir + "/Allclean && " + dir + "/Allrun -test", out),
        0
    ) << out;

    const auto table = sphTest::readKeyValues(dir/"comparison.dat");
    for (const std::string solver : {"isphFoam", "wcsphFoam"})
    {
        ASSERT_TRUE(table.count(solver + "_ended")) << solver << out;
        EXPECT_EQ(table.at(solver + "_ended"), "1") << solver;

        ASSERT_TRUE(table.count(solver + "_force_max_before_dip_N_per_m"))
            << solver << out;
        EXPECT_EQ
        (
            std::stod(table.at(solver + "_force_max_before_dip_N_per_m")), 0
        ) << solver;
        EXPECT_GT
        (
            std::stod(table.at(solver + "_force_max_after_dip_N_per_m")), 100
        ) << solver;

        // The cups have only begun to lift water at 0.5 s (compare reads
        // it from the particles above the wheel's axis): present, small
        const std::string above = solver + "_water_above_axis_0_to_4_s_max";
        ASSERT_TRUE(table.count(above)) << solver << out;
        EXPECT_GE(std::stod(table.at(above)), 0) << solver;
        EXPECT_LT(std::stod(table.at(above)), 0.05) << solver;

        ASSERT_TRUE(table.count(solver + "_nFluid_last")) << solver << out;
        EXPECT_GT(std::stoi(table.at(solver + "_nFluid_first")), 1000) << solver;
        EXPECT_EQ
        (
            table.at(solver + "_nFluid_first"), table.at(solver + "_nFluid_last")
        ) << solver;
    }

    // The WCSPH case takes the tensile instability control (README.md): its
    // log's momentum line names it
    std::string wcsphLog;
    sphTest::run("cat " + dir/"wcsph"/"log.wcsphFoam", wcsphLog);
    EXPECT_NE
    (
        wcsphLog.find("tensile instability control, Sun et al. 2018"),
        std::string::npos
    );

    for (const char* png : {"wheel_t0.png", "bucketForce.png", "waterAboveAxis.png"})
    {
        EXPECT_TRUE(isFile(dir/png)) << png;
    }
}
