/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Wall shapes and their discretisation (wallMesh): segment lengths close
    to dr, inward normals, vertex angles theta_v (000_8c7cd3aabddcf18a.txt
    table 2), joins between patches, signed distance and dummy layers
    (004_f29223b75201dc88.txt section 3.2). Geometry is exact up to
    round-off, so the tolerances are 1e-12 relative.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallMesh.H"
#include "mathematicalConstants.H"

using namespace Foam;
using namespace Foam::SPH;
using constant::mathematical::pi;

namespace
{
    const scalar tol = 1e-12;

    //- Walls from "name { ... }" patch dictionaries
    wallMesh makeWalls(const std::string& text, scalar dr)
    {
        const dictionary d(sphTest::dict(text));
        wordList names;
        List<List<wallChain>> chains;
        for (const entry& e : d)
        {
            names.append(e.keyword());
            chains.append(wallShape::New(e.keyword(), e.dict())->chains(dr));
        }
        return wallMesh(names, chains, dr);
    }

    label countAngle(const wallMesh& w, scalar theta)
    {
        label n = 0;
        for (const scalar a : w.pointAngles())
        {
            if (mag(a - theta) < 1e-9) ++n;
        }
        return n;
    }
}


TEST(wallMesh, boxTankHasQuarterCornersAndStraightSides)
{
    const scalar dr = 0.1;
    const wallMesh w = makeWalls("tank { type box; min (0 0); max (1 0.5); }", dr);

    // Perimeter 3 split into pieces of dr: 30 vertices and 30 segments
    EXPECT_EQ(w.points().size(), 30);
    EXPECT_EQ(w.segments().size(), 30);
    EXPECT_EQ(countAngle(w, 0.5*pi), 4);
    EXPECT_EQ(countAngle(w, pi), 26);
    forAll(w.segments(), s)
    {
        EXPECT_NEAR(w.segmentLength(s), dr, tol);
        // The inward normal points to the centre side of the segment
        const vector2D mid = 0.5*(w.points()[w.segments()[s].first()] + w.points()[w.segments()[s].second()]);
        EXPECT_GT((vector2D(0.5, 0.25) - mid) & w.segmentNormals()[s], 0);
    }
}


TEST(wallMesh, obstacleCornersSeeThreeQuartersOfFluid)
{
    const wallMesh w = makeWalls
    (
        "obstacle { type polygon; points ((0 0) (0.2 0) (0.2 0.2) (0 0.2)); side outside; }",
        0.05
    );
    EXPECT_EQ(countAngle(w, 1.5*pi), 4);
    // The fluid is outside: the normal of the bottom segment points down
    forAll(w.segments(), s)
    {
        const vector2D a = w.points()[w.segments()[s].first()];
        const vector2D b = w.points()[w.segments()[s].second()];
        if (mag(a.y()) < tol && mag(b.y()) < tol)
        {
            EXPECT_NEAR(w.segmentNormals()[s].y(), -1, tol);
        }
    }
    EXPECT_GT(w.signedDistance(vector2D(0.1, -0.1)), 0);
    EXPECT_LT(w.signedDistance(vector2D(0.1, 0.1)), 0);
}


TEST(wallMesh, patchesJoinAtSharedEnds)
{
    // The cavity: fixed walls as one polyline, the lid as a line
    const wallMesh w = makeWalls
    (
        "fixedWalls { type polyline; points ((0 1) (0 0) (1 0) (1 1)); }"
        "lid { type line; points ((1 1) (0 1)); }",
        0.1
    );
    EXPECT_EQ(w.points().size(), 40);       // closed loop: no duplicate corners
    EXPECT_EQ(w.segments().size(), 40);
    EXPECT_EQ(countAngle(w, 0.5*pi), 4);    // the lid corners too
    label nLid = 0;
    for (const label p : w.segmentPatch()) nLid += (p == 1);
    EXPECT_EQ(nLid, 10);
}


TEST(wallMesh, openEndsCountAsStraight)
{
    const wallMesh w = makeWalls
    (
        "tank { type polyline; points ((0 1) (0 0) (2 0) (2 1)); }", 0.25
    );
    EXPECT_EQ(w.points().size(), 17);
    EXPECT_EQ(countAngle(w, 0.5*pi), 2);
    EXPECT_EQ(countAngle(w, pi), 15);
}


TEST(wallMesh, circleAnglesTurnOnceAround)
{
    const wallMesh w = makeWalls
    (
        "cylinder { type circle; centre (0 0); radius 0.5; side outside; }", 0.05
    );
    // Fluid outside: each vertex angle exceeds pi and the turns add to -2 pi
    scalar turn = 0;
    for (const scalar a : w.pointAngles())
    {
        EXPECT_GT(a, pi);
        turn += pi - a;
    }
    EXPECT_NEAR(turn, -2*pi, 1e-10);
    // Chords of about dr: 63 chords of length 2 R sin(pi/63)
    EXPECT_EQ(w.segments().size(), 63);
}


