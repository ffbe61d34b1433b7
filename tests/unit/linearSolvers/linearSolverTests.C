/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The linear solver wrapper (src/sph/linearSolvers): every solver with
    every preconditioner on a symmetric positive definite system (the
    5-point Poisson matrix) and a non-symmetric one (upwind convection-
    diffusion), against Eigen's direct SparseLU; warm start, the iteration
    limit, the OpenFOAM log line, ILU0 on matrices it factorises exactly,
    and the errors of a bad dictionary.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "linearSolver.H"
#include "ILU0.H"
#include "BoomerAMG.H"
#include "OStringStream.H"

#include <Eigen/SparseLU>
#include <Eigen/Dense>

using namespace Foam;

namespace
{
    //- n x n grid, 5-point stencil: -lap u + c (du/dx) (c = 0: symmetric)
    SPH::sparseMatrix gridMatrix(const label n, const scalar c)
    {
        std::vector<Eigen::Triplet<scalar>> t;
        const scalar h = 1.0/(n + 1);
        auto id = [n](label i, label j) { return int(i + n*j); };
        for (label j = 0; j < n; ++j)
        {
            for (label i = 0; i < n; ++i)
            {
                t.emplace_back(id(i, j), id(i, j), 4/(h*h) + c/h);
                if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1/(h*h) - c/h);
                if (i < n - 1) t.emplace_back(id(i, j), id(i + 1, j), -1/(h*h));
                if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1/(h*h));
                if (j < n - 1) t.emplace_back(id(i, j), id(i, j + 1), -1/(h*h));
            }
        }
        SPH::sparseMatrix A(n*n, n*n);
        A.setFromTriplets(t.begin(), t.end());
        return A;
    }

    //- n x n lattice, each node coupled to those within 2.5 spacings with
    //- a Wendland-like weight, as an SPH Laplacian row (about 20 entries,
    //- most of them small); the missing neighbours beyond the edges go
    //- to the diagonal, which makes it nonsingular
    SPH::sparseMatrix wideStencilMatrix(const label n)
    {
        std::vector<Eigen::Triplet<scalar>> t;
        const label reach = 2;
        const scalar radius = 2.5;
        auto id = [n](label i, label j) { return int(i + n*j); };
        for (label j = 0; j < n; ++j)
        {
            for (label i = 0; i < n; ++i)
            {
                scalar diagonal = 0;
                for (label dj = -reach; dj <= reach; ++dj)
                {
                    for (label di = -reach; di <= reach; ++di)
                    {
                        const scalar q = std::hypot(di, dj)/radius;
                        if ((di == 0 && dj == 0) || q >= 1) continue;
                        const scalar w = std::pow(1 - q, 4)*(1 + 4*q);
                        diagonal += w;
                        const label k = i + di, l = j + dj;
                        if (k >= 0 && k < n && l >= 0 && l < n)
                        {
                            t.emplace_back(id(i, j), id(k, l), -w);
                        }
                    }
                }
                t.emplace_back(id(i, j), id(i, j), diagonal);
            }
        }
        SPH::sparseMatrix A(n*n, n*n);
        A.setFromTriplets(t.begin(), t.end());
        return A;
    }

    SPH::vectorN rhs(const label size)
    {
        SPH::vectorN b(size);
        for (label i = 0; i < size; ++i)
        {
            b[i] = std::sin(0.1*i) + 1;
        }
        return b;
    }

    SPH::vectorN direct(const SPH::sparseMatrix& A, const SPH::vectorN& b)
    {
        Eigen::SparseMatrix<scalar> Ac(A);
        Eigen::SparseLU<Eigen::SparseMatrix<scalar>> lu(Ac);
        return lu.solve(b);
    }

    autoPtr<SPH::linearSolver> makeSolver(const std::string& text)
    {
        return SPH::linearSolver::New("p", sphTest::dict(text));
    }

    class linearSolvers : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            sphTest::throwOnFatal();
        }
    };
}


TEST_F(linearSolvers, tableHoldsBiCGStabAndGMRES)
{
    const wordList names(SPH::linearSolver::dictionaryConstructorTablePtr_->sortedToc());
    EXPECT_EQ(names, wordList({"BiCGStab", "GMRES"}));
}


