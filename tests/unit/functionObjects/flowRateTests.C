/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The flowRate function object: the volume behind a section is a count of
    lattice particles times dr^2, and the discharge between two rows of its
    file is the volume that crossed over the interval. Both are exact up
    to round-off.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "flowRate.H"

using namespace Foam;

namespace
{
    const scalar tol = 1e-12;

    const SPH::functionObjects::flowRate& asFlowRate(const autoPtr<functionObject>& fo)
    {
        return refCast<const SPH::functionObjects::flowRate>(fo());
    }
}


TEST(flowRate, volumeBehindASectionCountsWholeColumns)
{
    // Block [0, 1] x [0, 0.5], dr = 0.02: 25 of its 50 columns lie left of
    // x = 0.5, 25 particles each
    sphTest::sphTank tank("flowRateVolume");
    auto fo = tank.fo("q", "type flowRate; point (0.5 0.3);");
    fo->execute();
    const scalar dr = tank.spec.dr;
    EXPECT_NEAR(asFlowRate(fo).volume(), 25*25*dr*dr, tol);
    EXPECT_EQ(asFlowRate(fo).q(), -VGREAT);

    // Facing the other way, the volume behind is the rest of the block
    auto back = tank.fo("qBack", "type flowRate; point (0.5 0.3); normal (-2 0);");
    back->execute();
    EXPECT_NEAR(asFlowRate(back).volume(), 25*25*dr*dr, tol);

    // halfWidth keeps rows 0..9 (centres 0.01..0.19) of |y - 0.1| <= 0.1
    auto part = tank.fo("qPart", "type flowRate; point (0.5 0.1); halfWidth 0.1;");
    part->execute();
    EXPECT_NEAR(asFlowRate(part).volume(), 25*10*dr*dr, tol);
}


TEST(flowRate, dischargeIsTheVolumeThatCrossedOverTheInterval)
{
    sphTest::sphTank tank("flowRateQ");
    auto fo = tank.fo("q", "type flowRate; point (0.5 0);");
    const scalar dr = tank.spec.dr;

    tank.runTime->setTime(0.1, 1);
    fo->execute();
    fo->write();

    // The column just left of the section (centres 0.49) moves across it
    vector2DField& x = tank.parts->positions();
    label moved = 0;
    for (label b = 0; b < tank.nFluid; ++b)
    {
        if (mag(x[b].x() - 0.49) < 1e-9)
        {
            x[b].x() += 2*dr;
            ++moved;
        }
    }
    ASSERT_EQ(moved, 25);

    // Steps without a write do not start a new interval
    tank.runTime->setTime(0.15, 2);
    fo->execute();
    tank.runTime->setTime(0.3, 3);
    fo->execute();
    fo->write();
    EXPECT_NEAR(asFlowRate(fo).q(), 25*dr*dr/0.2, tol);

    // The file: header, then Time, volume and q (the first row without one)
    const std::vector<std::string> lines =
        sphTest::readLines(tank.postProcessing("q/0/flowRate.dat"));
    ASSERT_EQ(lines.size(), 7u);
    EXPECT_EQ(lines[0].rfind("# Discharge per unit width through a section", 0), 0u);
    EXPECT_NE(lines[4].find("volumeBehind"), std::string::npos) << lines[4];
    std::istringstream row(lines[6]);
    double t, v, q;
    row >> t >> v >> q;
    ASSERT_FALSE(row.fail()) << lines[6];
    EXPECT_EQ(t, 0.3);
    EXPECT_NEAR(v, 24*25*dr*dr, 1e-6*v);
    EXPECT_NEAR(q, 25*dr*dr/0.2, 1e-6*q);
}


TEST(flowRate, badEntriesAreErrors)
{
    sphTest::throwOnFatal();
    sphTest::sphTank tank("flowRateBad");
    EXPECT_THROW(tank.fo("q", "type flowRate;"), Foam::error);
    EXPECT_THROW(tank.fo("q", "type flowRate; point (1 0); normal (0 0);"), Foam::error);
    EXPECT_THROW(tank.fo("q", "type flowRate; point (1 0); halfWidth -1;"), Foam::error);
}


// ************************************************************************* //
