/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The closed forms of one segment (wendlandC2WallIntegrals): psi of
    000_8c7cd3aabddcf18a.txt eq. (61) and the primitive chi of the kernel
    along a line (eq. (6)) against composite Gauss-Legendre quadrature of
    their defining integrals, the limits of eq. (62) and table 2, and the
    support cut-off.

    psi(q, u) = 2 q int_0^u P(Q)/Q^2 dv and chi(q, u) = int_0^u W(Q)/alpha dv
    with Q^2 = q^2 + v^2, P(Q) = (1 - Q/2)^5 (1 + 5Q/2 + 2Q^2) (h^2 times
    eq. (55) times 2 pi Q^2). For q >= 0.05 both integrands are analytic on
    [0, u] with the nearest complex singularity at v = +-i q, so 64 panels
    of 20-point Gauss-Legendre converge to round-off (~1e-15): tolerance
    1e-13 on values of order 1.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "usawTestTools.H"
#include "wendlandC2WallIntegrals.H"

using namespace Foam;
using namespace usawTest;

namespace
{
    //- Composite Gauss-Legendre of f over [0, u]
    template<class F>
    scalar compositeGL(F f, const scalar u)
    {
        std::vector<scalar> x, w;
        gaussLegendre(20, x, w);
        const label nPanels = 64;
        const scalar d = u/nPanels;
        scalar sum = 0;
        for (label p = 0; p < nPanels; ++p)
        {
            const scalar c = (p + 0.5)*d;
            for (size_t i = 0; i < x.size(); ++i)
            {
                sum += 0.5*d*w[i]*f(c + 0.5*d*x[i]);
            }
        }
        return sum;
    }

    scalar P(const scalar Q)
    {
        const scalar t = 1 - 0.5*Q;
        return t*t*t*t*t*(1 + 2.5*Q + 2*Q*Q);
    }

    scalar Wbyalpha(const scalar Q)
    {
        const scalar t = 1 - 0.5*Q;
        return t*t*t*t*(1 + 2*Q);
    }

    const std::vector<scalar> qs{0.05, 0.3, 0.77, 1.2, 1.9, 1.999};
}


TEST(wendlandC2WallIntegrals, psiOfEq61MatchesQuadratureOfEq58)
{
    using SPH::wendlandC2WallIntegrals;
    for (const scalar q : qs)
    {
        const scalar uMax = std::sqrt(4 - q*q);
        for (const scalar frac : {0.01, 0.3, 0.8, 1.0})
        {
            const scalar u = frac*uMax;
            const scalar ref = 2*q*compositeGL
            (
                [q](const scalar v)
                {
                    const scalar Q2 = q*q + v*v;
                    return P(std::sqrt(Q2))/Q2;
                },
                u
            );
            EXPECT_NEAR(wendlandC2WallIntegrals::psi(q, u), ref, 1e-13)
                << "q " << q << " u " << u;
        }
    }
}


TEST(wendlandC2WallIntegrals, chiIsTheLineIntegralOfTheKernel)
{
    using SPH::wendlandC2WallIntegrals;
    for (const scalar q : qs)
    {
        const scalar uMax = std::sqrt(4 - q*q);
        for (const scalar frac : {0.01, 0.3, 0.8, 1.0})
        {
            const scalar u = frac*uMax;
            const scalar ref = compositeGL
            (
                [q](const scalar v) { return Wbyalpha(std::sqrt(q*q + v*v)); },
                u
            );
            EXPECT_NEAR(wendlandC2WallIntegrals::chi(q, u), ref, 1e-13)
                << "q " << q << " u " << u;
        }
    }

    // On the line the integrand is a polynomial: int_0^2 = 2/3 exactly
    EXPECT_NEAR(wendlandC2WallIntegrals::chi(0, 2), 2.0/3.0, 1e-15);
}


TEST(wendlandC2WallIntegrals, onTheLineGivesEq62AndOnAnEndTable2)
{
    const scalar h = 0.2;
    const SPH::wendlandC2WallIntegrals I(h);
    scalar gt, gm;

    // Inside the segment: 1/2; the gradient is the whole line integral
    // of w, 2 (alpha/h) chi(0, 2) = 7/(3 pi h)
    ASSERT_TRUE(I.segment(0, -3*h, 3*h, pi, pi, gt, gm));
    EXPECT_NEAR(gt, 0.5, 1e-15);
    EXPECT_NEAR(gm, 7/(3*pi*h), 1e-13/h);

    // On the extension of the segment: 0 (eq. (62))
    ASSERT_TRUE(I.segment(0, 0.5*h, 3*h, pi, pi, gt, gm));
    EXPECT_NEAR(gt, 0, 1e-15);

    // On an end with fluid angle theta: (1 - theta/(2 pi))/2 (table 2),
    // whichever end it is
    for (const scalar theta : {0.5*pi, pi, 1.5*pi})
    {
        ASSERT_TRUE(I.segment(0, 0, 0.5*h, theta, 0.1, gt, gm));
        EXPECT_NEAR(gt, 0.5*(1 - theta/(2*pi)), 1e-15);
        ASSERT_TRUE(I.segment(0, -0.5*h, 0, 0.1, theta, gt, gm));
        EXPECT_NEAR(gt, 0.5*(1 - theta/(2*pi)), 1e-15);
    }
}


TEST(wendlandC2WallIntegrals, nothingBeyondTheSupport)
{
    const scalar h = 0.2;
    const SPH::wendlandC2WallIntegrals I(h);
    scalar gt = 1, gm = 1;

    // Line too far, segment beyond the circle on either side
    EXPECT_FALSE(I.segment(2*h, -h, h, pi, pi, gt, gm));
    EXPECT_EQ(gt, 0);
    EXPECT_EQ(gm, 0);
    EXPECT_FALSE(I.segment(h, std::sqrt(3.0)*h, 5*h, pi, pi, gt, gm));
    EXPECT_FALSE(I.segment(h, -5*h, -std::sqrt(3.0)*h, pi, pi, gt, gm));

    // Just inside: small but positive
    ASSERT_TRUE(I.segment(1.99*h, -h, h, pi, pi, gt, gm));
    EXPECT_GT(gt, 0);
    EXPECT_LT(gt, 1e-6);
    EXPECT_GT(gm, 0);
}


TEST(wendlandC2WallIntegrals, segmentsAddUp)
{
    // Eqs. (57) and (6) are integrals over the segment: splitting it at any
    // point must give the same sum (tests the sign(y_i) bookkeeping of
    // eq. (60) with ends on both sides of the foot of the perpendicular)
    const scalar h = 0.2;
    const SPH::wendlandC2WallIntegrals I(h);
    for (const scalar d : {-0.7*h, 0.01*h, 0.5*h, 1.5*h})
    {
        for (const scalar cut : {-0.6*h, -0.1*h, 0.0, 0.25*h, 0.9*h})
        {
            scalar gt, gm, gt1, gm1, gt2, gm2;
            I.segment(d, -1.3*h, 1.1*h, pi, pi, gt, gm);
            I.segment(d, -1.3*h, cut, pi, pi, gt1, gm1);
            I.segment(d, cut, 1.1*h, pi, pi, gt2, gm2);
            EXPECT_NEAR(gt1 + gt2, gt, 1e-14) << "d " << d << " cut " << cut;
            EXPECT_NEAR(gm1 + gm2, gm, 1e-13/h) << "d " << d << " cut " << cut;
        }
    }
}


// ************************************************************************* //
