/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "BiCGStab.H"
#include "addToRunTimeSelectionTable.H"

#include <Eigen/IterativeLinearSolvers>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(BiCGStab, 0);
    addToRunTimeSelectionTable(linearSolver, BiCGStab, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::BiCGStab::BiCGStab(const word& fieldName, const dictionary& dict)
:
    linearSolver(fieldName, dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::solverPerformance Foam::SPH::BiCGStab::solve
(
    const sparseMatrix& A,
    const vectorN& b,
    vectorN& x
) const
{
    // Eigen's BiCGSTAB measures |r|/|b|, as linearSolver does
    return solveWith<Eigen::BiCGSTAB>(A, b, x, [](auto&) {}, false);
}


// ************************************************************************* //
