/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    wallMesh in a periodic domain: walls that cross the seam of an
    x-periodic channel are joined through it (one vertex at x = 0 = L,
    segments across the seam, the angle of a straight wall), distances are
    taken through the seam, dummy layers tile across it without duplicates
    or gaps, unmatched wall ends and walls along a seam are reported, and
    the walls read back from constant/sphMesh with their domain.

    Geometry is exact up to round-off: 1e-12 in lengths and angles.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallMesh.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <vector>

using namespace Foam;
using namespace Foam::SPH;
using constant::mathematical::pi;

namespace
{
    const scalar tol = 1e-12;
    const scalar dr = 0.05;

    //- x-periodic on [0, 1), y bounded by the walls
    const SPH::domain channelDomain(vector2D(0, 0), vector2D(1, 1), {true, false});

    wallMesh makeWalls(const std::string& text, const SPH::domain& dom)
    {
        const dictionary d(sphTest::dict(text));
        wordList names;
        List<List<wallChain>> chains;
        for (const entry& e : d)
        {
            names.append(e.keyword());
            chains.append(wallShape::New(e.keyword(), e.dict())->chains(dr));
        }
        return wallMesh(names, chains, dr, dom);
    }

    const std::string channelWalls =
        "lowerWall { type line; points ((0 0) (1 0)); }"
        " upperWall { type line; points ((1 1) (0 1)); }";

    label countAngle(const wallMesh& w, scalar theta)
    {
        label n = 0;
        for (const scalar a : w.pointAngles())
        {
            n += mag(a - theta) < 1e-9;
        }
        return n;
    }

    //- Sorted x of the dummies of one layer at height y
    std::vector<scalar> rowX
    (
        const List<vector2D>& pts,
        const labelList& layer,
        const label k,
        const scalar y
    )
    {
        std::vector<scalar> xs;
        forAll(pts, i)
        {
            if (layer[i] == k && mag(pts[i].y() - y) < tol)
            {
                xs.push_back(pts[i].x());
            }
        }
        std::sort(xs.begin(), xs.end());
        return xs;
    }
}


TEST(periodicWallMesh, channelWallsJoinThroughTheSeam)
{
    const wallMesh w(makeWalls(channelWalls, channelDomain));

    // 20 vertices per wall: the one at x = 1 is the one at x = 0
    EXPECT_EQ(w.points().size(), 40);
    EXPECT_EQ(w.segments().size(), 40);
    labelList nPts, nSeg;
    w.patchCounts(nPts, nSeg);
    EXPECT_EQ(nPts, labelList({20, 20}));
    EXPECT_EQ(nSeg, labelList({20, 20}));

    // Every vertex starts one segment and ends one: closed through the seam
    labelList nOut(w.points().size(), 0), nIn(w.points().size(), 0);
    for (const labelPair& s : w.segments())
    {
        ++nOut[s.first()];
        ++nIn[s.second()];
    }
    EXPECT_EQ(nOut, labelList(w.points().size(), 1));
    EXPECT_EQ(nIn, labelList(w.points().size(), 1));

    // In the box, all distinct; the angles of a straight wall
    forAll(w.points(), v)
    {
        const vector2D& p = w.points()[v];
        EXPECT_GE(p.x(), 0);
        EXPECT_LT(p.x(), 1);
        for (label u = 0; u < v; ++u)
        {
            EXPECT_GT(mag(channelDomain.separation(p, w.points()[u])), 0.5*dr);
        }
    }
    EXPECT_EQ(countAngle(w, pi), 40);

    // Every segment dr long with the fluid's normal, the ones across the
    // seam too
    forAll(w.segments(), s)
    {
        EXPECT_NEAR(w.segmentLength(s), dr, tol) << "segment " << s;
        const scalar ny = (w.segmentPatch()[s] == 0 ? 1 : -1);
        EXPECT_NEAR(w.segmentNormals()[s].x(), 0, tol) << "segment " << s;
        EXPECT_NEAR(w.segmentNormals()[s].y(), ny, tol) << "segment " << s;
        EXPECT_NEAR(w.pointNormals()[w.segments()[s].first()].y(), ny, tol);
    }
    EXPECT_TRUE(w.unmatchedSeamEnds(1e-6*dr).empty());
    EXPECT_TRUE(w.seamSegments(1e-6*dr).empty());
}


TEST(periodicWallMesh, patchesMeetAtTheSeamToo)
{
    // The bed in two patches: they meet at x = 0.4 and through the seam
    const wallMesh w
    (
        makeWalls
        (
            "left { type line; points ((0 0) (0.4 0)); }"
            " right { type line; points ((0.4 0) (1 0)); }",
            channelDomain
        )
    );
    EXPECT_EQ(w.points().size(), 20);
    EXPECT_EQ(w.segments().size(), 20);
    EXPECT_EQ(countAngle(w, pi), 20);
    EXPECT_TRUE(w.unmatchedSeamEnds(1e-6*dr).empty());
}


TEST(periodicWallMesh, signedDistanceIsSeenThroughTheSeam)
{
    const wallMesh w(makeWalls(channelWalls, channelDomain));
    for (const scalar x : {0.0, -0.0, 1e-3, 0.5, 1 - 1e-3, 1.0, -1e-17, 2.3})
    {
        EXPECT_NEAR(w.signedDistance(vector2D(x, 0.3)), 0.3, tol) << x;
        EXPECT_NEAR(w.signedDistance(vector2D(x, 0.02)), 0.02, tol) << x;
        EXPECT_NEAR(w.signedDistance(vector2D(x, 0.99)), 0.01, tol) << x;
        EXPECT_NEAR(w.signedDistance(vector2D(x, -0.01)), -0.01, tol) << x;
    }
}


