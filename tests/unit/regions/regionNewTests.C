/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Unit tests of region::New: selection by type word, unknown and missing
    types.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>

#include "region.H"
#include "regionTestTools.H"

using namespace Foam;
using namespace Foam::SPH;
using namespace Foam::SPH::test;

// * * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(regionNew, selectsEachShapeByTypeAndKeepsTheName)
{
    const autoPtr<region> b
    (
        regionFrom("water { type box; min (0 0); max (1 1); }")
    );
    const autoPtr<region> p
    (
        regionFrom("pool { type polygon; points ((0 0) (1 0) (0 1)); }")
    );
    const autoPtr<region> c
    (
        regionFrom("hole { type circle; centre (0 0); radius 1; }")
    );

    EXPECT_EQ(b->type(), "box");
    EXPECT_EQ(p->type(), "polygon");
    EXPECT_EQ(c->type(), "circle");

    EXPECT_EQ(b->name(), "water");
    EXPECT_EQ(p->name(), "pool");
    EXPECT_EQ(c->name(), "hole");
}


TEST(regionNew, unknownTypeThrowsListingValidTypes)
{
    const std::string message = errorMessage
    (
        []() { regionFrom("water { type triangle; }"); }
    );

    EXPECT_NE(message.find("triangle"), std::string::npos) << message;
    EXPECT_NE(message.find("box"), std::string::npos) << message;
    EXPECT_NE(message.find("circle"), std::string::npos) << message;
    EXPECT_NE(message.find("polygon"), std::string::npos) << message;
}


TEST(regionNew, missingTypeThrows)
{
    throwFatalErrors();

    EXPECT_THROW
    (
        regionFrom("water { min (0 0); max (1 1); }"),
        Foam::error
    );
}


// ************************************************************************* //
