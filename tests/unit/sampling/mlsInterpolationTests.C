/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The MLS SPH interpolation of sphCompare: with the linear basis a linear
    field is reproduced exactly (to round-off) wherever three non-collinear
    particles are within reach, inside, at walls and in corners, on a
    regular lattice and on a disordered one, and a smooth field converges at
    second order; with the quadratic basis quadratic fields are exact too
    and a smooth field converges at third order. A stencil that cannot
    determine a fit falls back to the order below (two rows of particles:
    linear; one row: Shepard), and a point beyond reach has no value.

    "Exact" is to round-off: each value is a sum of ~50 terms whose weights
    come from a 3 x 3 (6 x 6) solve with a condition number below ~1e3
    (1e5), measured on these stencils, so 1e-11 (1e-10) absolute on values
    of O(10).

\*---------------------------------------------------------------------------*/

#include "samplingTestTools.H"
#include "mlsInterpolation.H"

using namespace Foam;
using namespace Foam::SPH;
using samplingTest::str;

namespace
{
    const scalar roundOff = 1e-11;

    autoPtr<kernel> wendland(const scalar dr)
    {
        return kernel::New(sphTest::dict("kernel wendlandC2; hByDr 2;"), dr);
    }

    //- Points inside, next to the walls, on the walls and in the corners
    //- of [0, 1]^2
    List<vector2D> probePoints()
    {
        return List<vector2D>
        ({
            vector2D(0.5, 0.5), vector2D(0.4133, 0.2271), vector2D(0.9, 0.75),
            vector2D(0.5, 0.0), vector2D(0.0, 0.31), vector2D(1.0, 0.6),
            vector2D(0.37, 1.0), vector2D(0, 0), vector2D(1, 1),
            vector2D(0.02, 0.98)
        });
    }
}


TEST(samplingMlsInterpolation, linearFieldIsExactOnALattice)
{
    sphTest::throwOnFatal();
    const label n = 20;
    const List<vector2D> x(samplingTest::lattice(n, 1));
    const autoPtr<kernel> W(wendland(1.0/n));

    scalarField f(x.size());
    vector2DField U(x.size());
    forAll(x, i)
    {
        f[i] = samplingTest::linear(x[i]);
        U[i] = vector2D(samplingTest::linear(x[i]), 1 - 2*x[i].x() + 4*x[i].y());
    }

    mlsInterpolation interp(x, scalarField(x.size(), 1.0), identity(x.size()), *W);
    const List<vector2D> pts(probePoints());
    const mlsInterpolation::stencils st = interp.weights(pts);
    const scalarField fi(mlsInterpolation::interpolate<scalar>(st, f));
    const vector2DField Ui(mlsInterpolation::interpolate<vector2D>(st, U));

    forAll(pts, i)
    {
        EXPECT_EQ(st.status[i], mlsInterpolation::pointStatus::linear) << str(pts[i]);
        EXPECT_NEAR(fi[i], samplingTest::linear(pts[i]), roundOff) << str(pts[i]);
        EXPECT_NEAR(Ui[i].x(), samplingTest::linear(pts[i]), roundOff) << str(pts[i]);
        EXPECT_NEAR(Ui[i].y(), 1 - 2*pts[i].x() + 4*pts[i].y(), roundOff) << str(pts[i]);
    }
}


TEST(samplingMlsInterpolation, linearFieldIsExactOnDisorderedParticlesOfUnequalVolumes)
{
    sphTest::throwOnFatal();
    const label n = 20;
    const List<vector2D> x(samplingTest::lattice(n, 1, 0.3));
    const autoPtr<kernel> W(wendland(1.0/n));

    // Volumes as m/rho with rho varying by +-5 %
    scalarField V(x.size()), f(x.size());
    forAll(x, i)
    {
        V[i] = 1/(1000*(1 + 0.05*std::sin(17.0*i)));
        f[i] = samplingTest::linear(x[i]);
    }

    mlsInterpolation interp(x, V, identity(x.size()), *W);
    const List<vector2D> pts(probePoints());
    const mlsInterpolation::stencils st = interp.weights(pts);
    const scalarField fi(mlsInterpolation::interpolate<scalar>(st, f));

    forAll(pts, i)
    {
        EXPECT_EQ(st.status[i], mlsInterpolation::pointStatus::linear) << str(pts[i]);
        EXPECT_NEAR(fi[i], samplingTest::linear(pts[i]), roundOff) << str(pts[i]);
    }
}


