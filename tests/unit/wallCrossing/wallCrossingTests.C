/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    wallCrossing: a move through a wall is mirrored back with its normal
    velocity reversed (times the elasticity: 0 leaves the velocity along
    the wall only), a move inside the fluid is left alone; in a channel
    periodic in x (walls joined through the seam, an obstacle in the
    middle) a particle crossing the seam is not a wall crossing, whether
    its new position is given wrapped or not, while a wall crossed next to
    the seam is still caught and bounced.

    Positions are mirrored exactly up to round-off: 1e-12.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallCrossing.H"

#include <ostream>

using namespace Foam;

namespace Foam
{
    inline void PrintTo(const vector2D& v, std::ostream* os)
    {
        *os << '(' << v.x() << ' ' << v.y() << ')';
    }

    inline std::ostream& operator<<(std::ostream& os, const vector2D& v)
    {
        return os << '(' << v.x() << ' ' << v.y() << ')';
    }
}

namespace
{
    const scalar dr = 0.05;
    const scalar tol = 1e-12;

    SPH::wallMesh makeWalls(const std::string& text, const SPH::domain& dom)
    {
        const dictionary d(sphTest::dict(text));
        wordList names;
        List<List<SPH::wallChain>> chains;
        for (const entry& e : d)
        {
            names.append(e.keyword());
            chains.append(SPH::wallShape::New(e.keyword(), e.dict())->chains(dr));
        }
        return SPH::wallMesh(names, chains, dr, dom);
    }

    //- One move x0 -> x with velocity U; returns the number bounced
    label bounceOne(const SPH::wallCrossing& wc, const vector2D& x0, vector2D& x, vector2D& U)
    {
        List<vector2D> X0(1, x0), X(1, x), V(1, U);
        const label n = wc.bounce(X0, X, V, 1);
        x = X[0];
        U = V[0];
        return n;
    }

    //- The walls of the box [0, 1]^2
    SPH::wallMesh unitTank()
    {
        return makeWalls
        (
            "tank { type box; min (0 0); max (1 1); }",
            SPH::domain(vector2D(0, 0), vector2D(1, 1))
        );
    }

    //- The channel x in [0, 1) periodic, walls at y = 0 and 1, an
    //- obstacle (0.4, 0.4)-(0.6, 0.6) in the middle
    const SPH::domain channel(vector2D(0, 0), vector2D(1, 1), {true, false});
    const std::string channelWalls =
        "lowerWall { type line; points ((0 0) (1 0)); }"
        " upperWall { type line; points ((1 1) (0 1)); }"
        " obstacle { type box; min (0.4 0.4); max (0.6 0.6); side outside; }";
}


TEST(wallCrossing, aMoveThroughAWallIsMirroredBack)
{
    const SPH::wallMesh walls(unitTank());
    const SPH::wallCrossing wc(walls, 4*dr);

    vector2D x(0.5, -0.01), U(0.3, -2);
    EXPECT_EQ(bounceOne(wc, vector2D(0.5, 0.02), x, U), 1);
    EXPECT_NEAR(x.x(), 0.5, tol);
    EXPECT_NEAR(x.y(), 0.01, tol);
    EXPECT_EQ(U, vector2D(0.3, 2));

    vector2D y(0.52, 0.3), V(1, 1);
    EXPECT_EQ(bounceOne(wc, vector2D(0.5, 0.3), y, V), 0);
    EXPECT_EQ(y, vector2D(0.52, 0.3));
    EXPECT_EQ(V, vector2D(1, 1));
}


