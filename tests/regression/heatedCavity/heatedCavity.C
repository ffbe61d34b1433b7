/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The differentially heated cavity tutorial (Leroy et al. 2015, section
    4.2; de Vahl Davis 1983) as a user runs it: Allrun -test runs
    buoyantBoussinesqSimpleFoam at 16^2 and 32^2 and isphFoam at 16^2
    (225 fluid particles) at Ra 1e3 and 1e5 to steady state, and compare
    writes the mean Nu, the velocity maxima and the profile errors.

    Tolerances (measured figures of the SPH runs at the coarse 16^2 of the
    test). The profiles are sphCompare's (sph/system/sphCompareDict:
    quadratic moving least squares over the kernel, fluid and wall
    vertices) at each of the 11 written times of the run's last half
    (checked), averaged by compare with the maxima and Nu: one snapshot
    scatters as the particles move past the lines (v+max at Ra 1e5 went
    from 62.2 to 67.9 over the last ten snapshots of one run).
    - Ra 1e3: mean Nu on the cold wall (compare's least-squares fit)
      1.119 against de Vahl Davis' 1.117 (+0.2 %), checked to 3 %; u+max
      3.663 and v+max 3.716 against 3.649 and 3.697 (+0.4 %, +0.5 %),
      checked to 5 %; T on the centrelines 3.9e-3 off FV 32^2, checked
      to 1e-2 (a Shepard average, one-sided by the walls, read 2.6e-2).
    - Ra 1e5 (16^2 is 2-3 particles across its boundary layers): mean Nu
      4.90 against 4.509 (+8.7 %), checked to 15 %; u+max 31.8 against
      34.73 (-8.5 %), checked to 20 %; v+max 53.3 against 68.59 (-22 %:
      its peak lies one spacing from the wall; a linear fit over 2 dr
      read 80.7, a Shepard average 63.7-65.7), checked to 30 %; T 2.1e-2
      off FV 32^2 (Shepard: 9-11e-2), checked to 5e-2. Without the
      buoyancy the fluid stays at rest (u+ = 0, Nu = 1), which fails all
      of them.
    - The wallNusselt function object (Leroy et al. 2015, eq. (42)) on the
      cold wall, its mean over the last half of the run (its default
      renormalised gradient; the paper's G-: 1.189 and 3.92): 1.167 at
      Ra 1e3 (+4.5 %), checked to 10 % of 1.117; 3.84 at Ra 1e5 (-15 %,
      the boundary layer on 2-3 particles), checked to 20 % of 4.509.

    With heatScheme implicit and viscousScheme implicit (as a user sets
    them in sph/system/sphSchemes), Ra 1e3 at 16^2 runs at the flow's
    time step: 217 steps where the explicit heat bound 0.125 h^2/kappa
    takes 768, checked below 0.4 of it. Measured u+max 3.543 (-2.9 %)
    and v+max 3.563 (-3.6 %), checked to 8 % and 10 %; mean Nu 1.181
    (+5.8 %: the first-order time error of steps 3.5 times longer, which
    the explicit run does not have), checked to 12 %. When the vertex
    particles lost the force's dt f in their u* under the implicit
    viscous step (eq. (45) of Leroy et al. 2014 keeps it), u+max read
    4.106 (+12.5 %) and v+max 3.021 (-18 %).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <cmath>
#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    //- The words of the first row of file whose first words are key
    std::vector<std::string> rowOf
    (
        const fileName& file,
        const std::vector<std::string>& key
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
            if (w.size() < key.size() + 4) continue;
            bool match = true;
            for (size_t k = 0; k < key.size(); ++k)
            {
                match = match && w[k] == key[k];
            }
            if (match) return w;
        }
        return {};
    }

    //- The mean of a wallNusselt.dat's patch averages over the last half
    //- of its times
    double lateNusselt(const fileName& file)
    {
        std::ifstream is(file);
        std::string line;
        std::vector<std::pair<double, double>> rows;
        while (std::getline(is, line))
        {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream ls(line);
            std::string patch;
            double t = 0, mn = 0, mx = 0, integral = 0, average = 0;
            if (ls >> t >> patch >> mn >> mx >> integral >> average)
            {
                rows.emplace_back(t, average);
            }
        }
        if (rows.empty()) return -1;
        const double tFrom = 0.5*rows.back().first;
        double sum = 0;
        int count = 0;
        for (const auto& row : rows)
        {
            if (row.first >= tFrom) { sum += row.second; ++count; }
        }
        return sum/count;
    }

    struct expected
    {
        std::string Ra;
        double Nu, NuTol, u, uTol, v, vTol, eT, NuWall, NuWallTol;
    };
}


