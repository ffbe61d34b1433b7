/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Restarts are exact to the bit under every writeControl (timeStep,
    runTime, adjustable) for both solvers: a run writes its times, a copy
    keeps those up to the middle one and restarts from it, and every later
    time directory comes back byte for byte (sphTest::
    expectRestartsReproduce). With runTime and an adjustable time step the
    time directories have names rounded to six digits (0.130417), which is
    the clock OpenFOAM itself would restart from; the exact time, the write
    grid and the step history are in uniform/<solver>State.

    Cases: the ISPH-USAW cavity with ILU0 and with BoomerAMG, the periodic
    Poiseuille flow of both solvers (meanVelocityForce), and the Zhou
    dam-break (WCSPH) at 12 particles per H; and both solvers with the
    fluid particles sorted by cell (particleSortInterval) every 3 (ISPH)
    or 7 (WCSPH) steps between the writes, the leapfrog's rates carried
    across the sorts.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "restartCheck.H"

using namespace Foam;
using sphTest::run;
using sphTest::setEntry;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";
    const std::string source = std::string(SPHFOAM_SOURCE_DIR);

    //- A copy of a case under the build's tests/cases
    fileName copyCase(const std::string& from, const std::string& name)
    {
        const fileName dir =
            fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/sphTest::perTest(name);
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        EXPECT_EQ(run("cp -r " + from + " " + dir, out), 0) << out;
        return dir;
    }

    void mesh(const fileName& dir)
    {
        std::string out;
        ASSERT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
    }

    //- How the case writes: writeControl and writeInterval
    void writes
    (
        const fileName& dir,
        const std::string& control,
        const std::string& interval
    )
    {
        setEntry(dir/"system"/"controlDict", "writeControl", control);
        setEntry(dir/"system"/"controlDict", "writeInterval", interval);
    }

    fileName cavity(const std::string& name)
    {
        const fileName dir =
            copyCase(source + "/tests/regression/isphFoam/cavity", name);
        setEntry(dir/"system"/"sphMeshDict", "n", "20");
        setEntry(dir/"system"/"controlDict", "endTime", "0.6");
        mesh(dir);
        return dir;
    }

    fileName zhou(const std::string& name)
    {
        const fileName dir =
            copyCase(source + "/tutorials/damBreak/zhou", name);
        setEntry(dir/"system"/"sphMeshDict", "resolution", "12");
        setEntry(dir/"system"/"controlDict", "endTime", "0.2");
        mesh(dir);
        return dir;
    }

    fileName poiseuille(const std::string& templ, const std::string& name)
    {
        const std::string tutorial = source + "/tutorials/periodic/poiseuille/";
        const fileName dir = copyCase(tutorial + templ, name);
        std::string out;
        EXPECT_EQ
        (
            run("cp " + tutorial + "fv/system/poiseuilleParameters " + dir/"system", out),
            0
        ) << out;
        setEntry(dir/"system"/"poiseuilleParameters", "n", "10");
        setEntry(dir/"system"/"poiseuilleParameters", "force", "meanVelocity");
        setEntry(dir/"system"/"controlDict", "endTime", "1");
        mesh(dir);
        return dir;
    }
}


TEST(restartExact, isphCavityUnderEveryWriteControl)
{
    // 20^2, ILU0-preconditioned BiCGStab, adjustable time step
    for
    (
        const auto& w : std::vector<std::pair<std::string, std::string>>
        {{"timeStep", "2"}, {"runTime", "0.13"}, {"adjustable", "0.13"}}
    )
    {
        SCOPED_TRACE(w.first);
        const fileName dir = cavity("restartCavity_" + w.first);
        writes(dir, w.first, w.second);
        EXPECT_NE(sphTest::expectRestartsReproduce("isphFoam", dir), "");
    }
}


TEST(restartExact, isphCavityWithBoomerAMG)
{
    const fileName dir = cavity("restartCavityAMG");
    std::string out;
    run
    (
        "sed -i 's/^        preconditioner .*/        preconditioner  BoomerAMG;"
        " reuse 10;/' " + dir/"system"/"sphSolution", out
    );
    writes(dir, "adjustable", "0.13");
    EXPECT_NE(sphTest::expectRestartsReproduce("isphFoam", dir), "");
}


TEST(restartExact, periodicPoiseuilleOfBothSolvers)
{
    for (const std::string& app : {"isphFoam", "wcsphFoam"})
    {
        SCOPED_TRACE(app);
        const fileName dir = poiseuille
        (
            app == "isphFoam" ? "sph" : "wcsph", "restartPoiseuille_" + app
        );
        writes(dir, "adjustable", "0.23");
        EXPECT_NE(sphTest::expectRestartsReproduce(app, dir), "");
    }
}


TEST(restartExact, wcsphZhouUnderEveryWriteControl)
{
    for
    (
        const auto& w : std::vector<std::pair<std::string, std::string>>
        {{"timeStep", "37"}, {"runTime", "0.047"}, {"adjustable", "0.047"}}
    )
    {
        SCOPED_TRACE(w.first);
        const fileName dir = zhou("restartZhou_" + w.first);
        writes(dir, w.first, w.second);
        EXPECT_NE(sphTest::expectRestartsReproduce("wcsphFoam", dir), "");
    }
}


// ************************************************************************* //


TEST(restartExact, particlesSortedByCellBetweenWrites)
{
    {
        SCOPED_TRACE("isphFoam, BoomerAMG");
        const fileName dir = cavity("restartCavitySorted");
        std::string out;
        run
        (
            "sed -i 's/^        preconditioner .*/        preconditioner  BoomerAMG;"
            " reuse 10;/' " + dir/"system"/"sphSolution", out
        );
        setEntry(dir/"system"/"sphSchemes", "particleSortInterval", "3");
        writes(dir, "timeStep", "2");
        EXPECT_NE(sphTest::expectRestartsReproduce("isphFoam", dir), "");
    }
    {
        SCOPED_TRACE("wcsphFoam, leapfrog");
        const fileName dir = zhou("restartZhouSorted");
        setEntry(dir/"system"/"sphSchemes", "timeScheme", "leapfrog");
        setEntry(dir/"system"/"sphSchemes", "particleSortInterval", "7");
        writes(dir, "timeStep", "37");
        EXPECT_NE(sphTest::expectRestartsReproduce("wcsphFoam", dir), "");
    }
}
