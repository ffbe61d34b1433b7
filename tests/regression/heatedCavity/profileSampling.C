/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    How the heated cavities' compare scripts read particles onto their
    centrelines (bin/tools/python/heatTransferData.py): linear_mls, the
    linear moving least squares, is exact for a linear field on a lattice
    cut by a wall, up to the wall, where the Shepard average's support is
    one-sided. On the square lattice of spacing 0.05 filling the unit
    square, f = 3 + 2x - y sampled along y = 1/2 from x = 0 to 1 with
    radius 2 dr: measured 8.9e-15 (checked below 1e-12), where shepard is
    5.2e-2 off at the walls (checked above 1e-2, so that the check on
    linear_mls can fail). A vector field is read component by component,
    and a sample with no particle within the radius reads nan.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <sstream>

using namespace Foam;

TEST(profileSampling, linearMlsIsExactForALinearFieldUpToTheWalls)
{
    const std::string script =
        "import sys, numpy as np\n"
        "sys.path.insert(0, '" + std::string(SPHFOAM_SOURCE_DIR)
      + "/bin/tools/python')\n"
        "import heatTransferData as htd\n"
        "dx = 0.05\n"
        "g = np.arange(0.5*dx, 1, dx)\n"
        "X, Y = np.meshgrid(g, g)\n"
        "P = np.column_stack((X.ravel(), Y.ravel()))\n"
        "f = 3 + 2*P[:, 0] - P[:, 1]\n"
        "S = np.column_stack((np.linspace(0, 1, 41), np.full(41, 0.5)))\n"
        "exact = 3 + 2*S[:, 0] - 0.5\n"
        "mls = htd.linear_mls(P, f, S, 2*dx)\n"
        "vec = htd.linear_mls(P, np.column_stack((f, -f)), S, 2*dx)\n"
        "far = htd.linear_mls(P, f, np.array([[5.0, 5.0]]), 2*dx)\n"
        "print(np.abs(mls - exact).max(),"
        " np.abs(htd.shepard(P, f, S, 2*dx) - exact).max(),"
        " np.abs(vec[:, 0] - mls).max() + np.abs(vec[:, 1] + mls).max(),"
        " int(np.isnan(far[0])))\n";
    const fileName file = sphTest::makeCase("profileSampling")/"check.py";
    sphTest::writeFile(file, script);
    std::string out;
    ASSERT_EQ(sphTest::run(std::string(SPHFOAM_PYTHON) + " " + file, out), 0)
        << out;

    std::istringstream is(out);
    double mls = -1, shepard = -1, vector = -1;
    int farIsNan = 0;
    is >> mls >> shepard >> vector >> farIsNan;
    ASSERT_FALSE(is.fail()) << out;
    EXPECT_LT(mls, 1e-12);
    EXPECT_GT(shepard, 1e-2);
    EXPECT_LT(vector, 1e-12);
    EXPECT_EQ(farIsNan, 1);
}


// ************************************************************************* //
