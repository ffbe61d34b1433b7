/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "implicitViscousStep.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::implicitViscousStep::assemble
(
    const Kernel& K,
    const scalar rho,
    const scalar mu,
    const scalar dt,
    const scalar dr,
    const UList<vector2D>& U,
    const direction d
)
{
    const scalar rhoByDt = rho/dt;
    mu_ = mu;
    Sp_ = -rhoByDt;
    lap_.robinWalls(robinK_, robinG_, dr);
    robinData(U, d);
    setSource(rhoByDt, dr, U, d);

    // The vertex particles keep their wall velocity
    scalarList& f = lap_.dirichletValues();
    for (label i = nFluid_; i < f.size(); ++i)
    {
        f[i] = U[i][d];
    }
    lap_.assemble(K, source_);
}


template<class Kernel>
Foam::FixedList<Foam::solverPerformance, 2>
Foam::SPH::implicitViscousStep::solve
(
    const Kernel& K,
    const scalar rho,
    const scalar mu,
    const scalar dt,
    const scalar dr,
    const UList<vector2D>& U,
    const FixedList<const linearSolver*, 2>& solvers,
    UList<vector2D>& Ustar
)
{
    FixedList<solverPerformance, 2> perf;
    const label n = U.size();
    x_.resize(n);
    for (direction d = 0; d < 2; ++d)
    {
        assemble(K, rho, mu, dt, dr, U, d);
        for (label i = 0; i < n; ++i)
        {
            x_[i] = U[i][d];
        }
        perf[d] = solvers[d]->solve(lap_.matrix(), lap_.source(), x_);
        for (label i = 0; i < nFluid_; ++i)
        {
            Ustar[i][d] = x_[i];
        }
    }
    for (label i = nFluid_; i < n; ++i)
    {
        Ustar[i] = U[i];
    }
    return perf;
}


// ************************************************************************* //
