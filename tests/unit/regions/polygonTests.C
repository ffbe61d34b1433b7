/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Unit tests of SPH::polygon: inside test for convex and concave shapes,
    either orientation, closed edges, exact area, and each invalid input.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>

#include "polygon.H"
#include "box.H"
#include "regionTestTools.H"

using namespace Foam;
using namespace Foam::SPH;
using namespace Foam::SPH::test;

// * * * * * * * * * * * * * * * * Local Data  * * * * * * * * * * * * * * * //

namespace
{

//- L-shape: the unit square [0,2]x[0,2] without its upper-right quarter
const char* const lShape =
    "pool { type polygon; points ((0 0) (2 0) (2 1) (1 1) (1 2) (0 2)); }";

//- The same L-shape listed clockwise
const char* const lShapeClockwise =
    "pool { type polygon; points ((0 0) (0 2) (1 2) (1 1) (2 1) (2 0)); }";

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(polygon, triangleContainsInsidePointsNotOutside)
{
    const autoPtr<region> wedge
    (
        regionFrom("wedge { type polygon; points ((0 0) (1 0) (0 1)); }")
    );

    EXPECT_TRUE(wedge->contains(vector2D(0.2, 0.2)));
    EXPECT_TRUE(wedge->contains(vector2D(0.49, 0.49)));

    EXPECT_FALSE(wedge->contains(vector2D(0.51, 0.51)));
    EXPECT_FALSE(wedge->contains(vector2D(-0.1, 0.5)));
    EXPECT_FALSE(wedge->contains(vector2D(0.5, -0.1)));
    EXPECT_FALSE(wedge->contains(vector2D(2, 0.5)));
}


TEST(polygon, concaveLShapeExcludesItsNotch)
{
    const autoPtr<region> pool(regionFrom(lShape));

    EXPECT_TRUE(pool->contains(vector2D(0.5, 0.5)));    // corner block
    EXPECT_TRUE(pool->contains(vector2D(1.5, 0.5)));    // lower arm
    EXPECT_TRUE(pool->contains(vector2D(0.5, 1.5)));    // left arm

    EXPECT_FALSE(pool->contains(vector2D(1.5, 1.5)));   // the notch
    EXPECT_FALSE(pool->contains(vector2D(1.01, 1.01)));
    EXPECT_FALSE(pool->contains(vector2D(2.5, 0.5)));
}


TEST(polygon, orientationDoesNotMatter)
{
    const autoPtr<region> anticlockwise(regionFrom(lShape));
    const autoPtr<region> clockwise(regionFrom(lShapeClockwise));

    EXPECT_EQ(anticlockwise->area(), clockwise->area());

    // A lattice over the bounds and beyond, off the edges and on them
    for (label i = -2; i <= 22; ++i)
    {
        for (label j = -2; j <= 22; ++j)
        {
            const vector2D p(0.1*i + 0.005, 0.1*j + 0.005);
            const vector2D q(0.5*i, 0.5*j);

            EXPECT_EQ(anticlockwise->contains(p), clockwise->contains(p)) << show(p);
            EXPECT_EQ(anticlockwise->contains(q), clockwise->contains(q)) << show(q);
        }
    }
}


TEST(polygon, areaIsExact)
{
    // Dyadic corners: every shoelace product and sum is exact
    EXPECT_EQ(regionFrom(lShape)->area(), 3.0);
    EXPECT_EQ(regionFrom(lShapeClockwise)->area(), 3.0);

    const autoPtr<region> wedge
    (
        regionFrom("wedge { type polygon; points ((0 0) (3 0) (0 0.5)); }")
    );
    EXPECT_EQ(wedge->area(), 0.75);
}


TEST(polygon, edgesAndCornersAreInside)
{
    const autoPtr<region> pool(regionFrom(lShape));

    EXPECT_TRUE(pool->contains(vector2D(0, 0)));        // corners
    EXPECT_TRUE(pool->contains(vector2D(1, 1)));        // re-entrant corner
    EXPECT_TRUE(pool->contains(vector2D(2, 1)));
    EXPECT_TRUE(pool->contains(vector2D(1, 0)));        // bottom edge
    EXPECT_TRUE(pool->contains(vector2D(2, 0.5)));      // right edge
    EXPECT_TRUE(pool->contains(vector2D(1.5, 1)));      // notch edges
    EXPECT_TRUE(pool->contains(vector2D(1, 1.5)));
    EXPECT_TRUE(pool->contains(vector2D(0.5, 2)));      // top edge
    EXPECT_TRUE(pool->contains(vector2D(0, 1.5)));      // left edge
}


TEST(polygon, squareAgreesWithBoxOnAndOffEdges)
{
    const polygon square
    (
        "square",
        List<vector2D>({{0, 0}, {1, 0}, {1, 1}, {0, 1}})
    );
    const box unit("unit", vector2D(0, 0), vector2D(1, 1));

    EXPECT_EQ(square.area(), unit.area());

    // Quarter steps: exact values, many of them on the edges
    for (label i = -2; i <= 6; ++i)
    {
        for (label j = -2; j <= 6; ++j)
        {
            const vector2D p(0.25*i, 0.25*j);
            EXPECT_EQ(square.contains(p), unit.contains(p)) << show(p);
        }
    }
}


TEST(polygon, acceptsThreeComponentPointsIgnoringZ)
{
    const autoPtr<region> wedge
    (
        regionFrom("wedge { type polygon; points ((0 0 0) (1 0 0) (0 1 0)); }")
    );

    EXPECT_EQ(wedge->area(), 0.5);
}


TEST(polygon, twoPointsThrowAsDegenerate)
{
    const std::string message = errorMessage
    (
        []() { regionFrom("line { type polygon; points ((0 0) (1 0)); }"); }
    );

    EXPECT_NE(message.find("entry points"), std::string::npos) << message;
    EXPECT_NE(message.find("open or degenerate polygon"), std::string::npos)
        << message;
}


TEST(polygon, bowtieThrowsAsSelfIntersecting)
{
    const std::string message = errorMessage
    (
        []()
        {
            regionFrom
            (
                "tie { type polygon; points ((0 0) (1 1) (1 0) (0 1)); }"
            );
        }
    );

    EXPECT_NE(message.find("self-intersecting"), std::string::npos) << message;
}


TEST(polygon, cornerTouchingAnotherEdgeThrows)
{
    throwFatalErrors();

    // Two triangles joined at the corner (1 1): edges meet there
    EXPECT_THROW
    (
        regionFrom
        (
            "eight { type polygon;"
            " points ((0 0) (2 0) (1 1) (2 2) (0 2) (1 1)); }"
        ),
        Foam::error
    );
}


TEST(polygon, edgeFoldingBackThrows)
{
    throwFatalErrors();

    // The edge (2 2)-(2 1) runs back over the edge (2 0)-(2 2)
    EXPECT_THROW
    (
        regionFrom
        (
            "spike { type polygon; points ((0 0) (2 0) (2 2) (2 1) (0 1)); }"
        ),
        Foam::error
    );
}


TEST(polygon, collinearPointsThrowAsZeroArea)
{
    const std::string message = errorMessage
    (
        []()
        {
            regionFrom("line { type polygon; points ((0 0) (1 1) (2 2)); }");
        }
    );

    EXPECT_NE(message.find("zero area"), std::string::npos) << message;
}


TEST(polygon, nearlyCollinearPointsThrowAsZeroArea)
{
    // On one line in exact arithmetic; in floating point the orientation
    // test may or may not give exactly zero, and either check must catch it
    const std::string message = errorMessage
    (
        []()
        {
            regionFrom
            (
                "line { type polygon; points ((0 0) (0.1 0.3) (0.2 0.6)); }"
            );
        }
    );

    EXPECT_NE(message.find("zero area"), std::string::npos) << message;
}


TEST(polygon, repeatedConsecutivePointThrows)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        regionFrom
        (
            "pool { type polygon; points ((0 0) (1 0) (1 0) (1 1) (0 1)); }"
        ),
        Foam::error
    );
}


TEST(polygon, firstPointRepeatedAtEndThrowsWithHint)
{
    const std::string message = errorMessage
    (
        []()
        {
            regionFrom
            (
                "pool { type polygon;"
                " points ((0 0) (1 0) (1 1) (0 1) (0 0)); }"
            );
        }
    );

    EXPECT_NE(message.find("do not repeat the first point"), std::string::npos)
        << message;
}


TEST(polygon, constructorFromPointsChecksThem)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        polygon("tie", List<vector2D>({{0, 0}, {1, 1}, {1, 0}, {0, 1}})),
        Foam::error
    );
}


// ************************************************************************* //
