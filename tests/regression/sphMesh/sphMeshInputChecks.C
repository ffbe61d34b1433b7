/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The inputs of issue 12 that crashed, hung or were silently mangled by
    sphMesh: each is now an error naming the file or the entry, with the
    message the check gives (FOAM_SIGFPE on, as a user's shell has it;
    never a stack trace).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallMesh.H"
#include "IOdictionary.H"
#include <unistd.h>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string sphMeshExe =
        "FOAM_SIGFPE=true timeout 60 " + std::string(SPHFOAM_BINARY_DIR) + "/applications/sphMesh";

    const std::string tank = "walls { tank { type box; min (0 0); max (1 1); } }\n";
    const std::string water = "fluid { water { type box; min (0 0); max (0.5 0.5); } }\n";

    fileName meshCase(const std::string& name, const std::string& body)
    {
        const fileName dir = sphTest::makeCase(name);
        sphTest::writeFile(dir/"system"/"sphSchemes",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }\n"
            "kernel wendlandC2;\nhByDr 1.3;\n");
        sphTest::writeFile(dir/"system"/"sphMeshDict",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphMeshDict; }\n"
            + body);
        return dir;
    }

    //- Run sphMesh on the body: a fatal error (exit 1) without a stack
    //- trace whose message holds every one of the words
    void expectError
    (
        const std::string& name,
        const std::string& body,
        std::initializer_list<std::string> words
    )
    {
        const fileName dir = meshCase(name, body);
        std::string out;
        EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1) << out;
        EXPECT_EQ(out.find("printStack"), std::string::npos) << out;
        EXPECT_EQ(out.find("Written"), std::string::npos) << out;
        for (const std::string& w : words)
        {
            EXPECT_NE(out.find(w), std::string::npos) << "'" << w << "' in\n" << out;
        }
    }
}


TEST(sphMeshInput, hugeWallBoxNamesTheEntry)
{
    expectError("sphMeshHugeBox", "dr 0.1;\n" + water
        + "walls { tank { type box; min (-1e300 -1e300); max (1e300 1e300); } }\n",
        {"sphMeshDict.walls.tank.min", "Entry 'min'", "1e+300", "1e+15"});
}


TEST(sphMeshInput, overflowingNumberIsABadTokenNotASignal)
{
    // OpenFOAM's reader overflows on 1e400: with the traps held it reports
    // the token with the file and line
    expectError("sphMeshOverflow", "dr 1e400;\n" + water + tank,
        {"sphMeshDict", "line 2"});
}


TEST(sphMeshInput, farLatticeOriginIsOutOfRange)
{
    expectError("sphMeshFarOrigin", "dr 0.1;\nlatticeOrigin (1e9 1e9);\n" + water + tank,
        {"latticeOrigin", "1e+08 spacings dr"});
}


TEST(sphMeshInput, tinySpacingIsOutOfRange)
{
    expectError("sphMeshTinyDr", "dr 1e-12;\n" + water + tank,
        {"sphMeshDict", "spacings dr", "take a larger dr"});
}


TEST(sphMeshInput, hugeFluidCircleNamesTheEntry)
{
    expectError("sphMeshHugeCircle", "dr 0.1;\n"
        "fluid { water { type circle; centre (0.5 0.5); radius 1e300; } }\n" + tank,
        {"Entry 'radius'", "sphMeshDict.fluid.water"});
}


TEST(sphMeshInput, arcShorterThanTheSpacing)
{
    expectError("sphMeshTinyArc", "dr 0.1;\n" + water +
        "walls { tank { type box; min (0 0); max (1 1); }\n"
        "  bump { type arc; centre (0.5 0.5); radius 0.3; startAngle 0; endAngle 1e-9; } }\n",
        {"Wall patch bump", "less than one spacing", "sphMeshDict.walls.bump"});
}


TEST(sphMeshInput, fluidThatIsNotADictionary)
{
    expectError("sphMeshFluidList", "dr 0.1;\nfluid ((0 0) (1 1));\n" + tank,
        {"Entry 'fluid' must be a dictionary", "sphMeshDict"});
}


