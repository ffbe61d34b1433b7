/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The analytical wall renormalisation of usawWalls
    (000_8c7cd3aabddcf18a.txt eqs. (56)-(64), table 2, eqs. (6)-(7)):
    exact values on walls and corners, an independent brute-force
    quadrature of eq. (3) and of its gradient at random points near
    straight walls, corners of several angles, a thin plate and a narrow
    channel, central differences of gamma against grad gamma, the pair
    lists, periodic walls and the kernel check.

    All lengths are in units of h = 2 dr = 0.2; gamma is dimensionless and
    grad gamma is compared as h |grad gamma|.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "usawTestTools.H"
#include "usawWalls.H"

#include <iostream>

using namespace Foam;
using namespace usawTest;

namespace
{
    const scalar dr = 0.1;
    const scalar h = 2*dr;

    struct geometry
    {
        const char* name;
        const char* walls;
        vector2D lo, hi;    // where random points are drawn
    };

    // Walls reach far enough (or close) that the fluid is well defined in
    // every support the quadrature sees
    const geometry geometries[] =
    {
        {
            "straightWall",
            "bed { type line; points ((-2 0) (2 0)); }",
            {-0.5, 0}, {0.5, 0.45}
        },
        {
            "tankCorner",   // theta = pi/2
            "tank { type box; min (0 0); max (2 2); }",
            {0, 0}, {0.5, 0.5}
        },
        {
            "obstacleCorner",   // theta = 3 pi/2
            "block { type polygon; points ((0 0) (1 0) (1 1) (0 1));"
            " side outside; }",
            {-0.45, -0.45}, {0.45, 0.45}
        },
        {
            "wedge",    // theta = pi/3, with segments off the axes
            "wedge { type polygon; points ((0 0) (2 0) (1 1.7320508075688772)); }",
            {0, 0}, {0.5, 0.5}
        },
        {
            "thinPlate",    // solid 0.2 h thick: both faces in the support
            "plate { type polygon; points ((0 0) (1 0) (1 0.04) (0 0.04));"
            " side outside; }",
            {-0.45, -0.4}, {0.45, 0.44}
        },
        {
            "narrowChannel",    // fluid 1.5 h wide: both walls in the support
            "bottom { type line; points ((-2 0) (2 0)); }"
            " top { type line; points ((2 0.3) (-2 0.3)); }",
            {-0.5, 0}, {0.5, 0.3}
        }
    };

    class usawGeometry : public ::testing::TestWithParam<geometry>
    {
    protected:
        autoPtr<SPH::kernel> W_;
        autoPtr<SPH::wallMesh> walls_;
        autoPtr<SPH::usawWalls> usaw_;

        void SetUp() override
        {
            sphTest::throwOnFatal();
            W_ = makeKernel(dr);
            walls_.reset(new SPH::wallMesh(makeWalls(GetParam().walls, dr)));
            usaw_.reset(new SPH::usawWalls(*walls_, *W_, 0));
        }

        std::vector<vector2D> randomPoints(const label n, const unsigned seed) const
        {
            // Off the walls by at least 1e-3 h, so that the quadrature's
            // rays start in the fluid; within the support of a wall
            return pointsNearWalls
            (
                *walls_, GetParam().lo, GetParam().hi, 1e-3*h, 2*h, n, seed
            );
        }
    };

    std::string geometryName(const ::testing::TestParamInfo<geometry>& info)
    {
        return info.param.name;
    }
}


TEST_P(usawGeometry, gammaMatchesQuadratureOfEq3)
{
    // The closed forms are exact to round-off (psi and chi to ~1e-14 each,
    // see wendlandC2WallIntegralsTests), summed over at most ~20 segments;
    // the quadrature is converged to 1e-14 per radian (usawTestTools.H).
    // Tolerance 1e-11 on gamma and on h |grad gamma| (1e-6 was asked for).
    const fluidQuadrature quad(*walls_, h);
    const std::vector<vector2D> pts = randomPoints(200, 12345);
    ASSERT_EQ(pts.size(), 200u);

    scalar maxErrGamma = 0, maxErrGrad = 0, minGamma = 1;
    for (const vector2D& p : pts)
    {
        scalar g, gq;
        vector2D gg, ggq;
        usaw_->evaluate(p, g, gg);
        quad.integrate(p, gq, ggq);

        EXPECT_NEAR(g, gq, 1e-11) << "at " << p;
        EXPECT_NEAR(h*gg.x(), h*ggq.x(), 1e-11) << "at " << p;
        EXPECT_NEAR(h*gg.y(), h*ggq.y(), 1e-11) << "at " << p;
        maxErrGamma = max(maxErrGamma, mag(g - gq));
        maxErrGrad = max(maxErrGrad, h*mag(gg - ggq));
        minGamma = min(minGamma, g);
    }
    std::cout
        << "    " << GetParam().name << ": max |gamma - quadrature| = "
        << maxErrGamma << ", max h|grad gamma - quadrature| = " << maxErrGrad
        << " (min gamma " << minGamma << ")" << std::endl;
}


