/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The USAW operators of src/sph/operators/usawOperators
    (000_8c7cd3aabddcf18a.txt eqs. (5), (8)-(10), (15)-(17), (37)) on
    regular lattices in a walled tank:

    - identities that hold to round-off for any fields and volumes: G+ and
      G- differ by 2 A G{1}; G+ and D are adjoint up to wall terms (the
      summation by parts behind G+ in the momentum equation); the pair sums
      of L cancel, leaving the wall flux (a discrete Gauss theorem); the
      three forms of L agree when they should;
    - away from walls, G- and D of linear fields are exact up to the
      kernel's lattice moment (1 - 8.0e-4 for Wendland C2 at h = 2 dr),
      to round-off;
    - near a straight wall and in a corner, the consistency errors of G-
      and D (linear fields), of L with its wall fluxes (quadratic field) and
      of the laminar wall friction (Couette flow) at fixed h as dr/h falls.

    Polynomial fields make every error scale-invariant: at fixed h/dr it is
    the same at every dr (to round-off), so convergence is measured at fixed
    h = 0.1 with h/dr = 2, 4, 8 (dr/h -> 0, where the lattice sums tend to
    the integrals the operators are built on). Tolerances are stated with
    each test from the expected order; the measured errors are printed.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "operatorTestTools.H"
#include "usawOperators.H"

#include <functional>
#include <iostream>
#include <limits>
#include <random>

using namespace Foam;
using namespace operatorTest;

namespace
{
    const scalar eps = std::numeric_limits<scalar>::epsilon();

    // Tank [0, L]^2 with h = 0.1: a straight stretch of bottom wall more
    // than 2h from the side walls, and the corner at the origin
    const scalar L = 0.6;
    const scalar hFixed = 0.1;
    const std::string tank = "tank { type box; min (0 0); max (0.6 0.6); }";

    latticeCase tankCase(const scalar hByDr, const layout lay)
    {
        return latticeCase
        (
            tank, hFixed/hByDr, lay, vector2D(0, 0), vector2D(L, L), hByDr
        );
    }

    // Fields: A linear, u linear (div u = 1.4), Q quadratic (lap Q = 1)
    const vector2D gradA(0.3, -0.7);
    scalar linearA(const vector2D& p) { return 1 + (gradA & p); }

    const tensor2D J(1, -2, 3, 0.4);    // du_i/dx_j, row i
    vector2D linearU(const vector2D& p)
    {
        return vector2D(0.2, -0.5) + (J & p);
    }

    scalar quadQ(const vector2D& p)
    {
        return p.x()*p.x() + p.x()*p.y() - 0.5*p.y()*p.y();
    }
    vector2D gradQ(const vector2D& p)
    {
        return vector2D(2*p.x() + p.y(), p.x() - p.y());
    }

    //- Largest err(a) over the fluid particles within 2h of the bottom
    //- wall's straight stretch, and within 2h of the corner (0, 0); only
    //- particles at least yMin from the bottom wall
    struct regionErrors
    {
        scalar straight = 0;
        scalar corner = 0;
    };

    regionErrors maxErrors
    (
        const latticeCase& c,
        const std::function<scalar(label)>& err,
        const scalar yMin = 0
    )
    {
        const scalar h = c.W->h();
        regionErrors e;
        for (label a = 0; a < c.nFluid; ++a)
        {
            const vector2D& p = c.x[a];
            if (p.y() >= 2*h || p.y() < yMin)
            {
                continue;
            }
            if (p.x() > 2*h && p.x() < L - 2*h)
            {
                e.straight = max(e.straight, err(a));
            }
            else if (p.x() < 2*h)
            {
                e.corner = max(e.corner, err(a));
            }
        }
        return e;
    }

