/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    wcsphFoam's time integrators (timeScheme in system/sphSchemes;
    src/sph/solvers/wcsph/wcsph/wcsphSymplectic.C): the symplectic
    predictor-corrector and its leapfrog form are second order in time on
    the first instants of the Zhou dam-break (against Runge-Kutta 4 at an
    eighth of the step), keep still water at rest as Runge-Kutta 4 does,
    restart exactly; an unknown timeScheme and moving walls with the new
    schemes are clear errors. With wallTension no the leapfrog runs the
    dam-break through its impacts without artificial viscosity.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "restartCheck.H"
#include "solverCase.H"
#include "probeSeries.H"
#include "particles.H"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <fstream>
#include <sstream>


using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";

    void appendTo(const fileName& file, const std::string& text)
    {
        std::string out;
        EXPECT_EQ(run("echo '" + text + "' >> " + file, out), 0) << out;
    }

    //- The Zhou dam-break at H/dr 12 (288 fluid particles), meshed, with a
    //- fixed time step and no function objects: the start of the collapse
    fileName zhouCase(const std::string& name)
    {
        const fileName dir = sphTest::copyTutorial("damBreak/zhou", sphTest::perTest(name));
        std::string out;
        run("sed -i 's/^resolution .*/resolution 12;/' " + dir/"system"/"sphMeshDict"
            + " && sed -i -e 's/^adjustTimeStep .*/adjustTimeStep no;/'"
              " -e 's/^logInterval .*/logInterval 100000;/'"
              " -e '/^functions/,$d' " + dir/"system"/"controlDict", out);
        EXPECT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
        return dir;
    }

    //- Fluid velocities at endTime after a run with the given scheme and
    //- step, by particle id (the fluid's ids are 0 .. nFluid-1; the
    //- particles are renumbered as they move, particleSortInterval)
    List<vector2D> zhouVelocities
    (
        const fileName& base, const std::string& scheme, const scalar dt,
        const std::string& endTime, const label sortInterval = 20
    )
    {
        const fileName dir =
            base + "_" + scheme + "_" + std::to_string(label(1e6*dt))
          + "_" + std::to_string(sortInterval);
        std::string out;
        run("rm -rf " + dir + " && cp -r " + base + " " + dir, out);
        sphTest::setEntry(dir/"system"/"controlDict", "deltaT", std::to_string(dt));
        sphTest::setEntry(dir/"system"/"controlDict", "endTime", endTime);
        sphTest::setEntry(dir/"system"/"controlDict", "writeInterval", endTime);
        appendTo(dir/"system"/"sphSchemes", "timeScheme " + scheme + ";");
        appendTo
        (
            dir/"system"/"sphSchemes",
            "particleSortInterval " + std::to_string(sortInterval) + ";"
        );
        EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 0) << sphTest::logTail(out);

        auto runTime = sphTest::makeTime(dir);
        SPH::particles parts(*runTime, endTime, SPH::particles::defaultLocal, false);
        parts.add<vector2D>("U");
        parts.add<label>("type");
        parts.add<label>("id");
        parts.read();
        const labelField& type = parts.field<label>("type");
        const labelField& id = parts.field<label>("id");
        List<vector2D> U(std::count(type.begin(), type.end(), 0));
        forAll(type, i)
        {
            if (type[i] == 0)
            {
                U[id[i]] = parts.field<vector2D>("U")[i];
            }
        }
        return U;
    }

    std::string show(const scalarList& values)
    {
        std::ostringstream os;
        for (const scalar v : values) os << v << ' ';
        return os.str();
    }

    scalar rmsDifference(const List<vector2D>& a, const List<vector2D>& b)
    {
        EXPECT_EQ(a.size(), b.size());
        scalar sum = 0;
        forAll(a, i)
        {
            sum += magSqr(a[i] - b[i]);
        }
        return std::sqrt(sum/max(a.size(), 1));
    }

    //- The still-water tank of tutorials/wcsph/hydrostaticTank, dr = 0.025
    //- (20 layers), to endTime with the given scheme: the largest fluid
    //- speed over sqrt(g H) and the largest departure of the bottom probe
    //- from rho g H, over rho g H
    std::pair<scalar, scalar> stillTank
    (
        const std::string& scheme,
        const std::string& endTime,
        const std::string& schemesEntries = ""
    )
    {
        const scalar H = 0.5, rho = 1000, g = 9.81;
        const fileName dir = sphTest::copyTutorial("wcsph/hydrostaticTank", sphTest::perTest("tank"));
        std::string out;
        sphTest::setEntry(dir/"system"/"sphMeshDict", "dr", "0.025");
        sphTest::setEntry(dir/"system"/"controlDict", "endTime", endTime);
        sphTest::setEntry(dir/"system"/"controlDict", "writeInterval", "0.05");
        appendTo(dir/"system"/"controlDict", "logInterval 100000;");
        appendTo(dir/"system"/"sphSchemes", "timeScheme " + scheme + ";" + schemesEntries);
        EXPECT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
        EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 0) << sphTest::logTail(out);
        EXPECT_NE(out.find("time scheme         " + scheme), std::string::npos)
            << sphTest::logTail(out);

        scalar maxSpeed = 0;
        auto runTime = sphTest::makeTime(dir);
        label nTimes = 0;
        for (const instant& t : runTime->times())
        {
            if (t.value() <= 0) continue;
            ++nTimes;
            SPH::particles parts(*runTime, t.name(), SPH::particles::defaultLocal, false);
            parts.add<vector2D>("U");
            parts.add<label>("type");
            parts.read();
            forAll(parts.positions(), i)
            {
                if (parts.field<label>("type")[i] == 0)
                {
                    maxSpeed = max(maxSpeed, mag(parts.field<vector2D>("U")[i]));
                }
            }
        }
        EXPECT_GE(nTimes, 10);

        scalar worst = 0;
        for (const auto& [t, p] : sphTest::probeSeries(dir/"postProcessing"/"bottom"/"0"/"p"))
        {
            worst = max(worst, mag(p/(rho*g*H) - 1));
        }
        return {maxSpeed/std::sqrt(g*H), worst};
    }
}


