/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    ./Allreport -quick as a user runs it, into the build folder: every
    validation tutorial's test run (Allrun -test, or a short run) in a copy,
    then report/index.html and summary.md. Asserted: the command ends with
    status 0, both files exist, every case has its section and its PNG of error against
    run time, every errors.csv the tutorials wrote parses (errorTable.py
    reads it strictly: header, field count, numbers) and holds rows of its
    own case, and the page names the stability map and the benchmarks.
    The time is printed, not asserted (it follows the machine's load).
    The page is opened in Debian's headless chromium (Allwmake installs
    it) and its screenshot must be written. With the lock exchange, the
    wavy channel and the water wheel (3 Dec): 725 s, 404 s of CPU, at a
    load of 5-7 (./Allreport -quick, 17 sections, 101 rows). Measured: 656 s for the test, 619 s of it
    Allreport (289 s CPU; fishPass 150 s, cavity 100 s), at a load of 6-9
    on the 2 cores; with the machine at a load of 15 the same runs took
    31 minutes.
    A second test: errors.csv files with a wrong header, a value that is
    not a number and a short row are each refused naming the file, the
    line and what is wrong (1 s). A third: the page sums the solver seconds
    of the runs it shows, each run once, from their errors.csv rows. A
    fourth: a full form killed part-way goes on when run again, the killed
    solver log kept aside beside an earlier kill's and its run continued
    from its latest complete write, and is reused once it has ended.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include <iostream>
#include "testCase.H"

#include <chrono>

using namespace Foam;

namespace
{

// The report's sections (Allreport's table; the three still tanks share one)
const std::vector<std::string> cases =
{
    "cavity", "damBreak/zhou", "damBreak/obstacle", "damBreak/wedge",
    "periodic/poiseuille", "periodic/taylorGreen", "periodic/cylinderArray",
    "turbulence/channel", "turbulence/fishPass", "heatTransfer/poiseuille",
    "heatTransfer/heatedCavity", "heatTransfer/heatedLidCavity",
    "heatTransfer/lockExchange", "heatTransfer/wavyChannel",
    "heatTransfer/turbulentChannel", "heatTransfer/tallCavity",
    "freeSurface/waterWheel", "hydrostaticTank", "weir/sharpCrested"
};

std::string slug(const std::string& name)
{
    std::string s;
    for (const char c : name)
    {
        s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return s;
}

} // End anonymous namespace


TEST(allreport, quickFormWritesEveryCaseWithItsFigureInFifteenMinutes)
{
    const fileName out = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"allreport";
    rmDir(out);
    std::string log;
    const auto start = std::chrono::steady_clock::now();
    const int status = sphTest::runWithBashrc
    (
        "./Allreport -quick -out " + out + " 2>&1", log
    );
    const double seconds = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start
    ).count();
    EXPECT_EQ(status, 0) << log;
    // Its time is reported, not a pass/fail: it depends on the machine's
    // load (656 s at a load of 6-9 on the 2-core machine, 31 min at 12-15)
    std::cout << "Allreport -quick took " << seconds << " s" << std::endl;

    const fileName page = out/"index.html";
    ASSERT_TRUE(isFile(page)) << log;
    ASSERT_TRUE(isFile(out/"summary.md")) << log;
    const std::string html = sphTest::readFile(page);
    const std::string md = sphTest::readFile(out/"summary.md");
    for (const std::string& name : cases)
    {
        const std::string png = slug(name) + ".png";
        EXPECT_NE(html.find("id=\"case-" + slug(name) + "\""), std::string::npos) << name;
        EXPECT_NE(html.find("src=\"" + png + "\""), std::string::npos) << name;
        EXPECT_TRUE(isFile(out/png)) << name;
        EXPECT_GT(fileSize(out/png), 10000) << name;
        EXPECT_NE(md.find("## " + name + "\n"), std::string::npos) << name;
    }
    EXPECT_NE(html.find("id=\"stability\""), std::string::npos);
    EXPECT_NE(html.find("id=\"benchmarks\""), std::string::npos);

