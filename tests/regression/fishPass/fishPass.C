/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The fish-pass tutorial (Leroy et al. 2014 section 5.2) as a user runs
    it: Allrun -test runs pimpleFoam (kEpsilon, wall functions, cyclic in
    x, the body force 1.885 m/s^2 of a vectorSemiImplicitSource) on 6
    cells per slot width and isphFoam (ISPH-USAW, the same 0/,
    turbulenceProperties and fvOptions, walls from the same blockMeshDict
    by sphMesh -fromPolyMesh) at dr = b/6 = 0.05 m, both from rest to
    t = 1 s, and compare writes runs/test/results/runs.dat and
    differences.dat. (wcsphFoam runs too once it has the RAS model; until
    then Allrun reports its refusal and goes on.)

    Tolerances, measured 2026-12-07 on the 45-degree slot (tutorial README;
    on the 1:2 slot before it, 2026-12-02: slot FV 2.69, ISPH 3.15 m/s,
    P1 max 11 %, P3 mean 5.6 %):
    - the mean velocity along the slot, U . (1,1)/sqrt(2) across it at
      x = 8.5 b: FV 2.58 m/s, ISPH 2.95 m/s (+14 %); checked to 25 %, and
      above 1.5 m/s for both (a flow that does not start, or a slot that
      the particles cannot pass, fails);
    - no particle lost (fluid particles of the first and the last file
      equal), k and epsilon positive and finite on every particle;
    - |U| along P1 (2 b behind the slot): max difference to FV 20 % of
      FV's peak (the jet, still turning into the pool at 1 s, a fraction
      of b apart), mean 4.5 %; checked to 30 % and 10 %; along P3 the mean
      7.5 %, checked to 10 %.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

using namespace Foam;

namespace
{
    //- max and mean |U| difference of ISPH to FV along a section
    std::pair<double, double> umagDifference
    (
        const fileName& diffs,
        const std::string& section
    )
    {
        // method dr vs section quantity max mean bins
        const std::vector<std::string> row =
            sphTest::tableRow(diffs, {"ISPH", "0.05", "FV_nb6", section, "Umag"});
        if (row.size() != 8u) return {1e9, 1e9};
        return {std::stod(row[5]), std::stod(row[6])};
    }
}


TEST(fishPassTutorial, isphKEpsilonFollowsFvThroughTheSlot)
{
    const fileName dir = sphTest::copyTutorial("turbulence/fishPass", "fishPass");
    sphTest::run("rm -rf " + dir + "/runs " + dir + "/results");
    std::string out;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun -test", out), 0) << out;

    // method size first last steps CPU clock t Uslot kMin epsMin finite
    const fileName results = dir/"runs"/"test"/"results";
    const std::vector<std::string> fv =
        sphTest::tableRow(results/"runs.dat", {"FV", "0.05"});
    const std::vector<std::string> sph =
        sphTest::tableRow(results/"runs.dat", {"ISPH", "0.05"});
    ASSERT_EQ(fv.size(), 12u) << out;
    ASSERT_EQ(sph.size(), 12u) << out;

    EXPECT_EQ(fv[7], "1");
    EXPECT_EQ(sph[7], "1");
    const double uFv = std::stod(fv[8]);
    const double uSph = std::stod(sph[8]);
    EXPECT_GT(uFv, 1.5);
    EXPECT_GT(uSph, 1.5);
    EXPECT_LT(std::abs(uSph/uFv - 1), 0.25) << "slot: FV " << uFv << ", ISPH " << uSph;

    // No particle lost, k and epsilon positive and finite
    EXPECT_EQ(sph[2], sph[3]);
    EXPECT_GT(std::stoi(sph[2]), 2000);
    EXPECT_GT(std::stod(sph[9]), 0.0);
    EXPECT_GT(std::stod(sph[10]), 0.0);
    EXPECT_EQ(sph[11], "yes");
    EXPECT_GT(std::stod(fv[9]), 0.0);
    EXPECT_GT(std::stod(fv[10]), 0.0);

    const fileName diffs = results/"differences.dat";
    EXPECT_LT(umagDifference(diffs, "P1").first, 0.30);
    EXPECT_LT(umagDifference(diffs, "P1").second, 0.10);
    EXPECT_LT(umagDifference(diffs, "P3").second, 0.10);

    EXPECT_TRUE(isFile(results/"sections_Umag.png"));
    EXPECT_TRUE(isFile(results/"velocity_isph_dr0.05.png"));
}


// ************************************************************************* //
