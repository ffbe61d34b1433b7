/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::reachesAnAnchor (src/sph/linearSolvers/floatingRows): which rows of
    a weakly diagonally dominant matrix reach a strictly dominant row. A
    chain to an anchor, a set coupled only among itself, a set joined to
    the anchored rows by a kernel's tail (1e-42) only, a set held by links
    of less than 1e-4 of its diagonal (nonsingular, but a level 1e4 times
    as sensitive to its sources), links that run one
    way, Dirichlet rows skipped, and rows marked as anchors; each verdict
    against Eigen's SparseLU (singular or not). And two whose answer does
    not depend on the order of the rows: a chain numbered back and forth
    around its anchor, and random matrices against a plain fixed point of
    "a row reaches when a row it refers to does".

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "floatingRows.H"

#include <Eigen/SparseLU>
#include <random>

using namespace Foam;

namespace
{
    typedef std::vector<Eigen::Triplet<scalar>> triplets;

    //- Rows i: diag d_i, off-diagonals -w to each listed neighbour, with
    //- d_i the sum of the |off| plus extra[i] (> 0: strictly dominant)
    SPH::sparseMatrix matrix
    (
        const label n,
        const std::vector<std::tuple<int, int, scalar>>& links,
        const std::vector<scalar>& extra
    )
    {
        triplets t;
        std::vector<scalar> diag(extra);
        for (const auto& [i, j, w] : links)
        {
            t.emplace_back(i, j, -w);
            diag[i] += w;
        }
        for (label i = 0; i < n; ++i)
        {
            t.emplace_back(i, i, diag[i]);
        }
        SPH::sparseMatrix M(n, n);
        M.setFromTriplets(t.begin(), t.end());
        M.makeCompressed();
        return M;
    }

    bool singular(const SPH::sparseMatrix& M)
    {
        Eigen::SparseMatrix<scalar> A(M);
        Eigen::SparseLU<Eigen::SparseMatrix<scalar>> lu;
        lu.compute(A);
        return lu.info() != Eigen::Success || lu.absDeterminant() < 1e-30;
    }

    boolList none(const label n) { return boolList(n, false); }

    //- {0, 1} anchored by row 1, {2, 3} coupled among themselves; row 2
    //- refers to row 1 with the given weight (0: not at all)
    SPH::sparseMatrix twoPairs(const scalar link)
    {
        std::vector<std::tuple<int, int, scalar>> links
        {{0, 1, 1}, {1, 0, 1}, {2, 3, 1}, {3, 2, 1}};
        if (link > 0) links.emplace_back(2, 1, link);
        return matrix(4, links, {0, 0.5, 0, 0});
    }

    //- reachesAnAnchor's verdict, row by row
    void expectReaches(const boolList& r, const std::vector<bool>& expected)
    {
        ASSERT_EQ(r.size(), label(expected.size()));
        for (size_t i = 0; i < expected.size(); ++i)
        {
            EXPECT_EQ(bool(r[i]), expected[i]) << "row " << i;
        }
    }
}


TEST(floatingRows, aChainToAnAnchorDoesNotFloat)
{
    // 0 - 1 - 2 - 3, row 3 strictly dominant
    const auto M = matrix
    (
        4,
        {{0, 1, 1}, {1, 0, 1}, {1, 2, 1}, {2, 1, 1}, {2, 3, 1}, {3, 2, 1}},
        {0, 0, 0, 0.5}
    );
    expectReaches
    (
        SPH::reachesAnAnchor(M, none(4), none(4)), {true, true, true, true}
    );
    EXPECT_FALSE(singular(M));
}


TEST(floatingRows, aSetCoupledOnlyAmongItselfFloats)
{
    // {0, 1} anchored by row 1; {2, 3} only among themselves
    const auto M = twoPairs(0);
    expectReaches
    (
        SPH::reachesAnAnchor(M, none(4), none(4)), {true, true, false, false}
    );
    EXPECT_TRUE(singular(M));
}


TEST(floatingRows, aKernelsTailIsNoLink)
{
    // {2, 3} joined to the anchored {0, 1} by 1e-42 only floats; a real
    // link anchors it
    const auto tail = SPH::reachesAnAnchor(twoPairs(1e-42), none(4), none(4));
    expectReaches(tail, {true, true, false, false});

    const auto M = twoPairs(1e-3);
    expectReaches
    (
        SPH::reachesAnAnchor(M, none(4), none(4)), {true, true, true, true}
    );
    EXPECT_FALSE(singular(M));
}


