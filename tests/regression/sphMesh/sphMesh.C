/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    sphMesh as a user runs it: on the Zhou dam-break from sphMeshDict, on
    the blockMesh of OpenFOAM's own interFoam damBreak with -fromPolyMesh,
    and on bad dictionaries, which must fail naming the file and entry.
    Counts are exact (a lattice and straight walls); the VTK picture is read
    back with python3-vtk9.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particles.H"
#include "wallMesh.H"
#include "mathematicalConstants.H"


using namespace Foam;
using sphTest::run;
using constant::mathematical::pi;

namespace
{
    const std::string sphMeshExe = std::string(SPHFOAM_BINARY_DIR) + "/applications/sphMesh";


    //- A copy of a tutorial case in the build folder
    fileName copyTutorial(const std::string& tutorial, const std::string& name)
    {
        const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/name;
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        run("cp -r " + std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/" + tutorial + " " + dir, out);
        return dir;
    }

    //- A case with the given sphMeshDict body, kernel modifiedGaussian
    fileName makeMeshCase(const std::string& name, const std::string& sphMeshDict)
    {
        const fileName dir = sphTest::makeCase(name);
        sphTest::writeFile(dir/"system"/"sphSchemes",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }\n"
            "kernel modifiedGaussian;\n");
        sphTest::writeFile(dir/"system"/"sphMeshDict",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphMeshDict; }\n"
            + sphMeshDict);
        return dir;
    }

    List<vector2D> readPositions(const Time& runTime, const word& set)
    {
        SPH::particles parts(runTime, runTime.constant(), "sphMesh"/set, false);
        parts.read();
        return parts.positions();
    }

    label countAngle(const SPH::wallMesh& w, scalar theta)
    {
        label n = 0;
        for (const scalar a : w.pointAngles()) n += mag(a - theta) < 1e-9;
        return n;
    }
}


TEST(sphMeshApplication, helpPrintsOpenFoamUsage)
{
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -help", out), 0) << out;
    EXPECT_NE(out.find("Usage: sphMesh [OPTIONS]"), std::string::npos) << out;
    EXPECT_NE(out.find("-fromPolyMesh"), std::string::npos) << out;
    EXPECT_NE(out.find("-case"), std::string::npos) << out;
}


TEST(sphMeshApplication, linksTheInstalledLibOpenFOAM)
{
    std::string out;
    run("ldd " + sphMeshExe, out);
    EXPECT_NE(out.find("libOpenFOAM.so => /lib/libOpenFOAM.so"), std::string::npos)
        << out;
}


TEST(sphMeshApplication, zhouDamBreakFromSphMeshDict)
{
    const fileName dir = copyTutorial("damBreak/zhou", "sphMeshZhou");
    std::string out;
    ASSERT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("End"), std::string::npos);

    auto runTime = sphTest::makeTime(dir);
    const scalar H = 0.6, dr = H/48;

    // The column 2H x H holds exactly 96 x 48 lattice particles, the
    // lowest-left at (dr/2, dr/2)
    const List<vector2D> fluid(readPositions(*runTime, "fluid"));
    EXPECT_EQ(fluid.size(), 96*48);
    scalar minX = GREAT, minY = GREAT;
    for (const vector2D& p : fluid) { minX = min(minX, p.x()); minY = min(minY, p.y()); }
    EXPECT_NEAR(minX, 0.5*dr, 1e-12);
    EXPECT_NEAR(minY, 0.5*dr, 1e-12);

    // Walls: four patches joined into one closed tank; its corners see a
    // quarter of fluid
    const SPH::wallMesh walls(*runTime);
    EXPECT_EQ
    (
        walls.patchNames(),
        wordList({"leftWall", "bottom", "rightWall", "top"})
    );
    EXPECT_EQ(countAngle(walls, 0.5*pi), 4);
    EXPECT_EQ(walls.points().size(), walls.segments().size());
    forAll(walls.segments(), s)
    {
        EXPECT_NEAR(walls.segmentLength(s), dr, 0.02*dr);
    }

    // Dummies: 3 layers for the modified Gaussian (support 3 dr), layer k
    // at (k + 1/2) dr behind the wall
    SPH::particles dummy(*runTime, runTime->constant(), "sphMesh/dummy", false);
    dummy.add<label>("layer");
    dummy.add<label>("patch");
    dummy.read();
    labelList perLayer(3, 0);
    for (const label k : dummy.field<label>("layer")) ++perLayer[k];
    // Around the tank (2 x (1.8 + 3.2196) long) and its four corners,
    // about dr apart
    EXPECT_NEAR(perLayer[0], 2*(1.8 + 3.2196)/dr + 4, 4);
    EXPECT_GT(perLayer[1], perLayer[0]);
    EXPECT_GT(perLayer[2], perLayer[1]);
    // (k + 1/2) dr behind the wall, sqrt(2) times that at the corners
    forAll(dummy.positions(), i)
    {
        const scalar d = -walls.signedDistance(dummy.positions()[i]);
        const scalar k = dummy.field<label>("layer")[i] + 0.5;
        EXPECT_GE(d, k*dr*(1 - 1e-9));
        EXPECT_LE(d, k*dr*std::sqrt(2.0)*(1 + 1e-9));
    }

    // The VTK picture reads back in ParaView's reader with every point
    const std::string py =
        std::string(SPHFOAM_PYTHON) + " -c \"from vtkmodules.vtkIOXML import vtkXMLPolyDataReader as R;"
        "r=R();r.SetFileName('" + dir + "/VTK/sphMesh_0.vtp');r.Update();o=r.GetOutput();"
        "print(o.GetNumberOfPoints(), o.GetPointData().GetArray('type').GetRange())\"";
    ASSERT_EQ(run(py, out), 0) << out;
    const label nAll = fluid.size() + walls.points().size() + dummy.size();
    EXPECT_EQ(out, std::to_string(nAll) + " (0.0, 3.0)\n");
}