TEST(wallCrossing, anInelasticBounceKeepsOnlyTheVelocityAlongTheWall)
{
    const SPH::wallMesh walls(unitTank());
    const SPH::wallCrossing wc(walls, 4*dr);

    // Through the floor: the position is mirrored as in an elastic bounce
    List<vector2D> x0(1, vector2D(0.5, 0.02)), x(1, vector2D(0.5, -0.01));
    List<vector2D> U(1, vector2D(0.3, -2));
    EXPECT_EQ(wc.bounce(x0, x, U, 1, 0), 1);
    EXPECT_NEAR(x[0].y(), 0.01, tol);
    EXPECT_NEAR(U[0].x(), 0.3, tol);
    EXPECT_NEAR(U[0].y(), 0, tol);

    // Half the normal speed back through the right wall
    x0[0] = vector2D(0.99, 0.5);
    x[0] = vector2D(1.02, 0.5);
    U[0] = vector2D(4, -1);
    EXPECT_EQ(wc.bounce(x0, x, U, 1, 0.5), 1);
    EXPECT_NEAR(x[0].x(), 0.98, tol);
    EXPECT_NEAR(U[0].x(), -2, tol);
    EXPECT_NEAR(U[0].y(), -1, tol);
}


TEST(wallCrossing, crossingThePeriodicSeamIsNotAWallCrossing)
{
    const SPH::wallMesh walls(makeWalls(channelWalls, channel));
    const SPH::wallCrossing wc(walls, 4*dr);

    // Through the seam at the obstacle's height (the wrapped move is not
    // a trip across the domain through the obstacle), along the walls, and
    // with the new position given unwrapped
    const vector2D moves[][2] =
    {
        {vector2D(0.99, 0.5), vector2D(0.01, 0.5)},
        {vector2D(0.01, 0.45), vector2D(0.98, 0.46)},
        {vector2D(0.99, 0.5), vector2D(1.01, 0.5)},
        {vector2D(0.995, 0.01), vector2D(0.005, 0.01)},
        {vector2D(0.005, 0.99), vector2D(0.995, 0.98)},
        {vector2D(1.0, 0.3), vector2D(0.0, 0.31)},
        {vector2D(-1e-17, 0.02), vector2D(0.99, 0.02)}
    };
    for (const auto& m : moves)
    {
        vector2D x(m[1]), U(1, 0.1);
        EXPECT_EQ(bounceOne(wc, m[0], x, U), 0) << m[0] << " -> " << m[1];
        EXPECT_EQ(x, m[1]);
        EXPECT_EQ(U, vector2D(1, 0.1));
    }
}


TEST(wallCrossing, aWallCrossedNextToTheSeamIsCaught)
{
    const SPH::wallMesh walls(makeWalls(channelWalls, channel));
    const SPH::wallCrossing wc(walls, 4*dr);

    struct move { vector2D x0, x, expect; };
    const move moves[] =
    {
        // Across the seam and through the bed: mirrored in y, x kept as given
        {vector2D(0.99, 0.01), vector2D(0.01, -0.01), vector2D(0.01, 0.01)},
        {vector2D(0.99, 0.01), vector2D(1.01, -0.01), vector2D(1.01, 0.01)},
        {vector2D(0.005, 0.01), vector2D(-0.005, -0.01), vector2D(-0.005, 0.01)},
        {vector2D(0.005, 0.99), vector2D(0.995, 1.01), vector2D(0.995, 0.99)},
        // On the seam, through the segment across it
        {vector2D(0, 0.02), vector2D(0, -0.02), vector2D(0, 0.02)},
        {vector2D(1, 0.02), vector2D(1, -0.02), vector2D(1, 0.02)},
        // Into the obstacle, far from the seam: as without periodicity
        {vector2D(0.39, 0.5), vector2D(0.41, 0.5), vector2D(0.39, 0.5)}
    };
    for (const move& m : moves)
    {
        // The velocity of the move, its minimum image
        const vector2D d(channel.separation(m.x, m.x0));
        vector2D x(m.x), U(d);
        EXPECT_EQ(bounceOne(wc, m.x0, x, U), 1) << m.x0 << " -> " << m.x;
        EXPECT_LT(mag(x - m.expect), tol) << m.x0 << " -> " << m.x << ": " << x;
        EXPECT_LT(mag(mag(U) - mag(d)), tol);
        // The normal part reversed: now away from the wall it hit
        EXPECT_GT(walls.signedDistance(x), 0);
    }
}


// ************************************************************************* //
