/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The Shepard interpolation shared by the function objects
    (004_f29223b75201dc88.txt eq. (10)): exact for a constant field at any
    wet point, exact for a linear field at interior points placed
    symmetrically in the lattice, fluid particles only, zero where dry.
    "Exact" is to round-off: sums of ~50 terms of size O(1) relative, so
    1e-12 relative.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "shepardInterpolation.H"

using namespace Foam;
using namespace Foam::SPH;

namespace
{
    const scalar roundOff = 1e-12;
}


TEST(shepardInterpolation, constantFieldIsExactWhereverWet)
{
    sphTest::sphTank tank("shepardConstant");
    shepardInterpolation interp(*tank.cloud);
    const scalarField& rho = tank.parts->field<scalar>("rho");

    // Inside, on the bottom wall, in the corner, on the free surface and at
    // an arbitrary point: every weighted average of a constant is it
    for
    (
        const vector2D& x :
        {
            vector2D(0.5, 0.25), vector2D(0.3, 0), vector2D(0, 0),
            vector2D(0.71, 0.5), vector2D(0.4133, 0.2271)
        }
    )
    {
        ASSERT_GT(interp.setPoint(x), 0.1) << sphTest::str(x);
        EXPECT_NEAR(interp.interpolate(rho, 0.1), sphTest::rho0, roundOff*sphTest::rho0)
            << sphTest::str(x);
    }
}


TEST(shepardInterpolation, linearFieldIsExactAtSymmetricInteriorPoints)
{
    sphTest::sphTank tank("shepardLinear");
    shepardInterpolation interp(*tank.cloud);
    const scalar dr = tank.spec.dr;

    // Points on a lattice node or halfway between nodes, a full support
    // (4 dr) from the walls and the surface: the neighbours are symmetric
    // about the point, so the first moment vanishes
    for
    (
        const vector2D& x :
        {
            vector2D(25*dr, 12.5*dr), vector2D(10.5*dr, 8*dr),
            vector2D(30*dr, 15*dr)
        }
    )
    {
        interp.setPoint(x);
        const scalar pExact = sphTest::rho0*sphTest::gMag*(tank.spec.H - x.y());
        const scalarField& p = tank.parts->field<scalar>("p");
        EXPECT_NEAR(interp.interpolate(p), pExact, roundOff*pExact) << sphTest::str(x);

        const vector2D U(interp.interpolate(tank.parts->field<vector2D>("U")));
        EXPECT_NEAR(U.x(), 2*x.x(), roundOff) << sphTest::str(x);
        EXPECT_NEAR(U.y(), -x.y(), roundOff) << sphTest::str(x);
    }
}


TEST(shepardInterpolation, countsFluidParticlesOnly)
{
    sphTest::sphTank tank("shepardFluidOnly");
    shepardInterpolation interp(*tank.cloud);

    // On the bottom wall the support also holds dummy particles carrying
    // the poison pressure: none may be among the neighbours
    interp.setPoint(vector2D(0.5, 0));
    ASSERT_GT(interp.nNeighbours(), 0);
    const scalar p = interp.interpolate(tank.parts->field<scalar>("p"));
    EXPECT_LT(p, sphTest::rho0*sphTest::gMag*tank.spec.H);

    // The wall halves the support: about half the interior fraction
    // (0.4996 on this lattice; 1e-3 covers the lattice's variation)
    EXPECT_NEAR(interp.fluidFraction(), 0.5, 1e-3);
}


TEST(shepardInterpolation, dryPointReadsZero)
{
    sphTest::sphTank tank("shepardDry");
    shepardInterpolation interp(*tank.cloud);

    // Beyond the block (x > 1 + support): no fluid at all
    EXPECT_EQ(interp.setPoint(vector2D(1.5, 0.1)), 0);
    EXPECT_FALSE(interp.wet(0.1));
    EXPECT_EQ(interp.interpolate(tank.parts->field<scalar>("p"), 0.1), 0);
    EXPECT_EQ(interp.hydrostaticPressure(0.1), 0);

    // Wet but below the threshold: also zero
    const scalar phi = interp.setPoint(vector2D(1.0 + 1.5*tank.spec.dr, 0.25));
    ASSERT_GT(phi, 0);
    ASSERT_LT(phi, 0.5);
    EXPECT_EQ(interp.interpolate(tank.parts->field<scalar>("p"), phi + 1e-3), 0);
    EXPECT_GT(interp.interpolate(tank.parts->field<scalar>("p"), phi - 1e-3), 0);
}


TEST(shepardInterpolation, hydrostaticTermIsExactOnTheBed)
{
    sphTest::sphTank tank("shepardHydrostatic");
    shepardInterpolation interp(*tank.cloud);
    const scalar pBed = sphTest::rho0*sphTest::gMag*tank.spec.H;

    interp.setPoint(vector2D(0.5, 0));

    // 004_... eq. (10) carries each p_b down to the bed along the
    // hydrostatic column: exact for a fluid at rest
    EXPECT_NEAR(interp.hydrostaticPressure(), pBed, roundOff*pBed);

    // The plain average reads the pressure at the weighted mean height of
    // the fluid in the half support, 0.883 dr above the bed on this
    // lattice (wendlandC2, h = 2 dr): 1e-3 dr covers the rounding of that
    // figure
    const scalar yBar = 0.883*tank.spec.dr;
    EXPECT_NEAR
    (
        interp.interpolate(tank.parts->field<scalar>("p")),
        sphTest::rho0*sphTest::gMag*(tank.spec.H - yBar),
        sphTest::rho0*sphTest::gMag*1e-3*tank.spec.dr
    );
}


TEST(shepardInterpolation, latticeFractionIsCloseToOne)
{
    // The discrete sum of dr^2 W over the lattice approximates the unit
    // integral of the kernel: for wendlandC2 with h = 2 dr the aliasing
    // error is 1.2e-3 (computed independently); 2e-3 bounds it
    sphTest::sphTank tank("shepardLattice");
    EXPECT_NEAR(shepardInterpolation::latticeFraction(*tank.W, tank.spec.dr), 1, 2e-3);
    EXPECT_GT(shepardInterpolation::latticeFraction(*tank.W, tank.spec.dr), 1);

    // Inside the block, at a particle, the fluid fraction is that sum
    // (rho = rho0 so V = dr^2); halfway between four particles it is the
    // lattice sum at offsets of half a spacing, 0.99923 (computed
    // independently)
    const scalar dr = tank.spec.dr;
    EXPECT_NEAR
    (
        shepardInterpolation::fluidFraction(*tank.cloud, vector2D(24.5*dr, 12.5*dr)),
        shepardInterpolation::latticeFraction(*tank.W, dr),
        roundOff
    );
    EXPECT_NEAR
    (
        shepardInterpolation::fluidFraction(*tank.cloud, vector2D(25*dr, 12*dr)),
        0.9992305191624021,
        roundOff
    );
}


// ************************************************************************* //
