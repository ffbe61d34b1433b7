/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The implicit USAW Laplacian of src/sph/operators/laplacianMatrix
    (Leroy et al. 2014, eqs. (10), (40)) on regular lattices in a walled
    box:

    - applied to a field, the matrix and its right-hand side give the
      explicit operator usaw::laplacian, for both wall forms and a variable
      B, to round-off;
    - a variable coefficient: away from the walls the matrix gives
      div(B grad phi) of a quadratic phi and a linear B up to the lattice's
      kernel moment alone;
    - Dirichlet rows are identity rows with s f in the right-hand side,
      and their columns move to the other rows' right-hand sides; extension
      and copy rows continue the field;
    - Poisson problems: laplacianMatrixPoissonTests.C.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "laplacianMatrixTestTools.H"
#include "laplacianMatrix.H"
#include "usawOperators.H"

#include <iostream>
#include <random>

using namespace Foam;
using namespace laplacianTest;

namespace
{
    SPH::vectorN toVector(const scalarUList& f)
    {
        SPH::vectorN v(f.size());
        forAll(f, i)
        {
            v[i] = f[i];
        }
        return v;
    }

    //- L_a{phi} = b_a - (A phi)_a when S = 0: what the rows say phi's
    //- Laplacian is
    SPH::vectorN appliedLaplacian
    (
        const SPH::laplacianMatrix& lap,
        const scalarUList& phi
    )
    {
        return lap.source() - lap.matrix()*toVector(phi);
    }

    //- Largest |pair term| of the rows, the scale of their round-off
    scalar rowScale(const SPH::sparseMatrix& A, const scalarUList& phi)
    {
        scalar s = 0;
        for (int i = 0; i < A.outerSize(); ++i)
        {
            for (SPH::sparseMatrix::InnerIterator it(A, i); it; ++it)
            {
                s = max(s, mag(it.value()*phi[it.col()]));
            }
        }
        return s;
    }
}


// * * * * * * * * * * * * The matrix is the operator  * * * * * * * * * * * //

TEST(laplacianMatrix, appliedToAFieldIsTheExplicitOperator)
{
    // All rows interior and S = 0: b - A phi is L{B, phi} with the wall
    // data in b. The same sums as usaw::laplacian in another order, so
    // round-off only: 1e-11 of the largest pair term. Random phi, B and
    // Neumann data, the nodal lattice (vertex particles with volume).
    sphTest::throwOnFatal();
    latticeCase c = boxCase(0.05);
    const label n = c.size();
    std::mt19937 gen(3);
    std::uniform_real_distribution<scalar> u(-1, 1);
    scalarList phi(n), B(n), zero(n, Zero);
    forAll(phi, i)
    {
        phi[i] = u(gen);
        B[i] = 2 + u(gen);
    }

    SPH::laplacianMatrix lap(c.nbrs, *c.usaw, c.V, c.nFluid);
    for (scalar& g : lap.wallFlux())
    {
        g = u(gen);
    }
    lap.coefficient(B);

    // Eq. (10) with (grad phi)_a . n_s = dphi/dn_s
    scalarList explicitL(n);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        lap.assemble(K, zero);
        SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, B, phi, lap.wallFlux(), explicitL);
    });
    SPH::vectorN implicitL(appliedLaplacian(lap, phi));
    scalar tol = 1e-11*rowScale(lap.matrix(), phi);
    for (label a = 0; a < n; ++a)
    {
        EXPECT_NEAR(implicitL[a], explicitL[a], tol) << "eq. (10), (40) form, particle " << a;
    }

    // Eq. (10) as printed at the fluid particles: (grad phi)_a = R G-{phi}
    List<tensor2D> R(n);
    List<vector2D> gradPhi(n);
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::renormalisation(K, c.nbrs, *c.usaw, c.V, c.x, 1e-6, R);
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, R, phi, gradPhi);
        lap.ownGradient(R);
        lap.assemble(K, zero);
        SPH::usaw::laplacian
        (
            K, c.nbrs, *c.usaw, c.V, B, phi, lap.wallFlux(), gradPhi, explicitL
        );
    });
    implicitL = appliedLaplacian(lap, phi);
    tol = 1e-11*rowScale(lap.matrix(), phi);
    label nWall = 0;
    for (label a = 0; a < c.nFluid; ++a)
    {
        nWall += c.usaw->offsets()[a + 1] > c.usaw->offsets()[a];
        EXPECT_NEAR(implicitL[a], explicitL[a], tol) << "eq. (10), particle " << a;
    }
    EXPECT_GT(nWall, 0) << "some fluid particles must see the walls";
}