TEST(wcsphIntegrators, unknownTimeSchemeIsAFatalIOErrorListingTheValidWords)
{
    const fileName dir = sphTest::tankCase("wcsph", sphTest::perTest("badScheme"));
    appendTo(dir/"system"/"sphSchemes", "timeScheme verlet;");
    std::string out;
    EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 1) << out;
    for (const char* word :
        {"timeScheme", "verlet", "sphSchemes", "RungeKutta4", "symplectic", "leapfrog"})
    {
        EXPECT_NE(out.find(word), std::string::npos) << word << " not in" << nl << out;
    }
}


TEST(wcsphIntegrators, movingWallsWithSymplecticAreAClearError)
{
    // The wall model places moving walls at the time of the last rate
    // evaluation (t^{n+1/2} for the symplectic schemes): not supported yet
    const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/sphTest::perTest("box");
    std::string out;
    run("rm -rf " + dir + " && mkdir -p " + dir.path() + " && cp -r "
        + std::string(SPHFOAM_SOURCE_DIR) + "/tests/regression/wcsphFoam/movingBox " + dir, out);
    ASSERT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
    appendTo(dir/"system"/"sphSchemes", "timeScheme symplectic;");
    EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 1) << sphTest::logTail(out);
    for (const char* word : {"timeScheme symplectic", "sphSchemes", "RungeKutta4 only"})
    {
        EXPECT_NE(out.find(word), std::string::npos) << word << " not in" << nl << out;
    }
}


TEST(wcsphIntegrators, symplecticAndLeapfrogAreSecondOrderInTime)
{
    // The first 0.04 s of the collapse at H/dr 12, fixed steps of 4e-4 s
    // (C_n = dt c0/h = 0.27, about the largest stable one), 2e-4 and 1e-4,
    // against Runge-Kutta 4 at 5e-5 s (its error, O(dt^4), is below 1 %
    // of the finest step's here). The RMS velocity error of a second-order
    // scheme falls 4 times when the step is halved: the observed order
    // log2(e(dt)/e(dt/2)) must lie in [1.6, 2.6] (first order gives 1;
    // the acoustic modes at omega dt up to about 0.3 add a relative
    // O((omega dt)^2) of about 10 % to the ratio)
    const fileName base = zhouCase("zhouOrder");
    const std::string T = "0.04";
    const List<vector2D> reference = zhouVelocities(base, "RungeKutta4", 5e-5, T);
    ASSERT_GT(reference.size(), 200);

    for (const std::string scheme : {"symplectic", "leapfrog"})
    {
        scalarList errors;
        for (const scalar dt : {4e-4, 2e-4, 1e-4})
        {
            errors.append(rmsDifference(zhouVelocities(base, scheme, dt, T), reference));
        }
        std::cout << scheme << ": RMS velocity errors [m/s] at dt = 4e-4, 2e-4, 1e-4: "
            << show(errors) << std::endl;
        for (label k = 0; k < 2; ++k)
        {
            const scalar order = std::log2(errors[k]/errors[k + 1]);
            EXPECT_GT(order, 1.6) << scheme << ": errors " << show(errors);
            EXPECT_LT(order, 2.6) << scheme << ": errors " << show(errors);
        }
        // The finest step is already close: well below the speeds of the
        // collapse (g t = 0.4 m/s)
        EXPECT_LT(errors[2], 1e-3) << scheme << ": errors " << show(errors);
    }
}


