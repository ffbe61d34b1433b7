/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    cellLinkedList against an O(N^2) brute-force search: the neighbour sets
    must be identical (no tolerance: both compute rij = p - x_j with the
    same operations, so even pairs at exactly the radius must agree), and
    the separations identical too for points inside the box.

\*---------------------------------------------------------------------------*/

#include "neighbourTestTools.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace neighbourTest;

namespace
{
    //- A box, its search radius and periodicity
    struct boxCase
    {
        const char* name;
        vector2D min;
        vector2D max;
        scalar radius;
        bool periodicX;
        bool periodicY;

        SPH::cellLinkedList cells() const
        {
            return SPH::cellLinkedList
            (
                min, max, radius, {periodicX, periodicY}
            );
        }
    };

    //- Name the case in GoogleTest's messages
    void PrintTo(const boxCase& b, std::ostream* os)
    {
        *os << b.name;
    }

    //- Every query must give exactly the brute-force hits
    void expectSameAsBruteForce
    (
        const SPH::cellLinkedList& cells,
        const UList<vector2D>& pts,
        const UList<vector2D>& queries,
        const scalar radius
    )
    {
        const vector2D period(periodOf(cells));
        label nPairs = 0;
        forAll(queries, q)
        {
            const std::vector<hit> expect =
                bruteForce(queries[q], pts, radius, period);
            const std::vector<hit> found = cellSearch(cells, queries[q], radius);

            ASSERT_EQ(indices(found), indices(expect))
                << "query " << q << " at " << queries[q].x() << ' '
                << queries[q].y();
            for (size_t k = 0; k < found.size(); ++k)
            {
                EXPECT_EQ(found[k].rij, expect[k].rij) << "query " << q;
                EXPECT_EQ(found[k].r2, expect[k].r2) << "query " << q;
            }
            nPairs += found.size();
        }
        // Guard against a vacuous pass
        EXPECT_GT(nPairs, queries.size());
    }

    class cellLinkedListBoxes : public ::testing::TestWithParam<boxCase>
    {
    protected:
        void SetUp() override
        {
            throwFatalErrors();
        }
    };
}


// * * * * * * * * * * * * * * * Box parameterised * * * * * * * * * * * * * //

TEST_P(cellLinkedListBoxes, randomPointsMatchBruteForce)
{
    const boxCase& b = GetParam();
    const List<vector2D> pts(randomPoints(1500, b.min, b.max));
    SPH::cellLinkedList cells(b.cells());
    cells.build(pts);

    // Queries at the points themselves and at fresh random points
    expectSameAsBruteForce(cells, pts, pts, b.radius);
    expectSameAsBruteForce
    (
        cells, pts, randomPoints(300, b.min, b.max, 777), b.radius
    );
}


TEST_P(cellLinkedListBoxes, latticeMatchesBruteForce)
{
    // A lattice whose spacing divides the radius: many pairs at exactly the
    // radius, which rounding decides, identically in both searches
    const boxCase& b = GetParam();
    const scalar dr = b.radius/2;
    const vector2D L(b.max - b.min);
    const List<vector2D> pts
    (
        lattice
        (
            b.min + vector2D(0.5*dr, 0.5*dr), dr,
            label(L.x()/dr), label(L.y()/dr)
        )
    );
    SPH::cellLinkedList cells(b.cells());
    cells.build(pts);
    expectSameAsBruteForce(cells, pts, pts, b.radius);
}