    //- Errors at h/dr = 2, 4, 8: print them and check the ratio of the
    //- last two against minRatio (4 for second order); a negative corner
    //- error means the corner is not part of the test
    void checkConvergence
    (
        const char* what,
        const std::function<regionErrors(const latticeCase&)>& errors,
        const scalar minRatio,
        const layout lay = layout::cellCentred
    )
    {
        std::vector<regionErrors> e;
        for (const scalar hByDr : {2.0, 4.0, 8.0})
        {
            e.push_back(errors(tankCase(hByDr, lay)));
        }
        std::cout
            << "    " << what << (lay == layout::nodal ? " (nodal)" : "")
            << ", h/dr = 2, 4, 8:" << nl
            << "      straight wall " << e[0].straight << ' ' << e[1].straight
            << ' ' << e[2].straight << "  ratios " << e[0].straight/e[1].straight
            << ' ' << e[1].straight/e[2].straight << std::endl;
        EXPECT_GE(e[1].straight/e[2].straight, minRatio) << what;

        if (e[0].corner >= 0)
        {
            std::cout
                << "      corner        " << e[0].corner << ' ' << e[1].corner
                << ' ' << e[2].corner << "  ratios " << e[0].corner/e[1].corner
                << ' ' << e[1].corner/e[2].corner << std::endl;
            EXPECT_GE(e[1].corner/e[2].corner, minRatio) << what;
        }
    }

    //- Random values in [-1, 1] from a fixed seed
    scalarList randomList(const label n, const unsigned seed)
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<scalar> u(-1, 1);
        scalarList r(n);
        for (scalar& v : r)
        {
            v = u(gen);
        }
        return r;
    }
}


// * * * * * * * * * * * * * * * Identities  * * * * * * * * * * * * * * * //

TEST(usawOperators, gradPlusMinusGradMinusIsTwiceAShiftGradient)
{
    // Eqs. (5), (8), (37): G+{A}_a - G-{A}_a = 2 A_a G{1}_a term by term,
    // for any field. Each side sums O(100) terms of size ~|A| |grad w| V
    // ~ 0.01/h: tolerance 1e-12/h.
    sphTest::throwOnFatal();
    latticeCase c(tank, 0.05, layout::nodal, vector2D(0, 0), vector2D(L, L));
    const label n = c.size();
    const scalarList A(randomList(n, 1));
    List<vector2D> gp(n), gm(n), g1(n);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::gradPlus(K, c.nbrs, *c.usaw, c.V, A, gp);
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, A, gm);
        SPH::usaw::concentrationGradient(K, c.nbrs, *c.usaw, c.V, g1);
    });

    // |A| <= 1 and sum_b V_b |grad w_ab| ~ 1/h: terms are O(1/h)
    for (label a = 0; a < n; ++a)
    {
        EXPECT_LE(mag(gp[a] - gm[a] - 2*A[a]*g1[a]), 1e-12/c.W->h())
            << "particle " << a << " at " << c.x[a];
    }
}


TEST(usawOperators, tensileControlTakesEachParticlesOwnForm)
{
    // The tensile instability control is G- (8) at the flagged particles
    // and G+ (5) at the others, wall terms included: compared with the two
    // operators term by term on a tank with walls (the same sums, so to
    // round-off), every other particle flagged
    sphTest::throwOnFatal();
    latticeCase c(tank, 0.05, layout::nodal, vector2D(0, 0), vector2D(L, L));
    const label n = c.size();
    const scalarList A(randomList(n, 2));
    List<bool> symmetric(n, false);
    for (label a = 0; a < n; a += 2)
    {
        symmetric[a] = true;
    }
    List<vector2D> gp(n), gm(n), gt(n);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::gradPlus(K, c.nbrs, *c.usaw, c.V, A, gp);
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, A, gm);
        SPH::usaw::gradTensileControl(K, c.nbrs, *c.usaw, c.V, A, symmetric, gt);
    });

    label nWall = 0;
    for (label a = 0; a < c.nbrs.size(); ++a)
    {
        nWall += c.usaw->gamma()[a] < 1;
        EXPECT_LE(mag(gt[a] - (symmetric[a] ? gm[a] : gp[a])), 1e-12/c.W->h())
            << "particle " << a << " at " << c.x[a];
    }
    EXPECT_GT(nWall, 10) << "the case must have particles by the walls";

    // A flag list shorter than the targets is refused, not read past
    const List<bool> shortFlags(c.nbrs.size() - 1, false);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        EXPECT_THROW
        (
            SPH::usaw::gradTensileControl(K, c.nbrs, *c.usaw, c.V, A, shortFlags, gt),
            Foam::error
        );
    });
}


