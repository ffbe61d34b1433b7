/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The stages of an ISPH-USAW time step (000_8c7cd3aabddcf18a.txt
    section 3.2) and the checks after it. The particle sums are the USAW
    operators (src/sph/operators/usawOperators), templates over the
    concrete kernel reached once per call through SPH::dispatch.

\*---------------------------------------------------------------------------*/

#include "isph.H"
#include "Time.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

#include <chrono>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::isph::moveWalls(const scalar t, const bool setVelocity)
{
    if (!motion_->any())
    {
        return;
    }
    motion_->vertices(t, wallX_, wallU_);
    vector2DField& x = parts_.positions();
    vector2DField& U = parts_.field<vector2D>("U");
    forAll(wallX_, v)
    {
        x[nFluid_ + v] = wallX_[v];
        if (setVelocity)
        {
            U[nFluid_ + v] = wallU_[v];
        }
    }
    if (motion_->movesGeometry())
    {
        usaw_->updateGeometry(wallX_);
    }
}


void Foam::SPH::isph::findNeighbours()
{
    const auto start = now();
    cloud_->updateCells();
    nbrs_.build(cloud_->cells(), parts_.positions(), kernel_->support(), true);
    usaw_->update(parts_.positions());
    times_.neighbours += secondsSince(start);
}


void Foam::SPH::isph::predictVelocity(const scalar dt)
{
    const auto start = now();
    const vector2DField& U = parts_.field<vector2D>("U");

    // Eq. (31) without gravity (carried by A = p - rho g.x) with the wall
    // friction (15)-(17)
    if (nu_ > 0)
    {
        dispatch(*kernel_, [&](const auto& K)
        {
            usaw::laminarViscous
            (
                K, nbrs_, *usaw_, V_, rho0_*nu_, U, dr_, visc_
            );
        });
    }
    const label n = parts_.size();
    for (label i = 0; i < nFluid_; ++i)
    {
        Ustar_[i] = nu_ > 0 ? U[i] + (dt/rho0_)*visc_[i] : U[i];
    }
    // Vertex particles: the wall velocity at t^n
    for (label i = nFluid_; i < n; ++i)
    {
        Ustar_[i] = U[i];
    }
    times_.operators += secondsSince(start);
}


void Foam::SPH::isph::detectFreeSurface(const scalar dt)
{
    const auto start = now();
    dispatch(*kernel_, [&](const auto& K)
    {
        usaw::divPosition(K, nbrs_, *usaw_, V_, divR_);
    });
    times_.operators += secondsSince(start);

    const label n = parts_.size();
    const label* off = nbrs_.offsets().cdata();
    const label* nbr = nbrs_.indices().cdata();
    const vector2D* rij = nbrs_.rij().cdata();
    const scalar* r = nbrs_.r().cdata();
    const vector2D* U = parts_.field<vector2D>("U").cdata();

    // Section 3.2: D{r} <= 1.5 marks the free surface ...
    for (label i = 0; i < n; ++i)
    {
        surface_[i] = divR_[i] <= freeSurfaceDivR_;
    }

    // ... except for a particle about to hit a wall and the vertex it
    // would hit, eq. (39): its distance to the vertex after a step at its
    // velocity below h q_max/8
    const scalar reach = kernel_->support()/8;
    labelList notSurface(n, 0);
    for (label i = 0; i < nFluid_; ++i)
    {
        if (!surface_[i]) continue;
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label v = nbr[k];
            if (v < nFluid_ || r[k] == 0) continue;
            if (r[k] + dt*(U[i] & rij[k])/r[k] < reach)
            {
                notSurface[i] = 1;
                notSurface[v] = 1;
            }
        }
    }
    nSurface_ = 0;
    for (label i = 0; i < n; ++i)
    {
        surface_[i] = surface_[i] && !notSurface[i];
        if (i < nFluid_ && surface_[i]) ++nSurface_;
    }

    // Particles within h q_max/2 of the free surface are not shifted
    // (section 3.2, after eq. (37))
    const scalar near = 0.5*kernel_->support();
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < nFluid_; ++i)
    {
        label isNear = surface_[i];
        for (label k = off[i]; k < off[i + 1] && !isNear; ++k)
        {
            isNear = surface_[nbr[k]] && r[k] < near;
        }
        nearSurface_[i] = isNear;
    }
}


void Foam::SPH::isph::renormalise()
{
    // R = G-{r}^-1: R . G-{p} is exact for a linear p, also where the
    // kernel is cut by the free surface. A particle with too few
    // neighbours to span the plane (a droplet, a jet one particle thick)
    // keeps G-{p}.
    const auto start = now();
    dispatch(*kernel_, [&](const auto& K)
    {
        usaw::renormalisation
        (
            K, nbrs_, *usaw_, V_, parts_.positions(), minMomentDet_, R_
        );
    });
    times_.operators += secondsSince(start);
}