    // Every errors.csv parses, strictly, and only names its own cases
    std::string parsed;
    const int parseStatus = sphTest::run
    (
        std::string(SPHFOAM_PYTHON) + " -c \"import sys, glob; sys.path.insert(0, '"
      + SPHFOAM_SOURCE_DIR + "/bin/tools/python'); import errorTable\n"
        "files = glob.glob('" + out + "/quick/**/errors.csv', recursive=True)\n"
        "rows = [r for f in files for r in errorTable.read_errors(f)]\n"
        "print(len(files), len(rows), len({r['case'] for r in rows}))\"",
        parsed
    );
    ASSERT_EQ(parseStatus, 0) << parsed;
    std::istringstream counts(parsed);
    int nFiles = 0, nRows = 0, nCases = 0;
    counts >> nFiles >> nRows >> nCases;
    EXPECT_GE(nFiles, 18) << parsed;        // 18 tutorials, one file or more each
    EXPECT_GE(nRows, 40) << parsed;
    EXPECT_EQ(nCases, int(cases.size())) << parsed;

    // The page as a reader sees it
    // Allwmake installs chromium (bin/tools/sphDependencies): its absence
    // is a broken set-up, not a reason to skip the check
    ASSERT_FALSE(sphTest::run("command -v chromium").empty())
        << "chromium is not installed: run Allwmake (bin/tools/sphDependencies)";
    std::string shot;
    sphTest::run
    (
        "cd " + out + " && timeout 120 chromium --headless --no-sandbox --disable-gpu"
        " --disable-background-networking --disable-component-update --disable-sync"
        " --no-first-run --user-data-dir=$(mktemp -d) --screenshot=" + out/"shot.png"
      + " --window-size=1400,4000 file://" + page + " 2>&1",
        shot
    );
    ASSERT_TRUE(isFile(out/"shot.png")) << shot;
    EXPECT_GT(fileSize(out/"shot.png"), 50000) << shot;
}


TEST(allreport, aBadErrorsCsvNamesTheFileLineAndEntry)
{
    // What a tutorial writes is read strictly: the report names the file,
    // the line and the entry of a bad one instead of plotting nonsense
    const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"allreportBadCsv";
    rmDir(dir);
    const std::string header =
        "case,method,resolution,particles,measure,value,reference,wallSeconds,cpuSeconds\n";
    sphTest::writeFile(dir/"header"/"errors.csv", "case,method,value\n");
    sphTest::writeFile
    (
        dir/"value"/"errors.csv",
        header + "cavity,FV,16,256,L2,0.01,Ghia,1,0.5\ncavity,FV,32,1024,L2,abc,Ghia,2,1\n"
    );
    sphTest::writeFile(dir/"fields"/"errors.csv", header + "cavity,FV,16,256,L2,0.01\n");
    const std::string read =
        std::string(SPHFOAM_PYTHON) + " -c \"import sys; sys.path.insert(0, '"
      + SPHFOAM_SOURCE_DIR + "/bin/tools/python'); import errorTable; "
        "errorTable.read_errors(sys.argv[1])\" ";
    std::string out;
    EXPECT_NE(sphTest::run(read + dir/"header"/"errors.csv" + " 2>&1", out), 0);
    EXPECT_NE(out.find(dir/"header"/"errors.csv" + ": line 1: the header must be"),
        std::string::npos) << out;
    EXPECT_NE(sphTest::run(read + dir/"value"/"errors.csv" + " 2>&1", out), 0);
    EXPECT_NE(out.find("errors.csv: line 3: value 'abc' is not a number"),
        std::string::npos) << out;
    EXPECT_NE(sphTest::run(read + dir/"fields"/"errors.csv" + " 2>&1", out), 0);
    EXPECT_NE(out.find("errors.csv: line 2: 6 fields, expected 9"), std::string::npos)
        << out;
}