TEST(usawOperators, gradPlusAndDivAreAdjointUpToWallTerms)
{
    // Multiplying (5) by V_a gamma_a u_a and (9) by V_a gamma_a p_a and
    // summing over all particles, the pair terms
    // V_a V_b (p_b u_a + p_a u_b) . grad w_ab cancel (antisymmetric), so
    //   sum_a V_a gamma_a (u_a . G+_a{p} + p_a D_a{u})
    //     = -sum_a V_a sum_s (p_s u_a + p_a u_s) . grad gamma_as,
    // the discrete counterpart of int div(p u) = wall flux. Random fields
    // and the nodal lattice (vertex particles with volume) in a tank with
    // an obstacle (corners of pi/2 and 3pi/2). Recursive summation of the
    // ~1e5 pair terms: tolerance 1e-12 of the sum of their magnitudes.
    sphTest::throwOnFatal();
    latticeCase c
    (
        tank + " block { type polygon; points ((0.2 0.2) (0.35 0.2) (0.35 0.4)"
        " (0.2 0.4)); side outside; }",
        0.05, layout::nodal, vector2D(0, 0), vector2D(L, L)
    );
    const label n = c.size();
    const scalarList p(randomList(n, 2));
    const scalarList ux(randomList(n, 3)), uy(randomList(n, 4));
    List<vector2D> u(n);
    forAll(u, i)
    {
        u[i] = vector2D(ux[i], uy[i]);
    }
    List<vector2D> gp(n);
    scalarList d(n);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::gradPlus(K, c.nbrs, *c.usaw, c.V, p, gp);
        SPH::usaw::div(K, c.nbrs, *c.usaw, c.V, u, d);
    });

    const SPH::usawWalls& w = *c.usaw;
    scalar lhs = 0, rhs = 0, scale = 0;
    for (label a = 0; a < n; ++a)
    {
        lhs += c.V[a]*w.gamma()[a]*((u[a] & gp[a]) + p[a]*d[a]);
        for (label k = w.offsets()[a]; k < w.offsets()[a + 1]; ++k)
        {
            const labelPair& e = w.segmentParticles()[w.segments()[k]];
            const scalar ps = 0.5*(p[e.first()] + p[e.second()]);
            const vector2D us = 0.5*(u[e.first()] + u[e.second()]);
            rhs -= c.V[a]*((ps*u[a] + p[a]*us) & w.gradGammaAs()[k]);
        }
        for (label k = c.nbrs.offsets()[a]; k < c.nbrs.offsets()[a + 1]; ++k)
        {
            const label b = c.nbrs.indices()[k];
            scale += c.V[a]*c.V[b]*mag(p[b]*u[a] + p[a]*u[b])
                *mag(c.W->gradW(c.nbrs.rij()[k], c.nbrs.r()[k]));
        }
    }
    std::cout << "    sum V gamma (u.G+{p} + p D{u}) = " << lhs << ", wall terms "
        << rhs << ", pair-term scale " << scale << std::endl;
    ASSERT_GT(mag(rhs), 1e-3*scale) << "the wall terms must matter";
    EXPECT_NEAR(lhs, rhs, 1e-12*scale);
}


