/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearSolver.H"
#include "ILU0.H"

#include <Eigen/IterativeLinearSolvers>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class EigenSolver>
Foam::solverPerformance Foam::SPH::linearSolver::run
(
    EigenSolver& solver,
    const bool relativeToStart,
    const sparseMatrix& A,
    const vectorN& b,
    vectorN& x
) const
{
    const scalar normB = b.norm();
    if (normB == 0)
    {
        x.setZero();
        return solverPerformance(type(), fieldName_, 0, 0, 0, true);
    }

    const scalar initialResidual = (b - A*x).norm()/normB;
    const scalar target = max(tolerance_, relTol_*initialResidual);

    solver.compute(A);
    if (solver.info() != Eigen::Success)
    {
        // Only a factorising preconditioner (ILUT) can fail here
        return solverPerformance
        (
            type(), fieldName_, initialResidual, initialResidual, 0, false
        );
    }

    // The solver's own measure may differ from the true residual (Eigen's
    // GMRES: preconditioned, relative to the start of the call; BiCGSTAB:
    // updated by recurrence): ask it for the target, check the true
    // residual, and ask again ten times tighter while it is missed
    scalar residual = initialResidual;
    scalar factor = 1;
    label nIter = 0;
    for
    (
        label round = 0;
        round < 4 && !(residual <= target) && nIter < maxIter_;
        ++round, factor *= 0.1
    )
    {
        solver.setTolerance
        (
            factor*(relativeToStart ? target/residual : target)
        );
        solver.setMaxIterations(maxIter_ - nIter);
        const vectorN guess(x);
        x = solver.solveWithGuess(b, guess);
        nIter += solver.iterations();
        residual = (b - A*x).norm()/normB;
        if (!std::isfinite(residual))
        {
            break;
        }
    }

    return solverPerformance
    (
        type(), fieldName_, initialResidual, residual, nIter,
        residual <= target
    );
}


template<class EigenSolver>
Foam::solverPerformance Foam::SPH::linearSolver::runKeepingHierarchy
(
    EigenSolver& solver,
    const bool relativeToStart,
    const sparseMatrix& A,
    const vectorN& b,
    vectorN& x
) const
{
    solverPerformance perf = run(solver, relativeToStart, A, b, x);
    label withThisBuild = perf.nIterations();
    if (!perf.converged() && amgHierarchy_->wasReused())
    {
        // A kept hierarchy can miss a matrix that changed a lot (free-
        // surface rows appearing): once more, from where the solve
        // stopped, with a new one
        amgHierarchy_->expire();
        const solverPerformance again = run(solver, relativeToStart, A, b, x);
        perf = solverPerformance
        (
            perf.solverName(), perf.fieldName(), perf.initialResidual(),
            again.finalResidual(), perf.nIterations() + again.nIterations(),
            again.converged()
        );
        withThisBuild = again.nIterations();
    }
    amgHierarchy_->record(withThisBuild);
    return perf;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

template<template<class, class> class Solver, class Configure>
Foam::solverPerformance Foam::SPH::linearSolver::solveWith
(
    const sparseMatrix& A,
    const vectorN& b,
    vectorN& x,
    const Configure& configure,
    const bool relativeToStart
) const
{
    switch (preconditioner_)
    {
        case preconditionerType::none:
        {
            Solver<sparseMatrix, Eigen::IdentityPreconditioner> s;
            configure(s);
            return run(s, relativeToStart, A, b, x);
        }
        case preconditionerType::diagonal:
        {
            Solver<sparseMatrix, Eigen::DiagonalPreconditioner<scalar>> s;
            configure(s);
            return run(s, relativeToStart, A, b, x);
        }
        case preconditionerType::ILU0:
        {
            Solver<sparseMatrix, ILU0> s;
            configure(s);
            return run(s, relativeToStart, A, b, x);
        }
        case preconditionerType::ILUT:
        {
            Solver<sparseMatrix, Eigen::IncompleteLUT<scalar, int>> s;
            s.preconditioner().setDroptol(dropTolerance_);
            s.preconditioner().setFillfactor(fillFactor_);
            configure(s);
            return run(s, relativeToStart, A, b, x);
        }
        case preconditionerType::BoomerAMG:
        {
            Solver<sparseMatrix, BoomerAMG> s;
            s.preconditioner().setControls(amgControls_);
            s.preconditioner().attach(amgHierarchy_);
            configure(s);
            return runKeepingHierarchy(s, relativeToStart, A, b, x);
        }
    }
    return solverPerformance();
}


// ************************************************************************* //