TEST(allreport, aKilledFullFormGoesOnAndKeepsWhatWasWritten)
{
    // The full form runs for hours and the machine ends processes (a
    // restart, the end of a session): a tutorial is left with some runs
    // and a solver log without End. Run again, the report must not take
    // those as finished runs (nor a stale errors.csv as the tutorial's): it
    // sets the killed log aside (kept) and runs the tutorial's full form
    // again, the killed run going on from its latest complete write (a run
    // longer than the time between kills would otherwise never end). A
    // project folder of links and one short tutorial stands in for the
    // project; its run to 0.3 s, its End cut off and a 0.4 written in part
    // are what a kill at 0.4 s leaves.
    const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"allreportResume";
    rmDir(dir);
    const fileName tank = dir/"tutorials"/"isph"/"hydrostaticTank";
    const std::string src(SPHFOAM_SOURCE_DIR);
    const std::string apps(std::string(SPHFOAM_BINARY_DIR) + "/applications/");
    std::string out;
    ASSERT_EQ
    (
        sphTest::run
        (
            "mkdir -p " + tank.path() + " && cp " + src + "/Allreport " + dir
          + " && ln -s " + src + "/etc " + src + "/bin " + dir
          + " && cp -r " + src + "/tutorials/isph/hydrostaticTank " + tank.path()
          + " && cd " + tank + " && sed -i -e 's/^endTime .*/endTime 0.3;/'"
            " -e 's/^writeInterval .*/writeInterval 0.1;/' system/controlDict"
            " && " + apps + "sphMesh > log.sphMesh 2>&1"
            " && OMP_NUM_THREADS=1 " + apps + "isphFoam > log.isphFoam 2>&1"
            " && sed -i 's/^endTime .*/endTime 0.5;/' system/controlDict"
            " && mkdir -p 0.4/uniform",
            out
        ),
        0
    ) << out;
    std::string killedLog = sphTest::readFile(tank/"log.isphFoam");
    ASSERT_NE(killedLog.find("\nEnd\n"), std::string::npos) << killedLog;
    killedLog.erase(killedLog.find("\nEnd\n") + 1);
    sphTest::writeFile(tank/"log.isphFoam", killedLog);
    // A run that stopped loudly ended: its log is not a kill's, it stays
    const std::string stoppedLog =
        "Exec   : wcsphFoam\n\n--> FOAM FATAL ERROR: \nSpeed 9 m/s, more than maxSpeed\n";
    sphTest::writeFile(tank/"log.wcsphFoam", stoppedLog);
    // The log of a kill before that one, set aside then: it must stay
    const std::string earlierLog = "Exec   : isphFoam\nStarting time loop\n";
    sphTest::writeFile(tank/"log.isphFoam.unfinished", earlierLog);
    // Without the file below, this errors.csv would be reused as the case's
    sphTest::writeFile
    (
        tank/"errors.csv",
        "case,method,resolution,particles,measure,value,reference,wallSeconds,cpuSeconds\n"
    );
    sphTest::writeFile(tank/"log.Allreport.inProgress", "2026-12-07 04:00:00 (pid 1)\n");

    const int status = sphTest::run
    (
        "cd " + dir + " && ./Allreport -cases isphTank -out " + dir/"report", out
    );
    ASSERT_EQ(status, 0) << out;
    EXPECT_NE(out.find("isphTank: the full form begun 2026-12-07 04:00:00 (pid 1) did not end"),
        std::string::npos) << out;
    EXPECT_NE(out.find("log.isphFoam has no End (the run was killed): moved to "
        "log.isphFoam.unfinished1"), std::string::npos) << out;
    EXPECT_NE(out.find("hydrostaticTank: it goes on from its latest time, 0.3 "
        "(startFrom latestTime)"), std::string::npos) << out;
    EXPECT_EQ(sphTest::readFile(tank/"log.isphFoam.unfinished1"), killedLog);
    EXPECT_EQ(sphTest::readFile(tank/"log.isphFoam.unfinished"), earlierLog);
    EXPECT_EQ(sphTest::readFile(tank/"log.wcsphFoam"), stoppedLog);
    EXPECT_FALSE(isFile(tank/"log.wcsphFoam.unfinished"));
    const std::string resumed = sphTest::readFile(tank/"log.isphFoam");
    EXPECT_NE(resumed.find("Skipping the incomplete time directory"), std::string::npos)
        << resumed;
    EXPECT_NE(resumed.find("Restarting from \"" + tank + "/0.3/lagrangian/sph\""),
        std::string::npos) << resumed;
    EXPECT_NE(resumed.find("\nEnd\n"), std::string::npos);
    EXPECT_TRUE(isFile(tank/"0.5"/"lagrangian"/"sph"/"positions"));
    // The tutorial's own controlDict (in the repository) is as it was
    const std::string dict = sphTest::readFile(tank/"system"/"controlDict");
    EXPECT_NE(dict.find("\nstartFrom       startTime;"), std::string::npos) << dict;
    EXPECT_EQ(dict.find("skipIncompleteTimes"), std::string::npos) << dict;
    EXPECT_FALSE(isFile(tank/"log.Allreport.continued"));
    EXPECT_FALSE(isFile(tank/"log.Allreport.inProgress"));
    EXPECT_NE(sphTest::readFile(dir/"report"/"runs.tsv").find("\tran\t"), std::string::npos);
    EXPECT_NE(sphTest::readFile(tank/"errors.csv").find("hydrostaticTank,ISPH-USAW"), std::string::npos)
        << sphTest::readFile(tank/"errors.csv");

    // The compare scripts' log reader adds the killed leg (kept beside the
    // log) up to the restart: the steps from 0, the CPU of both legs
    ASSERT_EQ
    (
        sphTest::run
        (
            "cd " + tank + " && " + SPHFOAM_PYTHON + " -c 'import sys; sys.path.insert(0, \""
          + src + "/bin/tools/python\"); import foamCaseFiles as f; "
            "a = f.read_log(\"log.isphFoam.unfinished1\"); b = f.read_log(\"log.isphFoam\"); "
            "print(b[\"legs\"], b[\"steps\"] > a[\"steps\"], b[\"cpu\"] > a[\"cpu\"] > 0)' 2>&1",
            out
        ),
        0
    ) << out;
    EXPECT_EQ(out, "2 True True\n");

    // Once the full form has ended, the next report reuses it
    ASSERT_EQ
    (
        sphTest::run("cd " + dir + " && ./Allreport -cases isphTank -out " + dir/"report", out),
        0
    ) << out;
    EXPECT_NE(out.find("isphTank: reusing its errors.csv"), std::string::npos) << out;
}


