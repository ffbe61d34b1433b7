/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::domain: wrap() exact inside and at the seam (x = max, x = min -
    1e-17, -0.0, several periods out), minimum-image separation and image,
    the escape check in the non-periodic directions only and open sides
    (openSides) that bound nothing, construction from sphMeshDict's
    periodic and openSides entries and their errors, constant/sphMesh/domain
    written and read back, and the reductions.

    Tolerances: a wrap by k periods costs about k ulp of the coordinate
    (one multiply-subtract per period count), so points k periods out are
    compared to 4 (|k| + 1) ulp of the period; everything else is exact.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "domain.H"

#include <cmath>
#include <limits>
#include <ostream>
#include <random>

using namespace Foam;

namespace Foam
{
    inline void PrintTo(const vector2D& v, std::ostream* os)
    {
        *os << '(' << v.x() << ' ' << v.y() << ')';
    }
}

namespace
{
    const scalar eps = std::numeric_limits<scalar>::epsilon();

    //- Same bits (tells -0.0 from 0.0)
    bool sameBits(const scalar a, const scalar b)
    {
        return std::signbit(a) == std::signbit(b) && (a == b || (a != a && b != b));
    }

    bool insideHalfOpen(const SPH::domain& dom, const vector2D& x)
    {
        for (direction d = 0; d < 2; ++d)
        {
            if (dom.periodic(d) && !(x[d] >= dom.min()[d] && x[d] < dom.max()[d]))
            {
                return false;
            }
        }
        return true;
    }

    //- A channel periodic in x on [0, 1), walls bounding y to [0, 1]
    SPH::domain channel()
    {
        return SPH::domain(vector2D(0, 0), vector2D(1, 1), {true, false});
    }

    //- Walls' bounds used when constructing from a dictionary
    const vector2D wallsMin(-0.25, 0);
    const vector2D wallsMax(1.25, 0.5);
}


TEST(domain, wrapLeavesPointsInsideBitForBit)
{
    const SPH::domain dom(vector2D(-0.3, 0.1), vector2D(0.7, 0.6), {true, true});
    std::mt19937 gen(11);
    std::uniform_real_distribution<scalar> ux(-0.3, 0.7), uy(0.1, 0.6);
    for (label i = 0; i < 10000; ++i)
    {
        const vector2D x(ux(gen), uy(gen));
        const vector2D w(dom.wrap(x));
        ASSERT_TRUE(sameBits(w.x(), x.x()) && sameBits(w.y(), x.y())) << x.x();
    }
    // The lower corner itself, and the last double below the upper one
    EXPECT_EQ(dom.wrap(dom.min()), dom.min());
    const vector2D below
    (
        std::nextafter(0.7, 0.0),
        std::nextafter(0.6, 0.0)
    );
    EXPECT_EQ(dom.wrap(below), below);
}


TEST(domain, wrapAtTheSeamIsTheSeamsPointInTheBox)
{
    const SPH::domain dom(channel());

    // x = max is the image of x = min
    EXPECT_EQ(dom.wrap(vector2D(1, 0.5)).x(), 0);

    // min - 1e-17 + 1 rounds to 1 = max, outside [min, max): the seam is min
    const vector2D w(dom.wrap(vector2D(-1e-17, 0.5)));
    EXPECT_EQ(w.x(), 0);
    EXPECT_TRUE(insideHalfOpen(dom, w));

    // -0.0 is inside [0, 1): returned as it is, sign bit and all
    const vector2D z(dom.wrap(vector2D(-0.0, 0.5)));
    EXPECT_TRUE(sameBits(z.x(), -0.0));
    EXPECT_TRUE(insideHalfOpen(dom, z));

    // The smallest step below min wraps to the last double below max
    const scalar tiny = std::numeric_limits<scalar>::denorm_min();
    const vector2D t(dom.wrap(vector2D(-tiny, 0.5)));
    EXPECT_TRUE(insideHalfOpen(dom, t)) << t.x();

    // A box whose period is not exact in binary: 1.1 - 0.1 is not 1, and
    // max - period lands below min
    const SPH::domain odd(vector2D(0.1, 0), vector2D(1.1, 1), {true, false});
    for
    (
        const scalar x :
        {1.1, 0.1 - 1e-17, std::nextafter(0.1, 0.0), 1.1 + 1e-16, 2.1, -0.9, -1.9}
    )
    {
        const vector2D wx(odd.wrap(vector2D(x, 0.5)));
        EXPECT_TRUE(insideHalfOpen(odd, wx)) << x << " -> " << wx.x();
        EXPECT_LT(mag(odd.separation(wx, vector2D(0.1, 0.5)).x()), 8*eps) << x;
    }
}