TEST(sphMeshApplication, damBreakFromOpenFoamTutorialMesh)
{
    // OpenFOAM's own interFoam damBreak: blockMesh, setFields
    const fileName fv = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"sphMeshDamBreakFv";
    rmDir(fv);
    mkDir(fv.path());
    std::string out;
    ASSERT_EQ(run("cp -r /usr/share/doc/openfoam-examples/examples/multiphase/interFoam/"
                  "laminar/damBreak/damBreak " + fv + " && chmod -R u+w " + fv
                  + " && find " + fv + " -name '*.gz' -exec gunzip -f {} +"
                  + " && cp " + fv + "/0/alpha.water.orig " + fv + "/0/alpha.water"
                  + " && blockMesh -case " + fv + " && setFields -case " + fv, out), 0) << out;

    const fileName dir = copyTutorial("damBreak/obstacle/sph", "sphMeshDamBreak");
    ASSERT_EQ(run("mkdir -p " + dir + "/constant " + dir + "/0 && cp -r " + fv
                  + "/constant/polyMesh " + dir + "/constant/ && cp " + fv
                  + "/0/alpha.water " + dir + "/0/", out), 0) << out;
    ASSERT_EQ(run(sphMeshExe + " -fromPolyMesh -case " + dir, out), 0) << out;

    auto runTime = sphTest::makeTime(dir);
    const SPH::wallMesh walls(*runTime);
    // The tutorial closes the top too (atmosphere as a wall)
    EXPECT_EQ
    (
        walls.patchNames(),
        wordList({"leftWall", "rightWall", "lowerWall", "atmosphere"})
    );

    // The tank's four corners and the obstacle's feet see a quarter of
    // fluid, the obstacle's top corners three quarters; a closed loop
    EXPECT_EQ(countAngle(walls, 0.5*pi), 6);
    EXPECT_EQ(countAngle(walls, 1.5*pi), 2);
    EXPECT_EQ(walls.points().size(), walls.segments().size());

    // The water: the cells setFields marked (x < 0.1461, y < 0.292)
    // snapped to the mesh, then the lattice at dr/2 from walls
    const scalar dr = 0.004;
    const List<vector2D> fluid(readPositions(*runTime, "fluid"));
    scalar maxX = 0, maxY = 0;
    for (const vector2D& p : fluid)
    {
        maxX = max(maxX, p.x());
        maxY = max(maxY, p.y());
        EXPECT_GE(walls.signedDistance(p), 0.5*dr*(1 - 1e-6));
    }
    EXPECT_NEAR(maxX, 0.1461, 2*0.584/23);     // within one FV cell
    EXPECT_NEAR(maxY, 0.292, 2*0.584/42);
    EXPECT_NEAR(scalar(fluid.size()), maxX*maxY/(dr*dr), 0.05*fluid.size());

    // The obstacle (x 0.292..0.316, y < 0.048) is filled with dummies
    SPH::particles dummy(*runTime, runTime->constant(), "sphMesh/dummy", false);
    dummy.add<label>("layer");
    dummy.add<label>("patch");
    dummy.read();
    label inObstacle = 0;
    for (const vector2D& p : dummy.positions())
    {
        inObstacle += p.x() > 0.292 && p.x() < 0.316 && p.y() < 0.048 && p.y() > 0;
        EXPECT_LE(walls.signedDistance(p), 1e-9);
    }
    EXPECT_GT(inObstacle, 2*(0.048/dr));
}


