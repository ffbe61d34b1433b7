/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The bad inputs of issue 12 that made the solvers hang, crash or carry
    on: each now stops at once with exit code 1 and a message naming the
    file and the entry (or, for the restart fields, the file and the
    particle); none with a signal, a timeout or a stack trace.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "solverCase.H"

#include <cmath>

using namespace Foam;
using sphTest::run;

namespace
{
    //- Run the solver on the tank after a shell edit in the case folder
    sphTest::solverRun runEdited
    (
        const std::string& solver,
        const std::string& name,
        const std::string& edit
    )
    {
        const fileName dir = sphTest::tankCase(solver, "inputs." + solver + "." + name);
        std::string out;
        run("cd " + dir + " && " + edit, out);
        return sphTest::runSolver(solver + "Foam", dir);
    }

    std::string set(const std::string& key, const std::string& value)
    {
        return "sed -i 's/^" + key + " .*/" + key + " " + value + ";/' system/controlDict";
    }

    //- Exit code 1, the message, and no crash
    void expectError(const sphTest::solverRun& r, const std::vector<std::string>& has)
    {
        EXPECT_EQ(r.status, 1) << r.tail();
        EXPECT_FALSE(r.stackTrace()) << r.tail();
        for (const std::string& s : has)
        {
            EXPECT_TRUE(r.has(s)) << "no '" << s << "' in: " << r.tail();
        }
    }
}


TEST(solverInputs, zeroTimeStepOrCourantNumberIsAnErrorNotAHang)
{
    expectError
    (
        runEdited("wcsph", "deltaT0", set("deltaT", "0") + " && " + set("adjustTimeStep", "no")),
        {"Entry deltaT 0", "system/controlDict"}
    );
    expectError(runEdited("wcsph", "maxCo0", set("maxCo", "0")), {"Entry maxCo 0", "system/controlDict"});
    expectError(runEdited("wcsph", "maxDeltaT0", set("maxDeltaT", "0")), {"Entry maxDeltaT 0", "system/controlDict"});
    expectError
    (
        runEdited("isph", "deltaT0", set("deltaT", "0") + " && " + set("adjustTimeStep", "no")),
        {"Entry deltaT 0", "system/controlDict"}
    );
}


TEST(solverInputs, negativeTimeStepIsNamedNotACollapse)
{
    const sphTest::solverRun r =
        runEdited("wcsph", "deltaTNegative", set("deltaT", "-0.001") + " && " + set("adjustTimeStep", "no"));
    expectError(r, {"Entry deltaT -0.001", "system/controlDict"});
    EXPECT_FALSE(r.has("collapsed")) << r.tail();
}


TEST(solverInputs, zeroWriteIntervalIsAnErrorNotSIGFPE)
{
    expectError(runEdited("wcsph", "writeInterval0", set("writeInterval", "0")), {"Entry writeInterval 0", "system/controlDict"});
    expectError(runEdited("wcsph", "writeIntervalNegative", set("writeInterval", "-1")), {"Entry writeInterval -1"});
}


TEST(solverInputs, endTimeBeforeTheStartIsAnError)
{
    expectError(runEdited("wcsph", "endTimeNegative", set("endTime", "-1")), {"Entry endTime -1", "before the start time 0"});
}


TEST(solverInputs, endTimeAtTheStartIsNothingToDo)
{
    const sphTest::solverRun r = runEdited("wcsph", "endTime0", set("endTime", "0"));
    EXPECT_EQ(r.status, 0) << r.tail();
    EXPECT_TRUE(r.has("nothing to do")) << r.tail();
}


TEST(solverInputs, wrongDimensionsExitCleanly)
{
    // OpenFOAM's dimensioned<Type> aborts with a stack trace: the solvers
    // catch it and exit with the message alone
    for (const std::string s : {"wcsph", "isph"})
    {
        expectError
        (
            runEdited
            (
                s, "rhoDimensions",
                "sed -i 's/^rho .*/rho [0 1 0 0 0 0 0] 1000;/' constant/transportProperties"
            ),
            {"do not match the expected dimensions", "constant/transportProperties"}
        );
    }
}


