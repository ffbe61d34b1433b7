/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::spreadLimit, the time loop's check of the room the fluid takes, on
    the function objects' test tank (a 50 x 25 lattice block at dr = 0.02
    beside dummy walls):
    - the block on its lattice has spread 0 (its whole kernels sum what the
      lattice does), for the Wendland and the cubic spline kernels;
    - the block spread 10 % each way takes 1.1^2 = 1.21 times the room;
      the check passes it under maxSpread 0.25 and stops it under 0.2,
      naming the entry, the spread and the least filled particle;
    - the block 5 % closer each way has a negative spread, which the
      summary at the end prints;
    - the kernels the walls' dummies reach and those the surface or the
      block's side cuts do not count, nor those holding a particle the
      method flags as a free surface; fewer than ten whole kernels (a thin
      layer) are not checked.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "../functionObjects/functionObjectTestTools.H"
#include "spreadLimit.H"
#include "OStringStream.H"

using namespace Foam;

namespace
{
    //- Spread the block's particles by factor about (0.5, 0) and rebuild
    //- the cell list
    void spreadBlock(sphTest::sphTank& tank, const scalar factor)
    {
        vector2DField& x = tank.parts->positions();
        for (label i = 0; i < tank.nFluid; ++i)
        {
            x[i] = vector2D(0.5 + factor*(x[i].x() - 0.5), factor*x[i].y());
        }
        tank.cloud->updateCells();
    }

    scalar spreadOf(const sphTest::sphTank& tank, label& nWhole)
    {
        return SPH::spreadLimit::spread(*tank.cloud, nWhole);
    }
}


TEST(spreadLimit, latticeBlockHasNoSpread)
{
    for (const std::string k : {"kernel wendlandC2;", "kernel cubicSpline;"})
    {
        sphTest::tankSpec spec;
        spec.kernel = k;
        sphTest::sphTank tank("spreadLattice", spec);
        label nWhole = 0;
        // The kernels the surface just reaches count (their first moment
        // is below 2 %): they lack a few parts in 1e4
        EXPECT_NEAR(spreadOf(tank, nWhole), 0, 1e-3) << k;
        // Those reaching the dummies, and most within 2h of the surface
        // or the block's right side, do not: 900 of 1250 (Wendland)
        EXPECT_GT(nWhole, 600) << k;
        EXPECT_LT(nWhole, 1100) << k;
    }
}


TEST(spreadLimit, spreadBlockTakesTheRoomItsSpacingSays)
{
    sphTest::sphTank tank("spreadTenPercent");
    spreadBlock(tank, 1.1);
    label nWhole = 0;
    const scalar s = spreadOf(tank, nWhole);
    // 1.21 - 1 for a continuous kernel sum; h = 2 dr over a spacing of
    // 1.1 dr still sums it within a few parts in 1e4
    EXPECT_NEAR(s, 0.21, 0.002);
    EXPECT_GT(nWhole, 300);

    string what;
    const SPH::spreadLimit loose(sphTest::dict("maxSpread 0.25;"));
    EXPECT_EQ(loose.find(*tank.cloud, tank.parts->positions(), *tank.runTime, what), -1);

    const SPH::spreadLimit tight(sphTest::dict("maxSpread 0.2;"));
    const label i = tight.find(*tank.cloud, tank.parts->positions(), *tank.runTime, what);
    EXPECT_GE(i, 0);
    EXPECT_LT(i, tank.nFluid);
    EXPECT_NE(what.find("more than maxSpread 0.2 (system/sphSchemes)"), std::string::npos) << what;
    EXPECT_NE(what.find("a spread of 0.209"), std::string::npos) << what;
}