TEST(domain, wrapBringsBackPointsSeveralPeriodsOut)
{
    const SPH::domain dom(vector2D(-0.3, 0.1), vector2D(0.7, 0.6), {true, true});
    const vector2D L(dom.period());
    for (label k = -7; k <= 7; ++k)
    {
        for (const scalar x : {-0.3, -0.1, 0.25, 0.6999})
        {
            const vector2D p(x + k*L.x(), 0.35 - k*L.y());
            const vector2D w(dom.wrap(p));
            EXPECT_TRUE(insideHalfOpen(dom, w)) << k << ' ' << x;
            EXPECT_NEAR(w.x(), x, 4*(mag(k) + 1)*eps*L.x()) << k << ' ' << x;
            EXPECT_NEAR(w.y(), 0.35, 4*(mag(k) + 1)*eps) << k;
        }
    }
    // Wrapping is idempotent
    const vector2D w(dom.wrap(vector2D(13.37, -4.2)));
    EXPECT_EQ(dom.wrap(w), w);
}


TEST(domain, wrapMovesOnlyPeriodicDirections)
{
    const SPH::domain dom(channel());
    const vector2D w(dom.wrap(vector2D(2.25, 7.5)));
    EXPECT_EQ(w, vector2D(0.25, 7.5));

    const SPH::domain none(vector2D(0, 0), vector2D(1, 1));
    EXPECT_EQ(none.wrap(vector2D(-3.5, 9)), vector2D(-3.5, 9));
    EXPECT_FALSE(none.anyPeriodic());
    EXPECT_EQ(none.period(), vector2D::zero);
}


TEST(domain, wrapKeepsNaN)
{
    const SPH::domain dom(channel());
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_TRUE(std::isnan(dom.wrap(vector2D(nan, 0.5)).x()));
    EXPECT_FALSE(std::isfinite(dom.wrap(vector2D(HUGE_VAL, 0.5)).x()));
}


TEST(domain, separationIsTheMinimumImage)
{
    const SPH::domain dom(channel());

    // Through the seam: 0.01 and 0.99 are 0.02 apart
    const vector2D d(dom.separation(vector2D(0.01, 0.5), vector2D(0.99, 0.5)));
    EXPECT_NEAR(d.x(), 0.02, 2*eps);
    EXPECT_EQ(d.y(), 0);
    EXPECT_NEAR(dom.separation(vector2D(0.99, 0.5), vector2D(0.01, 0.5)).x(), -0.02, 2*eps);

    // Unwrapped inputs, several periods apart
    EXPECT_NEAR(dom.separation(vector2D(3.01, 0), vector2D(-1.99, 0)).x(), 0, 8*eps);
    EXPECT_NEAR(dom.separation(vector2D(0.2, 0), vector2D(-4.1, 0)).x(), 0.3, 8*eps);

    // Already the shortest: a - b to the bit; the non-periodic y is never
    // shortened
    const vector2D a(0.3, 0.9), b(0.1 + 1e-3, 0.05);
    EXPECT_EQ(dom.separation(a, b), a - b);
    EXPECT_EQ(dom.separation(vector2D(0, 5), vector2D(0, -5)).y(), 10);

    // At the seam itself: max and min are the same point
    EXPECT_EQ(dom.separation(vector2D(1, 0.5), vector2D(0, 0.5)).x(), 0);
    EXPECT_LE(mag(dom.separation(vector2D(-1e-17, 0.5), vector2D(0, 0.5)).x()), 1e-17);
    EXPECT_EQ(dom.separation(vector2D(-0.0, 0.5), vector2D(0, 0.5)).x(), 0);

    // |component| <= period/2 for any pair
    std::mt19937 gen(5);
    std::uniform_real_distribution<scalar> u(-3, 3);
    for (label i = 0; i < 1000; ++i)
    {
        const vector2D s(dom.separation(vector2D(u(gen), 0), vector2D(u(gen), 0)));
        ASSERT_LE(mag(s.x()), 0.5*(1 + 4*eps));
    }
}