TEST(allreport, theKilledLegsOfAnOpenFOAMRunAreCounted)
{
    // An OpenFOAM solver's log does not say where it started: continued
    // from its latest write after a kill (its killed log kept beside it,
    // as Allreport does), the compare scripts' reader takes the written
    // time before its first step as the restart and adds the killed leg up
    // to there. icoFoam's cavity, 60 steps, written every 20, killed at
    // step 49 (0.245 s) and continued from 0.2: 20 steps + the 40 before
    const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"readLogLegs";
    rmDir(dir);
    std::string out;
    ASSERT_EQ
    (
        sphTest::run
        (
            "cp -r /usr/share/doc/openfoam-examples/examples/incompressible/icoFoam/cavity/cavity "
          + dir + " && cd " + dir + " && blockMesh > log.blockMesh 2>&1"
            " && sed -i -e 's/^endTime .*/endTime 0.3;/' -e 's/^writeInterval .*/writeInterval 20;/'"
            " system/controlDict && icoFoam > log.icoFoam 2>&1"
            " && sed -n '1,/^Time = 0.25$/p' log.icoFoam | sed '$d' > log.icoFoam.unfinished"
            " && rm -r 0.3 log.icoFoam && touch -d '1 minute ago' log.icoFoam.unfinished"
            " && sed -i 's/^startFrom .*/startFrom latestTime;/' system/controlDict"
            " && icoFoam > log.icoFoam 2>&1 && " + std::string(SPHFOAM_PYTHON)
          + " -c 'import sys; sys.path.insert(0, \"" SPHFOAM_SOURCE_DIR "/bin/tools/python\");"
            " import foamCaseFiles as f; a = f.read_log(\"log.icoFoam.unfinished\");"
            " b = f.read_log(\"log.icoFoam\");"
            " print(a[\"steps\"], b[\"start\"], b[\"steps\"], b[\"legs\"], b[\"end\"])' 2>&1",
            out
        ),
        0
    ) << out;
    EXPECT_EQ(out, "49 0.2 60 2 True\n");

    // Killed after its last write, before End: continued, it starts at
    // its end time and takes no step (no 'Time =', no seconds): the run is
    // the killed leg's, 60 steps at 0.3 s
    ASSERT_EQ
    (
        sphTest::run
        (
            "cd " + dir + " && sed '/^End/d' log.icoFoam > log.icoFoam.unfinished1"
            " && touch -d '30 seconds ago' log.icoFoam.unfinished1 && icoFoam > log.icoFoam 2>&1"
            " && " + std::string(SPHFOAM_PYTHON)
          + " -c 'import sys; sys.path.insert(0, \"" SPHFOAM_SOURCE_DIR "/bin/tools/python\");"
            " import foamCaseFiles as f; a = f.read_log(\"log.icoFoam.unfinished1\");"
            " b = f.read_log(\"log.icoFoam\");"
            " print(b[\"start\"], b[\"t\"], b[\"steps\"], b[\"cpu\"] == a[\"cpu\"], b[\"end\"])' 2>&1",
            out
        ),
        0
    ) << out;
    EXPECT_EQ(out, "0.3 0.3 60 True True\n");
}


