/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    usawWalls in a channel periodic in x (period 1, walls at y = 0 and
    y = 1 joined through the seam by wallMesh, dr = 0.05, Wendland C2 with
    h = 2 dr): gamma and grad gamma do not depend on x, also right at the
    seam (x = 0, 1, -1e-17, -0.0, an unwrapped x), and equal those of long
    non-periodic walls away from their ends; a particle next to the seam
    sees the segments beyond it through their images.

    Tolerance 1e-12: an infinite straight wall is invariant along itself,
    and the closed-form segment integrals add up to it to round-off (the
    sums have a few tens of terms of order 1).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "usawTestTools.H"
#include "wallTestTools.H"
#include "usawWalls.H"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace Foam;
using namespace usawTest;

namespace
{
    const scalar dr = 0.05;
    const scalar h = 2*dr;
    const scalar tol = 1e-12;

    const SPH::domain channel(vector2D(0, 0), vector2D(1, 1), {true, false});

    //- The channel's walls from x = 0 to 1, joined through the seam
    SPH::wallMesh periodicWalls()
    {
        return sphTest::makeWalls
        (
            "lowerWall { type line; points ((0 0) (1 0)); }"
            " upperWall { type line; points ((1 1) (0 1)); }",
            dr, channel
        );
    }

    //- Long walls, not periodic, the points far from their ends
    const char* const longWalls =
        "lowerWall { type line; points ((-3 0) (4 0)); }"
        " upperWall { type line; points ((4 1) (-3 1)); }";

    const std::vector<scalar> heights =
        {0, 1e-3, 0.01, 0.025, dr, 0.07, 0.1, 0.15, 0.2, 0.35, 0.5, 0.8, 0.93, 0.99, 1};

    //- x along the channel: inside, next to the seam and on it
    std::vector<scalar> positionsAlong()
    {
        return
        {
            0, 1e-3, 0.5, 1 - 1e-3,
            1, -0.0, -1e-17, std::nextafter(1.0, 0.0), 0.025, 0.975, 2.3, -0.6
        };
    }
}


TEST(usawWallsPeriodic, gammaIsTheSameAlongTheChannelAndAtTheSeam)
{
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    ASSERT_NEAR(W->h(), h, 1e-15);
    const SPH::wallMesh walls(periodicWalls());
    const SPH::usawWalls usaw(walls, *W, 0);        // the walls' domain
    ASSERT_TRUE(usaw.domain().periodic(0));

    const SPH::wallMesh longW(makeWalls(longWalls, dr));
    const SPH::usawWalls reference(longW, *W, 0);

    for (const scalar y : heights)
    {
        scalar g0, gRef;
        vector2D gg0, ggRef;
        usaw.evaluate(vector2D(0.5, y), g0, gg0);
        reference.evaluate(vector2D(0.5, y), gRef, ggRef);

        // Against the long walls
        EXPECT_NEAR(g0, gRef, tol) << "y " << y;
        EXPECT_NEAR(h*mag(gg0 - ggRef), 0, tol) << "y " << y;

        // Whatever x
        for (const scalar x : positionsAlong())
        {
            scalar g;
            vector2D gg;
            usaw.evaluate(vector2D(x, y), g, gg);
            EXPECT_NEAR(g, g0, tol) << "at (" << x << ' ' << y << ')';
            EXPECT_NEAR(h*mag(gg - gg0), 0, tol) << "at (" << x << ' ' << y << ')';
            EXPECT_NEAR(gg.x()*h, 0, tol) << "at (" << x << ' ' << y << ')';
        }
    }

    // On a wall: half the support in the fluid; beyond 2h: all of it
    EXPECT_NEAR(usaw.gammaAt(vector2D(1, 0)), 0.5, tol);
    EXPECT_NEAR(usaw.gammaAt(vector2D(-1e-17, 1)), 0.5, tol);
    EXPECT_NEAR(usaw.gammaAt(vector2D(0, 0.5)), 1, tol);
}


