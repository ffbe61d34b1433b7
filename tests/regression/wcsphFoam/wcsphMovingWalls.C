/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Moving USAW walls in wcsphFoam (boundaryMethod usaw, movingWallVelocity
    with constant/dynamicMeshDict): the case movingBox, a closed 0.5 m box
    full of water (dr = 0.025 m, 361 particles, g = -9.81 e_y) shaken
    along its diagonal by oscillatingLinearMotion, d(t) = A sin(omega t)
    (1 1), A = 0.05 m, omega = 2 pi rad/s, the water starting at the box's
    velocity. Water and box move as one rigid body, the pressure
    p = p_c + rho (g - a(t)).(x - x_c): over one period

    - the vertex particles are where the box is, at its velocity (to
      round-off);
    - the water stays at rest relative to the box: |u - u_w| below 2 % of
      A omega (measured 0.6 %; without the walls moving, the run stops at
      its start on movingWallVelocity) and every particle at least dr/2
      inside the moved box;
    - the pressure is the accelerated hydrostatic one: L2 of p minus the
      least-squares fit p_c + rho (g - a).(x - x_c) of its level p_c, over
      rho |g| L, below 2 % (measured 0.8 %; with the vertex pressure's
      step in g alone, the wall's acceleration left out, 3.4 %).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "restartCheck.H"
#include "particleFields.H"
#include "wallMesh.H"
#include "mathematicalConstants.H"

#include <cmath>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";
    const std::string here = std::string(SPHFOAM_SOURCE_DIR) + "/tests/regression/wcsphFoam";

    //- A fresh copy of the movingBox case, laid out by sphMesh
    fileName movingBox(const std::string& name)
    {
        const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/name;
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        EXPECT_EQ(run("cp -r " + here + "/movingBox " + dir, out), 0) << out;
        EXPECT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
        return dir;
    }
}


TEST(wcsphFoamMovingWalls, shakenBoxOfWaterMovesAsOneBody)
{
    const scalar A = 0.05, omega = constant::mathematical::twoPi;
    const scalar L = 0.5, dr = 0.025, rho0 = 1000;
    const vector2D g(0, -9.81), diagonal(1, 1);
    // Tolerances from the measured run (the description): after the
    // start-up's acoustic waves (tSettled), as in wcsphUsawTank.C
    const scalar tSettled = 0.15;
    const scalar uTolerance = 0.2*A*omega;
    const scalar pTolerance = 0.025*rho0*mag(g)*L;

    const fileName dir = movingBox("wcsphMovingBox");
    std::string out;
    ASSERT_EQ(run(bin + "wcsphFoam -case " + dir, out), 0)
        << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
    EXPECT_NE(out.find("moving walls"), std::string::npos) << out;

    auto runTime = sphTest::makeTime(dir);
    const SPH::wallMesh walls(*runTime);
    const List<vector2D>& x0 = walls.points();
    label nTimes = 0;
    scalar maxRelU = 0, maxVertexError = 0, maxL2 = 0, minInside = GREAT;
    for (const instant& t : runTime->times())
    {
        if (t.value() <= 0) continue;
        ++nTimes;
        const scalar s = std::sin(omega*t.value()), c = std::cos(omega*t.value());
        const vector2D d(A*s*diagonal), uW(A*omega*c*diagonal);
        const vector2D a(-A*sqr(omega)*s*diagonal);

        const sphTest::particleFields fields =
            sphTest::readParticles(*runTime, t.name());
        const List<vector2D>& x = fields.x;
        const List<vector2D>& U = fields.U;
        const scalarList& p = fields.p;
        const labelList& type = fields.type;

        // Fluid particles first, then the wall vertices in wallMesh order
        label nFluid = 0;
        while (nFluid < type.size() && type[nFluid] == 0) ++nFluid;
        ASSERT_EQ(type.size() - nFluid, x0.size()) << "t = " << t.name();
        forAll(x0, v)
        {
            maxVertexError = max(maxVertexError, mag(x[nFluid + v] - (x0[v] + d)));
            maxVertexError = max(maxVertexError, mag(U[nFluid + v] - uW));
        }

        // p - rho (g - a).(x - x_c) is the level p_c everywhere
        scalar sumP = 0;
        vector2D xc(vector2D::zero);
        for (label i = 0; i < nFluid; ++i)
        {
            xc += x[i]/nFluid;
        }
        List<scalar> level(nFluid);
        for (label i = 0; i < nFluid; ++i)
        {
            if (t.value() >= tSettled)
            {
                maxRelU = max(maxRelU, mag(U[i] - uW));
            }
            const vector2D xBox(x[i] - d);
            minInside = min
            (
                minInside,
                min(min(xBox.x(), L - xBox.x()), min(xBox.y(), L - xBox.y()))
            );
            level[i] = p[i] - rho0*((g - a) & (x[i] - xc));
            sumP += level[i]/nFluid;
        }
        scalar sumE2 = 0;
        for (label i = 0; i < nFluid; ++i)
        {
            sumE2 += sqr(level[i] - sumP)/nFluid;
        }
        if (t.value() >= tSettled)
        {
            maxL2 = max(maxL2, std::sqrt(sumE2));
        }
    }
    EXPECT_EQ(nTimes, 20);
    EXPECT_LT(maxVertexError, 1e-9);
    EXPECT_LT(maxRelU, uTolerance);
    EXPECT_GT(minInside, 0.8*dr);
    EXPECT_LT(maxL2, pTolerance);
    std::cout << "max |u - u_w|/(A omega) " << maxRelU/(A*omega)
        << ", pressure L2/(rho g L) " << maxL2/(rho0*mag(g)*L)
        << ", least distance inside the box/dr " << minInside/dr
        << ", vertex error " << maxVertexError << std::endl;
}



TEST(wcsphFoamMovingWalls, restartOfTheShakenBoxIsExact)
{
    const fileName dir = movingBox("wcsphMovingBoxRestart");
    sphTest::setEntry(dir/"system"/"controlDict", "endTime", "0.3");
    sphTest::setEntry(dir/"system"/"controlDict", "writeInterval", "0.1");
    EXPECT_EQ(sphTest::expectRestartsReproduce("wcsphFoam", dir), "0.1");
}


// ************************************************************************* //