TEST_P(cellLinkedListBoxes, pointsOnCellBordersMatchBruteForce)
{
    // Points on every cell border line (including the box edges), so that
    // the cell of a point and the reach of a query are decided by rounding
    const boxCase& b = GetParam();
    SPH::cellLinkedList cells(b.cells());
    const vector2D h(cells.cellSize());
    const label nx = cells.nCellsXY()[0];
    const label ny = cells.nCellsXY()[1];

    List<vector2D> pts;
    for (label j = 0; j <= 2*ny; ++j)
    {
        for (label i = 0; i <= 2*nx; ++i)
        {
            // Periodic edges would hold the same point twice (max == min)
            if ((b.periodicX && i == 2*nx) || (b.periodicY && j == 2*ny))
            {
                continue;
            }
            pts.append(b.min + vector2D(0.5*i*h.x(), 0.5*j*h.y()));
        }
    }
    cells.build(pts);
    expectSameAsBruteForce(cells, pts, pts, b.radius);
    // A radius of exactly one cell puts query reaches on the borders too;
    // kept below half a period, where the minimum image itself is a tie
    const scalar r = Foam::min(h.x(), 0.99*cells.maxRadius());
    expectSameAsBruteForce(cells, pts, pts, r);
}


TEST_P(cellLinkedListBoxes, sortedIndexIsCellOrderedPermutation)
{
    const boxCase& b = GetParam();
    const List<vector2D> pts(randomPoints(1000, b.min, b.max));
    SPH::cellLinkedList cells(b.cells());
    cells.build(pts);

    const labelUList& start = cells.cellStart();
    const labelUList& sorted = cells.sortedIndex();
    ASSERT_EQ(start.size(), cells.nCells() + 1);
    EXPECT_EQ(start.first(), 0);
    EXPECT_EQ(start.last(), pts.size());

    std::vector<bool> seen(pts.size(), false);
    for (label c = 0; c < cells.nCells(); ++c)
    {
        ASSERT_LE(start[c], start[c + 1]);
        for (label k = start[c]; k < start[c + 1]; ++k)
        {
            EXPECT_EQ(cells.cellIndex(pts[sorted[k]]), c);
            EXPECT_FALSE(seen[sorted[k]]);
            seen[sorted[k]] = true;
            if (k > start[c])
            {
                EXPECT_LT(sorted[k - 1], sorted[k]) << "ascending within a cell";
            }
        }
    }
}


INSTANTIATE_TEST_SUITE_P
(
    periodicities,
    cellLinkedListBoxes,
    ::testing::Values
    (
        boxCase{"nonPeriodic", {-0.3, 0.1}, {0.7, 0.6}, 0.07, false, false},
        boxCase{"periodicX", {-0.3, 0.1}, {0.7, 0.6}, 0.07, true, false},
        boxCase{"periodicY", {-0.3, 0.1}, {0.7, 0.6}, 0.07, false, true},
        boxCase{"periodicXY", {-0.3, 0.1}, {0.7, 0.6}, 0.07, true, true},
        // 0.15/0.07: two cells across the period, the tricky case
        boxCase{"twoCellsPeriodicX", {-0.3, 0.1}, {-0.15, 0.6}, 0.07, true, false},
        boxCase{"twoCellsPeriodicXY", {0, 0}, {0.15, 0.15}, 0.07, true, true},
        // Three cells: a 3-cell reach covers the whole period
        boxCase{"threeCellsPeriodicY", {0, 0}, {0.6, 0.22}, 0.07, false, true}
    ),
    [](const ::testing::TestParamInfo<boxCase>& info)
    {
        return std::string(info.param.name);
    }
);


// * * * * * * * * * * * * * * * * Single cases  * * * * * * * * * * * * * * //

namespace
{
    class cellLinkedListTest : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            throwFatalErrors();
        }
    };
}


