/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    sphMesh on the periodic channel of tests/regression/periodic/channel (1 m
    x 1 m, periodic in x, walls lowerWall at y = 0 and upperWall at y = 1,
    dr = 0.05), as a user runs it, and on its bad variants, which must fail
    naming the file and entry.

    Counts are exact (a lattice and straight walls):
    - boundaryMethod usaw seeds the nodes k dr (first row dr from the
      walls): 20 columns x = 0 .. 0.95 (x = 1 is x = 0) by 19 rows
      y = 0.05 .. 0.95;
    - boundaryMethod dummyRepulsive seeds the cell centres (k + 1/2) dr:
      20 x 20, and floor(support/dr) dummy layers of 20 per wall;
    - each wall has 20 vertices (the one at x = 1 is the one at x = 0) and
      20 segments, every vertex angle pi.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particles.H"
#include "wallMesh.H"
#include "scalarIOField.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

using namespace Foam;
using sphTest::run;
using constant::mathematical::pi;

namespace
{
    const std::string sphMeshExe =
        std::string(SPHFOAM_BINARY_DIR) + "/applications/sphMesh";
    const scalar dr = 0.05;

    //- A copy of the channel case under the build folder
    fileName copyChannel(const std::string& name)
    {
        const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/name;
        rmDir(dir);
        mkDir(dir.path());
        run
        (
            "cp -r " + std::string(SPHFOAM_SOURCE_DIR)
          + "/tests/regression/periodic/channel " + dir
        );
        return dir;
    }

    std::string readText(const fileName& file)
    {
        std::ifstream is(file);
        std::stringstream ss;
        ss << is.rdbuf();
        return ss.str();
    }

    //- Replace one piece of text in a case file (it must be there)
    void edit(const fileName& file, const std::string& from, const std::string& to)
    {
        std::string text(readText(file));
        const size_t pos = text.find(from);
        ASSERT_NE(pos, std::string::npos) << from << " not in " << file;
        text.replace(pos, from.size(), to);
        std::ofstream(file) << text;
    }

    List<vector2D> readPositions(const Time& runTime, const word& set)
    {
        SPH::particles parts(runTime, runTime.constant(), "sphMesh"/set, false);
        parts.read();
        return parts.positions();
    }

    //- The distinct values of one coordinate, to 1e-9
    std::set<long> distinct(const List<vector2D>& pts, const direction d)
    {
        std::set<long> v;
        for (const vector2D& p : pts)
        {
            v.insert(std::lround(p[d]*1e9));
        }
        return v;
    }

    //- Smallest distance between two of the points through the seam
    scalar closestPair(const SPH::domain& dom, const List<vector2D>& pts)
    {
        scalar m = GREAT;
        forAll(pts, i)
        {
            for (label j = 0; j < i; ++j)
            {
                m = min(m, mag(dom.separation(pts[i], pts[j])));
            }
        }
        return m;
    }

    //- Run sphMesh on a variant of the channel that must fail; its output
    std::string failingRun
    (
        const std::string& name,
        const std::string& from,
        const std::string& to
    )
    {
        const fileName dir = copyChannel(name);
        edit(dir/"system"/"sphMeshDict", from, to);
        std::string out;
        EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1) << out;
        EXPECT_NE(out.find("FOAM FATAL IO ERROR"), std::string::npos) << out;
        return out;
    }

    const std::string lowerWall = "lowerWall   { type line; points ((0 0) (1 0)); }";
}


