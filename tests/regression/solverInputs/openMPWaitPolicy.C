/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The solvers' OpenMP threads sleep when they wait unless the user says
    otherwise (SPH::waitPassivelyByDefault, issue 17): with OMP_WAIT_POLICY
    unset the solver runs with PASSIVE and says so in its log; a policy the
    user sets is kept. The run itself must still end normally after the
    solver has replaced itself.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "solverCase.H"

using namespace Foam;

namespace
{
    //- The tank run with an environment prefix ("env -u X" or "X=y")
    sphTest::solverRun runWith(const std::string& solver, const std::string& name, const std::string& env)
    {
        const fileName dir = sphTest::tankCase(solver, "openMP." + solver + "." + name);
        const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";
        sphTest::solverRun r;
        r.status = sphTest::run
        (
            "env " + env + " OMP_NUM_THREADS=2 timeout 60 " + bin + solver + "Foam -case " + dir,
            r.out
        );
        return r;
    }
}


TEST(openMPWaitPolicy, unsetMeansPassiveForBothSolvers)
{
    for (const std::string solver : {"isph", "wcsph"})
    {
        const sphTest::solverRun r = runWith(solver, "unset", "-u OMP_WAIT_POLICY");
        EXPECT_EQ(r.status, 0) << r.tail();
        EXPECT_TRUE(r.has("OpenMP: 2 thread(s) (OMP_NUM_THREADS), wait policy PASSIVE")) << r.tail();
        EXPECT_TRUE(r.has("\nEnd")) << r.tail();
        // One banner: the replaced program prints nothing before it is replaced
        EXPECT_EQ(r.out.find("Create time"), r.out.rfind("Create time")) << r.out;
    }
}


TEST(openMPWaitPolicy, theUsersPolicyIsKept)
{
    const sphTest::solverRun r = runWith("wcsph", "active", "OMP_WAIT_POLICY=ACTIVE");
    EXPECT_EQ(r.status, 0) << r.tail();
    EXPECT_TRUE(r.has("wait policy ACTIVE (OMP_WAIT_POLICY)")) << r.tail();
}


// ************************************************************************* //
