/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    heatScheme implicit of the heat-transfer model (Leroy et al. 2015,
    eq. (17), backward Euler on SPH::implicitDiffusionStep), in the square
    box of the differentially heated cavity (hot side isothermal at 1, cold
    side at 0, and a floor and lid that are adiabatic or carry a flux):

    - its rows are the explicit heat equation: with T^n = T, b - A T is
      heatTransfer::laplacian (the pair sums and the walls (31)-(34)) to
      round-off, with the paper's floor of d_as and with 0.5 dr;
    - far beyond the explicit limit (dt = 100 C_visq h^2/K) T stays
      within the walls' values at every step (a discrete maximum
      principle, the lagged vertex T being means of T^n), where the
      explicit step blows up;
    - the steady state it reaches with large steps is the explicit
      equation's fixed point: L{K, T} = 0 to the solver's tolerance,
      the vertex T of (32) included.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "heatedBoxCase.H"
#include "../operators/laplacianMatrixTestTools.H"
#include "implicitDiffusionStep.H"

#include <iostream>
#include <random>

using namespace Foam;
using namespace operatorTest;

namespace
{
    //- The heated box (heatedBoxCase.H) with its explicit operator
    struct cavity
    :
        public heatedBoxCase
    {
        cavity(const scalar dr, const bool lidFlux)
        :
            heatedBoxCase(dr, lidFlux ? 0.7 : 0)
        {}

        //- The explicit L{K, T} of the fluid (vertex T of (32) set first)
        scalarList explicitL(scalarList& T, const scalar K, const scalar floor)
        {
            const label n = c.size();
            scalarList KE(n, K), L(n, Zero);
            SPH::dispatch(*c.W, [&](const auto& W)
            {
                SPH::heatTransfer::vertexValues
                (
                    W, c.nbrs, *c.usaw, c.V, c.nFluid, d, T
                );
                SPH::heatTransfer::laplacian
                (
                    W, c.nbrs, *c.usaw, c.V, c.nFluid, KE, T, d, K, K, floor,
                    SPH::heatTransfer::turbulentWall(), L
                );
            });
            return L;
        }
    };

    autoPtr<SPH::linearSolver> solverT()
    {
        return SPH::linearSolver::New
        (
            "T",
            sphTest::dict
            (
                "solver BiCGStab; preconditioner ILU0; tolerance 1e-13;"
                " relTol 0; maxIter 2000;"
            )
        );
    }

    //- One step of either form from T (vertex T of (32) from T first)
    scalarList heatStep
    (
        cavity& cav,
        SPH::implicitDiffusionStep* step,
        const SPH::linearSolver& solver,
        const scalar K,
        const scalar dt,
        scalarList T
    )
    {
        const latticeCase& c = cav.c;
        if (!step)
        {
            const scalarList L(cav.explicitL(T, K, c.dr));
            for (label a = 0; a < c.nFluid; ++a) T[a] += dt*L[a];
            return T;
        }
        const scalarList KE(c.size(), K);
        SPH::dispatch(*c.W, [&](const auto& W)
        {
            SPH::heatTransfer::vertexValues
            (
                W, c.nbrs, *c.usaw, c.V, c.nFluid, cav.d, T
            );
            SPH::heatTransfer::implicitWallData(cav.d, *c.usaw, T, *step);
            const solverPerformance perf =
                step->solve(W, KE, dt, c.dr, solver, T);
            EXPECT_TRUE(perf.converged());
        });
        return T;
    }

    void checkRows(const bool lidFlux, const scalar floorByDr)
    {
        cavity cav(0.05, lidFlux);
        const latticeCase& c = cav.c;
        const label n = c.size();
        const scalar K = 0.03, dt = 1e-2, floor = floorByDr*c.dr;
        std::mt19937 gen(7);
        std::uniform_real_distribution<scalar> u(0, 1);
        scalarList T(n, -1.0);
        for (label a = 0; a < c.nFluid; ++a) T[a] = u(gen);
        const scalarList L(cav.explicitL(T, K, floor));

        SPH::implicitDiffusionStep step(c.nbrs, *c.usaw, c.V, c.nFluid);
        SPH::heatTransfer::implicitWallData(cav.d, *c.usaw, T, step);
        const scalarList KE(n, K);
        SPH::dispatch(*c.W, [&](const auto& W)
        {
            step.assemble(W, KE, dt, floor, T);
        });
        const SPH::sparseMatrix& A = step.system().matrix();
        const SPH::vectorN& b = step.system().source();
        SPH::vectorN x(n);
        forAll(T, i) x[i] = T[i];
        const SPH::vectorN r(b - A*x);

        // Round-off of sums of terms up to the largest |A_ab T_b| (the
        // diagonal's T/dt cancels in b - A T)
        const scalar scale = laplacianTest::largestTerm(A, x);
        scalar worst = 0;
        label nWall = 0;
        for (label a = 0; a < c.nFluid; ++a)
        {
            nWall += c.usaw->offsets()[a + 1] > c.usaw->offsets()[a];
            worst = max(worst, mag(r[a] - L[a]));
            EXPECT_NEAR(r[a], L[a], 1e-12*scale) << "particle " << a;
        }
        for (label v = c.nFluid; v < n; ++v)
        {
            EXPECT_EQ(b[v], T[v]) << "vertex particle " << v;
        }
        EXPECT_GT(nWall, 100);
        std::cout << "    lid " << (lidFlux ? "flux" : "adiabatic")
            << ", floor " << floorByDr << " dr: max |b - A T - L| / max|A T| "
            << worst/scale << std::endl;
    }
}