TEST_P(usawGeometry, gradGammaMatchesCentralDifferences)
{
    // Step e = 1e-5 h: truncation e^2 |gamma'''|/6 with h^3|gamma'''| of
    // order 10 (at most ~1e-9 in h |grad gamma|), round-off 1e-16/1e-5 =
    // 1e-11: tolerance 1e-8. Points stay 1e-3 h off the walls, so the
    // stencil never crosses one.
    const scalar e = 1e-5*h;
    const std::vector<vector2D> pts = randomPoints(200, 777);

    scalar maxErr = 0;
    for (const vector2D& p : pts)
    {
        scalar g;
        vector2D gg;
        usaw_->evaluate(p, g, gg);
        const vector2D fd
        (
            (usaw_->gammaAt(p + vector2D(e, 0)) - usaw_->gammaAt(p - vector2D(e, 0)))/(2*e),
            (usaw_->gammaAt(p + vector2D(0, e)) - usaw_->gammaAt(p - vector2D(0, e)))/(2*e)
        );
        EXPECT_NEAR(h*gg.x(), h*fd.x(), 1e-8) << "at " << p;
        EXPECT_NEAR(h*gg.y(), h*fd.y(), 1e-8) << "at " << p;
        maxErr = max(maxErr, h*mag(gg - fd));
    }
    std::cout
        << "    " << GetParam().name << ": max h|sum grad gamma_as - central"
        << " differences of gamma| = " << maxErr << std::endl;
}


TEST_P(usawGeometry, pairListsMatchPointEvaluation)
{
    // update() must give what evaluate() gives point by point, and its
    // pairs must add up to grad gamma (eq. (7)); same arithmetic, so only
    // summation order may differ: tolerance 1e-14
    const std::vector<vector2D> pts = randomPoints(300, 4242);
    usaw_->update(List<vector2D>(pts.begin(), pts.end()));

    ASSERT_EQ(usaw_->size(), label(pts.size()));
    ASSERT_EQ(usaw_->offsets().size(), label(pts.size()) + 1);

    const labelUList& off = usaw_->offsets();
    for (size_t a = 0; a < pts.size(); ++a)
    {
        scalar g;
        vector2D gg;
        usaw_->evaluate(pts[a], g, gg);
        EXPECT_NEAR(usaw_->gamma()[a], g, 1e-14);
        EXPECT_NEAR(h*mag(usaw_->gradGamma()[a] - gg), 0, 1e-14);

        vector2D sum(vector2D::zero);
        for (label k = off[a]; k < off[a + 1]; ++k)
        {
            const label s = usaw_->segments()[k];
            sum += usaw_->gradGammaAs()[k];

            // grad gamma_as is along the inward normal (eq. (6))
            const vector2D& n = usaw_->segmentNormals()[s];
            EXPECT_NEAR(mag(usaw_->gradGammaAs()[k] & vector2D(-n.y(), n.x())), 0, 1e-14/h);
            EXPECT_NEAR
            (
                usaw_->distances()[k],
                (pts[a] - usaw_->segmentCentres()[s]) & n,
                1e-14
            );
        }
        EXPECT_NEAR(h*mag(sum - usaw_->gradGamma()[a]), 0, 1e-14);
    }
}


INSTANTIATE_TEST_SUITE_P
(
    walls,
    usawGeometry,
    ::testing::ValuesIn(geometries),
    geometryName
);