TEST(wcsphIntegrators, sortingTheParticlesChangesOnlyTheRoundOff)
{
    // particleSortInterval renumbers the fluid between steps; the
    // leapfrog's predictor carries the last step's rates across it. Over
    // the first 0.2 s of the collapse (1000 steps, 143 sorts; the front
    // has moved 4 spacings) the velocities must be those of the run never
    // sorted up to the order of the sums (measured: 8.5e-15 m/s with the
    // leapfrog, 3.0e-15 with Runge-Kutta 4); the leapfrog's rates left on
    // the old numbering gave 7.2e-6 m/s
    const fileName base = zhouCase("zhouSort");
    const std::string T = "0.2";
    for (const std::string scheme : {"leapfrog", "RungeKutta4"})
    {
        const scalar diff = rmsDifference
        (
            zhouVelocities(base, scheme, 2e-4, T, 7),
            zhouVelocities(base, scheme, 2e-4, T, 0)
        );
        EXPECT_LT(diff, 1e-10) << scheme;
        std::cout << scheme << ": RMS velocity difference sorted/unsorted "
            << diff << " m/s" << std::endl;
    }
}


TEST(wcsphIntegrators, symplecticKeepsStillWaterAtRest)
{
    // The tutorial's acceptance figures, as for Runge-Kutta 4
    // (wcsphFoam.hydrostaticTankStaysAtRestForTwoSeconds): speed below 1 %
    // of sqrt(g H), the bottom pressure within 3 % of rho g H
    const auto [speed, pressure] = stillTank("symplectic", "1");
    EXPECT_LT(speed, 0.01);
    EXPECT_LT(pressure, 0.03);
}


TEST(wcsphIntegrators, leapfrogKeepsStillWaterAtRest)
{
    const auto [speed, pressure] = stillTank("leapfrog", "1");
    EXPECT_LT(speed, 0.01);
    EXPECT_LT(pressure, 0.03);
}


TEST(wcsphIntegrators, leapfrogWithoutWallTensionKeepsStillWaterAtRest)
{
    // The still tank's free surface meets the walls: its dummies there
    // carry p near 0, which wallTension no must not disturb
    const auto [speed, pressure] = stillTank("leapfrog", "1", " wallTension no;");
    EXPECT_LT(speed, 0.01);
    EXPECT_LT(pressure, 0.03);
}


TEST(wcsphIntegrators, leapfrogWithoutWallTensionNeedsNoArtificialViscosity)
{
    // The Zhou dam-break at H/dr 24, leapfrog at maxCo 0.4 and no
    // artificial viscosity, to t sqrt(g/H) = 6.1. With the dummies'
    // pressure as printed (eq. (10)) a lone particle under the ceiling
    // copies its own tension onto the dummies, is pulled back and forth
    // across the wall with a growing amplitude, and the run stops on
    // densityBounds at t sqrt(g/H) = 4.6 (tutorials/damBreak/zhou/
    // README.md); with wallTension no it runs on, every particle kept
    const fileName dir = sphTest::copyTutorial("damBreak/zhou", sphTest::perTest("zhou"));
    std::string out;
    run("sed -i 's/^resolution .*/resolution 24;/' " + dir/"system"/"sphMeshDict"
        + " && sed -i -e 's/^maxCo .*/maxCo 0.4;/' -e 's/^endTime .*/endTime 1.5;/'"
          " -e 's/^writeInterval .*/writeInterval 0.5;/'"
          " -e 's/^logInterval .*/logInterval 100000;/'"
          " -e '/^functions/,$d' " + dir/"system"/"controlDict", out);
    appendTo(dir/"system"/"sphSchemes", "timeScheme leapfrog; wallTension no;");
    ASSERT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
    EXPECT_EQ(run(bin + "wcsphFoam -case " + dir, out), 0) << sphTest::logTail(out);
    EXPECT_NE(out.find("fluid tension read as 0 (wallTension no)"), std::string::npos)
        << sphTest::logTail(out);

    auto runTime = sphTest::makeTime(dir);
    SPH::particles parts(*runTime, "1.5", SPH::particles::defaultLocal, false);
    parts.add<vector2D>("U");
    parts.add<label>("type");
    parts.read();
    const labelField& type = parts.field<label>("type");
    label nFluid = 0;
    scalar maxSpeed = 0;
    forAll(type, i)
    {
        if (type[i] == 0)
        {
            ++nFluid;
            maxSpeed = max(maxSpeed, mag(parts.field<vector2D>("U")[i]));
        }
    }
    EXPECT_EQ(nFluid, 1152);
    // Twice the speed of a fall from the column's height, 2 sqrt(2 g H)
    EXPECT_LT(maxSpeed, 2*std::sqrt(2*9.81*0.6));
}


TEST(wcsphIntegrators, leapfrogRestartIsExactToTheBit)
{
    // The leapfrog's predictor reuses the last step's rates except after a
    // write: a run restarted from a write must be the run straight through
    // (binary writes: an ascii restart reads rounded values back)
    const fileName dir = sphTest::tankCase("wcsph", sphTest::perTest("restart"), "0.02");
    sphTest::setEntry(dir/"system"/"controlDict", "writeFormat", "binary");
    appendTo(dir/"system"/"sphSchemes", "timeScheme leapfrog;");
    sphTest::expectExactRestart("wcsphFoam", dir, "0.02", "0.01");
}


// ************************************************************************* //
