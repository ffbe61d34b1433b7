/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The terms of the k-epsilon model (Leroy et al. 2014, section 3.1 and
    Appendix A) on particle lattices:
    - the production (20)-(21) on a linear shear, both of its branches;
    - the epsilon diffusion with the wall term (27) in a log layer
      (k uniform, epsilon = u_k^3/(kappa y), nu_T = kappa y u_k) beside a
      flat wall, against the exact d/dy(nu_T/sigma deps/dy) = u_k^4/(sigma
      y^2): the wall term is what makes it right near the wall;
    - the vertex values (26), (28)-(29): k the fluid's, epsilon the first
      row's plus the log layer's jump of (A.7);
    - no diffusion of a uniform field away from walls.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "../operators/operatorTestTools.H"
#include "kEpsilon.H"
#include "usawOperators.H"

#include <cmath>

using namespace Foam;
using namespace operatorTest;

namespace
{
    const scalar Cmu = 0.09, kappa = 0.41, sigmaEps = 1.3;

    // A channel 1 m high (walls at y = 0 and 1), periodic lattice
    // truncated in x (only columns far from the ends are checked)
    const char* channelWalls =
        "bottom { type line; points ((-1 0) (2 0)); }"
        "top { type line; points ((2 1) (-1 1)); }";

    bool farFromEnds(const latticeCase& c, label a)
    {
        return c.x[a].x() > 0.3 && c.x[a].x() < 0.7;
    }
}


TEST(kEpsilonTerms, productionOnALinearShear)
{
    latticeCase c(channelWalls, 0.05, layout::nodal, {-1, 0}, {2, 1});
    const scalar a = 3;
    List<vector2D> u(c.size());
    forAll(u, i) u[i] = vector2D(a*c.x[i].y(), 0);
    List<tensor2D> G(c.size());
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, u, G);
    });
    label checked = 0;
    for (label i = 0; i < c.nFluid; ++i)
    {
        if (!farFromEnds(c, i)) continue;
        // nu_T S^2 below sqrt(Cmu) k S, and above (S = a; G-{u} of the
        // paper is exact up to the lattice's kernel moment: 1 % inside,
        // 5 % within the kernel's support of a wall, its quadrature)
        const scalar k = 0.5;
        const bool nearWall = min(c.x[i].y(), 1 - c.x[i].y()) < c.W->support();
        const scalar tol = nearWall ? 0.05 : 0.01;
        const scalar P1 = SPH::kEpsilon::production(k, 1e-3, G[i], Cmu);
        const scalar P2 = SPH::kEpsilon::production(k, 10, G[i], Cmu);
        EXPECT_NEAR(P1, 1e-3*a*a, tol*1e-3*a*a) << "y " << c.x[i].y();
        EXPECT_NEAR(P2, 0.3*k*a, tol*0.3*k*a) << "y " << c.x[i].y();
        // production quadratic: nu_T S^2 whatever sqrt(Cmu) k S
        const scalar P3 = SPH::kEpsilon::production(k, 10, G[i], Cmu, false);
        EXPECT_NEAR(P3, 10*a*a, tol*10*a*a) << "y " << c.x[i].y();
        ++checked;
    }
    EXPECT_GT(checked, 100);
}


