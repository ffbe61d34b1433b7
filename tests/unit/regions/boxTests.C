/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Unit tests of SPH::box: inside test, closed edges, exact area, bad input.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>

#include "box.H"
#include "regionTestTools.H"

using namespace Foam;
using namespace Foam::SPH;
using namespace Foam::SPH::test;

// * * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(box, containsInsidePointsNotOutside)
{
    const autoPtr<region> water
    (
        regionFrom("water { type box; min (0 0); max (1.2 0.6); }")
    );

    EXPECT_TRUE(water->contains(vector2D(0.6, 0.3)));
    EXPECT_TRUE(water->contains(vector2D(0.01, 0.59)));

    EXPECT_FALSE(water->contains(vector2D(-0.01, 0.3)));
    EXPECT_FALSE(water->contains(vector2D(1.21, 0.3)));
    EXPECT_FALSE(water->contains(vector2D(0.6, -0.01)));
    EXPECT_FALSE(water->contains(vector2D(0.6, 0.61)));
}


TEST(box, edgesAndCornersAreInside)
{
    const box water("water", vector2D(0, 0), vector2D(1, 1));

    EXPECT_TRUE(water.contains(vector2D(0, 0.5)));
    EXPECT_TRUE(water.contains(vector2D(1, 0.5)));
    EXPECT_TRUE(water.contains(vector2D(0.5, 0)));
    EXPECT_TRUE(water.contains(vector2D(0.5, 1)));
    EXPECT_TRUE(water.contains(vector2D(0, 0)));
    EXPECT_TRUE(water.contains(vector2D(1, 1)));
}


TEST(box, areaIsWidthTimesHeight)
{
    const autoPtr<region> water
    (
        regionFrom("water { type box; min (-0.5 0.25); max (1.5 1); }")
    );

    // Dyadic corners: width 2, height 0.75 and their product are exact
    EXPECT_EQ(water->area(), 1.5);
}


TEST(box, boundsAreItsCorners)
{
    const autoPtr<region> water
    (
        regionFrom("water { type box; min (-1 2); max (3 4); }")
    );

    EXPECT_EQ(water->bounds().min(), vector2D(-1, 2));
    EXPECT_EQ(water->bounds().max(), vector2D(3, 4));
}


TEST(box, acceptsThreeComponentPointsIgnoringZ)
{
    const autoPtr<region> water
    (
        regionFrom("water { type box; min (0 0 -0.05); max (2 1 0.05); }")
    );

    EXPECT_EQ(water->bounds().min(), vector2D(0, 0));
    EXPECT_EQ(water->bounds().max(), vector2D(2, 1));
    EXPECT_EQ(water->area(), 2.0);
}


TEST(box, maxBelowMinThrows)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        regionFrom("water { type box; min (1 0); max (0 1); }"),
        Foam::error
    );
}


TEST(box, maxEqualToMinInOneComponentThrows)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        regionFrom("water { type box; min (0 0); max (1 0); }"),
        Foam::error
    );
}


TEST(box, maxBelowMinMessageNamesTheEntries)
{
    const std::string message = errorMessage
    (
        []() { regionFrom("water { type box; min (1 0); max (0 1); }"); }
    );

    EXPECT_NE(message.find("water"), std::string::npos) << message;
    EXPECT_NE(message.find("entry max"), std::string::npos) << message;
    EXPECT_NE(message.find("entry min"), std::string::npos) << message;
}


TEST(box, pointWithOneComponentThrows)
{
    const std::string message = errorMessage
    (
        []() { regionFrom("water { type box; min (0); max (1 1); }"); }
    );

    EXPECT_NE(message.find("min"), std::string::npos) << message;
    EXPECT_NE(message.find("(x y)"), std::string::npos) << message;
}


TEST(box, constructorFromCornersChecksThem)
{
    throwFatalErrors();

    EXPECT_THROW(box("water", vector2D(0, 1), vector2D(1, 0)), Foam::error);
}


// ************************************************************************* //
