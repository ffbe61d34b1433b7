/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The wallForces function object on a tank filled to H (= its width W)
    with water at rest, p = rho0 g (H - y), H/dr = 50:

    - bottom: F_y = -rho0 g H W. The plain Shepard value on a wall is the
      pressure at the kernel-weighted mean height of the fluid in the half
      support, ybar = 0.883 dr on this lattice (wendlandC2, h = 2 dr), so
      the force is low by ybar/H = 1.8 %: checked to lie between that
      biased value and the exact one, within 3 % of the exact one. With the
      hydrostatic term of 004_... eq. (10) it is exact: p is constant
      along the bottom, so the midpoint rule adds no error; 1e-10.
    - left wall: F_x = -rho0 g H^2/2, moment about its foot
      rho0 g H^3/6. On a vertical wall the stencil is symmetric in y and p
      depends on y only, so the Shepard value is exact except within a
      support (4 dr) of the bed and of the surface. There the one-sided
      stencil shifts the reading by at most ybar = 0.883 dr, fading over
      the 4 dr: about rho0 g 2 dr^2 at each end, 4 (dr/H)^2 = 0.16 % of
      the force; the wet strip above the surface (fraction still > 0.1 for
      a few dr) reads about rho0 g 1.5 dr over ~3 dr, 0.3 %. Without
      counting on the ends cancelling that is 0.64 %: checked to 1 %. The
      moment weighs the surface end by y = H, so its share is
      6 (2 + 4.5) (dr/H)^2 = 1.6 % of rho0 g H^3/6: checked to 2 %.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "wallForces.H"

using namespace Foam;
using sphTest::rho0;
using sphTest::gMag;

namespace
{
    const SPH::functionObjects::wallForces& asForces(const autoPtr<functionObject>& fo)
    {
        return refCast<const SPH::functionObjects::wallForces>(fo());
    }

    //- The tank filled to the depth H = its width
    sphTest::tankSpec fullTank()
    {
        sphTest::tankSpec spec;
        spec.dr = 0.01;
        spec.H = 0.5;
        spec.blockWidth = 0.5;
        spec.tankWidth = 0.5;
        spec.tankHeight = 1.0;
        return spec;
    }
}


TEST(wallForces, bottomCarriesTheWeightOfTheWater)
{
    const sphTest::tankSpec spec = fullTank();
    sphTest::sphTank tank("forcesBottom", spec);
    const scalar H = spec.H;
    const scalar W = spec.tankWidth;
    const scalar exact = -rho0*gMag*H*W;

    auto fo = tank.fo("bottom", "type wallForces; patches (bottom);");
    fo->execute();
    const auto& f = asForces(fo);

    EXPECT_EQ(f.force().x(), 0);
    EXPECT_NEAR(f.force().y(), exact, 0.03*mag(exact));
    // The bias of the one-sided average has the expected sign
    EXPECT_GT(f.force().y(), exact);
    EXPECT_EQ(f.nDry(), 0);

    auto foH = tank.fo("bottomH", "type wallForces; patches (bottom); hydrostatic yes;");
    foH->execute();
    EXPECT_NEAR(asForces(foH).force().y(), exact, 1e-10*mag(exact));
}


TEST(wallForces, sideWallCarriesHalfRhoGHSquared)
{
    const sphTest::tankSpec spec = fullTank();
    sphTest::sphTank tank("forcesSide", spec);
    const scalar H = spec.H;

    // The left wall is pushed towards -x; about its foot the moment is
    // (0, y) x (-f, 0) = +y f
    auto fo = tank.fo("left", "type wallForces; patches (leftWall); CofR (0 0);");
    fo->execute();
    const auto& f = asForces(fo);

    const scalar Fx = -0.5*rho0*gMag*sqr(H);
    const scalar Mz = rho0*gMag*pow3(H)/6;
    EXPECT_NEAR(f.force().x(), Fx, 0.01*mag(Fx));
    EXPECT_EQ(f.force().y(), 0);
    EXPECT_NEAR(f.moment(), Mz, 0.02*Mz);

    // The wall above the water is dry: no force there
    EXPECT_GT(f.nDry(), 0);
}


