/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    kill -9 while a solver writes: runs that write at every step are killed
    at staggered moments; afterwards every numbered time directory must be
    complete (the particle fields, uniform/time and the solver's state),
    and startFrom latestTime must restart from the latest one (removing the
    unfinished .writing folder, if any, with a word) and run on. A time
    directory made incomplete by hand is refused by name, or skipped with
    skipIncompleteTimes yes.

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
    const std::string tutorials = std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/";

    //- The tank of the solver, coarse, meshed, writing every step to a
    //- long end
    fileName tank(const std::string& app, const std::string& name)
    {
        const fileName dir =
            fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/sphTest::perTest(name);
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        const std::string from =
            app == "isphFoam" ? "isph/hydrostaticTank" : "wcsph/hydrostaticTank";
        EXPECT_EQ(run("cp -r " + tutorials + from + " " + dir, out), 0) << out;
        // 200 fluid particles: a write is most of a step, so kills land in
        // writes
        setEntry(dir/"system"/"sphMeshDict", "dr", "0.05");
        EXPECT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
        const fileName controlDict(dir/"system"/"controlDict");
        setEntry(controlDict, "writeControl", "timeStep");
        setEntry(controlDict, "writeInterval", "1");
        setEntry(controlDict, "endTime", "100");
        return dir;
    }

    //- The .writing folders in the case
    std::string unfinishedWrites(const fileName& dir)
    {
        return run("find " + dir + " -maxdepth 1 -name '*.writing'");
    }

    //- What a complete time directory of the solver holds
    std::string missingIn(const fileName& timeDir, const std::string& app)
    {
        std::string missing;
        for
        (
            const std::string& f :
            std::vector<std::string>
            {
                std::string("lagrangian/sph/positions"), "lagrangian/sph/U",
                "lagrangian/sph/p", "lagrangian/sph/id", "lagrangian/sph/type",
                "uniform/time",
                "uniform/" + app.substr(0, app.size() - 4) + "State"
            }
        )
        {
            if (!isFile(timeDir/f) || fileSize(timeDir/f) == 0)
            {
                missing += " " + f;
            }
        }
        return missing;
    }
}


TEST(killDuringWrite, everyTimeLeftIsCompleteAndTheLatestRestarts)
{
    for (const std::string app : {"isphFoam", "wcsphFoam"})
    {
        SCOPED_TRACE(app);
        const fileName dir = tank(app, "kill_" + app);
        const std::string exe = "env OMP_NUM_THREADS=1 " + bin + app + " -case " + dir;

        // Kill at staggered moments once the time loop runs (a write
        // every step of a few milliseconds), however busy the machine
        std::string out;
        label unfinished = 0;
        for (int k = 0; k < 12; ++k)
        {
            const fileName log(dir/"log.kill");
            const std::string delay = std::to_string(0.01 + 0.013*k);
            run
            (
                exe + " > " + log + " 2>&1 & pid=$!;"
                " for i in $(seq 1200); do"
                " grep -q 'Starting time loop' " + log + " && break; sleep 0.05;"
                " done; sleep " + delay + "; kill -9 $pid; wait $pid; echo $? > "
              + dir/"status.kill",
                out
            );
            const std::string status = run("cat " + dir/"status.kill");
            EXPECT_EQ(status, "137\n")
                << "run " << k << " was not killed: " << run("tail -30 " + log);
            if (!unfinishedWrites(dir).empty()) ++unfinished;

            for (const std::string& t : sphTest::timeDirs(dir))
            {
                EXPECT_EQ(missingIn(dir/t, app), "")
                    << "time " << t << " after kill " << k << " is incomplete";
            }
            setEntry(dir/"system"/"controlDict", "startFrom", "latestTime");
        }
        std::cout << app << ": " << sphTest::timeDirs(dir).size()
            << " times written, " << unfinished << " kills left a .writing"
            << " folder" << std::endl;

        // The latest time restarts and the run goes on for a few steps
        const std::vector<std::string> times(sphTest::timeDirs(dir));
        ASSERT_FALSE(times.empty());
        setEntry
        (
            dir/"system"/"controlDict", "endTime",
            std::to_string(std::stod(times.back()) + 0.1)
        );
        EXPECT_EQ(run(exe, out), 0) << sphTest::logTail(out);
        EXPECT_NE(out.find("Restarting from"), std::string::npos)
            << sphTest::logTail(out);
        EXPECT_EQ(unfinishedWrites(dir), "");
    }
}