TEST(laplacianMatrix, variableCoefficientGivesDivBGradPhiAwayFromWalls)
{
    // Beyond 2h from the walls, on the full lattice, the pair sums of (10)
    // for a quadratic phi and a linear B are m (B lap phi + grad B .
    // grad phi) exactly (the odd moments vanish by symmetry), m the
    // kernel's lattice moment (1 - 8.0e-4 at h = 2 dr). Tolerance:
    // 1.01 |m - 1| |div(B grad phi)| plus round-off, 1e-11 relative.
    sphTest::throwOnFatal();
    latticeCase c = boxCase(0.05);
    const label n = c.size();
    const scalarList phi(sample(c, phiQ));
    const scalarList B(sample(c, linearB));
    const scalarList zero(n, Zero);
    const scalar m = latticeMoment(c);
    std::cout << "    lattice moment at h = 2 dr: m - 1 = " << m - 1 << std::endl;

    SPH::laplacianMatrix lap(c.nbrs, *c.usaw, c.V, c.nFluid);
    lap.coefficient(B);
    SPH::dispatch(*c.W, [&](const auto& K) { lap.assemble(K, zero); });
    const SPH::vectorN L(appliedLaplacian(lap, phi));

    const scalar support = c.W->support();
    label nChecked = 0;
    scalar maxRelErr = 0;
    for (label a = 0; a < c.nFluid; ++a)
    {
        if (c.walls.signedDistance(c.x[a]) < support + 1e-9)
        {
            continue;
        }
        const scalar exact = 4*B[a] + (gradB & gradPhiQ(c.x[a]));
        maxRelErr = max(maxRelErr, mag(L[a] - exact)/exact);
        EXPECT_NEAR(L[a], exact, 1.01*mag(m - 1)*exact + 1e-11*mag(exact))
            << "particle " << a << " at " << c.x[a];
        ++nChecked;
    }
    std::cout << "    max |L{B, phi} - div(B grad phi)|/div(B grad phi) = "
        << maxRelErr << " over " << nChecked << " particles" << std::endl;
    EXPECT_GT(nChecked, 100);

    // B matters: without it the same rows give lap phi, not div(B grad phi)
    SPH::laplacianMatrix lap1(c.nbrs, *c.usaw, c.V, c.nFluid);
    SPH::dispatch(*c.W, [&](const auto& K) { lap1.assemble(K, zero); });
    const SPH::vectorN L1(appliedLaplacian(lap1, phi));
    const label centre = c.nFluid/2;
    EXPECT_NEAR(L1[centre], 4, 4*1.01*mag(m - 1));
}


// * * * * * * * * * * * * * * * * Row kinds  * * * * * * * * * * * * * * * //

TEST(laplacianMatrix, dirichletRowsAreIdentityRowsWithTheValueInTheSource)
{
    // Dirichlet rows: the single entry 1 on the diagonal and b = s f. The
    // other rows keep every other coefficient of the all-interior matrix
    // exactly (same sums, same order) and lose the Dirichlet columns to
    // their right-hand side: b_a = b0_a - sum_{j Dirichlet} A0_aj s f_j,
    // to round-off (1e-12 of the largest term).
    sphTest::throwOnFatal();
    latticeCase c = boxCase(0.1);
    const label n = c.size();
    std::mt19937 gen(11);
    std::uniform_real_distribution<scalar> u(-1, 1);
    scalarList S(n), f(n);
    forAll(S, i)
    {
        S[i] = u(gen);
        f[i] = u(gen);
    }
    const scalar s = -2.5;

    SPH::laplacianMatrix lap0(c.nbrs, *c.usaw, c.V, c.nFluid);
    SPH::laplacianMatrix lap(c.nbrs, *c.usaw, c.V, c.nFluid);
    for (SPH::laplacianMatrix* l : {&lap0, &lap})
    {
        l->dirichletValues() = f;
        l->dirichletScale(s);
        forAll(l->wallFlux(), k)
        {
            l->wallFlux()[k] = 0.1*k;
        }
    }
    boolList isD(n, false);
    for (label i = 0; i < n; ++i)
    {
        isD[i] = (i >= c.nFluid) || (i % 7 == 3);
        lap.kinds()[i] = isD[i] ? label(SPH::laplacianMatrix::dirichlet) : label(SPH::laplacianMatrix::interior);
    }
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        lap0.assemble(K, S);
        lap.assemble(K, S);
    });
    const SPH::sparseMatrix& A0 = lap0.matrix();
    const SPH::sparseMatrix& A = lap.matrix();

    label nMoved = 0;
    for (label i = 0; i < n; ++i)
    {
        if (isD[i])
        {
            ASSERT_EQ(A.row(i).nonZeros(), 1) << "row " << i;
            EXPECT_EQ(A.coeff(i, i), 1);
            EXPECT_EQ(lap.source()[i], s*f[i]);
            continue;
        }
        scalar expected = lap0.source()[i], scale = mag(expected);
        label nD = 0;
        for (SPH::sparseMatrix::InnerIterator it(A0, i); it; ++it)
        {
            if (isD[it.col()])
            {
                expected -= it.value()*s*f[it.col()];
                scale = max(scale, mag(it.value()*s*f[it.col()]));
                EXPECT_EQ(A.coeff(i, it.col()), 0) << "row " << i;
                ++nD;
            }
            else
            {
                EXPECT_EQ(A.coeff(i, it.col()), it.value()) << "row " << i;
            }
        }
        EXPECT_EQ(A.row(i).nonZeros(), A0.row(i).nonZeros() - nD) << "row " << i;
        nMoved += nD;
        EXPECT_NEAR(lap.source()[i], expected, 1e-12*scale) << "row " << i;
    }
    EXPECT_GT(nMoved, 0);
}


