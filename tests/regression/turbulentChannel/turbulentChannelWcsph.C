/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The turbulent channel tutorial's WCSPH-USAW k-epsilon (Leroy et al.
    2014 sections 3.1, 5.1 and 5.2: the model "the same as in WCSPH with
    the present boundary conditions", after Ferrand et al. 2013) as a user
    runs it: Allrun -test -fv -wcsph runs wcsphFoam at Re* = 640, dr = 0.1
    (190 particles, the first row at y+ = 64, c0 = 220 m/s: 11000 steps,
    25 s CPU) from the FV case's own 0/k, 0/epsilon, 0/nut to t = 2 s
    beside pimpleFoam over the same 2 s (FV-t, the spin-up from the same
    start), and compare's differences.dat holds WCSPH against FV-t.
    Tolerances, about 1.6 times what was measured (2026-12-02, with the
    case's shift), as for ISPH's (turbulentChannelSph.C, its figures
    beside):
    - u+ for y+ > 30: max 4.8 % (ISPH 5.0 %); checked to 8 %;
    - k+, eps+, nuT+ from the third row on: max 4.1, 4.7, 2.3 % (ISPH
      2.4, 4.6, 2.8 %); checked to 7, 8, 5 %;
    - the particles stay on their rows: drift 0.045 dr; checked to 0.1 dr
      (without the shift 0.39 dr at 5 s: see the tutorial's README);
    - the log names the k-epsilon stage and the viscous term (22)-(24);
    - with boundaryMethod dummyRepulsive a RAS case is refused, naming
      simulationType and boundaryMethod usaw, and so is one with a wall
      that slides (as isphFoam's); without constant/turbulenceProperties
      the run is laminar and says so, and writes no k.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

using namespace Foam;

namespace
{
    double maxDifference
    (
        const fileName& diffs,
        const std::string& quantity
    )
    {
        const std::vector<std::string> row =
            sphTest::tableRow(diffs, {"640", "WCSPH", "0.1", quantity, "FV-t"});
        return row.size() == 8u ? std::stod(row[5]) : 1e9;
    }

    //- A copy of the wcsph/ template at Re* 640, dr 0.1, tEnd 2 in dir/run,
    //- meshed
    fileName wcsphRun(const fileName& dir, std::string& out)
    {
        const fileName run = dir/"runs"/"test"/"Re640"/"wcsph_dr0.1";
        sphTest::runWithBashrc
        (
            "cd " + dir + " && . $SPHFOAM_PROJECT_DIR/bin/tools/RunFunctions"
            " && . ./channelFunctions && copyTemplate wcsph " + run
          + " && setParameters 640 0.1 2 " + run
          + " && cd " + run + " && sphMesh > log.sphMesh 2>&1",
            out
        );
        return run;
    }
}


TEST(turbulentChannelTutorial, wcsphKEpsilonFollowsTheFvSpinUp)
{
    const fileName dir =
        sphTest::copyTutorial("turbulence/channel", "turbulentChannelWcsph");
    sphTest::run("rm -rf " + dir + "/runs " + dir + "/results");
    std::string out;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test -fv -wcsph", out), 0)
        << out;

    const fileName results = dir/"runs"/"test"/"results";
    const fileName diffs = results/"differences.dat";
    EXPECT_LT(maxDifference(diffs, "u+"), 0.08) << out;
    EXPECT_LT(maxDifference(diffs, "k+"), 0.07);
    EXPECT_LT(maxDifference(diffs, "eps+"), 0.08);
    EXPECT_LT(maxDifference(diffs, "nuT+"), 0.05);

    // Re method dr n y+_1 u*_wall log_max log_mean CPU_s clock_s t files drift
    const std::vector<std::string> sph =
        sphTest::tableRow(results/"runs.dat", {"640", "WCSPH", "0.1"});
    ASSERT_EQ(sph.size(), 13u);
    EXPECT_EQ(sph[10], "2");
    EXPECT_LT(std::stod(sph[12]), 0.1);

    std::string log;
    sphTest::run
    (
        "cat " + dir + "/runs/test/Re640/wcsph_dr0.1/log.wcsphFoam", log
    );
    EXPECT_NE(log.find("turbulence          k-epsilon"), std::string::npos)
        << log.substr(0, 6000);
    EXPECT_NE(log.find("mu_E = rho0 (nu + nu_T)"), std::string::npos);

    // k, epsilon and nut written with the particles
    const fileName last =
        dir/"runs"/"test"/"Re640"/"wcsph_dr0.1"/"2"/"lagrangian"/"sph";
    for (const word name : {"k", "epsilon", "nut"})
    {
        EXPECT_TRUE(isFile(last/name)) << last/name;
    }
}


TEST(turbulentChannelTutorial, wcsphRasWithDummyWallsIsRefused)
{
    const fileName dir =
        sphTest::copyTutorial("turbulence/channel", "turbulentChannelWcsphDummy");
    sphTest::run("rm -rf " + dir + "/runs " + dir + "/results");
    std::string out;
    const fileName run = wcsphRun(dir, out);
    ASSERT_TRUE(isDir(run/"constant"/"sphMesh")) << out;

    // Dummy walls, laid out again for them
    sphTest::run
    (
        "sed -i 's/^boundaryMethod .*/boundaryMethod  dummyRepulsive;/' "
      + run + "/system/sphSchemes"
    );
    std::string log;
    sphTest::runWithBashrc("cd " + run + " && sphMesh", log);
    const int rc = sphTest::runWithBashrc("cd " + run + " && wcsphFoam", log);
    EXPECT_NE(rc, 0);
    EXPECT_NE(log.find("simulationType RAS with boundaryMethod dummyRepulsive"), std::string::npos)
        << log.substr(0, 6000);
    EXPECT_NE(log.find("use boundaryMethod usaw"), std::string::npos);
    EXPECT_NE(log.find("turbulenceProperties"), std::string::npos);
}


TEST(turbulentChannelTutorial, wcsphRasWithAMovingWallIsRefused)
{
    const fileName dir =
        sphTest::copyTutorial("turbulence/channel", "turbulentChannelWcsphMoving");
    sphTest::run("rm -rf " + dir + "/runs " + dir + "/results");
    std::string out;
    const fileName run = wcsphRun(dir, out);
    ASSERT_TRUE(isDir(run/"constant"/"sphMesh")) << out;

    // The upper wall slides at 1 m/s (a Couette lid)
    sphTest::run
    (
        "cd " + run + " && sed -i '/upperWall/,/}/{s/type .*noSlip;/type"
        " fixedValue; value uniform (1 0 0);/}' 0/U"
    );
    std::string log;
    const int rc = sphTest::runWithBashrc("cd " + run + " && wcsphFoam", log);
    EXPECT_NE(rc, 0);
    EXPECT_NE(log.find("RASModel kEpsilon with moving walls"), std::string::npos)
        << log.substr(0, 6000);
}


TEST(turbulentChannelTutorial, wcsphWithoutTurbulencePropertiesIsLaminar)
{
    const fileName dir =
        sphTest::copyTutorial("turbulence/channel", "turbulentChannelWcsphLaminar");
    sphTest::run("rm -rf " + dir + "/runs " + dir + "/results");
    std::string out;
    const fileName run = wcsphRun(dir, out);
    ASSERT_TRUE(isDir(run/"constant"/"sphMesh")) << out;

    // 0.001 s (5 steps), written at the end
    sphTest::run
    (
        "rm " + run + "/constant/turbulenceProperties && sed -i"
        " 's/^endTime .*/endTime 0.001;/; s/^writeInterval .*/writeInterval"
        " 0.001;/' " + run + "/system/controlDict"
    );
    std::string log;
    ASSERT_EQ(sphTest::runWithBashrc("cd " + run + " && wcsphFoam", log), 0)
        << log.substr(0, 6000);
    EXPECT_NE(log.find("turbulence          laminar: no k, epsilon or nut"), std::string::npos)
        << log.substr(0, 6000);
    EXPECT_EQ(log.find("k-epsilon"), std::string::npos);
    EXPECT_NE(log.find("viscosity          L{mu, u}/rho"), std::string::npos);
    EXPECT_TRUE(isFile(run/"0.001"/"lagrangian"/"sph"/"U"));
    EXPECT_FALSE(isFile(run/"0.001"/"lagrangian"/"sph"/"k"));
}


// ************************************************************************* //