TEST(usawWalls, gammaIsHalfOnAStraightWall)
{
    // Eq. (62) inside a segment, table 2 (theta = pi) on a vertex
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::wallMesh walls(makeWalls("bed { type line; points ((-2 0) (2 0)); }", dr));
    const SPH::usawWalls usaw(walls, *W, 0);

    for (const scalar x : {-0.3, -0.05, 0.0, 0.0123, 0.1, 0.25})
    {
        scalar g;
        vector2D gg;
        usaw.evaluate(vector2D(x, 0), g, gg);
        EXPECT_NEAR(g, 0.5, 1e-15) << "at x = " << x;

        // The whole line integral of w along the normal: 7/(3 pi h)
        EXPECT_NEAR(gg.x(), 0, 1e-13/h);
        EXPECT_NEAR(gg.y(), 7/(3*pi*h), 1e-13/h);
    }
}


TEST(usawWalls, gammaIsThetaOverTwoPiOnCornerVertices)
{
    // Eq. (64), table 2: a vertex particle of fluid angle theta has
    // gamma = theta/(2 pi), for pi/2 (tank), pi (straight), 3pi/2
    // (obstacle), pi/3 (equilateral wedge) and 5pi/3 (its outside)
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));

    const char* cases[] =
    {
        "tank { type box; min (0 0); max (2 2); }",
        "block { type polygon; points ((0 0) (2 0) (2 2) (0 2)); side outside; }",
        "wedge { type polygon; points ((0 0) (2 0) (1 1.7320508075688772)); }",
        "wedge { type polygon; points ((0 0) (2 0) (1 1.7320508075688772)); side outside; }"
    };
    for (const char* text : cases)
    {
        const SPH::wallMesh walls(makeWalls(text, dr));
        SPH::usawWalls usaw(walls, *W, 0);

        // The vertex particles themselves, through update()
        usaw.update(walls.points());

        // Vertices that no segment reaches but those on lines through them
        // (any other wall would add to gamma)
        label nChecked = 0;
        const scalarList& theta = walls.pointAngles();
        forAll(walls.points(), v)
        {
            const vector2D& p = walls.points()[v];
            bool alone = true;
            forAll(walls.segments(), s)
            {
                const vector2D& p1 = walls.points()[walls.segments()[s].first()];
                const vector2D& p2 = walls.points()[walls.segments()[s].second()];
                const vector2D e(p2 - p1);
                const scalar t = min(max(((p - p1) & e)/magSqr(e), 0.0), 1.0);
                const bool onLine = mag((p - p1) & walls.segmentNormals()[s]) < 1e-12;
                if (!onLine && mag(p - p1 - t*e) < 2*h)
                {
                    alone = false;
                }
            }
            if (!alone)
            {
                continue;
            }
            EXPECT_NEAR(usaw.gamma()[v], theta[v]/(2*pi), 1e-14)
                << text << " vertex " << p << " theta " << theta[v];
            ++nChecked;
        }
        EXPECT_GE(nChecked, 3) << text;
    }
}


TEST(usawWalls, gammaTendsToItsVertexValueFromAnyDirection)
{
    // gamma is continuous (eq. (3) integrates a bounded kernel), so the
    // vertex value of table 2 must be the limit of eq. (60) from every
    // direction into the fluid, not only along the bisector: at distance
    // e from the vertex |gamma - theta/(2 pi)| <= e max|grad gamma|, with
    // h max|grad gamma| < 1.5
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::wallMesh walls(makeWalls("tank { type box; min (0 0); max (2 2); }", dr));
    const SPH::usawWalls usaw(walls, *W, 0);

    for (const scalar e : {1e-3*h, 1e-6*h, 1e-8*h})
    {
        for (const scalar phi : {0.01, 0.3, 0.25*pi, 1.2, 0.5*pi - 0.01})
        {
            const vector2D p(e*std::cos(phi), e*std::sin(phi));
            EXPECT_NEAR(usaw.gammaAt(p), 0.25, 1.5*e/h + 1e-14)
                << "distance " << e << " angle " << phi;
        }
    }
}


TEST(usawWalls, gammaIsOneFarFromWalls)
{
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::wallMesh walls(makeWalls("tank { type box; min (0 0); max (2 2); }", dr));
    SPH::usawWalls usaw(walls, *W, 0);

    const List<vector2D> x({vector2D(1, 1), vector2D(0.4001, 1.5), vector2D(1.2, 1.5999)});
    usaw.update(x);
    forAll(x, a)
    {
        EXPECT_EQ(usaw.gamma()[a], 1);
        EXPECT_EQ(usaw.gradGamma()[a], vector2D::zero);
        EXPECT_EQ(usaw.offsets()[a + 1] - usaw.offsets()[a], 0);
    }
}


