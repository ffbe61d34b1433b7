/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The lattice moments behind isphFoam's freeSurfaceCondition ghost
    (src/sph/solvers/isph/stages/freeSurface/ghostSurface.H): the full
    lattice's second moment sum_v dr^2 F(r_v) r_v r_v^T is -I up to the
    lattice's quadrature, and for a particle on the top row of a half
    lattice the ghosts' moments (the full lattice's minus the real rows')
    are those of the rows above it, which the Poisson row and the gradient
    use: with p_v = p_a (1 - r_va.n/delta) and p_a = rho |g| delta, the
    ghosts' gradient part equals that of the hydrostatic pressure. The
    ghosts' kernel sum (freeSurfaceCompaction's density) leaves out the
    nodes beyond a wall's line, which gamma counts out. A surface normal
    loses its parts into the walls within reach (offWalls): a film's tip
    in a tank's top corner had its normal into the ceiling 1.05 dr above,
    its ghosts' p = 0 half-way to it, and was thrown into the corner.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "ghostSurface.H"
#include "kernel.H"
#include "kernelDispatch.H"
#include "IStringStream.H"
#include "../operators/operatorTestTools.H"

using namespace Foam;

namespace
{
    autoPtr<SPH::kernel> wendland(const scalar dr)
    {
        IStringStream is("kernel wendlandC2; hByDr 2;");
        const dictionary dict(is);
        return SPH::kernel::New(dict, dr);
    }

    //- sum over lattice nodes d = dr (i, j) != 0 with j in [jMin, jMax]
    //- of dr^2 F d d^T (the full lattice's: all j)
    template<class Kernel>
    tensor2D rowsMoment
    (
        const Kernel& K,
        const scalar dr,
        const label jMin,
        const label jMax
    )
    {
        const label m = label(K.support()/dr) + 1;
        tensor2D T(Zero);
        for (label i = -m; i <= m; ++i)
        {
            for (label j = max(jMin, -m); j <= min(jMax, m); ++j)
            {
                const vector2D d(dr*i, dr*j);
                if ((i || j) && mag(d) < K.support())
                {
                    T += dr*dr*K.dWdrByR(mag(d))*(d*d);
                }
            }
        }
        return T;
    }
}


TEST(ghostSurface, latticeMomentIsMinusIdentity)
{
    for (const scalar dr : {0.01, 0.004})
    {
        const autoPtr<SPH::kernel> W(wendland(dr));
        SPH::dispatch(*W, [&](const auto& K)
        {
            const tensor2D T = SPH::ghostSurface::latticeMoment(K, dr);
            // Measured -0.99920 on the diagonal at h = 2 dr (the lattice
            // quadrature of -I); the off-diagonal vanishes by symmetry
            EXPECT_NEAR(T.xx(), -1, 2e-3) << "dr " << dr;
            EXPECT_NEAR(T.yy(), -1, 2e-3) << "dr " << dr;
            EXPECT_NEAR(T.xy(), 0, 1e-12) << "dr " << dr;
            EXPECT_NEAR(T.yx(), 0, 1e-12) << "dr " << dr;
            // Independent of dr: F ~ 1/h^4, r^2 ~ h^2, dr^2 ~ h^2
            EXPECT_NEAR(T.xx(), rowsMoment(K, dr, -100, 100).xx(), 1e-12);
        });
    }
}


TEST(ghostSurface, ghostsOfATopRowParticleCarryTheHydrostaticGradient)
{
    // A particle on the top row of a half lattice (rows j <= 0): its
    // ghosts are the rows j >= 1. The gradient's ghost part
    // p_a/delta T_g n (projection.C) must equal -T_g grad p for the
    // hydrostatic grad p = -rho |g| n when p_a = rho |g| delta, and T_g
    // (lattice minus real) must be the rows above
    const scalar dr = 0.01, delta = dr/2, rhoG = 1000*9.81;
    const autoPtr<SPH::kernel> W(wendland(dr));
    SPH::dispatch(*W, [&](const auto& K)
    {
        const tensor2D Tg =
            SPH::ghostSurface::latticeMoment(K, dr)
          - rowsMoment(K, dr, -100, 0);
        const tensor2D above = rowsMoment(K, dr, 1, 100);
        EXPECT_NEAR(mag(Tg - above), 0, 1e-12);

        const vector2D n(0, 1);
        const scalar pA = rhoG*delta;
        const vector2D ghostPart = pA/delta*(Tg & n);
        const vector2D hydrostatic = -(Tg & vector2D(-rhoG*n));
        EXPECT_NEAR(mag(ghostPart - hydrostatic), 0, 1e-9*rhoG);
        // The ghosts are about half the support: n.T_g.n near -1/2
        EXPECT_LT(n & (Tg & n), -0.3);
        EXPECT_GT(n & (Tg & n), -0.7);
    });
}


