/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::wallMotion: the solid-body motion of wall patches from a
    dynamicMeshDict through OpenFOAM's own solidBodyMotionFunction, against
    the analytic motions: positions to round-off, velocities exact where
    the function gives them (rotatingMotion, linearMotion) and otherwise to
    the error of the central difference, h^2/6 |x'''| + eps |x|/h with
    h = wallMotion::differenceStep.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallTestTools.H"
#include "wallMotion.H"
#include "wallShape.H"

#include <cmath>

using namespace Foam;

namespace
{
    const scalar dr = 0.1;

    SPH::wallMesh makeWalls(const std::string& text)
    {
        return sphTest::makeWalls(text, dr);
    }

    //- A drum of radius 0.5 about (0.3 0.2) and a still line
    const std::string drum =
        "drum { type circle; centre (0.3 0.2); radius 0.5; side outside; }"
        " floor { type line; points ((-1 -1) (2 -1)); }";

    std::string dynamicMeshDict(const std::string& entries)
    {
        return
            "dynamicFvMesh dynamicMotionSolverFvMesh;"
            " motionSolver multiSolidBodyMotionSolver;"
            " multiSolidBodyMotionSolverCoeffs { " + entries + " }";
    }

    using sphTest::errorOf;

    class wallMotion : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            sphTest::throwOnFatal();
            runTime = sphTest::makeTime(sphTest::makeCase("wallMotion"));
        }

        std::unique_ptr<Time> runTime;

        //- Positions and velocities of every vertex of the patch at t
        void move
        (
            const SPH::wallMotion& m,
            const SPH::wallMesh& walls,
            const word& patch,
            const scalar t,
            List<vector2D>& x,
            List<vector2D>& U,
            labelList& pts
        ) const
        {
            const label patchi = walls.patchNames().find(patch);
            pts.clear();
            forAll(walls.pointPatch(), v)
            {
                if (walls.pointPatch()[v] == patchi) pts.append(v);
            }
            x = walls.points();
            U = List<vector2D>(x.size(), vector2D::zero);
            m.move(m.patchMotion()[patchi], t, walls.points(), pts, x, U);
        }
    };

    //- The central difference's error bound for a motion of |x'''| <= d3
    //- and |x| <= r (round-off eps |x| per position: 2 eps |x|/(2h) centred,
    //- up to 8 eps |x|/(2h) one-sided at t < h)
    scalar differenceError(const scalar d3, const scalar r)
    {
        const scalar h = SPH::wallMotion::differenceStep;
        return sqr(h)/6*d3 + 4*2.2e-16*r/h;
    }
}


TEST_F(wallMotion, rotatingMotionIsTheAnalyticRotation)
{
    const SPH::wallMesh walls(makeWalls(drum));
    const scalar omega = 1.5708;
    const SPH::wallMotion motion
    (
        sphTest::dict
        (
            dynamicMeshDict
            (
                "drum { solidBodyMotionFunction rotatingMotion;"
                " rotatingMotionCoeffs { origin (0.3 0.2 0); axis (0 0 1); omega 1.5708; } }"
            )
        ),
        *runTime, walls
    );
    ASSERT_EQ(motion.size(), 1);
    EXPECT_EQ(motion.type(0), "rotatingMotion");
    EXPECT_EQ(motion.patchMotion()[walls.patchNames().find("floor")], -1);

    const vector2D c(0.3, 0.2);
    List<vector2D> x, U;
    labelList pts;
    for (const scalar t : {0.0, 0.3, 1.0, 2.7})
    {
        move(motion, walls, "drum", t, x, U, pts);
        ASSERT_GT(pts.size(), 10);
        const scalar theta = omega*t;
        for (const label v : pts)
        {
            const vector2D d0(walls.points()[v] - c);
            const vector2D xa
            (
                c + vector2D
                (
                    std::cos(theta)*d0.x() - std::sin(theta)*d0.y(),
                    std::sin(theta)*d0.x() + std::cos(theta)*d0.y()
                )
            );
            EXPECT_NEAR(mag(x[v] - xa), 0, 1e-12) << "t = " << t;
            // omega e_z x r, exact (the function's own omega)
            const vector2D Ua(omega*vector2D(-(xa - c).y(), (xa - c).x()));
            EXPECT_NEAR(mag(U[v] - Ua), 0, 1e-12) << "t = " << t;
        }
    }
}


