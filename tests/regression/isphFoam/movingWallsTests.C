/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The prescribed wall motions of isphFoam (SPH::wallBoundaries: 0/U's
    boundaryField and constant/dynamicMeshDict, which replace the former
    constant/movingWalls): a sliding lid ramped by a uniformFixedValue
    table and a wall turning by rotatingMotion with a ramped omega, which
    vertices move (a vertex where a moving patch meets a still one stays),
    and the errors of bad entries.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallTestTools.H"
#include "wallBoundaries.H"
#include "wallShape.H"
#include "mathematicalConstants.H"

using namespace Foam;

namespace
{
    const scalar dr = 0.1;

    //- Walls from "name { type ...; ... }" patch dictionaries
    SPH::wallMesh makeWalls(const std::string& text)
    {
        return sphTest::makeWalls(text, dr);
    }

    const std::string cavity =
        "lid { type line; points ((1 1) (0 1)); }"
        " fixedWalls { type polyline; points ((0 1) (0 0) (1 0) (1 1)); }";

    using sphTest::errorOf;

    class movingWalls : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            sphTest::throwOnFatal();
            runTime = sphTest::makeTime(sphTest::makeCase("movingWalls"));
        }

        std::unique_ptr<Time> runTime;

        //- The motion from 0/U's boundaryField and a dynamicMeshDict
        SPH::wallBoundaries make
        (
            const SPH::wallMesh& walls,
            const std::string& U,
            const std::string& dynamicMeshDict = ""
        ) const
        {
            return SPH::wallBoundaries
            (
                sphTest::dict(U), sphTest::dict(dynamicMeshDict), *runTime, walls
            );
        }
    };

    //- constant/dynamicMeshDict of one rotatingMotion entry
    std::string rotation(const std::string& key, const std::string& coeffs)
    {
        return
            "motionSolver multiSolidBodyMotionSolver;"
            " multiSolidBodyMotionSolverCoeffs { " + key
          + " { solidBodyMotionFunction rotatingMotion;"
            " rotatingMotionCoeffs { axis (0 0 1); " + coeffs + " } } }";
    }
}


TEST_F(movingWalls, slidingLidRampsAndItsCornersStay)
{
    const SPH::wallMesh walls(makeWalls(cavity));
    const SPH::wallBoundaries motion
    (
        make
        (
            walls,
            "lid { type uniformFixedValue; uniformValue table ((0 (0 0 0)) (2 (1 0 0))); }"
            " fixedWalls { type noSlip; }"
        )
    );
    EXPECT_TRUE(motion.any());
    EXPECT_FALSE(motion.movesGeometry());

    const label n = walls.points().size();
    List<vector2D> x(n), U(n);
    label nMoving = 0;
    for (const scalar t : {-1.0, 0.0, 0.5, 2.0, 7.0})
    {
        motion.vertices(t, x, U);
        const scalar ramp = t <= 0 ? 0 : min(t/2, 1.0);
        nMoving = 0;
        forAll(x, v)
        {
            EXPECT_EQ(x[v], walls.points()[v]);
            const vector2D& p = walls.points()[v];
            const bool lidInterior = p.y() > 1 - 1e-12 && p.x() > 1e-12 && p.x() < 1 - 1e-12;
            EXPECT_EQ(U[v], lidInterior ? ramp*vector2D(1, 0) : vector2D::zero)
                << "vertex at " << p.x() << ' ' << p.y() << ", t = " << t;
            nMoving += lidInterior;
        }
    }
    EXPECT_EQ(nMoving, 9);
}


TEST_F(movingWalls, rotatingWallTurnsAboutItsOriginFromRest)
{
    // A circle about (0.3 0.2) turning at omega = 2 rad/s after a 1 s ramp:
    // theta = omega t^2/(2 T) for t < T, omega (t - T/2) after
    const SPH::wallMesh walls
    (
        makeWalls("drum { type circle; centre (0.3 0.2); radius 0.5; side outside; }")
    );
    const SPH::wallBoundaries motion
    (
        make
        (
            walls,
            "drum { type movingWallVelocity; }",
            rotation("drum", "origin (0.3 0.2 0); omega table ((0 0) (1 2) (100 2));")
        )
    );
    EXPECT_TRUE(motion.movesGeometry());

    const vector2D c(0.3, 0.2);
    const label n = walls.points().size();
    List<vector2D> x(n), U(n), xa(n), xb(n), Ua(n);
    for (const scalar t : {0.5, 1.0, 3.0})
    {
        const scalar theta = t < 1 ? t*t : 2*(t - 0.5);
        const scalar omega = 2*min(t, 1.0);
        motion.vertices(t, x, U);
        const scalar eps = 1e-6;
        motion.vertices(t - eps, xa, Ua);
        motion.vertices(t + eps, xb, Ua);
        forAll(x, v)
        {
            const vector2D d0(walls.points()[v] - c);
            const vector2D d(x[v] - c);
            EXPECT_NEAR(mag(d), mag(d0), 1e-12);
            // The angle turned
            EXPECT_NEAR(d.x(), std::cos(theta)*d0.x() - std::sin(theta)*d0.y(), 1e-12);
            EXPECT_NEAR(d.y(), std::sin(theta)*d0.x() + std::cos(theta)*d0.y(), 1e-12);
            // omega e_z x (x - c), the time derivative of the position
            EXPECT_NEAR(U[v].x(), -omega*d.y(), 1e-12);
            EXPECT_NEAR(U[v].y(), omega*d.x(), 1e-12);
            EXPECT_NEAR(mag((xb[v] - xa[v])/(2*eps) - U[v]), 0, 1e-6);
        }
    }
}


