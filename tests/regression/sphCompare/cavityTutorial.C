/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The lid-driven cavity tutorial as a user runs it, FV side (isphFoam does
    not exist yet: Allrun says so and goes on): Allrun -test -fv runs
    icoFoam at 16^2 and 32^2 cells to steady state, compares them with
    sphCompare and writes the pictures and the table; sweep then reuses
    those runs for its convergence table and picture.

    Figures: at 16^2, Re = 100, icoFoam is within 0.04 U of Ghia et al.
    (measured 0.022 and 0.017; 0.009 U at 32^2 and finer, see
    ../shared/reference/README.md), and its L2 of eq. (66) against the
    32^2 run is of the order of its distance to Ghia (measured 0.015).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    //- The rows of a results table whose first word is key
    List<List<std::string>> rowsOf(const fileName& file, const std::string& key)
    {
        List<List<std::string>> rows;
        std::ifstream is(file);
        std::string line;
        while (std::getline(is, line))
        {
            std::istringstream ls(line);
            List<std::string> words;
            std::string w;
            while (ls >> w) words.append(w);
            if (!words.empty() && words[0] == key) rows.append(words);
        }
        return rows;
    }
}


TEST(sphCompareCavityTutorial, allrunAndSweepGiveProfilesErrorsAndRunTimes)
{
    const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"cavityTutorial";
    const std::string source = std::string(SPHFOAM_SOURCE_DIR);
    rmDir(dir);
    mkDir(dir);
    std::string out;
    ASSERT_EQ
    (
        sphTest::run
        (
            "cd " + source + "/tutorials/cavity && cp -r Allrun Allclean compare"
            " sweep cavityFunctions fv sph " + dir,
            out
        ),
        0
    ) << out;

    // As the README says: source etc/bashrc from the project folder
    const std::string env =
        "cd " + source + " && unset SPHFOAM_PROJECT_DIR && . ./etc/bashrc && ";
    ASSERT_EQ(sphTest::run(env + dir + "/Allrun -test -fv", out), 0) << out;

    // Both runs reached steady state
    for (const char* n : {"16", "32"})
    {
        std::string log;
        sphTest::run("cat " + dir + "/runs/Re100/fv" + n + "/log.icoFoam", log);
        EXPECT_NE(log.find("condition satisfied"), std::string::npos) << n;
    }

    for (const char* png : {"Re100_n16_velocity.png", "Re100_n16_pressure.png"})
    {
        EXPECT_TRUE(isFile(dir/"results"/png)) << png << "\n" << out;
    }

    // method n max|du| max|dv| L2(66) L2(p) clock cpu tEnd
    const List<List<std::string>> fv = rowsOf(dir/"results"/"Re100_n16.dat", "FV");
    ASSERT_EQ(fv.size(), 1) << out;
    ASSERT_EQ(fv[0].size(), 9);
    EXPECT_LT(std::stod(fv[0][2]), 0.04);
    EXPECT_LT(std::stod(fv[0][3]), 0.04);
    EXPECT_GT(std::stod(fv[0][4]), 1e-3);
    EXPECT_LT(std::stod(fv[0][4]), 0.04);
    EXPECT_GE(std::stod(fv[0][7]), 0);                  // CPU seconds
    EXPECT_GT(std::stod(fv[0][8]), 5);                  // steady time
    EXPECT_LT(std::stod(fv[0][8]), 50);

    // The sweep reuses both runs (no icoFoam again) and says why it has no
    // SPH side
    ASSERT_EQ(sphTest::run(env + dir + "/sweep -Re 100 -fv '16 32' -sph 16", out), 0) << out;
    EXPECT_NE(out.find("icoFoam already run"), std::string::npos) << out;
    EXPECT_NE(out.find("isphFoam is not on PATH"), std::string::npos) << out;
    const List<List<std::string>> sweep = rowsOf(dir/"results"/"sweep_Re100.dat", "FV");
    ASSERT_EQ(sweep.size(), 2) << out;
    EXPECT_EQ(sweep[0][1], "16");
    EXPECT_EQ(sweep[0][2], "256");
    // The same L2 as Allrun's table (written to 4 figures there)
    EXPECT_NEAR(std::stod(sweep[0][3]), std::stod(fv[0][4]), 1e-3*std::stod(fv[0][4]));
    EXPECT_EQ(std::stod(sweep[1][3]), 0);               // the reference itself
    EXPECT_TRUE(isFile(dir/"results"/"sweep_Re100.png"));
}


// ************************************************************************* //
