/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    heatScheme implicit of SPH::heatTransfer: the heat equation of Leroy
    et al. 2015, eq. (17), backward Euler on SPH::implicitDiffusionStep.

\*---------------------------------------------------------------------------*/

#include "heatTransfer.H"
#include "kernelDispatch.H"
#include "IOdictionary.H"
#include "stage.H"

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

void Foam::SPH::heatTransfer::implicitWallData
(
    const wallData& walls,
    const usawWalls& usaw,
    const scalarUList& T,
    implicitDiffusionStep& step
)
{
    // (34): K dT/dn = K (T_a - T_s)/max(d_as, c dr), a Robin wall towards
    // T_s; (31): dT/dn = -G; the laplacianMatrix's wall term has the
    // factor B_s + B_a = 2 K of (31)'s -2/gamma_a sum q |grad gamma_as|
    const List<labelPair>& ends = usaw.segmentParticles();
    scalarList& k = step.robinK();
    scalarList& g = step.robinG();
    scalarList& q = step.wallFlux();
    forAll(ends, s)
    {
        k[s] = 0;
        g[s] = 0;
        q[s] = 0;
        if (walls.kind[s] == isothermal)
        {
            k[s] = 1;
            g[s] = 0.5*(T[ends[s].first()] + T[ends[s].second()]);
        }
        else if (walls.kind[s] == fluxImposed)
        {
            q[s] = -walls.gradient[s];
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::heatTransfer::connectImplicit()
{
    if (turbulent_.law)
    {
        const IOdictionary schemes
        (
            IOobject
            (
                "sphSchemes", runTime_.system(), runTime_,
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            )
        );
        FatalIOErrorInFunction(schemes.lookup("heatScheme"))
            << "heatScheme implicit in a RAS run (0/k): the implicit step"
            << " takes the laminar wall flux (34), and the explicit k-epsilon"
            << " model bounds the time step anyway; use heatScheme explicit"
            << " (the paper's)" << exit(FatalIOError);
    }
    const IOdictionary solution
    (
        IOobject
        (
            "sphSolution", runTime_.system(), runTime_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    const dictionary& solvers = solution.subDict("solvers");
    if (!solvers.isDict("T"))
    {
        FatalIOErrorInFunction(solvers)
            << "heatScheme implicit (system/sphSchemes) solves for T, but "
            << solvers.name() << " has no entry T: add one, e.g." << nl << nl
            << "    T { solver BiCGStab; preconditioner ILU0; tolerance 1e-10;"
            << " relTol 0; }" << nl << exit(FatalIOError);
    }
    solverT_ = linearSolver::New("T", solvers.subDict("T"));
    stopIfNotConverged_ =
        solution.subOrEmptyDict("ISPH").getOrDefault<bool>
        (
            "stopIfNotConverged", true
        );
    const turbulenceCoupling& w = *work_;
    implicitStep_.reset
    (
        new implicitDiffusionStep(w.nbrs, w.usaw, w.V, w.nFluid)
    );
}


void Foam::SPH::heatTransfer::correctImplicit(const scalar dt)
{
    const turbulenceCoupling& w = *work_;
    scalarField& T = parts_.field<scalar>("T");
    dispatch(w.W, [&](const auto& K)
    {
        // The vertex T of (32) from T^n: Dirichlet rows of the step
        vertexValues(K, w.nbrs, w.usaw, w.V, w.nFluid, walls_, T);
        implicitWallData(walls_, w.usaw, T, *implicitStep_);
        lastSolve_ = implicitStep_->solve
        (
            K, KE_, dt, fluxMinDistance_*w.dr, *solverT_, T
        );
    });
    if (!lastSolve_.converged() && stopIfNotConverged_)
    {
        throw stageFailure
        (
            "The T solve did not converge: residual "
          + Foam::name(lastSolve_.finalResidual()) + " after "
          + Foam::name(lastSolve_.nIterations()) + " iterations, tolerance "
          + Foam::name(solverT_->tolerance()) + " (system/sphSolution"
            " solvers.T; ISPH { stopIfNotConverged no; } accepts it)"
        );
    }
}


// ************************************************************************* //
