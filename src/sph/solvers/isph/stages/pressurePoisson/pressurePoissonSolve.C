/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    pressurePoisson: the wall condition, the solve and what follows it
    (the pressure from A, the confined flow's level, the rows held at
    pMin), apart from the rows' assembly in pressurePoisson.C.

\*---------------------------------------------------------------------------*/

#include "pressurePoisson.H"
#include "floatingRows.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::pressurePoisson::wallCondition(const scalar dt)
{
    // Eq. (43) with the vertex particles' u* = u_w^n + dt g (45): zero at
    // a wall that does not accelerate, plus rho f_s.n_s of a body force
    // of u** at the wall (isphWork::wallAcceleration: buoyancy)
    if (!work_.motion.any() && work_.wallAcceleration.empty()) return;
    const label nFluid = work_.nFluid;
    const List<vector2D>& normal = work_.usaw.segmentNormals();
    scalarList& dAdn = laplacian_.wallFlux();
    dAdn = Zero;
    if (work_.motion.any())
    {
        work_.motion.vertices(runTime_.value(), work_.wallX, work_.wallU);
        const vector2DField& U = work_.parts.field<vector2D>("U");
        const List<labelPair>& ends = work_.usaw.segmentParticles();
        forAll(dAdn, s)
        {
            const label v1 = ends[s].first();
            const label v2 = ends[s].second();
            const vector2D uOld(0.5*(U[v1] + U[v2]));
            const vector2D uNew
                (0.5*(work_.wallU[v1 - nFluid] + work_.wallU[v2 - nFluid]));
            dAdn[s] = work_.rho0*((uOld - uNew) & normal[s])/dt;
        }
    }
    forAll(work_.wallAcceleration, s)
    {
        dAdn[s] += work_.rho0*(work_.wallAcceleration[s] & normal[s]);
    }
}


Foam::label Foam::SPH::pressurePoisson::anchorFloatingClusters()
{
    // Rows that reach no anchor (SPH::reachesAnAnchor) leave the system
    // singular, or nearly: a droplet sliding down a wall, all its particles
    // kept off the surface by the wall-crossing test (39) (the 4 mm
    // obstacle dam-break); a pair joined to the liquid by a kernel's tail
    // only (the water wheel at dr 0.02 m, t = 15.35 s, where GMRES
    // stalled). Their fluid particles, then the vertex particles that still
    // float, are held (Dirichlet rows)
    const sparseMatrix& M = laplacian_.matrix();
    const label n = M.rows();
    labelList& kind = laplacian_.kinds();
    boolList dirichlet(n);
    forAll(dirichlet, i)
    {
        dirichlet[i] = kind[i] == laplacianMatrix::dirichlet;
    }
    boolList fixed(n, false);
    boolList reaches(reachesAnAnchor(M, dirichlet, fixed));

    // A set held to the liquid by weak links only (below floatingRows'
    // share of the diagonal) takes the liquid's last pressure across them,
    // weighted by their entries (0 with none: a droplet): its own level
    // would be its sources over those links (3.3e8 Pa for a particle
    // pressed under the 2 mm obstacle dam-break's ceiling)
    const scalarField& p = work_.parts.field<scalar>("p");
    const vector2DField& x = work_.parts.positions();
    scalarList& f = laplacian_.dirichletValues();
    auto fix = [&](const label i)
    {
        scalar sumW = 0, sumWp = 0;
        for (sparseMatrix::InnerIterator it(M, i); it; ++it)
        {
            const label j = it.col();
            if (j != i && (reaches[j] || fixed[j]) && !dirichlet[j])
            {
                sumW += mag(it.value());
                sumWp += mag(it.value())*p[j];
            }
        }
        kind[i] = laplacianMatrix::dirichlet;
        f[i] = (work_.g & x[i]) - (sumW > 0 ? sumWp/sumW : 0)/work_.rho0;
    };
    label nFixed = 0;
    for (label i = 0; i < work_.nFluid; ++i)
    {
        if (!dirichlet[i] && !reaches[i])
        {
            fix(i);
            work_.surfaceNormal[i] = Zero;
            fixed[i] = true;
            ++nFixed;
        }
    }
    if (nFixed)
    {
        // Assembled again, the rows that refer to them are dominant
        reaches = reachesAnAnchor(M, dirichlet, fixed);
    }
    for (label i = work_.nFluid; i < n; ++i)
    {
        if (!dirichlet[i] && !reaches[i])
        {
            fix(i);
            ++nFixed;
        }
    }
    return nFixed;
}


void Foam::SPH::pressurePoisson::makeCompatible()
{
    const scalar* gamma = work_.usaw.gamma().cdata();
    const scalarList& V = work_.V;
    const label n = work_.parts.size();
    vectorN& b = laplacian_.source();
    scalar sumW = 0, sumWB = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar w = V[i]*gamma[i];
        sumW += w;
        sumWB += w*b[i];
    }
    const scalar mean = sumWB/sumW;
    for (label i = 0; i < n; ++i)
    {
        if (V[i] > 0)
        {
            b[i] -= mean;
        }
    }
}


