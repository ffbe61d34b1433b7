/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    wcsphFoam's interiorCompaction (SPH::wcsphShifting): the still tank of
    tutorials/wcsph/hydrostaticTank with its water spread 3 % each way (the
    room a shift makes, which continuity does not see) keeps that room when
    shifted without it and gives it back with it; the same tank unspread
    has no density lowered; an alpha above 1, or the entry without
    shifting, is refused naming the entry.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particleFields.H"

#include "vector2D.H"

#include <algorithm>
#include <numeric>
#include <vector>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";

    //- The still tank at dr = 0.05 (H = 0.5 m) to endTime, shifted, meshed
    fileName meshedTank
    (
        const std::string& name,
        const std::string& endTime,
        const std::string& schemes
    )
    {
        return sphTest::meshedTutorial
        (
            "wcsph/hydrostaticTank", name,
            "sed -i 's/^dr .*/dr 0.05;/' system/sphMeshDict"
            " && sed -i 's/^endTime .*/endTime " + endTime + ";/;"
            " s/^writeInterval .*/writeInterval 0.5;/' system/controlDict"
            " && printf 'shifting yes;\\n" + schemes + "' >> system/sphSchemes"
        );
    }

    //- The mean height of the ten highest fluid particles of a written time
    scalar top(const fileName& dir, const word& time)
    {
        auto runTime = sphTest::makeTime(dir);
        const sphTest::particleFields s = sphTest::readParticles(*runTime, time);
        std::vector<scalar> y;
        forAll(s.x, i)
        {
            if (s.type[i] == 0) y.push_back(s.x[i].y());
        }
        std::sort(y.begin(), y.end(), std::greater<scalar>());
        return std::accumulate(y.begin(), y.begin() + 10, scalar(0))/10;
    }

    //- The most densities a logged step lowered ("; N densities lowered")
    long mostLowered(const std::string& log)
    {
        long most = 0;
        const std::string key = " densities lowered";
        for (size_t at = log.find(key); at != std::string::npos; at = log.find(key, at + 1))
        {
            const size_t start = log.rfind("; ", at);
            most = std::max(most, std::stol(log.substr(start + 2, at - start - 2)));
        }
        return most;
    }

    std::string tail(const std::string& s)
    {
        return s.size() > 3000 ? s.substr(s.size() - 3000) : s;
    }
}


TEST(wcsphInteriorCompaction, givesBackTheRoomASpreadTankTookAndLeavesStillWaterAlone)
{
    // Spread 3 % each way: a whole kernel's sum is 1/1.03^2 = 0.943 of the
    // lattice's, 3.7 % beyond the 2 % dead band. Shifting alone keeps that
    // room and more (continuity sees no motion, and the shift moves water
    // into the unshifted band under the surface): the top ten rise from
    // 0.489 m to 0.504 m in 1 s, the spread of the whole kernels goes from
    // 0.062 to 0.050 (measured from the particles). With interiorCompaction
    // 0.1 the interior densities fall until the particles close up: spread
    // 0.018 at 0.5 and 1 s, the top ten at 0.488 m (the lattice's: 0.475)
    std::string out;
    const fileName kept = meshedTank("wcsphSpreadKept", "1", "");
    sphTest::spreadMeshedFluid(*sphTest::makeTime(kept), 1.03, 0.5);
    ASSERT_EQ(run(bin + "wcsphFoam -case " + kept, out), 0) << tail(out);
    EXPECT_EQ(out.find("densities lowered"), std::string::npos) << tail(out);
    const scalar spreadKept =
        sphTest::numberAfter(out, "Largest spread of the fluid: ");
    // The top row, y = H - dr/2 = 0.475 m, spread about y = 0
    const scalar topStart = 1.03*0.475;
    const scalar topKept = top(kept, "1");

    const fileName pulled = meshedTank("wcsphSpreadPulled", "1", "interiorCompaction 0.1;\\n");
    sphTest::spreadMeshedFluid(*sphTest::makeTime(pulled), 1.03, 0.5);
    ASSERT_EQ(run(bin + "wcsphFoam -case " + pulled, out), 0) << tail(out);
    EXPECT_NE(out.find("density lowered by 0.1 (deficit - 0.02) a step where a whole"
        " kernel is 2-10 % short (interiorCompaction)"), std::string::npos)
        << out.substr(0, 6000);
    EXPECT_GT(mostLowered(out), 10) << tail(out);
    const scalar topPulled = top(pulled, "1");
    std::cout << "    top ten after 1 s: " << topKept << " m without, " << topPulled
        << " m with interiorCompaction 0.1 (from " << topStart << " m); largest"
        << " spread without " << spreadKept << std::endl;
    // The time loop's spreadLimit sees the room at the start: 1.03^2 - 1
    EXPECT_NEAR(spreadKept, 0.0609, 0.005) << tail(out);
    EXPECT_GT(topKept - topStart, 0.01);
    EXPECT_LT(topPulled, topStart + 0.0025);
    EXPECT_GT(topPulled, 0.475);

    // Still water on its lattice: no kernel is 2 % short
    const fileName still = meshedTank("wcsphStillCompaction", "0.5", "interiorCompaction 0.1;\\n");
    ASSERT_EQ(run(bin + "wcsphFoam -case " + still, out), 0) << tail(out);
    EXPECT_NE(out.find("densities lowered"), std::string::npos) << tail(out);
    EXPECT_EQ(mostLowered(out), 0) << tail(out);

    // A fraction above 1 would turn densities negative: refused, naming the
    // entry and the file
    ASSERT_EQ(run("echo 'interiorCompaction 2;' >> " + still/"system"/"sphSchemes", out), 0);
    EXPECT_NE(run(bin + "wcsphFoam -case " + still, out), 0);
    EXPECT_NE(out.find("interiorCompaction"), std::string::npos) << tail(out);
    EXPECT_NE(out.find("sphSchemes"), std::string::npos) << tail(out);

    // Without the shift the entry would do nothing: refused, not ignored
    ASSERT_EQ(run("sed -i '/^shifting yes;/d; /^interiorCompaction 2;/d' "
        + still/"system"/"sphSchemes", out), 0);
    EXPECT_NE(run(bin + "wcsphFoam -case " + still, out), 0);
    EXPECT_NE(out.find("Entry interiorCompaction is read by wcsphFoam's shifting only"),
        std::string::npos) << tail(out);
}


// ************************************************************************* //