TEST_F(movingWalls, accelerationsOfATurningWallAndNoneOfASlidingOne)
{
    // The drum of the test above: a = domega/dt e_z x d - omega^2 d, d =
    // x - c, by the central difference of the velocity over 1e-4 s (its
    // error h^2/6 |d3u/dt3| about 1e-8 here; wcsphFoam's vertex pressure
    // takes it); the sliding lid of a cavity ramped over 1 s: none (its
    // surface does not push the fluid), though its vertices' speed grows
    const SPH::wallMesh drum
    (
        makeWalls("drum { type circle; centre (0.3 0.2); radius 0.5; side outside; }")
    );
    const SPH::wallBoundaries turning
    (
        make
        (
            drum,
            "drum { type movingWallVelocity; }",
            rotation("drum", "origin (0.3 0.2 0); omega table ((0 0) (1 2) (100 2));")
        )
    );
    const vector2D c(0.3, 0.2);
    const label n = drum.points().size();
    List<vector2D> x(n), U(n), a(n);
    for (const scalar t : {0.5, 3.0})
    {
        const scalar omega = 2*min(t, 1.0), domega = t < 1 ? 2 : 0;
        turning.vertices(t, x, U);
        turning.accelerations(t, a);
        forAll(x, v)
        {
            const vector2D d(x[v] - c);
            const vector2D expected
            (
                -domega*d.y() - sqr(omega)*d.x(),
                domega*d.x() - sqr(omega)*d.y()
            );
            EXPECT_NEAR(mag(a[v] - expected), 0, 1e-6) << "t = " << t;
        }
    }

    const SPH::wallMesh cavityWalls(makeWalls(cavity));
    const SPH::wallBoundaries sliding
    (
        make
        (
            cavityWalls,
            "lid { type uniformFixedValue; uniformValue table ((0 (0 0 0)) (1 (1 0 0))); }"
            " fixedWalls { type noSlip; }"
        )
    );
    List<vector2D> aLid(cavityWalls.points().size(), vector2D::one);
    sliding.accelerations(0.5, aLid);
    forAll(aLid, v)
    {
        EXPECT_EQ(aLid[v], vector2D::zero) << v;
    }
}


TEST_F(movingWalls, patternEntriesMoveEveryPatchTheyMatch)
{
    const SPH::wallMesh walls
    (
        makeWalls
        (
            "paddleA { type line; points ((0 0) (1 0)); }"
            " paddleB { type line; points ((1 0) (1 1)); }"
        )
    );
    const SPH::wallBoundaries motion
    (
        make
        (
            walls,
            "\"paddle.*\" { type movingWallVelocity; }",
            rotation("\"paddle.*\"", "origin (0 0 0); omega 1;")
        )
    );
    // One motion for both, so their shared vertex turns with them
    EXPECT_EQ(motion.motions().size(), 1);
    for (const label m : motion.vertexMotion())
    {
        EXPECT_EQ(m, 0);
    }
}


TEST_F(movingWalls, noFileMeansNoMotion)
{
    // No constant/dynamicMeshDict, and still walls in 0/U and 0/p
    const fileName dir = sphTest::makeCase("movingWallsNone");
    const std::string head = "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n";
    sphTest::writeFile(dir/"0"/"U", head + "boundaryField { \".*\" { type noSlip; } }\n");
    sphTest::writeFile(dir/"0"/"p", head + "boundaryField { \".*\" { type zeroGradient; } }\n");
    auto runTime = sphTest::makeTime(dir);
    const SPH::wallMesh walls(makeWalls(cavity));
    const SPH::wallBoundaries motion(*runTime, walls);
    EXPECT_FALSE(motion.any());
    EXPECT_FALSE(motion.movesGeometry());
}


TEST_F(movingWalls, badEntriesAreErrorsNamingThem)
{
    const SPH::wallMesh walls(makeWalls(cavity));
    const std::string still = " fixedWalls { type noSlip; }";
    auto make = [&](const std::string& U, const std::string& dynamicMeshDict = "")
    {
        return [this, &walls, U, dynamicMeshDict]()
        {
            SPH::wallBoundaries m(this->make(walls, U, dynamicMeshDict));
        };
    };

    // An unknown patch, and the patches there are
    std::string msg = errorOf(make("lidd { type fixedValue; value uniform (1 0 0); }" + still));
    EXPECT_NE(msg.find("lidd"), std::string::npos) << msg;
    EXPECT_NE(msg.find("fixedWalls"), std::string::npos) << msg;

    // A pattern that matches nothing
    msg = errorOf(make("\"wall.*\" { type fixedValue; value uniform (1 0 0); } lid { type noSlip; }" + still));
    EXPECT_NE(msg.find("matches no wall patch"), std::string::npos) << msg;

    // An unknown motion, and the motions there are
    msg = errorOf(make("lid { type translating; }" + still));
    for (const char* s : {"translating", "sliding", "rotating"})
    {
        EXPECT_NE(msg.find(s), std::string::npos) << msg;
    }

    // A sliding wall that would move through itself
    msg = errorOf(make("lid { type fixedValue; value uniform (0.6 0.8 0); }" + still));
    EXPECT_NE(msg.find("along itself"), std::string::npos) << msg;

    // A rotating patch that shares a vertex with a still one
    msg = errorOf(make("lid { type movingWallVelocity; }" + still, rotation("lid", "origin (0.5 0.5 0); omega 1;")));
    EXPECT_NE(msg.find("tear"), std::string::npos) << msg;

    // Missing entries
    msg = errorOf(make("lid { type fixedValue; }" + still));
    EXPECT_NE(msg.find("U"), std::string::npos) << msg;
    msg = errorOf(make("lid { type uniformFixedValue; uniformValue constant (1 0 0); rampTime -1; }" + still));
    EXPECT_NE(msg.find("rampTime"), std::string::npos) << msg;
}