TEST(domain, imageIsTheNearestCopy)
{
    const SPH::domain dom(channel());
    EXPECT_NEAR(dom.image(vector2D(0, 0.3), vector2D(0.98, 0)).x(), 1, 2*eps);
    EXPECT_NEAR(dom.image(vector2D(0.97, 0.3), vector2D(0.01, 0)).x(), -0.03, 2*eps);
    EXPECT_EQ(dom.image(vector2D(0.4, 0.3), vector2D(0.6, 7)), vector2D(0.4, 0.3));
    EXPECT_EQ(dom.image(vector2D(0.25, 0.3), vector2D(5.3, 0)).x(), 5.25);
}


TEST(domain, containsChecksTheNonPeriodicDirectionsOnly)
{
    const SPH::domain dom(channel());
    EXPECT_TRUE(dom.contains(vector2D(0.5, 0.5)));
    EXPECT_TRUE(dom.contains(vector2D(17.5, 0.5)));      // x has no outside
    EXPECT_TRUE(dom.contains(vector2D(-3, 0)));          // closed in y
    EXPECT_TRUE(dom.contains(vector2D(-3, 1)));
    EXPECT_FALSE(dom.contains(vector2D(0.5, 1 + 1e-12)));
    EXPECT_FALSE(dom.contains(vector2D(0.5, -1e-12)));
    EXPECT_FALSE(dom.contains(vector2D(0.5, std::numeric_limits<scalar>::quiet_NaN())));

    const SPH::domain both(vector2D(0, 0), vector2D(1, 1), {true, true});
    EXPECT_TRUE(both.contains(vector2D(-9, 9)));

    // grown(): room for splashes in y, x untouched
    const SPH::domain g(dom.grown(0.25));
    EXPECT_TRUE(g.contains(vector2D(0.5, 1.2)));
    EXPECT_FALSE(g.contains(vector2D(0.5, 1.3)));
    EXPECT_EQ(g.min().x(), 0);
    EXPECT_EQ(g.max().x(), 1);
    EXPECT_EQ(g.period(), dom.period());
}


TEST(domain, onSeamSeesBothSidesOfAPeriodicDirection)
{
    const SPH::domain dom(channel());
    EXPECT_TRUE(dom.onSeam(vector2D(0, 0.5), 1e-9));
    EXPECT_TRUE(dom.onSeam(vector2D(1 - 1e-12, 0.5), 1e-9));
    EXPECT_FALSE(dom.onSeam(vector2D(0.5, 0), 1e-9));     // y is not periodic
}


TEST(domain, readsThePeriodicEntryOfSphMeshDict)
{
    sphTest::throwOnFatal();

    // Periodic x from the entry, y from the walls
    const SPH::domain x
    (
        sphTest::dict("periodic { directions (x); min (0 -5); max (1 5); }"),
        wallsMin, wallsMax
    );
    EXPECT_TRUE(x.periodic(0) && !x.periodic(1));
    EXPECT_EQ(x.min(), vector2D(0, 0));
    EXPECT_EQ(x.max(), vector2D(1, 0.5));
    EXPECT_EQ(x.period(), vector2D(1, 0));

    // A single word, and both directions
    const SPH::domain y
    (
        sphTest::dict("periodic { directions y; min (0 -1); max (1 2); }"),
        wallsMin, wallsMax
    );
    EXPECT_TRUE(!y.periodic(0) && y.periodic(1));
    EXPECT_EQ(y.min(), vector2D(-0.25, -1));
    EXPECT_EQ(y.period(), vector2D(0, 3));

    const SPH::domain xy
    (
        sphTest::dict("periodic { directions (x y); min (0 0); max (2 3); }"),
        wallsMin, wallsMax
    );
    EXPECT_EQ(xy.directionNames(), wordList({"x", "y"}));
    EXPECT_EQ(xy.period(), vector2D(2, 3));

    // No entry: not periodic, the walls' box
    const SPH::domain none(sphTest::dict("dr 0.1;"), wallsMin, wallsMax);
    EXPECT_FALSE(none.anyPeriodic());
    EXPECT_EQ(none.min(), wallsMin);
    EXPECT_EQ(none.max(), wallsMax);
}