void Foam::SPH::isph::projectVelocity(const scalar dt)
{
    const auto start = now();
    const scalarField& p = parts_.field<scalar>("p");
    dispatch(*kernel_, [&](const auto& K)
    {
        if (pressureGradient_ == pressureGradientType::antisymmetric)
        {
            usaw::gradPlus(K, nbrs_, *usaw_, V_, p, gradP_);
        }
        else
        {
            usaw::gradMinus(K, nbrs_, *usaw_, V_, R_, p, gradP_);
        }
    });

    // Eq. (32); gravity, left out of u**, comes back here
    vector2D* U = parts_.field<vector2D>("U").data();
    for (label i = 0; i < nFluid_; ++i)
    {
        U[i] = Ustar_[i] + dt*(g_ - gradP_[i]/rho0_);
    }
    times_.operators += secondsSince(start);
}


void Foam::SPH::isph::shift()
{
    findNeighbours();

    const auto start = now();
    vector2DField& U = parts_.field<vector2D>("U");
    dispatch(*kernel_, [&](const auto& K)
    {
        usaw::concentrationGradient(K, nbrs_, *usaw_, V_, gradC_);
        usaw::gradMinus(K, nbrs_, *usaw_, V_, U, gradU_);
    });

    // Eqs. (35)-(36) and the Taylor correction (38): (grad u)_ij = d_i u_j
    // (OpenFOAM's), so dr . G-{u} is the change of u along dr
    const scalar coeff = shiftCoeff_*sqr(kernel_->h());
    vector2D* x = parts_.positions().data();
    scalar maxShift2 = 0;
    for (label i = 0; i < nFluid_; ++i)
    {
        if (nearSurface_[i]) continue;
        const vector2D delta(-coeff*gradC_[i]);
        U[i] += delta & gradU_[i];
        x[i] += delta;
        maxShift2 = max(maxShift2, magSqr(delta));
    }
    maxShift_ = std::sqrt(maxShift2);
    times_.operators += secondsSince(start);
}


Foam::label Foam::SPH::isph::holdOffWalls()
{
    if (minWallDistance_ <= 0)
    {
        return 0;
    }
    const label* off = usaw_->offsets().cdata();
    const label* seg = usaw_->segments().cdata();
    const labelPair* ends = usaw_->segmentParticles().cdata();
    const vector2D* normal = usaw_->segmentNormals().cdata();
    const vector2D* x0 = xStart_.cdata();
    vector2D* x = parts_.positions().data();
    vector2D* U = parts_.field<vector2D>("U").data();
    const scalar dMin = minWallDistance_;

    // The segments within reach of the particle's last neighbour search;
    // a segment's vertex ends are left to its neighbours (a particle by a
    // corner sees both walls' interiors), as is one that was behind the
    // segment's line at the start of the step (the far side of a plate)
    label nHeld = 0;
    #pragma omp parallel for schedule(static) reduction(+:nHeld)
    for (label i = 0; i < nFluid_; ++i)
    {
        bool held = false;
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label s = seg[k];
            const vector2D& n = normal[s];
            const vector2D& a = x[ends[s].first()];
            const vector2D e(x[ends[s].second()] - a);
            const scalar t = ((x[i] - a) & e)/magSqr(e);
            const scalar d = (x[i] - a) & n;
            if (t <= 0 || t >= 1 || d >= dMin || ((x0[i] - a) & n) < 0)
            {
                continue;
            }
            x[i] += (dMin - d)*n;
            const vector2D uWall
            (
                (1 - t)*U[ends[s].first()] + t*U[ends[s].second()]
            );
            const scalar un = (U[i] - uWall) & n;
            if (un < 0)
            {
                U[i] -= un*n;
            }
            held = true;
        }
        nHeld += held;
    }
    return nHeld;
}


Foam::label Foam::SPH::isph::findBadParticle(word& what) const
{
    const vector2D* x = parts_.positions().cdata();
    const vector2D* U = parts_.field<vector2D>("U").cdata();
    const scalar* p = parts_.field<scalar>("p").cdata();

    for (label i = 0; i < nFluid_; ++i)
    {
        const bool finite =
            std::isfinite(x[i].x()) && std::isfinite(x[i].y())
         && std::isfinite(U[i].x()) && std::isfinite(U[i].y())
         && std::isfinite(p[i]);
        if (!finite)
        {
            what = "NaN or Inf in the position, velocity or pressure of";
            return i;
        }
        if
        (
            x[i].x() < boxMin_.x() || x[i].y() < boxMin_.y()
         || x[i].x() > boxMax_.x() || x[i].y() > boxMax_.y()
        )
        {
            what = "Left the domain (the walls' box with a margin):";
            return i;
        }
    }

    // Fluid particles whose step crossed a (still) wall segment
    if (crossing_)
    {
        List<vector2D> xEnd(SubList<vector2D>(parts_.positions(), nFluid_));
        List<vector2D> UEnd(SubList<vector2D>(parts_.field<vector2D>("U"), nFluid_));
        if (crossing_->bounce(xStart_, xEnd, UEnd, nFluid_))
        {
            for (label i = 0; i < nFluid_; ++i)
            {
                if (xEnd[i] != x[i])
                {
                    what = "Crossed a wall:";
                    return i;
                }
            }
        }
    }
    return -1;
}


