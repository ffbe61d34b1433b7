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
      30 % of 0.406: at n = 5 the window is 10 dr wide and the front's
      crossings of it move with any change, maxCo 0.18, 0.19, 0.21, 0.22,
      0.25 giving 0.332, 0.421, 0.518, 0.421, 0.381 (the heavy front's
      X(10) 6.38, 6.61, 7.14, 6.76, 6.15 L);
    - the heavy front's distance from the lock at t+ = 5 and 10: measured
      3.51 L and 6.85 L (FV at n = 5: 2.41 L and 4.92 L; the SPH current
      leaves the lock faster at every n, see the README), checked to 10 %
      of those figures.
    Without the buoyancy the fluid stays at rest and no front forms
    (front.dat has no SPH row).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particleFields.H"

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

    //- The tutorial without its runs and results, in tests/cases/<name>
    fileName lockExchangeCopy(const std::string& name)
    {
        const fileName dir =
            fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"heatTransfer"/name;
        const std::string src =
            std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/heatTransfer";
        std::string out;
        rmDir(dir);
        mkDir(dir);
        EXPECT_EQ
        (
            sphTest::run
            (
                "tar -C " + src + " --exclude=runs --exclude=results"
                " --exclude='log.*' -cf - lockExchange | tar -C " + dir
              + " --strip-components=1 -xf -",
                out
            ),
            0
        ) << out;
        return dir;
    }
}


TEST(lockExchangeTutorial, sphFrontFroudeNumberSymmetricAndNearHaertel)
{
    const fileName dir = lockExchangeCopy("lockExchange");
    std::string out;
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
    EXPECT_NEAR(0.5*(frHeavy + frLight), frRef, 0.3*frRef) << "mean Fr";

    EXPECT_NEAR(std::stod(sph[9]), 3.51, 0.351) << "heavy front at t+ = 5";
    EXPECT_NEAR(std::stod(sph[10]), 6.85, 0.685) << "heavy front at t+ = 10";
    // FV ran too (the front.dat row is there): its fronts are its own
    // tests' (heatTransferFv)
    EXPECT_GT(std::stod(fv[9]), 0);
}


TEST(lockExchangeTutorial, implicitViscosityKeepsThePointSymmetry)
{
    // The set-up is symmetric under the half-turn about the box's centre
    // (x -> 30 L - x, y -> 2 L - y, T -> Th + Tc - T, u -> -u), and the
    // explicit viscous step keeps |u_a + u_mirror(a)| at 1e-9 of max |u|.
    // The implicit step solves on u* + dt a^n, a^n the last pressure's
    // acceleration g - G{p}/rho (implicitViscousPrediction.H). Taken from
    // the user's p = 0 at the first step, a^n was g, which the end walls'
    // friction damped as if it were a velocity: 0.9 % of max |u| after
    // one step. Taken again at the start of each step at the moved
    // positions, G{p} read the hydrostatic part over the particles'
    // relative displacement: 1.7e-4 of max |u| at t+ = 2. The projection's
    // own, carried by the particles (and zero at the first step): 1e-9.
    // Checked at t+ = 2 (about 20 steps, the particles renumbered once) to
    // 1e-7 of max |u|.
    const fileName dir = lockExchangeCopy("lockExchangeImplicit");
    std::string out;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test -sph", out), 0)
        << out;

    // The run's initial state (the lock set), to t+ = 2 with
    // viscousScheme implicit
    const fileName c = dir/"runs"/"implicit";
    ASSERT_EQ
    (
        sphTest::run
        (
            "mkdir -p " + c + " && cp -r " + dir/"runs"/"sph5"/"0" + " "
          + dir/"runs"/"sph5"/"constant" + " " + dir/"runs"/"sph5"/"system"
          + " " + c + " && cd " + c + " && sed -i"
            " -e 's/^viscousScheme .*/viscousScheme implicit;/'"
            " system/sphSchemes && sed -i"
            " -e 's/^endTime .*/endTime 2;/'"
            " -e 's/^writeInterval .*/writeInterval 2;/'"
            " system/controlDict && sed -i '/^solvers/,/^{/ s/^{/{\\n"
            "    U { solver BiCGStab; preconditioner ILU0; tolerance 1e-12;"
            " relTol 0; }/' system/sphSolution",
            out
        ),
        0
    ) << out;
    ASSERT_EQ
    (
        sphTest::run
        (
            std::string(SPHFOAM_BINARY_DIR) + "/applications/isphFoam -case "
          + c,
            out
        ),
        0
    ) << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
    ASSERT_NE(out.find("implicit (backward Euler)"), std::string::npos);
    // a^n is written with the time, for a restart
    EXPECT_TRUE
    (
        isFile(c/"2"/SPH::particles::defaultLocal/"pressureAcceleration")
    );

    auto runTime = sphTest::makeTime(c);
    const sphTest::particleFields s = sphTest::readParticles(*runTime, "2");
    const List<vector2D>& x = s.x;
    const List<vector2D>& U = s.U;
    const labelList& type = s.type;

    // The mirror of each fluid particle (its nearest to the turned point)
    const vector2D centre(15, 1);
    scalar uMax = 0, asymmetry = 0, worstMatch = 0;
    label nFluid = 0;
    forAll(x, a)
    {
        if (type[a] != 0) continue;
        ++nFluid;
        const vector2D turned(2*centre - x[a]);
        label m = -1;
        scalar best = GREAT;
        forAll(x, b)
        {
            if (type[b] == 0 && magSqr(x[b] - turned) < best)
            {
                best = magSqr(x[b] - turned);
                m = b;
            }
        }
        worstMatch = max(worstMatch, std::sqrt(best));
        uMax = max(uMax, mag(U[a]));
        asymmetry = max(asymmetry, mag(U[a] + U[m]));
    }
    std::cout << "    lock exchange, n = 5, t+ = 2, implicit viscosity: max |u + u_mirror| "
        << asymmetry << " (" << asymmetry/uMax << " of max |u| " << uMax
        << "), positions mirrored to " << worstMatch << std::endl;
    EXPECT_EQ(nFluid, 1341);      // 149 x 9
    EXPECT_LT(worstMatch, 1e-6);
    EXPECT_GT(uMax, 1e-2);
    EXPECT_LT(asymmetry, 1e-7*uMax);
}


// ************************************************************************* //
