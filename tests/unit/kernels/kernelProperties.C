/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Mathematical properties every kernel must have, checked for each one with
    its default coefficients: normalisation, the lattice antisymmetry of its
    gradient, dW/dr against finite differences, compact support.

    Quantities are compared in units of h: W scales as 1/h^2 and dW/dr as
    1/h^3, so tolerances are written for h = 1 and multiplied accordingly.

\*---------------------------------------------------------------------------*/

#include "kernelTestTools.H"
#include "kernelDispatch.H"
#include "ghostSurface.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace Foam;

namespace
{
    const scalar eps = std::numeric_limits<scalar>::epsilon();

    // A spacing that is not a power of two, so that nothing is exact by luck
    const scalar dr = 0.013;

    class kernelProperties : public ::testing::TestWithParam<const char*>
    {
    protected:
        autoPtr<SPH::kernel> W_;

        void SetUp() override
        {
            kernelTest::throwFatalErrors();
            W_ = kernelTest::makeKernel(std::string("kernel ") + GetParam() + ";", dr);
        }

        //- max |dW/dr| over the support, sampled finely
        scalar maxAbsDWdr() const
        {
            const label n = 10000;
            scalar m = 0;
            for (label i = 0; i <= n; ++i)
            {
                m = max(m, mag(W_->dWdr(W_->support()*i/n)));
            }
            return m;
        }

        //- Composite Simpson rule of 2 pi r W(r) over [a, b], n even
        scalar simpson(const scalar a, const scalar b, const label n) const
        {
            const scalar d = (b - a)/n;
            auto f = [&](const scalar r)
            {
                return 2*constant::mathematical::pi*r*W_->W(r);
            };
            scalar sum = f(a) + f(b);
            for (label i = 1; i < n; ++i)
            {
                sum += (i % 2 ? 4 : 2)*f(a + i*d);
            }
            return sum*d/3;
        }

        //- Sum over a square lattice (spacing dr, reaching past the
        //- support) of V_b nabla_a W_ab, and of its magnitudes
        void latticeGradientSum
        (
            const vector2D& xa,
            vector2D& sum,
            scalar& sumMag,
            label& nTerms
        ) const
        {
            const label m = label(W_->support()/dr) + 2;
            const scalar V = dr*dr;
            sum = vector2D::zero;
            sumMag = 0;
            nTerms = 0;
            for (label i = -m; i <= m; ++i)
            {
                for (label j = -m; j <= m; ++j)
                {
                    const vector2D rab(xa - vector2D(i*dr, j*dr));
                    const vector2D term(V*W_->gradW(rab, mag(rab)));
                    sum += term;
                    sumMag += mag(term);
                    nTerms += (magSqr(term) > 0);
                }
            }
        }
    };
}


TEST_P(kernelProperties, integratesToOne)
{
    // A radial function's integral over the disc is 2 pi int_0^R r W(r) dr
    // exactly, so the 2-D quadrature is a 1-D one in r: composite Simpson on
    // [0, h] and [h, R] (the cubic spline's pieces join at r = h) with steps
    // of about 1e-3 h. Its error (b - a) d^4 max|f''''|/180 is below 1e-10
    // for max|f''''| <= 1e5 (in units of h; the three kernels stay far
    // below), and round-off over ~3000 terms is ~1e-13: tolerance 1e-9.
    const scalar h = W_->h();
    const scalar R = W_->support();
    const label nInner = 1000;
    const label nOuter = 2*label(std::round(500*(W_->qMax() - 1)));
    const scalar integral = simpson(0, h, nInner) + simpson(h, R, nOuter);

    EXPECT_NEAR(integral, 1, 1e-9);
}


TEST_P(kernelProperties, latticeSumIsTheWholePlanesGhostSum)
{
    // kernel::latticeSum is the ghost sum of isphFoam's free surface
    // (ghostSurface::halfPlaneSum) over the whole plane, node by node in
    // the same order: equal to the last bit. A lattice's kernel sum is a
    // quadrature of the kernel's unit integral, so near 1
    const scalar whole =
        SPH::ghostSurface::halfPlaneSum(*W_, dr, vector2D(0, 1), -GREAT);
    EXPECT_EQ(W_->latticeSum(), whole);
    std::cout << "    lattice sum " << W_->latticeSum() << std::endl;
    EXPECT_NEAR(W_->latticeSum(), 1, 0.002);   // measured 1.00121, 0.999947, 1.00018
}


TEST_P(kernelProperties, gradientSumsToZeroOnLattice)
{
    // On a full lattice every b has a mirror image b' with r_ab' = -r_ab, so
    // the sum cancels exactly in exact arithmetic; both at a lattice point
    // and at a cell centre (mirror x -> dr - x). Floating point leaves
    // rounding of a few ulp per term plus the recursive-summation error
    // (N - 1) eps sum|terms|: tolerance (N + 10) eps sum|terms|.
    for (const vector2D& xa : {vector2D(0, 0), vector2D(0.5*dr, 0.5*dr)})
    {
        vector2D sum;
        scalar sumMag;
        label n;
        latticeGradientSum(xa, sum, sumMag, n);

        ASSERT_GT(n, 8) << "the lattice must reach into the support";
        const scalar tol = (n + 10)*eps*sumMag;
        EXPECT_LE(mag(sum.x()), tol) << "at " << xa.x() << " " << xa.y();
        EXPECT_LE(mag(sum.y()), tol) << "at " << xa.x() << " " << xa.y();
    }
}


