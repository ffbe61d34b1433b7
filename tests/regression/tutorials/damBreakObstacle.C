/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The obstacle dam-break tutorial as a user runs it (Allrun -test: the
    three solvers to t = 0.15 s, past the obstacle): one Allrun gives the
    pictures, the surge-front table and the run times, and each SPH front
    (wcsphFoam, isphFoam) agrees with FV within 10 % up to the obstacle
    (the acceptance figure; the FV front is known to one cell, 0.0127 m,
    about 6 % of the way run). Measured: 6.8 % and 7.4 %.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

using namespace Foam;

TEST(damBreakObstacleTutorial, oneAllrunGivesFrontsPicturesAndRunTimes)
{
    const fileName dir = sphTest::copyTutorial("damBreak/obstacle", "damBreakObstacle");
    std::string out;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test", out), 0) << out;

    const auto table = sphTest::readKeyValues(dir/"comparison.dat");
    ASSERT_TRUE(table.count("front_max_relative_difference")) << out;
    EXPECT_GE(std::stoi(table.at("front_points_before_obstacle")), 3);
    EXPECT_LT(std::stod(table.at("front_max_relative_difference")), 0.10);
    ASSERT_TRUE(table.count("isph_front_max_relative_difference")) << out;
    EXPECT_GE(std::stoi(table.at("isph_front_points_before_obstacle")), 3);
    EXPECT_LT(std::stod(table.at("isph_front_max_relative_difference")), 0.10);
    EXPECT_GT(std::stod(table.at("wcsphFoam_clock_s")), -1);
    EXPECT_GT(std::stod(table.at("isphFoam_clock_s")), -1);
    EXPECT_GT(std::stod(table.at("interFoam_clock_s")), -1);

    for (const char* png : {"damBreak_t0.png", "damBreak_t0.1.png", "surgeFront.png"})
    {
        EXPECT_TRUE(isFile(dir/png)) << png;
    }
}