TEST(laplacianMatrix, extensionAndCopyRowsContinueTheField)
{
    // An extension row is a weighted mean of its neighbours that are fluid
    // or interior/extension vertices: no source, no wall term, entries
    // that sum to zero (diagonal factor 1), non-positive off the diagonal.
    // A copy row is phi_a - phi_c = 0. Exact comparisons.
    sphTest::throwOnFatal();
    latticeCase c = boxCase(0.1);
    const label n = c.size();
    const scalarList S(n, 7.0);
    SPH::laplacianMatrix lap(c.nbrs, *c.usaw, c.V, c.nFluid);
    for (scalar& g : lap.wallFlux())
    {
        g = 3;
    }
    // Vertices alternate extension and copy (from the previous vertex)
    for (label i = c.nFluid; i < n; ++i)
    {
        const bool ext = (i - c.nFluid) % 2 == 0;
        lap.kinds()[i] = ext ? label(SPH::laplacianMatrix::extension) : label(SPH::laplacianMatrix::copy);
        lap.copyFrom()[i] = i - 1;
    }
    SPH::dispatch(*c.W, [&](const auto& K) { lap.assemble(K, S); });
    const SPH::sparseMatrix& A = lap.matrix();

    for (label i = c.nFluid; i < n; ++i)
    {
        EXPECT_EQ(lap.source()[i], 0) << "row " << i;
        if (lap.kinds()[i] == SPH::laplacianMatrix::copy)
        {
            ASSERT_EQ(A.row(i).nonZeros(), 2);
            EXPECT_EQ(A.coeff(i, i), 1);
            EXPECT_EQ(A.coeff(i, i - 1), -1);
            continue;
        }
        scalar sum = 0, diag = 0;
        for (SPH::sparseMatrix::InnerIterator it(A, i); it; ++it)
        {
            sum += it.value();
            if (it.col() == i)
            {
                diag = it.value();
            }
            else
            {
                EXPECT_LE(it.value(), 0) << "row " << i;
                EXPECT_NE(lap.kinds()[it.col()], SPH::laplacianMatrix::copy)
                    << "row " << i << " must not average over copy rows";
            }
        }
        EXPECT_GT(diag, 0) << "row " << i;
        EXPECT_NEAR(sum, 0, 1e-12*diag) << "row " << i;
    }
}



TEST(laplacianMatrix, rowSortIsStdSortForNearlySortedAndShuffledRows)
{
    // sortRow's insertion (nearly ascending rows) and its fallback to
    // std::sort (rows far from order) give std::sort's order exactly,
    // duplicate columns included, so the sums of a row do not change
    std::mt19937 gen(5);
    std::uniform_int_distribution<int> column(0, 80);
    std::uniform_real_distribution<double> value(-1, 1);
    for (int trial = 0; trial < 300; ++trial)
    {
        SPH::laplacianMatrix::matrixRow row(1 + trial % 70);
        for (auto& e : row)
        {
            e = {column(gen), value(gen)};
        }
        // A third shuffled, a third ascending but for a few swaps (the
        // diagonal at the end, as a row is built), a third descending
        if (trial % 3 == 1)
        {
            std::sort(row.begin(), row.end());
            for (int s = 0; s < 3 && row.size() > 1; ++s)
            {
                std::swap(row[gen() % row.size()], row.back());
            }
        }
        else if (trial % 3 == 2)
        {
            std::sort(row.rbegin(), row.rend());
        }
        SPH::laplacianMatrix::matrixRow expected(row);
        std::sort(expected.begin(), expected.end());
        SPH::laplacianMatrix::sortRow(row);
        ASSERT_EQ(row, expected) << "trial " << trial;
    }
}


// ************************************************************************* //
