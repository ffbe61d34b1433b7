/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The wall models (src/sph/boundaries/wallModel), the one selection by
    boundaryMethod that sphMesh, isphFoam and wcsphFoam share: the lattice
    corner and dummy layers sphMesh lays out, the wall particles and their
    volume shares; an unknown word lists the valid ones.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallModel.H"
#include "wcsphWallModel.H"
#include "wallShape.H"
#include "particles.H"
#include "mathematicalConstants.H"
#include <sstream>

using namespace Foam;
using namespace Foam::SPH;

namespace
{
    wallMesh boxWalls(const scalar dr)
    {
        const dictionary box(sphTest::dict("type box; min (0 0); max (1 0.5);"));
        const List<List<wallChain>> chains
        (
            1, wallShape::New("tank", box)->chains(dr)
        );
        return wallMesh(wordList(1, "tank"), chains, dr);
    }

    autoPtr<wallModel> select(const std::string& method)
    {
        return wallModel::New(sphTest::dict("boundaryMethod " + method + ";"));
    }
}


TEST(wallModel, sameWordsAsTheWcsphModels)
{
    // Every layout has its wcsphFoam model and the other way round: one
    // word selects both
    const wordList layouts = wallModel::dictionaryConstructorTablePtr_->sortedToc();
    const wordList wcsph = wcsphWallModel::dictionaryConstructorTablePtr_->sortedToc();
    EXPECT_EQ(layouts, wcsph);
    EXPECT_NE(layouts.find("usaw"), -1);
    EXPECT_NE(layouts.find("dummyRepulsive"), -1);
}


TEST(wallModel, defaultIsDummyRepulsive)
{
    EXPECT_EQ(wallModel::New(dictionary())->type(), "dummyRepulsive");
}


TEST(wallModel, unknownWordIsAnErrorListingTheValidOnes)
{
    sphTest::throwOnFatal();
    try
    {
        select("ghostParticles");
        FAIL() << "boundaryMethod ghostParticles accepted";
    }
    catch (const Foam::IOerror& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("boundaryMethod"), std::string::npos) << msg;
        EXPECT_NE(msg.find("ghostParticles"), std::string::npos) << msg;
        EXPECT_NE(msg.find("usaw"), std::string::npos) << msg;
        EXPECT_NE(msg.find("dummyRepulsive"), std::string::npos) << msg;
    }
}


TEST(wallModel, usawSeedsTheNodesAndLaysNothingBehindTheWalls)
{
    const scalar dr = 0.1;
    const autoPtr<wallModel> m(select("usaw"));
    const dictionary schemes(sphTest::dict("kernel wendlandC2; hByDr 2;"));
    const autoPtr<kernel> W(kernel::New(schemes, dr));

    // Particles at corner + (i + 1/2) dr = k dr from the walls' corner
    const vector2D corner(m->latticeCorner(vector2D(0, 0), dr));
    EXPECT_DOUBLE_EQ(corner.x() + 0.5*dr, 0);
    EXPECT_DOUBLE_EQ(corner.y() + 0.5*dr, 0);
    EXPECT_FALSE(m->particlesBehindWalls());
    EXPECT_EQ(m->defaultDummyLayers(*W, dr), 0);
}


TEST(wallModel, usawVertexVolumesTileTheWallStrip)
{
    // A box of 1 x 0.5 at dr 0.1: 30 vertices, 4 corners of angle pi/2 and
    // 26 straight ones of angle pi. Their shares theta/(2 pi) are 1/4 and
    // 1/2, and add up to the strip of width dr/2 along the walls: the
    // perimeter 3/dr in cells of dr^2, 15 cells
    const scalar dr = 0.1;
    const wallMesh walls(boxWalls(dr));
    const autoPtr<wallModel> m(select("usaw"));
    const label n = walls.points().size();
    ASSERT_EQ(n, 30);
    const scalarList share(m->volumeShares(walls, n));
    scalar sum = 0;
    label nCorner = 0;
    forAll(share, v)
    {
        sum += share[v];
        nCorner += mag(share[v] - 0.25) < 1e-12;
        EXPECT_TRUE(mag(share[v] - 0.25) < 1e-12 || mag(share[v] - 0.5) < 1e-12)
            << "vertex " << v << " share " << share[v];
    }
    EXPECT_EQ(nCorner, 4);
    EXPECT_NEAR(sum, 14, 1e-12);    // 26/2 + 4/4

    DynamicList<vector2D> x;
    DynamicList<label> type, patch;
    const fileName dir = sphTest::makeCase("wallModelUsaw");
    auto runTime = sphTest::makeTime(dir);
    m->wallParticles(*runTime, walls, x, type, patch);
    ASSERT_EQ(x.size(), n);
    forAll(x, v)
    {
        EXPECT_EQ(x[v], walls.points()[v]);
        EXPECT_EQ(type[v], label(particleKind::wallVertex));
        EXPECT_EQ(patch[v], walls.pointPatch()[v]);
    }
}