TEST(heatTransferImplicit, rowsAreTheExplicitHeatEquation)
{
    sphTest::throwOnFatal();
    checkRows(false, 1);
    checkRows(true, 1);
    checkRows(true, 0.5);
}


TEST(heatTransferImplicit, boundedFarBeyondTheExplicitLimit)
{
    // dt = 100 C_visq h^2/K: T stays within [0, 1] (the walls' and the
    // start's values) at every step; the explicit step leaves it at once
    sphTest::throwOnFatal();
    cavity cav(0.05, false);
    const latticeCase& c = cav.c;
    const scalar K = 0.03;
    const scalar dt = 100*0.125*sqr(c.W->h())/K;
    SPH::implicitDiffusionStep step(c.nbrs, *c.usaw, c.V, c.nFluid);
    const autoPtr<SPH::linearSolver> solver(solverT());
    scalarList T(c.size(), Zero);
    for (label a = 0; a < c.nFluid; ++a)
    {
        T[a] = c.x[a].y() > 0.5 ? 1 : 0;        // a jump: the hardest start
    }
    scalarList Te(T);
    scalar worstOut = 0, explicitOut = 0;
    for (label s = 0; s < 10; ++s)
    {
        T = heatStep(cav, &step, *solver, K, dt, T);
        for (label a = 0; a < c.nFluid; ++a)
        {
            worstOut = max(worstOut, max(T[a] - 1, -T[a]));
        }
        if (s < 3)
        {
            Te = heatStep(cav, nullptr, *solver, K, dt, Te);
        }
    }
    for (label a = 0; a < c.nFluid; ++a)
    {
        explicitOut = max(explicitOut, max(Te[a] - 1, -Te[a]));
    }
    std::cout << "    dt = 100 x the explicit limit: T outside [0, 1] by "
        << worstOut << " (implicit, 10 steps), " << explicitOut
        << " (explicit, 3 steps)" << std::endl;
    EXPECT_LT(worstOut, 1e-10);
    EXPECT_GT(explicitOut, 10);
}


TEST(heatTransferImplicit, steadyStateIsTheExplicitFixedPoint)
{
    // Pure conduction with an adiabatic floor and a heated lid: large
    // implicit steps (1000 times the explicit limit) reach the state where
    // the explicit L{K, T} of eq. (17), with the vertex T of (32) at that
    // state, vanishes: the lagged vertex T leaves no trace at a steady
    // state
    sphTest::throwOnFatal();
    cavity cav(0.05, true);
    const latticeCase& c = cav.c;
    const scalar K = 0.03;
    const scalar dt = 1000*0.125*sqr(c.W->h())/K;
    SPH::implicitDiffusionStep step(c.nbrs, *c.usaw, c.V, c.nFluid);
    const autoPtr<SPH::linearSolver> solver(solverT());
    scalarList T(c.size(), 0.5);
    scalar change = GREAT;
    label steps = 0;
    for (; steps < 200 && change > 1e-11; ++steps)
    {
        const scalarList Tn(T);
        T = heatStep(cav, &step, *solver, K, dt, T);
        change = 0;
        for (label a = 0; a < c.nFluid; ++a)
        {
            change = max(change, mag(T[a] - Tn[a]));
        }
    }
    const scalarList L(cav.explicitL(T, K, c.dr));
    scalar worstL = 0;
    for (label a = 0; a < c.nFluid; ++a)
    {
        worstL = max(worstL, mag(L[a]));
    }
    // L's scale: K |grad T|/dr with |grad T| of order 1
    const scalar scale = K/c.dr;
    std::cout << "    " << steps << " steps of 1000 x the limit: max |T^n+1"
        << " - T^n| " << change << ", max |L{K, T}| dr/K " << worstL/scale
        << std::endl;
    EXPECT_LT(change, 1e-11);
    EXPECT_LT(worstL, 1e-8*scale);
}


// ************************************************************************* //
