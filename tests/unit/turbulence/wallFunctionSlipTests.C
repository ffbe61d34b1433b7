/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::wallFunctionSlip, the RAS viscous term and vertex slip that
    isphFoam and wcsphFoam share (Leroy et al. 2014, eqs. (22)-(24)):
    - a uniform flow along still walls: no pair term (u_ab = 0), so the
      fluid far from the walls has no acceleration and the particles
      within the kernel's support of a wall are slowed along the wall
      only, by the log-law friction (23) (u*^2 > 0), with nu_T in the pair
      sums (nu + nu_T, compared with usaw::wallFunctionViscous);
    - eq. (24) moves a vertex particle along its wall only, and a vertex
      where the wall turns (a box's corner) stays at rest.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "../operators/operatorTestTools.H"
#include "wallFunctionSlip.H"
#include "usawOperators.H"

using namespace Foam;
using namespace operatorTest;

namespace
{
    const char* tank = "tank { type box; min (0 0); max (1 1); }";
}


TEST(wallFunctionSlip, uniformFlowIsSlowedAtTheWallsOnly)
{
    latticeCase c(tank, 0.05, layout::nodal, {0, 0}, {1, 1});
    const label n = c.size();
    const scalar nu = 1e-3;
    const SPH::turbulenceCoupling coupling
    {
        *c.W, c.nbrs, *c.usaw, c.V, nu, c.nFluid, c.dr, false
    };
    const scalarField nut(n, 0.02);
    const SPH::logLaw law(0.41, 5.2);
    const List<vector2D> U(n, vector2D(1, 0));
    List<vector2D> acc(n), ref(n);

    SPH::wallFunctionSlip slip;
    slip.viscousAcceleration(coupling, nut, law, U, acc);

    scalarList nuEff(n, nu + 0.02);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::wallFunctionViscous
        (
            K, c.nbrs, *c.usaw, c.V, nuEff, U, c.dr, nu, law, ref
        );
    });

    label nearWall = 0;
    for (label i = 0; i < c.nFluid; ++i)
    {
        // The same sums as the operator's with nu + nu_T, to round-off
        EXPECT_NEAR(acc[i].x(), ref[i].x(), 1e-12*(1 + mag(ref[i])));
        EXPECT_NEAR(acc[i].y(), ref[i].y(), 1e-12*(1 + mag(ref[i])));

        const scalar yWall = min(c.x[i].y(), 1 - c.x[i].y());
        const scalar xWall = min(c.x[i].x(), 1 - c.x[i].x());
        if (min(xWall, yWall) >= c.W->support())
        {
            EXPECT_NEAR(mag(acc[i]), 0, 1e-12) << c.x[i];
        }
        else if (xWall >= c.W->support())
        {
            // Beside the bottom or top wall only: slowed along x
            EXPECT_LT(acc[i].x(), 0) << c.x[i];
            EXPECT_NEAR(acc[i].y(), 0, 1e-12) << c.x[i];
            ++nearWall;
        }
    }
    EXPECT_GT(nearWall, 50);
}


TEST(wallFunctionSlip, verticesSlipAlongTheirWallAndCornersStay)
{
    latticeCase c(tank, 0.05, layout::nodal, {0, 0}, {1, 1});
    const label n = c.size();
    List<vector2D> U(n, vector2D::zero);
    const List<vector2D> visc(n, vector2D(3, 2));
    const scalar dt = 0.1;

    SPH::wallFunctionSlip slip;
    slip.moveVertices(*c.usaw, c.nFluid, visc, dt, U);

    label corners = 0, sides = 0;
    for (label v = c.nFluid; v < n; ++v)
    {
        const vector2D& p = c.x[v];
        const bool onX = p.x() < 1e-9 || p.x() > 1 - 1e-9;
        const bool onY = p.y() < 1e-9 || p.y() > 1 - 1e-9;
        if (onX && onY)
        {
            EXPECT_EQ(U[v], vector2D::zero) << p;
            ++corners;
        }
        else if (onY)
        {
            // Bottom and top: along x only, dt visc.x
            EXPECT_NEAR(U[v].x(), 0.3, 1e-12) << p;
            EXPECT_NEAR(U[v].y(), 0, 1e-12) << p;
            ++sides;
        }
        else
        {
            EXPECT_NEAR(U[v].x(), 0, 1e-12) << p;
            EXPECT_NEAR(U[v].y(), 0.2, 1e-12) << p;
            ++sides;
        }
    }
    EXPECT_EQ(corners, 4);
    EXPECT_GT(sides, 60);

    // The fluid particles are not touched
    for (label i = 0; i < c.nFluid; ++i)
    {
        EXPECT_EQ(U[i], vector2D::zero);
    }
}


// ************************************************************************* //