TEST_F(cellLinkedListTest, cellsAreNoSmallerThanHalfTheRadius)
{
    // 1/0.15 = 6.67: 6 cells of 1/6; 0.5/0.15 = 3.33: 3 cells of 1/6
    SPH::cellLinkedList cells(vector2D(0, 0), vector2D(1, 0.5), 0.3);
    EXPECT_EQ(cells.nCellsXY()[0], 6);
    EXPECT_EQ(cells.nCellsXY()[1], 3);
    EXPECT_GE(cells.cellSize().x(), 0.15);
    EXPECT_GE(cells.cellSize().y(), 0.15);

    // Rounding in L/radius must never leave a cell below half the radius
    for (const scalar r : {0.1, 0.2, 0.3, 0.7, 1e-3, 1.0/3, 2.0/3})
    {
        SPH::cellLinkedList c(vector2D(-1, 0.1), vector2D(1.1, 0.8), r);
        EXPECT_GE(c.cellSize().x(), 0.5*r);
        EXPECT_GE(c.cellSize().y(), 0.5*r);
    }
}


TEST_F(cellLinkedListTest, queryOutsidePointSetMatchesBruteForce)
{
    // Points fill the middle of the box only; queries from empty parts of
    // the box and from outside it (non-periodic, and periodic where the
    // minimum image brings outside queries back)
    const vector2D lo(0, 0), hi(1, 1);
    const List<vector2D> pts(randomPoints(800, {0.3, 0.3}, {0.7, 0.7}));
    const List<vector2D> queries
    ({
        {0.25, 0.5}, {0.5, 0.74}, {0.05, 0.05}, {-0.2, 0.5}, {0.5, 1.3},
        {-5, -5}, {1e6, 0.5}, {0.72, 0.72}, {0.28, 0.71}
    });

    SPH::cellLinkedList open(lo, hi, 0.1);
    open.build(pts);
    expectSameAsBruteForce(open, pts, queries, 0.1);

    // Periodic: an outside query is wrapped before the search, so rij can
    // differ from the brute force in the last bits; compare sets and r2
    SPH::cellLinkedList periodic(lo, hi, 0.35, {true, true});
    periodic.build(pts);
    const List<vector2D> outside({{-0.6, 0.5}, {1.55, 1.5}, {0.5, -2.4}});
    for (const vector2D& q : outside)
    {
        const std::vector<hit> expect = bruteForce(q, pts, 0.35, periodOf(periodic));
        const std::vector<hit> found = cellSearch(periodic, q, 0.35);
        ASSERT_EQ(indices(found), indices(expect));
        EXPECT_FALSE(found.empty());
        for (size_t k = 0; k < found.size(); ++k)
        {
            EXPECT_NEAR(found[k].r2, expect[k].r2, 1e-14);
        }
    }
}


TEST_F(cellLinkedListTest, pairsRoundedIntoRadiusAcrossSeamAreFound)
{
    // Found by a search over rounding cases: through the periodic seam the
    // rounded separation is just inside the radius (0.6 - 0.7 =
    // -0.09999999999999998), while the cell reach of the query, 0.6 + 0.1,
    // rounds to the last cell and would not wrap to the first
    SPH::cellLinkedList x(vector2D(0, 0), vector2D(0.7, 1), 0.1, {true, false});
    const List<vector2D> ptsX({{0.0, 0.5}, {0.6, 0.5}});
    x.build(ptsX);
    expectSameAsBruteForce(x, ptsX, ptsX, 0.1);
    EXPECT_EQ(cellSearch(x, ptsX[1], 0.1).size(), 2u);

    SPH::cellLinkedList y(vector2D(0, 0), vector2D(1, 0.7), 0.1, {false, true});
    const List<vector2D> ptsY({{0.5, 0.0}, {0.5, 0.6}});
    y.build(ptsY);
    expectSameAsBruteForce(y, ptsY, ptsY, 0.1);
    EXPECT_EQ(cellSearch(y, ptsY[1], 0.1).size(), 2u);
}


