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
    setComponent(rho, mu, dr, U, d);
    diffusion_.assemble(K, nu_, dt, dr, component_);
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
    for (direction d = 0; d < 2; ++d)
    {
        setComponent(rho, mu, dr, U, d);
        perf[d] = diffusion_.solve(K, nu_, dt, dr, *solvers[d], component_);
        for (label i = 0; i < nFluid_; ++i)
        {
            Ustar[i][d] = component_[i];
        }
    }
    for (label i = nFluid_; i < U.size(); ++i)
    {
        Ustar[i] = U[i];
    }
    return perf;
}


// ************************************************************************* //