TEST(wallForces, oppositeWallsCancel)
{
    const sphTest::tankSpec spec = fullTank();
    sphTest::sphTank tank("forcesCancel", spec);

    // Both side walls by a regular expression, moment about the centre
    // line: the tank is mirror-symmetric, so force and moment cancel to
    // round-off (sums of 50 terms of rho0 g H dr ~ 50)
    auto fo = tank.fo
    (
        "sides",
        "type wallForces; patches (\".*Wall\"); CofR (0.25 0 0);"
    );
    fo->execute();
    const auto& f = asForces(fo);
    EXPECT_EQ(f.patches().size(), 2);

    const scalar Fside = 0.5*rho0*gMag*sqr(spec.H);
    EXPECT_NEAR(f.force().x(), 0, 1e-12*Fside);
    EXPECT_NEAR(f.moment(), 0, 1e-12*Fside*spec.H);
}


TEST(wallForces, dryWallCarriesNothing)
{
    // The default tank: the block fills [0, 1] of a tank 2 wide
    sphTest::sphTank tank("forcesDry");
    auto fo = tank.fo("right", "type wallForces; patches (rightWall);");
    fo->execute();
    const auto& f = asForces(fo);
    EXPECT_EQ(f.force(), vector2D::zero);
    EXPECT_EQ(f.moment(), 0);
    EXPECT_GT(f.nDry(), 0);
}


TEST(wallForces, unknownPatchIsAnErrorListingThePatches)
{
    sphTest::throwOnFatal();
    sphTest::sphTank tank("forcesUnknown");
    try
    {
        tank.fo("f", "type wallForces; patches (bottom rightwall);");
        FAIL() << "unknown patch accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("rightwall"), std::string::npos) << msg;
        EXPECT_NE(msg.find("rightWall"), std::string::npos) << msg;
    }
}


TEST(wallForces, filesReadLikeOpenFOAMForces)
{
    const sphTest::tankSpec spec = fullTank();
    sphTest::sphTank tank("forcesFiles", spec);

    // writePrecision 6 gives the widths of the conventions' example
    auto fo = tank.fo
    (
        "forces1",
        "type wallForces; patches (bottom); hydrostatic yes; writePrecision 6;"
    );
    tank.runTime->setTime(0.1, 1);
    fo->execute();
    fo->write();

    const fileName dir = tank.postProcessing("forces1/0");
    const std::vector<std::string> force = sphTest::readLines(dir/"force.dat");
    ASSERT_EQ(force.size(), 5u);
    EXPECT_EQ(force[0], "# Force       ");
    EXPECT_EQ(force[1], "# CofR        : (0.000000e+00 0.000000e+00 0.000000e+00)");
    EXPECT_EQ(force[2], "#");
    EXPECT_EQ
    (
        force[3],
        "# Time        \t(total_x total_y total_z)\t(pressure_x pressure_y pressure_z)"
        "\t(viscous_x viscous_y viscous_z)"
    );
    // rho0 g H W = 1000 9.81 0.5 0.5 = 2452.5, exactly with hydrostatic
    EXPECT_EQ
    (
        force[4],
        "0.1           \t(0.000000e+00 -2.452500e+03 0.000000e+00)"
        "\t(0.000000e+00 -2.452500e+03 0.000000e+00)"
        "\t(0.000000e+00 0.000000e+00 0.000000e+00)"
    );

    const std::vector<std::string> moment = sphTest::readLines(dir/"moment.dat");
    ASSERT_EQ(moment.size(), 5u);
    EXPECT_EQ(moment[0], "# Moment      ");
    EXPECT_EQ(moment[3], force[3]);
    // About (0 0): the bottom's load acts at x = W/2: Mz = -2452.5 W/2
    EXPECT_EQ(moment[4].rfind("0.1           \t(0.000000e+00 0.000000e+00 -6.131250e+02)", 0), 0u)
        << moment[4];
}


// ************************************************************************* //
