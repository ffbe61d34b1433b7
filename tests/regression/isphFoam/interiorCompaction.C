/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    interiorCompaction (sphSchemes, beyond the paper): the still tank with
    its water spread 3 % each way (the room a shift makes, which the
    divergence-free projection does not see) keeps that room without it
    and gives it back with it; the same tank unspread gets no source at
    all; a negative alpha names the entry. The time loop's spreadLimit
    reports the kept room, and stops the run when maxSpread is below it.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particleFields.H"

#include "vector2D.H"

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";

    //- The still tank at dr = 0.05 (H = 0.5 m) to endTime, meshed
    fileName meshedTank(const std::string& name, const std::string& endTime)
    {
        return sphTest::meshedTutorial
        (
            "isph/hydrostaticTank", name,
            "sed -i 's/^dr .*/dr 0.05;/' system/sphMeshDict"
            " && sed -i 's/^endTime .*/endTime " + endTime + ";/' system/controlDict"
        );
    }

    //- The highest fluid particle of a written time
    scalar top(const fileName& dir, const word& time)
    {
        auto runTime = sphTest::makeTime(dir);
        const sphTest::particleFields s = sphTest::readParticles(*runTime, time);
        scalar yMax = -GREAT;
        forAll(s.x, i)
        {
            if (s.type[i] == 0) yMax = max(yMax, s.x[i].y());
        }
        return yMax;
    }

    std::string tail(const std::string& s)
    {
        return s.size() > 3000 ? s.substr(s.size() - 3000) : s;
    }
}


TEST(isphFoamInteriorCompaction, givesBackTheRoomASpreadTankTookAndLeavesStillWaterAlone)
{
    // Spread 3 % each way: the kernel sum of a whole kernel is 1/1.03^2 =
    // 0.943 of the lattice's, 3.7 % beyond the source's 2 % dead band. The
    // top row goes from H = 0.5 m to 0.515 m. The rows within a kernel of
    // the surface or a wall get no source, 6 of the 10 rows here, so the
    // top comes down about a third of the way (measured 0.5098 m at 1 s)
    std::string out;
    const fileName kept = meshedTank("isphSpreadKept", "1");
    sphTest::spreadMeshedFluid(*sphTest::makeTime(kept), 1.03, 0.5);
    ASSERT_EQ(run(bin + "isphFoam -case " + kept, out), 0) << tail(out);
    EXPECT_EQ(out.find("Diluted interior particles"), std::string::npos) << tail(out);
    const scalar topKept = top(kept, "1");
    // The time loop's spreadLimit sees the room kept: 1.03^2 - 1
    const scalar spreadKept = sphTest::numberAfter(out, "Largest spread of the fluid: ");
    EXPECT_NEAR(spreadKept, 0.0609, 0.005) << tail(out);

    const fileName pulled = meshedTank("isphSpreadPulled", "1");
    sphTest::spreadMeshedFluid(*sphTest::makeTime(pulled), 1.03, 0.5);
    ASSERT_EQ(run("echo 'interiorCompaction 0.1;' >> " + pulled/"system"/"sphSchemes", out), 0);
    ASSERT_EQ(run(bin + "isphFoam -case " + pulled, out), 0) << tail(out);
    EXPECT_NE
    (
        out.find("rows of water only (no free surface, no wall in the kernel): density"
            " source 0.1 rho0"), std::string::npos
    ) << out.substr(0, 6000);
    EXPECT_NE(out.find("Diluted interior particles pulled together (interiorCompaction): "),
        std::string::npos) << tail(out);
    const scalar topPulled = top(pulled, "1");
    std::cout << "    top row after 1 s: " << topKept << " m without, " << topPulled
        << " m with interiorCompaction 0.1 (spread to 0.515, lattice 0.5); largest"
        << " spread " << spreadKept << " without" << std::endl;
    EXPECT_GT(topKept, 0.514);
    EXPECT_LT(topPulled, 0.511);
    EXPECT_GT(topPulled, 0.5);

    // Still water on its lattice: no row is 2 % short, no source, no line
    const fileName still = meshedTank("isphStillCompaction", "0.5");
    ASSERT_EQ(run("echo 'interiorCompaction 0.1;' >> " + still/"system"/"sphSchemes", out), 0);
    ASSERT_EQ(run(bin + "isphFoam -case " + still, out), 0) << tail(out);
    EXPECT_EQ(out.find("Diluted interior particles"), std::string::npos) << tail(out);

    // A negative alpha is refused, naming the entry and the file
    ASSERT_EQ(run("echo 'interiorCompaction -1;' >> " + still/"system"/"sphSchemes", out), 0);
    EXPECT_NE(run(bin + "isphFoam -case " + still, out), 0);
    EXPECT_NE(out.find("interiorCompaction"), std::string::npos) << tail(out);
    EXPECT_NE(out.find("sphSchemes"), std::string::npos) << tail(out);
}


TEST(isphFoamInteriorCompaction, aSpreadBeyondMaxSpreadStopsTheRunLoudly)
{
    // The same spread tank under maxSpread 0.03: its 6 % stops the first
    // step, with the entry, the figures and the least filled particle; the
    // start is the last good state
    const fileName dir = meshedTank("isphSpreadStops", "1");
    sphTest::spreadMeshedFluid(*sphTest::makeTime(dir), 1.03, 0.5);
    std::string out;
    ASSERT_EQ(run("echo 'maxSpread 0.03;' >> " + dir/"system"/"sphSchemes", out), 0);
    EXPECT_EQ(run(bin + "isphFoam -case " + dir, out), 1) << tail(out);
    EXPECT_NE(out.find("the fluid spreading more than maxSpread 0.03 beyond"),
        std::string::npos) << out.substr(0, 6000);
    EXPECT_NE(out.find("more than maxSpread 0.03 (system/sphSchemes): the particles drift"
        " apart, the shifting most often; least filled: particle id "),
        std::string::npos) << tail(out);
    EXPECT_NE(out.find("The last good state, time 0, is written"), std::string::npos)
        << tail(out);
}


// ************************************************************************* //
