/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The surgeFront function object: the leading particle of the main body
    of fluid. Positions are lattice positions, so the expected fronts are
    exact up to the rounding of (i + 1/2) dr: 1e-12.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "timeClock.H"
#include "surgeFront.H"

using namespace Foam;

namespace
{
    const scalar tol = 1e-12;

    const SPH::functionObjects::surgeFront& asFront(const autoPtr<functionObject>& fo)
    {
        return refCast<const SPH::functionObjects::surgeFront>(fo());
    }

    //- A blob of 3 x 3 fluid particles with its lower left at x0
    List<vector2D> blob(const vector2D& x0, scalar dr)
    {
        List<vector2D> pts;
        for (label j = 0; j < 3; ++j)
        {
            for (label i = 0; i < 3; ++i)
            {
                pts.append(x0 + vector2D(i*dr, j*dr));
            }
        }
        return pts;
    }
}


TEST(surgeFront, blockFrontIsItsLastColumn)
{
    sphTest::sphTank tank("frontBlock");
    auto fo = tank.fo("front", "type surgeFront;");
    fo->execute();

    // The last column's centres: blockWidth - dr/2 (its corner particle
    // has exactly 3 neighbours within 2 dr, the default minimum)
    EXPECT_NEAR(asFront(fo).front(), tank.spec.blockWidth - 0.5*tank.spec.dr, tol);
    EXPECT_EQ(asFront(fo).direction(), vector2D(1, 0));

    // The particle named as the front is the one at the front
    const label b = asFront(fo).frontParticle();
    ASSERT_GE(b, 0);
    EXPECT_NEAR(tank.parts->positions()[b].x(), asFront(fo).front(), tol);
}


TEST(surgeFront, ignoresAnIsolatedParticleAhead)
{
    sphTest::tankSpec spec;
    spec.extraFluid = List<vector2D>({vector2D(1.6, 0.01)});
    sphTest::sphTank tank("frontSpray", spec);

    auto fo = tank.fo("front", "type surgeFront;");
    fo->execute();
    EXPECT_NEAR(asFront(fo).front(), spec.blockWidth - 0.5*spec.dr, tol);

    // It is the neighbour test that excludes it
    auto all = tank.fo("all", "type surgeFront; minNeighbours 0;");
    all->execute();
    EXPECT_NEAR(asFront(all).front(), 1.6, tol);
    EXPECT_EQ(asFront(all).frontParticle(), tank.nFluid - 1);
}


TEST(surgeFront, maxHeightIgnoresAJetAbove)
{
    // A compact blob (each particle has >= 3 neighbours) high up and ahead
    sphTest::tankSpec spec;
    spec.extraFluid = blob(vector2D(1.4, 0.8), spec.dr);
    sphTest::sphTank tank("frontJet", spec);

    auto fo = tank.fo("front", "type surgeFront;");
    fo->execute();
    EXPECT_NEAR(asFront(fo).front(), 1.4 + 2*spec.dr, tol);

    auto low = tank.fo("low", "type surgeFront; maxHeight 0.6;");
    low->execute();
    EXPECT_NEAR(asFront(low).front(), spec.blockWidth - 0.5*spec.dr, tol);
}


TEST(surgeFront, directionGivesTheProjection)
{
    sphTest::sphTank tank("frontDirection");

    // Flow towards -x: the front is the smallest x, written as -x . d
    auto fo = tank.fo("front", "type surgeFront; direction (-2 0 0);");
    fo->execute();
    EXPECT_EQ(asFront(fo).direction(), vector2D(-1, 0));
    EXPECT_NEAR(asFront(fo).front(), -0.5*tank.spec.dr, tol);
}


TEST(surgeFront, noQualifyingParticleIsWrittenAsUnavailable)
{
    sphTest::sphTank tank("frontNone");
    auto fo = tank.fo("front", "type surgeFront; maxHeight -1;");
    tank.runTime->setTime(0.1, 1);
    fo->execute();
    fo->write();
    EXPECT_EQ(asFront(fo).frontParticle(), -1);

    const std::vector<std::string> data =
        sphTest::dataLines(tank.postProcessing("front/0/surgeFront.dat"));
    ASSERT_EQ(data.size(), 1u);
    EXPECT_NE(data[0].find("-1.00000000e+300"), std::string::npos) << data[0];
}


TEST(surgeFront, fileHasTimeAndFront)
{
    sphTest::sphTank tank("frontFile");
    auto fo = tank.fo("front", "type surgeFront;");
    for (label i = 1; i <= 3; ++i)
    {
        tank.runTime->setTime(0.1*i, i);
        fo->execute();
        fo->write();
    }

    const fileName file = tank.postProcessing("front/0/surgeFront.dat");
    const std::vector<std::string> lines = sphTest::readLines(file);
    ASSERT_GE(lines.size(), 4u);
    EXPECT_EQ(lines[0].rfind("# Surge front", 0), 0u) << lines[0];

    const std::vector<std::string> data = sphTest::dataLines(file);
    ASSERT_EQ(data.size(), 3u);
    std::istringstream row(data[2]);
    double t, front;
    row >> t >> front;
    EXPECT_NEAR(t, 0.3, 1e-12);
    EXPECT_NEAR(front, tank.spec.blockWidth - 0.5*tank.spec.dr, 1e-8);  // 8 digits written
}


TEST(surgeFront, aRestartedRunWritesIntoTheFolderOfItsStart)
{
    // A run restarted from 0.7 keeps Time's startTime at its write grid's
    // origin, 0 (timeClock::restore); its objects, also one added to
    // controlDict later, write into front/0.7 as OpenFOAM's would
    sphTest::sphTank tank("frontRestart");
    tank.runTime->setTime(0.7, 7);
    SPH::timeClock::registerRunStart(*tank.runTime);
    tank.runTime->setTime(0.9, 9);
    auto fo = tank.fo("front", "type surgeFront;");
    fo->execute();
    fo->write();
    EXPECT_TRUE(isFile(tank.postProcessing("front/0.7/surgeFront.dat")));
    EXPECT_FALSE(isDir(tank.postProcessing("front/0")));
    EXPECT_FALSE(isDir(tank.postProcessing("front/0.9")));
}


// ************************************************************************* //