TEST(samplingMlsInterpolation, onlyTheListedParticlesTakePart)
{
    sphTest::throwOnFatal();
    const label n = 20;
    const List<vector2D> x(samplingTest::lattice(n, 1));
    const autoPtr<kernel> W(wendland(1.0/n));

    // The used particles carry the linear field, the others garbage (as
    // dummy particles carry values that are not the fluid's)
    labelList used;
    scalarField f(x.size());
    forAll(x, i)
    {
        const bool use = (i % 3 != 0);
        f[i] = use ? samplingTest::linear(x[i]) : 1e6;
        if (use) used.append(i);
    }

    mlsInterpolation interp(x, scalarField(x.size(), 1.0), used, *W);
    EXPECT_EQ(interp.nParticles(), used.size());
    const List<vector2D> pts(probePoints());
    const scalarField fi
    (
        mlsInterpolation::interpolate<scalar>(interp.weights(pts), f)
    );
    forAll(pts, i)
    {
        EXPECT_NEAR(fi[i], samplingTest::linear(pts[i]), roundOff) << str(pts[i]);
    }
}


TEST(samplingMlsInterpolation, smoothFieldConvergesAtSecondOrder)
{
    sphTest::throwOnFatal();

    // The error of a linear fit is O(h^2): halving dr (and h) divides it by
    // about 4 (between 3 and 5 allows for the pre-asymptotic range)
    auto maxError = [](const label n)
    {
        const List<vector2D> x(samplingTest::lattice(n, 1, 0.2));
        const autoPtr<kernel> W(wendland(1.0/n));
        scalarField f(x.size());
        forAll(x, i) f[i] = std::sin(3*x[i].x())*std::cos(2*x[i].y());

        mlsInterpolation interp(x, scalarField(x.size(), 1.0), identity(x.size()), *W);
        const List<vector2D> pts(probePoints());
        const scalarField fi
        (
            mlsInterpolation::interpolate<scalar>(interp.weights(pts), f)
        );
        scalar e = 0;
        forAll(pts, i)
        {
            e = max(e, mag(fi[i] - std::sin(3*pts[i].x())*std::cos(2*pts[i].y())));
        }
        return e;
    };

    const scalar e1 = maxError(20), e2 = maxError(40);
    EXPECT_GT(e1/e2, 3.0) << e1 << " " << e2;
    EXPECT_LT(e1/e2, 5.5) << e1 << " " << e2;
}


TEST(samplingMlsInterpolation, quadraticFitReproducesQuadraticFieldsExactly)
{
    sphTest::throwOnFatal();
    const label n = 20;
    const scalar quadOff = 1e-10;
    auto q = [](const vector2D& p)
    {
        return 1 - p.x() + 2*p.y() + 3*p.x()*p.x() - 4*p.x()*p.y() + 0.5*p.y()*p.y();
    };

    for (const scalar jitter : {0.0, 0.3})
    {
        const List<vector2D> x(samplingTest::lattice(n, 1, jitter));
        const autoPtr<kernel> W(wendland(1.0/n));
        scalarField f(x.size());
        forAll(x, i) f[i] = q(x[i]);

        mlsInterpolation interp
        (
            x, scalarField(x.size(), 1.0), identity(x.size()), *W, 2
        );
        const List<vector2D> pts(probePoints());
        const mlsInterpolation::stencils st = interp.weights(pts);
        const scalarField fi(mlsInterpolation::interpolate<scalar>(st, f));
        forAll(pts, i)
        {
            EXPECT_EQ(st.status[i], mlsInterpolation::pointStatus::quadratic)
                << str(pts[i]) << " jitter " << jitter;
            EXPECT_NEAR(fi[i], q(pts[i]), quadOff) << str(pts[i]) << " jitter " << jitter;
        }
    }
}