TEST(sphMeshInput, tooManyDummyLayers)
{
    expectError("sphMeshDummyLayers", "dr 0.1;\nnDummyLayers 1000000000;\n" + water + tank,
        {"Entry 'nDummyLayers'", "1000000000"});
}


TEST(sphMeshInput, countAboveMaxParticlesIsRefusedWithTheEstimate)
{
    // 1e8 particles in a 1 m tank at dr 1e-4: refused at once
    expectError("sphMeshTooMany", "dr 1e-4;\n"
        "fluid { water { type box; min (0 0); max (1 1); } }\n" + tank,
        {"would hold about 1.00", "more than maxParticles", "Estimated: 1e+08 fluid"});

    // and with a lower maxParticles
    expectError("sphMeshMaxParticles", "dr 0.01;\nmaxParticles 1000;\n" + water + tank,
        {"maxParticles = 1000", "Estimated: 2500 fluid"});
}


TEST(sphMeshInput, largeWallCircleDoesNotHang)
{
    // A small pool in a wall circle of radius 1e3 (63 000 wall segments):
    // the lattice covers the fluid only and the distance search is local
    const fileName dir = meshCase("sphMeshBigCircle", "dr 0.1;\n"
        "fluid { water { type box; min (-1 -1); max (1 1); } }\n"
        "walls { ring { type circle; centre (0 0); radius 1e3; } }\n");
    std::string out;
    ASSERT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("Fluid particles: 400"), std::string::npos) << out;
}


TEST(sphMeshInput, regionEntirelyOutsideTheWalls)
{
    expectError("sphMeshRegionOutside", "dr 0.1;\n"
        "fluid { water { type box; min (0 0); max (0.5 0.5); }\n"
        "        lost { type box; min (3 3); max (4 4); } }\n" + tank,
        {"Fluid region lost", "entirely outside", "sphMeshDict.fluid.lost"});
}


TEST(sphMeshInput, regionPartlyOutsideTheWallsBoxIsNotClipped)
{
    expectError("sphMeshRegionPartly", "dr 0.1;\n"
        "fluid { water { type box; min (0.5 0.5); max (1.5 0.8); } }\n" + tank,
        {"lie outside the walls", "kept: ", "does not clip", "sphMeshDict.fluid"});
}


TEST(sphMeshInput, selfIntersectingWallPolygon)
{
    expectError("sphMeshBowTie", "dr 0.1;\n"
        "fluid { water { type box; min (0.4 0.1); max (0.6 0.3); } }\n"
        "walls { tank { type polygon; points ((0 0) (1 1) (1 0) (0 1)); } }\n",
        {"Wall patch tank", "self-intersecting", "sphMeshDict.walls.tank"});
}


TEST(sphMeshInput, duplicatePatchName)
{
    expectError("sphMeshDuplicate", "dr 0.1;\n" + water +
        "walls { tank { type box; min (0 0); max (1 1); }\n"
        "        tank { type box; min (0 0); max (2 2); } }\n",
        {"tank", "sphMeshDict"});
}


TEST(sphMeshInput, duplicateRegionName)
{
    expectError("sphMeshDuplicateRegion", "dr 0.1;\n"
        "fluid { water { type box; min (0 0); max (0.5 0.5); }\n"
        "        water { type box; min (0 0); max (0.2 0.2); } }\n" + tank,
        {"water", "sphMeshDict"});
}


TEST(sphMeshInput, identicalWallBoxesOverlap)
{
    expectError("sphMeshTwoBoxes", "dr 0.1;\n" + water +
        "walls { tank { type box; min (0 0); max (1 1); }\n"
        "        again { type box; min (0 0); max (1 1); } }\n",
        {"Wall patches tank and again overlap", "sphMeshDict.walls.again"});
}


TEST(sphMeshInput, crossingWalls)
{
    expectError("sphMeshCrossing", "dr 0.1;\n" + water +
        "walls { tank { type box; min (0 0); max (1 1); }\n"
        "        baffle { type line; points ((0.75 -0.5) (0.75 0.5)); } }\n",
        {"Wall patches tank and baffle cross", "sphMeshDict.walls.baffle"});
}


