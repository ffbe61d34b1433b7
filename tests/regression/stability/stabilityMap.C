/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The stability map's short form (tutorials/stability, Allrun -quick): at
    least 25 runs of the stiff and extreme corners, none of which may go
    wrong silently (a signal, a hang, an exit without End or error, or an
    end whose last picture has a non-finite value, a lost particle or a
    speed beyond the case's physical bound). The pressure solve made hard
    on purpose must stop loudly, naming the solver settings; with
    stopIfNotConverged no it must run; the large time steps with
    retryOnFailure must count their retries; the still tanks at rest for
    2 t sqrt(g/H) must stay hydrostatic within 5 % of rho g H. Two more
    tests: -resume reuses the rows that ended and runs the unfinished one
    again, and a killed run goes on from its latest write.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    //- The rows of results/stability.csv, by run name (quoted fields with
    //- commas are kept whole)
    std::map<std::string, std::map<std::string, std::string>>
    readTable(const fileName& file)
    {
        std::ifstream is(file);
        std::string line;
        auto split = [](const std::string& l)
        {
            std::vector<std::string> f;
            std::string cur;
            bool quoted = false;
            for (char c : l)
            {
                if (c == '"') quoted = !quoted;
                else if (c == ',' && !quoted) { f.push_back(cur); cur.clear(); }
                else cur += c;
            }
            f.push_back(cur);
            return f;
        };
        std::getline(is, line);
        const std::vector<std::string> header(split(line));
        std::map<std::string, std::map<std::string, std::string>> rows;
        while (std::getline(is, line))
        {
            const std::vector<std::string> f(split(line));
            std::map<std::string, std::string> r;
            for (size_t i = 0; i < header.size() && i < f.size(); ++i)
            {
                r[header[i]] = f[i];
            }
            rows[r["name"]] = r;
        }
        return rows;
    }
}


TEST(stabilityMap, quickFormHasNoSilentFailure)
{
    const fileName dir = sphTest::copyTutorial("stability", "stability");
    std::string out;
    EXPECT_EQ
    (
        sphTest::runWithBashrc(dir + "/Allclean && " + dir + "/Allrun -quick", out),
        0
    ) << out;

    const auto rows = readTable(dir/"results"/"stability.csv");
    EXPECT_GE(rows.size(), 25u) << out;
    for (const auto& [name, r] : rows)
    {
        EXPECT_NE(r.at("outcome"), "WRONG") << name << ": " << r.at("cause");
        if (r.at("outcome") == "stopped")
        {
            EXPECT_FALSE(r.at("cause").empty()) << name;
        }
    }

    ASSERT_TRUE(rows.count("hardSolve_isph")) << out;
    EXPECT_EQ(rows.at("hardSolve_isph").at("outcome"), "stopped");
    EXPECT_NE
    (
        rows.at("hardSolve_isph").at("cause").find("did not converge"),
        std::string::npos
    ) << rows.at("hardSolve_isph").at("cause");

    ASSERT_TRUE(rows.count("hardSolveGoOn_isph"));
    EXPECT_EQ(rows.at("hardSolveGoOn_isph").at("outcome"), "ran");

    // retryOnFailure counts its retries, whether the run ends or stops
    for (const char* retried : {"maxCo1Retry_wcsph", "largeStepRetry_isph"})
    {
        ASSERT_TRUE(rows.count(retried));
        EXPECT_FALSE(rows.at(retried).at("retries").empty()) << retried;
    }
    // Without retries the ISPH large step stops where the check fires
    ASSERT_TRUE(rows.count("largeStep_isph"));
    EXPECT_EQ(rows.at("largeStep_isph").at("outcome"), "stopped");
    EXPECT_NE
    (
        rows.at("largeStep_isph").at("cause").find("maxStepDisplacement"),
        std::string::npos
    );

    // The still tanks that ran are still: hydrostatics within 5 % of rho g H
    for (const char* tank : {"longRest_isph", "longRest_wcsph"})
    {
        ASSERT_TRUE(rows.count(tank));
        ASSERT_EQ(rows.at(tank).at("outcome"), "ran") << tank;
        EXPECT_LT(std::stod(rows.at(tank).at("error")), 0.05) << tank;
    }
}