TEST(heatedCavityTutorial, sphNusseltMaximaAndProfilesAgainstDeVahlDavis)
{
    const fileName dir = sphTest::copyTutorial
    (
        "heatTransfer/heatedCavity", "heatTransfer/heatedCavity"
    );
    std::string out;
    sphTest::run
    (
        "rm -rf " + dir + "/runs " + dir + "/results",
        out
    );
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test", out), 0) << out;

    // summary.dat: Ra method n cpu Nu NuDVD NuMeanDVD umax uDVD vmax vDVD;
    // Ra<R>.dat: method n cells iter cpu NuCold NuHot NuSnGrad umax y vmax
    // x eU eV eT eNu
    const std::vector<expected> cases
    {
        {"1e3", 1.117, 0.03, 3.649, 0.05, 3.697, 0.05, 0.01, 1.117, 0.10},
        {"1e5", 4.509, 0.15, 34.73, 0.20, 68.59, 0.30, 0.05, 4.509, 0.20}
    };
    for (const expected& e : cases)
    {
        const std::vector<std::string> s =
            rowOf(dir/"results"/"summary.dat", {e.Ra, "sph", "16"});
        const std::vector<std::string> t =
            rowOf(dir/"results"/("Ra" + e.Ra + ".dat"), {"sph", "16"});
        ASSERT_EQ(s.size(), 11u) << "Ra " << e.Ra << nl << out;
        ASSERT_EQ(t.size(), 16u) << "Ra " << e.Ra << nl << out;
        EXPECT_NEAR(std::stod(s[4]), e.Nu, e.NuTol*e.Nu) << "mean Nu, Ra " << e.Ra;
        EXPECT_NEAR(std::stod(s[7]), e.u, e.uTol*e.u) << "u+max, Ra " << e.Ra;
        EXPECT_NEAR(std::stod(s[9]), e.v, e.vTol*e.v) << "v+max, Ra " << e.Ra;
        EXPECT_LT(std::stod(t[14]), e.eT) << "T profiles, Ra " << e.Ra;
        EXPECT_EQ
        (
            readDir
            (
                dir/"runs"/("Ra" + e.Ra)/"sph16"/"postProcessing"/"sphCompare",
                fileName::DIRECTORY
            ).size(),
            11
        ) << "sphCompare at the written times of the last half, Ra " << e.Ra;

        const double NuWall = lateNusselt
        (
            dir/"runs"/("Ra" + e.Ra)/"sph16"/"postProcessing"/"Nusselt"/"0"
           /"wallNusselt.dat"
        );
        EXPECT_NEAR(NuWall, e.NuWall, e.NuWallTol*e.NuWall)
            << "wallNusselt, Ra " << e.Ra;
    }
}


TEST(heatedCavityTutorial, implicitDiffusionAtTheFlowsTimeStep)
{
    const fileName dir = sphTest::copyTutorial
    (
        "heatTransfer/heatedCavity", "heatTransfer/heatedCavityImplicit"
    );
    std::string out;
    sphTest::run
    (
        "rm -rf " + dir + "/runs " + dir + "/results && sed -i"
        " -e 's/^viscousScheme .*/viscousScheme implicit;/'"
        " -e 's/^heatScheme .*/heatScheme implicit;/' "
      + dir + "/sph/system/sphSchemes",
        out
    );
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test -Ra 1e3", out), 0)
        << out;
    const fileName log = dir/"runs"/"Ra1e3"/"sph16"/"log.isphFoam";
    std::string steps;
    sphTest::run("sed -n 's/^Steps \\([0-9]*\\),.*/\\1/p' " + log, steps);
    ASSERT_FALSE(steps.empty()) << "no Steps line in " << log;

    // kappa = sqrt(Pr/Ra)/Pr, h = 2/16, tEnd = 40 (controlDict at Ra 1e3)
    const double kappa = std::sqrt(0.71/1e3)/0.71, h = 2.0/16;
    const double explicitSteps = 40/(0.125*h*h/kappa);
    EXPECT_LT(std::stod(steps), 0.4*explicitSteps);

    const std::vector<std::string> s =
        rowOf(dir/"results"/"summary.dat", {"1e3", "sph", "16"});
    ASSERT_EQ(s.size(), 11u) << out;
    EXPECT_NEAR(std::stod(s[4]), 1.117, 0.12*1.117) << "mean Nu";
    EXPECT_NEAR(std::stod(s[7]), 3.649, 0.08*3.649) << "u+max";
    EXPECT_NEAR(std::stod(s[9]), 3.697, 0.10*3.697) << "v+max";
}


// ************************************************************************* //