TEST(usawOperators, laplacianSumsToItsWallFlux)
{
    // The pair terms of (10) are antisymmetric in a and b, so
    //   sum_a V_a gamma_a L_a{B, A}
    //     = -sum_a V_a sum_s [B_s dAdn_s + B_a (grad A)_a . n_s]
    //        |grad gamma_as|:
    // a discrete Gauss theorem, for any fields. Same set-up and tolerance
    // as the adjoint test.
    sphTest::throwOnFatal();
    latticeCase c
    (
        tank + " block { type polygon; points ((0.2 0.2) (0.35 0.2) (0.35 0.4)"
        " (0.2 0.4)); side outside; }",
        0.05, layout::nodal, vector2D(0, 0), vector2D(L, L)
    );
    const label n = c.size();
    const scalarList A(randomList(n, 5));
    scalarList B(randomList(n, 6));
    for (scalar& b : B)
    {
        b += 2;     // a diffusivity: positive
    }
    const scalarList gx(randomList(n, 7)), gy(randomList(n, 8));
    List<vector2D> gA(n);
    forAll(gA, i)
    {
        gA[i] = vector2D(gx[i], gy[i]);
    }
    const scalarList dAdn(randomList(c.walls.segments().size(), 9));

    scalarList lap(n);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, B, A, dAdn, gA, lap);
    });

    const SPH::usawWalls& w = *c.usaw;
    scalar lhs = 0, rhs = 0, scale = 0;
    for (label a = 0; a < n; ++a)
    {
        lhs += c.V[a]*w.gamma()[a]*lap[a];
        for (label k = w.offsets()[a]; k < w.offsets()[a + 1]; ++k)
        {
            const label s = w.segments()[k];
            const labelPair& e = w.segmentParticles()[s];
            const scalar Bs = 0.5*(B[e.first()] + B[e.second()]);
            rhs -= c.V[a]*(Bs*dAdn[s]*mag(w.gradGammaAs()[k]) + B[a]*(gA[a] & w.gradGammaAs()[k]));
        }
        for (label k = c.nbrs.offsets()[a]; k < c.nbrs.offsets()[a + 1]; ++k)
        {
            const label b = c.nbrs.indices()[k];
            scale += c.V[a]*c.V[b]*(B[a] + B[b])*mag(A[a] - A[b])
                *mag(c.W->dWdr(c.nbrs.r()[k])/max(c.nbrs.r()[k], VSMALL));
        }
    }
    std::cout << "    sum V gamma L{B, A} = " << lhs << ", wall flux " << rhs
        << ", pair-term scale " << scale << std::endl;
    ASSERT_GT(mag(rhs), 1e-4*scale) << "the wall terms must matter";
    EXPECT_NEAR(lhs, rhs, 1e-12*scale);
}


TEST(usawOperators, laplacianFormsAgreeWhenTheNormalGradientIsUniform)
{
    // With B = 1 and a linear A, (grad A)_a . n_s = (grad A)_s . n_s, so
    // eq. (40), eq. (10) with that approximation and eq. (10) as printed
    // are the same sums in different order: tolerance 1e-12 relative
    sphTest::throwOnFatal();
    latticeCase c = tankCase(2, layout::cellCentred);
    const label n = c.size();
    scalarList A(n), ones(n, 1.0), dAdn(c.walls.segments().size());
    List<vector2D> gA(n, gradA);
    forAll(A, i)
    {
        A[i] = linearA(c.x[i]);
    }
    forAll(dAdn, s)
    {
        dAdn[s] = gradA & c.usaw->segmentNormals()[s];
    }
    scalarList l40(n), l10a(n), l10(n);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, A, dAdn, l40);
        SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, ones, A, dAdn, l10a);
        SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, ones, A, dAdn, gA, l10);
    });
    const scalar scale = mag(gradA)/hFixed;
    for (label a = 0; a < n; ++a)
    {
        EXPECT_NEAR(l40[a], l10a[a], 1e-12*scale);
        EXPECT_NEAR(l40[a], l10[a], 1e-12*scale);
    }
}


// * * * * * * * * * * * * * * * Consistency  * * * * * * * * * * * * * * * //