TEST(domain, badPeriodicEntriesAreFatalIOErrors)
{
    sphTest::throwOnFatal();
    auto message = [](const std::string& text)
    {
        try
        {
            SPH::domain(sphTest::dict(text), wallsMin, wallsMax);
        }
        catch (const Foam::error& e)
        {
            return std::string(e.message());
        }
        return std::string();
    };

    const std::string z(message("periodic { directions (z); min (0 0); max (1 1); }"));
    EXPECT_NE(z.find("Unknown periodic direction 'z'"), std::string::npos) << z;
    EXPECT_NE(z.find("x and y"), std::string::npos) << z;

    const std::string empty(message("periodic { directions (); min (0 0); max (1 1); }"));
    EXPECT_NE(empty.find("names no direction"), std::string::npos) << empty;

    const std::string flat(message("periodic { directions (x); min (1 0); max (1 1); }"));
    EXPECT_NE(flat.find("expected max > min"), std::string::npos) << flat;

    const std::string missing(message("periodic { directions (x); min (0 0); }"));
    EXPECT_NE(missing.find("max"), std::string::npos) << missing;

    // Not silently ignored when it is not a dictionary
    const std::string word(message("periodic (x);"));
    EXPECT_NE(word.find("must be a dictionary"), std::string::npos) << word;
}


TEST(domain, writtenToConstantSphMeshAndReadBack)
{
    sphTest::throwOnFatal();
    const fileName dir = sphTest::makeCase("domainReadBack");
    auto runTime = sphTest::makeTime(dir);

    // Before sphMesh wrote it: the walls' box, not periodic
    const SPH::domain before(*runTime, wallsMin, wallsMax);
    EXPECT_FALSE(before.anyPeriodic());
    EXPECT_EQ(before.min(), wallsMin);

    const SPH::domain dom(vector2D(0, -0.5), vector2D(1.5, 2), {true, false});
    dom.write(*runTime);
    ASSERT_TRUE(isFile(dir/"constant"/"sphMesh"/"domain"));

    // Every component read back; the walls' bounds no longer matter
    const SPH::domain back(*runTime, vector2D(-9, -9), vector2D(9, 9));
    EXPECT_EQ(back.periodic(), dom.periodic());
    EXPECT_EQ(back.min(), dom.min());
    EXPECT_EQ(back.max(), dom.max());
    EXPECT_EQ(back.period(), dom.period());

    // Not periodic: written as directions ()
    SPH::domain(vector2D(0, 0), vector2D(1, 1)).write(*runTime);
    const SPH::domain flat(*runTime, wallsMin, wallsMax);
    EXPECT_FALSE(flat.anyPeriodic());
    EXPECT_EQ(flat.max(), vector2D(1, 1));
}