TEST_F(linearSolvers, everySolverAndPreconditionerSolvesBothSystems)
{
    for (const scalar c : {0.0, 200.0})
    {
        const SPH::sparseMatrix A = gridMatrix(20, c);
        const SPH::vectorN b = rhs(A.rows());
        const SPH::vectorN exact = direct(A, b);
        for (const char* solver : {"BiCGStab", "GMRES"})
        {
            for (const char* pc : {"none", "diagonal", "ILU0", "ILUT", "BoomerAMG"})
            {
                const auto s = makeSolver
                (
                    std::string("solver ") + solver + "; preconditioner " + pc
                  + "; tolerance 1e-10; maxIter 2000;"
                );
                SPH::vectorN x = SPH::vectorN::Zero(A.rows());
                const solverPerformance perf = s->solve(A, b, x);
                const std::string what =
                    std::string(solver) + " " + pc + (c > 0 ? " non-symmetric" : " SPD");
                EXPECT_TRUE(perf.converged()) << what;
                EXPECT_LE(perf.finalResidual(), 1e-10) << what;
                EXPECT_NEAR(perf.initialResidual(), 1, 1e-14) << what;
                EXPECT_GT(perf.nIterations(), 0) << what;
                // The reported residual is the true one
                EXPECT_NEAR((b - A*x).norm()/b.norm(), perf.finalResidual(), 1e-14) << what;
                EXPECT_LT((x - exact).norm()/exact.norm(), 1e-7) << what;
                EXPECT_EQ(perf.solverName(), solver);
                EXPECT_EQ(perf.fieldName(), "p");
            }
        }
    }
}


TEST_F(linearSolvers, preconditionersCutTheIterations)
{
    const SPH::sparseMatrix A = gridMatrix(30, 50);
    const SPH::vectorN b = rhs(A.rows());
    label n[3];
    int k = 0;
    for (const char* pc : {"none", "diagonal", "ILU0"})
    {
        const auto s = makeSolver
        (
            std::string("solver BiCGStab; preconditioner ") + pc + "; tolerance 1e-8;"
        );
        SPH::vectorN x = SPH::vectorN::Zero(A.rows());
        n[k++] = s->solve(A, b, x).nIterations();
    }
    std::cout << "    BiCGStab iterations none, diagonal, ILU0: " << n[0] << ' '
        << n[1] << ' ' << n[2] << std::endl;
    EXPECT_LT(n[2], n[1]);
    EXPECT_LT(n[2], n[0]/2);
}


TEST_F(linearSolvers, BoomerAMGIterationsHardlyGrowWithTheGrid)
{
    // ILU(0) iterations grow like the grid's side; one multigrid cycle
    // removes every wavelength, so its count stays nearly flat
    label nIlu[2], nAmg[2];
    const label sides[2] = {40, 160};
    for (int k = 0; k < 2; ++k)
    {
        const SPH::sparseMatrix A = gridMatrix(sides[k], 50);
        const SPH::vectorN b = rhs(A.rows());
        for (const char* pc : {"ILU0", "BoomerAMG"})
        {
            const auto s = makeSolver
            (
                std::string("solver BiCGStab; preconditioner ") + pc
              + "; tolerance 1e-8;"
            );
            SPH::vectorN x = SPH::vectorN::Zero(A.rows());
            const solverPerformance perf = s->solve(A, b, x);
            EXPECT_TRUE(perf.converged()) << pc << " on " << sides[k];
            EXPECT_LT((b - A*x).norm()/b.norm(), 1e-8) << pc;
            (pc[0] == 'I' ? nIlu : nAmg)[k] = perf.nIterations();
        }
    }
    std::cout << "    BiCGStab iterations on 40^2 and 160^2: ILU0 " << nIlu[0]
        << ' ' << nIlu[1] << ", BoomerAMG " << nAmg[0] << ' ' << nAmg[1]
        << std::endl;
    EXPECT_GT(nIlu[1], 2*nIlu[0]);
    EXPECT_LE(nAmg[1], nAmg[0] + 3);
    EXPECT_LT(nAmg[1], nIlu[1]/4);
}


