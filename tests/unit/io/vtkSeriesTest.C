/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.

Description
    vtkSeries: the .series file is the JSON layout of foamToVTK (checked
    with Python's json.load through vtkInspect.py), a step with the same
    name is replaced, a restart prunes the later steps, a malformed file is
    survived, and times read back exactly (tolerance 0).

\*---------------------------------------------------------------------------*/

#include "vtkSeries.H"
#include "vtkTestTools.H"

#include <fstream>

using namespace Foam;
using namespace vtkTest;

namespace
{

//- Names of the steps, in order
std::vector<std::string> namesOf(const SPH::vtkSeries& series)
{
    std::vector<std::string> names;
    for (const auto& s : series.steps())
    {
        names.push_back(s.name);
    }
    return names;
}

//- Times of the steps, in order
std::vector<double> timesOf(const SPH::vtkSeries& series)
{
    std::vector<double> times;
    for (const auto& s : series.steps())
    {
        times.push_back(s.time);
    }
    return times;
}

void writeText(const fileName& file, const std::string& text)
{
    std::ofstream(file) << text;
}

} // End anonymous namespace


TEST(vtkSeries, missingFileIsEmptySeries)
{
    const SPH::vtkSeries series(freshDir()/"none.vtp.series");

    EXPECT_TRUE(series.empty());
    EXPECT_FALSE(isFile(series.file(), false));
}


TEST(vtkSeries, appendWritesParaViewJson)
{
    const fileName dir(freshDir());
    SPH::vtkSeries series(dir/"dam.vtp.series");

    series.append(dir/"dam_0.vtp", 0);
    series.append(dir/"dam_20.vtp", 0.05);

    const inspection json = inspect("series", series.file());
    ASSERT_EQ(json.status, 0) << "json.load failed on " << series.file();
    EXPECT_EQ(json.first("version"), std::vector<std::string>({"version", "1.0"}));
    EXPECT_EQ(json.first("files"), std::vector<std::string>({"files", "2"}));

    // The vtp files were never written, hence exists = 0
    const auto files = json.all("file");
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(files[0], std::vector<std::string>({"file", "dam_0.vtp", "0.0", "0"}));
    EXPECT_EQ(files[1], std::vector<std::string>({"file", "dam_20.vtp", "0.05", "0"}));
    EXPECT_FALSE(isFile(series.file() + ".tmp", false));
}


TEST(vtkSeries, layoutMatchesFoamToVtk)
{
    // The text itself, as in openfoam-conventions.md section 6, so a diff
    // against foamToVTK's series shows only the file names
    const fileName dir(freshDir());
    SPH::vtkSeries series(dir/"cavity.vtp.series");
    series.append("cavity_0.vtp", 0);
    series.append("cavity_20.vtp", 0.1);

    std::ifstream is(series.file());
    const std::string text
    (
        (std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>()
    );

    EXPECT_EQ
    (
        text,
        "{\n"
        "  \"file-series-version\" : \"1.0\",\n"
        "  \"files\" : [\n"
        "    { \"name\" : \"cavity_0.vtp\", \"time\" : 0 },\n"
        "    { \"name\" : \"cavity_20.vtp\", \"time\" : 0.1 }\n"
        "  ]\n"
        "}\n"
    );
}


TEST(vtkSeries, sameNameReplacesStep)
{
    const fileName dir(freshDir());
    SPH::vtkSeries series(dir/"a.vtp.series");

    series.append("a_0.vtp", 0);
    series.append("a_1.vtp", 1);
    series.append("a_2.vtp", 2);
    series.append("a_1.vtp", 1.5);   // same file rewritten at a later time

    EXPECT_EQ(namesOf(series), std::vector<std::string>({"a_0.vtp", "a_1.vtp"}));
    EXPECT_EQ(timesOf(series), std::vector<double>({0, 1.5}));

    // and the file says the same
    const SPH::vtkSeries reread(series.file());
    EXPECT_EQ(namesOf(reread), namesOf(series));
    EXPECT_EQ(timesOf(reread), timesOf(series));
}


TEST(vtkSeries, restartPrunesLaterTimes)
{
    const fileName dir(freshDir());
    {
        SPH::vtkSeries firstRun(dir/"a.vtp.series");
        for (label i = 0; i <= 7; ++i)
        {
            firstRun.append("a_" + Foam::name(10*i) + ".vtp", 0.1*i);
        }
    }

    // A second run restarting from the write at t = 0.5 (index 50): its
    // first output is at 0.5 under the same name, then 0.55
    SPH::vtkSeries restart(dir/"a.vtp.series");
    ASSERT_EQ(restart.size(), 8);

    restart.append("a_50.vtp", 0.1*5);
    EXPECT_EQ(restart.size(), 6);
    EXPECT_EQ(restart.steps().last().name, "a_50.vtp");

    restart.append("a_55.vtp", 0.55);
    EXPECT_EQ
    (
        namesOf(SPH::vtkSeries(dir/"a.vtp.series")),
        std::vector<std::string>
        ({"a_0.vtp", "a_10.vtp", "a_20.vtp", "a_30.vtp", "a_40.vtp", "a_50.vtp",
          "a_55.vtp"})
    );

    // Restart from an earlier time under new names drops 0.3 onwards too
    restart.append("b_25.vtp", 0.25);
    EXPECT_EQ(timesOf(restart), std::vector<double>({0, 0.1, 0.2, 0.25}));
}


TEST(vtkSeries, timesReadBackExactly)
{
    const fileName dir(freshDir());
    // Increasing, or append would prune
    const std::vector<double> times({1e-7, 0.1 + 0.2, 1.0/3.0, 12345.678, 1e5 + 1e-9});

    SPH::vtkSeries series(dir/"t.vtp.series");
    for (std::size_t i = 0; i < times.size(); ++i)
    {
        series.append("t_" + Foam::name(label(i)) + ".vtp", times[i]);
    }

    const SPH::vtkSeries reread(series.file());
    const std::vector<double> readTimes = timesOf(reread);
    ASSERT_EQ(readTimes.size(), times.size());
    for (std::size_t i = 0; i < times.size(); ++i)
    {
        EXPECT_TRUE(sameBits(readTimes[i], times[i])) << i;
    }

    // Python reads the same doubles from the text
    const inspection json = inspect("series", series.file());
    ASSERT_EQ(json.status, 0);
    const auto files = json.all("file");
    ASSERT_EQ(files.size(), times.size());
    for (std::size_t i = 0; i < times.size(); ++i)
    {
        EXPECT_TRUE(sameBits(number(files[i][2]), times[i])) << files[i][2];
    }
}


TEST(vtkSeries, namesAreRelativeToSeriesFolder)
{
    const fileName dir(freshDir());
    mkDir(dir/"VTK/sub");
    writeText(dir/"VTK/x.vtp", "");
    writeText(dir/"VTK/sub/y.vtp", "");

    SPH::vtkSeries series(dir/"VTK/x.vtp.series");
    series.append(dir/"VTK/x.vtp", 0);                 // absolute path
    series.append(dir/"VTK/./sub/../sub/y.vtp", 1);    // unclean path
    series.append("z.vtp", 2);                         // bare name

    EXPECT_EQ
    (
        namesOf(series),
        std::vector<std::string>({"x.vtp", "sub/y.vtp", "z.vtp"})
    );

    // ParaView resolves them from the series folder
    const auto files = inspect("series", series.file()).all("file");
    ASSERT_EQ(files.size(), 3u);
    EXPECT_EQ(files[0][3], "1");
    EXPECT_EQ(files[1][3], "1");
    EXPECT_EQ(files[2][3], "0");

    const std::string message =
        fatalMessage([&]{ series.append(dir/"elsewhere.vtp", 3); });
    EXPECT_NE(message.find("not inside the series folder"), std::string::npos)
        << message;
    EXPECT_EQ(series.size(), 3);
}


TEST(vtkSeries, malformedFileWarnsAndStartsFresh)
{
    const fileName dir(freshDir());
    const std::vector<std::string> broken
    ({
        "",
        "not json",
        "{ \"file-series-version\" : \"1.0\", \"files\" : [ { \"name\" : \"a.vtp\" ",
        "{ \"files\" : [ { \"name\" : \"a.vtp\" } ] }",          // no time
        "{ \"files\" : [ { \"name\" : \"a.vtp\", \"time\" : x } ] }",
        "{ \"file-series-version\" : \"1.0\" }",                 // no files
        "{ \"files\" : [] } trailing"
    });

    for (std::size_t i = 0; i < broken.size(); ++i)
    {
        const fileName file(dir/("broken" + Foam::name(label(i)) + ".vtp.series"));
        writeText(file, broken[i]);

        SPH::vtkSeries series(file);
        EXPECT_TRUE(series.empty()) << broken[i];

        series.append("b_1.vtp", 1);
        const inspection json = inspect("series", file);
        EXPECT_EQ(json.status, 0) << broken[i];
        EXPECT_EQ(json.first("files"), std::vector<std::string>({"files", "1"}));
    }
}


TEST(vtkSeries, readsForeignLayout)
{
    // Other writers (ParaView, foamToVTK, hand edits) lay the JSON out
    // differently and may add members; only the steps matter
    const fileName file(freshDir()/"f.vtp.series");
    writeText
    (
        file,
        "{\"file-series-version\":\"1.0\",\"note\":{\"by\":[1,2.5e-3,true,null]},"
        "\r\n\"files\":[{\"time\":-1e-3,\"name\":\"f_0.vtp\"},"
        "{\"name\":\"dir\\/f_\\u0031.vtp\",\"time\":2E1,\"extra\":false}]}"
    );

    const SPH::vtkSeries series(file);

    EXPECT_EQ(namesOf(series), std::vector<std::string>({"f_0.vtp", "dir/f_1.vtp"}));
    EXPECT_EQ(timesOf(series), std::vector<double>({-1e-3, 20}));
}


TEST(vtkSeries, staleTmpFileIsReplaced)
{
    // A crash between writing the .tmp and renaming it leaves a partial
    // .tmp beside an intact series; the next write must not be confused
    const fileName dir(freshDir());
    SPH::vtkSeries series(dir/"s.vtp.series");
    series.append("s_0.vtp", 0);
    writeText(series.file() + ".tmp", "{ \"files\" : [ { \"na");

    SPH::vtkSeries restart(series.file());
    EXPECT_EQ(restart.size(), 1);
    restart.append("s_1.vtp", 1);

    const inspection json = inspect("series", series.file());
    ASSERT_EQ(json.status, 0);
    EXPECT_EQ(json.first("files"), std::vector<std::string>({"files", "2"}));
    EXPECT_FALSE(isFile(series.file() + ".tmp", false));
}


TEST(vtkSeries, nonFiniteTimeIsFatal)
{
    SPH::vtkSeries series(freshDir()/"n.vtp.series");

    throwingErrors guard;
    EXPECT_THROW(series.append("n_0.vtp", std::nan("")), Foam::error);
    EXPECT_TRUE(series.empty());
}


TEST(vtkSeries, uncreatableFolderIsFatal)
{
    const fileName dir(freshDir());
    writeText(dir/"notAFolder", "x\n");
    SPH::vtkSeries series(dir/"notAFolder/VTK/a.vtp.series");

    const std::string message = fatalMessage([&]{ series.append("a_0.vtp", 0); });
    EXPECT_NE(message.find("a.vtp.series"), std::string::npos) << message;
}


// ************************************************************************* //