TEST(kEpsilonTerms, epsilonDiffusionInALogLayerWithTheWallTerm)
{
    // The log layer of u* = 1: u_k = Cmu^1/4 sqrt(k) = 1, eps = 1/(kappa y),
    // nu_T = kappa y; exact diffusion d/dy(nu_T/sigma deps/dy) = 1/(sigma y^2)
    const scalar dr = 0.02;
    latticeCase c(channelWalls, dr, layout::nodal, {-1, 0}, {2, 1});
    const scalar k0 = 1/std::sqrt(Cmu);
    const label n = c.size();
    scalarList k(n, k0), eps(n), D(n), L(n), noFlux(c.walls.segments().size(), 0.0);
    auto y = [&](label i) { return min(c.x[i].y(), 1 - c.x[i].y()); };
    for (label i = 0; i < n; ++i)
    {
        const scalar yi = max(y(i), 0.5*dr);   // vertices: see vertexValues
        eps[i] = 1/(kappa*yi);
        // nu_T = 0 at the vertex particles, as kEpsilon has it
        D[i] = i < c.nFluid ? kappa*yi/sigmaEps : 0;
    }
    labelListList vertexSegments(n - c.nFluid);
    forAll(c.usaw->segmentParticles(), s)
    {
        const labelPair& e = c.usaw->segmentParticles()[s];
        vertexSegments[e.first() - c.nFluid].append(s);
        vertexSegments[e.second() - c.nFluid].append(s);
    }
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::kEpsilon::vertexValues
        (
            K, c.nbrs, *c.usaw, c.V, c.nFluid, vertexSegments, Cmu, kappa,
            dr, k, eps
        );
        SPH::kEpsilon::epsilonDiffusion
        (
            K, c.nbrs, *c.usaw, c.V, c.nFluid, D, k, eps, noFlux, Cmu,
            sigmaEps, dr, L
        );
    });

    // The first row (at dr, the row the wall term (A.4) is made for)
    // within 1 % of the exact diffusion (0.02 % measured; 21 % when the
    // vertices had nu_T = kappa dr/2 instead of 0: the vertex value (A.7)
    // assumes the pair's coefficient to be 2 nu_T at mid-distance,
    // nu_T,a + 0), and 20 % on rows 5 to 12;
    // between them the kernel smooths the 1/y field over its support
    // (rows 2-4 up to 1.9 times the exact value), positive all the same.
    // Without the wall term the first row would be far off.
    label checked = 0;
    scalar worstFirst = 0, worstFar = 0, worstWithoutWall = VGREAT;
    const scalar c4 = 4*Cmu/sigmaEps;
    for (label i = 0; i < c.nFluid; ++i)
    {
        if (!farFromEnds(c, i) || c.x[i].y() > 0.5) continue;
        const scalar row = c.x[i].y()/dr;
        const scalar exact = 1/(sigmaEps*sqr(y(i)));
        const scalar err = mag(L[i] - exact)/exact;
        EXPECT_GT(L[i], 0) << "y " << c.x[i].y();
        if (row < 1.5)
        {
            scalar wallSum = 0;
            const label* wOff = c.usaw->offsets().cdata();
            for (label m = wOff[i]; m < wOff[i + 1]; ++m)
            {
                wallSum +=
                    mag(c.usaw->gradGammaAs()[m])
                   /max(c.usaw->distances()[m], dr);
            }
            const scalar pairsOnly =
                L[i] - c4*k[i]*k[i]*wallSum/c.usaw->gamma()[i];
            worstFirst = max(worstFirst, err);
            worstWithoutWall =
                min(worstWithoutWall, mag(pairsOnly - exact)/exact);
            ++checked;
        }
        else if (row > 4.5 && row < 12.5)
        {
            worstFar = max(worstFar, err);
        }
    }
    EXPECT_GT(checked, 5);
    EXPECT_LT(worstFirst, 0.01) << "first row";
    EXPECT_LT(worstFar, 0.20) << "rows 5 on";
    EXPECT_GT(worstWithoutWall, 0.5) << "first row without the wall term";
}


TEST(kEpsilonTerms, vertexValuesFollowTheFirstRows)
{
    const scalar dr = 0.05;
    latticeCase c(channelWalls, dr, layout::nodal, {-1, 0}, {2, 1});
    const label n = c.size();
    const scalar k0 = 2, eps0 = 3;
    scalarList k(n, k0), eps(n, eps0);
    labelListList vertexSegments(n - c.nFluid);
    forAll(c.usaw->segmentParticles(), s)
    {
        const labelPair& e = c.usaw->segmentParticles()[s];
        vertexSegments[e.first() - c.nFluid].append(s);
        vertexSegments[e.second() - c.nFluid].append(s);
    }
    for (label v = c.nFluid; v < n; ++v) { k[v] = -1; eps[v] = -1; }
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::kEpsilon::vertexValues
        (
            K, c.nbrs, *c.usaw, c.V, c.nFluid, vertexSegments, Cmu, kappa,
            dr, k, eps
        );
    });
    // k: the fluid's (uniform); epsilon: above the fluid's by the jump
    // 4 Cmu^3/4 k^3/2/(kappa dr_bs) of (A.7) averaged over the support
    const scalar jumpAtDr = 4*std::pow(Cmu, 0.75)*std::pow(k0, 1.5)/(kappa*dr);
    label checked = 0;
    for (label v = c.nFluid; v < n; ++v)
    {
        if (c.x[v].x() < 0.3 || c.x[v].x() > 0.7) continue;
        EXPECT_NEAR(k[v], k0, 1e-12);
        EXPECT_GT(eps[v], eps0 + 0.25*jumpAtDr);
        EXPECT_LT(eps[v], eps0 + jumpAtDr);
        ++checked;
    }
    EXPECT_GT(checked, 10);
}


TEST(kEpsilonTerms, noDiffusionOfAUniformField)
{
    latticeCase c(channelWalls, 0.05, layout::nodal, {-1, 0}, {2, 1});
    const label n = c.size();
    scalarList k(n, 0.7), D(n, 0.01), L(n), noFlux(c.walls.segments().size(), 0.0);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, D, k, noFlux, L);
    });
    for (label i = 0; i < c.nFluid; ++i)
    {
        EXPECT_NEAR(L[i], 0, 1e-12) << "particle " << i;
    }
}


// ************************************************************************* //