TEST_F(cellLinkedListTest, pointsOutsideNonPeriodicBoxAreClampedAndFound)
{
    // Nothing is lost: points beyond the box live in its edge cells
    const List<vector2D> pts
    ({
        {0.5, 0.5}, {1.05, 0.5}, {1.02, 0.5}, {0.98, 0.52}, {1.5, 0.5},
        {-0.04, -0.04}, {0.03, 0.01}, {0.5, 7}, {1e9, -1e9}
    });
    SPH::cellLinkedList cells(vector2D(0, 0), vector2D(1, 1), 0.1);
    cells.build(pts);
    expectSameAsBruteForce(cells, pts, pts, 0.1);
    expectSameAsBruteForce(cells, pts, List<vector2D>({{1.0, 0.5}, {1.5, 0.45}}), 0.1);
    EXPECT_EQ(cells.cellStart().last(), pts.size());
}


TEST_F(cellLinkedListTest, pointsOutsidePeriodicBoxAreWrapped)
{
    const vector2D lo(0, 0), hi(1, 1);
    const List<vector2D> inside(randomPoints(400, lo, hi));
    List<vector2D> shifted(inside);
    forAll(shifted, i)
    {
        shifted[i] += vector2D(scalar(i % 5 - 2), scalar(i % 3 - 1));
    }
    SPH::cellLinkedList a(lo, hi, 0.1, {true, true});
    SPH::cellLinkedList b(lo, hi, 0.1, {true, true});
    a.build(inside);
    b.build(shifted);

    forAll(inside, i)
    {
        EXPECT_EQ
        (
            indices(cellSearch(a, inside[i], 0.1)),
            indices(cellSearch(b, inside[i], 0.1))
        );
    }
}


TEST_F(cellLinkedListTest, largerQueryRadiusMatchesBruteForce)
{
    // Radius beyond the cell size: more cells visited, same answer
    const vector2D lo(0, 0), hi(1, 1);
    const List<vector2D> pts(randomPoints(600, lo, hi));

    SPH::cellLinkedList open(lo, hi, 0.05);
    open.build(pts);
    expectSameAsBruteForce(open, pts, pts, 0.17);

    SPH::cellLinkedList periodic(lo, hi, 0.05, {true, true});
    periodic.build(pts);
    expectSameAsBruteForce(periodic, pts, pts, 0.45);
}


TEST_F(cellLinkedListTest, rebuildReusesStorage)
{
    const vector2D lo(0, 0), hi(1, 1);
    SPH::cellLinkedList cells(lo, hi, 0.1);
    cells.build(randomPoints(1000, lo, hi, 1));
    const label* indexData = cells.sortedIndex().cdata();
    const vector2D* pointData = cells.sortedPoints().cdata();

    const List<vector2D> fewer(randomPoints(900, lo, hi, 2));
    cells.build(fewer);
    EXPECT_EQ(cells.sortedIndex().cdata(), indexData);
    EXPECT_EQ(cells.sortedPoints().cdata(), pointData);
    EXPECT_EQ(cells.size(), 900);
    expectSameAsBruteForce(cells, fewer, fewer, 0.1);
}


TEST_F(cellLinkedListTest, nonFinitePositionIsFatalError)
{
    List<vector2D> pts(randomPoints(10, vector2D(0, 0), vector2D(1, 1)));
    pts[7].y() = std::nan("");
    SPH::cellLinkedList cells(vector2D(0, 0), vector2D(1, 1), 0.1);
    EXPECT_THROW(cells.build(pts), Foam::error);
}


TEST_F(cellLinkedListTest, badBoxRadiusOrPeriodIsFatalError)
{
    const vector2D lo(0, 0), hi(1, 1);
    EXPECT_THROW(SPH::cellLinkedList(hi, lo, 0.1), Foam::error);
    EXPECT_THROW(SPH::cellLinkedList(lo, hi, 0), Foam::error);

    // A period shorter than two radii: a second image could be in reach
    EXPECT_THROW
    (
        SPH::cellLinkedList(lo, vector2D(0.15, 1), 0.1, {true, false}),
        Foam::error
    );
    // ... while the same box is fine when not periodic
    EXPECT_NO_THROW(SPH::cellLinkedList(lo, vector2D(0.15, 1), 0.1));
}


// ************************************************************************* //
