/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The heated Poiseuille tutorial (Leroy et al. 2015, section 4.1) as a
    user runs it: Allrun -test runs buoyantBoussinesqPimpleFoam and
    isphFoam on case TT (isothermal walls, Pr 1, Re 50, Gr 98) at 20
    cells/particles across (dr/L = 0.1) to 60 s (steady), and compare writes the
    errors against Table 2's T+ and p*+ and eq. (41)'s L2 error.

    Tolerances (measured figures in the tutorial's README):
    - ISPH T+: max relative error of the row means measured 1.2e-4 (the
      paper: "of the order of 1 %"); checked to 1e-3,
      which a wall term off by its factor 2, a flux of the wrong sign or a
      missing T shift all exceed;
    - ISPH L2 (41): measured 5e-5; checked to 5e-4;
    - ISPH p*+: measured 0.19 % at dr/L = 0.1, the rows averaged over
      the 50 files of the last quarter (3.2 % over 5 files: the rows'
      pressure oscillates coherently as they slide past each other, see
      compare); checked to 1 %, the criterion of issue 15 (without the
      Boussinesq force in the pressure's wall condition it was 7.5 %;
      without the force at all 100 %);
    - FV: T+ and p*+ measured 3e-6 (the steady state is exact on the
      mesh); checked to 1e-4;
    - wallNusselt (42) on both walls: 0.5007 against 0.5 with its default
      renormalised gradient (the paper's G-, wallGradient gamma: 0.509);
      checked to 0.5 %.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    //- The words of the row of errors.dat for config, method and N
    std::vector<std::string> rowOf
    (
        const fileName& file,
        const std::string& config,
        const std::string& method,
        const std::string& n
    )
    {
        std::ifstream is(file);
        std::string line;
        while (std::getline(is, line))
        {
            std::istringstream ls(line);
            std::vector<std::string> w;
            std::string s;
            while (ls >> s) w.push_back(s);
            if (w.size() > 8 && w[0] == config && w[1] == method && w[2] == n)
            {
                return w;
            }
        }
        return {};
    }
}


TEST(heatedPoiseuilleTutorial, temperatureAndDynamicPressureAgainstTable2)
{
    const fileName dir =
        sphTest::copyTutorial("heatTransfer/poiseuille", "heatedPoiseuille");
    std::string out;
    // Runs of a developer's source tree are not this test's
    sphTest::run("rm -rf " + dir + "/runs " + dir + "/results", out);
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test", out), 0) << out;

    // config method N dr/L eT eP eTp ePp L2 CPU clock time files
    const fileName table = dir/"results"/"errors.dat";
    const std::vector<std::string> sph = rowOf(table, "TT", "ISPH", "20");
    const std::vector<std::string> fv = rowOf(table, "TT", "FV", "20");
    ASSERT_FALSE(sph.empty()) << out;
    ASSERT_FALSE(fv.empty()) << out;

    EXPECT_LT(std::stod(sph[4]), 1e-3) << "ISPH T+";
    EXPECT_LT(std::stod(sph[8]), 5e-4) << "ISPH L2 (41)";
    EXPECT_LT(std::stod(sph[5]), 0.01) << "ISPH p*+";
    EXPECT_LT(std::stod(fv[4]), 1e-4) << "FV T+";
    EXPECT_LT(std::stod(fv[5]), 1e-4) << "FV p*+";

    // The wall Nusselt number (42), both walls: exact 0.5; measured
    // 0.5007 (R . G- at the wall vertices), checked to 0.5 %
    {
        std::ifstream is(dir/"runs"/"TT"/"sph20"/"postProcessing"/"Nusselt"/"0"/"wallNusselt.dat");
        std::string line, last[2];
        while (std::getline(is, line))
        {
            if (line.empty() || line[0] == '#') continue;
            last[0] = last[1];
            last[1] = line;
        }
        for (const std::string& l : last)
        {
            std::istringstream ls(l);
            std::string t, patch;
            double mn, mx, integral, average;
            ASSERT_TRUE(bool(ls >> t >> patch >> mn >> mx >> integral >> average)) << l;
            EXPECT_NEAR(average, 0.5, 0.0025) << patch;
            EXPECT_NEAR(integral, 1.1*average, 1e-6) << patch << ": length 1.1";
        }
    }

    // The fields under the names the FV side writes
    EXPECT_TRUE(isFile(dir/"runs"/"TT"/"sph20"/"60"/"lagrangian"/"sph"/"T"))
        << "T particle field";
    EXPECT_TRUE(isFile(dir/"runs"/"TT"/"sph20"/"60"/"lagrangian"/"sph"/"p_rgh"))
        << "p_rgh particle field";
}


// ************************************************************************* //
