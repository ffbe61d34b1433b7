/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "GMRES.H"
#include "addToRunTimeSelectionTable.H"

#include <unsupported/Eigen/IterativeSolvers>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(GMRES, 0);
    addToRunTimeSelectionTable(linearSolver, GMRES, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::GMRES::GMRES(const word& fieldName, const dictionary& dict)
:
    linearSolver(fieldName, dict),
    restart_(dict.getOrDefault<label>("restart", 30))
{
    if (restart_ < 1)
    {
        FatalIOErrorInFunction(dict.lookup("restart"))
            << "Entry restart " << restart_
            << ": expected the number of Krylov vectors, >= 1"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::GMRES::write(Ostream& os) const
{
    linearSolver::write(os);
    os  << ", restart " << restart_;
}


Foam::solverPerformance Foam::SPH::GMRES::solve
(
    const sparseMatrix& A,
    const vectorN& b,
    vectorN& x
) const
{
    // Eigen's GMRES measures the preconditioned residual relative to the
    // one it starts from
    const label restart = restart_;
    return solveWith<Eigen::GMRES>
    (
        A, b, x, [restart](auto& s) { s.set_restart(restart); }, true
    );
}


// ************************************************************************* //