TEST(ghostSurface, halfPlaneSumLeavesOutTheWallSide)
{
    // A particle on the top row (rows j <= 0) of a lattice that ends at a
    // wall on its left: columns i >= -k are fluid, the wall's line at
    // dWall = (k + 1/2) dr (inward normal nw = (1, 0)). Its ghosts (j >= 1)
    // must be those of the columns i >= -k only, and with the wall far
    // away, all of the half lattice j >= 1
    const scalar dr = 0.01, delta = dr/2;
    const autoPtr<SPH::kernel> W(wendland(dr));
    SPH::dispatch(*W, [&](const auto& K)
    {
        const label m = label(K.support()/dr) + 1;
        const vector2D n(0, 1), nw(1, 0);
        // The ghost rows j >= 1 of columns i >= iMin
        auto rowsAbove = [&](const label iMin)
        {
            scalar sum = 0;
            for (label i = max(iMin, -m); i <= m; ++i)
            {
                for (label j = 1; j <= m; ++j)
                {
                    const scalar r = dr*Foam::sqrt(scalar(i*i + j*j));
                    if (r < K.support()) sum += dr*dr*K.W(r);
                }
            }
            return sum;
        };
        const scalar upper = rowsAbove(-m);
        for (label k = 0; k <= m; ++k)
        {
            const scalar clipped = SPH::ghostSurface::halfPlaneSum
            (
                K, dr, n, delta, nw, (k + 0.5)*dr
            );
            EXPECT_NEAR(clipped, rowsAbove(-k), 1e-12*upper) << "k " << k;
            EXPECT_LT(clipped, upper*(1 + 1e-12)) << "k " << k;
        }
        EXPECT_NEAR
        (
            SPH::ghostSurface::halfPlaneSum(K, dr, n, delta), upper, 1e-12*upper
        );
        // A wall at the top row's own level on the surface's side (a film
        // on a ceiling): no ghost is left
        EXPECT_EQ
        (
            SPH::ghostSurface::halfPlaneSum(K, dr, n, delta, -n, 0.5*dr), 0
        );
    });
}


TEST(ghostSurface, normalsDoNotPointIntoNearWalls)
{
    // The tank [0, 0.6]^2 at dr = 0.05, vertices on the walls: the fluid
    // particle at (0.55, 0.55) is dr from the ceiling and the right wall,
    // the one at (0.40, 0.40) 4 dr from both. Reach 1.5 dr, as isphFoam's
    const scalar dr = 0.05, reach = 1.5*dr, minOpen = 0.1;
    const operatorTest::latticeCase c
    (
        "tank { type box; min (0 0); max (0.6 0.6); }", dr,
        operatorTest::layout::nodal, vector2D(0, 0), vector2D(0.6, 0.6), 2
    );
    auto particleAt = [&](const vector2D& p)
    {
        for (label i = 0; i < c.nFluid; ++i)
        {
            if (mag(c.x[i] - p) < 1e-9) return i;
        }
        return label(-1);
    };
    const label corner = particleAt(vector2D(0.55, 0.55));
    const label inner = particleAt(vector2D(0.40, 0.40));
    const label byCeiling = particleAt(vector2D(0.30, 0.55));
    ASSERT_GE(corner, 0);
    ASSERT_GE(inner, 0);
    ASSERT_GE(byCeiling, 0);
    auto off = [&](const label i, const vector2D& n)
    {
        return SPH::ghostSurface::offWalls
        (
            *c.usaw, c.x, i, n/mag(n), reach, minOpen
        );
    };
    const scalar tol = 1e-12;

    // Mostly into the ceiling, a little to the open left: left
    const vector2D tip(off(corner, vector2D(-0.24, 0.97)));
    EXPECT_NEAR(tip.x(), -1, tol);
    EXPECT_NEAR(tip.y(), 0, tol);

    // Into both walls (the ceiling 1.25 dr along it, then the right wall
    // dr along what is left): nothing open is left
    EXPECT_EQ(off(corner, vector2D(0.6, 0.8)), vector2D::zero);
    // Straight into the ceiling, or nearly (less than minOpen left)
    EXPECT_EQ(off(byCeiling, vector2D(0, 1)), vector2D::zero);
    EXPECT_EQ(off(byCeiling, vector2D(0.05, 1)), vector2D::zero);

    // Away from the walls, or along them: unchanged
    for (const vector2D& n : {vector2D(-0.6, -0.8), vector2D(-1, 0)})
    {
        const vector2D kept(off(corner, n));
        EXPECT_NEAR(mag(kept - n/mag(n)), 0, tol) << n;
    }

    // A normal that meets the near ceiling only at a glancing angle, 4 dr
    // along it (a contact line under an overhanging wall): unchanged
    const vector2D glancing(0.97, 0.24);
    EXPECT_NEAR(mag(off(byCeiling, glancing) - glancing/mag(glancing)), 0, tol);

    // Walls beyond reach: a normal towards them is the surface's
    const vector2D towards(0.6, 0.8);
    EXPECT_NEAR(mag(off(inner, towards) - towards), 0, tol);
}


// ************************************************************************* //
