/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.

Description
    vtkWallFile: wall vertices, line segments and their fields come back
    exactly through libsph's reader and through python3-vtk9.  Float64 data
    is compared bit for bit (tolerance 0).

\*---------------------------------------------------------------------------*/

#include "vtkWallFile.H"
#include "vtkPolyFileReader.H"
#include "vtkTestTools.H"

#include <cmath>

using namespace Foam;
using namespace vtkTest;

namespace
{

//- An open tank: three walls of a unit square, rotated so no coordinate is
//  a short decimal; the top edge is absent
struct tankData
{
    List<vector2D> vertices;
    List<labelPair> segments;
    List<vector2D> normals;
    labelList patch;
    scalarList angle;

    tankData()
    :
        vertices(4),
        segments(3),
        normals(3),
        patch({0, 1, 2}),
        angle(4)
    {
        const scalar c = std::cos(0.3);
        const scalar s = std::sin(0.3);
        const auto rotated = [&](scalar x, scalar y)
        {
            return vector2D(c*x - s*y, s*x + c*y);
        };

        vertices[0] = rotated(0, 1);
        vertices[1] = rotated(0, 0);
        vertices[2] = rotated(1, 0);
        vertices[3] = rotated(1, 1);

        segments[0] = labelPair(0, 1);
        segments[1] = labelPair(1, 2);
        segments[2] = labelPair(2, 3);

        normals[0] = rotated(1, 0);
        normals[1] = rotated(0, 1);
        normals[2] = rotated(-1, 0);

        angle[0] = M_PI;
        angle[1] = M_PI/2;
        angle[2] = M_PI/2;
        angle[3] = M_PI;
    }

    void addFields(SPH::vtkWallFile& walls) const
    {
        walls.addCellField("normal", normals);
        walls.addCellField("patch", patch);
        walls.addPointField("angle", angle);
    }
};

const scalar writeTime = 2.0/3.0;

} // End anonymous namespace


TEST(vtkWallFile, roundTripGivesSegmentsAndFields)
{
    const fileName file(freshDir()/"walls.vtp");
    const tankData tank;

    SPH::vtkWallFile walls(tank.vertices, tank.segments);
    tank.addFields(walls);
    EXPECT_EQ(walls.nSegments(), 3);
    walls.write(file, writeTime);

    const SPH::vtkPolyFileReader vtp(file);

    ASSERT_EQ(vtp.points().size(), 4);
    forAll(tank.vertices, i)
    {
        EXPECT_TRUE(sameBits(vtp.points()[i].x(), tank.vertices[i].x())) << i;
        EXPECT_TRUE(sameBits(vtp.points()[i].y(), tank.vertices[i].y())) << i;
    }
    EXPECT_EQ(vtp.nVertices(), 0);
    EXPECT_EQ(vtp.lines(), tank.segments);
    EXPECT_TRUE(sameBits(vtp.time(), writeTime));

    EXPECT_EQ(vtp.cellFieldNames(), wordList({"normal", "patch"}));
    EXPECT_EQ(vtp.pointFieldNames(), wordList({"angle"}));

    const auto& normal = vtp.cellField("normal");
    EXPECT_EQ(normal.type, "Float64");
    EXPECT_EQ(normal.nComponents(), 3);
    const List<vector2D> n(normal.vector2Ds());
    forAll(n, i)
    {
        EXPECT_TRUE(sameBits(n[i].x(), tank.normals[i].x())) << i;
        EXPECT_TRUE(sameBits(n[i].y(), tank.normals[i].y())) << i;
    }

    EXPECT_EQ(vtp.cellField("patch").type, "Int32");
    EXPECT_EQ(vtp.cellField("patch").labels(), tank.patch);

    const scalarList angle(vtp.pointField("angle").scalars());
    forAll(angle, i)
    {
        EXPECT_TRUE(sameBits(angle[i], tank.angle[i])) << i;
    }
}