TEST(usawOperators, linearFieldsAwayFromWallsSeeOnlyTheLatticeMoment)
{
    // Beyond 2h from every wall no segment term enters, and on the full
    // lattice -sum_b V_b grad w_ab (x) r_ab = m I by symmetry, so
    //   G-{A} = m grad A,  G-{u} = m grad u,  D{u} = m div u
    // exactly; m - 1 is the lattice error of the kernel's second moment,
    // computed here independently of the operators. Tolerance: round-off
    // of ~50 terms, 1e-13 relative.
    sphTest::throwOnFatal();
    latticeCase c = tankCase(2, layout::cellCentred);
    const label n = c.size();
    const scalar h = c.W->h();

    scalar m = 0;
    const label reach = 6;
    for (label i = -reach; i <= reach; ++i)
    {
        for (label j = -reach; j <= reach; ++j)
        {
            const vector2D rab(i*c.dr, j*c.dr);
            m -= c.dr*c.dr*rab.x()*c.W->gradW(rab, mag(rab)).x();
        }
    }
    std::cout << "    Wendland C2 lattice moment at h = 2 dr: m - 1 = " << m - 1 << std::endl;

    scalarList A(n);
    List<vector2D> u(n);
    forAll(A, i)
    {
        A[i] = linearA(c.x[i]);
        u[i] = linearU(c.x[i]);
    }
    List<vector2D> gA(n);
    List<tensor2D> gU(n);
    scalarList dU(n);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, A, gA);
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, u, gU);
        SPH::usaw::div(K, c.nbrs, *c.usaw, c.V, u, dU);
    });

    // OpenFOAM's grad u is d u_j/d x_i: the transpose of J
    const tensor2D gradU(J.T());
    label nBulk = 0;
    for (label a = 0; a < c.nFluid; ++a)
    {
        if (c.walls.signedDistance(c.x[a]) < 2*h)
        {
            continue;
        }
        ++nBulk;
        EXPECT_NEAR(mag(gA[a] - m*gradA), 0, 1e-13*mag(gradA));
        EXPECT_NEAR(mag(gU[a] - m*gradU), 0, 1e-13*mag(J));
        EXPECT_NEAR(dU[a], m*tr(J), 1e-13*mag(J));
    }
    EXPECT_GT(nBulk, 10);
}


TEST(usawOperators, renormalisedGradAndDivOfLinearFieldsAreExactAtAnyDistanceFromAWall)
{
    // R . G-{A} and tr(R . G-{u}) with R = G-{r}^-1: exact to round-off at
    // every fluid particle of the tank, beside the straight walls, in the
    // corners and in the bulk, for both seedings and h/dr = 2 and 4 (the
    // paper's G- and D miss by 1.8e-2 within 2h of a wall at h/dr = 2)
    sphTest::throwOnFatal();
    for (const layout lay : {layout::cellCentred, layout::nodal})
    {
        for (const scalar hByDr : {2.0, 4.0})
        {
            const latticeCase c(tankCase(hByDr, lay));
            List<vector2D> u(c.size());
            scalarList A(c.size());
            forAll(u, i)
            {
                u[i] = linearU(c.x[i]);
                A[i] = linearA(c.x[i]);
            }
            List<tensor2D> R(c.size());
            List<vector2D> g(c.size()), gPaper(c.size());
            scalarList d(c.size());
            SPH::dispatch(*c.W, [&](const auto& K)
            {
                SPH::usaw::renormalisation(K, c.nbrs, *c.usaw, c.V, c.x, 1e-6, R);
                SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, R, A, g);
                SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, A, gPaper);
                SPH::usaw::div(K, c.nbrs, *c.usaw, c.V, R, u, d);
            });
            scalar gradErr = 0, divErr = 0, paperErr = 0;
            for (label a = 0; a < c.nFluid; ++a)
            {
                gradErr = max(gradErr, mag(g[a] - gradA)/mag(gradA));
                divErr = max(divErr, mag(d[a] - tr(J))/mag(tr(J)));
                paperErr = max(paperErr, mag(gPaper[a] - gradA)/mag(gradA));
            }
            std::cout << "    h/dr " << hByDr
                << (lay == layout::nodal ? " nodal" : " cell-centred")
                << ": max relative error of R.G-{A} " << gradErr
                << ", tr(R.G-{u}) " << divErr << " (G-{A} of eq. (8): "
                << paperErr << ")" << std::endl;
            EXPECT_LT(gradErr, 1e3*eps);
            EXPECT_LT(divErr, 1e3*eps);
            EXPECT_GT(paperErr, 1e-4);     // the correction is doing the work
        }
    }
}