TEST(domain, anOpenSideBoundsNothing)
{
    // The wheel's channel: periodic in x, open above (yMax)
    const SPH::domain dom
    (
        vector2D(0, 0), vector2D(4, 2.9), {true, false},
        {false, false, false, true}
    );
    EXPECT_TRUE(dom.anyOpen());
    EXPECT_EQ(dom.openSideNames(), wordList({"yMax"}));
    EXPECT_TRUE(dom.contains(vector2D(1, 2.9)));
    EXPECT_TRUE(dom.contains(vector2D(1, 2.9 + 1e-12)));   // beyond yMax: inside
    EXPECT_TRUE(dom.contains(vector2D(1, 1e6)));
    EXPECT_FALSE(dom.contains(vector2D(1, -1e-12)));       // yMin is closed
    EXPECT_FALSE(dom.contains(vector2D(1, std::numeric_limits<scalar>::quiet_NaN())));
    EXPECT_FALSE(dom.contains(vector2D(1, std::numeric_limits<scalar>::infinity())));

    EXPECT_EQ(dom.beyondOpenSide(vector2D(1, 2.9)), -1);
    EXPECT_EQ(dom.beyondOpenSide(vector2D(1, 3)), 3);
    EXPECT_EQ(dom.beyondOpenSide(vector2D(1, -3)), -1);    // closed: not "open"
    EXPECT_EQ(word(SPH::domain::sideNames[3]), "yMax");

    // grown() keeps the sides open; a box without open sides has none
    const SPH::domain g(dom.grown(0.5));
    EXPECT_EQ(g.openSides(), dom.openSides());
    EXPECT_EQ(g.beyondOpenSide(vector2D(1, 3)), -1);
    EXPECT_EQ(g.beyondOpenSide(vector2D(1, 3.5)), 3);
    EXPECT_FALSE(channel().anyOpen());
    EXPECT_EQ(channel().beyondOpenSide(vector2D(0.5, 9)), -1);
}


TEST(domain, readsOpenSidesFromSphMeshDictAndWritesThem)
{
    sphTest::throwOnFatal();
    const SPH::domain one
    (
        sphTest::dict
        (
            "periodic { directions (x); min (0 0); max (1 1); } openSides yMax;"
        ),
        wallsMin, wallsMax
    );
    EXPECT_EQ(one.openSideNames(), wordList({"yMax"}));

    const SPH::domain two
    (
        sphTest::dict("openSides (xMax yMax);"), wallsMin, wallsMax
    );
    EXPECT_EQ(two.openSideNames(), wordList({"xMax", "yMax"}));
    EXPECT_TRUE(two.contains(vector2D(99, 99)));
    EXPECT_FALSE(two.contains(vector2D(-99, 0.1)));

    const SPH::domain none(sphTest::dict("dr 0.1;"), wallsMin, wallsMax);
    EXPECT_FALSE(none.anyOpen());

    // constant/sphMesh/domain carries them to the solvers
    const fileName dir = sphTest::makeCase("domainOpenSides");
    auto runTime = sphTest::makeTime(dir);
    one.write(*runTime);
    const SPH::domain back(*runTime, vector2D(-9, -9), vector2D(9, 9));
    EXPECT_EQ(back.openSides(), one.openSides());
    EXPECT_TRUE(back.periodic(0));
}


TEST(domain, badOpenSidesAreFatalIOErrorsNamingTheEntry)
{
    sphTest::throwOnFatal();
    auto message = [](const std::string& text)
    {
        try
        {
            SPH::domain(sphTest::dict(text), wallsMin, wallsMax);
        }
        catch (const Foam::error& e)
        {
            return std::string(e.message());
        }
        return std::string();
    };

    const std::string top(message("openSides (top);"));
    EXPECT_NE(top.find("Unknown side 'top' in entry 'openSides'"), std::string::npos) << top;
    EXPECT_NE(top.find("xMin, xMax, yMin and yMax"), std::string::npos) << top;

    const std::string seam
    (
        message("periodic { directions (x); min (0 0); max (1 1); } openSides (xMax);")
    );
    EXPECT_NE(seam.find("periodic direction x"), std::string::npos) << seam;
    EXPECT_NE(seam.find("'openSides'"), std::string::npos) << seam;
}


TEST(domain, reductionsOverParticles)
{
    const SPH::domain dom(channel());
    const scalarList f({0.5, -2, 3.25, 1});
    EXPECT_EQ(dom.gSum(f), 2.75);
    EXPECT_EQ(dom.gMax(f), 3.25);
    EXPECT_EQ(dom.gMin(f), -2);

    // Empty: the identities of each reduction, so that processors without
    // particles do not change a reduced result
    const scalarList none;
    EXPECT_EQ(dom.gSum(none), 0);
    EXPECT_EQ(dom.gMax(none), -VGREAT);
    EXPECT_EQ(dom.gMin(none), VGREAT);
}


// ************************************************************************* //