TEST(sphMeshApplication, negativeSpacingNamesTheFileLineAndEntry)
{
    const fileName dir = makeMeshCase("sphMeshBadDr",
        "dr -0.01;\n"
        "fluid { w { type box; min (0 0); max (1 1); } }\n"
        "walls { t { type box; min (0 0); max (2 2); } }\n");
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1);
    EXPECT_NE(out.find("FOAM FATAL IO ERROR"), std::string::npos) << out;
    EXPECT_NE(out.find("Entry 'dr'"), std::string::npos) << out;
    // The entry's scope and line, as OpenFOAM names them
    EXPECT_NE(out.find("system/sphMeshDict.dr at line 2."), std::string::npos) << out;
}


TEST(sphMeshApplication, perturbationMovesTheFluidByUpToItsFractionOfDr)
{
    const std::string body =
        "dr 0.1;\n"
        "fluid { w { type box; min (0 0); max (1 1); } }\n"
        "walls { t { type box; min (0 0); max (1 1); } }\n";
    const fileName lattice = makeMeshCase("sphMeshLattice", body);
    const fileName moved = makeMeshCase("sphMeshPerturbed", body + "perturbation 0.3;\n");
    std::string out;
    ASSERT_EQ(run(sphMeshExe + " -case " + lattice, out), 0) << out;
    ASSERT_EQ(run(sphMeshExe + " -case " + moved, out), 0) << out;
    EXPECT_NE(out.find("moved at random by up to 0.3 dr"), std::string::npos) << out;

    auto t0 = sphTest::makeTime(lattice);
    auto t1 = sphTest::makeTime(moved);
    const List<vector2D> a(readPositions(*t0, "fluid"));
    const List<vector2D> b(readPositions(*t1, "fluid"));
    ASSERT_EQ(a.size(), 100);
    ASSERT_EQ(b.size(), a.size());
    scalar largest = 0, mean = 0;
    forAll(a, i)
    {
        const scalar d = mag(b[i] - a[i]);
        largest = max(largest, d);
        mean += d/a.size();
        // Still inside the box, at least 0.2 dr from its walls
        EXPECT_GE(min(b[i].x(), b[i].y()), 0.02 - 1e-12);
        EXPECT_LE(max(b[i].x(), b[i].y()), 0.98 + 1e-12);
    }
    EXPECT_LE(largest, 0.03 + 1e-12);
    // Uniform in the disc: the mean distance is 2/3 of the radius
    EXPECT_NEAR(mean, 0.02, 0.003);
}


TEST(sphMeshApplication, perturbationOfHalfDrOrMoreNamesTheEntry)
{
    const fileName dir = makeMeshCase("sphMeshBadPerturbation",
        "dr 0.1;\n"
        "fluid { w { type box; min (0 0); max (1 1); } }\n"
        "walls { t { type box; min (0 0); max (1 1); } }\n"
        "perturbation 0.5;\n");
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1);
    EXPECT_NE(out.find("Entry 'perturbation' is 0.5"), std::string::npos) << out;
    EXPECT_NE(out.find("sphMeshDict.perturbation at line 5."), std::string::npos) << out;
}


TEST(sphMeshApplication, fluidOutsideTheWallsIsAnError)
{
    const fileName dir = makeMeshCase("sphMeshOutside",
        "dr 0.1;\n"
        "fluid { w { type box; min (1.5 0); max (3 1); } }\n"
        "walls { t { type box; min (0 0); max (2 2); } }\n");
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1);
    EXPECT_NE(out.find("outside the walls"), std::string::npos) << out;
    EXPECT_NE(out.find("sphMeshDict.fluid"), std::string::npos) << out;
}


TEST(sphMeshApplication, spacingLargerThanTheDomainIsAnError)
{
    const fileName dir = makeMeshCase("sphMeshHugeDr",
        "dr 5;\n"
        "fluid { w { type box; min (0 0); max (1 1); } }\n"
        "walls { t { type box; min (0 0); max (2 2); } }\n");
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1);
    EXPECT_NE(out.find("not smaller than the walls' extent"), std::string::npos) << out;
}


TEST(sphMeshApplication, openFluidPolygonIsAnError)
{
    const fileName dir = makeMeshCase("sphMeshOpenPolygon",
        "dr 0.1;\n"
        "fluid { w { type polygon; points ((0 0) (1 1)); } }\n"
        "walls { t { type box; min (0 0); max (2 2); } }\n");
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1);
    EXPECT_NE(out.find("points"), std::string::npos) << out;
    EXPECT_NE(out.find("sphMeshDict.fluid.w"), std::string::npos) << out;
}


