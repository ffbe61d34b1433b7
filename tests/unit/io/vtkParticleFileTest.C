/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.

Description
    vtkParticleFile: what is written is read back exactly, by libsph's own
    reader and by python3-vtk9 (the readers ParaView uses).  Float64 data
    must survive bit for bit, so every comparison is exact (tolerance 0);
    the values include -0.0, a subnormal and numbers with no short decimal
    form, which a text or Float32 path would change.

\*---------------------------------------------------------------------------*/

#include "vtkParticleFile.H"
#include "vtkPolyFileReader.H"
#include "vtkTestTools.H"

#include <cmath>
#include <fstream>
#include <limits>

using namespace Foam;
using namespace vtkTest;

namespace
{

//- Particles whose coordinates and fields have no short decimal form
struct particleData
{
    List<vector2D> positions;
    scalarList p;
    List<vector2D> U;
    labelList id;

    particleData()
    :
        positions(5),
        p(5),
        U(5),
        id(5)
    {
        const scalar tiny = std::numeric_limits<scalar>::denorm_min();

        positions[0] = vector2D(M_PI, -1.0/3.0);
        positions[1] = vector2D(1e-300, tiny);
        positions[2] = vector2D(-0.0, 1e300);
        positions[3] = vector2D(0.1, 0.1 + 0.2);
        positions[4] = vector2D(std::nextafter(1.0, 2.0), -123456.789);

        p[0] = 101325.0/3.0;
        p[1] = -0.0;
        p[2] = tiny;
        p[3] = std::nextafter(0.0, -1.0);
        p[4] = std::exp(1.0);

        U[0] = vector2D(1.0/7.0, -2.0/9.0);
        U[1] = vector2D(0, 0);
        U[2] = vector2D(-1e-17, 3e-5);
        U[3] = vector2D(std::sqrt(2.0), -std::sqrt(3.0));
        U[4] = vector2D(1e10 + 0.5, -0.0);

        id[0] = 0;
        id[1] = -7;
        id[2] = std::numeric_limits<int32_t>::max();
        id[3] = std::numeric_limits<int32_t>::min();
        id[4] = 42;
    }

    //- The file written from this data
    SPH::vtkParticleFile file() const
    {
        SPH::vtkParticleFile particles(positions);
        particles.addPointField("p", p);
        particles.addPointField("U", U);
        particles.addPointField("origId", id);
        return particles;
    }
};

//- A time with no short decimal form
const scalar writeTime = 0.1 + 0.2;

} // End anonymous namespace


TEST(vtkParticleFile, roundTripIsBitForBit)
{
    const fileName file(freshDir()/"particles.vtp");
    const particleData data;
    data.file().write(file, writeTime);

    const SPH::vtkPolyFileReader vtp(file);

    ASSERT_EQ(vtp.points().size(), data.positions.size());
    forAll(data.positions, i)
    {
        EXPECT_TRUE(sameBits(vtp.points()[i].x(), data.positions[i].x())) << i;
        EXPECT_TRUE(sameBits(vtp.points()[i].y(), data.positions[i].y())) << i;
    }

    EXPECT_EQ(vtp.nVertices(), data.positions.size());
    EXPECT_TRUE(vtp.lines().empty());
    EXPECT_TRUE(sameBits(vtp.time(), writeTime));

    EXPECT_EQ(vtp.pointFieldNames(), wordList({"p", "U", "origId"}));

    const auto& p = vtp.pointField("p");
    EXPECT_EQ(p.type, "Float64");
    const scalarList pRead(p.scalars());
    ASSERT_EQ(pRead.size(), data.p.size());
    forAll(pRead, i)
    {
        EXPECT_TRUE(sameBits(pRead[i], data.p[i])) << i;
    }

    const auto& U = vtp.pointField("U");
    EXPECT_EQ(U.type, "Float64");
    ASSERT_EQ(U.nComponents(), 3);
    const List<vector2D> URead(U.vector2Ds());
    forAll(URead, i)
    {
        EXPECT_TRUE(sameBits(URead[i].x(), data.U[i].x())) << i;
        EXPECT_TRUE(sameBits(URead[i].y(), data.U[i].y())) << i;
        EXPECT_TRUE(sameBits(U.components[2][i], 0.0)) << i;
    }

    const auto& id = vtp.pointField("origId");
    EXPECT_EQ(id.type, "Int32");
    EXPECT_EQ(id.labels(), data.id);
}


