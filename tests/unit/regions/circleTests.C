/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Unit tests of SPH::circle: inside test, closed boundary, exact area,
    bounds, bad radius.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>

#include "circle.H"
#include "mathematicalConstants.H"
#include "regionTestTools.H"

using namespace Foam;
using namespace Foam::SPH;
using namespace Foam::SPH::test;

// * * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(circle, containsInsidePointsNotOutside)
{
    const autoPtr<region> hole
    (
        regionFrom("hole { type circle; centre (0.5 0.3); radius 0.1; }")
    );

    EXPECT_TRUE(hole->contains(vector2D(0.5, 0.3)));
    EXPECT_TRUE(hole->contains(vector2D(0.55, 0.35)));
    EXPECT_TRUE(hole->contains(vector2D(0.5, 0.399)));

    EXPECT_FALSE(hole->contains(vector2D(0.5, 0.401)));
    EXPECT_FALSE(hole->contains(vector2D(0.58, 0.38)));   // corner of bounds
    EXPECT_FALSE(hole->contains(vector2D(0, 0)));
}


TEST(circle, circumferenceIsInside)
{
    // Dyadic values so that |p - centre|^2 = radius^2 holds exactly
    const circle hole("hole", vector2D(1, 1), 0.5);

    EXPECT_TRUE(hole.contains(vector2D(1.5, 1)));
    EXPECT_TRUE(hole.contains(vector2D(1, 0.5)));
}


TEST(circle, areaIsPiRadiusSquared)
{
    const autoPtr<region> hole
    (
        regionFrom("hole { type circle; centre (0 0); radius 0.25; }")
    );

    // pi/16: one rounding of pi times an exact power of two
    EXPECT_EQ(hole->area(), constant::mathematical::pi/16);
}


TEST(circle, boundsAreCentrePlusMinusRadius)
{
    const circle hole("hole", vector2D(1, 2), 0.5);

    EXPECT_EQ(hole.bounds().min(), vector2D(0.5, 1.5));
    EXPECT_EQ(hole.bounds().max(), vector2D(1.5, 2.5));
}


TEST(circle, zeroRadiusThrows)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        regionFrom("hole { type circle; centre (0 0); radius 0; }"),
        Foam::error
    );
}


TEST(circle, negativeRadiusThrowsNamingRadius)
{
    const std::string message = errorMessage
    (
        []() { regionFrom("hole { type circle; centre (0 0); radius -1; }"); }
    );

    EXPECT_NE(message.find("entry radius"), std::string::npos) << message;
}


TEST(circle, constructorFromCentreAndRadiusChecksRadius)
{
    throwFatalErrors();

    EXPECT_THROW(circle("hole", vector2D(0, 0), 0), Foam::error);
}


// ************************************************************************* //
