/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    verletList: after the points moved (less than half the skin, or more),
    the list it gives equals a fresh cell-list build at the new positions
    bit for bit (indices in the same order, rij and r), in a box and in a
    periodic one; it searches again only when the skin is used up.

\*---------------------------------------------------------------------------*/

#include "neighbourTestTools.H"
#include "verletList.H"

#include <gtest/gtest.h>
#include <random>

using namespace Foam;
using namespace neighbourTest;

namespace
{
    const vector2D lo(-0.5, 0.0);
    const vector2D hi(0.5, 0.6);
    const scalar radius = 0.06;
    const scalar skin = 0.2*0.03;

    //- Every point moved by a random step of at most maxStep
    void jiggle(List<vector2D>& x, const scalar maxStep, const unsigned seed)
    {
        std::mt19937_64 gen(seed);
        std::uniform_real_distribution<scalar> u(-1, 1);
        for (vector2D& p : x)
        {
            p += maxStep/std::sqrt(2.0)*vector2D(u(gen), u(gen));
        }
    }

    //- The same pairs, order and geometry, to the last bit
    void expectIdentical
    (
        const SPH::neighbourList& a,
        const SPH::neighbourList& b
    )
    {
        ASSERT_EQ(a.size(), b.size());
        ASSERT_EQ(a.nPairs(), b.nPairs());
        for (label i = 0; i <= a.size(); ++i)
        {
            ASSERT_EQ(a.offsets()[i], b.offsets()[i]) << "target " << i;
        }
        for (label k = 0; k < a.nPairs(); ++k)
        {
            ASSERT_EQ(a.indices()[k], b.indices()[k]) << "pair " << k;
            ASSERT_EQ(a.rij()[k].x(), b.rij()[k].x()) << "pair " << k;
            ASSERT_EQ(a.rij()[k].y(), b.rij()[k].y()) << "pair " << k;
            ASSERT_EQ(a.r()[k], b.r()[k]) << "pair " << k;
        }
    }

    void checkAgainstBuilds(const FixedList<bool, 2>& periodic)
    {
        List<vector2D> x(randomPoints(3000, lo, hi));
        SPH::cellLinkedList cells(lo, hi, radius, periodic);
        SPH::cellLinkedList fresh(lo, hi, radius, periodic);
        SPH::verletList verlet(skin);
        SPH::neighbourList nbrs(true), built(true);

        EXPECT_TRUE(verlet.update(cells, x, radius, nbrs));
        fresh.build(x);
        built.build(fresh, x, radius, true);
        expectIdentical(nbrs, built);

        // Small steps (a quarter of the skin in all): no search
        for (unsigned step = 0; step < 4; ++step)
        {
            jiggle(x, skin/16, step);
            EXPECT_FALSE(verlet.update(cells, x, radius, nbrs));
            fresh.build(x);
            built.build(fresh, x, radius, true);
            expectIdentical(nbrs, built);
        }
        EXPECT_EQ(verlet.nBuilds(), 1);

        // One step beyond half the skin: a search
        jiggle(x, 2*skin, 99);
        EXPECT_TRUE(verlet.update(cells, x, radius, nbrs));
        fresh.build(x);
        built.build(fresh, x, radius, true);
        expectIdentical(nbrs, built);
        EXPECT_EQ(verlet.nBuilds(), 2);
    }
}


TEST(verletList, equalsFreshBuildInABox)
{
    throwFatalErrors();
    checkAgainstBuilds({false, false});
}


TEST(verletList, equalsFreshBuildWhenPeriodic)
{
    throwFatalErrors();
    checkAgainstBuilds({true, true});
}


TEST(verletList, zeroSkinBuildsEveryTime)
{
    throwFatalErrors();
    List<vector2D> x(randomPoints(500, lo, hi));
    SPH::cellLinkedList cells(lo, hi, radius);
    SPH::verletList verlet(0);
    SPH::neighbourList nbrs(true);
    EXPECT_TRUE(verlet.update(cells, x, radius, nbrs));
    EXPECT_TRUE(verlet.update(cells, x, radius, nbrs));
    EXPECT_EQ(verlet.nBuilds(), 2);
}


// ************************************************************************* //
