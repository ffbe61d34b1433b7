/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH toolkit on OpenFOAM v1912

Description
    Unit tests of the tutorial shell functions: etc/bashrc,
    bin/tools/RunFunctions and bin/tools/CleanFunctions.

    Each test gets a fresh folder under the build tree
        <build>/tests/unit/runFunctions/work/<Suite>.<Test>/
    holding a case (case/), fake applications (bin/) and the script it runs.
    Scripts run under /bin/sh (dash on Debian), as tutorial Allrun scripts do.
    The folder is removed when the test passes and kept when it fails.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{

const fs::path sourceDir{SPHFOAM_SOURCE_DIR};
const fs::path binaryDir{SPHFOAM_BINARY_DIR};

// What a script printed, and how it ended
struct ShellResult
{
    int status = -1;
    std::string out;
    std::string err;
};

std::string readFile(const fs::path& file)
{
    std::ifstream is(file, std::ios::binary);
    std::ostringstream os;
    os << is.rdbuf();
    return os.str();
}

void writeFile(const fs::path& file, const std::string& text)
{
    fs::create_directories(file.parent_path());
    std::ofstream os(file, std::ios::binary);
    os << text;
}

void writeExecutable(const fs::path& file, const std::string& text)
{
    writeFile(file, text);
    fs::permissions(file, fs::perms::owner_all | fs::perms::group_read
        | fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
}

// Single-quoted for sh; the paths used here never hold a quote
std::string quoted(const fs::path& p)
{
    return "'" + p.string() + "'";
}

// The lines of a text, without their newlines
std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> result;
    std::istringstream is(text);
    std::string line;
    while (std::getline(is, line))
    {
        result.push_back(line);
    }
    return result;
}

// The entries of a ':'-separated list
std::vector<std::string> splitPath(const std::string& value)
{
    std::vector<std::string> result;
    std::string item;
    std::istringstream is(value);
    while (std::getline(is, item, ':'))
    {
        result.push_back(item);
    }
    return result;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

// The first line of text that starts with key=, without the key
std::string valueOf(const std::string& text, const std::string& key)
{
    for (const auto& line : lines(text))
    {
        if (line.rfind(key + "=", 0) == 0)
        {
            return line.substr(key.size() + 1);
        }
    }
    return "<" + key + " not printed>";
}

const char* const foamHeader =
    "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
    "    class       dictionary;\n    object      dict;\n}\n\n";


// A fresh work folder with a case, fake applications and a script runner
class ScriptTest : public ::testing::Test
{
protected:
    fs::path work_;
    fs::path case_;
    fs::path bin_;

    void SetUp() override
    {
        // foamDictionary (Debian OpenFOAM) cannot start without it
        setenv("WM_PROJECT_DIR", "/usr/share/openfoam", 1);

        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        work_ = binaryDir / "tests" / "unit" / "runFunctions" / "work"
            / (std::string(info->test_suite_name()) + "." + info->name());
        ASSERT_EQ(work_.string().find('\''), std::string::npos);
        fs::remove_all(work_);
        case_ = work_ / "case";
        bin_ = work_ / "bin";
        fs::create_directories(case_ / "system");
        fs::create_directories(case_ / "constant");
        fs::create_directories(bin_);

        // Prints its arguments on stdout, a line on stderr, counts its runs
        writeExecutable(bin_ / "okApp",
            "#!/bin/sh\n"
            "echo \"okApp ran with: $*\"\n"
            "echo \"okApp says on stderr\" 1>&2\n"
            "echo run >> runs.okApp\n"
            "exit 0\n");
        // Fails with status 3
        writeExecutable(bin_ / "failApp",
            "#!/bin/sh\n"
            "echo \"failApp cannot go on\" 1>&2\n"
            "exit 3\n");
        // Stands in for Open MPI: prints how it was called
        writeExecutable(bin_ / "mpirun",
            "#!/bin/sh\n"
            "echo \"mpirun $*\"\n"
            "echo \"rootAllowed=${OMPI_ALLOW_RUN_AS_ROOT:-unset}\"\n"
            "exit 0\n");
    }

    void TearDown() override
    {
        if (!HasFailure())
        {
            std::error_code ec;
            fs::remove_all(work_, ec);
        }
    }

    // Runs a script with /bin/sh in folder dir, after sourcing the functions
    ShellResult sh(const std::string& body, const fs::path& dir = fs::path())
    {
        const fs::path runDir = dir.empty() ? case_ : dir;
        const fs::path script = work_ / "script.sh";
        writeFile(script,
            "PATH=" + quoted(bin_) + ":\"$PATH\"; export PATH\n"
            "cd " + quoted(runDir) + " || exit 99\n"
            ". " + quoted(sourceDir / "bin/tools/RunFunctions") + "\n"
            ". " + quoted(sourceDir / "bin/tools/CleanFunctions") + "\n"
            + body + "\n");
        return run("/bin/sh " + quoted(script));
    }

    // Runs a shell command line; stdout and stderr to files in the work folder
    ShellResult run(const std::string& command)
    {
        const fs::path out = work_ / "stdout";
        const fs::path err = work_ / "stderr";
        const std::string full =
            command + " > " + quoted(out) + " 2> " + quoted(err) + " < /dev/null";

        ShellResult result;
        const int raw = std::system(full.c_str());
        result.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
        result.out = readFile(out);
        result.err = readFile(err);
        return result;
    }

    // A dictionary file with a FoamFile header
    void writeDict(const fs::path& file, const std::string& entries)
    {
        writeFile(file, std::string(foamHeader) + entries);
    }
};

using RunApplication = ScriptTest;
using RunParallel = ScriptTest;
using GetApplication = ScriptTest;
using Switches = ScriptTest;
using CleanFunctions = ScriptTest;
using CloneCase = ScriptTest;
using Bashrc = ScriptTest;
using FishFunctions = ScriptTest;

} // namespace


// * * * * * * * * * * * * * * * runApplication  * * * * * * * * * * * * * * //

TEST_F(RunApplication, WritesLogAndReturnsZero)
{
    const auto r = sh("runApplication okApp first second\necho \"status=$?\"");

    EXPECT_EQ(valueOf(r.out, "status"), "0");
    EXPECT_TRUE(contains(r.out, "Running okApp on " + case_.string())) << r.out;
    ASSERT_TRUE(fs::exists(case_ / "log.okApp"));
    const std::string log = readFile(case_ / "log.okApp");
    EXPECT_TRUE(contains(log, "okApp ran with: first second")) << log;
    EXPECT_TRUE(contains(log, "okApp says on stderr")) << "stderr goes to the log too";
    EXPECT_FALSE(contains(r.out, "okApp ran with")) << "application output leaked";
}

TEST_F(RunApplication, ReturnsExitStatusOfApplication)
{
    const auto r = sh("runApplication failApp\necho \"status=$?\"");

    EXPECT_EQ(valueOf(r.out, "status"), "3");
    EXPECT_TRUE(contains(readFile(case_ / "log.failApp"), "failApp cannot go on"));
}

TEST_F(RunApplication, StatusStopsAScriptWithSetE)
{
    const auto r = sh("set -e\nrunApplication failApp\necho reached");

    EXPECT_EQ(r.status, 3);
    EXPECT_FALSE(contains(r.out, "reached"));
}

TEST_F(RunApplication, SkipsWhenLogExists)
{
    const auto r = sh(
        "runApplication okApp one\n"
        "runApplication okApp two\necho \"status=$?\"");

    EXPECT_TRUE(contains(r.out,
        "okApp already run on " + case_.string()
        + ": remove log file 'log.okApp' to re-run")) << r.out;
    EXPECT_EQ(valueOf(r.out, "status"), "0");
    EXPECT_EQ(lines(readFile(case_ / "runs.okApp")).size(), 1u) << "ran twice";
    const std::string log = readFile(case_ / "log.okApp");
    EXPECT_TRUE(contains(log, "with: one"));
    EXPECT_FALSE(contains(log, "with: two"));
}

TEST_F(RunApplication, OverwriteReplacesLog)
{
    const auto r = sh(
        "runApplication okApp one\n"
        "runApplication -overwrite okApp two\n"
        "runApplication -o okApp three");

    EXPECT_EQ(lines(readFile(case_ / "runs.okApp")).size(), 3u);
    const std::string log = readFile(case_ / "log.okApp");
    EXPECT_FALSE(contains(log, "with: one"));
    EXPECT_FALSE(contains(log, "with: two"));
    EXPECT_TRUE(contains(log, "with: three")) << log;
    EXPECT_FALSE(contains(r.out, "already run"));
}

TEST_F(RunApplication, AppendExtendsLog)
{
    sh("runApplication okApp one\n"
       "runApplication -append okApp two\n"
       "runApplication -a okApp three");

    const std::string log = readFile(case_ / "log.okApp");
    const auto one = log.find("with: one");
    const auto two = log.find("with: two");
    const auto three = log.find("with: three");
    ASSERT_NE(one, std::string::npos) << log;
    ASSERT_NE(two, std::string::npos) << log;
    ASSERT_NE(three, std::string::npos) << log;
    EXPECT_LT(one, two);
    EXPECT_LT(two, three);
}

TEST_F(RunApplication, SuffixNamesLog)
{
    const auto r = sh(
        "runApplication -suffix coarse okApp one\n"
        "runApplication -s fine okApp two\n"
        "runApplication -s fine okApp three");

    EXPECT_FALSE(fs::exists(case_ / "log.okApp"));
    EXPECT_TRUE(contains(readFile(case_ / "log.okApp.coarse"), "with: one"));
    EXPECT_TRUE(contains(readFile(case_ / "log.okApp.fine"), "with: two"));
    EXPECT_TRUE(contains(r.out, "remove log file 'log.okApp.fine' to re-run")) << r.out;
    EXPECT_EQ(lines(readFile(case_ / "runs.okApp")).size(), 2u);
}

TEST_F(RunApplication, LogNamedAfterApplicationWithoutPath)
{
    const auto r = sh("runApplication " + quoted(bin_ / "okApp") + " x");

    EXPECT_TRUE(fs::exists(case_ / "log.okApp"));
    EXPECT_TRUE(contains(r.out, "Running okApp on")) << r.out;
}

TEST_F(RunApplication, DecomposeParDictGoesToApplication)
{
    sh("runApplication -decomposeParDict system/myDict okApp a");

    EXPECT_TRUE(contains(readFile(case_ / "log.okApp"),
        "with: a -decomposeParDict system/myDict"));
}

TEST_F(RunApplication, NoApplicationIsAnError)
{
    const auto r = sh("runApplication -o\necho \"status=$?\"");

    EXPECT_NE(valueOf(r.out, "status"), "0");
    EXPECT_FALSE(r.err.empty());
}


// * * * * * * * * * * * * * * * runParallel * * * * * * * * * * * * * * * * //

TEST_F(RunParallel, ProcessesFromDecomposeParDict)
{
    writeDict(case_ / "system/decomposeParDict",
        "numberOfSubdomains 4;\nmethod scotch;\n");

    const auto r = sh("runParallel okApp x y\necho \"status=$?\"");

    EXPECT_EQ(valueOf(r.out, "status"), "0") << r.err;
    EXPECT_TRUE(contains(r.out, "Running okApp on " + case_.string())) << r.out;
    const std::string log = readFile(case_ / "log.okApp");
    EXPECT_TRUE(contains(log, "mpirun -np 4 okApp -parallel x y")) << log;
}

TEST_F(RunParallel, NpOptionOverridesDictionary)
{
    writeDict(case_ / "system/decomposeParDict", "numberOfSubdomains 4;\n");

    sh("runParallel -np 2 -s two okApp");

    EXPECT_TRUE(contains(readFile(case_ / "log.okApp.two"), "mpirun -np 2 okApp -parallel"));
}

TEST_F(RunParallel, DecomposeParDictOptionGivesProcessesAndArgument)
{
    writeDict(case_ / "system/decomposeParDict", "numberOfSubdomains 4;\n");
    writeDict(case_ / "system/decomposeParDict.6", "numberOfSubdomains 6;\n");

    sh("runParallel -decomposeParDict system/decomposeParDict.6 okApp");

    EXPECT_TRUE(contains(readFile(case_ / "log.okApp"),
        "mpirun -np 6 okApp -parallel -decomposeParDict system/decomposeParDict.6"));
}

TEST_F(RunParallel, SkipsWhenLogExists)
{
    writeFile(case_ / "log.okApp", "old\n");

    const auto r = sh("runParallel -np 2 okApp");

    EXPECT_TRUE(contains(r.out, "remove log file 'log.okApp' to re-run")) << r.out;
    EXPECT_EQ(readFile(case_ / "log.okApp"), "old\n");
}

TEST_F(RunParallel, RealMpirunStartsApplication)
{
    // The real Open MPI (it needs permission to start as root, which runParallel gives)
    fs::remove(bin_ / "mpirun");
    // Debian's openfoam depends on Open MPI, so mpirun is always there
    ASSERT_EQ(run("command -v mpirun").status, 0) << "no mpirun on PATH";

    const auto r = sh("runParallel -np 1 okApp z\necho \"status=$?\"");

    EXPECT_EQ(valueOf(r.out, "status"), "0") << readFile(case_ / "log.okApp");
    EXPECT_TRUE(contains(readFile(case_ / "log.okApp"), "okApp ran with: -parallel z"))
        << readFile(case_ / "log.okApp");
}

TEST_F(RunParallel, ReturnsMpirunStatus)
{
    writeExecutable(bin_ / "mpirun", "#!/bin/sh\nexit 5\n");

    const auto r = sh("runParallel -np 2 okApp\necho \"status=$?\"");

    EXPECT_EQ(valueOf(r.out, "status"), "5");
}


// * * * * * * * * * * * * * getApplication and friends * * * * * * * * * * //

TEST_F(GetApplication, ReadsApplicationFromControlDict)
{
    writeDict(case_ / "system/controlDict",
        "application     icoFoam;\n\nstartFrom       startTime;\nendTime 0.5;\n");

    const auto r = sh("app=$(getApplication)\necho \"app=$app\"");

    EXPECT_EQ(valueOf(r.out, "app"), "icoFoam") << r.err;
}

TEST_F(GetApplication, NoControlDictGivesFalse)
{
    const auto r = sh("getApplication\necho \"status=$?\"");

    ASSERT_FALSE(lines(r.out).empty());
    EXPECT_EQ(lines(r.out).front(), "false");
    EXPECT_NE(valueOf(r.out, "status"), "0");
    EXPECT_TRUE(contains(r.err, "controlDict")) << r.err;
}

TEST_F(GetApplication, NoApplicationEntryGivesFalse)
{
    writeDict(case_ / "system/controlDict", "endTime 0.5;\n");

    const auto r = sh("$(getApplication) && echo ran || echo \"failed=$?\"");

    EXPECT_EQ(valueOf(r.out, "failed"), "1") << r.out;
    EXPECT_TRUE(contains(r.err, "application")) << r.err;
}

TEST_F(GetApplication, NumberOfProcessors)
{
    writeDict(case_ / "system/decomposeParDict", "numberOfSubdomains 3;\n");
    writeDict(case_ / "system/otherDict", "numberOfSubdomains 8;\n");

    const auto r = sh(
        "echo \"default=$(getNumberOfProcessors)\"\n"
        "echo \"other=$(getNumberOfProcessors system/otherDict)\"\n"
        "echo \"missing=$(getNumberOfProcessors system/none)\"");

    EXPECT_EQ(valueOf(r.out, "default"), "3") << r.err;
    EXPECT_EQ(valueOf(r.out, "other"), "8");
    EXPECT_EQ(valueOf(r.out, "missing"), "1");
}


// * * * * * * * * * * * * isTest, isParallel, isTrue * * * * * * * * * * * //

TEST_F(Switches, IsTestAndNotTest)
{
    const auto r = sh(
        "isTest -foo -test bar && echo t1=yes || echo t1=no\n"
        "isTest -foo bar && echo t2=yes || echo t2=no\n"
        "isTest && echo t3=yes || echo t3=no\n"
        "isTest -testing && echo t4=yes || echo t4=no\n"
        "notTest -test && echo n1=yes || echo n1=no\n"
        "notTest a b && echo n2=yes || echo n2=no\n");

    EXPECT_EQ(valueOf(r.out, "t1"), "yes");
    EXPECT_EQ(valueOf(r.out, "t2"), "no");
    EXPECT_EQ(valueOf(r.out, "t3"), "no");
    EXPECT_EQ(valueOf(r.out, "t4"), "no");
    EXPECT_EQ(valueOf(r.out, "n1"), "no");
    EXPECT_EQ(valueOf(r.out, "n2"), "yes");
}

TEST_F(Switches, IsParallel)
{
    const auto r = sh(
        "isParallel -case x -parallel && echo p1=yes || echo p1=no\n"
        "isParallel -test && echo p2=yes || echo p2=no\n");

    EXPECT_EQ(valueOf(r.out, "p1"), "yes");
    EXPECT_EQ(valueOf(r.out, "p2"), "no");
}

TEST_F(Switches, IsTrueWords)
{
    std::string body;
    for (const char* word : {"yes", "on", "true", "y", "t", "no", "off", "false", "n",
                             "f", "none", "maybe", "YES", ""})
    {
        body += "isTrue '" + std::string(word) + "' && echo 'w" + word
            + "=1' || echo 'w" + word + "=0'\n";
    }
    const auto r = sh(body);

    for (const char* word : {"yes", "on", "true", "y", "t"})
    {
        EXPECT_EQ(valueOf(r.out, std::string("w") + word), "1") << word;
    }
    for (const char* word : {"no", "off", "false", "n", "f", "none", "maybe", "YES", ""})
    {
        EXPECT_EQ(valueOf(r.out, std::string("w") + word), "0") << word;
    }
}

TEST_F(Switches, IsTrueReadsDictionaryEntry)
{
    writeDict(case_ / "system/switches", "runMe yes;\nskipMe off;\nsub { deep on; }\n");

    const auto r = sh(
        "isTrue -dict system/switches -entry runMe && echo a=1 || echo a=0\n"
        "isTrue -dict system/switches -entry skipMe && echo b=1 || echo b=0\n"
        "isTrue -dict system/switches -entry sub.deep && echo c=1 || echo c=0\n"
        "isTrue -dict system/switches -entry absent && echo d=1 || echo d=0\n"
        "isTrue -dict system/none -entry runMe && echo e=1 || echo e=0\n");

    EXPECT_EQ(valueOf(r.out, "a"), "1") << r.err;
    EXPECT_EQ(valueOf(r.out, "b"), "0");
    EXPECT_EQ(valueOf(r.out, "c"), "1");
    EXPECT_EQ(valueOf(r.out, "d"), "0");
    EXPECT_EQ(valueOf(r.out, "e"), "0");
}


// * * * * * * * * * * * * * * * CleanFunctions  * * * * * * * * * * * * * * //

TEST_F(CleanFunctions, CleanCaseRemovesGeneratedKeepsInputs)
{
    // Inputs
    writeDict(case_ / "0/U", "internalField uniform (0 0 0);\n");
    writeDict(case_ / "constant/transportProperties", "nu 0.01;\n");
    writeDict(case_ / "system/controlDict", "application icoFoam;\n");
    writeDict(case_ / "system/blockMeshDict", "scale 1;\n");
    // Generated
    for (const char* time : {"0.1", "1e-05", "2", "0.005", "-0.25", "1.5e+02"})
    {
        writeDict(case_ / time / "U", "internalField uniform (1 0 0);\n");
    }
    writeFile(case_ / "0.1/lagrangian/sph/positions", "()\n");
    writeFile(case_ / "2/uniform/time", "value 2;\n");
    writeFile(case_ / "log.icoFoam", "End\n");
    writeFile(case_ / "log.blockMesh.fine", "End\n");
    writeFile(case_ / "postProcessing/probes/0/U", "# Time\n");
    writeFile(case_ / "VTK/case_0.vtp", "<VTKFile/>\n");
    writeFile(case_ / "constant/sphMesh/points", "()\n");
    writeFile(case_ / "constant/polyMesh/points", "()\n");
    writeFile(case_ / "processor0/0/U", "x\n");
    writeFile(case_ / "case.foam", "");
    writeFile(case_ / "system/machines", "localhost\n");

    const auto r = sh("cleanCase\necho \"status=$?\"");

    EXPECT_EQ(valueOf(r.out, "status"), "0") << r.err;
    EXPECT_TRUE(contains(r.out, "Cleaning case " + case_.string())) << r.out;

    for (const char* gone : {"0.1", "1e-05", "2", "0.005", "-0.25", "1.5e+02", "log.icoFoam",
                             "log.blockMesh.fine", "postProcessing", "VTK", "constant/sphMesh",
                             "constant/polyMesh", "processor0", "case.foam",
                             "system/machines"})
    {
        EXPECT_FALSE(fs::exists(case_ / gone)) << gone << " should be removed";
    }
    for (const char* kept : {"0/U", "constant/transportProperties", "system/controlDict",
                             "system/blockMeshDict"})
    {
        EXPECT_TRUE(fs::exists(case_ / kept)) << kept << " should be kept";
    }
}

TEST_F(CleanFunctions, TimeRemovalOnlyTakesNumericFolders)
{
    for (const char* dir : {"0", "0.orig", "0.0", "validation", "2abc", "1.2.3", "e5", "1e"})
    {
        fs::create_directories(case_ / dir);
    }
    writeFile(case_ / "5", "a file named like a time\n");
    writeFile(case_ / "0.5", "another\n");
    fs::create_directories(case_ / "0.25");

    sh("cleanTimeDirectories");

    EXPECT_FALSE(fs::exists(case_ / "0.25"));
    for (const char* kept : {"0", "0.orig", "0.0", "validation", "2abc", "1.2.3", "e5", "1e",
                             "5", "0.5", "constant", "system"})
    {
        EXPECT_TRUE(fs::exists(case_ / kept)) << kept << " should be kept";
    }
}

TEST_F(CleanFunctions, PolyMeshKeptWhenItHoldsBlockMeshDict)
{
    writeDict(case_ / "constant/polyMesh/blockMeshDict", "scale 1;\n");
    writeFile(case_ / "constant/polyMesh/points", "()\n");

    const auto r = sh("cleanCase");

    EXPECT_TRUE(fs::exists(case_ / "constant/polyMesh/blockMeshDict"));
    EXPECT_TRUE(contains(r.err, "blockMeshDict")) << "no warning: " << r.err;
}

TEST_F(CleanFunctions, ZeroRemovedOnlyWhenOrigRestoresIt)
{
    writeFile(case_ / "0/U", "x\n");
    writeFile(case_ / "0.orig/U", "x\n");

    sh("cleanCase");

    EXPECT_FALSE(fs::exists(case_ / "0"));
    EXPECT_TRUE(fs::exists(case_ / "0.orig/U"));
}

TEST_F(CleanFunctions, CleanCase0RemovesZero)
{
    writeFile(case_ / "0/U", "x\n");
    writeFile(case_ / "1/U", "x\n");

    sh("cleanCase0");

    EXPECT_FALSE(fs::exists(case_ / "0"));
    EXPECT_FALSE(fs::exists(case_ / "1"));
    EXPECT_TRUE(fs::exists(case_ / "system"));
}

TEST_F(CleanFunctions, CleanSamplesAndPostProcessing)
{
    for (const char* dir : {"sets", "samples", "sampleSurfaces", "postProcessing-old",
                            "EnSight", "surfaceSampling"})
    {
        writeFile(case_ / dir / "data", "x\n");
    }

    sh("cleanSamples");
    EXPECT_FALSE(fs::exists(case_ / "sets"));
    EXPECT_FALSE(fs::exists(case_ / "samples"));
    EXPECT_FALSE(fs::exists(case_ / "sampleSurfaces"));
    EXPECT_TRUE(fs::exists(case_ / "EnSight"));

    sh("cleanPostProcessing");
    EXPECT_FALSE(fs::exists(case_ / "postProcessing-old"));
    EXPECT_FALSE(fs::exists(case_ / "EnSight"));
    EXPECT_FALSE(fs::exists(case_ / "surfaceSampling"));
    EXPECT_TRUE(fs::exists(case_ / "system"));
}

TEST_F(CleanFunctions, RemoveCase)
{
    writeFile(work_ / "other/system/controlDict", "x\n");

    const auto r = sh("removeCase ../other\necho \"status=$?\"\n"
                      "removeCase\necho \"noArg=$?\"");

    EXPECT_FALSE(fs::exists(work_ / "other"));
    EXPECT_TRUE(contains(r.out, "Removing case ../other")) << r.out;
    EXPECT_EQ(valueOf(r.out, "status"), "0");
    EXPECT_NE(valueOf(r.out, "noArg"), "0");
    EXPECT_TRUE(fs::exists(case_));
}


// * * * * * * * * * * * * * cloneCase, restore0Dir  * * * * * * * * * * * * //

TEST_F(CloneCase, CopiesConstantSystemAndZero)
{
    writeDict(case_ / "system/controlDict", "application icoFoam;\n");
    writeDict(case_ / "constant/transportProperties", "nu 0.01;\n");
    writeFile(case_ / "0/U", "x\n");
    writeFile(case_ / "0.orig/U", "x\n");
    writeFile(case_ / "log.icoFoam", "End\n");
    writeFile(case_ / "0.5/U", "x\n");

    const auto r = sh("cloneCase case caseFine\necho \"status=$?\"", work_);

    EXPECT_EQ(valueOf(r.out, "status"), "0") << r.err;
    const fs::path clone = work_ / "caseFine";
    EXPECT_EQ(readFile(clone / "system/controlDict"), readFile(case_ / "system/controlDict"));
    EXPECT_TRUE(fs::exists(clone / "constant/transportProperties"));
    EXPECT_TRUE(fs::exists(clone / "0/U"));
    EXPECT_TRUE(fs::exists(clone / "0.orig/U"));
    EXPECT_FALSE(fs::exists(clone / "log.icoFoam"));
    EXPECT_FALSE(fs::exists(clone / "0.5"));
}

TEST_F(CloneCase, RefusesExistingDestination)
{
    writeDict(case_ / "system/controlDict", "application icoFoam;\n");
    writeFile(work_ / "caseFine/mine", "keep me\n");

    const auto r = sh("cloneCase case caseFine\necho \"status=$?\"", work_);

    EXPECT_NE(valueOf(r.out, "status"), "0");
    EXPECT_FALSE(r.err.empty());
    EXPECT_EQ(readFile(work_ / "caseFine/mine"), "keep me\n");
    EXPECT_FALSE(fs::exists(work_ / "caseFine/system"));
}

TEST_F(CloneCase, RefusesSourceThatIsNoCase)
{
    fs::create_directories(work_ / "notACase/system");

    const auto r = sh("cloneCase notACase copy\necho \"status=$?\"", work_);

    EXPECT_NE(valueOf(r.out, "status"), "0");
    EXPECT_FALSE(fs::exists(work_ / "copy"));
}

TEST_F(CloneCase, Restore0DirReplacesZero)
{
    writeFile(case_ / "0.orig/U", "original\n");
    writeFile(case_ / "0/U", "changed\n");
    writeFile(case_ / "0/alpha.water", "from setFields\n");
    writeFile(case_ / "processor0/0/U", "changed\n");

    const auto r = sh("restore0Dir\necho \"status=$?\"");

    EXPECT_EQ(valueOf(r.out, "status"), "0");
    EXPECT_EQ(readFile(case_ / "0/U"), "original\n");
    EXPECT_FALSE(fs::exists(case_ / "0/alpha.water"));
    EXPECT_EQ(readFile(case_ / "processor0/0/U"), "changed\n");
    EXPECT_TRUE(contains(r.err, "0.orig")) << r.err;

    sh("restore0Dir -processor");
    EXPECT_EQ(readFile(case_ / "processor0/0/U"), "original\n");
}


// * * * * * * * * * * * * * * * * etc/bashrc  * * * * * * * * * * * * * * * //

TEST_F(Bashrc, SetsEnvironmentOnceFromAnyFolder)
{
    const fs::path project = fs::canonical(sourceDir);
    writeFile(work_ / "env.sh",
        ". " + quoted(project / "etc/bashrc") + "\n"
        "echo \"status=$?\"\n"
        ". " + quoted(project / "etc/bashrc") + "\n"
        "echo \"SPHFOAM_PROJECT_DIR=$SPHFOAM_PROJECT_DIR\"\n"
        "echo \"FOAM_SPHFOAM_TOOLS=$FOAM_SPHFOAM_TOOLS\"\n"
        "echo \"WM_PROJECT_DIR=$WM_PROJECT_DIR\"\n"
        "echo \"PATH=$PATH\"\n"
        "echo \"LD_LIBRARY_PATH=$LD_LIBRARY_PATH\"\n");

    const auto r = run("cd " + quoted(case_) + " && env -u WM_PROJECT_DIR -u SPHFOAM_PROJECT_DIR"
        " LD_LIBRARY_PATH=/opt/some/lib bash " + quoted(work_ / "env.sh"));

    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(valueOf(r.out, "status"), "0");
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_EQ(valueOf(r.out, "SPHFOAM_PROJECT_DIR"), project.string());
    EXPECT_EQ(valueOf(r.out, "FOAM_SPHFOAM_TOOLS"), (project / "bin/tools").string());
    EXPECT_EQ(valueOf(r.out, "WM_PROJECT_DIR"), "/usr/share/openfoam");

    const auto path = splitPath(valueOf(r.out, "PATH"));
    const std::string bin = (project / "platforms/bin").string();
    ASSERT_FALSE(path.empty());
    EXPECT_EQ(path.front(), bin);
    EXPECT_EQ(std::count(path.begin(), path.end(), bin), 1);
    EXPECT_NE(std::find(path.begin(), path.end(), "/usr/bin"), path.end());

    const auto libs = splitPath(valueOf(r.out, "LD_LIBRARY_PATH"));
    const std::vector<std::string> expected{(project / "platforms/lib").string(), "/opt/some/lib"};
    EXPECT_EQ(libs, expected);
}

TEST_F(Bashrc, KeepsExistingOpenFoamFolderOnly)
{
    const fs::path bashrc = fs::canonical(sourceDir) / "etc/bashrc";
    const fs::path existing = work_ / "myOpenFOAM";
    fs::create_directories(existing);

    const auto kept = run("env WM_PROJECT_DIR=" + quoted(existing) + " bash -c '. \"$0\";"
        " echo \"WM_PROJECT_DIR=$WM_PROJECT_DIR\"' " + quoted(bashrc));
    EXPECT_EQ(valueOf(kept.out, "WM_PROJECT_DIR"), existing.string()) << kept.err;

    const auto replaced = run("env WM_PROJECT_DIR=/no/such/folder bash -c '. \"$0\";"
        " echo \"WM_PROJECT_DIR=$WM_PROJECT_DIR\"' " + quoted(bashrc));
    EXPECT_EQ(valueOf(replaced.out, "WM_PROJECT_DIR"), "/usr/share/openfoam") << replaced.err;
}

TEST_F(Bashrc, SwitchingProjectsDropsTheOldFolders)
{
    const fs::path project = fs::canonical(sourceDir);
    const fs::path other = fs::canonical(work_) / "otherProject";
    fs::create_directories(other / "etc");
    fs::copy_file(project / "etc/bashrc", other / "etc/bashrc");
    writeFile(other / "bin/tools/RunFunctions", "\n");

    writeFile(work_ / "env.sh",
        ". " + quoted(project / "etc/bashrc") + "\n"
        ". " + quoted(other / "etc/bashrc") + "\n"
        "echo \"SPHFOAM_PROJECT_DIR=$SPHFOAM_PROJECT_DIR\"\n"
        "echo \"PATH=$PATH\"\n");
    const auto r = run("bash " + quoted(work_ / "env.sh"));

    EXPECT_EQ(valueOf(r.out, "SPHFOAM_PROJECT_DIR"), other.string()) << r.err;
    const auto path = splitPath(valueOf(r.out, "PATH"));
    ASSERT_FALSE(path.empty());
    EXPECT_EQ(path.front(), (other / "platforms/bin").string());
    EXPECT_EQ(std::count(path.begin(), path.end(), (project / "platforms/bin").string()), 0);
}

TEST_F(Bashrc, PosixShellFromProjectFolder)
{
    const fs::path project = fs::canonical(sourceDir);

    const auto r = run("cd " + quoted(project) + " && env -u SPHFOAM_PROJECT_DIR /bin/sh -c"
        " '. ./etc/bashrc && echo \"SPHFOAM_PROJECT_DIR=$SPHFOAM_PROJECT_DIR\"'");

    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(valueOf(r.out, "SPHFOAM_PROJECT_DIR"), project.string());
}

TEST_F(Bashrc, TutorialHeaderRunsUnderPosixShell)
{
    const fs::path project = fs::canonical(sourceDir);
    writeDict(case_ / "system/controlDict", "application okApp;\n");
    writeExecutable(case_ / "Allrun",
        "#!/bin/sh\n"
        "cd \"${0%/*}\" || exit 1                          # Run from this directory\n"
        ". \"${SPHFOAM_PROJECT_DIR:?source etc/bashrc first}\"/bin/tools/RunFunctions\n"
        "#------------------------------------------------------------------------------\n"
        "\n"
        "runApplication $(getApplication) \"$@\"\n");

    // With the environment of etc/bashrc, from another folder
    writeFile(work_ / "run.sh",
        ". " + quoted(project / "etc/bashrc") + "\n"
        "PATH=" + quoted(bin_) + ":$PATH\n"
        "/bin/sh case/Allrun -test\n"
        "echo \"status=$?\"\n");
    const auto r = run("cd " + quoted(work_) + " && env -u SPHFOAM_PROJECT_DIR bash "
        + quoted(work_ / "run.sh"));

    EXPECT_EQ(valueOf(r.out, "status"), "0") << r.err;
    EXPECT_TRUE(contains(readFile(case_ / "log.okApp"), "okApp ran with: -test"))
        << r.out << r.err;

    // Without it the header stops the script with a hint
    fs::remove(case_ / "log.okApp");
    const auto bare = run("env -u SPHFOAM_PROJECT_DIR /bin/sh " + quoted(case_ / "Allrun"));
    EXPECT_NE(bare.status, 0);
    EXPECT_TRUE(contains(bare.err, "source etc/bashrc first")) << bare.err;
    EXPECT_FALSE(fs::exists(case_ / "log.okApp"));
}


// * * * * * * * * * * * * * fishPass's setParameters * * * * * * * * * * * //

// The fish-pass writes the FV cell counts from nb and the slot's rise;
// a rise that would put the slot's bands out of order is refused by name
TEST_F(FishFunctions, SetParametersSizesTheBandsAndRefusesABadSlotRise)
{
    const fs::path functions =
        sourceDir / "tutorials/turbulence/fishPass/fishFunctions";
    const auto parameters = [&](const std::string& rise)
    {
        writeFile(case_ / "system/fishParameters",
            "b 0.3;\nslotRise " + rise + ";\nnb 1;\nnx0 1;\nn0 1;\nn1 1;\n"
            "n2 1;\nn3 1;\ndr 1;\ntEnd 1;\n");
    };

    parameters("1");
    auto r = sh(". " + quoted(functions) + "\nsetParameters . 10 0.03 20\n"
        "echo \"status=$?\"\nparameter n0 system/fishParameters");
    EXPECT_EQ(valueOf(r.out, "status"), "0") << r.err;
    // The band below the slot, 1 b high at x = 7 b and 2 b at x = 9 b
    EXPECT_EQ(lines(r.out).back(), "15") << r.out;
    EXPECT_TRUE(contains(readFile(case_ / "system/fishParameters"), "dr              0.03;"));

    for (const std::string bad : {"-1", "5.5", "steep"})
    {
        parameters(bad);
        r = sh(". " + quoted(functions) + "\nsetParameters . 10 0.03 20\n"
            "echo \"status=$?\"");
        EXPECT_EQ(valueOf(r.out, "status"), "1") << bad;
        EXPECT_TRUE(contains(r.err, "slotRise " + bad + ": expected a number above -1"))
            << r.err;
    }
}


// ************************************************************************* //
