/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "implicitDiffusionStep.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::implicitDiffusionStep::assemble
(
    const Kernel& K,
    const scalarUList& B,
    const scalar dt,
    const scalar dMin,
    const scalarUList& phi
)
{
    B_ = B;
    Sp_ = -1/dt;
    lap_.robinWalls(robinK_, robinG_, dMin);
    scalarList& f = lap_.dirichletValues();
    forAll(phi, i)
    {
        source_[i] = i < nFluid_ ? -(phi[i]/dt + rate_[i]) : 0;
        f[i] = phi[i];
    }
    lap_.assemble(K, source_);
}


template<class Kernel>
Foam::solverPerformance Foam::SPH::implicitDiffusionStep::solve
(
    const Kernel& K,
    const scalarUList& B,
    const scalar dt,
    const scalar dMin,
    const linearSolver& solver,
    UList<scalar>& phi
)
{
    assemble(K, B, dt, dMin, phi);
    const label n = phi.size();
    x_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        x_[i] = phi[i];
    }
    const solverPerformance perf = solver.solve(lap_.matrix(), lap_.source(), x_);
    for (label i = 0; i < nFluid_; ++i)
    {
        phi[i] = x_[i];
    }
    return perf;
}


// ************************************************************************* //