TEST(sphMeshInput, wallsCrossingAtASharedVertex)
{
    // The baffle's vertex at y = 0 is the tank's at x = 0.7: an X through
    // one point
    expectError("sphMeshCrossingVertex", "dr 0.1;\n" + water +
        "walls { tank { type box; min (0 0); max (1 1); }\n"
        "        baffle { type line; points ((0.7 -0.5) (0.7 0.5)); } }\n",
        {"Wall patches tank and baffle cross", "sphMeshDict.walls.baffle"});
}


TEST(sphMeshInput, wallEndOnAnotherWallIsAJunction)
{
    // A baffle standing on the floor, at a vertex of it and between two
    for (const std::string x : {"0.7", "0.75"})
    {
        const fileName dir = meshCase("sphMeshJunction" + x.substr(2), "dr 0.1;\n" + water +
            "walls { tank { type box; min (0 0); max (1 1); }\n"
            "        baffle { type line; points ((" + x + " 0) (" + x + " 0.3)); } }\n");
        std::string out;
        EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
        EXPECT_NE(out.find("Fluid particles: 25"), std::string::npos) << out;
    }
}


TEST(sphMeshInput, patchNameWithASpace)
{
    expectError("sphMeshBadName", "dr 0.1;\n" + water +
        "walls { \"a b\" { type box; min (0 0); max (1 1); } }\n",
        {"wall patch name \"a b\"", "cannot be written and read back"});
}


TEST(sphMeshInput, coarseSpacingIsAnError)
{
    expectError("sphMeshCoarse", "dr 0.6;\n"
        "fluid { water { type box; min (0 0); max (1 1); } }\n" + tank,
        {"Fluid region water", "too coarse", "sphMeshDict.fluid.water"});
}


TEST(sphMeshInput, readOnlyMeshFolderIsAnErrorAndUnchanged)
{
    const fileName dir = meshCase("sphMeshReadOnly", "dr 0.1;\n" + water + tank);
    std::string out;
    ASSERT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("Written"), std::string::npos) << out;
    const fileName positions(dir/"constant"/"sphMesh"/"fluid"/"positions");
    const std::string before(sphTest::run("md5sum < " + positions));

    // A finer mesh over the read-only folder
    sphTest::writeFile(dir/"system"/"sphMeshDict",
        "FoamFile { version 2.0; format ascii; class dictionary; object sphMeshDict; }\n"
        "dr 0.05;\n" + water + tank);
    // Permissions do not bind root: run as nobody then, for whom the
    // whole case is read-only
    run("chmod a-w " + dir + "/constant/sphMesh", out);
    const std::string as =
        ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups env " : "";
    EXPECT_EQ(run(as + sphMeshExe + " -case " + dir, out), 1) << out;
    std::string ignored;
    run("chmod u+w " + dir + "/constant/sphMesh", ignored);
    EXPECT_NE(out.find("read-only"), std::string::npos) << out;
    EXPECT_EQ(out.find("Written"), std::string::npos) << out;
    EXPECT_EQ(sphTest::run("md5sum < " + positions), before);
}


TEST(sphMeshInput, layoutRecordsTheWallModel)
{
    for (const std::string method : {"usaw", "dummyRepulsive"})
    {
        const fileName dir = meshCase("sphMeshLayout" + method, "dr 0.1;\n" + water + tank);
        sphTest::writeFile(dir/"system"/"sphSchemes",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }\n"
            "kernel wendlandC2;\nhByDr 1.3;\nboundaryMethod " + method + ";\n");
        std::string out;
        ASSERT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
        auto runTime = sphTest::makeTime(dir);
        const IOdictionary layout
        (
            IOobject("layout", runTime->constant(), "sphMesh", *runTime,
                     IOobject::MUST_READ, IOobject::NO_WRITE, false)
        );
        EXPECT_EQ(layout.get<word>("boundaryMethod"), method);
        EXPECT_EQ(layout.get<scalar>("dr"), 0.1);
        EXPECT_EQ(layout.get<label>("nDummyLayers"), method == "usaw" ? 0 : 2);
        // Nothing left beside constant/sphMesh
        EXPECT_EQ(sphTest::run("ls " + dir + "/constant"), "sphMesh\n");
    }
}


// ************************************************************************* //