TEST(usawOperators, gradMinusOfLinearFieldConvergesAtSecondOrderNearWalls)
{
    // The continuous G- of eq. (8) with exact segment integrals is exact
    // for linear fields at any distance from a wall (Gauss' theorem), so
    // what remains is the lattice quadrature of the truncated integrals and
    // the midpoint value A_s: both O((dr/h)^2). Second order: ratio 4 per
    // halving of dr/h; accept >= 3.5 from h/dr = 4 to 8.
    sphTest::throwOnFatal();
    checkConvergence
    (
        "max |G-{A} - grad A|/|grad A| within 2h of a wall",
        [](const latticeCase& c)
        {
            scalarList A(c.size());
            forAll(A, i)
            {
                A[i] = linearA(c.x[i]);
            }
            List<vector2D> g(c.size());
            SPH::dispatch(*c.W, [&](const auto& K)
            {
                SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, A, g);
            });
            return maxErrors
            (
                c, [&](const label a) { return mag(g[a] - gradA)/mag(gradA); }
            );
        },
        3.5
    );
}


TEST(usawOperators, divOfLinearFieldConvergesAtSecondOrderNearWalls)
{
    // As for G-: eq. (9) is exact for linear fields in the continuum;
    // second order, ratio >= 3.5 from h/dr = 4 to 8
    sphTest::throwOnFatal();
    checkConvergence
    (
        "max |D{u} - div u|/|div u| within 2h of a wall",
        [](const latticeCase& c)
        {
            List<vector2D> u(c.size());
            forAll(u, i)
            {
                u[i] = linearU(c.x[i]);
            }
            scalarList d(c.size());
            SPH::dispatch(*c.W, [&](const auto& K)
            {
                SPH::usaw::div(K, c.nbrs, *c.usaw, c.V, u, d);
            });
            return maxErrors
            (
                c, [&](const label a) { return mag(d[a] - tr(J))/mag(tr(J)); }
            );
        },
        3.5
    );
}


TEST(usawOperators, laplacianOfQuadraticFieldWithWallFluxConverges)
{
    // Eq. (10) as printed, with the exact normal derivative at the segment
    // centres and the exact (grad Q)_a: in the continuum its two wall
    // terms make it exact for quadratic fields near a straight wall (the
    // B_a (grad A)_a term cancels the first moment of the truncated Morris
    // sum). The lattice error falls at an order that reaches 2 from below
    // (ratios 2.5, 3.35, 3.7 for h/dr = 2-4-8-16): accept >= 3 from 4 to 8.
    // Eq. (40)'s approximation (grad Q)_a.n_s = (grad Q)_s.n_s leaves an
    // O(|Q''|) error that does not fall (printed, not checked).
    sphTest::throwOnFatal();
    std::vector<scalar> err40;
    checkConvergence
    (
        "max |L{1, Q} - lap Q| within 2h of a wall, eq. (10)",
        [&err40](const latticeCase& c)
        {
            const label n = c.size();
            scalarList Q(n), ones(n, 1.0), dQdn(c.walls.segments().size());
            List<vector2D> gQ(n);
            forAll(Q, i)
            {
                Q[i] = quadQ(c.x[i]);
                gQ[i] = gradQ(c.x[i]);
            }
            forAll(dQdn, s)
            {
                dQdn[s] = gradQ(c.usaw->segmentCentres()[s]) & c.usaw->segmentNormals()[s];
            }
            scalarList l10(n), l40(n);
            SPH::dispatch(*c.W, [&](const auto& K)
            {
                SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, ones, Q, dQdn, gQ, l10);
                SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, Q, dQdn, l40);
            });
            err40.push_back
            (
                maxErrors(c, [&](const label a) { return mag(l40[a] - 1); }).straight
            );
            return maxErrors(c, [&](const label a) { return mag(l10[a] - 1); });
        },
        3
    );
    std::cout << "      eq. (40) form, straight wall: " << err40[0] << ' ' << err40[1]
        << ' ' << err40[2] << std::endl;
}


