/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Bad input to the solvers on a periodic case (issue 11, "How we will
    check"), through isphFoam as a user runs it on the Poiseuille channel of
    tutorials/periodic/poiseuille/sph (periodic in x only, walls lowerWall
    and upperWall) at 10 particles across: each must stop with a non-zero
    exit and an error that names the file and the entry.
    - an unknown wall condition type in 0/U: the error lists the valid ones;
    - meanVelocityForce holding Ubar (0 1 0) along y, which is not periodic.
    The sphMesh errors of a periodic case (a period that is not a whole
    number of dr, a wall crossing the seam without its image) are in
    periodicChannel.C.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"

#include <fstream>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";

    //- The Poiseuille SPH case at 10 particles across, meshed
    fileName poiseuille(const std::string& name)
    {
        const std::string tutorial =
            std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/periodic/poiseuille";
        const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/name;
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        EXPECT_EQ
        (
            run
            (
                "cp -r " + tutorial + "/sph " + dir
              + " && cp " + tutorial + "/fv/system/poiseuilleParameters " + dir + "/system/"
              + " && sed -i 's/^n .*/n 10;/' " + dir + "/system/poiseuilleParameters"
              + " && " + bin + "sphMesh -case " + dir,
                out
            ),
            0
        ) << out;
        return dir;
    }

    //- isphFoam on a case that must fail: its exit status must be non-zero
    //- and it must say FOAM FATAL (IO) ERROR; its output
    std::string failingRun(const fileName& dir)
    {
        std::string out;
        EXPECT_NE(run(bin + "isphFoam -case " + dir, out), 0) << out;
        EXPECT_NE(out.find("FOAM FATAL"), std::string::npos) << out;
        EXPECT_EQ(out.find("\nEnd\n"), std::string::npos) << out;
        return out;
    }

    bool has(const std::string& s, const std::string& part)
    {
        return s.find(part) != std::string::npos;
    }
}


TEST(periodicSolverErrors, unknownWallConditionInUListsTheValidTypes)
{
    // partialSlip: an OpenFOAM type that an SPH wall does not take. The
    // cyclic and empty entries of the periodic case are accepted (ignored)
    const fileName dir = poiseuille("periodicBadWallCondition");
    std::string out;
    ASSERT_EQ
    (
        run
        (
            "sed -i '/^    upperWall/,/}/s/type  *noSlip;/type            partialSlip;/' "
          + dir + "/0/U", out
        ),
        0
    ) << out;
    ASSERT_TRUE(has(run("cat " + dir + "/0/U"), "partialSlip"));

    const std::string msg = failingRun(dir);
    EXPECT_TRUE(has(msg, "FOAM FATAL IO ERROR")) << msg;
    EXPECT_TRUE(has(msg, "0/U.boundaryField.upperWall")) << msg;
    EXPECT_TRUE(has(msg, "Unknown U wall condition type partialSlip for upperWall")) << msg;
    for (const char* valid :
        {"noSlip", "slip", "fixedValue", "uniformFixedValue", "movingWallVelocity"})
    {
        EXPECT_TRUE(has(msg, std::string("    ") + valid + " ")) << valid << ": " << msg;
    }
}


TEST(periodicSolverErrors, meanVelocityAlongANonPeriodicDirectionNamesTheFvOption)
{
    // The channel is periodic in x only: a mean velocity along y cannot be
    // held (the walls bound y)
    const fileName dir = poiseuille("periodicUbarAlongY");
    sphTest::writeFile
    (
        dir/"constant"/"fvOptions",
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " location constant; object fvOptions; }\n"
        "meanVelocity\n"
        "{\n"
        "    type            meanVelocityForce;\n"
        "    selectionMode   all;\n"
        "    fields          (U);\n"
        "    Ubar            (0 1 0);\n"
        "    relaxation      1;\n"
        "}\n"
    );

    const std::string msg = failingRun(dir);
    EXPECT_TRUE(has(msg, "FOAM FATAL IO ERROR")) << msg;
    // The file and entry, as OpenFOAM's IO error gives them ("file:
    // <case>/constant/fvOptions.meanVelocity at line N.")
    EXPECT_TRUE(has(msg, "constant/fvOptions.meanVelocity")) << msg;
    EXPECT_TRUE(has(msg, "fvOption meanVelocity: Ubar")) << msg;
    EXPECT_TRUE(has(msg, "along y, which is not periodic")) << msg;
}


// ************************************************************************* //
