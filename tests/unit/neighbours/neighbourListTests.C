/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    neighbourList: CSR lists equal to the brute-force neighbour sets, stored
    geometry equal to the separations, and the same arrays for any number
    of threads.

\*---------------------------------------------------------------------------*/

#include "neighbourTestTools.H"
#include "neighbourList.H"
#include "openMPThreshold.H"

#include <gtest/gtest.h>
#include <omp.h>

using namespace Foam;
using namespace neighbourTest;

namespace
{
    const vector2D lo(-0.5, 0.0);
    const vector2D hi(0.5, 0.6);
    const scalar radius = 0.06;

    class neighbourListTest : public ::testing::Test
    {
    protected:
        List<vector2D> pts_;

        void SetUp() override
        {
            throwFatalErrors();
            pts_ = randomPoints(2000, lo, hi);
        }

        //- Neighbour indices of target i, sorted
        static std::vector<label> listed(const SPH::neighbourList& nl, const label i)
        {
            std::vector<label> js
            (
                nl.indices().cdata() + nl.offsets()[i],
                nl.indices().cdata() + nl.offsets()[i + 1]
            );
            std::sort(js.begin(), js.end());
            return js;
        }
    };
}


TEST_F(neighbourListTest, matchesBruteForceWithSelfExcluded)
{
    SPH::cellLinkedList cells(lo, hi, radius, {true, false});
    cells.build(pts_);
    SPH::neighbourList nl;
    nl.build(cells, pts_, radius, true);

    ASSERT_EQ(nl.size(), pts_.size());
    label nPairs = 0;
    forAll(pts_, i)
    {
        std::vector<label> expect
        (
            indices(bruteForce(pts_[i], pts_, radius, periodOf(cells)))
        );
        expect.erase(std::find(expect.begin(), expect.end(), i));
        ASSERT_EQ(listed(nl, i), expect) << "target " << i;
        EXPECT_EQ(nl.nNeighbours(i), label(expect.size()));
        nPairs += expect.size();
    }
    EXPECT_EQ(nl.nPairs(), nPairs);
    EXPECT_GT(nPairs, 4*pts_.size());
}


TEST_F(neighbourListTest, includesSelfUnlessExcluded)
{
    SPH::cellLinkedList cells(lo, hi, radius);
    cells.build(pts_);
    SPH::neighbourList with, without;
    with.build(cells, pts_, radius, false);
    without.build(cells, pts_, radius, true);

    EXPECT_EQ(with.nPairs(), without.nPairs() + pts_.size());
    forAll(pts_, i)
    {
        const std::vector<label> js(listed(with, i));
        EXPECT_EQ(std::count(js.begin(), js.end(), i), 1);
    }
}


TEST_F(neighbourListTest, otherTargetsMatchBruteForce)
{
    // Targets that are not the stored points (e.g. probes, wall vertices)
    const List<vector2D> targets(randomPoints(300, lo - vector2D(0.1, 0.1), hi, 99));
    SPH::cellLinkedList cells(lo, hi, radius, {false, true});
    cells.build(pts_);
    SPH::neighbourList nl;
    nl.build(cells, targets, radius, false);

    ASSERT_EQ(nl.size(), targets.size());
    forAll(targets, i)
    {
        EXPECT_EQ
        (
            listed(nl, i),
            indices(bruteForce(targets[i], pts_, radius, periodOf(cells)))
        ) << "target " << i;
    }
}


TEST_F(neighbourListTest, storedGeometryIsMinimumImageSeparation)
{
    SPH::cellLinkedList cells(lo, hi, radius, {true, true});
    cells.build(pts_);
    SPH::neighbourList nl(true);
    nl.build(cells, pts_, radius, true);

    ASSERT_TRUE(nl.storesGeometry());
    ASSERT_EQ(nl.rij().size(), nl.nPairs());
    ASSERT_EQ(nl.r().size(), nl.nPairs());
    const vector2D period(periodOf(cells));
    forAll(pts_, i)
    {
        for (label k = nl.offsets()[i]; k < nl.offsets()[i + 1]; ++k)
        {
            // The same operations as the search: equal to the bit
            const label j = nl.indices()[k];
            const List<vector2D> xj({pts_[j]});
            const std::vector<hit> h(bruteForce(pts_[i], xj, radius, period));
            ASSERT_EQ(h.size(), 1u);
            EXPECT_EQ(nl.rij()[k], h[0].rij);
            EXPECT_EQ(nl.r()[k], std::sqrt(h[0].r2));
        }
    }
}