TEST_F(linearSolvers, BoomerAMGKeepsItsHierarchyForReuseSolves)
{
    // A matrix that drifts a little from solve to solve, as the particles'
    // does from step to step: the old hierarchy still preconditions it,
    // and every answer is as accurate as with a new one
    const auto s = makeSolver
    (
        "solver BiCGStab; preconditioner BoomerAMG; tolerance 1e-10; reuse 4;"
    );
    const SPH::sparseMatrix A0 = gridMatrix(40, 20);
    const SPH::vectorN b = rhs(A0.rows());
    for (label k = 0; k < 9; ++k)
    {
        const SPH::sparseMatrix A = gridMatrix(40, 20 + 2*k);
        SPH::vectorN x = SPH::vectorN::Zero(A.rows());
        const solverPerformance perf = s->solve(A, b, x);
        EXPECT_TRUE(perf.converged()) << k;
        EXPECT_LT((b - A*x).norm()/b.norm(), 1e-10) << k;
        EXPECT_LT(perf.nIterations(), 15) << k;
    }
    EXPECT_EQ(s->nPreconditionerBuilds(), 3);     // solves 0, 4 and 8

    // A restart time (expire) and a new size each build anew
    SPH::vectorN x = SPH::vectorN::Zero(A0.rows());
    s->expirePreconditioner();
    s->solve(A0, b, x);
    EXPECT_EQ(s->nPreconditionerBuilds(), 4);
    const SPH::sparseMatrix B = gridMatrix(30, 20);
    SPH::vectorN y = SPH::vectorN::Zero(B.rows());
    EXPECT_TRUE(s->solve(B, rhs(B.rows()), y).converged());
    EXPECT_EQ(s->nPreconditionerBuilds(), 5);

    // Other preconditioners keep nothing
    EXPECT_EQ
    (
        makeSolver("solver BiCGStab; preconditioner ILU0; tolerance 1e-8;")
            ->nPreconditionerBuilds(),
        0
    );
}


TEST_F(linearSolvers, BoomerAMGControlsAreWrittenAndChecked)
{
    const auto s = makeSolver
    (
        "solver GMRES; preconditioner BoomerAMG; tolerance 1e-8;"
        " coarsening PMIS; smoother l1GaussSeidel; nSweeps 2;"
    );
    OStringStream settings;
    s->write(settings);
    EXPECT_NE(settings.str().find("BoomerAMG (PMIS, extendedI interpolation,"
        " l1GaussSeidel x2, strongThreshold 0.5"), std::string::npos)
        << settings.str();
    EXPECT_NE(settings.str().find(", filterTolerance 0)"), std::string::npos)
        << settings.str();

    const SPH::sparseMatrix A = gridMatrix(30, 0);
    const SPH::vectorN b = rhs(A.rows());
    SPH::vectorN x = SPH::vectorN::Zero(A.rows());
    EXPECT_TRUE(s->solve(A, b, x).converged());

    for
    (
        const char* bad :
        {
            "strongThreshold 1.5;", "nSweeps 0;", "coarsening CLJP;",
            "smoother chebyshev;", "aggressiveLevels -1;", "reuse 0;",
            "filterTolerance 1;", "filterTolerance -0.1;"
        }
    )
    {
        const std::string text(bad);
        const std::string entry(text.substr(0, text.find(' ')));
        const std::string value(text.substr(text.find(' ') + 1, text.size() - text.find(' ') - 2));
        try
        {
            makeSolver
            (
                std::string("solver BiCGStab; preconditioner BoomerAMG;"
                " tolerance 1e-8; ") + bad
            );
            ADD_FAILURE() << "no error for " << bad;
        }
        catch (const Foam::error& err)
        {
            // The entry's name or, from an Enum, the value it refused
            const std::string msg(err.message());
            EXPECT_TRUE
            (
                msg.find(entry) != std::string::npos
             || msg.find(value) != std::string::npos
            ) << bad << ": " << msg;
        }
    }
}