TEST(stabilityMap, resumeRunsOnlyTheRowsThatDidNotEnd)
{
    // The full map runs for hours: -resume reuses each row whose run ended
    // (its outcome.json), and runs again one whose case was not made for it
    const fileName dir = sphTest::copyTutorial("stability", "stabilityResume");
    rmDir(dir/"runs");
    const std::string rows = " -quick -only viscousTank_isph hardSolve_isph -resume";
    std::string first, second;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun" + rows, first), 0) << first;
    EXPECT_EQ(first.find("reusing its outcome"), std::string::npos) << first;
    const auto before = readTable(dir/"results"/"stability.csv");

    // The second row's outcome never written, and its case taken for
    // another row's (row.json): it runs again
    rm(dir/"runs"/"quick"/"hardSolve_isph"/"outcome.json");
    sphTest::writeFile
    (
        dir/"runs"/"quick"/"hardSolve_isph"/"row.json",
        "{\"name\": \"hardSolve_isph\", \"solver\": \"isphFoam\", \"setting\": \"old\"}"
    );
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun" + rows, second), 0) << second;
    EXPECT_NE
    (
        second.find("viscousTank_isph/outcome.json"), std::string::npos
    ) << second;
    EXPECT_EQ(second.find("hardSolve_isph/outcome.json"), std::string::npos) << second;
    EXPECT_EQ(second.find("judged from its log"), std::string::npos) << second;
    EXPECT_TRUE(isFile(dir/"runs"/"quick"/"hardSolve_isph"/"outcome.json"));
    EXPECT_NE
    (
        sphTest::readFile(dir/"runs"/"quick"/"hardSolve_isph"/"row.json")
            .find("p tolerance 1e-12, maxIter 20"),
        std::string::npos
    );

    const auto after = readTable(dir/"results"/"stability.csv");
    ASSERT_EQ(after.size(), 2u);
    for (const auto& [name, r] : before)
    {
        EXPECT_EQ(after.at(name).at("outcome"), r.at("outcome")) << name;
        EXPECT_EQ(after.at(name).at("cause"), r.at("cause")) << name;
    }
    EXPECT_EQ(after.at("viscousTank_isph").at("error"), before.at("viscousTank_isph").at("error"));
}


TEST(stabilityMap, resumeGoesOnFromTheKilledRunsLatestWrite)
{
    // A row of the full form can take longer than the machine stays up:
    // killed, it must go on from its latest write (not from its first step,
    // or it would never end), and the table must count the legs as one
    // run. The large step with retries stops at 0.07125 s after 9 retries
    // (6 before that write); its log cut before the FOAM FATAL error is
    // what a kill during the last retries leaves. logInterval 1 so that
    // the kept leg's log shows the time it reached.
    const fileName dir = sphTest::copyTutorial("stability", "stabilityKilled");
    rmDir(dir/"runs");
    const std::string row = " -quick -only largeStepRetry_isph -resume";
    const fileName run = dir/"runs"/"quick"/"largeStepRetry_isph";
    std::string first, again, second;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun" + row, first), 0) << first;
    const auto whole = readTable(dir/"results"/"stability.csv").at("largeStepRetry_isph");
    ASSERT_EQ(whole.at("outcome"), "stopped");
    ASSERT_EQ(whole.at("retries").rfind("9", 0), 0u) << whole.at("retries");

    ASSERT_EQ
    (
        sphTest::runWithBashrc
        (
            "cd " + run + " && sed -i 's/^logInterval .*/logInterval 1;/'"
            " system/controlDict && rm -r 0.07125 outcome.json"
            " && (isphFoam > log.isphFoam 2>&1; test $? = 1)",
            again
        ),
        0
    ) << again;
    std::string killedLog = sphTest::readFile(run/"log.isphFoam");
    ASSERT_NE(killedLog.find("--> FOAM FATAL"), std::string::npos);
    killedLog.erase(killedLog.find("--> FOAM FATAL"));
    sphTest::writeFile(run/"log.isphFoam", killedLog);

    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun" + row, second), 0) << second;
    EXPECT_NE(second.find("killed before it ended: it goes on from its write at"
        " t = 0.07125 s (its log kept as log.isphFoam.unfinished)"),
        std::string::npos) << second;
    // Kept, so the case was not made again (that clears the folder)
    EXPECT_EQ(sphTest::readFile(run/"log.isphFoam.unfinished"), killedLog);
    const std::string resumed = sphTest::readFile(run/"log.isphFoam");
    EXPECT_NE(resumed.find("Restarting from \"" + run + "/0.07125/lagrangian/sph\""),
        std::string::npos) << resumed;

    const auto legs = readTable(dir/"results"/"stability.csv").at("largeStepRetry_isph");
    EXPECT_EQ(legs.at("outcome"), "stopped");
    EXPECT_EQ(legs.at("reached"), whole.at("reached"));
    EXPECT_EQ(legs.at("retries"), whole.at("retries"));
    EXPECT_EQ(legs.at("cause").find(whole.at("cause")), 0u) << legs.at("cause");
    EXPECT_NE(legs.at("cause").find("killed, went on from its write at t = 0.07125 s"),
        std::string::npos) << legs.at("cause");

    // Killed after the run ended, before the map wrote its outcome: judged
    // from what it left, not run again
    const std::string resumedLog = sphTest::readFile(run/"log.isphFoam");
    rm(run/"outcome.json");
    std::string third;
    ASSERT_EQ(sphTest::runWithBashrc(dir + "/Allrun" + row, third), 0) << third;
    EXPECT_NE(third.find("it ended before the map recorded it"), std::string::npos) << third;
    EXPECT_EQ(sphTest::readFile(run/"log.isphFoam"), resumedLog);
    const auto judged = readTable(dir/"results"/"stability.csv").at("largeStepRetry_isph");
    for (const char* column : {"outcome", "reached", "retries", "cause"})
    {
        EXPECT_EQ(judged.at(column), legs.at(column)) << column;
    }
}


// ************************************************************************* //