TEST(sphMeshApplication, unknownWallTypeListsTheValidOnes)
{
    const fileName dir = makeMeshCase("sphMeshBadWall",
        "dr 0.1;\n"
        "fluid { w { type box; min (0 0); max (1 1); } }\n"
        "walls { t { type boxx; min (0 0); max (2 2); } }\n");
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1);
    EXPECT_NE(out.find("boxx"), std::string::npos) << out;
    EXPECT_NE(out.find("polyline"), std::string::npos) << out;
    EXPECT_NE(out.find("sphMeshDict.walls.t"), std::string::npos) << out;
}


TEST(sphMeshApplication, zeroLengthWallSegmentIsAnError)
{
    const fileName dir = makeMeshCase("sphMeshZeroSegment",
        "dr 0.1;\n"
        "fluid { w { type box; min (0 0); max (1 1); } }\n"
        "walls { t { type polyline; points ((0 2) (0 0) (0 0) (2 0) (2 2)); } }\n");
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1);
    EXPECT_NE(out.find("zero-length segment"), std::string::npos) << out;
}


TEST(sphMeshApplication, unknownBoundaryMethodListsTheValidOnes)
{
    // sphMesh lays the walls out through the wall model the solvers select
    const fileName dir = makeMeshCase("sphMeshBadBoundaryMethod",
        "dr 0.1;\n"
        "fluid { w { type box; min (0 0); max (1 1); } }\n"
        "walls { t { type box; min (0 0); max (2 2); } }\n");
    sphTest::writeFile(dir/"system"/"sphSchemes",
        "FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }\n"
        "kernel wendlandC2;\nboundaryMethod ghostParticles;\n");
    std::string out;
    EXPECT_EQ(run(sphMeshExe + " -case " + dir, out), 1);
    EXPECT_NE(out.find("ghostParticles"), std::string::npos) << out;
    EXPECT_NE(out.find("usaw"), std::string::npos) << out;
    EXPECT_NE(out.find("dummyRepulsive"), std::string::npos) << out;
    EXPECT_NE(out.find("sphSchemes"), std::string::npos) << out;
}


TEST(sphMeshApplication, wallModelDecidesTheLatticeAndTheDummies)
{
    // usaw: fluid on the nodes k dr, no dummies; dummyRepulsive: on the
    // cell centres (k + 1/2) dr, dummies behind the walls
    for (const std::string method : {"usaw", "dummyRepulsive"})
    {
        const fileName dir = makeMeshCase("sphMeshLayout" + method,
            "dr 0.1;\n"
            "fluid { w { type box; min (0 0); max (1 1); } }\n"
            "walls { t { type box; min (0 0); max (1 1); } }\n");
        sphTest::writeFile(dir/"system"/"sphSchemes",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }\n"
            "kernel wendlandC2;\nhByDr 2;\nboundaryMethod " + method + ";\n");
        std::string out;
        ASSERT_EQ(run(sphMeshExe + " -case " + dir, out), 0) << out;
        EXPECT_NE(out.find("Selecting wall model " + method), std::string::npos) << out;

        auto runTime = sphTest::makeTime(dir);
        const List<vector2D> fluid(readPositions(*runTime, "fluid"));
        const bool usaw = method == "usaw";
        // 9 x 9 interior nodes, or 10 x 10 cell centres
        EXPECT_EQ(fluid.size(), usaw ? 81 : 100) << method;
        const scalar offset = usaw ? 0.1 : 0.05;
        scalar xMin = GREAT, yMin = GREAT;
        for (const vector2D& p : fluid)
        {
            xMin = min(xMin, p.x());
            yMin = min(yMin, p.y());
        }
        EXPECT_NEAR(xMin, offset, 1e-12) << method;
        EXPECT_NEAR(yMin, offset, 1e-12) << method;
        const bool dummies = isFile(dir/"constant"/"sphMesh"/"dummy"/"positions");
        if (usaw)
        {
            EXPECT_TRUE(!dummies || readPositions(*runTime, "dummy").empty());
        }
        else
        {
            ASSERT_TRUE(dummies);
            // 4 layers (Wendland, h = 2 dr) around a 1 x 1 box at dr 0.1:
            // layer k is the square ring (k + 1/2) dr outside, 12 + 2k
            // particles a side, 4 (11 + 2k) in all
            label expected = 0;
            for (label k = 0; k < 4; ++k) expected += 4*(10 + 2*k + 1);
            EXPECT_EQ(readPositions(*runTime, "dummy").size(), expected);
        }
    }
}