TEST_F(neighbourListTest, sameArraysForOneAndTwoThreads)
{
    // Enough points for the loops to run on 2 threads (SPH::worthThreads)
    pts_ = randomPoints(4*SPH::minParticlesPerThread, lo, hi);
    SPH::cellLinkedList cells(lo, hi, radius, {true, false});
    SPH::neighbourList one(true), two(true);

    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    cells.build(pts_);
    one.build(cells, pts_, radius, true);
    const labelList sorted1(cells.sortedIndex());

    omp_set_num_threads(2);
    ASSERT_TRUE(SPH::worthThreads(pts_.size()));
    cells.build(pts_);
    two.build(cells, pts_, radius, true);
    omp_set_num_threads(saved);

    EXPECT_EQ(labelList(cells.sortedIndex()), sorted1);
    EXPECT_EQ(labelList(one.offsets()), labelList(two.offsets()));
    EXPECT_EQ(labelList(one.indices()), labelList(two.indices()));
    EXPECT_EQ(List<vector2D>(one.rij()), List<vector2D>(two.rij()));
}


TEST_F(neighbourListTest, rebuildReusesStorage)
{
    SPH::cellLinkedList cells(lo, hi, radius);
    cells.build(pts_);
    SPH::neighbourList nl(true);
    nl.build(cells, pts_, radius, true);
    const label* data = nl.indices().cdata();

    // Fewer points, hence fewer pairs: no new allocation
    const List<vector2D> fewer(SubList<vector2D>(pts_, 1500));
    cells.build(fewer);
    nl.build(cells, fewer, radius, true);
    EXPECT_EQ(nl.indices().cdata(), data);
    EXPECT_EQ(nl.size(), 1500);
}


TEST_F(neighbourListTest, radiusBeyondHalfPeriodIsFatalError)
{
    SPH::cellLinkedList cells(lo, hi, radius, {false, true});
    cells.build(pts_);
    SPH::neighbourList nl;
    EXPECT_THROW(nl.build(cells, pts_, 0.31, true), Foam::error);
    EXPECT_NO_THROW(nl.build(cells, pts_, 0.29, true));
}


TEST_F(neighbourListTest, excludeSelfNeedsTheCellListPoints)
{
    SPH::cellLinkedList cells(lo, hi, radius);
    cells.build(pts_);
    SPH::neighbourList nl;
    const List<vector2D> other(randomPoints(10, lo, hi, 5));
    EXPECT_THROW(nl.build(cells, other, radius, true), Foam::error);
    EXPECT_NO_THROW(nl.build(cells, other, radius, false));
}


// ************************************************************************* //


TEST_F(neighbourListTest, refreshedVerletListHoldsEveryPairWithinTheRadius)
{
    // Built with radius + skin, then every point moves less than skin/2
    // (across the periodic seams too): the refreshed list still contains
    // all pairs within radius, with their new separations
    const scalar skin = 0.2*radius;
    SPH::cellLinkedList cells(lo, hi, radius + skin, {true, true});
    cells.build(pts_);
    SPH::neighbourList nl(true);
    nl.build(cells, pts_, radius + skin, true);

    List<vector2D> moved(pts_);
    const List<vector2D> dir(randomPoints(pts_.size(), vector2D(-1, -1), vector2D(1, 1)));
    forAll(moved, i)
    {
        moved[i] += 0.49*skin*dir[i]/max(mag(dir[i]), 1.0);
    }
    nl.refresh(cells, moved, moved);

    const vector2D period(periodOf(cells));
    label nWithin = 0;
    forAll(moved, i)
    {
        const std::vector<hit> truth(bruteForce(moved[i], moved, radius, period));
        std::vector<label> within;
        for (label k = nl.offsets()[i]; k < nl.offsets()[i + 1]; ++k)
        {
            if (nl.r()[k] < radius)
            {
                within.push_back(nl.indices()[k]);
            }
            EXPECT_NEAR(nl.r()[k], mag(nl.rij()[k]), 1e-15);
        }
        std::sort(within.begin(), within.end());
        std::vector<label> expected(indices(truth));
        expected.erase(std::remove(expected.begin(), expected.end(), i), expected.end());
        ASSERT_EQ(within, expected) << "target " << i;
        nWithin += within.size();
    }
    EXPECT_GT(nWithin, 10*pts_.size());
}


TEST_F(neighbourListTest, refreshNeedsStoredGeometry)
{
    SPH::cellLinkedList cells(lo, hi, radius);
    cells.build(pts_);
    SPH::neighbourList nl(false);
    nl.build(cells, pts_, radius, true);
    EXPECT_THROW(nl.refresh(cells, pts_, pts_), Foam::error);
}
