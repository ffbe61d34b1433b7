/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The dam-break over a wedge (Leroy et al. 2014 section 4.3) as a user
    runs it: Allrun -test takes isphFoam and wcsphFoam (USAW walls) at
    dr = 2 cm, and interFoam, to t = 0.3 s (t+ = 0.94), just past the
    water's arrival at the wedge. Both SPH runs must end (End in the log)
    and the water must reach the wedge's left side (force above 10 N/m) in
    t+ = 0.8 to 1.0 in both, within 0.05 of each other: the surge front
    over the 0.61 m from the column to the wedge's foot, which the two
    methods agree on to a few steps (measured: 0.903 and 0.899, the
    writes of the force being 0.004 and 0.017 apart in t+). A front that
    is slowed by a wall leak, or sped up by a pressure blow-up, moves it.
    interFoam (2 cm cells, the wedge cut out in steps) must end and reach
    the wedge within 0.05 of isphFoam too (measured 0.929: its front is
    known to a cell, 2 cm of the 0.61 m run, about 0.03 in t+).
    66 to 130 s on a machine shared with two other jobs (about 36 s of CPU).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

using namespace Foam;

TEST(damBreakWedgeTutorial, allThreeEndAndReachTheWedgeTogether)
{
    const fileName dir = sphTest::copyTutorial("damBreak/wedge", "damBreakWedge");
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
        ASSERT_TRUE(table.count(solver + "_arrival_tplus")) << solver << out;
        const double arrival = std::stod(table.at(solver + "_arrival_tplus"));
        EXPECT_GT(arrival, 0.8) << solver;
        EXPECT_LT(arrival, 1.0) << solver;
        EXPECT_GT(std::stod(table.at(solver + "_clock_s")), -1) << solver;
    }
    const double isphArrival = std::stod(table.at("isphFoam_arrival_tplus"));
    EXPECT_LT
    (
        std::abs(isphArrival - std::stod(table.at("wcsphFoam_arrival_tplus"))),
        0.05
    );
    ASSERT_TRUE(table.count("interFoam_arrival_tplus")) << out;
    EXPECT_EQ(table.at("interFoam_ended"), "1");
    EXPECT_LT
    (
        std::abs(isphArrival - std::stod(table.at("interFoam_arrival_tplus"))),
        0.05
    );

    for (const char* png : {"wedge_t0.png", "wedgeForce.png"})
    {
        EXPECT_TRUE(isFile(dir/png)) << png;
    }
}