TEST(usawWalls, periodicWallsAreSeenAcrossThePeriod)
{
    // A channel bed periodic in x with period 1 must give the infinite
    // wall's gamma everywhere, also within 2h of x = 0 and x = 1, where
    // half the segments are reached through the periodic image
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::wallMesh bed(makeWalls("bed { type line; points ((0 0) (1 0)); }", dr));
    const SPH::wallMesh infinite(makeWalls("bed { type line; points ((-3 0) (4 0)); }", dr));
    const SPH::usawWalls periodic
    (
        bed, *W, 0, vector2D(0, -0.5), vector2D(1, 0.5), {true, false}
    );
    const SPH::usawWalls reference(infinite, *W, 0);

    for (const scalar x : {0.0, 0.013, 0.1, 0.37, 0.95, 0.999})
    {
        for (const scalar y : {0.0, 0.02, 0.15, 0.39})
        {
            const vector2D p(x, y);
            scalar g, gr;
            vector2D gg, ggr;
            periodic.evaluate(p, g, gg);
            reference.evaluate(p, gr, ggr);
            EXPECT_NEAR(g, gr, 1e-14) << "at " << p;
            EXPECT_NEAR(h*mag(gg - ggr), 0, 1e-13) << "at " << p;
        }
    }
}


TEST(usawWalls, refusesKernelsWithoutAClosedForm)
{
    sphTest::throwOnFatal();
    const autoPtr<SPH::kernel> W(makeKernel(dr, "cubicSpline"));
    const SPH::wallMesh walls(makeWalls("tank { type box; min (0 0); max (2 2); }", dr));
    EXPECT_THROW(SPH::usawWalls(walls, *W, 0), Foam::error);
}



TEST(usawWalls, holdOffPutsAParticleBackAtDMinAndFlagsIt)
{
    // A floor y = 0 from x = 0 to 2; dMin = dr/2; the particles between
    // vertices (a segment leaves its ends to its neighbours). Particle 0
    // at 0.3 dr, moving into the floor, is put back to dMin and loses its
    // velocity towards it (the along-wall part stays); particle 1 at
    // 0.7 dr is left alone; particle 2 at 0.3 dr, moving away, is put
    // back and keeps its velocity. The flags name the particles held.
    const autoPtr<SPH::kernel> W(makeKernel(dr));
    const SPH::wallMesh walls
    (
        makeWalls("floor { type line; points ((0 0) (2 0)); }", dr)
    );
    const label nFluid = 3;
    SPH::usawWalls usaw(walls, *W, nFluid);
    List<vector2D> x
    ({
        vector2D(1.05, 0.3*dr), vector2D(1.35, 0.7*dr), vector2D(0.65, 0.3*dr)
    });
    x.append(walls.points());
    List<vector2D> U(x.size(), vector2D::zero);
    U[0] = vector2D(1, -2);
    U[1] = vector2D(1, -2);
    U[2] = vector2D(1, 2);
    const List<vector2D> x0(x);
    usaw.update(x);

    labelList held(nFluid, -1);
    const scalar dMin = 0.5*dr;
    EXPECT_EQ(usaw.holdOff(x0, x, U, nFluid, dMin, &held), 2);
    EXPECT_EQ(held, labelList({1, 0, 1}));
    EXPECT_NEAR(x[0].y(), dMin, 1e-15);
    EXPECT_EQ(U[0], vector2D(1, 0));
    EXPECT_EQ(x[1], x0[1]);
    EXPECT_EQ(U[1], vector2D(1, -2));
    EXPECT_NEAR(x[2].y(), dMin, 1e-15);
    EXPECT_EQ(U[2], vector2D(1, 2));

    // Without flags the same, and the count alone
    List<vector2D> xAgain(x0), UAgain(U);
    UAgain[0] = vector2D(1, -2);
    EXPECT_EQ(usaw.holdOff(x0, xAgain, UAgain, nFluid, dMin), 2);
    EXPECT_EQ(xAgain[0], x[0]);
}


// ************************************************************************* //
