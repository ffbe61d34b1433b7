/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The lock-exchange tutorial (Leroy et al. 2015, section 4.4; Haertel et
    al. 2000, no-slip, Gr 1.25e6, Pr 1) as a user runs it: Allrun -test
    runs buoyantBoussinesqPimpleFoam and isphFoam (pressureGradient
    symmetric, the paper's figure 13) at n = 5 particles per half-height
    (145 x 9 fluid particles) to t+ = 10, and compare writes the fronts and
    the front Froude numbers (results/front.dat).

    Tolerances (measured figures of the coarse n = 5 run; the tutorial's
    README has the finer ones):
    - the isphFoam log names the symmetric gradient of the dynamic
      pressure (sphSchemes pressureGradient symmetric, confined);
    - the heavy and light fronts' Froude numbers agree to 1 % (the set-up
      is symmetric under x -> 30 L - x, y -> 2 L - y, T -> Th + Tc - T):
      measured 0.4031 both. G{p} - rho g instead of the dynamic pressure's
      gradient broke the symmetry (0.356 against 0.385);
    - the mean front Froude number over 4 L <= X <= 6 L: measured 0.4031,
      -0.7 % off Haertel et al.'s 0.406 (FV at n = 5: 0.361), checked to
      10 % of 0.406;
    - the heavy front's distance from the lock at t+ = 5 and 10: measured
      3.51 L and 6.85 L (FV at n = 5: 2.41 L and 4.92 L; the SPH current
      leaves the lock faster at every n, see the README), checked to 10 %
      of those figures.
    Without the buoyancy the fluid stays at rest and no front forms
    (front.dat has no SPH row).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <cmath>
#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    //- The whole of a file
    std::string slurp(const fileName& file)
    {
        std::ifstream is(file);
        std::stringstream ss;
        ss << is.rdbuf();
        return ss.str();
    }
}


TEST(lockExchangeTutorial, sphFrontFroudeNumberSymmetricAndNearHaertel)
{
    // The tutorial without its runs and results
    const fileName dir =
        fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"heatTransfer"/"lockExchange";
    const std::string src =
        std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/heatTransfer";
    std::string out;
    rmDir(dir);
    mkDir(dir.path());
    ASSERT_EQ
    (
        sphTest::run
        (
            "tar -C " + src + " --exclude=runs --exclude=results --exclude='log.*'"
            " -cf - lockExchange | tar -C " + dir.path()
          + " -xf -",
            out
        ),
        0
    ) << out;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test", out), 0) << out;

    // The solver's description of its projection
    const std::string log = slurp(dir/"runs"/"sph5"/"log.isphFoam");
    EXPECT_NE(log.find("pressureGradient symmetric) of the dynamic pressure"),
              std::string::npos) << log.substr(0, 4000);

    // front.dat: method n cells cpu Uheavy FrHeavy Ulight FrLight FrErr
    // X5 X10 X15 X20 Fr5_20
    const std::vector<std::string> sph =
        sphTest::tableRow(dir/"results"/"front.dat", {"sph", "5"});
    const std::vector<std::string> fv =
        sphTest::tableRow(dir/"results"/"front.dat", {"fv", "5"});
    ASSERT_EQ(sph.size(), 14u) << slurp(dir/"results"/"front.dat") << out;
    ASSERT_EQ(fv.size(), 14u) << slurp(dir/"results"/"front.dat") << out;

    const double frHeavy = std::stod(sph[5]), frLight = std::stod(sph[7]);
    const double frRef = 0.406;
    EXPECT_NEAR(frHeavy, frLight, 0.01*frLight) << "front symmetry";
    EXPECT_NEAR(0.5*(frHeavy + frLight), frRef, 0.1*frRef) << "mean Fr";

    EXPECT_NEAR(std::stod(sph[9]), 3.51, 0.351) << "heavy front at t+ = 5";
    EXPECT_NEAR(std::stod(sph[10]), 6.85, 0.685) << "heavy front at t+ = 10";
    // FV ran too (the front.dat row is there): its fronts are its own
    // tests' (heatTransferFv)
    EXPECT_GT(std::stod(fv[9]), 0);
}


// ************************************************************************* //
