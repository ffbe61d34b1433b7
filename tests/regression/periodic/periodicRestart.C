/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Bit-exact restarts of the solvers on periodic cases (issue 11, "How we
    will check"), with the check of restartCheck.H (run A from 0 to T, run B
    to T/2 and restarted to T: every file of the T directories the same):
    - isphFoam on the Poiseuille channel of tutorials/periodic/poiseuille/sph
      (periodic in x, walls at y = 0 and D) at 10 particles across, driven
      by meanVelocityForce, whose controller state
      uniform/meanVelocityProperties is part of the restart;
    - wcsphFoam on the same channel (WCSPH-USAW,
      tutorials/periodic/poiseuille/wcsph) under meanVelocityForce, whose
      controller is updated once per step after the Runge-Kutta update;
    - wcsphFoam on the Taylor-Green vortex of tutorials/periodic/taylorGreen
      (periodic in x and y, no walls) at 25^2, the vortex written per
      particle by its setTaylorGreen.
    The moving-wall case (the stirrer, constant/dynamicMeshDict) is in
    tests/regression/isphFoam (isphFoam.restartIsExactToTheBit), with the
    same check.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "restartCheck.H"

#include <algorithm>

using namespace Foam;
using sphTest::run;
using sphTest::setEntry;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";
    const std::string tutorials = std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/periodic/";

    //- A tutorial's case template copied under the build's tests/cases, with
    //- the tutorial's parameter file (from its fv/system) in its system/
    fileName copyTemplate
    (
        const std::string& tutorial,
        const std::string& templ,
        const std::string& parameters,
        const std::string& name
    )
    {
        const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/name;
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        EXPECT_EQ
        (
            run
            (
                "cp -r " + tutorials + tutorial + "/" + templ + " " + dir
              + " && cp " + tutorials + tutorial + "/fv/system/" + parameters + " "
              + dir + "/system/"
            , out),
            0
        ) << out;
        return dir;
    }

    //- Was the file written at the time?
    bool has(const std::vector<std::string>& files, const std::string& f)
    {
        return std::find(files.begin(), files.end(), f) != files.end();
    }
}


TEST(periodicRestart, isphPoiseuilleWithMeanVelocityForceIsExactToTheBit)
{
    // 10 particles across (dr = 0.1, 10 x 9 fluid particles and 20 wall
    // vertices), the drive meanVelocityForce (the tutorial's force
    // meanVelocity); T = 1 s is 36 steps, the mean velocity then held at
    // Ubar = 1 to 1e-5 by the controller
    const fileName dir =
        copyTemplate("poiseuille", "sph", "poiseuilleParameters", "periodicRestartPoiseuille");
    setEntry(dir/"system"/"poiseuilleParameters", "n", "10");
    setEntry(dir/"system"/"poiseuilleParameters", "force", "meanVelocity");
    std::string out;
    ASSERT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("Domain: periodic in x"), std::string::npos) << out;

    const std::vector<std::string> files =
        sphTest::expectExactRestart("isphFoam", dir, "1", "0.5", "meanVelocityForce");
    EXPECT_TRUE(has(files, "uniform/meanVelocityProperties"));
}


TEST(periodicRestart, wcsphPoiseuilleWithMeanVelocityForceIsExactToTheBit)
{
    // 10 particles across, WCSPH-USAW (c0 = 15 m/s): T = 1 s is about 380
    // steps of the acoustic limit. The force of the step after the write
    // is the controller's state of uniform/meanVelocityProperties
    const fileName dir = copyTemplate
    (
        "poiseuille", "wcsph", "poiseuilleParameters", "periodicRestartPoiseuilleWcsph"
    );
    setEntry(dir/"system"/"poiseuilleParameters", "n", "10");
    setEntry(dir/"system"/"poiseuilleParameters", "force", "meanVelocity");
    std::string out;
    ASSERT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;

    const std::vector<std::string> files = sphTest::expectExactRestart
    (
        "wcsphFoam", dir, "1", "0.5", "meanVelocity: meanVelocityForce, Ubar (1 0)"
    );
    EXPECT_TRUE(has(files, "uniform/meanVelocityProperties"));
}


TEST(periodicRestart, wcsphTaylorGreenIsExactToTheBit)
{
    // 25^2 particles (dr = 0.04), the vortex at t = 0 per particle; T = 0.1 s
    // is 64 steps of 1.5625e-3 s
    const fileName dir =
        copyTemplate("taylorGreen", "wcsph", "taylorGreenParameters", "periodicRestartTaylorGreen");
    setEntry(dir/"system"/"taylorGreenParameters", "n", "25");
    std::string out;
    ASSERT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("Domain: periodic in x y"), std::string::npos) << out;
    ASSERT_EQ
    (
        // setTaylorGreen needs numpy: the build's Python (SPHFOAM_PYTHON)
        run
        (
            std::string(SPHFOAM_PYTHON) + " " + tutorials + "taylorGreen/setTaylorGreen"
            " -case " + dir, out
        ),
        0
    ) << out;
    EXPECT_NE(out.find("625 values"), std::string::npos) << out;

    sphTest::expectExactRestart("wcsphFoam", dir, "0.1", "0.05");
}


// ************************************************************************* //
