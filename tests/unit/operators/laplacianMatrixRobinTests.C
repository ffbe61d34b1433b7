/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The two terms laplacianMatrix offers the equations of a time step
    (implicit viscosity first), on the nodal lattice of the walled unit
    box with random B, Neumann data and row kinds:

    - the implicit source Sp (fvm::Sp) and the Robin walls
      dphi/dn_as = (k_s phi_a - g_s)/max(d_as, dMin) change the interior
      rows' diagonal by -Sp_a + sum_s w_as k_s and their right-hand side by
      sum_s w_as g_s, w_as = (B_s + B_a)/gamma_a |grad gamma_as|/max(d_as,
      dMin), and nothing else (every off-diagonal entry and every other
      row identical to the bit);
    - without them the matrix is the one of before (the other tests of
      laplacianMatrix, unchanged).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "laplacianMatrixTestTools.H"
#include "laplacianMatrix.H"

#include <random>

using namespace Foam;
using namespace laplacianTest;

TEST(laplacianMatrix, implicitSourceAndRobinWallsAddTheirTermsOnly)
{
    // Tolerance: the diagonal and b are sums in another order, 1e-12 of
    // their largest term; off-diagonal entries and non-interior rows are
    // the same operations, so equal to the bit
    sphTest::throwOnFatal();
    latticeCase c = boxCase(0.05);
    const label n = c.size();
    const label nSeg = c.usaw->segmentParticles().size();
    std::mt19937 gen(7);
    std::uniform_real_distribution<scalar> u(-1, 1);
    scalarList B(n), S(n), f(n), Sp(n), k(nSeg), g(nSeg);
    forAll(B, i)
    {
        B[i] = 2 + u(gen);
        S[i] = u(gen);
        f[i] = u(gen);
        Sp[i] = -10*(1 + u(gen));
    }
    forAll(k, s)
    {
        k[s] = 0.5*(1 + u(gen));
        g[s] = u(gen);
    }
    const scalar dMin = 0.7*c.dr;

    auto build = [&](SPH::laplacianMatrix& lap)
    {
        lap.coefficient(B);
        std::mt19937 kinds(3);
        forAll(lap.kinds(), i)
        {
            // Fluid rows interior, a quarter of the vertices Dirichlet
            lap.kinds()[i] =
                (i >= c.nFluid && kinds() % 4 == 0)
              ? SPH::laplacianMatrix::dirichlet
              : SPH::laplacianMatrix::interior;
        }
        lap.dirichletValues() = f;
        forAll(lap.wallFlux(), s)
        {
            lap.wallFlux()[s] = 0.1*s;
        }
    };
    SPH::laplacianMatrix plain(c.nbrs, *c.usaw, c.V, c.nFluid);
    SPH::laplacianMatrix timeStep(c.nbrs, *c.usaw, c.V, c.nFluid);
    build(plain);
    build(timeStep);
    timeStep.implicitSource(Sp);
    timeStep.robinWalls(k, g, dMin);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        plain.assemble(K, S);
        timeStep.assemble(K, S);
    });

    const SPH::sparseMatrix& A0 = plain.matrix();
    const SPH::sparseMatrix& A1 = timeStep.matrix();
    ASSERT_EQ(A0.nonZeros(), A1.nonZeros());
    const scalar* gamma = c.usaw->gamma().cdata();
    label nRobin = 0;
    for (label a = 0; a < n; ++a)
    {
        const bool interior = plain.kinds()[a] == SPH::laplacianMatrix::interior;
        scalar dDiag = 0, dB = 0, scale = mag(plain.source()[a]);
        if (interior)
        {
            dDiag = -Sp[a];
            for (label e = c.usaw->offsets()[a]; e < c.usaw->offsets()[a + 1]; ++e)
            {
                const label s = c.usaw->segments()[e];
                const labelPair& ends = c.usaw->segmentParticles()[s];
                const scalar Bs = 0.5*(B[ends.first()] + B[ends.second()]);
                const scalar w =
                    (Bs + B[a])/gamma[a]*mag(c.usaw->gradGammaAs()[e])
                   /max(c.usaw->distances()[e], dMin);
                dDiag += w*k[s];
                dB += w*g[s];
                scale = max(scale, mag(w));
                ++nRobin;
            }
        }
        SPH::sparseMatrix::InnerIterator it0(A0, a), it1(A1, a);
        for (; it0 && it1; ++it0, ++it1)
        {
            ASSERT_EQ(it0.col(), it1.col());
            if (it0.col() == a)
            {
                scale = max(scale, mag(it0.value()));
                EXPECT_NEAR(it1.value() - it0.value(), dDiag, 1e-12*scale)
                    << "diagonal of row " << a;
            }
            else
            {
                EXPECT_EQ(it1.value(), it0.value()) << "row " << a;
            }
        }
        EXPECT_NEAR(timeStep.source()[a] - plain.source()[a], dB, 1e-12*scale)
            << "right-hand side of row " << a;
    }
    EXPECT_GT(nRobin, 100) << "the rows must see the walls";
}


// ************************************************************************* //
