/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Body forces of constant/fvOptions: the constant force, the mean
    velocity controller of Leroy et al. 2014, eqs. (67)-(68), its restart
    file, and the errors.

\*---------------------------------------------------------------------------*/

#include "fvOptionForces.H"
#include "meanVelocityForce.H"
#include "testCase.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const std::string header =
    "FoamFile { version 2.0; format ascii; class dictionary;"
    " object fvOptions; }\n";

const std::string meanVelocity =
    "meanVelocity { type meanVelocityForce; selectionMode all; fields (U);"
    " Ubar (1 0 0); }\n";

fileName caseWith(const std::string& name, const std::string& fvOptions)
{
    const fileName dir = sphTest::makeCase(name);
    sphTest::writeFile(dir/"constant"/"fvOptions", header + fvOptions);
    return dir;
}


//- The mean of U after n steps of a fluid with drag k under the forces
scalar driven(SPH::fvOptionForces& forces, List<vector2D>& U, scalar k, label n)
{
    const scalar dt = 0.01;
    for (label step = 0; step < n; ++step)
    {
        const vector2D a = forces.acceleration(U, dt);
        for (vector2D& u : U)
        {
            u += dt*(a - k*u);
        }
    }
    scalar mean = 0;
    for (const vector2D& u : U) mean += u.x();
    return mean/U.size();
}

} // End anonymous namespace


TEST(bodyForce, constantForceIsTheSpecificExplicitSource)
{
    const fileName dir = caseWith
    (
        "bodyForceConstant",
        "f { type vectorSemiImplicitSource; selectionMode all;"
        " volumeMode specific; injectionRateSuSp { U ((1.2 -0.5 0) 0); } }\n"
    );
    auto runTime = sphTest::makeTime(dir);
    SPH::fvOptionForces forces(*runTime);
    ASSERT_EQ(forces.size(), 1);
    List<vector2D> U(4, vector2D(3, 4));
    EXPECT_EQ(forces.acceleration(U, 0.1), vector2D(1.2, -0.5));
}


TEST(bodyForce, meanVelocityReachesUbarInOneStepWithoutDrag)
{
    // Eq. (67) with v^{n-2} = v^{n-1} at the first step: F = Ubar/dt, then
    // F = 0 once the mean is Ubar
    auto runTime = sphTest::makeTime(caseWith("bodyForceMean", meanVelocity));
    SPH::fvOptionForces forces(*runTime);
    List<vector2D> U(5, vector2D::zero);
    EXPECT_NEAR(driven(forces, U, 0, 1), 1, 1e-12);
    EXPECT_NEAR(driven(forces, U, 0, 3), 1, 1e-12);
}


TEST(bodyForce, meanVelocityBalancesTheDragAtSteadyState)
{
    // Drag k u: at steady state the force is k Ubar; the deadbeat law holds
    // the mean within the drag's change over one step, then converges
    auto runTime = sphTest::makeTime(caseWith("bodyForceDrag", meanVelocity));
    SPH::fvOptionForces forces(*runTime);
    List<vector2D> U(5, vector2D::zero);
    const scalar k = 3;
    EXPECT_NEAR(driven(forces, U, k, 2000), 1, 1e-10);
    const vector2D a = forces.acceleration(U, 0.01);
    EXPECT_NEAR(a.x(), k*1, 1e-8);
    EXPECT_EQ(a.y(), 0);
}


TEST(bodyForce, meanVelocityRestartsFromItsPropertiesFile)
{
    const fileName dir = caseWith("bodyForceRestart", meanVelocity);
    vector2D a1;
    {
        auto runTime = sphTest::makeTime(dir);
        SPH::fvOptionForces forces(*runTime);
        List<vector2D> U(5, vector2D::zero);
        driven(forces, U, 3, 7);
        runTime->setTime(0.5, 1);
        forces.write();
        a1 = forces.acceleration(U, 0.01);
    }
    ASSERT_TRUE(isFile(dir/"0.5"/"uniform"/"meanVelocityProperties"));
    sphTest::run
    (
        "foamDictionary -entry startFrom -set latestTime "
      + dir/"system"/"controlDict"
    );
    auto runTime = sphTest::makeTime(dir);
    ASSERT_EQ(runTime->timeName(), "0.5");
    SPH::fvOptionForces forces(*runTime);
    List<vector2D> U(5, vector2D::zero);
    {
        // The same velocities as the first run had after 7 steps
        auto first = sphTest::makeTime(caseWith("bodyForceRestartRef", meanVelocity));
        SPH::fvOptionForces reference(*first);
        driven(reference, U, 3, 7);
    }
    EXPECT_EQ(forces.acceleration(U, 0.01), a1);
}


TEST(bodyForce, forceIsTheLastUpdateWithoutUpdating)
{
    // wcsphFoam applies one force at the four Runge-Kutta stages and
    // updates it once per step: force() must give the last update's value
    // (the state read at start before the first) and change nothing, so
    // that the next update is the one acceleration() alone would give.
    // Exact: the same doubles are returned
    auto runTime = sphTest::makeTime(caseWith("bodyForceForce", meanVelocity));
    SPH::fvOptionForces forces(*runTime), reference(*runTime);
    EXPECT_EQ(forces.force(), vector2D::zero);
    List<vector2D> U(5, vector2D(0.3, 0)), URef(U);
    for (label step = 0; step < 4; ++step)
    {
        const vector2D a = forces.acceleration(U, 0.01);
        EXPECT_EQ(forces.force(), a);
        EXPECT_EQ(forces.force(), a);
        EXPECT_EQ(reference.acceleration(URef, 0.01), a);
        for (label i = 0; i < U.size(); ++i)
        {
            U[i] += 0.01*(a - 2*U[i]);
            URef[i] += 0.01*(a - 2*URef[i]);
        }
    }

    const fileName dir = caseWith
    (
        "bodyForceForceConstant",
        "f { type vectorSemiImplicitSource; selectionMode all;"
        " volumeMode specific; injectionRateSuSp { U ((1.2 -0.5 0) 0); } }\n"
    );
    auto constantTime = sphTest::makeTime(dir);
    SPH::fvOptionForces constant(*constantTime);
    EXPECT_EQ(constant.force(), vector2D(1.2, -0.5));
}


TEST(bodyForce, badEntriesAreErrorsNamingThem)
{
    sphTest::throwOnFatal();
    const std::map<std::string, std::string> cases
    {
        {"f { type noSuchForce; }\n", "noSuchForce"},
        {"f { type vectorSemiImplicitSource; volumeMode absolute;"
         " injectionRateSuSp { U ((1 0 0) 0); } }\n", "volumeMode absolute"},
        {"f { type vectorSemiImplicitSource; volumeMode specific;"
         " injectionRateSuSp { U ((1 0 0) -2); } }\n", "without the implicit part"},
        {"f { type meanVelocityForce; fields (T); Ubar (1 0 0); }\n", "acts on fields"},
        {"f { type meanVelocityForce; selectionMode cellZone; Ubar (1 0 0); }\n",
         "selectionMode cellZone"},
        {"f { type meanVelocityForce; Ubar (0 0 0); }\n", "Ubar"},
    };
    label i = 0;
    for (const auto& c : cases)
    {
        auto runTime = sphTest::makeTime
        (
            caseWith("bodyForceBad" + std::to_string(i++), c.first)
        );
        std::string message;
        try
        {
            SPH::fvOptionForces forces(*runTime);
        }
        catch (const Foam::error& err)
        {
            message = err.message();
        }
        EXPECT_NE(message.find(c.second), std::string::npos)
            << c.first << " -> " << message;
    }
}


// ************************************************************************* //