void Foam::SPH::pressurePoisson::setPressure()
{
    const label n = work_.parts.size();
    scalarField& p = work_.parts.field<scalar>("p");
    const vector2DField& x = work_.parts.positions();
    const scalar rho0 = work_.rho0;
    const vector2D g = work_.g;
    for (label i = 0; i < n; ++i)
    {
        p[i] = xA_[i] + rho0*(g & x[i]);
    }
    if (!freeSurface_)
    {
        scalar mean = 0;
        for (label i = 0; i < work_.nFluid; ++i)
        {
            mean += p[i];
        }
        mean /= work_.nFluid;
        for (label i = 0; i < n; ++i)
        {
            p[i] += pRefValue_ - mean;
        }
    }
}


Foam::label Foam::SPH::pressurePoisson::holdAtPMin()
{
    isphWork& w = work_;
    const scalarField& p = w.parts.field<scalar>("p");
    const vector2DField& x = w.parts.positions();
    labelList& kind = laplacian_.kinds();
    scalarList& f = laplacian_.dirichletValues();
    label n = 0;
    for (label i = 0; i < w.nFluid; ++i)
    {
        if (kind[i] != laplacianMatrix::interior || !(p[i] < pMin_))
        {
            continue;
        }

        // A free-surface row (ghost values beyond it) borders the air: it
        // separates at the air's pressure, 0, as the paper's free-surface
        // particles, and its gradient is its real neighbours'. Held at
        // pMin, its ghosts (p rising from pMin to 0 over delta = dr/2)
        // pulled it into the liquid at |pMin|/(rho delta), 250 m/s^2 at
        // pMin -5000 Pa and dr = 0.04 m: a lone particle at a water wheel's
        // paddle tip, sucked after the rising tip, left it at 4.7 m/s
        const bool surfaceRow =
            w.ghostSurface && w.surfaceNormal[i] != vector2D::zero;

        // A = s f with s = -rho: p = pMin, or 0
        kind[i] = laplacianMatrix::dirichlet;
        const scalar pAir = w.airPressure ? (*w.airPressure)[i] : 0;
        f[i] = (w.g & x[i]) - (surfaceRow ? pAir : pMin_)/w.rho0;
        if (surfaceRow)
        {
            w.surfaceNormal[i] = Zero;
            ++nReleased_;
        }
        ++n;
    }
    return n;
}


void Foam::SPH::pressurePoisson::solve()
{
    // Warm start from the last pressure
    isphWork& w = work_;
    const label n = w.parts.size();
    const scalarField& p = w.parts.field<scalar>("p");
    const vector2DField& x = w.parts.positions();
    xA_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        xA_[i] = p[i] - w.rho0*(w.g & x[i]);
    }

    const scalar cpuStart = processCpuSeconds();
    lastSolve_ = solver_->solve(laplacian_.matrix(), laplacian_.source(), xA_);
    solveCpuSeconds_ += processCpuSeconds() - cpuStart;
    nIterations_ += lastSolve_.nIterations();
    setPressure();

    if (!lastSolve_.converged() && stopIfNotConverged_)
    {
        throw stageFailure
        (
            "The pressure solve did not converge: residual "
          + Foam::name(lastSolve_.finalResidual()) + " after "
          + Foam::name(lastSolve_.nIterations()) + " iterations, tolerance "
          + Foam::name(solver_->tolerance()) + " (system/sphSolution"
            " solvers.p; ISPH { stopIfNotConverged no; } accepts it)"
        );
    }
}


Foam::label Foam::SPH::pressurePoisson::pocketResponse
(
    const labelUList& pocketOf,
    const label k,
    scalarField& phi
)
{
    // Rows' right-hand sides are linear in the surface values: a Dirichlet
    // row's is its value, a ghost row's source S holds -pAir M/delta
    // (ghostRows), pAir times its implicit source Sp = -M/delta, and an
    // equation row's right-hand side is -S
    const label n = work_.parts.size();
    const labelList& kind = laplacian_.kinds();
    vectorN b(vectorN::Zero(n));
    vectorN x(vectorN::Zero(n));
    forAll(pocketOf, i)
    {
        if (pocketOf[i] != k) continue;
        if (kind[i] == laplacianMatrix::dirichlet)
        {
            b[i] = 1;
        }
        else if (ghostSp_.size() && kind[i] == laplacianMatrix::interior)
        {
            b[i] = -ghostSp_[i];
        }
    }
    const scalar cpuStart = processCpuSeconds();
    const solverPerformance perf = solver_->solve(laplacian_.matrix(), b, x);
    solveCpuSeconds_ += processCpuSeconds() - cpuStart;
    nIterations_ += perf.nIterations();
    phi.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        phi[i] = x[i];
    }
    return perf.nIterations();
}


// ************************************************************************* //
