/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "implicitViscousPrediction.H"
#include "projection.H"
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


void Foam::SPH::implicitViscousPrediction::setOldValues(const scalar dt)
{
    isphWork& w = work_;
    const vector2DField& U = w.parts.field<vector2D>("U");
    const vector2DField& a = *w.pressureAcceleration;
    for (label i = 0; i < w.nFluid; ++i)
    {
        uOld_[i] = (afterForces_ ? w.Ustar[i] : U[i]) + dt*a[i];
    }
    for (label i = w.nFluid; i < uOld_.size(); ++i)
    {
        uOld_[i] = U[i];
    }
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
        afterForces
      ? wordList({"U", "pressureAcceleration", "Ustar"})
      : wordList({"U", "pressureAcceleration"}),
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
    uOld_(work.parts.size()),
    nIterations_(0)
{
    // Zero (none) unless a restart reads the last step's
    work.parts.addIfPresent<vector2D>("pressureAcceleration");
    work.pressureAcceleration =
        &work.parts.field<vector2D>("pressureAcceleration");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::implicitViscousPrediction::describe(Ostream& os) const
{
    const string indent("                        ");
    os  << "eqs. (15)-(17), (31), implicit (backward Euler): nu "
        << work_.nu << (work_.nu > 0 ? "" : " (none)") << ", on u^n + dt ("
        << (afterForces_ ? "f + " : "") << "g - G{p^n}/rho), the last"
        << " pressure's acceleration taken off again (the projection's, kept"
        << " with the particles: pressureAcceleration)" << nl
        << indent.c_str();
    solverUx_->write(os);
    os  << "; Uy alike";
}


void Foam::SPH::implicitViscousPrediction::execute(const scalar dt)
{
    isphWork& w = work_;
    setOldValues(dt);
    // The force stages' dt f at the vertex particles (buoyancy, eq. (45))
    const label n = w.Ustar.size();
    vertexForce_.resize(n - w.nFluid);
    forAll(vertexForce_, v)
    {
        vertexForce_[v] =
            afterForces_ ? w.Ustar[w.nFluid + v] : vector2D::zero;
    }
    if (!(w.nu > 0))
    {
        w.Ustar = uOld_;
    }
    else
    {
        solve(dt);
    }
    forAll(vertexForce_, v)
    {
        w.Ustar[w.nFluid + v] += vertexForce_[v];
    }

    // u** = w - dt a^n: the pressure is the projection's
    const vector2DField& a = *w.pressureAcceleration;
    for (label i = 0; i < w.nFluid; ++i)
    {
        w.Ustar[i] -= dt*a[i];
    }
}


void Foam::SPH::implicitViscousPrediction::solve(const scalar dt)
{
    isphWork& w = work_;
    const FixedList<const linearSolver*, 2> solvers
    ({
        solverUx_.get(), solverUy_.get()
    });
    dispatch(w.W, [&](const auto& K)
    {
        lastSolve_ = step_.solve
        (
            K, w.rho0, w.rho0*w.nu, dt, w.cloud.dr(), uOld_, solvers, w.Ustar
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