TEST(floatingRows, aSetHeldByLinksOfLessThan1e4OfItsDiagonalFloats)
{
    // The 2 mm obstacle dam-break at 0.574 s: a particle pressed under the
    // ceiling, held to the liquid by entries of 2e-6 to 3e-5 of its
    // diagonal and itself dominant by 1e-5, with the ceiling's vertices
    // coupled among themselves. Its set is nonsingular, but its level is
    // 1e5 times as sensitive to its sources as the liquid's: it was solved
    // at 3.3e8 Pa. Rows 2 and 3 here: 3e-5 to the anchored pair, and
    // row 3 dominant by 1e-5 of its off-diagonal sum
    const auto weak = matrix
    (
        4,
        {{0, 1, 1}, {1, 0, 1}, {2, 3, 1}, {3, 2, 1}, {2, 1, 3e-5}},
        {0, 0.5, 0, 1e-5}
    );
    expectReaches
    (
        SPH::reachesAnAnchor(weak, none(4), none(4)), {true, true, false, false}
    );
    EXPECT_FALSE(singular(weak));

    // The same set through 1e-3 of the diagonal, or dominant by 1e-3 of
    // its sum, is held
    expectReaches
    (
        SPH::reachesAnAnchor(twoPairs(1e-3), none(4), none(4)),
        {true, true, true, true}
    );
    const auto dominant = matrix
    (
        4, {{0, 1, 1}, {1, 0, 1}, {2, 3, 1}, {3, 2, 1}}, {0, 0.5, 0, 1e-3}
    );
    expectReaches
    (
        SPH::reachesAnAnchor(dominant, none(4), none(4)), {true, true, true, true}
    );

    // How sensitive: the pair's level under a unit source, against the
    // anchored pair's
    Eigen::SparseMatrix<scalar> A(weak);
    Eigen::SparseLU<Eigen::SparseMatrix<scalar>> lu;
    lu.compute(A);
    Eigen::VectorXd b(4);
    b << 1, 1, 1, 1;
    const Eigen::VectorXd x = lu.solve(b);
    EXPECT_GT(std::abs(x(2)), 1e4*std::abs(x(0)));
}


TEST(floatingRows, aLinkCountsOnlyFromTheRowThatRefersToTheAnchor)
{
    // Row 0 refers to the anchor 2 and to row 4; rows 1 and 3 refer to 0,
    // so they reach 2 through it. Rows 4 and 5 refer only to each other:
    // 0's reference to 4 runs the wrong way, and {4, 5} floats
    const auto M = matrix
    (
        6,
        {
            {0, 2, 1}, {0, 4, 1}, {1, 0, 1}, {3, 0, 1},
            {4, 5, 1}, {5, 4, 1}
        },
        {0, 0, 1, 0, 0, 0}
    );
    expectReaches
    (
        SPH::reachesAnAnchor(M, none(6), none(6)),
        {true, true, true, true, false, false}
    );
    EXPECT_TRUE(singular(M));
}


TEST(floatingRows, markedAnchorsAndSkippedRows)
{
    // {0, 1} only among themselves: marking row 1 an anchor (a particle
    // fixed at p = 0, which assembled again makes its neighbours dominant)
    // anchors row 0; a skipped row is neither anchor nor link
    const auto M = matrix(3, {{0, 1, 1}, {1, 0, 1}, {2, 1, 1}}, {0, 0, 0.5});
    boolList anchor(none(3));
    anchor[1] = true;
    expectReaches(SPH::reachesAnAnchor(M, none(3), anchor), {true, true, true});

    boolList skip(none(3));
    skip[1] = true;
    expectReaches(SPH::reachesAnAnchor(M, skip, anchor), {false, false, true});
}


TEST(floatingRows, aChainNumberedAgainstEverySweep)
{
    // The anchor at row 20; step c of the chain alternates around it
    // (21, 19, 22, 18, ...) and refers to step c - 1: a pass over the rows
    // in either direction reaches one more step only. The last step refers
    // to nothing reached and floats.
    const label n = 41, steps = 30;
    std::vector<std::tuple<int, int, scalar>> links;
    label previous = 20;
    for (label c = 1; c <= steps; ++c)
    {
        const label row = c % 2 ? 20 + (c + 1)/2 : 20 - c/2;
        if (c < steps) links.emplace_back(row, previous, 1);
        previous = row;
    }
    std::vector<scalar> extra(n, 1);
    std::vector<bool> expected(n, true);
    for (const auto& link : links) extra[std::get<0>(link)] = 0;
    extra[previous] = 0;
    links.emplace_back(previous, previous == 35 ? 5 : 35, 0);
    expected[previous] = false;

    const auto M = matrix(n, links, extra);
    expectReaches(SPH::reachesAnAnchor(M, none(n), none(n)), expected);
}


TEST(floatingRows, randomMatricesInRandomOrderAgainstAFixedPoint)
{
    std::mt19937 random(2026);
    for (label trial = 0; trial < 40; ++trial)
    {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const label n = 150;
        std::uniform_int_distribution<int> row(0, n - 1), count(0, 3);
        std::uniform_real_distribution<scalar> unit(0, 1);
        std::vector<std::tuple<int, int, scalar>> links;
        std::vector<scalar> extra(n, 0);
        boolList skip(none(n)), anchor(none(n));
        for (label i = 0; i < n; ++i)
        {
            for (int k = count(random); k > 0; --k)
            {
                const int j = row(random);
                if (j != i) links.emplace_back(i, j, unit(random) < 0.1 ? 1e-42 : 1);
            }
            const scalar u = unit(random);
            if (u < 0.02) extra[i] = 0.5;
            else if (u < 0.03) anchor[i] = true;
            else if (u < 0.06) skip[i] = true;
        }

        // The plain fixed point, every row again until none changes; a link
        // counts from 1e-10 of its row's diagonal (a row of tails only
        // links by them)
        const auto M = matrix(n, links, extra);
        std::vector<scalar> diag(extra);
        for (const auto& [i, j, w] : links) diag[i] += w;
        std::vector<bool> expected(n);
        for (label i = 0; i < n; ++i)
        {
            expected[i] = !skip[i] && (anchor[i] || extra[i] > 0);
        }
        for (bool changed = true; changed;)
        {
            changed = false;
            for (const auto& [i, j, w] : links)
            {
                if (!expected[i] && !skip[i] && expected[j] && w > 1e-10*diag[i])
                {
                    expected[i] = changed = true;
                }
            }
        }
        expectReaches(SPH::reachesAnAnchor(M, skip, anchor), expected);
    }
}


// ************************************************************************* //