TEST_F(linearSolvers, BoomerAMGFilterLumpsSmallEntriesIntoTheDiagonal)
{
    // Row 0: entries below 0.25 x 2 go to the diagonal; row 1 has no
    // diagonal entry and is kept whole; row 2 is a Dirichlet row
    const std::vector<int> start{0, 5, 7, 8};
    const std::vector<int> columns{0, 1, 2, 3, 4, 0, 2, 2};
    const std::vector<scalar> values{4, -2, -1, -0.1, 0.05, -1, 3, 1};
    const SPH::BoomerAMG::compressedRows f = SPH::BoomerAMG::filtered
    (
        3, start.data(), columns.data(), values.data(), 0.25
    );
    EXPECT_EQ(f.start, (std::vector<int>{0, 3, 5, 6}));
    EXPECT_EQ(f.columns, (std::vector<int>{0, 1, 2, 0, 2, 2}));
    ASSERT_EQ(f.values.size(), 6u);
    EXPECT_DOUBLE_EQ(f.values[0], 4 - 0.1 + 0.05);
    EXPECT_EQ(f.values[1], -2);
    EXPECT_EQ(f.values[2], -1);
    EXPECT_EQ(f.values[3], -1);
    EXPECT_EQ(f.values[4], 3);
    EXPECT_EQ(f.values[5], 1);

    // The row sums (a Laplacian's constant null space) are kept
    const SPH::sparseMatrix A = wideStencilMatrix(20);
    const SPH::BoomerAMG::compressedRows g = SPH::BoomerAMG::filtered
    (
        A.rows(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(), 0.25
    );
    EXPECT_LT(g.columns.size(), 0.6*A.nonZeros());
    for (Eigen::Index i = 0; i < A.rows(); ++i)
    {
        scalar sumA = 0, sumF = 0;
        for (int k = A.outerIndexPtr()[i]; k < A.outerIndexPtr()[i + 1]; ++k)
        {
            sumA += A.valuePtr()[k];
        }
        for (int k = g.start[i]; k < g.start[i + 1]; ++k)
        {
            sumF += g.values[k];
        }
        EXPECT_NEAR(sumF, sumA, 1e-12) << "row " << i;
    }
}


TEST_F(linearSolvers, BoomerAMGOnTheFilteredMatrixGivesTheSameAnswer)
{
    // The hierarchy of the filtered matrix preconditions the whole one:
    // the answer is the same, the iterations about the same
    const SPH::sparseMatrix A = wideStencilMatrix(60);
    const SPH::vectorN b = rhs(A.rows());
    SPH::vectorN x[2];
    label nIter[2];
    const char* filters[2] = {"0", "0.25"};
    for (int k = 0; k < 2; ++k)
    {
        const auto s = makeSolver
        (
            std::string("solver BiCGStab; preconditioner BoomerAMG;"
            " tolerance 1e-10; filterTolerance ") + filters[k] + ";"
        );
        x[k] = SPH::vectorN::Zero(A.rows());
        const solverPerformance perf = s->solve(A, b, x[k]);
        EXPECT_TRUE(perf.converged()) << filters[k];
        EXPECT_LT((b - A*x[k]).norm()/b.norm(), 1e-10) << filters[k];
        nIter[k] = perf.nIterations();
        EXPECT_EQ(s->preconditionerEntriesKept() < 1, k == 1);
    }
    std::cout << "    BiCGStab iterations, filterTolerance 0 and 0.25: "
        << nIter[0] << ' ' << nIter[1] << std::endl;
    EXPECT_LT((x[1] - x[0]).norm()/x[0].norm(), 1e-8);
    EXPECT_LE(nIter[1], nIter[0] + 3);
}


TEST_F(linearSolvers, warmStartFromTheSolutionTakesNoIteration)
{
    const SPH::sparseMatrix A = gridMatrix(15, 100);
    const SPH::vectorN b = rhs(A.rows());
    for (const char* solver : {"BiCGStab", "GMRES"})
    {
        const auto s = makeSolver
        (
            std::string("solver ") + solver + "; preconditioner ILU0; tolerance 1e-6;"
        );
        SPH::vectorN x = direct(A, b);
        const SPH::vectorN x0(x);
        const solverPerformance perf = s->solve(A, b, x);
        EXPECT_TRUE(perf.converged()) << solver;
        EXPECT_EQ(perf.nIterations(), 0) << solver;
        EXPECT_LT(perf.initialResidual(), 1e-12) << solver;
        EXPECT_EQ((x - x0).norm(), 0) << solver;
    }
}


TEST_F(linearSolvers, relTolStopsAtAFractionOfTheInitialResidual)
{
    const SPH::sparseMatrix A = gridMatrix(20, 0);
    const SPH::vectorN b = rhs(A.rows());
    for (const char* solver : {"BiCGStab", "GMRES"})
    {
        const auto s = makeSolver
        (
            std::string("solver ") + solver
          + "; preconditioner diagonal; tolerance 1e-12; relTol 0.01;"
        );
        SPH::vectorN x = SPH::vectorN::Zero(A.rows());
        const solverPerformance perf = s->solve(A, b, x);
        EXPECT_TRUE(perf.converged()) << solver;
        EXPECT_LE(perf.finalResidual(), 0.01) << solver;
        EXPECT_GT(perf.finalResidual(), 1e-8) << solver;
    }
}


TEST_F(linearSolvers, iterationLimitIsReportedAsNotConverged)
{
    const SPH::sparseMatrix A = gridMatrix(30, 0);
    const SPH::vectorN b = rhs(A.rows());
    for (const char* solver : {"BiCGStab", "GMRES"})
    {
        const auto s = makeSolver
        (
            std::string("solver ") + solver
          + "; preconditioner none; tolerance 1e-12; maxIter 5;"
        );
        SPH::vectorN x = SPH::vectorN::Zero(A.rows());
        const solverPerformance perf = s->solve(A, b, x);
        EXPECT_FALSE(perf.converged()) << solver;
        EXPECT_EQ(perf.nIterations(), 5) << solver;
        EXPECT_GT(perf.finalResidual(), 1e-12) << solver;
        EXPECT_LT(perf.finalResidual(), 1) << solver;
    }
}


TEST_F(linearSolvers, zeroRightHandSideGivesZero)
{
    const SPH::sparseMatrix A = gridMatrix(5, 0);
    SPH::vectorN x = SPH::vectorN::Ones(A.rows());
    const auto s = makeSolver("solver GMRES; preconditioner ILU0; tolerance 1e-8;");
    const solverPerformance perf = s->solve(A, SPH::vectorN::Zero(A.rows()), x);
    EXPECT_TRUE(perf.converged());
    EXPECT_EQ(x.norm(), 0);
}


TEST_F(linearSolvers, logLineIsOpenFOAMs)
{
    const SPH::sparseMatrix A = gridMatrix(10, 0);
    const SPH::vectorN b = rhs(A.rows());
    const auto s = makeSolver("solver BiCGStab; preconditioner ILU0; tolerance 1e-8;");
    SPH::vectorN x = SPH::vectorN::Zero(A.rows());
    const solverPerformance perf = s->solve(A, b, x);
    OStringStream os;
    perf.print(os);
    const std::string line(os.str());
    EXPECT_EQ(line.find("BiCGStab:  Solving for p, Initial residual = 1, Final residual = "), 0u)
        << line;
    EXPECT_NE(line.find(", No Iterations " + std::to_string(perf.nIterations())), std::string::npos)
        << line;

    OStringStream settings;
    s->write(settings);
    EXPECT_EQ
    (
        settings.str(),
        "BiCGStab for p, preconditioner ILU0, tolerance 1e-08, relTol 0, maxIter 1000"
    );
}


TEST_F(linearSolvers, ILU0IsExactForATridiagonalMatrix)
{
    // No fill-in: ILU(0) is the LU factorisation itself
    const label n = 50;
    std::vector<Eigen::Triplet<scalar>> t;
    for (label i = 0; i < n; ++i)
    {
        t.emplace_back(i, i, 3 + 0.01*i);
        if (i > 0) t.emplace_back(i, i - 1, -1.3);
        if (i < n - 1) t.emplace_back(i, i + 1, -0.7);
    }
    SPH::sparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    const SPH::vectorN b = rhs(n);

    SPH::ILU0 ilu;
    ilu.compute(A);
    EXPECT_EQ(ilu.nZeroPivots(), 0);
    const SPH::vectorN x = ilu.solve(b);
    EXPECT_LT((A*x - b).norm()/b.norm(), 1e-14);

    const auto s = makeSolver("solver BiCGStab; preconditioner ILU0; tolerance 1e-12;");
    SPH::vectorN y = SPH::vectorN::Zero(n);
    EXPECT_LE(s->solve(A, b, y).nIterations(), 1);
}


TEST_F(linearSolvers, ILU0KeepsThePatternOfTheMatrix)
{
    // On the 5-point matrix L U differs from A only where fill was dropped
    const SPH::sparseMatrix A = gridMatrix(6, 10);
    SPH::ILU0 ilu;
    ilu.compute(A);
    // Columns of A: (L U - A) e_j vanishes on the pattern of A
    Eigen::MatrixXd LU(A.rows(), A.cols());
    for (label j = 0; j < A.cols(); ++j)
    {
        SPH::vectorN e = SPH::vectorN::Zero(A.rows());
        e[j] = 1;
        // (L U)^{-1} e_j, then invert back with a dense solve
        LU.col(j) = ilu.solve(e);
    }
    const Eigen::MatrixXd M = LU.inverse();
    const Eigen::MatrixXd Ad(A);
    for (int i = 0; i < A.outerSize(); ++i)
    {
        for (SPH::sparseMatrix::InnerIterator it(A, i); it; ++it)
        {
            EXPECT_NEAR(M(i, it.col()), it.value(), 1e-9*std::abs(it.value()))
                << "(" << i << ", " << it.col() << ")";
        }
    }
}


TEST_F(linearSolvers, unknownSolverIsAnIOErrorListingTheValidOnes)
{
    try
    {
        makeSolver("solver PCG; preconditioner ILU0; tolerance 1e-8;");
        FAIL() << "no error";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        for (const char* s : {"PCG", "BiCGStab", "GMRES"})
        {
            EXPECT_NE(msg.find(s), std::string::npos) << msg;
        }
    }
}


TEST_F(linearSolvers, unknownPreconditionerIsAnIOErrorListingTheValidOnes)
{
    try
    {
        makeSolver("solver BiCGStab; preconditioner DIC; tolerance 1e-8;");
        FAIL() << "no error";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        for (const char* s : {"DIC", "none", "diagonal", "ILU0", "ILUT", "BoomerAMG"})
        {
            EXPECT_NE(msg.find(s), std::string::npos) << msg;
        }
    }
}


TEST_F(linearSolvers, missingOrBadEntriesAreIOErrorsNamingThem)
{
    const std::vector<std::pair<std::string, std::string>> cases
    {
        {"preconditioner ILU0; tolerance 1e-8;", "solver"},
        {"solver GMRES; tolerance 1e-8;", "preconditioner"},
        {"solver GMRES; preconditioner none;", "tolerance"},
        {"solver GMRES; preconditioner none; tolerance -1;", "tolerance"},
        {"solver GMRES; preconditioner none; tolerance 1e-8; relTol 2;", "relTol"},
        {"solver GMRES; preconditioner none; tolerance 1e-8; maxIter 0;", "maxIter"},
        {"solver GMRES; preconditioner none; tolerance 1e-8; restart 0;", "restart"},
    };
    for (const auto& c : cases)
    {
        try
        {
            makeSolver(c.first);
            ADD_FAILURE() << "no error for: " << c.first;
        }
        catch (const Foam::IOerror& err)
        {
            const std::string msg(err.message());
            const std::string where(err.ioFileName());
            EXPECT_TRUE
            (
                msg.find(c.second) != std::string::npos
             || where.find(c.second) != std::string::npos
            ) << c.first << ": " << msg << " in " << where;
        }
    }
}