TEST_F(wallMotion, rampedOmegaStartsAtRest)
{
    // omega from 0 to 2 rad/s over 1 s: at rest at t = 0, then
    // theta = t^2 (OpenFOAM's table integrates the ramp exactly)
    const SPH::wallMesh walls(makeWalls(drum));
    const SPH::wallMotion motion
    (
        sphTest::dict
        (
            dynamicMeshDict
            (
                "drum { solidBodyMotionFunction rotatingMotion; rotatingMotionCoeffs"
                " { origin (0.3 0.2 0); axis (0 0 1); omega table ((0 0) (1 2) (100 2)); } }"
            )
        ),
        *runTime, walls
    );
    const vector2D c(0.3, 0.2);
    List<vector2D> x, U;
    labelList pts;
    for (const scalar t : {0.0, 0.5, 0.5, 2.0, 0.0})
    {
        move(motion, walls, "drum", t, x, U, pts);
        const scalar theta = t < 1 ? t*t : 2*(t - 0.5);
        const scalar omega = 2*min(t, 1.0);
        for (const label v : pts)
        {
            const vector2D d0(walls.points()[v] - c);
            const vector2D d(x[v] - c);
            EXPECT_NEAR(d.x(), std::cos(theta)*d0.x() - std::sin(theta)*d0.y(), 1e-12);
            EXPECT_NEAR(d.y(), std::sin(theta)*d0.x() + std::cos(theta)*d0.y(), 1e-12);
            EXPECT_NEAR(mag(U[v] - omega*vector2D(-d.y(), d.x())), 0, 1e-12);
        }
    }
}


TEST_F(wallMotion, linearMotionTranslates)
{
    const SPH::wallMesh walls(makeWalls(drum));
    const SPH::wallMotion motion
    (
        sphTest::dict
        (
            dynamicMeshDict
            (
                "\"dr.*\" { solidBodyMotionFunction linearMotion;"
                " linearMotionCoeffs { velocity (0.3 -0.1 0); } }"
            )
        ),
        *runTime, walls
    );
    List<vector2D> x, U;
    labelList pts;
    for (const scalar t : {0.0, 0.5, 4.0})
    {
        move(motion, walls, "drum", t, x, U, pts);
        for (const label v : pts)
        {
            EXPECT_NEAR(mag(x[v] - (walls.points()[v] + t*vector2D(0.3, -0.1))), 0, 1e-12);
            EXPECT_EQ(U[v], vector2D(0.3, -0.1));
        }
    }
}


TEST_F(wallMotion, oscillatingMotionVelocityToTheDifferenceError)
{
    // x = x0 + A sin(omega t): U = A omega cos(omega t), |x'''| = A omega^3
    const SPH::wallMesh walls(makeWalls(drum));
    const SPH::wallMotion motion
    (
        sphTest::dict
        (
            dynamicMeshDict
            (
                "drum { solidBodyMotionFunction oscillatingLinearMotion;"
                " oscillatingLinearMotionCoeffs { amplitude (0.1 0.05 0); omega 3; } }"
            )
        ),
        *runTime, walls
    );
    const vector2D A(0.1, 0.05);
    const scalar omega = 3;
    const scalar tol = differenceError(mag(A)*pow3(omega), 1);
    List<vector2D> x, U;
    labelList pts;
    for (const scalar t : {0.0, 0.4, 1.3})
    {
        move(motion, walls, "drum", t, x, U, pts);
        for (const label v : pts)
        {
            EXPECT_NEAR(mag(x[v] - (walls.points()[v] + std::sin(omega*t)*A)), 0, 1e-12);
            EXPECT_NEAR(mag(U[v] - omega*std::cos(omega*t)*A), 0, tol) << "t = " << t;
        }
    }
}