TEST(usawWallsPeriodic, pairListsAreThoseOfTheNearestImages)
{
    // Particles at the same height, one at x = 0.01 next to the seam and
    // one 10 dr further: the same segments relative to them, the same
    // distances and grad gamma_as, and the first sees the segment whose
    // centre is at x = 0.975 through the seam
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::wallMesh walls(periodicWalls());
    SPH::usawWalls usaw(walls, *W, 0);

    const scalar y = 0.07;
    const List<vector2D> x({vector2D(0.01, y), vector2D(0.51, y), vector2D(1.01, y)});
    usaw.update(x);

    const labelUList& off = usaw.offsets();
    ASSERT_EQ(off[1] - off[0], off[2] - off[1]);
    ASSERT_EQ(off[1] - off[0], off[3] - off[2]);
    ASSERT_GT(off[1] - off[0], 0);

    auto seen = [&](const label a)
    {
        // (x of the segment's centre relative to a, d_as, |grad gamma_as|)
        std::vector<std::vector<scalar>> s;
        for (label k = off[a]; k < off[a + 1]; ++k)
        {
            const label seg = usaw.segments()[k];
            const vector2D r(channel.separation(x[a], usaw.segmentCentres()[seg]));
            s.push_back({r.x(), usaw.distances()[k], mag(usaw.gradGammaAs()[k])});
        }
        std::sort(s.begin(), s.end());
        return s;
    };
    const auto s0 = seen(0), s1 = seen(1), s2 = seen(2);
    for (size_t k = 0; k < s0.size(); ++k)
    {
        for (label c = 0; c < 3; ++c)
        {
            EXPECT_NEAR(s0[k][c], s1[k][c], tol) << k;
            EXPECT_NEAR(s0[k][c], s2[k][c], tol) << k;
        }
        // Only the lower wall within reach, at distance y
        EXPECT_NEAR(s0[k][1], y, tol);
    }

    bool seesAcross = false;
    for (label k = off[0]; k < off[1]; ++k)
    {
        const label s = usaw.segments()[k];
        seesAcross |= mag(usaw.segmentCentres()[s].x() - 0.975) < tol;
        EXPECT_LT(mag(channel.separation(x[0], usaw.segmentCentres()[s])), 2*h + dr);
    }
    EXPECT_TRUE(seesAcross);

    // gamma of the pair sums equals evaluate()
    for (label a = 0; a < 3; ++a)
    {
        EXPECT_NEAR(usaw.gamma()[a], usaw.gammaAt(x[a]), tol);
    }
    EXPECT_NEAR(usaw.gamma()[0], usaw.gamma()[1], tol);
}


TEST(usawWallsPeriodic, segmentsThroughTheSeamAreOneSpacingLong)
{
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::wallMesh walls(periodicWalls());
    const SPH::usawWalls usaw(walls, *W, 7);
    forAll(usaw.segmentCentres(), s)
    {
        const vector2D& c = usaw.segmentCentres()[s];
        EXPECT_GE(c.x(), 0);
        EXPECT_LT(c.x(), 1);
        // Centres at (i + 1/2) dr
        EXPECT_NEAR(c.x()/dr - std::floor(c.x()/dr), 0.5, 1e-9) << s;
        EXPECT_NEAR(mag(usaw.segmentTangents()[s].x()), 1, tol);
    }
    // fromSegment: from the centre of the segment across the seam
    forAll(walls.segments(), k)
    {
        const vector2D& a = walls.points()[walls.segments()[k].first()];
        const vector2D& b = walls.points()[walls.segments()[k].second()];
        const vector2D r(usaw.fromSegment(vector2D(0.01, 0.3), a, b));
        EXPECT_NEAR(r.x(), channel.separation(vector2D(0.01, 0.3), usaw.segmentCentres()[k]).x(), tol);
        EXPECT_LE(mag(r.x()), 0.5);
    }
}


TEST(usawWallsPeriodic, noWallsInABoxPeriodicInXAndY)
{
    // A Taylor-Green box: no segment, gamma 1 everywhere
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::domain box(vector2D(0, 0), vector2D(1, 1), {true, true});
    const SPH::wallMesh none(wordList(), List<List<SPH::wallChain>>(), dr, box);
    EXPECT_EQ(none.segments().size(), 0);
    SPH::usawWalls usaw(none, *W, 0);
    const List<vector2D> x({vector2D(0, 0), vector2D(0.5, 0.99), vector2D(-3, 7)});
    usaw.update(x);
    for (label a = 0; a < x.size(); ++a)
    {
        EXPECT_EQ(usaw.gamma()[a], 1);
        EXPECT_EQ(usaw.gradGamma()[a], vector2D::zero);
        EXPECT_EQ(usaw.offsets()[a + 1], 0);
    }

    // Walls are needed when a direction is not periodic
    EXPECT_THROW
    (
        SPH::wallMesh
        (
            wordList(), List<List<SPH::wallChain>>(), dr,
            SPH::domain(vector2D(0, 0), vector2D(1, 1), {true, false})
        ),
        Foam::error
    );
}


TEST(usawWallsPeriodic, periodicWallsNeedAPeriodicSearch)
{
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::wallMesh walls(periodicWalls());
    EXPECT_THROW
    (
        SPH::usawWalls(walls, *W, 0, SPH::domain(vector2D(0, 0), vector2D(1, 1))),
        Foam::error
    );
    EXPECT_THROW
    (
        SPH::usawWalls
        (
            walls, *W, 0, SPH::domain(vector2D(0, 0), vector2D(2, 1), {true, false})
        ),
        Foam::error
    );
}


// ************************************************************************* //