TEST(killDuringWrite, anIncompleteTimeIsRefusedByNameOrSkippedOnRequest)
{
    const fileName dir = tank("isphFoam", "incompleteTime");
    const fileName controlDict(dir/"system"/"controlDict");
    setEntry(controlDict, "adjustTimeStep", "no");
    setEntry(controlDict, "endTime", "0.005");
    std::string out;
    ASSERT_EQ(run(bin + "isphFoam -case " + dir, out), 0) << out;
    const std::vector<std::string> times(sphTest::timeDirs(dir));
    ASSERT_GE(times.size(), 3u);

    // The latest loses its positions (a damaged copy)
    rm(dir/times.back()/"lagrangian"/"sph"/"positions");
    setEntry(controlDict, "startFrom", "latestTime");
    setEntry(controlDict, "endTime", "0.007");
    EXPECT_NE(run(bin + "isphFoam -case " + dir, out), 0) << out;
    EXPECT_NE(out.find(times.back()), std::string::npos) << out;
    EXPECT_NE(out.find("is incomplete"), std::string::npos) << out;
    EXPECT_NE(out.find("skipIncompleteTimes"), std::string::npos) << out;
    EXPECT_EQ(out.find("printStack"), std::string::npos) << out;

    // With the opt-in: from the time before, saying so
    run("echo 'skipIncompleteTimes yes;' >> " + controlDict, out);
    EXPECT_EQ(run(bin + "isphFoam -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("Skipping the incomplete time directory"), std::string::npos) << out;
    EXPECT_NE
    (
        out.find("Starting from time " + times[times.size() - 2]),
        std::string::npos
    ) << out;
    EXPECT_TRUE(isFile(dir/times.back()/"lagrangian"/"sph"/"positions"))
        << "the skipped time was not written again";

    // A time whose solver state is missing is refused, naming the file
    const std::vector<std::string> now(sphTest::timeDirs(dir));
    rm(dir/now.back()/"uniform"/"isphState");
    EXPECT_NE(run(bin + "isphFoam -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("uniform/isphState\" is missing"), std::string::npos) << out;
}


TEST(killDuringWrite, aWriteThatFailsSaysSoAndKeepsEarlierTimes)
{
    // A file in the way of the third time directory: its write fails (as
    // on a full disk or a folder that cannot be written, which root, who
    // runs the tests, would not see)
    const fileName dir = tank("wcsphFoam", "failedWrite");
    const fileName controlDict(dir/"system"/"controlDict");
    setEntry(controlDict, "adjustTimeStep", "no");
    setEntry(controlDict, "endTime", "0.0005");
    std::string out;
    ASSERT_EQ(run(bin + "wcsphFoam -case " + dir, out), 0) << out;
    const std::vector<std::string> times(sphTest::timeDirs(dir));
    ASSERT_GE(times.size(), 4u);
    for (std::size_t i = 2; i < times.size(); ++i) rmDir(dir/times[i]);
    run("touch " + dir/times[2], out);
    setEntry(controlDict, "startFrom", "latestTime");

    const int status = run(bin + "wcsphFoam -case " + dir, out);
    EXPECT_EQ(status, 1) << out;
    EXPECT_NE(out.find("Cannot write the time directory"), std::string::npos) << out;
    EXPECT_NE(out.find("Every earlier time directory is intact"), std::string::npos) << out;
    EXPECT_EQ(out.find("printStack"), std::string::npos) << out;
    EXPECT_EQ(missingIn(dir/times[1], "wcsphFoam"), "");
    EXPECT_EQ(unfinishedWrites(dir), "") << "a half write is left";
}


// ************************************************************************* //


TEST(killDuringWrite, aLaterTimeWithoutParticlesIsNotAFreshStart)
{
    // A later time directory that holds no written state (an empty copy,
    // or one Time names differently from the folder): starting afresh from
    // constant/sphMesh there would pass for a restart; it is an error
    const fileName dir = tank("isphFoam", "laterWithoutParticles");
    const fileName controlDict(dir/"system"/"controlDict");
    setEntry(controlDict, "adjustTimeStep", "no");
    setEntry(controlDict, "endTime", "0.005");
    std::string out;
    ASSERT_EQ(run(bin + "isphFoam -case " + dir, out), 0) << out;

    mkDir(dir/"0.5");
    setEntry(controlDict, "startFrom", "latestTime");
    setEntry(controlDict, "endTime", "0.6");
    EXPECT_NE(run(bin + "isphFoam -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("No particles to start from at time 0.5"), std::string::npos) << out;
    EXPECT_EQ(out.find("Restarting from"), std::string::npos) << out;
    EXPECT_EQ(out.find("printStack"), std::string::npos) << out;
}
