/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::wallConditions: the boundaryField of 0/U and 0/p read with
    OpenFOAM's type names, Function1 and dictionary rules (patterns,
    #include, $macros), and the errors of bad entries; SPH::wallBoundaries'
    error for a case that still has constant/movingWalls.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallTestTools.H"
#include "wallConditions.H"
#include "wallBoundaries.H"
#include "wallShape.H"

using namespace Foam;
using cond = SPH::wallConditions::conditionType;

namespace
{
    const scalar dr = 0.1;

    //- Walls from "name { type ...; ... }" patch dictionaries
    SPH::wallMesh makeWalls(const std::string& text)
    {
        return sphTest::makeWalls(text, dr);
    }

    //- The unit cavity: its lid y = 1 and three fixed walls
    const std::string cavity =
        "lid { type line; points ((1 1) (0 1)); }"
        " fixedWalls { type polyline; points ((0 1) (0 0) (1 0) (1 1)); }";

    using sphTest::errorOf;

    std::string errorOf(const std::string& boundaryField, const std::string& field = "U")
    {
        const SPH::wallMesh walls(makeWalls(cavity));
        return errorOf
        (
            [&]() { SPH::wallConditions c(sphTest::dict(boundaryField), walls, field); }
        );
    }

    bool has(const std::string& msg, const std::string& s)
    {
        return msg.find(s) != std::string::npos;
    }

    class wallConditions : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            sphTest::throwOnFatal();
        }
    };
}


TEST_F(wallConditions, uniformFixedValueTableRampsTheLid)
{
    // The FV cavity's lid: 0 to (1 0 0) over 2 s, linear between, held
    // after (OpenFOAM's table clamps by default)
    const SPH::wallMesh walls(makeWalls(cavity));
    const SPH::wallConditions U
    (
        sphTest::dict
        (
            "lid { type uniformFixedValue; uniformValue table ((0 (0 0 0)) (2 (1 0 0)));"
            " value uniform (0 0 0); }"
            " fixedWalls { type noSlip; }"
        ),
        walls, "U"
    );
    const label lid = walls.patchNames().find("lid");
    const label fixed = walls.patchNames().find("fixedWalls");
    EXPECT_EQ(U.type(lid), cond::uniformFixedValue);
    EXPECT_TRUE(U.slides(lid));
    EXPECT_FALSE(U.slides(fixed));
    for (const scalar t : {-1.0, 0.0, 0.5, 1.5, 2.0, 9.0})
    {
        const scalar ramp = min(max(t, 0.0)/2, 1.0);
        // Linear interpolation: exact but for the last bit
        EXPECT_NEAR(U.velocity(lid, t).x(), ramp, 1e-15) << "t = " << t;
        EXPECT_EQ(U.velocity(lid, t).y(), 0);
        EXPECT_EQ(U.velocity(fixed, t), vector2D::zero);
    }
    EXPECT_EQ(U.describe(lid), "slides along itself at U (1 0), from rest over 2 s (uniformFixedValue)");

    // Other Function1s: a constant, and fixedValue
    const SPH::wallConditions U2
    (
        sphTest::dict
        (
            "lid { type uniformFixedValue; uniformValue sine; uniformValueCoeffs"
            " { frequency 0.5; amplitude 1; scale (2 0 0); level (0 0 0); } }"
            " fixedWalls { type fixedValue; value uniform (0 0 0); }"
        ),
        walls, "U"
    );
    // OpenFOAM's sine: level + amplitude scale sin(2 pi f t)
    EXPECT_NEAR(U2.velocity(lid, 0.5).x(), 2, 1e-12);
    EXPECT_EQ(U2.type(fixed), cond::fixedValue);
    EXPECT_EQ(U2.velocity(fixed, 3), vector2D::zero);
}


TEST_F(wallConditions, patternKeysMatchAndExactNamesWin)
{
    const SPH::wallMesh walls(makeWalls(cavity));
    const label lid = walls.patchNames().find("lid");
    const label fixed = walls.patchNames().find("fixedWalls");
    {
        const SPH::wallConditions U
        (
            sphTest::dict
            (
                "\"(fixed.*)\" { type noSlip; }"
                " lid { type fixedValue; value uniform (0.5 0 0); }"
            ),
            walls, "U"
        );
        EXPECT_EQ(U.type(fixed), cond::noSlip);
        EXPECT_EQ(U.velocity(lid, 0), vector2D(0.5, 0));
    }
    {
        // An exact name beats a pattern that also matches it
        const SPH::wallConditions U
        (
            sphTest::dict
            (
                "lid { type fixedValue; value uniform (0.5 0 0); }"
                " \".*\" { type noSlip; }"
            ),
            walls, "U"
        );
        EXPECT_EQ(U.type(lid), cond::fixedValue);
        EXPECT_EQ(U.type(fixed), cond::noSlip);
        EXPECT_EQ(U.entryIndex(lid) == U.entryIndex(fixed), false);
    }
    {
        // p: both pressure types, one pattern for both walls
        const SPH::wallConditions p
        (
            sphTest::dict("\"(lid|fixedWalls)\" { type fixedFluxPressure; }"), walls, "p"
        );
        EXPECT_EQ(p.type(lid), cond::fixedFluxPressure);
        EXPECT_EQ(p.type(fixed), cond::fixedFluxPressure);
        EXPECT_EQ(p.nEntries(), 1);
    }
}


