/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The lid-driven cavity tutorial with WCSPH-USAW beside ISPH-USAW and
    icoFoam, as a user runs it (Allrun -test -wcsph: Re 100, 16^2 particles
    and cells, the FV reference at 32^2, each to the FV steady time): one
    Allrun gives the three rows of the table and the pictures.

    Figures: at 16^2 WCSPH-USAW (c0 = 10 U, background pressure b0) was
    measured at max |u - u_Ghia| = 0.064 U, max |v - v_Ghia| = 0.089 U and
    L2 (66) = 0.060 against FV 32^2 (ISPH-USAW: 0.055, 0.049 and 0.051).
    The bounds, 0.1 U from Ghia and L2 below 0.2, are those of a flow that
    has the cavity's vortex at 16 particles a side: without the moving lid
    (the wall model's sliding-wall velocity) the centrelines are zero, an
    error of 0.2 to 1 U; without the background pressure cavities open.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    //- The words of the first row of a results table starting with key
    std::vector<std::string> rowOf(const fileName& file, const std::string& key)
    {
        std::ifstream is(file);
        std::string line;
        while (std::getline(is, line))
        {
            std::istringstream ls(line);
            std::vector<std::string> words;
            std::string w;
            while (ls >> w) words.push_back(w);
            if (!words.empty() && words[0] == key) return words;
        }
        return {};
    }
}


TEST(cavityTutorialWcsph, oneAllrunGivesWcsphUsawBesideIsphAndFv)
{
    const fileName dir = sphTest::copyTutorial("cavity", "cavityWcsph");
    std::string out;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test -wcsph", out), 0) << out;

    const fileName table = dir/"results"/"Re100_n16.dat";
    // method n max|du| max|dv| L2(66) L2(p) clock cpu tEnd
    for (const char* method : {"FV", "SPH", "WCSPH"})
    {
        EXPECT_EQ(rowOf(table, method).size(), 9u) << method << "\n" << out;
    }
    const std::vector<std::string> wc = rowOf(table, "WCSPH");
    ASSERT_EQ(wc.size(), 9u);
    EXPECT_LT(std::stod(wc[2]), 0.1);
    EXPECT_LT(std::stod(wc[3]), 0.1);
    EXPECT_LT(std::stod(wc[4]), 0.2);
    EXPECT_GT(std::stod(wc[4]), 1e-3);
    EXPECT_GT(std::stod(wc[7]), 0);                 // CPU seconds

    std::string log;
    sphTest::run("cat " + dir + "/runs/Re100/wcsph16/log.wcsphFoam", log);
    EXPECT_NE(log.find("Selecting wall model usaw"), std::string::npos);
    EXPECT_NE(log.find("End"), std::string::npos);
    for (const char* png : {"Re100_n16_velocity.png", "Re100_n16_pressure.png"})
    {
        EXPECT_TRUE(isFile(dir/"results"/png)) << png;
    }
}


// ************************************************************************* //
