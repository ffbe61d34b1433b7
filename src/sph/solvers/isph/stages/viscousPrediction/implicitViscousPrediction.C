/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "implicitViscousPrediction.H"
#include "kernelDispatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::dictionary& Foam::SPH::implicitViscousPrediction::solverDict
(
    const dictionary& solution
)
{
    const dictionary& solvers = solution.subDict("solvers");
    if (!solvers.isDict("U"))
    {
        FatalIOErrorInFunction(solvers)
            << "viscousScheme implicit (system/sphSchemes) solves for the"
            << " velocity, but " << solvers.name() << " has no entry U: add"
            << " one, e.g." << nl << nl
            << "    U { solver BiCGStab; preconditioner ILU0; tolerance 1e-10;"
            << " relTol 0; }" << nl << exit(FatalIOError);
    }
    return solvers.subDict("U");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::implicitViscousPrediction::implicitViscousPrediction
(
    isphWork& work,
    const dictionary& solution,
    const bool afterForces
)
:
    stage
    (
        "viscousPrediction",
        afterForces ? wordList({"U", "Ustar"}) : wordList({"U"}),
        {"Ustar"},
        "viscous prediction"
    ),
    work_(work),
    solverUx_(linearSolver::New("Ux", solverDict(solution))),
    solverUy_(linearSolver::New("Uy", solverDict(solution))),
    stopIfNotConverged_
    (
        solution.subOrEmptyDict("ISPH").getOrDefault<bool>
        (
            "stopIfNotConverged", true
        )
    ),
    afterForces_(afterForces),
    step_(work.nbrs, work.usaw, work.V, work.nFluid),
    uOld_(afterForces ? work.parts.size() : 0),
    nIterations_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::implicitViscousPrediction::describe(Ostream& os) const
{
    const string indent("                        ");
    os  << "eqs. (15)-(17), (31), implicit (backward Euler): nu "
        << work_.nu << (work_.nu > 0 ? "" : " (none)") << nl << indent.c_str();
    solverUx_->write(os);
}


void Foam::SPH::implicitViscousPrediction::execute(const scalar dt)
{
    isphWork& w = work_;
    const vector2DField& U = w.parts.field<vector2D>("U");
    if (afterForces_)
    {
        // The fluid's u* of bodyForces, the vertices' wall velocity
        for (label i = 0; i < w.nFluid; ++i)
        {
            uOld_[i] = w.Ustar[i];
        }
        for (label i = w.nFluid; i < uOld_.size(); ++i)
        {
            uOld_[i] = U[i];
        }
    }
    const UList<vector2D>& uOld =
        afterForces_
      ? static_cast<const UList<vector2D>&>(uOld_)
      : static_cast<const UList<vector2D>&>(U);
    if (!(w.nu > 0))
    {
        w.Ustar = uOld;
        return;
    }
    const FixedList<const linearSolver*, 2> solvers
    ({
        solverUx_.get(), solverUy_.get()
    });
    dispatch(w.W, [&](const auto& K)
    {
        lastSolve_ = step_.solve
        (
            K, w.rho0, w.rho0*w.nu, dt, w.cloud.dr(), uOld, solvers, w.Ustar
        );
    });
    for (direction d = 0; d < 2; ++d)
    {
        const solverPerformance& perf = lastSolve_[d];
        nIterations_ += perf.nIterations();
        if (!perf.converged() && stopIfNotConverged_)
        {
            throw stageFailure
            (
                "The " + perf.fieldName() + " solve did not converge: residual "
              + Foam::name(perf.finalResidual()) + " after "
              + Foam::name(perf.nIterations()) + " iterations, tolerance "
              + Foam::name(solvers[d]->tolerance()) + " (system/sphSolution"
                " solvers.U; ISPH { stopIfNotConverged no; } accepts it)"
            );
        }
    }
}


void Foam::SPH::implicitViscousPrediction::printStep(Ostream& os) const
{
    if (work_.nu > 0)
    {
        lastSolve_[0].print(os);
        lastSolve_[1].print(os);
    }
}


// ************************************************************************* //