TEST_F(wallConditions, emptyAndCyclicPatchesOfAnFVCaseAreIgnored)
{
    const SPH::wallMesh walls(makeWalls(cavity));
    const SPH::wallConditions U
    (
        sphTest::dict
        (
            "lid { type noSlip; } fixedWalls { type noSlip; }"
            " frontAndBack { type empty; }"
            " \"(left|right)\" { type cyclic; }"
        ),
        walls, "U"
    );
    EXPECT_EQ(U.nEntries(), 2);
}


TEST_F(wallConditions, unknownTypeListsTheValidOnes)
{
    std::string msg = errorOf("lid { type noSlipp; } fixedWalls { type noSlip; }");
    for (const char* s :
        {"noSlipp", "lid", "noSlip", "slip", "fixedValue", "uniformFixedValue",
         "movingWallVelocity"})
    {
        EXPECT_TRUE(has(msg, s)) << s << ": " << msg;
    }
    // The pressure's own
    msg = errorOf("\".*\" { type noSlip; }", "p");
    for (const char* s : {"noSlip", "zeroGradient", "fixedFluxPressure"})
    {
        EXPECT_TRUE(has(msg, s)) << s << ": " << msg;
    }
    // An empty wall patch is an unknown type too
    msg = errorOf("lid { type empty; } fixedWalls { type noSlip; }");
    EXPECT_TRUE(has(msg, "Unknown U wall condition type empty")) << msg;
}


TEST_F(wallConditions, missingWallPatchEntryIsAnErrorNamingIt)
{
    const std::string msg = errorOf("lid { type noSlip; } frontAndBack { type empty; }");
    EXPECT_TRUE(has(msg, "No entry for the wall patch fixedWalls")) << msg;
}


TEST_F(wallConditions, entriesNamingNoWallPatchAreErrors)
{
    std::string msg = errorOf
    (
        "lid { type noSlip; } fixedWalls { type noSlip; }"
        " inlet { type fixedValue; value uniform (1 0 0); }"
    );
    EXPECT_TRUE(has(msg, "No wall patch inlet")) << msg;
    EXPECT_TRUE(has(msg, "fixedWalls")) << msg;

    msg = errorOf("lid { type noSlip; } fixedWalls { type noSlip; } \"in.*\" { type noSlip; }");
    EXPECT_TRUE(has(msg, "matches no wall patch")) << msg;
}


TEST_F(wallConditions, badVelocitiesAreErrors)
{
    const std::string still = " fixedWalls { type noSlip; }";
    // Across the lid: eq. (43) would let fluid through
    std::string msg = errorOf("lid { type fixedValue; value uniform (0 1 0); }" + still);
    EXPECT_TRUE(has(msg, "must move along itself")) << msg;
    // Along z
    msg = errorOf("lid { type fixedValue; value uniform (1 0 1); }" + still);
    EXPECT_TRUE(has(msg, "z component must be 0")) << msg;
    // A table that turns across the wall later is caught when evaluated
    const SPH::wallMesh walls(makeWalls(cavity));
    const SPH::wallConditions U
    (
        sphTest::dict
        (
            "lid { type uniformFixedValue; uniformValue table ((0 (0 0 0)) (1 (1 1 0))); }"
          + still
        ),
        walls, "U"
    );
    msg = errorOf([&]() { U.velocity(walls.patchNames().find("lid"), 0.5); });
    EXPECT_TRUE(has(msg, "at t = 0.5")) << msg;
    // Not uniform, or missing
    msg = errorOf("lid { type fixedValue; value nonuniform List<vector> 0(); }" + still);
    EXPECT_TRUE(has(msg, "uniform (Ux Uy 0)")) << msg;
    msg = errorOf("lid { type uniformFixedValue; }" + still);
    EXPECT_TRUE(has(msg, "uniformValue")) << msg;
}


