/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The physical bounds checked after every step (SPH::stepDisplacement for
    both solvers, SPH::wcsphBounds for wcsphFoam), on the still tank at
    dr = 0.05 m (200 fluid particles): runs that blow up stop with a last
    good state that is good (its densities within densityBounds, its
    speeds below maxMach c0), a Mach number above maxMach warns or stops
    as onMachExceeded says, a valid run trips nothing, and bad entries
    name themselves.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particles.H"

#include <cmath>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";

    //- The tutorial's sound speed, 10 sqrt(2 g H), H = 0.5 m
    const scalar c0Tank = 10*std::sqrt(2*9.81*0.5);

    //- The hydrostatic tank tutorial at dr = 0.05, with sphSchemes and
    //- controlDict entries replaced or added
    fileName tankCase
    (
        const std::string& name,
        const std::string& endTime,
        const std::string& schemes = "",
        const std::string& control = "",
        const std::string& fluidBox = "min (0 0); max ($W $H)"
    )
    {
        const fileName dir =
            fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/sphTest::perTest(name);
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        run("cp -r " + std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/wcsph/hydrostaticTank " + dir
            + " && sed -i 's/^dr .*/dr 0.05;/; s/min (0 0); max (\\$W \\$H)/" + fluidBox + "/' "
            + dir + "/system/sphMeshDict"
            + " && sed -i 's/^endTime .*/endTime " + endTime + ";/' " + dir + "/system/controlDict"
            + " && echo 'logInterval 1000;" + control + "' >> " + dir + "/system/controlDict"
            + " && echo '" + schemes + "' >> " + dir + "/system/sphSchemes", out);
        EXPECT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
        return dir;
    }

    //- The time of "The last good state, time T, ..." in a solver's output
    std::string lastGoodTime(const std::string& out)
    {
        const std::string key = "The last good state, time ";
        const std::size_t at = out.find(key);
        if (at == std::string::npos) return "";
        const std::size_t from = at + key.size();
        return out.substr(from, out.find(',', from) - from);
    }

    //- The fluid's extremes in a time directory: rho/rho0 and |U|
    struct extremes
    {
        label nFluid = 0;
        scalar rhoMin = VGREAT, rhoMax = -VGREAT, speedMax = 0;
    };

    extremes readExtremes(const fileName& dir, const word& time)
    {
        auto runTime = sphTest::makeTime(dir);
        SPH::particles parts(*runTime, time, SPH::particles::defaultLocal, false);
        parts.add<vector2D>("U");
        parts.add<scalar>("rho");
        parts.add<label>("type");
        parts.read();
        extremes e;
        const scalar rho0 = 1000;
        forAll(parts.positions(), i)
        {
            if (parts.field<label>("type")[i] != 0) continue;
            ++e.nFluid;
            const scalar rho = parts.field<scalar>("rho")[i];
            // NaN fails both
            EXPECT_TRUE(std::isfinite(rho)) << "particle " << i;
            e.rhoMin = min(e.rhoMin, rho/rho0);
            e.rhoMax = max(e.rhoMax, rho/rho0);
            e.speedMax = max(e.speedMax, mag(parts.field<vector2D>("U")[i]));
        }
        return e;
    }

    //- Every fluid particle within the default bounds: rho/rho0 in
    //- (0.8 1.25), |U| below 0.3 c0
    void expectGood
    (
        const fileName& dir,
        const std::string& time,
        const scalar c0,
        const label nFluid
    )
    {
        ASSERT_FALSE(time.empty());
        const extremes e = readExtremes(dir, time);
        EXPECT_EQ(e.nFluid, nFluid);
        EXPECT_GE(e.rhoMin, 0.8) << "t = " << time;
        EXPECT_LE(e.rhoMax, 1.25) << "t = " << time;
        EXPECT_LT(e.speedMax, 0.3*c0) << "t = " << time;
    }
}


TEST(wcsphBounds, tooLongFixedStepStopsWithAGoodLastState)
{
    // deltaT 0.01 s is 50 times eq. (15)'s 2e-4 s: the run saved a
    // state at t = 0.03 with |U| up to 1.9e19 m/s and rho from -1.9e15
    const fileName dir = tankCase
    (
        "wcsphBoundsLongStep", "0.1", "", "adjustTimeStep no; deltaT 0.01;"
    );
    std::string out;
    EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 1) << out;
    EXPECT_EQ(out.find("NaN or Inf in"), std::string::npos) << out;
    EXPECT_NE(out.find("more than maxStepDisplacement 1 h"), std::string::npos) << out;
    const std::string time = lastGoodTime(out);
    expectGood(dir, time, c0Tank, 200);
}


TEST(wcsphBounds, soundSpeedTooLowForTheHydrostaticStartStopsBeforeAStep)
{
    // c0 = 0.1 m/s: b0 = rho0 c0^2/7 = 1.43 Pa holds the 4905 Pa at the
    // bottom only at rho = 3.2 rho0. The runs (fixed deltaT: a
    // saved state with rho from -6.4e4 to 7.0e4; adjustTimeStep: to the
    // end, exit 0, rho 1.5-3.5 rho0) started from it
    for (const std::string control : {"", "adjustTimeStep no; deltaT 0.001;"})
    {
        const fileName dir = tankCase("wcsphBoundsLowC0", "0.1", "c0 0.1;", control);
        std::string out;
        EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 1) << out;
        EXPECT_NE(out.find("outside densityBounds (0.8 1.25)"), std::string::npos) << out;
        EXPECT_NE(out.find("in the starting state, time 0"), std::string::npos) << out;
        EXPECT_NE(out.find("raise c0"), std::string::npos) << out;
        // Nothing written: no state after the start was good
        EXPECT_FALSE(isDir(dir/"0.001")) << out;
        EXPECT_EQ(out.find("Starting time loop"), std::string::npos) << out;
    }
}


