/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The tall differentially heated cavity tutorial (Leroy et al. 2015
    section 5.2: aspect ratio 4, Ra = 6.4e8, Pr = 0.71, k-epsilon with the
    buoyant terms) as Allreport's quick form runs it: Allrun -test runs
    buoyantBoussinesqSimpleFoam on 20 x 80 cells to its residual criterion
    and isphFoam at dr = 0.05 from rest to t = 10 s, far from the steady
    state. It checks the chain, with tolerances from what was measured
    (2026-12-03):
    - FV reaches SIMPLE's residual criterion;
    - the SPH's stage list names the buoyant k-epsilon terms;
    - across mid-height (z+ = 1) the SPH's T against FV's, max
      |dT|/(Th - Tc): measured 0.094 at 10 s (the boundary layers of the
      hot and cold walls form within seconds); checked to 0.15. Without
      heat transport the line stays at 0.5 (0.5 off at the walls);
    - the three lines and errors.csv are written.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

using namespace Foam;

TEST(tallCavityTutorial, quickFormRunsBothSidesAndTheBoundaryLayersForm)
{
    const fileName dir =
        sphTest::copyTutorial("heatTransfer/tallCavity", "tallCavity");
    std::string out;
    sphTest::run("rm -rf " + dir + "/runs " + dir + "/results", out);
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test", out), 0) << out;

    const fileName test = dir/"runs"/"test";
    const std::string fvLog =
        sphTest::run("cat " + test/"fv20"/"log.buoyantBoussinesqSimpleFoam");
    EXPECT_NE(fvLog.find("SIMPLE solution converged"), std::string::npos);

    const std::string sphLog = sphTest::run("cat " + test/"sph0.05"/"log.isphFoam");
    EXPECT_NE(sphLog.find("buoyant G (Leroy et al. 2015"), std::string::npos);
    EXPECT_NE(sphLog.find("\nEnd"), std::string::npos);

    const fileName table = test/"results"/"differences.dat";
    for (const char* line : {"x+=0.125", "z+=1", "x=W/2"})
    {
        const std::vector<std::string> row =
            sphTest::tableRow(table, {"sph0.05", "fv20", line});
        ASSERT_GE(row.size(), 5u) << line << out;
        EXPECT_GT(std::stod(row[3]), 0) << line;
    }
    const std::vector<std::string> mid =
        sphTest::tableRow(table, {"sph0.05", "fv20", "z+=1"});
    EXPECT_LT(std::stod(mid[3]), 0.15) << "T across mid-height";

    EXPECT_TRUE(isFile(test/"results"/"errors.csv"));
    EXPECT_TRUE(isFile(test/"results"/"temperature.png"));
}


// ************************************************************************* //