TEST_P(kernelProperties, dWdrMatchesCentralDifferences)
{
    // Central difference with step d = 1e-4 h: truncation d^2 max|W'''|/6,
    // round-off ~ eps max|W|/d. For h = 1 max|W'''| is 8.4 (wendlandC2),
    // 2.0 (cubicSpline), 1.2 (modifiedGaussian) and max|W| < 0.6, so the
    // error is below 1.5e-8 + 1.4e-12: tolerance 2e-8/h^3. The modified
    // Gaussian's derivative jumps at q = k, so stay 0.01 h inside.
    const scalar h = W_->h();
    const scalar d = 1e-4*h;
    const scalar tol = 2e-8/(h*h*h);
    const label n = 400;

    for (label i = 1; i < n; ++i)
    {
        const scalar r = (W_->support() - 0.01*h)*i/n;
        const scalar fd = (W_->W(r + d) - W_->W(r - d))/(2*d);
        EXPECT_NEAR(W_->dWdr(r), fd, tol) << "at q = " << r/h;
    }
}


TEST_P(kernelProperties, dWdrIsNonPositive)
{
    const label n = 10000;
    for (label i = 0; i <= n + 100; ++i)
    {
        const scalar r = W_->support()*i/n;
        EXPECT_LE(W_->dWdr(r), 0) << "at q = " << r/W_->h();
    }
}


TEST_P(kernelProperties, vanishesAtAndBeyondSupport)
{
    const scalar R = W_->support();
    for (const scalar r : {R, R*(1 + 1e-12), 1.5*R, 10*R})
    {
        EXPECT_EQ(W_->W(r), 0) << "at r/R = " << r/R;
        EXPECT_EQ(W_->dWdr(r), 0) << "at r/R = " << r/R;
        EXPECT_EQ(W_->gradW(vector2D(r, 0), r), vector2D::zero);
    }
}


TEST_P(kernelProperties, continuousAtSupportEdge)
{
    // W(R) = 0, so by the mean value theorem |W(R - d)| <= d max|dW/dr|;
    // a jump at the edge would break this for small d
    const scalar R = W_->support();
    const scalar bound = maxAbsDWdr();
    for (const scalar d : {1e-3*R, 1e-6*R, 1e-9*R})
    {
        EXPECT_GE(W_->W(R - d), 0);
        EXPECT_LE(W_->W(R - d), d*bound*(1 + 1e-12)) << "at d/R = " << d/R;
    }
}


TEST_P(kernelProperties, gradWVanishesAtZeroDistance)
{
    EXPECT_EQ(W_->dWdr(0), 0);
    EXPECT_EQ(W_->gradW(vector2D::zero, 0), vector2D::zero);
    SPH::dispatch(*W_, [](const auto& K)
    {
        EXPECT_EQ(K.gradW(vector2D::zero, 0), vector2D::zero);
    });
}


TEST_P(kernelProperties, gradWPointsFromBToA)
{
    // nabla_a W_ab = W'(r) r_ab/r with W' <= 0: it points from a to b,
    // i.e. against r_ab = r_a - r_b, with magnitude |W'|
    const vector2D rab(0.3*dr, -0.4*dr);
    const scalar r = mag(rab);
    const vector2D g(W_->gradW(rab, r));
    EXPECT_LT(g & rab, 0);
    EXPECT_NEAR(mag(g), mag(W_->dWdr(r)), 1e-14*mag(W_->dWdr(r)));
}


TEST_P(kernelProperties, inlineMembersMatchVirtualOnes)
{
    // The templated hot-loop path (dispatch + inline members) must give the
    // same numbers as the virtual interface: same formulas, so to 4 ulp
    SPH::dispatch(*W_, [&](const auto& K)
    {
        const label n = 200;
        for (label i = 0; i <= n; ++i)
        {
            const scalar r = 1.1*K.support()*i/n;
            const vector2D rab(0.6*r, 0.8*r);
            const SPH::kernel& base = K;
            EXPECT_EQ(K.W(r), base.W(r));
            EXPECT_EQ(K.dWdr(r), base.dWdr(r));
            const vector2D gInline(K.gradW(rab, r));
            const vector2D gVirtual(base.gradW(rab, r));
            const scalar tol = 4*eps*mag(gVirtual);
            EXPECT_NEAR(gInline.x(), gVirtual.x(), tol);
            EXPECT_NEAR(gInline.y(), gVirtual.y(), tol);
        }
    });
}


TEST_P(kernelProperties, valueAtOriginIsTheNormalisation)
{
    // wendlandC2: 7/(4 pi h^2) (000_8c7c... eq. (1)); cubicSpline:
    // 10/(7 pi h^2); modifiedGaussian (004_f29... eq. (5), k = 3):
    // (1 - e^{-9})/(2 pi h^2 I(3)), I(3) = (1 - e^{-9})/2 - 9 e^{-9}/2
    const scalar pi = constant::mathematical::pi;
    const scalar h2 = sqr(W_->h());
    const word name(GetParam());
    scalar expected = 0;
    if (name == "wendlandC2")
    {
        expected = 7/(4*pi*h2);
    }
    else if (name == "cubicSpline")
    {
        expected = 10/(7*pi*h2);
    }
    else
    {
        const scalar e9 = std::exp(-9.0);
        expected = (1 - e9)/(2*pi*h2*(0.5*(1 - e9) - 4.5*e9));
    }
    EXPECT_NEAR(W_->W(0), expected, 1e-14*expected);
}


INSTANTIATE_TEST_SUITE_P
(
    allKernels,
    kernelProperties,
    ::testing::Values("wendlandC2", "cubicSpline", "modifiedGaussian"),
    [](const ::testing::TestParamInfo<const char*>& info)
    {
        return std::string(info.param);
    }
);


// ************************************************************************* //