// A block of water 0.25 m deep falls 0.25 m, with p = 0 (free fall): it
// reaches 0.3 c0 = 1.2 m/s at t = 0.12 s and 2.2 m/s (Mach 0.55) at the
// floor. c0 = 4 m/s is too low for that fall, and the hydrostatic density
// of the block after impact, 1.11 rho0, is within the bounds
const std::string fallingBlock = "min (0 0.25); max ($W 0.5)";
const std::string lowC0 = "c0 4; ";


TEST(wcsphBounds, machAboveTheLimitStopsWhenTheCaseSaysStop)
{
    const fileName dir = tankCase
    (
        "wcsphBoundsMachStop", "0.5", lowC0 + "onMachExceeded stop;", "", fallingBlock
    );
    std::string out;
    run("sed -i 's/^internalField .*/internalField uniform 0;/' " + dir/"0"/"p", out);
    EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 1) << out;
    EXPECT_NE(out.find("Mach number |U|/c0 = "), std::string::npos) << out;
    EXPECT_NE(out.find("above maxMach 0.3"), std::string::npos) << out;
    EXPECT_NE(out.find("onMachExceeded stop"), std::string::npos) << out;
    const std::string time = lastGoodTime(out);
    expectGood(dir, time, 4, 100);
    // Before free fall reaches 1.2 m/s (0.122 s): the fastest particle,
    // at the block's edge, is pushed by the wall's repulsion too (stopped
    // at 0.103 s); after half of it
    EXPECT_LT(std::stod(time), 1.2/9.81);
    EXPECT_GT(std::stod(time), 0.6/9.81);
}


TEST(wcsphBounds, machAboveTheLimitWarnsOncePerWriteIntervalByDefault)
{
    const fileName dir = tankCase("wcsphBoundsMachWarn", "0.5", lowC0, "", fallingBlock);
    std::string out;
    run("sed -i 's/^internalField .*/internalField uniform 0;/' " + dir/"0"/"p", out);
    const int status = run(bin + "wcsphFoam -case " + dir, out);
    const std::string warning = "Mach number |U|/c0 = ";
    const std::size_t first = out.find(warning);
    ASSERT_NE(first, std::string::npos) << out;
    EXPECT_NE(out.find("onMachExceeded warn", first), std::string::npos) << out;

    // Once per write interval of 0.02 s, not at each step (hundreds)
    label nWarnings = 0;
    for (std::size_t at = first; at != std::string::npos; at = out.find(warning, at + 1))
    {
        ++nWarnings;
    }
    EXPECT_GE(nWarnings, 2) << out;
    EXPECT_LE(nWarnings, 0.5/0.02 + 1) << out;
    // It runs on, or stops at a bound (the impact's density) with a good
    // last state
    if (status != 0)
    {
        EXPECT_EQ(status, 1) << out;
        expectGood(dir, lastGoodTime(out), VGREAT, 100);
    }
}


TEST(wcsphBounds, stillTankTripsNoCheckAndReportsItsExtremes)
{
    const fileName dir = tankCase("wcsphBoundsStill", "0.2");
    std::string out;
    ASSERT_EQ(run(bin + "wcsphFoam -case " + dir, out), 0) << out;
    EXPECT_EQ(out.find("Warning"), std::string::npos) << out;
    EXPECT_NE(out.find("maxStepDisplacement 1 h in a step"), std::string::npos) << out;
    EXPECT_NE(out.find("densityBounds (0.8 1.25), max|U|/c0 above maxMach 0.3"), std::string::npos) << out;
    EXPECT_NE(out.find("Bounds reached: rho/rho0 from "), std::string::npos) << out;
    EXPECT_NE(out.find("Largest move in a step: "), std::string::npos) << out;
    // The water keeps its room: a spread within 1 % (SPH::spreadLimit)
    const scalar spread = sphTest::numberAfter(out, "Largest spread of the fluid: ");
    ASSERT_FALSE(std::isnan(spread)) << out;
    EXPECT_LT(std::abs(spread), 0.01) << out;
}


TEST(wcsphBounds, badEntriesNameTheFileAndEntry)
{
    const std::vector<std::pair<std::string, std::string>> cases
    {
        {"densityBounds (1.1 2);", "densityBounds"},
        {"densityBounds (0.5 0.9);", "densityBounds"},
        {"maxMach -1;", "maxMach"},
        {"maxMach 0;", "maxMach"},
        {"onMachExceeded sometimes;", "warn"},
        {"maxStepDisplacement 0;", "maxStepDisplacement"},
        {"maxSpread -1;", "maxSpread"},
        {"wallBounceElasticity 1.5;", "wallBounceElasticity"},
        {"wallBounceElasticity -0.1;", "wallBounceElasticity"},
    };
    for (const auto& c : cases)
    {
        const fileName dir = tankCase("wcsphBoundsBadEntry", "0.01", c.first);
        std::string out;
        EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 1) << c.first << out;
        EXPECT_NE(out.find(c.second), std::string::npos) << c.first << out;
        EXPECT_NE(out.find("system/sphSchemes"), std::string::npos) << c.first << out;
    }
}


// ************************************************************************* //