TEST(vtkWallFile, pythonVtkReadsLinesAndArrays)
{
    const fileName file(freshDir()/"walls.vtp");
    const tankData tank;

    SPH::vtkWallFile walls(tank.vertices, tank.segments);
    tank.addFields(walls);
    walls.write(file, writeTime);

    const inspection vtp = inspect("vtp", file);
    ASSERT_EQ(vtp.status, 0) << "vtkInspect.py could not read " << file;

    EXPECT_EQ(vtp.first("points"), std::vector<std::string>({"points", "4"}));
    EXPECT_EQ(vtp.first("verts"), std::vector<std::string>({"verts", "0"}));
    EXPECT_EQ(vtp.first("lines"), std::vector<std::string>({"lines", "3"}));
    EXPECT_TRUE(sameBits(number(vtp.first("time").at(1)), writeTime));

    const auto lines = vtp.all("line");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0], std::vector<std::string>({"line", "0", "0", "1"}));
    EXPECT_EQ(lines[1], std::vector<std::string>({"line", "1", "1", "2"}));
    EXPECT_EQ(lines[2], std::vector<std::string>({"line", "2", "2", "3"}));

    const auto points = vtp.all("point");
    ASSERT_EQ(points.size(), 4u);
    EXPECT_TRUE(sameBits(number(points[2][2]), tank.vertices[2].x()));
    EXPECT_TRUE(sameBits(number(points[2][3]), tank.vertices[2].y()));
    EXPECT_TRUE(sameBits(number(points[2][4]), 0.0));

    const auto cellArrays = vtp.all("cellarray");
    ASSERT_EQ(cellArrays.size(), 2u);
    EXPECT_EQ
    (
        cellArrays[0],
        std::vector<std::string>({"cellarray", "normal", "Float64", "3", "3"})
    );
    EXPECT_EQ
    (
        cellArrays[1],
        std::vector<std::string>({"cellarray", "patch", "Int32", "1", "3"})
    );
    EXPECT_EQ
    (
        vtp.first("pointarray"),
        std::vector<std::string>({"pointarray", "angle", "Float64", "1", "4"})
    );

    const auto normal = vtp.values("normal");
    ASSERT_EQ(normal.size(), 3u);
    EXPECT_TRUE(sameBits(number(normal[1][3]), tank.normals[1].x()));
    EXPECT_TRUE(sameBits(number(normal[1][4]), tank.normals[1].y()));
    EXPECT_TRUE(sameBits(number(normal[1][5]), 0.0));

    const auto patch = vtp.values("patch");
    ASSERT_EQ(patch.size(), 3u);
    EXPECT_EQ(patch[2][3], "2.0");

    const auto angle = vtp.values("angle");
    ASSERT_EQ(angle.size(), 4u);
    EXPECT_TRUE(sameBits(number(angle[1][3]), M_PI/2));
}


TEST(vtkWallFile, startEndListsEqualPairs)
{
    const tankData tank;
    const labelList start({0, 1, 2});
    const labelList end({1, 2, 3});
    const fileName file(freshDir()/"walls.vtp");

    SPH::vtkWallFile(tank.vertices, start, end).write(file, 0);

    EXPECT_EQ(SPH::vtkPolyFileReader(file).lines(), tank.segments);
}


TEST(vtkWallFile, segmentIndexOutOfRangeIsFatal)
{
    const tankData tank;

    const std::string message = fatalMessage([&]
    {
        SPH::vtkWallFile(tank.vertices, List<labelPair>({labelPair(3, 4)}));
    });
    EXPECT_NE(message.find("Wall segment 0 joins points 3 and 4"), std::string::npos)
        << message;

    throwingErrors guard;
    EXPECT_THROW
    (
        SPH::vtkWallFile(tank.vertices, List<labelPair>({labelPair(-1, 0)})),
        Foam::error
    );
    EXPECT_THROW
    (
        SPH::vtkWallFile(tank.vertices, labelList({0, 1}), labelList({1})),
        Foam::error
    );
}


TEST(vtkWallFile, cellFieldSizeMustMatchSegments)
{
    const tankData tank;
    SPH::vtkWallFile walls(tank.vertices, tank.segments);

    // One value per vertex is a point field, not a cell field
    const std::string message =
        fatalMessage([&]{ walls.addCellField("angle", tank.angle); });

    EXPECT_NE(message.find("angle has 4 values for 3 cells"), std::string::npos)
        << message;
}


// ************************************************************************* //