TEST(allreport, thePageSaysWhatTheRunsItShowsCost)
{
    // The full form reuses finished runs, so its own time says nothing of
    // theirs: the page sums the solvers' seconds from the errors.csv rows,
    // each run once (one row per measure; two Rayleigh numbers at one
    // resolution are two runs, told apart by their times)
    const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"allreportCost";
    rmDir(dir);
    const std::string header =
        "case,method,resolution,particles,measure,value,reference,wallSeconds,cpuSeconds\n";
    sphTest::writeFile
    (
        dir/"a"/"results"/"errors.csv",
        header
      + "cavity,FV,16,256,L2 u,0.01,Ghia,2,1.5\n"
        "cavity,FV,16,256,L2 v,0.02,Ghia,2,1.5\n"
        "cavity,ISPH-USAW,16,225,L2 u,0.03,Ghia,120,100\n"
        "cavity,ISPH-USAW,16,225,L2 u Re 400,0.04,Ghia,70,60\n"
        "cavity,WCSPH,16,225,L2 u,0.05,Ghia,nan,nan\n"
    );
    sphTest::writeFile
    (
        dir/"runs.tsv",
        "#case\tfolder\taction\tseconds\tcpuSeconds\tcommand\tlog\n"
        "cavity\t" + dir/"a" + "\treused\t0\t0\t-\t-\n"
    );
    std::string out;
    ASSERT_EQ
    (
        sphTest::run
        (
            std::string(SPHFOAM_PYTHON) + " " + SPHFOAM_SOURCE_DIR
          + "/bin/tools/python/sphReport.py -out " + dir/"out" + " -runs " + dir/"runs.tsv"
          + " -project " + SPHFOAM_SOURCE_DIR + " 2>&1",
            out
        ),
        0
    ) << out;
    const std::string md = sphTest::readFile(dir/"out"/"summary.md");
    const std::string cost =
        "4 runs: 162 s of solver CPU (0.0 h), 192 s of wall clock; "
        "1 without a CPU time, not counted.";
    EXPECT_NE(md.find("The page shows " + cost), std::string::npos) << md;
    EXPECT_NE(md.find("The rows below come from " + cost), std::string::npos) << md;
    EXPECT_NE(sphTest::readFile(dir/"out"/"index.html").find("The page shows " + cost),
        std::string::npos);
}
