/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The obstacle dam-break tutorial as a user runs it (Allrun -test: both
    solvers to t = 0.15 s, past the obstacle): one Allrun gives the
    pictures, the surge-front table and both run times, and the SPH and FV
    fronts agree within 10 % up to the obstacle (the acceptance figure; the
    FV front is known to one cell, 0.0127 m, about 6 % of the way run).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <fstream>
#include <map>

using namespace Foam;

namespace
{

    std::map<std::string, std::string> readTable(const fileName& file)
    {
        std::map<std::string, std::string> values;
        std::ifstream is(file);
        std::string key, value;
        while (is >> key)
        {
            if (key[0] == '#') { std::getline(is, value); continue; }
            is >> value;
            values[key] = value;
        }
        return values;
    }
}


TEST(damBreakObstacleTutorial, oneAllrunGivesFrontsPicturesAndRunTimes)
{
    const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"damBreakObstacle";
    rmDir(dir);
    mkDir(dir.path());
    std::string out;
    ASSERT_EQ(sphTest::run("cp -r " + std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/damBreak/obstacle " + dir, out), 0);

    const std::string source = std::string(SPHFOAM_SOURCE_DIR);
    // As the README says: source etc/bashrc from the project folder (a
    // POSIX shell cannot tell a sourced file where it is)
    ASSERT_EQ
    (
        sphTest::run
        (
            "cd " + source + " && unset SPHFOAM_PROJECT_DIR && . ./etc/bashrc && "
          + dir + "/Allrun -test",
            out
        ),
        0
    ) << out;

    const auto table = readTable(dir/"comparison.dat");
    ASSERT_TRUE(table.count("front_max_relative_difference")) << out;
    EXPECT_GE(std::stoi(table.at("front_points_before_obstacle")), 3);
    EXPECT_LT(std::stod(table.at("front_max_relative_difference")), 0.10);
    EXPECT_GT(std::stod(table.at("wcsphFoam_clock_s")), -1);
    EXPECT_GT(std::stod(table.at("interFoam_clock_s")), -1);

    for (const char* png : {"damBreak_t0.png", "damBreak_t0.1.png", "surgeFront.png"})
    {
        EXPECT_TRUE(isFile(dir/png)) << png;
    }
}