TEST(periodicChannel, usawNodesTileThePeriodAndWallsJoinThroughTheSeam)
{
    const fileName dir = copyChannel("periodicChannelUsaw");
    std::string out;
    ASSERT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("Domain: periodic in x"), std::string::npos) << out;

    auto runTime = sphTest::makeTime(dir);

    // 20 columns x = i dr, 19 rows y = j dr, j = 1 .. 19
    const List<vector2D> fluid(readPositions(*runTime, "fluid"));
    EXPECT_EQ(fluid.size(), 20*19);
    const std::set<long> xs(distinct(fluid, 0)), ys(distinct(fluid, 1));
    EXPECT_EQ(xs.size(), 20u);
    EXPECT_EQ(ys.size(), 19u);
    EXPECT_EQ(*xs.begin(), 0);
    EXPECT_EQ(*xs.rbegin(), std::lround(0.95e9));
    EXPECT_EQ(*ys.begin(), std::lround(0.05e9));
    EXPECT_EQ(*ys.rbegin(), std::lround(0.95e9));
    for (const vector2D& p : fluid)
    {
        EXPECT_GE(p.x(), 0);
        EXPECT_LT(p.x(), 1);
    }

    // The domain, read back as the solvers will
    const SPH::wallMesh walls(*runTime);
    const SPH::domain& dom = walls.domain();
    EXPECT_TRUE(dom.periodic(0));
    EXPECT_FALSE(dom.periodic(1));
    EXPECT_EQ(dom.min(), vector2D(0, 0));
    EXPECT_EQ(dom.max(), vector2D(1, 1));
    EXPECT_EQ(dom.period(), vector2D(1, 0));
    EXPECT_NEAR(closestPair(dom, fluid), dr, 1e-12);

    // One vertex per x = i dr on each wall: no duplicate at the seam
    EXPECT_EQ(walls.patchNames(), wordList({"lowerWall", "upperWall"}));
    labelList nPts, nSeg;
    walls.patchCounts(nPts, nSeg);
    EXPECT_EQ(nPts, labelList({20, 20}));
    EXPECT_EQ(nSeg, labelList({20, 20}));
    EXPECT_NEAR(closestPair(dom, walls.points()), dr, 1e-12);
    forAll(walls.segments(), s)
    {
        EXPECT_NEAR(walls.segmentLength(s), dr, 1e-12);
    }

    // constant/sphMesh/walls/pointAngles: all pi, as inside a straight wall
    const scalarField angles
    (
        scalarIOField
        (
            IOobject
            (
                "pointAngles", runTime->constant(), "sphMesh/walls", *runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            )
        )
    );
    ASSERT_EQ(angles.size(), 40);
    for (const scalar a : angles)
    {
        EXPECT_NEAR(a, pi, 1e-12);
    }

    // No dummy particles for USAW walls
    EXPECT_EQ(readPositions(*runTime, "dummy").size(), 0);

    // constant/sphMesh/domain as a user reads it
    const std::string domainText(readText(dir/"constant"/"sphMesh"/"domain"));
    EXPECT_NE(domainText.find("directions      ( x );"), std::string::npos) << domainText;

    // The VTK picture draws the segments through the seam one dr long: to
    // an extra image point, 42 points for 40 segments
    const std::string py =
        std::string(SPHFOAM_PYTHON) + " -c \"from vtkmodules.vtkIOXML import"
        " vtkXMLPolyDataReader as R;import math;"
        "r=R();r.SetFileName('" + dir + "/VTK/sphMesh_walls_0.vtp');r.Update();"
        "o=r.GetOutput();p=o.GetPoints();"
        "L=[math.dist(p.GetPoint(o.GetCell(c).GetPointId(0)),"
        "p.GetPoint(o.GetCell(c).GetPointId(1))) for c in range(o.GetNumberOfCells())];"
        "print(o.GetNumberOfPoints(), o.GetNumberOfCells(), round(max(L), 9))\"";
    ASSERT_EQ(run(py, out), 0) << out;
    EXPECT_EQ(out, "42 40 0.05\n");
}


TEST(periodicChannel, dummyLayersTileAcrossTheSeam)
{
    const fileName dir = copyChannel("periodicChannelDummies");
    edit
    (
        dir/"system"/"sphSchemes",
        "boundaryMethod  usaw;",
        "boundaryMethod  dummyRepulsive;"
    );
    std::string out;
    ASSERT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
    auto runTime = sphTest::makeTime(dir);

    // Cell centres: 20 x 20
    const List<vector2D> fluid(readPositions(*runTime, "fluid"));
    EXPECT_EQ(fluid.size(), 20*20);
    EXPECT_EQ(distinct(fluid, 0).size(), 20u);

    // Wendland C2 with h = 2 dr: support 4 dr, 4 layers of 20 per wall, in
    // the fluid's columns, none twice and none missing at x = 0 = 1
    SPH::particles dummy(*runTime, runTime->constant(), "sphMesh/dummy", false);
    dummy.add<label>("layer");
    dummy.add<label>("patch");
    dummy.read();
    const labelList& layer = dummy.field<label>("layer");
    const labelList& patch = dummy.field<label>("patch");
    ASSERT_EQ(dummy.size(), 4*2*20);
    labelList perLayerPatch(8, 0);
    forAll(layer, i)
    {
        ++perLayerPatch[2*layer[i] + patch[i]];
        const vector2D& p = dummy.positions()[i];
        const scalar yExpect =
            patch[i] == 0 ? -(layer[i] + 0.5)*dr : 1 + (layer[i] + 0.5)*dr;
        EXPECT_NEAR(p.y(), yExpect, 1e-12);
        EXPECT_GE(p.x(), 0);
        EXPECT_LT(p.x(), 1);
        const scalar col = p.x()/dr - 0.5;
        EXPECT_NEAR(col, std::round(col), 1e-9) << p.x();
    }
    EXPECT_EQ(perLayerPatch, labelList(8, 20));

    const SPH::wallMesh walls(*runTime);
    EXPECT_NEAR(closestPair(walls.domain(), dummy.positions()), dr, 1e-12);
}


