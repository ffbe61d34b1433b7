/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Unit tests of SPH::fluidRegion: union and difference applied in order,
    names, bounds, and each invalid fluid dictionary.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>

#include "fluidRegion.H"
#include "box.H"
#include "circle.H"
#include "regionTestTools.H"

using namespace Foam;
using namespace Foam::SPH;
using namespace Foam::SPH::test;

// * * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(fluidRegion, unionOfTwoRegions)
{
    const fluidRegion fluid
    (
        dictFrom
        (
            "left  { type box; min (0 0); max (1 1); }"
            "right { type circle; centre (2 0.5); radius 0.5; }"
        )
    );

    EXPECT_TRUE(fluid.contains(vector2D(0.5, 0.5)));
    EXPECT_TRUE(fluid.contains(vector2D(2, 0.5)));
    EXPECT_TRUE(fluid.contains(vector2D(1, 0.5)));      // where they touch

    EXPECT_FALSE(fluid.contains(vector2D(1.1, 0.9)));
    EXPECT_FALSE(fluid.contains(vector2D(3, 0.5)));
}


TEST(fluidRegion, subtractedHoleIsNotFluid)
{
    const fluidRegion fluid
    (
        dictFrom
        (
            "water { type box; min (0 0); max (1.2 0.6); }"
            "hole  { type circle; centre (0.5 0.3); radius 0.1;"
            "        operation subtract; }"
        )
    );

    EXPECT_TRUE(fluid.contains(vector2D(0.1, 0.1)));
    EXPECT_TRUE(fluid.contains(vector2D(0.5, 0.45)));

    EXPECT_FALSE(fluid.contains(vector2D(0.5, 0.3)));
    EXPECT_FALSE(fluid.contains(vector2D(0.55, 0.35)));
    EXPECT_FALSE(fluid.contains(vector2D(1.3, 0.3)));
}


TEST(fluidRegion, boundaryOfSubtractedRegionIsNotFluid)
{
    const fluidRegion fluid
    (
        dictFrom
        (
            "water { type box; min (0 0); max (2 1); }"
            "dry   { type box; min (1 0); max (2 1); operation subtract; }"
        )
    );

    EXPECT_TRUE(fluid.contains(vector2D(0.5, 0.5)));
    EXPECT_FALSE(fluid.contains(vector2D(1, 0.5)));
}


TEST(fluidRegion, laterAddRefillsPartOfAHole)
{
    const fluidRegion fluid
    (
        dictFrom
        (
            "water  { type box; min (0 0); max (3 1); }"
            "gap    { type box; min (1 0); max (2 1); operation subtract; }"
            "island { type circle; centre (1.5 0.5); radius 0.25; }"
        )
    );

    EXPECT_TRUE(fluid.contains(vector2D(0.5, 0.5)));
    EXPECT_FALSE(fluid.contains(vector2D(1.1, 0.1)));
    EXPECT_TRUE(fluid.contains(vector2D(1.5, 0.5)));
    EXPECT_TRUE(fluid.contains(vector2D(2.5, 0.5)));
}


TEST(fluidRegion, orderOfOperationsMatters)
{
    // The circle of the test above, now subtracted after the water: its
    // inside is dry, and a later add elsewhere does not refill it
    const fluidRegion fluid
    (
        dictFrom
        (
            "water { type box; min (0 0); max (3 1); }"
            "hole  { type circle; centre (1.5 0.5); radius 0.25;"
            "        operation subtract; }"
            "more  { type box; min (3 0); max (4 1); operation add; }"
        )
    );

    EXPECT_FALSE(fluid.contains(vector2D(1.5, 0.5)));
    EXPECT_TRUE(fluid.contains(vector2D(3.5, 0.5)));
}


TEST(fluidRegion, namesAndSizeFollowDictionaryOrder)
{
    const fluidRegion fluid
    (
        dictFrom
        (
            "water { type box; min (0 0); max (1.2 0.6); }"
            "hole  { type circle; centre (0.5 0.3); radius 0.1;"
            "        operation subtract; }"
            "pool  { type polygon; points ((2 0) (3 0) (3 1)); }"
        )
    );

    ASSERT_EQ(fluid.size(), 3);
    EXPECT_EQ(fluid.names(), wordList({"water", "hole", "pool"}));
    EXPECT_EQ(fluid.operations()[0], fluidRegion::operation::add);
    EXPECT_EQ(fluid.operations()[1], fluidRegion::operation::subtract);
    EXPECT_EQ(fluid.operations()[2], fluidRegion::operation::add);
    EXPECT_EQ(fluid.regions()[2].type(), "polygon");
}


