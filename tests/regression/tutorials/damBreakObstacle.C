/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The obstacle dam-break tutorial as a user runs it (Allrun -test: the
    three solvers to t = 0.15 s, past the obstacle): one Allrun gives the
    pictures, the surge-front table and the run times, and each SPH front
    (wcsphFoam, isphFoam) agrees with FV within 10 % up to the obstacle
    (the acceptance figure; the FV front is known to one cell, 0.0127 m,
    about 6 % of the way run). Measured: 6.8 % and 7.4 %. The water depth
    at the gauges x = 0.1 and 0.2 m follows FV's within 1.5 cm on average
    (measured 2.8 and 1.3 mm for wcsphFoam, 0.7 and 7.5 mm for isphFoam;
    an FV cell is 8 mm high), and spray.dat gives the particles held off
    the walls per step.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include <fstream>
#include <map>

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

    // waterDepth.dat: "solver x meanDifference" rows
    std::map<std::string, double> depth;
    std::ifstream rows(dir/"waterDepth.dat");
    for (std::string solver, x; rows >> solver;)
    {
        if (solver[0] == '#')
        {
            rows.ignore(1000, '\n');
            continue;
        }
        double diff;
        rows >> x >> diff;
        depth[solver + " " + x] = diff;
    }
    for (const char* gauge : {"wcsphFoam 0.1", "wcsphFoam 0.2", "isphFoam 0.1", "isphFoam 0.2"})
    {
        ASSERT_TRUE(depth.count(gauge)) << gauge << '\n' << out;
        EXPECT_LT(depth.at(gauge), 0.015) << gauge;
    }
    const auto spray = sphTest::readKeyValues(dir/"spray.dat");
    ASSERT_TRUE(spray.count("isphFoam_held_per_step")) << out;
    EXPECT_GE(std::stod(spray.at("isphFoam_held_per_step")), 0);

    for (const char* png : {"damBreak_t0.png", "damBreak_t0.1.png", "surgeFront.png", "waterDepth.png"})
    {
        EXPECT_TRUE(isFile(dir/png)) << png;
    }
}
