/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The waveGauges function object on a flat block of water of depth H:
    the surface where the fluid fraction falls to half its interior value
    is the top of the particles' volumes, y = H. By symmetry the lattice
    rows below H and their mirror images above it would make up a full
    lattice, so phi(H) is half the interior value up to the lattice's
    variation of phi (0.2 %), far inside the contract of dr/2.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "waveGauges.H"

using namespace Foam;

namespace
{
    const SPH::functionObjects::waveGauges& asGauges(const autoPtr<functionObject>& fo)
    {
        return refCast<const SPH::functionObjects::waveGauges>(fo());
    }
}


TEST(waveGauges, flatBlockDepthIsHWithinHalfASpacing)
{
    sphTest::sphTank tank("gaugesFlat");
    const scalar H = tank.spec.H;
    const scalar dr = tank.spec.dr;

    // Mid-block, off the lattice symmetry, and beyond the block (dry)
    auto fo = tank.fo("gauges", "type waveGauges; x (0.5 0.2371 1.5);");
    fo->execute();
    const auto& g = asGauges(fo);

    EXPECT_EQ(g.bed(), 0);                  // the lowest wall point
    ASSERT_EQ(g.depths().size(), 3);
    EXPECT_NEAR(g.depths()[0], H, 0.5*dr);
    EXPECT_NEAR(g.depths()[1], H, 0.5*dr);
    EXPECT_EQ(g.depths()[2], 0);
}


TEST(waveGauges, bedEntryIsTheDatum)
{
    sphTest::sphTank tank("gaugesBed");
    auto fo = tank.fo("gauges", "type waveGauges; x (0.5); bed 0.1;");
    fo->execute();
    EXPECT_NEAR(asGauges(fo).depths()[0], tank.spec.H - 0.1, 0.5*tank.spec.dr);
}


TEST(waveGauges, lowerSurfaceFractionReadsHigher)
{
    // phi falls monotonically across the surface, so a lower threshold
    // is met higher up: the definition, not a tuning, decides the reading
    sphTest::sphTank tank("gaugesFraction");
    auto half = tank.fo("half", "type waveGauges; x (0.5);");
    auto low = tank.fo("low", "type waveGauges; x (0.5); surfaceFraction 0.2;");
    half->execute();
    low->execute();
    EXPECT_GT(asGauges(low).depths()[0], asGauges(half).depths()[0] + 0.25*tank.spec.dr);
}


TEST(waveGauges, isolatedDropletIsNotWater)
{
    // One fluid particle high over the dry part of the tank: its fluid
    // fraction is at most V W(0) = 0.14, below half the interior value
    sphTest::tankSpec spec;
    spec.extraFluid = List<vector2D>({vector2D(1.5, 0.3)});
    sphTest::sphTank tank("gaugesDroplet", spec);

    auto fo = tank.fo("gauges", "type waveGauges; x (1.5 0.5);");
    fo->execute();
    EXPECT_EQ(asGauges(fo).depths()[0], 0);
    EXPECT_NEAR(asGauges(fo).depths()[1], spec.H, 0.5*spec.dr);
}


TEST(waveGauges, fileHasAColumnPerGauge)
{
    sphTest::sphTank tank("gaugesFile");
    auto fo = tank.fo("gauges", "type waveGauges; x (0.5 1.5);");
    tank.runTime->setTime(0.1, 1);
    fo->execute();
    fo->write();

    const fileName file = tank.postProcessing("gauges/0/waveGauges.dat");
    const std::vector<std::string> lines = sphTest::readLines(file);
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(lines[0].rfind("# Water depth above the bed", 0), 0u) << lines[0];
    EXPECT_EQ(lines[1].rfind("# bed", 0), 0u) << lines[1];
    EXPECT_EQ(lines[3].rfind("# Time", 0), 0u) << lines[3];
    EXPECT_NE(lines[3].find("\tx=0.5"), std::string::npos) << lines[3];
    EXPECT_NE(lines[3].find("\tx=1.5"), std::string::npos) << lines[3];

    // Time, then one tab-separated value per gauge
    std::istringstream row(lines[4]);
    double t, d0, d1;
    row >> t >> d0 >> d1;
    ASSERT_FALSE(row.fail()) << lines[4];
    EXPECT_EQ(t, 0.1);
    EXPECT_NEAR(d0, tank.spec.H, 0.5*tank.spec.dr);
    EXPECT_EQ(d1, 0);
    EXPECT_EQ(std::count(lines[4].begin(), lines[4].end(), '\t'), 2);
}


// ************************************************************************* //