void Foam::SPH::isph::fail(const string& what, const label i)
{
    const scalar tFailed = runTime_.value();
    string where;
    if (i >= 0)
    {
        const vector2D& x = parts_.positions()[i];
        where = " particle id " + Foam::name(parts_.field<label>("id")[i])
          + " at (" + Foam::name(x.x()) + " " + Foam::name(x.y()) + ")";
    }

    // The state at the start of the step was good: put it back and write
    // it at the time it belongs to
    parts_.positions() = xStart_;
    parts_.field<vector2D>("U") = UStart_;
    parts_.field<scalar>("p") = pStart_;
    maxAccel_ = maxAccelStart_;
    lastDeltaT_ = lastDeltaTStart_;
    runTime_.setTime(runTime_.value() - runTime_.deltaTValue(), runTime_.timeIndex() - 1);
    runTime_.writeNow();
    write();

    FatalErrorInFunction
        << what.c_str() << where.c_str() << nl
        << "    at time " << tFailed << " s (time step "
        << runTime_.timeIndex() + 1 << ", deltaT " << runTime_.deltaTValue()
        << " s)" << nl
        << "The last good state, time " << runTime_.timeName()
        << ", is written in " << runTime_.timePath() << nl
        << exit(FatalError);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::isph::evolve()
{
    const auto stepStart = now();
    const timings before = times_;

    const scalar dt = runTime_.deltaTValue();
    const scalar tNew = runTime_.value();
    const scalar tOld = tNew - dt;

    xStart_ = parts_.positions();
    UStart_ = parts_.field<vector2D>("U");
    pStart_ = parts_.field<scalar>("p");
    maxAccelStart_ = maxAccel_;
    lastDeltaTStart_ = lastDeltaT_;

    if (deltaT0_ < 0)
    {
        deltaT0_ = dt;
    }
    if (dt < minDeltaTFraction_*deltaT0_)
    {
        fail
        (
            "The time step collapsed to " + Foam::name(dt) + " s, below "
          + Foam::name(minDeltaTFraction_) + " of the first one ("
          + Foam::name(deltaT0_) + " s)",
            -1
        );
    }

    vector2D* x = parts_.positions().data();
    vector2D* U = parts_.field<vector2D>("U").data();

    // Eq. (30), the walls half way
    for (label i = 0; i < nFluid_; ++i)
    {
        x[i] += 0.5*dt*U[i];
    }
    moveWalls(tOld + 0.5*dt, false);
    findNeighbours();

    predictVelocity(dt);
    if (pressureGradient_ == pressureGradientType::renormalised)
    {
        renormalise();
    }
    if (freeSurface_)
    {
        detectFreeSurface(dt);
    }
    solvePressure(dt, tOld, tNew);
    if (!lastSolve_.converged() && stopIfNotConverged_)
    {
        fail
        (
            "The pressure solve did not converge: residual "
          + Foam::name(lastSolve_.finalResidual()) + " after "
          + Foam::name(lastSolve_.nIterations()) + " iterations, tolerance "
          + Foam::name(pSolver_->tolerance()) + " (system/sphSolution"
            " solvers.p; ISPH { stopIfNotConverged no; } accepts it)",
            -1
        );
    }
    projectVelocity(dt);

    // Eq. (34), the walls at the new time
    for (label i = 0; i < nFluid_; ++i)
    {
        x[i] += 0.5*dt*U[i];
    }
    moveWalls(tNew, true);

    if (shifting_)
    {
        shift();
    }
    nHeld_ = holdOffWalls();
    nHeldTotal_ += nHeld_;

    // The acceleration that limits the next step, eq. (49)
    scalar maxA2 = 0, maxU2 = 0;
    for (label i = 0; i < nFluid_; ++i)
    {
        maxA2 = max(maxA2, magSqr(U[i] - UStart_[i]));
        maxU2 = max(maxU2, magSqr(U[i]));
    }
    maxAccel_ = std::sqrt(maxA2)/dt;
    maxSpeed_ = std::sqrt(maxU2);
    lastDeltaT_ = dt;

    word what;
    const label bad = findBadParticle(what);
    if (bad >= 0)
    {
        fail(what, bad);
    }

    // The cell list that function objects search: the final positions
    const auto cellsStart = now();
    cloud_->updateCells();
    times_.neighbours += secondsSince(cellsStart);

    ++nSteps_;
    nSolverIterations_ += lastSolve_.nIterations();
    times_.other += secondsSince(stepStart) - (times_.total() - before.total());
}


// ************************************************************************* //