TEST(solverInputs, movingWallsFileIsAnError)
{
    for (const std::string s : {"wcsph", "isph"})
    {
        expectError
        (
            runEdited(s, "movingWalls", "echo 'tank { velocity (1 0); }' > constant/movingWalls"),
            {"constant/movingWalls", "dynamicMeshDict"}
        );
    }
}


TEST(solverInputs, fieldFileWithoutInternalFieldIsAnError)
{
    expectError
    (
        runEdited("wcsph", "UNoInternalField", "sed -i '/^internalField/d' 0/U"),
        {"Missing entry internalField", "0/U"}
    );
    expectError
    (
        runEdited("isph", "UNoInternalField", "sed -i '/^internalField/d' 0/U"),
        {"Missing entry internalField", "0/U"}
    );
}


TEST(solverInputs, restartWithoutFluidParticlesIsAnError)
{
    // A type of 7 everywhere made every particle a dummy, and the run
    // "succeeded" with none
    std::string time, out;
    const fileName dir = sphTest::restartCase("wcsph", "inputs.restartType7", time);
    run("sed -i 's/^0$/7/' " + dir/time/"lagrangian/sph/type", out);
    const sphTest::solverRun r = sphTest::runSolver("wcsphFoam", dir);
    expectError(r, {time + "/lagrangian/sph/type", "particle 0 (id 0) has type 7"});
}


TEST(solverInputs, restartFieldErrorsNameTheirFile)
{
    // NaN in U was reported as a "non-finite position", with no file
    std::string time, out;
    fileName dir = sphTest::restartCase("isph", "inputs.restartUNaN", time);
    // (the particles are renumbered as they move: particle 3 has its id)
    const std::string id3 = std::to_string(sphTest::peekRestart<label>(dir, time, "id", 3));
    sphTest::pokeRestart<vector2D>(dir, time, "U", 3, vector2D(0, std::nan("")));
    sphTest::solverRun r = sphTest::runSolver("isphFoam", dir);
    expectError(r, {time + "/lagrangian/sph/U", "particle 3 (id " + id3 + ") holds (0 nan)"});
    EXPECT_FALSE(r.has("non-finite position")) << r.tail();

    dir = sphTest::restartCase("wcsph", "inputs.restartDuplicateId", time);
    const label id2 = sphTest::peekRestart<label>(dir, time, "id", 2);
    sphTest::pokeRestart<label>(dir, time, "id", 5, id2);
    r = sphTest::runSolver("wcsphFoam", dir);
    expectError
    (
        r,
        {
            time + "/lagrangian/sph/id",
            "particle 5 (id " + std::to_string(id2) + ") has the id of particle 2"
        }
    );
}


// ************************************************************************* //


TEST(solverInputs, particleSortIntervalMustBeAWholeNumberOfSteps)
{
    for (const std::string solver : {"wcsph", "isph"})
    {
        SCOPED_TRACE(solver);
        const std::string sort = "echo 'particleSortInterval ";
        expectError
        (
            runEdited(solver, "sortHalf", sort + "2.5;' >> system/sphSchemes"),
            {"Entry particleSortInterval 2.5", "whole number", "system/sphSchemes"}
        );
        expectError
        (
            runEdited(solver, "sortNegative", sort + "-1;' >> system/sphSchemes"),
            {"Entry particleSortInterval -1", "system/sphSchemes"}
        );
        // The default is logged with the stages; 0 switches it off
        const sphTest::solverRun on = runEdited(solver, "sortDefault", "true");
        EXPECT_EQ(on.status, 0) << on.tail();
        EXPECT_TRUE(on.has("renumbered cell by cell every 20 steps")) << on.tail();
        const sphTest::solverRun off =
            runEdited(solver, "sortOff", sort + "0;' >> system/sphSchemes");
        EXPECT_EQ(off.status, 0) << off.tail();
        EXPECT_FALSE(off.has("renumbered cell by cell")) << off.tail();
    }
}
