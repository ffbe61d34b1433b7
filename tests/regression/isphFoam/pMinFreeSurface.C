/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    ISPH { pMin } with freeSurfaceCondition ghost: a free-surface row
    solved below pMin is released at p = 0 (it borders the air), not held
    at pMin with its ghosts, whose pressure rising from pMin to 0 over
    dr/2 pulls the particle into the liquid at |pMin|/(rho dr/2) (the water
    wheel's lone particle at a rising paddle tip, flung at 4.7 m/s). A film
    of two rows on the floor of the tutorial tank (dr = 0.02 m, pMin -1000
    Pa, 50 m/s^2 of ghost pull) whose walls start moving down at 1 m/s:
    rows go below pMin in the first steps; the log counts the free-surface
    ones released, and no written free-surface particle (VTK field
    freeSurface) is at pMin (held with its ghosts, 2 were at t = 0.01 s).
    The film's speeds are no test: its largest |U| at 0.05 s is 0.80 or
    0.96 m/s released (writes every 0.01 or 0.05 s change the steps),
    1.00 m/s held.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <fstream>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";

    const char* const dynamicMeshDict =
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object dynamicMeshDict; }\n"
        "dynamicFvMesh dynamicMotionSolverFvMesh;\n"
        "motionSolver multiSolidBodyMotionSolver;\n"
        "multiSolidBodyMotionSolverCoeffs\n{\n    tank\n    {\n"
        "        solidBodyMotionFunction linearMotion;\n"
        "        linearMotionCoeffs { velocity (0 -1 0); }\n    }\n}\n";
}


TEST(isphFoamPMin, freeSurfaceRowBelowPMinIsReleasedAtZeroPressure)
{
    const fileName dir =
        fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"isphPMinFilm";
    rmDir(dir);
    mkDir(dir.path());
    std::string out;
    ASSERT_EQ
    (
        run
        (
            "cp -r " + std::string(SPHFOAM_SOURCE_DIR)
          + "/tutorials/isph/hydrostaticTank " + dir + " && cd " + dir
          + " && sed -i 's/^dr .*/dr 0.02;/;"
            " s/max (\\$W #eval{ \\$H + 0.5\\*\\$dr })/max ($W #eval{ 2.5*$dr })/'"
            " system/sphMeshDict"
            " && sed -i 's/^endTime .*/endTime 0.05;/; s/^writeInterval .*/"
            "writeInterval 0.01;/; s/^logInterval .*/logInterval 1;/'"
            " system/controlDict"
            " && sed -i 's/^freeSurface .*/freeSurface yes;\\n"
            "freeSurfaceCondition ghost;/' system/sphSchemes"
            " && sed -i 's/^ *stopIfNotConverged .*/&\\n    pMin -1000;/'"
            " system/sphSolution"
            " && sed -i 's/type            noSlip;/type movingWallVelocity;"
            " value uniform (0 0 0);/' 0/U",
            out
        ),
        0
    ) << out;
    {
        std::ofstream os(dir/"constant"/"dynamicMeshDict");
        os << dynamicMeshDict;
    }
    ASSERT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
    ASSERT_EQ(run(bin + "isphFoam -case " + dir, out), 0)
        << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
    EXPECT_NE(out.find("freeSurfaceCondition ghost"), std::string::npos) << out;
    EXPECT_NE(out.find("a free-surface particle below it is released at p = 0"),
        std::string::npos) << out;
    EXPECT_NE(out.find("at the free surface, released at p = 0)"), std::string::npos)
        << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);

    // Every write: fluid particles flagged free-surface at p <= pMin
    const std::string script =
        "import glob, sys\n"
        "from vtkmodules.vtkIOXML import vtkXMLPolyDataReader\n"
        "from vtkmodules.util.numpy_support import vtk_to_numpy as v\n"
        "n = 0; files = 0\n"
        "for f in glob.glob(sys.argv[1] + '/VTK/isphPMinFilm_[0-9]*.vtp'):\n"
        "    r = vtkXMLPolyDataReader(); r.SetFileName(f); r.Update()\n"
        "    d = r.GetOutput().GetPointData(); files += 1\n"
        "    t, fs, p = (v(d.GetArray(k)) for k in ('type', 'freeSurface', 'p'))\n"
        "    n += int(((t == 0) & (fs == 1) & (p <= -1000 + 1e-6)).sum())\n"
        "print('files', files, 'surfaceAtPMin', n)\n";
    {
        std::ofstream os(dir/"surfaceAtPMin.py");
        os << script;
    }
    ASSERT_EQ
    (
        run(std::string(SPHFOAM_PYTHON) + " " + std::string(dir/"surfaceAtPMin.py") + " " + dir, out), 0
    ) << out;
    EXPECT_NE(out.find("files 6 "), std::string::npos) << out;
    EXPECT_NE(out.find("surfaceAtPMin 0"), std::string::npos) << out;
}


// ************************************************************************* //