TEST(fluidRegion, boundsCoverAddedRegionsOnly)
{
    const fluidRegion fluid
    (
        dictFrom
        (
            "water { type box; min (0 0); max (1 1); }"
            "cut   { type box; min (0.5 -1); max (5 0.5); operation subtract; }"
            "drop  { type circle; centre (2 2); radius 0.5; }"
        )
    );

    EXPECT_EQ(fluid.bounds().min(), vector2D(0, 0));
    EXPECT_EQ(fluid.bounds().max(), vector2D(2.5, 2.5));
}


TEST(fluidRegion, unknownOperationThrowsListingAddAndSubtract)
{
    const std::string message = errorMessage
    (
        []()
        {
            fluidRegion
            (
                dictFrom
                (
                    "water { type box; min (0 0); max (1 1); }"
                    "hole  { type circle; centre (0.5 0.5); radius 0.1;"
                    "        operation remove; }"
                )
            );
        }
    );

    EXPECT_NE(message.find("entry operation remove"), std::string::npos)
        << message;
    EXPECT_NE(message.find("hole"), std::string::npos) << message;
    EXPECT_NE(message.find("add"), std::string::npos) << message;
    EXPECT_NE(message.find("subtract"), std::string::npos) << message;
}


TEST(fluidRegion, emptyDictionaryThrows)
{
    throwFatalErrors();

    EXPECT_THROW(fluidRegion(dictFrom("")), Foam::error);
}


TEST(fluidRegion, firstRegionSubtractThrows)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        fluidRegion
        (
            dictFrom
            (
                "hole  { type circle; centre (0.5 0.5); radius 0.1;"
                "        operation subtract; }"
                "water { type box; min (0 0); max (1 1); }"
            )
        ),
        Foam::error
    );
}


TEST(fluidRegion, entryThatIsNotADictionaryThrows)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        fluidRegion
        (
            dictFrom
            (
                "water { type box; min (0 0); max (1 1); }"
                "dr 0.01;"
            )
        ),
        Foam::error
    );
}


TEST(fluidRegion, badRegionInsideThrows)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        fluidRegion(dictFrom("water { type box; min (1 1); max (0 0); }")),
        Foam::error
    );
}


TEST(fluidRegion, listConstructionMatchesDictionary)
{
    PtrList<region> regions(2);
    regions.set(0, new box("water", vector2D(0, 0), vector2D(1.2, 0.6)));
    regions.set(1, new circle("hole", vector2D(0.5, 0.3), 0.1));

    const fluidRegion fromList
    (
        std::move(regions),
        {fluidRegion::operation::add, fluidRegion::operation::subtract}
    );

    const fluidRegion fromDict
    (
        dictFrom
        (
            "water { type box; min (0 0); max (1.2 0.6); }"
            "hole  { type circle; centre (0.5 0.3); radius 0.1;"
            "        operation subtract; }"
        )
    );

    EXPECT_EQ(fromList.names(), fromDict.names());

    for (label i = 0; i <= 24; ++i)
    {
        for (label j = 0; j <= 12; ++j)
        {
            const vector2D p(0.05*i, 0.05*j);
            EXPECT_EQ(fromList.contains(p), fromDict.contains(p)) << show(p);
        }
    }
}


TEST(fluidRegion, listConstructionWithFirstSubtractThrows)
{
    throwFatalErrors();

    PtrList<region> regions(1);
    regions.set(0, new circle("hole", vector2D(0.5, 0.3), 0.1));

    EXPECT_THROW
    (
        fluidRegion
        (
            std::move(regions),
            {fluidRegion::operation::subtract}
        ),
        Foam::error
    );
}


TEST(fluidRegion, listConstructionWithMismatchedSizesThrows)
{
    throwFatalErrors();

    PtrList<region> regions(1);
    regions.set(0, new box("water", vector2D(0, 0), vector2D(1, 1)));

    EXPECT_THROW
    (
        fluidRegion
        (
            std::move(regions),
            {fluidRegion::operation::add, fluidRegion::operation::add}
        ),
        Foam::error
    );
}


// ************************************************************************* //