TEST(periodicWallMesh, dummyLayersTileAcrossTheSeam)
{
    const wallMesh w(makeWalls(channelWalls, channelDomain));
    List<vector2D> pts;
    labelList layer, patch;
    w.dummyLayers(3, dr, pts, layer, patch);

    // 20 per layer and wall: the fluid lattice's columns (i + 1/2) dr
    // continued through the walls, none twice at the seam, none missing
    EXPECT_EQ(pts.size(), 3*2*20);
    for (label k = 0; k < 3; ++k)
    {
        for (const scalar y : {-(k + 0.5)*dr, 1 + (k + 0.5)*dr})
        {
            const std::vector<scalar> xs(rowX(pts, layer, k, y));
            ASSERT_EQ(xs.size(), 20u) << "layer " << k << " y " << y;
            for (label i = 0; i < 20; ++i)
            {
                EXPECT_NEAR(xs[i], (i + 0.5)*dr, tol) << "layer " << k;
            }
        }
    }
    forAll(pts, i)
    {
        EXPECT_GE(pts[i].x(), 0);
        EXPECT_LT(pts[i].x(), 1);
        for (label j = 0; j < i; ++j)
        {
            EXPECT_GT(mag(channelDomain.separation(pts[i], pts[j])), 0.5*dr);
        }
    }
}


TEST(periodicWallMesh, steppedBedJoinsWithItsCorners)
{
    // A step up between x = 0.4 and 0.7 on a bed that crosses the seam
    const wallMesh w
    (
        makeWalls
        (
            "bed { type polyline;"
            " points ((0 0) (0.4 0) (0.4 0.2) (0.7 0.2) (0.7 0) (1 0)); }",
            channelDomain
        )
    );
    EXPECT_EQ(w.points().size(), w.segments().size());
    EXPECT_EQ(countAngle(w, 0.5*pi), 2);
    EXPECT_EQ(countAngle(w, 1.5*pi), 2);
    EXPECT_EQ(countAngle(w, pi), w.points().size() - 4);

    List<vector2D> pts;
    labelList layer, patch;
    w.dummyLayers(2, dr, pts, layer, patch);

    // The first layer under the bed, across the seam from x = 0.7 to 1.4:
    // the columns (i + 1/2) dr without a gap or a double at x = 0 = 1, and
    // the step's two inner corners, mitred dr/2 into it (x = 0.425, 0.675)
    const std::vector<scalar> xs(rowX(pts, layer, 0, -0.5*dr));
    std::vector<scalar> expect;
    for (label i = 0; i < 20; ++i)
    {
        const scalar x = (i + 0.5)*dr;
        if (x < 0.4 + dr || x > 0.7 - dr)
        {
            expect.push_back(x);
        }
    }
    ASSERT_EQ(xs.size(), expect.size());
    for (size_t i = 0; i < xs.size(); ++i)
    {
        EXPECT_NEAR(xs[i], expect[i], tol);
    }
    forAll(pts, i)
    {
        EXPECT_LT(w.signedDistance(pts[i]), -0.25*dr);
        for (label j = 0; j < i; ++j)
        {
            EXPECT_GT(mag(channelDomain.separation(pts[i], pts[j])), 0.5*dr - tol);
        }
    }
}


TEST(periodicWallMesh, unmatchedSeamEndsAreReported)
{
    // A bed that rises by 0.02 over the period does not meet its image
    const wallMesh sloped
    (
        makeWalls("bed { type line; points ((0 0) (1 0.02)); }", channelDomain)
    );
    EXPECT_EQ(sloped.unmatchedSeamEnds(1e-6*dr).size(), 2);

    // A wall on one side of the seam only
    const wallMesh half
    (
        makeWalls("plate { type line; points ((0 0.5) (0.5 0.5)); }", channelDomain)
    );
    const labelList ends(half.unmatchedSeamEnds(1e-6*dr));
    ASSERT_EQ(ends.size(), 1);
    EXPECT_EQ(half.points()[ends[0]], vector2D(0, 0.5));

    // Not periodic: a free end at x = 0 is just a free end
    const wallMesh flat
    (
        makeWalls
        (
            "plate { type line; points ((0 0.5) (0.5 0.5)); }",
            SPH::domain(vector2D(0, 0), vector2D(1, 1))
        )
    );
    EXPECT_TRUE(flat.unmatchedSeamEnds(1e-6*dr).empty());
}


TEST(periodicWallMesh, aWallAlongTheSeamIsReported)
{
    const wallMesh w
    (
        makeWalls
        (
            "bed { type line; points ((0 0) (1 0)); }"
            " post { type line; points ((0 0.8) (0 0.2)); }",
            channelDomain
        )
    );
    EXPECT_EQ(w.seamSegments(1e-6*dr).size(), label(std::round(0.6/dr)));
}


TEST(periodicWallMesh, readBackWithItsDomain)
{
    const fileName dir = sphTest::makeCase("periodicWallsReadBack");
    auto runTime = sphTest::makeTime(dir);
    const wallMesh w(makeWalls(channelWalls, channelDomain));
    w.write(*runTime);
    w.domain().write(*runTime);

    const wallMesh back(*runTime);
    EXPECT_TRUE(back.domain().periodic(0));
    EXPECT_FALSE(back.domain().periodic(1));
    EXPECT_EQ(back.domain().period(), vector2D(1, 0));
    EXPECT_EQ(back.points(), w.points());
    EXPECT_EQ(back.segmentNormals(), w.segmentNormals());
    EXPECT_EQ(back.pointAngles(), w.pointAngles());
    forAll(back.segments(), s)
    {
        EXPECT_NEAR(back.segmentLength(s), dr, tol);
    }
}


// ************************************************************************* //