TEST(spreadLimit, compressedBlockHasANegativeSpreadAndReportsIt)
{
    // 5 % closer each way: 0.95^2 - 1 = -0.0975 (WCSPH's water under its
    // own weight is a little denser than the lattice)
    sphTest::sphTank tank("spreadCompressed");
    spreadBlock(tank, 0.95);
    label nWhole = 0;
    EXPECT_NEAR(spreadOf(tank, nWhole), -0.0975, 0.002);
    SPH::spreadLimit check(sphTest::dict(""));
    string what;
    EXPECT_EQ(check.find(*tank.cloud, tank.parts->positions(), *tank.runTime, what), -1);
    check.accept();
    OStringStream os;
    check.printSummary(os);
    EXPECT_NE(os.str().find("Largest spread of the fluid: -0.09"), std::string::npos) << os.str();
}


TEST(spreadLimit, thinLayerIsNotChecked)
{
    // Three rows: every kernel reaches the surface or the bottom
    sphTest::tankSpec spec;
    spec.H = 3*spec.dr;
    sphTest::sphTank tank("spreadThin", spec);
    spreadBlock(tank, 1.5);
    label nWhole = 0;
    EXPECT_EQ(spreadOf(tank, nWhole), -1);
    EXPECT_LT(nWhole, 10);
    string what;
    const SPH::spreadLimit tight(sphTest::dict("maxSpread 0.01;"));
    EXPECT_EQ(tight.find(*tank.cloud, tank.parts->positions(), *tank.runTime, what), -1);
}


TEST(spreadLimit, kernelsHoldingFreeSurfaceParticlesDoNotCount)
{
    // isphFoam flags the particles it keeps at a free surface (p = 0 or an
    // air pocket's pressure): a kernel holding one has air in it, whether
    // or not its first moment shows it
    sphTest::sphTank tank("spreadSurface");
    spreadBlock(tank, 1.1);
    label nBefore = 0;
    const scalar before = spreadOf(tank, nBefore);

    labelList surface(tank.parts->size(), Zero);
    label nNone = 0;
    EXPECT_EQ(SPH::spreadLimit::spread(*tank.cloud, nNone, &surface), before);
    EXPECT_EQ(nNone, nBefore);

    // Ten particles round a void in the middle of the block: the whole
    // kernels that held them (about 50 each, overlapping) drop out
    const vector2DField& x = tank.parts->positions();
    label nMarked = 0;
    for (label i = 0; i < tank.nFluid && nMarked < 10; ++i)
    {
        if (mag(x[i] - vector2D(0.5, 0.25)) < 0.05)
        {
            surface[i] = 1;
            ++nMarked;
        }
    }
    ASSERT_EQ(nMarked, 10);
    label nVoid = 0;
    SPH::spreadLimit::spread(*tank.cloud, nVoid, &surface);
    EXPECT_LT(nVoid, nBefore - 40);
    EXPECT_GT(nVoid, 100);

    // The check of a run reads the flags it was given: with every fluid
    // particle at a surface no kernel is whole, and the spread that stops
    // the unflagged check is not measured
    string what;
    const SPH::spreadLimit unflagged(sphTest::dict("maxSpread 0.2;"));
    EXPECT_GE(unflagged.find(*tank.cloud, tank.parts->positions(), *tank.runTime, what), 0);
    SubList<label>(surface, tank.nFluid) = 1;
    const SPH::spreadLimit flagged(sphTest::dict("maxSpread 0.2;"), &surface);
    EXPECT_EQ(flagged.find(*tank.cloud, tank.parts->positions(), *tank.runTime, what), -1);

    // Flags of another size than the particles (some added or removed
    // since the method set them) are not read
    labelList stale(tank.parts->size() - 1, 1);
    label nStale = 0;
    EXPECT_EQ(SPH::spreadLimit::spread(*tank.cloud, nStale, &stale), before);
    EXPECT_EQ(nStale, nBefore);
}


TEST(spreadLimit, defaultAndBadEntries)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    const SPH::spreadLimit byDefault(sphTest::dict(""));
    EXPECT_NE(byDefault.describe().find("maxSpread 0.1 "), std::string::npos);
    for (const std::string bad : {"maxSpread 0;", "maxSpread -0.1;", "maxSpread x;"})
    {
        EXPECT_ANY_THROW(SPH::spreadLimit(sphTest::dict(bad))) << bad;
    }
    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //
