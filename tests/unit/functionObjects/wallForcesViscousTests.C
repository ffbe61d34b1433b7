/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The viscous part of wallForces (Leroy et al. 2014 eqs. (69)-(70)) on a
    channel of USAW walls y = 0 and y = D (vertex particles every dr, the
    fluid on the nodes k dr between them, as sphMesh lays it for
    boundaryMethod usaw), D/dr = 40, h = 2 dr, W = 2 D long. Only the
    middle segments of each wall are measured (patches lowerMid, upperMid,
    D/2 long, more than a support from the fluid's ends), so every vertex
    sees the full lattice. mu = rho0 nu = 1000 0.1 = 100.

    - Couette, u = (a y, 0), the upper wall moving at a D: the shear
      stress on both walls is mu a, F_x = +mu a l on the lower wall (the
      fluid drags it along) and -mu a l on the upper one (l the measured
      length). The renormalised gradient is exact for a linear field:
      1e-10. The paper's gamma form divides the half-support lattice sum
      by gamma_v = 1/2; on the lattice that sum equals 1/2 to the
      quadrature error of a smooth integrand (the trapezoid rule on nodes
      k dr, whose boundary row carries no normal moment; measured
      -0.08 %): checked to 0.2 %.
    - Poiseuille, u = 4 U y (D - y)/D^2: the wall shear is mu 4 U/D on
      both walls, F_x = mu 4 U l/D on each. The one-sided stencil reads the
      curvature u'' = -8 U/D^2 as part of the gradient, an error of the
      order of the stencil's first moment over the gradient: about
      h u''/(4 U/D) = 2 h/D = 0.1 at D/h = 20, the O(dr) error of a
      first-order wall gradient. Checked to lie within 15 % and, as it must
      for a concave profile read one-sidedly, below the exact value; and
      that halving dr halves the error (first order: ratio in [1.6, 2.4]).
      The quadratic fit (wallGradient quadratic) is exact for it: 1e-8.
    - No force along y (u_y = 0 and du_x/dx = 0): F_y = 0 to round-off.
    - The pressure on USAW walls is the mean of the segment's vertex
      particles' (eq. (69)'s p_s), or with wallPressure shepard the fluid's.
    - Walls of dummy particles (the tank of functionObjectTestTools): the
      viscous part is not computed, and says so.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "wallForces.H"

using namespace Foam;
using sphTest::rho0;

namespace
{

const scalar nu = 0.1;
const scalar mu = rho0*nu;

//- The channel with what wallForces measures on a patch
struct usawChannel
:
    public sphTest::usawChannel
{
    using sphTest::usawChannel::usawChannel;

    //- What wallForces measured on a patch
    struct measured
    {
        bool viscous;
        vector2D pressure;
        vector2D viscousForce;
        vector2D total;
    };

    //- Run wallForces on a patch with a wallGradient scheme (and more
    //- entries)
    measured forces
    (
        const word& patch,
        const word& scheme,
        const std::string& more = ""
    )
    {
        autoPtr<functionObject> fo = functionObject::New
        (
            patch + scheme,
            *runTime,
            sphTest::dict("type wallForces; patches (" + patch
                + "); wallGradient " + scheme + "; " + more)
        );
        fo->execute();
        const auto& f = refCast<const SPH::functionObjects::wallForces>(fo());
        return {f.viscous(), f.pressureForce(), f.viscousForce(), f.force()};
    }
};

} // End anonymous namespace


TEST(wallForcesViscous, couetteShearIsExactWhenRenormalised)
{
    const scalar a = 2;
    usawChannel ch("viscousCouette", 40, [=](scalar y) { return a*y; }, a*1.0);
    const scalar l = ch.D;
    const scalar exact = mu*a*l;

    const auto lower = ch.forces("lowerMid", "renormalised");
    ASSERT_TRUE(lower.viscous);
    EXPECT_NEAR(lower.viscousForce.x(), exact, 1e-10*exact);
    EXPECT_NEAR(lower.viscousForce.y(), 0, 1e-10*exact);
    // No pressure: the total is the viscous part
    EXPECT_EQ(lower.pressure, vector2D::zero);
    EXPECT_EQ(lower.total, lower.viscousForce);

    const auto upper = ch.forces("upperMid", "renormalised");
    EXPECT_NEAR(upper.viscousForce.x(), -exact, 1e-10*exact);

    // The quadratic fit holds the linear field too
    EXPECT_NEAR(ch.forces("lowerMid", "quadratic").viscousForce.x(), exact, 1e-9*exact);

    // The paper's G^{gamma,-} (eq. (70)): the lattice's quadrature error
    // (measured -0.08 %)
    const auto lowerGamma = ch.forces("lowerMid", "gamma");
    EXPECT_NEAR(lowerGamma.viscousForce.x(), exact, 2e-3*exact);
    EXPECT_NEAR(lowerGamma.viscousForce.y(), 0, 1e-10*exact);
}