TEST(vtkParticleFile, pythonVtkReadsSameNumbers)
{
    const fileName file(freshDir()/"particles.vtp");
    const particleData data;
    data.file().write(file, writeTime);

    const inspection vtp = inspect("vtp", file);
    ASSERT_EQ(vtp.status, 0) << "vtkInspect.py could not read " << file;

    const label n = data.positions.size();
    EXPECT_EQ(vtp.first("points"), std::vector<std::string>({"points", "5"}));
    EXPECT_EQ(vtp.first("verts"), std::vector<std::string>({"verts", "5"}));
    EXPECT_EQ(vtp.first("lines"), std::vector<std::string>({"lines", "0"}));
    ASSERT_EQ(vtp.first("time").size(), 2u);
    EXPECT_TRUE(sameBits(number(vtp.first("time")[1]), writeTime));

    const auto points = vtp.all("point");
    ASSERT_EQ(label(points.size()), n);
    for (label i = 0; i < n; ++i)
    {
        ASSERT_EQ(points[i].size(), 5u);
        EXPECT_TRUE(sameBits(number(points[i][2]), data.positions[i].x())) << i;
        EXPECT_TRUE(sameBits(number(points[i][3]), data.positions[i].y())) << i;
        EXPECT_TRUE(sameBits(number(points[i][4]), 0.0)) << i;
    }

    // Names, types and components as ParaView will list them
    const auto arrays = vtp.all("pointarray");
    ASSERT_EQ(arrays.size(), 3u);
    using record = std::vector<std::string>;
    EXPECT_EQ(arrays[0], record({"pointarray", "p", "Float64", "1", "5"}));
    EXPECT_EQ(arrays[1], record({"pointarray", "U", "Float64", "3", "5"}));
    EXPECT_EQ(arrays[2], record({"pointarray", "origId", "Int32", "1", "5"}));
    EXPECT_TRUE(vtp.all("cellarray").empty());

    const auto p = vtp.values("p");
    const auto U = vtp.values("U");
    const auto id = vtp.values("origId");
    ASSERT_EQ(label(p.size()), n);
    ASSERT_EQ(label(U.size()), n);
    ASSERT_EQ(label(id.size()), n);
    for (label i = 0; i < n; ++i)
    {
        EXPECT_TRUE(sameBits(number(p[i][3]), data.p[i])) << i;
        EXPECT_TRUE(sameBits(number(U[i][3]), data.U[i].x())) << i;
        EXPECT_TRUE(sameBits(number(U[i][4]), data.U[i].y())) << i;
        EXPECT_TRUE(sameBits(number(U[i][5]), 0.0)) << i;
        EXPECT_EQ(number(id[i][3]), data.id[i]) << i;
    }
}


TEST(vtkParticleFile, noParticlesStillGivesReadableFile)
{
    // All particles may have left the domain; ParaView must still open the
    // step rather than break the series
    const fileName file(freshDir()/"empty.vtp");

    SPH::vtkParticleFile particles{List<vector2D>()};
    particles.addPointField("p", scalarList());
    particles.write(file, 1.5);

    const SPH::vtkPolyFileReader vtp(file);
    EXPECT_TRUE(vtp.points().empty());
    EXPECT_EQ(vtp.nVertices(), 0);
    EXPECT_EQ(vtp.time(), 1.5);

    const inspection py = inspect("vtp", file);
    ASSERT_EQ(py.status, 0);
    EXPECT_EQ(py.first("points"), std::vector<std::string>({"points", "0"}));
    EXPECT_EQ(py.first("time"), std::vector<std::string>({"time", "1.5"}));
}