TEST(wallModel, usawRestartWithOtherWallParticlesIsAnError)
{
    sphTest::throwOnFatal();
    const scalar dr = 0.1;
    const wallMesh walls(boxWalls(dr));
    const autoPtr<wallModel> m(select("usaw"));
    m->checkRestart(walls, "0.1/lagrangian/sph", 50, walls.points().size());
    try
    {
        m->checkRestart(walls, "0.1/lagrangian/sph", 50, 200);
        FAIL() << "200 wall particles accepted for 30 vertices";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("0.1/lagrangian/sph"), std::string::npos) << msg;
        EXPECT_NE(msg.find("boundaryMethod usaw"), std::string::npos) << msg;
    }
}


TEST(wallModel, meshMadeForAnotherModelIsAnErrorSayingHowToRemakeIt)
{
    // sphMesh's record in constant/sphMesh/layout: a mesh laid out for
    // dummyRepulsive taken by usaw (isphFoam), and the reverse
    sphTest::throwOnFatal();
    const scalar dr = 0.1;
    const wallMesh walls(boxWalls(dr));
    for (const std::string made : {"dummyRepulsive", "usaw"})
    {
        const std::string other = made == "usaw" ? "dummyRepulsive" : "usaw";
        const fileName dir = sphTest::makeCase("wallModelMesh" + made);
        auto runTime = sphTest::makeTime(dir);
        mkDir(dir/"constant"/"sphMesh");
        select(made)->writeLayout(*runTime, "sphMesh", dr, made == "usaw" ? 0 : 2);

        DynamicList<vector2D> x;
        DynamicList<label> type, patch;
        try
        {
            select(other)->wallParticles(*runTime, walls, x, type, patch);
            FAIL() << "a mesh made for " << made << " taken by " << other;
        }
        catch (const Foam::error& e)
        {
            const std::string msg(e.message());
            EXPECT_NE(msg.find("made by sphMesh for boundaryMethod " + made),
                      std::string::npos) << msg;
            EXPECT_NE(msg.find("set boundaryMethod " + other
                + " in system/sphSchemes and run sphMesh again"),
                      std::string::npos) << msg;
        }
        // Its own model takes it
        if (made == "usaw")
        {
            select(made)->wallParticles(*runTime, walls, x, type, patch);
            EXPECT_EQ(x.size(), walls.points().size());
        }
    }
}


TEST(wallModel, meshWithoutTheRecordIsAcceptedWithANote)
{
    // A mesh from before sphMesh wrote constant/sphMesh/layout
    const wallMesh walls(boxWalls(0.1));
    const fileName dir = sphTest::makeCase("wallModelOldMesh");
    auto runTime = sphTest::makeTime(dir);
    DynamicList<vector2D> x;
    DynamicList<label> type, patch;
    std::ostringstream log;
    std::streambuf* old = std::cout.rdbuf(log.rdbuf());
    select("usaw")->wallParticles(*runTime, walls, x, type, patch);
    std::cout.rdbuf(old);
    EXPECT_EQ(x.size(), walls.points().size());
    EXPECT_NE(log.str().find("no record of its wall model"), std::string::npos) << log.str();
}


TEST(wallModel, dummyRepulsiveSeedsCellCentresAndFillsTheSupport)
{
    const scalar dr = 0.1;
    const autoPtr<wallModel> m(select("dummyRepulsive"));
    EXPECT_EQ(m->latticeCorner(vector2D(0.2, 0.3), dr), vector2D(0.2, 0.3));
    EXPECT_TRUE(m->particlesBehindWalls());

    // Support 2h: a particle dr/2 from the wall reaches 2h - dr/2 behind
    // it, layers (k + 1/2) dr, k < floor(2h/dr)
    const dictionary wendland(sphTest::dict("kernel wendlandC2; hByDr 2;"));
    EXPECT_EQ(m->defaultDummyLayers(*kernel::New(wendland, dr), dr), 4);
    const dictionary wendland13(sphTest::dict("kernel wendlandC2; hByDr 1.3;"));
    EXPECT_EQ(m->defaultDummyLayers(*kernel::New(wendland13, dr), dr), 2);

    const wallMesh walls(boxWalls(dr));
    const scalarList share(m->volumeShares(walls, 7));
    ASSERT_EQ(share.size(), 7);
    for (const scalar s : share) EXPECT_EQ(s, 1);
}


// ************************************************************************* //