TEST(wallForcesViscous, poiseuilleWallShearFirstOrderOrExactWhenQuadratic)
{
    const scalar Umax = 1.5;
    auto profile = [=](scalar y) { return 4*Umax*y*(1 - y); };
    const scalar exact = mu*4*Umax;     // per unit length, D = 1, l = 1

    scalar err[2];
    const label nAcross[2] = {40, 80};
    for (label k = 0; k < 2; ++k)
    {
        usawChannel ch("viscousPoiseuille" + std::to_string(k), nAcross[k], profile, 0);
        for (const word scheme : {"renormalised", "gamma"})
        {
            SCOPED_TRACE(scheme + " at D/dr = " + std::to_string(nAcross[k]));
            const auto lower = ch.forces("lowerMid", scheme);
            const auto upper = ch.forces("upperMid", scheme);
            const scalar Fl = lower.viscousForce.x();
            EXPECT_NEAR(Fl, exact, 0.15*exact);
            EXPECT_LT(Fl, exact);
            // The flow is symmetric: the upper wall is dragged alike
            EXPECT_NEAR(upper.viscousForce.x(), Fl, 1e-9*exact);
            EXPECT_NEAR(upper.viscousForce.y(), 0, 1e-9*exact);
            if (scheme == "renormalised")
            {
                err[k] = exact - Fl;
            }
        }
        // A quadratic fit of a parabola: exact to round-off
        EXPECT_NEAR(ch.forces("lowerMid", "quadratic").viscousForce.x(), exact, 1e-8*exact);
        EXPECT_NEAR(ch.forces("upperMid", "quadratic").viscousForce.x(), exact, 1e-8*exact);
    }
    // Measured 25.7 and 12.8 (4.3 % and 2.1 %): first order
    const scalar ratio = err[0]/err[1];
    EXPECT_GT(ratio, 1.6) << err[0] << " " << err[1];
    EXPECT_LT(ratio, 2.4) << err[0] << " " << err[1];
}


TEST(wallForcesViscous, usawPressureIsThatOfTheVertexParticles)
{
    // Fluid at p = 0, the vertex particles at p = 5: eq. (69)'s segment
    // value is the vertices' mean, so the lower wall (normal +y) is pushed
    // down by 5 per unit length; the Shepard reading sees the fluid's 0
    usawChannel ch("viscousVertexPressure", 40, [](scalar) { return 0.0; }, 0);
    scalarField& p = ch.parts->field<scalar>("p");
    for (label k = ch.cloud->nFluid(); k < p.size(); ++k)
    {
        p[k] = 5;
    }
    const auto vertices = ch.forces("lowerMid", "gamma");
    EXPECT_NEAR(vertices.pressure.y(), -5*ch.D, 1e-12);
    EXPECT_NEAR(vertices.pressure.x(), 0, 1e-12);
    const auto shepard = ch.forces("lowerMid", "gamma", "wallPressure shepard;");
    EXPECT_EQ(shepard.pressure, vector2D::zero);
}


TEST(wallForcesViscous, dummyWallsHaveNoViscousPart)
{
    sphTest::sphTank tank("viscousDummy");
    auto fo = tank.fo("b", "type wallForces; patches (bottom);");
    fo->execute();
    const auto& f = refCast<const SPH::functionObjects::wallForces>(fo());
    EXPECT_FALSE(f.viscous());
    EXPECT_EQ(f.viscousForce(), vector2D::zero);
}


TEST(wallForcesViscous, unknownWallGradientIsAnError)
{
    sphTest::throwOnFatal();
    sphTest::sphTank tank("viscousBadScheme");
    try
    {
        tank.fo("f", "type wallForces; patches (bottom); wallGradient linear;");
        FAIL() << "wallGradient linear accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("wallGradient linear"), std::string::npos) << msg;
    }
}


// ************************************************************************* //