TEST(usawOperators, laminarViscousOfCouetteFlowConvergesAtSecondOrder)
{
    // u = (y, 0) over the still bottom wall: the viscous term (15) must
    // vanish. Its wall friction uses dr_as = max(y_a, dr) (17), exact for
    // y_a >= dr, so in the continuum it cancels the truncated Morris sum.
    // Second order (ratio >= 3.5, measured 3.9-4.0) for particles at least
    // h/2 from the wall, on both lattices; the rows closer in converge
    // more slowly, and on the cell-centred lattice the first row (y = dr/2
    // < dr) keeps an O(1) error by design of (17) (printed).
    sphTest::throwOnFatal();
    for (const layout lay : {layout::cellCentred, layout::nodal})
    {
        for (const scalar yMin : {0.5*hFixed, 0.0})
        {
            const auto errors = [yMin](const latticeCase& c)
            {
                const label n = c.size();
                List<vector2D> u(n, vector2D::zero), visc(n);
                for (label a = 0; a < c.nFluid; ++a)
                {
                    u[a] = vector2D(c.x[a].y(), 0);
                }
                SPH::dispatch(*c.W, [&](const auto& K)
                {
                    SPH::usaw::laminarViscous(K, c.nbrs, *c.usaw, c.V, 1, u, c.dr, visc);
                });
                // h |L{mu, u}| with mu = 1, du/dy = 1: relative to mu (du/dy)/h,
                // the size of each of its two terms near the wall
                regionErrors e = maxErrors
                (
                    c, [&](const label a) { return c.W->h()*mag(visc[a]); }, yMin
                );
                e.corner = -1;  // no Couette solution in the corner
                return e;
            };
            if (yMin > 0)
            {
                checkConvergence("h |L{mu, u}|, y >= h/2", errors, 3.5, lay);
            }
            else
            {
                std::vector<scalar> e;
                for (const scalar hByDr : {2.0, 4.0, 8.0})
                {
                    e.push_back(errors(tankCase(hByDr, lay)).straight);
                }
                std::cout << "    h |L{mu, u}|, all rows"
                    << (lay == layout::nodal ? " (nodal)" : "") << ": "
                    << e[0] << ' ' << e[1] << ' ' << e[2] << std::endl;
            }
        }
    }
}


TEST(usawOperators, concentrationGradientVanishesAsDrOverHFalls)
{
    // G{1} (37) is the difference of the lattice sum of grad w and its
    // exact integral grad gamma: zero in the continuum, O((dr/h)^2) on the
    // lattice near walls (midpoint rule cut by the wall), approached from
    // below as for L (ratios 2.4, 3.3, 3.7 for h/dr = 2-4-8-16): accept >= 3
    // from 4 to 8. Exactly zero (by symmetry) in the bulk.
    sphTest::throwOnFatal();
    checkConvergence
    (
        "max h |G{1}| within 2h of a wall",
        [](const latticeCase& c)
        {
            List<vector2D> g(c.size());
            SPH::dispatch(*c.W, [&](const auto& K)
            {
                SPH::usaw::concentrationGradient(K, c.nbrs, *c.usaw, c.V, g);
            });
            for (label a = 0; a < c.nFluid; ++a)
            {
                if (c.walls.signedDistance(c.x[a]) > 2*c.W->h())
                {
                    EXPECT_LT(c.W->h()*mag(g[a]), 1e-13);
                }
            }
            return maxErrors(c, [&](const label a) { return c.W->h()*mag(g[a]); });
        },
        3
    );
}