TEST(wallMesh, arcRunsCounterClockwise)
{
    const wallMesh w = makeWalls
    (
        "bowl { type arc; centre (0 1); radius 1; startAngle 180; endAngle 360; }", 0.1
    );
    // Fluid inside the circle: the normal at the bottom points up
    scalar best = GREAT;
    vector2D nBottom(vector2D::zero);
    forAll(w.segments(), s)
    {
        const vector2D mid = 0.5*(w.points()[w.segments()[s].first()] + w.points()[w.segments()[s].second()]);
        if (mag(mid.x()) < best) { best = mag(mid.x()); nBottom = w.segmentNormals()[s]; }
    }
    EXPECT_GT(nBottom.y(), 0.99);
    EXPECT_EQ(w.points().size(), 32);   // round(pi/0.1) = 31 chords
}


TEST(wallMesh, oppositeFluidSidesAreAnError)
{
    sphTest::throwOnFatal();
    EXPECT_THROW
    (
        makeWalls
        (
            "a { type line; points ((0 0) (1 0)); }"
            "b { type line; points ((2 0) (1 0)); }",
            0.1
        ),
        Foam::error
    );
}


TEST(wallMesh, zeroLengthSegmentIsAnError)
{
    sphTest::throwOnFatal();
    try
    {
        makeWalls("w { type polyline; points ((0 0) (1 0) (1 0) (1 1)); }", 0.1);
        FAIL() << "repeated point accepted";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(std::string(e.message()).find("zero-length"), std::string::npos) << e.message();
    }
}


TEST(wallMesh, unknownShapeListsTheValidOnes)
{
    sphTest::throwOnFatal();
    try
    {
        makeWalls("w { type hexagon; }", 0.1);
        FAIL() << "unknown shape accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("hexagon"), std::string::npos) << msg;
        EXPECT_NE(msg.find("polyline"), std::string::npos) << msg;
    }
}


TEST(wallMesh, dummyLayersFillTheRingOutsideABox)
{
    const scalar dr = 0.1;
    const wallMesh w = makeWalls("tank { type box; min (0 0); max (1 1); }", dr);
    List<vector2D> pos;
    labelList layer, patch;
    w.dummyLayers(3, dr, pos, layer, patch);

    // Layer k is the outline of a square of side 1 + (2k + 1) dr:
    // 4 (11 + 2k) points
    labelList n(3, 0);
    for (const label k : layer) ++n[k];
    EXPECT_EQ(n[0], 44);
    EXPECT_EQ(n[1], 52);
    EXPECT_EQ(n[2], 60);

    // Each lies (k + 1/2) dr outside (in the max-norm), the corners
    // included: the fluid lattice at (i + 1/2) dr continued
    bool foundCorner = false;
    forAll(pos, i)
    {
        const vector2D& p = pos[i];
        const scalar out = max
        (
            max(-p.x(), p.x() - 1),
            max(-p.y(), p.y() - 1)
        );
        EXPECT_NEAR(out, (layer[i] + 0.5)*dr, 1e-12) << p.x() << " " << p.y();
        foundCorner = foundCorner || mag(p - vector2D(-0.25, -0.25)) < 1e-12;
    }
    EXPECT_TRUE(foundCorner);
}


TEST(wallMesh, dummyLayersShrinkInsideAnObstacleAndStopWhenItCloses)
{
    const scalar dr = 0.1;
    const wallMesh w = makeWalls
    (
        "obstacle { type box; min (0 0); max (0.3 0.3); side outside; }", dr
    );
    List<vector2D> pos;
    labelList layer, patch;
    w.dummyLayers(4, dr, pos, layer, patch);

    // Inside a 0.3 square: layer 0 is the outline of the 0.2 square
    // (2 pieces a side), layer 1 would have no size and is dropped
    labelList n(4, 0);
    for (const label k : layer) ++n[k];
    EXPECT_EQ(n[0], 8);
    EXPECT_EQ(n[1], 0);
    EXPECT_EQ(n[2], 0);
    for (const vector2D& p : pos)
    {
        EXPECT_NEAR(w.signedDistance(p), -0.5*dr, 1e-12);
    }
}


TEST(wallMesh, dummyLayersLeaveOutACrestNarrowerThanTheirOffset)
{
    // A weir plate in a channel: its crest (0.05) is narrower than the
    // offset of every layer, whose mitred corners meet beyond it. The
    // collapsed crest pieces are left out; the faces keep their layers.
    const scalar dr = 0.1;
    const wallMesh w = makeWalls
    (
        "bed  { type line; points ((0 0) (1 0)); }"
        "weir { type polyline; points ((1 0) (1 1) (1.05 1) (1.55 0.5) (1.55 0)); }"
        "bed2 { type line; points ((1.55 0) (3 0)); }",
        dr
    );
    List<vector2D> pos;
    labelList layer, patch;
    w.dummyLayers(3, dr, pos, layer, patch);
    ASSERT_GT(pos.size(), 0);

    label nUpstream = 0, nDownstream = 0;
    forAll(pos, i)
    {
        // Never on the fluid side
        EXPECT_LT(w.signedDistance(pos[i]), -0.25*dr) << "dummy " << i;
        if (layer[i] == 0 && pos[i].y() > 0)
        {
            if (mag(pos[i].x() - (1 + 0.5*dr)) < 1e-9) ++nUpstream;
            if (mag(pos[i].x() - (1.55 - 0.5*dr)) < 1e-9) ++nDownstream;
        }
    }
    // The first layer runs along both faces of the plate
    EXPECT_GE(nUpstream, 9);
    EXPECT_GE(nDownstream, 4);
}