TEST(samplingMlsInterpolation, quadraticFitConvergesAtThirdOrder)
{
    sphTest::throwOnFatal();

    // Halving dr (and h) divides the error of a quadratic fit by about 8
    // (between 6 and 11 allows for the pre-asymptotic range)
    auto maxError = [](const label n)
    {
        const List<vector2D> x(samplingTest::lattice(n, 1, 0.2));
        const autoPtr<kernel> W(wendland(1.0/n));
        scalarField f(x.size());
        forAll(x, i) f[i] = std::sin(3*x[i].x())*std::cos(2*x[i].y());

        mlsInterpolation interp
        (
            x, scalarField(x.size(), 1.0), identity(x.size()), *W, 2
        );
        const List<vector2D> pts(probePoints());
        const scalarField fi
        (
            mlsInterpolation::interpolate<scalar>(interp.weights(pts), f)
        );
        scalar e = 0;
        forAll(pts, i)
        {
            e = max(e, mag(fi[i] - std::sin(3*pts[i].x())*std::cos(2*pts[i].y())));
        }
        return e;
    };

    const scalar e1 = maxError(20), e2 = maxError(40);
    EXPECT_GT(e1/e2, 6.0) << e1 << " " << e2;
    EXPECT_LT(e1/e2, 11.0) << e1 << " " << e2;
}


TEST(samplingMlsInterpolation, twoRowsOfParticlesFallBackFromQuadraticToLinear)
{
    sphTest::throwOnFatal();
    const scalar dr = 0.05;
    const autoPtr<kernel> W(wendland(dr));

    // Two rows: a quadratic in y is not determined, a linear fit is
    List<vector2D> x(40);
    scalarField f(40);
    forAll(x, i)
    {
        x[i] = vector2D((i % 20 + 0.5)*dr, 0.5 + (i/20)*dr);
        f[i] = samplingTest::linear(x[i]);
    }

    mlsInterpolation interp(x, scalarField(x.size(), 1.0), identity(x.size()), *W, 2);
    const List<vector2D> pts({vector2D(0.5, 0.52)});
    const mlsInterpolation::stencils st = interp.weights(pts);
    EXPECT_EQ(st.status[0], mlsInterpolation::pointStatus::linear);
    EXPECT_NEAR
    (
        mlsInterpolation::interpolate<scalar>(st, f)()[0],
        samplingTest::linear(pts[0]),
        roundOff
    );
}


TEST(samplingMlsInterpolation, collinearParticlesFallBackToShepardAndFarPointsHaveNoValue)
{
    sphTest::throwOnFatal();
    const scalar dr = 0.05;
    const autoPtr<kernel> W(wendland(dr));

    // One row of particles: no slope across it
    List<vector2D> x(20);
    scalarField f(20, 3.5);
    forAll(x, i) x[i] = vector2D((i + 0.5)*dr, 0.5);

    mlsInterpolation interp(x, scalarField(x.size(), 1.0), identity(x.size()), *W);
    const List<vector2D> pts({vector2D(0.5, 0.52), vector2D(0.5, 0.9)});
    const mlsInterpolation::stencils st = interp.weights(pts);
    const scalarField fi(mlsInterpolation::interpolate<scalar>(st, f));

    EXPECT_EQ(st.status[0], mlsInterpolation::pointStatus::constant);
    EXPECT_NEAR(fi[0], 3.5, roundOff);
    EXPECT_EQ(st.count(mlsInterpolation::pointStatus::constant), 1);

    // 0.4 from the row, beyond the support 2h = 4 dr = 0.2
    EXPECT_EQ(st.status[1], mlsInterpolation::pointStatus::none);
    EXPECT_TRUE(std::isnan(fi[1]));
}


// ************************************************************************* //