TEST(usawOperators, divPositionUsesMinimumImages)
{
    // D{r} of eq. (9) with r_ab from the neighbour list: in a channel
    // periodic in x it must not see the jump of x across the period, so it
    // is the same in every column (the lattice is invariant under shifts
    // by dr), and away from the walls it is 2 m (m the lattice moment)
    sphTest::throwOnFatal();
    const scalar dr = 0.05;
    const autoPtr<SPH::kernel> W
    (
        SPH::kernel::New(sphTest::dict("kernel wendlandC2;"), dr)
    );
    const SPH::wallMesh walls
    (
        makeWalls
        (
            "bottom { type line; points ((0 0) (1 0)); }"
            " top { type line; points ((1 0.6) (0 0.6)); }",
            dr
        )
    );
    DynamicList<vector2D> pts;
    for (label j = 0; j < 12; ++j)
    {
        for (label i = 0; i < 20; ++i)
        {
            pts.append(vector2D((i + 0.5)*dr, (j + 0.5)*dr));
        }
    }
    const label nFluid = pts.size();
    pts.append(walls.points());
    const List<vector2D> x(pts);
    scalarList V(x.size(), dr*dr);
    for (label v = nFluid; v < x.size(); ++v)
    {
        V[v] = 0;
    }

    SPH::cellLinkedList cells(vector2D(0, 0), vector2D(1, 0.6), W->support(), {true, false});
    cells.build(x);
    SPH::neighbourList nbrs(true);
    nbrs.build(cells, x, W->support(), true);
    SPH::usawWalls usaw(walls, *W, nFluid, vector2D(0, 0), vector2D(1, 0.6), {true, false});
    usaw.update(x);

    scalarList d(x.size());
    SPH::dispatch(*W, [&](const auto& K)
    {
        SPH::usaw::divPosition(K, nbrs, usaw, V, d);
    });
    for (label j = 0; j < 12; ++j)
    {
        for (label i = 1; i < 20; ++i)
        {
            EXPECT_NEAR(d[j*20 + i], d[j*20], 1e-13) << "row " << j << " column " << i;
        }
    }
    // Rows 4..7 are more than 2h = 4 dr from both walls
    EXPECT_NEAR(d[5*20], 2*(1 - 8.0e-4), 1e-5);
}


TEST(usawOperators, errorsOfPolynomialFieldsDoNotFallAtFixedHByDr)
{
    // With h/dr fixed, a lattice scaled by k and a linear field give every
    // term of (8) scaled consistently: the relative error is a property of
    // the lattice and the kernel, the same at every dr. So G- of a linear
    // field is not exact on a lattice (1.8e-2 near a wall at h = 2 dr) and
    // does not converge under refinement at fixed h/dr - only as dr/h
    // falls (tests above). Same errors to round-off: 1e-12.
    sphTest::throwOnFatal();
    scalar e[2];
    label i = 0;
    for (const scalar dr : {0.05, 0.025})
    {
        latticeCase c(tank, dr, layout::cellCentred, vector2D(0, 0), vector2D(L, L));
        scalarList A(c.size());
        forAll(A, j)
        {
            A[j] = linearA(c.x[j]);
        }
        List<vector2D> g(c.size());
        SPH::dispatch(*c.W, [&](const auto& K)
        {
            SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, A, g);
        });
        e[i] = 0;
        for (label a = 0; a < c.nFluid; ++a)
        {
            e[i] = max(e[i], mag(g[a] - gradA)/mag(gradA));
        }
        ++i;
    }
    std::cout << "    max |G-{A} - grad A|/|grad A| at h = 2 dr, dr = 0.05, 0.025: "
        << e[0] << ' ' << e[1] << std::endl;
    EXPECT_NEAR(e[0], e[1], 1e-12);
}


TEST(usawOperators, mismatchedOperandsAreFatal)
{
    sphTest::throwOnFatal();
    latticeCase c = tankCase(2, layout::cellCentred);
    const label n = c.size();
    scalarList A(n, 1.0), shortA(n - 1, 1.0);
    List<vector2D> g(n), shortG(c.nbrs.size() - 1);
    SPH::neighbourList noGeometry(false);
    noGeometry.build(*c.cells, c.x, c.W->support(), true);

    SPH::dispatch(*c.W, [&](const auto& K)
    {
        EXPECT_NO_THROW(SPH::usaw::gradPlus(K, c.nbrs, *c.usaw, c.V, A, g));
        EXPECT_THROW(SPH::usaw::gradPlus(K, c.nbrs, *c.usaw, c.V, shortA, g), Foam::error);
        EXPECT_THROW(SPH::usaw::gradPlus(K, c.nbrs, *c.usaw, c.V, A, shortG), Foam::error);
        EXPECT_THROW(SPH::usaw::gradPlus(K, noGeometry, *c.usaw, c.V, A, g), Foam::error);
        scalarList dAdn(c.walls.segments().size() + 1, 0.0), lap(n);
        EXPECT_THROW(SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, A, dAdn, lap), Foam::error);
    });
}


// ************************************************************************* //