TEST(vtkParticleFile, rewriteReplacesFileAndLeavesNoTmp)
{
    const fileName file(freshDir()/"particles.vtp");
    const List<vector2D> positions({vector2D(0, 0), vector2D(1, 0)});

    SPH::vtkParticleFile first(positions);
    first.addPointField("p", scalarList({1, 2}));
    first.write(file, 0.1);

    SPH::vtkParticleFile second(positions);
    second.addPointField("p", scalarList({3, 4}));
    second.write(file, 0.2);

    const SPH::vtkPolyFileReader vtp(file);
    EXPECT_EQ(vtp.time(), 0.2);
    EXPECT_EQ(vtp.pointField("p").scalars(), scalarList({3, 4}));
    EXPECT_FALSE(isFile(file + ".tmp", false));
}


TEST(vtkParticleFile, sameObjectWritesAtSeveralTimes)
{
    // write() is const: the TimeValue of one write must not leak into the next
    const fileName dir(freshDir());
    SPH::vtkParticleFile particles(List<vector2D>({vector2D(0.5, 0.5)}));

    particles.write(dir/"a.vtp", 1);
    particles.write(dir/"b.vtp", 2);

    EXPECT_EQ(SPH::vtkPolyFileReader(dir/"a.vtp").time(), 1);
    EXPECT_EQ(SPH::vtkPolyFileReader(dir/"b.vtp").time(), 2);
    EXPECT_TRUE(particles.pointFieldNames().empty());
}


TEST(vtkParticleFile, createsMissingFolders)
{
    const fileName file(freshDir()/"VTK/deeper/particles.vtp");

    SPH::vtkParticleFile(List<vector2D>({vector2D(1, 2)})).write(file, 0);

    EXPECT_TRUE(isFile(file, false));
}


TEST(vtkParticleFile, uncreatableFolderIsFatalNamingFile)
{
    // A regular file where a folder is needed: fails even for root, unlike
    // a permission-based test
    const fileName dir(freshDir());
    std::ofstream(dir/"notAFolder") << "x\n";
    const fileName file(dir/"notAFolder/VTK/particles.vtp");

    const SPH::vtkParticleFile particles(List<vector2D>({vector2D(1, 2)}));

    {
        throwingErrors guard;
        EXPECT_THROW(particles.write(file, 0), Foam::error);
    }

    const std::string message = fatalMessage([&]{ particles.write(file, 0); });
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_FALSE(isFile(file + ".tmp", false));
}


TEST(vtkParticleFile, wrongFieldSizeIsFatal)
{
    SPH::vtkParticleFile particles(List<vector2D>({vector2D(0, 0), vector2D(1, 1)}));

    const std::string message =
        fatalMessage([&]{ particles.addPointField("p", scalarList({1, 2, 3})); });

    EXPECT_NE(message.find("p has 3 values for 2 points"), std::string::npos)
        << message;
}


TEST(vtkParticleFile, duplicateFieldNameIsFatal)
{
    SPH::vtkParticleFile particles(List<vector2D>({vector2D(0, 0)}));
    particles.addPointField("p", scalarList({1}));

    throwingErrors guard;
    EXPECT_THROW(particles.addPointField("p", labelList({1})), Foam::error);
    EXPECT_THROW(particles.addPointField("", scalarList({1})), Foam::error);
}


TEST(vtkParticleFile, nonFiniteTimeIsFatal)
{
    const fileName file(freshDir()/"particles.vtp");
    SPH::vtkParticleFile particles(List<vector2D>({vector2D(0, 0)}));

    throwingErrors guard;
    EXPECT_THROW(particles.write(file, std::nan("")), Foam::error);
    EXPECT_FALSE(isFile(file, false));
}


// ************************************************************************* //