TEST(periodicChannel, aBoxPeriodicInXAndYNeedsNoWalls)
{
    // The Taylor-Green vortex's box: the channel without its walls,
    // periodic in y too; the nodes k dr tile both periods
    const fileName dir = copyChannel("periodicBoxXY");
    edit(dir/"system"/"sphMeshDict", "directions  (x);", "directions  (x y);");
    edit
    (
        dir/"system"/"sphMeshDict",
        "    lowerWall   { type line; points ((0 0) (1 0)); }\n"
        "    upperWall   { type line; points ((1 1) (0 1)); }\n",
        ""
    );
    std::string out;
    ASSERT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("Domain: periodic in x y"), std::string::npos) << out;

    auto runTime = sphTest::makeTime(dir);
    const List<vector2D> fluid(readPositions(*runTime, "fluid"));
    EXPECT_EQ(fluid.size(), 20*20);
    EXPECT_EQ(distinct(fluid, 0).size(), 20u);
    EXPECT_EQ(distinct(fluid, 1).size(), 20u);
    EXPECT_EQ(*distinct(fluid, 1).begin(), 0);

    const SPH::wallMesh walls(*runTime);
    EXPECT_EQ(walls.points().size(), 0);
    EXPECT_TRUE(walls.domain().periodic(0) && walls.domain().periodic(1));
    EXPECT_NEAR(closestPair(walls.domain(), fluid), dr, 1e-12);

    // Without the periodicity in y the walls are missing
    edit(dir/"system"/"sphMeshDict", "directions  (x y);", "directions  (x);");
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1) << out;
    EXPECT_NE(out.find("walls"), std::string::npos) << out;
}


TEST(periodicChannel, periodNotAWholeNumberOfSpacingsNamesTheEntry)
{
    const std::string out = failingRun
    (
        "periodicChannelBadPeriod",
        "max         (1 1);",
        "max         (1.03 1);"
    );
    EXPECT_NE(out.find("system/sphMeshDict.periodic"), std::string::npos) << out;
    EXPECT_NE(out.find("is 20.6 spacings dr = 0.05"), std::string::npos) << out;
    EXPECT_NE(out.find("whole number"), std::string::npos) << out;
    EXPECT_NE(out.find("Nearest valid periods: 1 (20 dr) or 1.05 (21 dr)"), std::string::npos)
        << out;
}


TEST(periodicChannel, wallCrossingTheSeamWithoutItsImageNamesThePatch)
{
    // The bed rises by 0.02 over the period: its ends miss each other
    const std::string out = failingRun
    (
        "periodicChannelNoImage",
        lowerWall,
        "lowerWall   { type line; points ((0 0) (1 0.02)); }"
    );
    EXPECT_NE(out.find("system/sphMeshDict.walls.lowerWall"), std::string::npos) << out;
    EXPECT_NE(out.find("periodic seam"), std::string::npos) << out;
    EXPECT_NE(out.find("lowerWall at (0 0.02) = (1 0.02)"), std::string::npos) << out;
    EXPECT_NE(out.find("lowerWall at (0 0) = (1 0)"), std::string::npos) << out;
}


TEST(periodicChannel, wallOnOneSideOfTheSeamOnlyNamesThePatch)
{
    const std::string out = failingRun
    (
        "periodicChannelOneSide",
        lowerWall,
        "lowerWall   { type line; points ((0 0) (0.5 0)); }"
        " plug { type line; points ((0.5 0) (0.5 -0.2) (1 -0.2)); }"
    );
    EXPECT_NE(out.find("system/sphMeshDict.walls.lowerWall"), std::string::npos) << out;
    EXPECT_NE(out.find("lowerWall at (0 0) = (1 0)"), std::string::npos) << out;
    EXPECT_NE(out.find("plug at (0 -0.2) = (1 -0.2)"), std::string::npos) << out;
}


TEST(periodicChannel, wallBeyondThePeriodicBoxNamesThePatch)
{
    const std::string out = failingRun
    (
        "periodicChannelBeyond",
        lowerWall,
        "lowerWall   { type line; points ((-0.5 0) (1.5 0)); }"
    );
    EXPECT_NE(out.find("system/sphMeshDict.walls.lowerWall"), std::string::npos) << out;
    EXPECT_NE(out.find("outside the periodic box"), std::string::npos) << out;
}


TEST(periodicChannel, unknownPeriodicDirectionListsTheValidOnes)
{
    const std::string out = failingRun
    (
        "periodicChannelBadDirection",
        "directions  (x);",
        "directions  (z);"
    );
    EXPECT_NE(out.find("system/sphMeshDict.periodic.directions"), std::string::npos) << out;
    EXPECT_NE(out.find("'z'"), std::string::npos) << out;
    EXPECT_NE(out.find("x and y"), std::string::npos) << out;
}


// ************************************************************************* //