TEST_F(wallConditions, readsTheCaseFileWithIncludesAndMacros)
{
    // As the FV cavity's 0/U: the lid velocity from an #include-d file
    const fileName dir = sphTest::makeCase("wallConditionsFile");
    sphTest::writeFile(dir/"system"/"lidParameters", "Ulid 2; tRamp 0.5;\n");
    sphTest::writeFile
    (
        dir/"0"/"U",
        "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
        "#include \"../system/lidParameters\"\n"
        "dimensions [0 1 -1 0 0 0 0];\n"
        "internalField uniform (0 0 0);\n"
        "boundaryField\n{\n"
        "    lid { type uniformFixedValue;"
        " uniformValue table ((0 (0 0 0)) ($tRamp ($Ulid 0 0))); value uniform (0 0 0); }\n"
        "    fixedWalls { type noSlip; }\n"
        "    frontAndBack { type empty; }\n"
        "}\n"
    );
    auto runTime = sphTest::makeTime(dir);
    const SPH::wallMesh walls(makeWalls(cavity));
    const SPH::wallConditions U(*runTime, walls, "U");
    EXPECT_NEAR(U.velocity(walls.patchNames().find("lid"), 0.25).x(), 1, 1e-15);

    // The file and the entry path in the errors
    sphTest::writeFile
    (
        dir/"0"/"p",
        "FoamFile { version 2.0; format ascii; class volScalarField; object p; }\n"
        "boundaryField { lid { type zeroGradient; } fixedWalls { type fixedValue; } }\n"
    );
    try
    {
        SPH::wallConditions p(*runTime, walls, "p");
        ADD_FAILURE() << "no error";
    }
    catch (const Foam::IOerror& err)
    {
        EXPECT_TRUE(has(err.ioFileName(), "0/p.boundaryField.fixedWalls")) << err.ioFileName();
    }
    // No file at all
    rmDir(dir/"0");
    const std::string msg = errorOf([&]() { SPH::wallConditions p(*runTime, walls, "p"); });
    EXPECT_TRUE(has(msg, "0/p")) << msg;
}


TEST_F(wallConditions, formerMovingWallsFileSaysWhatReplacesIt)
{
    const fileName dir = sphTest::makeCase("wallConditionsMovingWalls");
    sphTest::writeFile(dir/"constant"/"movingWalls", "lid { type sliding; U (1 0); }\n");
    auto runTime = sphTest::makeTime(dir);
    const SPH::wallMesh walls(makeWalls(cavity));
    const std::string msg = errorOf([&]() { SPH::wallBoundaries b(*runTime, walls); });
    for (const char* s : {"movingWalls", "0/U", "constant/dynamicMeshDict", "uniformFixedValue"})
    {
        EXPECT_TRUE(has(msg, s)) << s << ": " << msg;
    }
}


TEST_F(wallConditions, onlyWhatTheSolverSupports)
{
    const SPH::wallMesh walls(makeWalls(cavity));
    const SPH::wallConditions U
    (
        sphTest::dict("lid { type fixedValue; value uniform (1 0 0); } fixedWalls { type noSlip; }"),
        walls, "U"
    );
    const std::string msg = errorOf
    (
        [&]() { U.allowOnly({cond::noSlip}, "the dummy walls"); }
    );
    for (const char* s : {"lid", "fixedValue", "the dummy walls", "noSlip"})
    {
        EXPECT_TRUE(has(msg, s)) << s << ": " << msg;
    }
}


TEST_F(wallConditions, cavityTutorialSphCaseUsesTheFvCasesU)
{
    // tutorials/cavity: sph/0/U is fv/0/U to the byte, and its lid ramps
    // from 0 to Ulid over tRamp (system/cavityParameters: 1 and 1 s)
    const fileName tutorial = fileName(SPHFOAM_SOURCE_DIR)/"tutorials"/"cavity";
    std::string out;
    EXPECT_EQ(sphTest::run("cmp " + tutorial/"fv/0/U" + " " + tutorial/"sph/0/U", out), 0) << out;

    auto runTime = sphTest::makeTime(tutorial/"fv");
    const SPH::wallMesh walls
    (
        makeWalls
        (
            "movingWall { type line; points ((1 1) (0 1)); }"
            " fixedWalls { type polyline; points ((0 1) (0 0) (1 0) (1 1)); }"
        )
    );
    const SPH::wallConditions U(*runTime, walls, "U");
    const label lid = walls.patchNames().find("movingWall");
    EXPECT_EQ(U.typeName(lid), "uniformFixedValue");
    EXPECT_NEAR(U.velocity(lid, 0.5).x(), 0.5, 1e-15);
    EXPECT_EQ(U.velocity(lid, 5), vector2D(1, 0));
    EXPECT_EQ(U.typeName(walls.patchNames().find("fixedWalls")), "noSlip");
    const SPH::wallConditions p(*runTime, walls, "p");
    EXPECT_EQ(p.typeName(lid), "zeroGradient");
}