TEST_F(wallMotion, multiMotionRotationToTheDifferenceError)
{
    // A rotation inside multiMotion: its velocity by the central difference,
    // |x'''| = omega^3 r
    const SPH::wallMesh walls(makeWalls(drum));
    const SPH::wallMotion motion
    (
        sphTest::dict
        (
            dynamicMeshDict
            (
                "drum { solidBodyMotionFunction multiMotion; multiMotionCoeffs {"
                " turn { solidBodyMotionFunction rotatingMotion;"
                " rotatingMotionCoeffs { origin (0.3 0.2 0); axis (0 0 1); omega 2; } } } }"
            )
        ),
        *runTime, walls
    );
    const vector2D c(0.3, 0.2);
    const scalar omega = 2;
    const scalar tol = differenceError(pow3(omega)*0.5, 1);
    List<vector2D> x, U;
    labelList pts;
    for (const scalar t : {0.0, 0.5, 2.0})
    {
        move(motion, walls, "drum", t, x, U, pts);
        for (const label v : pts)
        {
            const vector2D d(x[v] - c);
            EXPECT_NEAR(mag(d), 0.5, 1e-12);
            EXPECT_NEAR(mag(U[v] - omega*vector2D(-d.y(), d.x())), 0, tol) << "t = " << t;
        }
    }
    EXPECT_LT(tol, 1e-9);
}


TEST_F(wallMotion, noFileOrStaticMeshMeansNoMotion)
{
    const SPH::wallMesh walls(makeWalls(drum));
    const SPH::wallMotion none(*runTime, walls);
    EXPECT_EQ(none.size(), 0);
    const SPH::wallMotion still
    (
        sphTest::dict("dynamicFvMesh staticFvMesh;"), *runTime, walls
    );
    EXPECT_EQ(still.size(), 0);
}


TEST_F(wallMotion, badEntriesAreErrorsNamingThem)
{
    const SPH::wallMesh walls(makeWalls(drum));
    auto make = [&](const std::string& text)
    {
        return [&, text]() { SPH::wallMotion m(sphTest::dict(text), *runTime, walls); };
    };
    const std::string rot =
        " { solidBodyMotionFunction rotatingMotion;"
        " rotatingMotionCoeffs { origin (0 0 0); axis (0 0 1); omega 1; } }";

    // A key that names no wall patch, and the patches there are
    std::string msg = errorOf(make(dynamicMeshDict("wheel" + rot)));
    EXPECT_NE(msg.find("wheel"), std::string::npos) << msg;
    EXPECT_NE(msg.find("drum"), std::string::npos) << msg;
    msg = errorOf(make(dynamicMeshDict("\"wh.*\"" + rot)));
    EXPECT_NE(msg.find("matches no wall patch"), std::string::npos) << msg;

    // An unknown function: OpenFOAM's selector lists the valid ones
    msg = errorOf
    (
        make(dynamicMeshDict("drum { solidBodyMotionFunction turning; }"))
    );
    for (const char* s : {"turning", "rotatingMotion", "linearMotion", "multiMotion"})
    {
        EXPECT_NE(msg.find(s), std::string::npos) << s << ": " << msg;
    }

    // Another motion solver
    msg = errorOf(make("motionSolver solidBody;"));
    EXPECT_NE(msg.find("multiSolidBodyMotionSolver"), std::string::npos) << msg;

    // Out of the plane: a rotation about x
    msg = errorOf
    (
        make
        (
            dynamicMeshDict
            (
                "drum { solidBodyMotionFunction rotatingMotion;"
                " rotatingMotionCoeffs { origin (0 0 0); axis (1 0 0); omega 1; } }"
            )
        )
    );
    EXPECT_NE(msg.find("axis"), std::string::npos) << msg;

    // ... and an oscillating tilt, found when the walls are moved
    const SPH::wallMotion tilt
    (
        sphTest::dict
        (
            dynamicMeshDict
            (
                "drum { solidBodyMotionFunction oscillatingRotatingMotion;"
                " oscillatingRotatingMotionCoeffs"
                " { origin (0 0 0); amplitude (10 0 0); omega 1; } }"
            )
        ),
        *runTime, walls
    );
    List<vector2D> x, U;
    labelList pts;
    msg = errorOf([&]() { move(tilt, walls, "drum", 1, x, U, pts); });
    EXPECT_NE(msg.find("out of the x-y plane"), std::string::npos) << msg;
}
