/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Bad heat-transfer inputs of isphFoam (issue 15): each stops at once
    with exit code 1 and a FatalIOError naming the file and the entry,
    never a crash: a 0/T without an entry for a wall patch, a
    fixedGradient without its gradient, beta or Pr missing from
    constant/transportProperties when there is a 0/T, TRef a word, a
    vertexTemperature or isothermalFluxMinDistance out of its range
    (system/sphSchemes). The
    same tank with a good 0/T runs, and without one it is isothermal.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "solverCase.H"

#include <fstream>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string goodT =
        "FoamFile { version 2.0; format ascii; class volScalarField; object T; }\n"
        "dimensions [0 0 0 1 0 0 0];\n"
        "internalField uniform 300;\n"
        "boundaryField { tank { type fixedValue; value uniform 300; } }\n";

    const std::string heatEntries =
        "beta [0 0 0 -1 0 0 0] 3e-3;\\nTRef 300;\\nPr 0.7;\\nPrt 0.85;";

    //- The isph tank with 0/T (text) and the heat entries of
    //- transportProperties, then an edit in the case folder
    sphTest::solverRun runHeated
    (
        const std::string& name,
        const std::string& T,
        const std::string& edit = "true"
    )
    {
        const fileName dir = sphTest::tankCase("isph", "heatInputs." + name);
        std::string out;
        std::ofstream(dir/"0"/"T") << T;
        run
        (
            "cd " + dir + " && printf '" + heatEntries
          + "\\n' >> constant/transportProperties && " + edit,
            out
        );
        return sphTest::runSolver("isphFoam", dir);
    }

    void expectError(const sphTest::solverRun& r, const std::vector<std::string>& has)
    {
        EXPECT_EQ(r.status, 1) << r.tail();
        EXPECT_FALSE(r.stackTrace()) << r.tail();
        EXPECT_TRUE(r.has("FOAM FATAL IO ERROR")) << r.tail();
        for (const std::string& s : has)
        {
            EXPECT_TRUE(r.has(s)) << "no '" << s << "' in: " << r.tail();
        }
    }
}


TEST(heatTransferInputs, aGoodTRunsAndNoTIsIsothermal)
{
    const sphTest::solverRun r = runHeated("good", goodT);
    EXPECT_EQ(r.status, 0) << r.tail();
    EXPECT_TRUE(r.has("heat transfer")) << r.tail();
    EXPECT_TRUE(r.has("p_rgh = p - rho (1 - beta (T - TRef)) gh")) << r.tail();

    const fileName dir = sphTest::tankCase("isph", "heatInputs.none");
    const sphTest::solverRun iso = sphTest::runSolver("isphFoam", dir);
    EXPECT_EQ(iso.status, 0) << iso.tail();
    EXPECT_TRUE(iso.has("No 0/T: isothermal")) << iso.tail();
    EXPECT_FALSE(iso.has("heat transfer")) << iso.tail();
    EXPECT_FALSE(iso.has("p_rgh")) << iso.tail();
}


TEST(heatTransferInputs, aWallPatchMissingFromT)
{
    std::string T(goodT);
    T.replace(T.find("tank {"), std::string("tank { type fixedValue; value uniform 300; }").size(), "");
    expectError(runHeated("noPatch", T), {"No entry for the wall patch tank", "0/T"});
}


TEST(heatTransferInputs, fixedGradientWithoutGradient)
{
    std::string T(goodT);
    const std::string fv("type fixedValue; value uniform 300;");
    T.replace(T.find(fv), fv.size(), "type fixedGradient;");
    expectError
    (
        runHeated("noGradient", T),
        {"Missing entry 'gradient' of the fixedGradient T of wall patch tank", "0/T"}
    );
}


TEST(heatTransferInputs, betaOrPrMissing)
{
    expectError
    (
        runHeated("noBeta", goodT, "sed -i '/^beta /d' constant/transportProperties"),
        {"Missing entry beta", "constant/transportProperties"}
    );
    expectError
    (
        runHeated("noPr", goodT, "sed -i '/^Pr /d' constant/transportProperties"),
        {"Missing entry Pr", "constant/transportProperties"}
    );
}


TEST(heatTransferInputs, TRefAWord)
{
    expectError
    (
        runHeated("TRefWord", goodT, "sed -i 's/^TRef .*/TRef Tmean;/' constant/transportProperties"),
        {"Entry TRef", "is not a number", "constant/transportProperties"}
    );
}


TEST(heatTransferInputs, badWallTemperatureSchemes)
{
    expectError
    (
        runHeated
        (
            "fluxMinDistance", goodT,
            "echo 'isothermalFluxMinDistance 0;' >> system/sphSchemes"
        ),
        {"Entry isothermalFluxMinDistance 0", "> 0 and <= 1", "sphSchemes"}
    );
    expectError
    (
        runHeated
        (
            "vertexForm", goodT,
            "echo 'vertexTemperature quadratic;' >> system/sphSchemes"
        ),
        {"quadratic is not in enumeration", "shepard", "linear", "sphSchemes"}
    );
}



TEST(heatTransferInputs, heatSchemeImplicit)
{
    // Runs with solvers.T, and prints the T solve's line each step
    const sphTest::solverRun good = runHeated
    (
        "implicitGood", goodT,
        "echo 'heatScheme implicit;' >> system/sphSchemes && sed -i"
        " '/^solvers/{n;s/^{/{\\n    T { solver BiCGStab; preconditioner"
        " ILU0; tolerance 1e-10; relTol 0; }/}' system/sphSolution"
    );
    EXPECT_EQ(good.status, 0) << good.tail();
    EXPECT_TRUE(good.has("backward Euler (heatScheme implicit)")) << good.tail();
    EXPECT_TRUE(good.has("Solving for T")) << good.tail();

    expectError
    (
        runHeated
        (
            "implicitNoSolver", goodT,
            "echo 'heatScheme implicit;' >> system/sphSchemes"
        ),
        {"heatScheme implicit", "has no entry T", "sphSolution"}
    );
    expectError
    (
        runHeated
        (
            "schemeWord", goodT,
            "echo 'heatScheme crankNicolson;' >> system/sphSchemes"
        ),
        {"crankNicolson is not in enumeration", "explicit", "implicit", "sphSchemes"}
    );
}

// ************************************************************************* //
