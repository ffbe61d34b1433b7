/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.

Description
    vtkCaseWriter: files land where foamToVTK puts a case's output
    (VTK/<case>_<timeIndex>.vtp), both series stay current and list only
    files that exist, static walls are written once, and a restarted run
    continues the series.

\*---------------------------------------------------------------------------*/

#include "vtkCaseWriter.H"
#include "vtkPolyFileReader.H"
#include "vtkTestTools.H"

#include <fstream>

using namespace Foam;
using namespace vtkTest;

namespace
{

//- Two particles moving right with time t
SPH::vtkParticleFile particlesAt(const scalar t)
{
    SPH::vtkParticleFile particles
    (
        List<vector2D>({vector2D(0.1 + t, 0.2), vector2D(0.3 + t, 0.4)})
    );
    particles.addPointField("p", scalarList({1000*t, 2000*t}));
    particles.addPointField("U", List<vector2D>(2, vector2D(1, 0)));
    return particles;
}

//- A floor segment
SPH::vtkWallFile floorWall()
{
    SPH::vtkWallFile walls
    (
        List<vector2D>({vector2D(0, 0), vector2D(1, 0)}),
        List<labelPair>({labelPair(0, 1)})
    );
    walls.addCellField("normal", List<vector2D>({vector2D(0, 1)}));
    walls.addCellField("patch", labelList({0}));
    return walls;
}

//- Names listed in a series file, read by Python's json module, with a
//  check that each listed file exists
std::vector<std::string> listedFiles(const fileName& series)
{
    const inspection json = inspect("series", series);
    EXPECT_EQ(json.status, 0) << series;

    std::vector<std::string> names;
    for (const auto& f : json.all("file"))
    {
        EXPECT_EQ(f.at(3), "1") << f.at(1) << " is listed but missing";
        names.push_back(f.at(1));
    }
    return names;
}

} // End anonymous namespace


TEST(vtkCaseWriter, writesFoamToVtkLayout)
{
    const fileName caseDir(freshDir()/"dam");
    SPH::vtkCaseWriter vtk(caseDir, "dam");

    for (const label index : {0, 20, 40})
    {
        const scalar t = 0.0025*index;
        vtk.writeParticles(particlesAt(t), index, t);
        EXPECT_TRUE(vtk.writeWalls(floorWall(), index, t));
    }

    EXPECT_EQ(vtk.vtkDir(), caseDir/"VTK");
    EXPECT_EQ(vtk.particleFile(20), caseDir/"VTK/dam_20.vtp");
    EXPECT_EQ(vtk.wallFile(20), caseDir/"VTK/dam_walls_20.vtp");

    EXPECT_EQ
    (
        listedFiles(caseDir/"VTK/dam.vtp.series"),
        std::vector<std::string>({"dam_0.vtp", "dam_20.vtp", "dam_40.vtp"})
    );
    EXPECT_EQ
    (
        listedFiles(caseDir/"VTK/dam_walls.vtp.series"),
        std::vector<std::string>
        ({"dam_walls_0.vtp", "dam_walls_20.vtp", "dam_walls_40.vtp"})
    );

    // The file of index 20 holds the data of t = 0.05
    const inspection vtp = inspect("vtp", caseDir/"VTK/dam_20.vtp");
    ASSERT_EQ(vtp.status, 0);
    EXPECT_TRUE(sameBits(number(vtp.first("time").at(1)), 0.0025*20));
    EXPECT_EQ(vtp.first("points"), std::vector<std::string>({"points", "2"}));
    EXPECT_TRUE(sameBits(number(vtp.values("p").at(1).at(3)), 2000*0.0025*20));

    const inspection walls = inspect("vtp", caseDir/"VTK/dam_walls_40.vtp");
    ASSERT_EQ(walls.status, 0);
    EXPECT_EQ(walls.first("lines"), std::vector<std::string>({"lines", "1"}));
    EXPECT_EQ(walls.all("cellarray").size(), 2u);
}


TEST(vtkCaseWriter, staticWallsWrittenOnce)
{
    const fileName caseDir(freshDir());
    SPH::vtkCaseWriter vtk(caseDir, "tank", SPH::vtkCaseWriter::staticWalls);

    EXPECT_TRUE(vtk.wallsDue());
    EXPECT_TRUE(vtk.writeWalls(floorWall(), 0, 0));
    EXPECT_FALSE(vtk.wallsDue());
    EXPECT_FALSE(vtk.writeWalls(floorWall(), 10, 0.1));

    vtk.writeParticles(particlesAt(0), 0, 0);
    vtk.writeParticles(particlesAt(0.1), 10, 0.1);

    // One wall step, shown by ParaView at every time of the particles
    EXPECT_EQ
    (
        listedFiles(caseDir/"VTK/tank_walls.vtp.series"),
        std::vector<std::string>({"tank_walls_0.vtp"})
    );
    EXPECT_FALSE(isFile(vtk.wallFile(10), false));
    EXPECT_EQ(vtk.particleSeries().size(), 2);
}


TEST(vtkCaseWriter, movingWallsWrittenEachTime)
{
    const fileName caseDir(freshDir());
    SPH::vtkCaseWriter vtk(caseDir, "gate");

    EXPECT_TRUE(vtk.writeWalls(floorWall(), 0, 0));
    EXPECT_TRUE(vtk.wallsDue());
    EXPECT_TRUE(vtk.writeWalls(floorWall(), 5, 0.5));

    EXPECT_EQ(vtk.wallSeries().size(), 2);
    EXPECT_TRUE(isFile(vtk.wallFile(5), false));
}


TEST(vtkCaseWriter, restartContinuesSeries)
{
    const fileName caseDir(freshDir());
    {
        SPH::vtkCaseWriter firstRun(caseDir, "dam");
        for (label index = 0; index <= 3; ++index)
        {
            firstRun.writeParticles(particlesAt(0.1*index), index, 0.1*index);
        }
    }

    // Restart from the write of index 2: writes 2 (again) and 3 (again)
    SPH::vtkCaseWriter restart(caseDir, "dam");
    EXPECT_EQ(restart.particleSeries().size(), 4);

    restart.writeParticles(particlesAt(0.2), 2, 0.2);
    EXPECT_EQ
    (
        listedFiles(caseDir/"VTK/dam.vtp.series"),
        std::vector<std::string>({"dam_0.vtp", "dam_1.vtp", "dam_2.vtp"})
    );

    restart.writeParticles(particlesAt(0.25), 3, 0.25);
    EXPECT_TRUE(sameBits(SPH::vtkPolyFileReader(restart.particleFile(3)).time(), 0.25));
    EXPECT_EQ(restart.particleSeries().steps().last().time, 0.25);
}


TEST(vtkCaseWriter, uncreatableCaseFolderIsFatal)
{
    const fileName dir(freshDir());
    std::ofstream(dir/"notAFolder") << "x\n";

    SPH::vtkCaseWriter vtk(dir/"notAFolder", "dam");

    const std::string message =
        fatalMessage([&]{ vtk.writeParticles(particlesAt(0), 0, 0); });

    EXPECT_NE(message.find("dam_0.vtp"), std::string::npos) << message;
    EXPECT_TRUE(vtk.particleSeries().empty());
}


// ************************************************************************* //
