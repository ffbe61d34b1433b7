/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "pressurePoisson.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    enum rowKind : Foam::label
    {
        equation = 0, dirichlet = 1, extension = 2, copy = 3
    };

    //- Eigen's compressed rows hold each column once, in ascending order
    void compress(std::vector<std::pair<int, Foam::scalar>>& row)
    {
        std::sort(row.begin(), row.end());
        std::size_t last = 0;
        for (std::size_t k = 1; k < row.size(); ++k)
        {
            if (row[k].first == row[last].first)
            {
                row[last].second += row[k].second;
            }
            else
            {
                row[++last] = row[k];
            }
        }
        row.resize(last + 1);
    }
}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::pressurePoisson::classifyRows(const Kernel& K)
{
    const label n = work_.parts.size();
    const label nF = work_.nFluid;
    const label* off = work_.nbrs.offsets().cdata();
    const label* nbr = work_.nbrs.indices().cdata();
    const scalar* r = work_.nbrs.r().cdata();
    const label* surface = work_.surface.cdata();
    label* kind = rowKind_.data();


    // Kind of each row: a fluid particle at the free surface, or one no
    // other fluid particle reaches, has p = 0 (Dirichlet); a vertex
    // particle at or above the free surface is an extension row: its A is
    // the mean of its neighbours', the pressure continued, which the wall
    // terms of the fluid particles by the contact line see; a vertex no
    // fluid particle reaches (dry) matters only through the segments it
    // shares with reached vertices, and copies the A of such a neighbour
    // along the wall (else p = 0)
    labelList& copyFrom = copyFrom_;
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        bool reached = false;
        for (label k = off[i]; k < off[i + 1] && !reached; ++k)
        {
            reached = nbr[k] < nF && K.dWdrByR(r[k]) < 0;
        }
        if (i < nF)
        {
            kind[i] = (surface[i] || !reached) ? dirichlet : equation;
        }
        else
        {
            kind[i] = !reached ? copy : surface[i] ? extension : equation;
        }
    }
    for (label i = nF; i < n; ++i)
    {
        if (kind[i] != copy) continue;
        copyFrom[i] = -1;
        for (const label v : vertexNeighbours_[i - nF])
        {
            if (kind[nF + v] == equation || kind[nF + v] == extension)
            {
                copyFrom[i] = nF + v;
                break;
            }
        }
        if (copyFrom[i] < 0)
        {
            kind[i] = dirichlet;
        }
    }
}


template<class Kernel>
void Foam::SPH::pressurePoisson::assemble(const Kernel& K, const scalar dt)
{
    const label n = work_.parts.size();
    const label nF = work_.nFluid;
    const label* off = work_.nbrs.offsets().cdata();
    const label* nbr = work_.nbrs.indices().cdata();
    const vector2D* rij = work_.nbrs.rij().cdata();
    const scalar* r = work_.nbrs.r().cdata();
    const scalar* gamma = work_.usaw.gamma().cdata();
    const vector2D* gradGamma = work_.usaw.gradGamma().cdata();
    const label* wOff = work_.usaw.offsets().cdata();
    const label* seg = work_.usaw.segments().cdata();
    const vector2D* gradGammaAs = work_.usaw.gradGammaAs().cdata();
    const labelPair* ends = work_.usaw.segmentParticles().cdata();
    const vector2D* x = work_.parts.positions().cdata();
    const scalar* V = work_.V.cdata();
    const scalar* divU = divU_.cdata();
    const scalar* dAdn = dAdn_.cdata();
    const tensor2D* R = work_.R.cdata();
    const label* kind = rowKind_.cdata();
    const label* copyFrom = copyFrom_.cdata();
    const bool ownGradient = ownGradient_;
    const scalar diagFactor = freeSurface_ ? 1 : 1 + diagonalReinforcement_;
    const scalar rho = work_.rho0;
    const vector2D g = work_.g;


    // Each row as (column, coefficient) pairs; a Dirichlet neighbour's
    // term goes to the right-hand side
    b_.resize(n);
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        std::vector<std::pair<int, scalar>>& row = rows_[i];
        row.clear();
        if (kind[i] == dirichlet)
        {
            row.emplace_back(i, 1);
            b_[i] = -rho*(g & x[i]);
            continue;
        }
        if (kind[i] == copy)
        {
            row.emplace_back(i, 1);
            row.emplace_back(copyFrom[i], -1);
            compress(row);
            b_[i] = 0;
            continue;
        }

        scalar diag = 0;
        scalar bi = 0;
        auto add = [&](const label j, const scalar c)
        {
            // c (A_i - A_j)
            diag += c;
            if (kind[j] == dirichlet)
            {
                bi -= c*rho*(g & x[j]);
            }
            else
            {
                row.emplace_back(j, -c);
            }
        };

        const scalar invGamma = 1/gamma[i];
        const bool sources = kind[i] == equation;
        // The fluid particle's own normal gradient, eq. (10) as printed:
        // (grad A)_a . grad gamma_a/gamma_a with (grad A)_a = R G-{A}, the
        // gradient of the projection (eq. (40) doubles the wall's instead,
        // and the projection then leaves the divergence of a particle
        // driven towards a wall); q = R^T grad gamma_a/gamma_a
        const bool own = sources && ownGradient && i < nF;
        const vector2D q
        (
            own ? invGamma*(R[i].T() & gradGamma[i]) : vector2D::zero
        );

        // One entry per neighbour (an extension row averages over the fluid
        // and the reached vertices)
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label j = nbr[k];
            if (sources || j < nF || kind[j] == equation || kind[j] == extension)
            {
                scalar c = -2*invGamma*V[j]*K.dWdrByR(r[k]);
                if (own)
                {
                    c -= invGamma*V[j]*(K.gradW(rij[k], r[k]) & q);
                }
                add(j, c);
            }
        }

        if (sources)
        {
            bi -= rho/dt*divU[i];
            for (label k = wOff[i]; k < wOff[i + 1]; ++k)
            {
                if (own)
                {
                    // (A_a - A_s) grad gamma_as . q, A_s the vertices' mean
                    const scalar f = invGamma*(gradGammaAs[k] & q);
                    add(ends[seg[k]].first(), 0.5*f);
                    add(ends[seg[k]].second(), 0.5*f);
                }
                bi -= (own ? 1 : 2)*invGamma*dAdn[seg[k]]*mag(gradGammaAs[k]);
            }
        }
        row.emplace_back(i, diagFactor*diag);
        b_[i] = bi;

        compress(row);
    }
}


void Foam::SPH::pressurePoisson::fillMatrix()
{
    const label n = work_.parts.size();
    A_.resize(n, n);
    int* start = A_.outerIndexPtr();
    start[0] = 0;
    for (label i = 0; i < n; ++i)
    {
        start[i + 1] = start[i] + rows_[i].size();
    }
    A_.resizeNonZeros(start[n]);
    int* col = A_.innerIndexPtr();
    scalar* val = A_.valuePtr();
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        int k = start[i];
        for (const auto& entry : rows_[i])
        {
            col[k] = entry.first;
            val[k] = entry.second;
            ++k;
        }
    }
}


void Foam::SPH::pressurePoisson::wallCondition(const scalar dt)
{
    // Eq. (43) with the vertex particles' u* = u_w^n + dt g (45): zero at
    // a wall that does not accelerate
    if (!work_.motion.any())
    {
        return;
    }
    const label nFluid = work_.nFluid;
    work_.motion.vertices(runTime_.value(), work_.wallX, work_.wallU);
    const vector2DField& U = work_.parts.field<vector2D>("U");
    const List<labelPair>& ends = work_.usaw.segmentParticles();
    const List<vector2D>& normal = work_.usaw.segmentNormals();
    forAll(dAdn_, s)
    {
        const label v1 = ends[s].first();
        const label v2 = ends[s].second();
        const vector2D uOld(0.5*(U[v1] + U[v2]));
        const vector2D uNew
        (
            0.5*(work_.wallU[v1 - nFluid] + work_.wallU[v2 - nFluid])
        );
        dAdn_[s] = work_.rho0*((uOld - uNew) & normal[s])/dt;
    }
}


void Foam::SPH::pressurePoisson::makeCompatible()
{
    const scalar* gamma = work_.usaw.gamma().cdata();
    const scalarList& V = work_.V;
    const label n = work_.parts.size();
    scalar sumW = 0, sumWB = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar w = V[i]*gamma[i];
        sumW += w;
        sumWB += w*b_[i];
    }
    const scalar mean = sumWB/sumW;
    for (label i = 0; i < n; ++i)
    {
        if (V[i] > 0)
        {
            b_[i] -= mean;
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::pressurePoisson::pressurePoisson
(
    isphWork& work,
    const Time& runTime,
    const dictionary& solution,
    const bool ownGradient,
    const bool freeSurface
)
:
    stage
    (
        "pressurePoisson", {"Ustar", "R", "freeSurface"}, {"p"},
        "pressure Poisson"
    ),
    work_(work),
    runTime_(runTime),
    ownGradient_(ownGradient),
    freeSurface_(freeSurface),
    solver_(linearSolver::New("p", solution.subDict("solvers").subDict("p"))),
    stopIfNotConverged_(true),
    diagonalReinforcement_(1e-6),
    pRefValue_(0),
    divU_(work.parts.size()),
    dAdn_(work.cloud.walls().segments().size(), Zero),
    rowKind_(work.parts.size(), Zero),
    copyFrom_(work.parts.size(), label(-1)),
    vertexNeighbours_(work.cloud.walls().points().size()),
    rows_(work.parts.size()),
    nIterations_(0)
{
    const dictionary& controls = solution.subOrEmptyDict("ISPH");
    stopIfNotConverged_ =
        controls.getOrDefault<bool>("stopIfNotConverged", stopIfNotConverged_);
    diagonalReinforcement_ = controls.getOrDefault<scalar>
    (
        "diagonalReinforcement", diagonalReinforcement_
    );
    if (!(diagonalReinforcement_ >= 0))
    {
        FatalIOErrorInFunction(controls.lookup("diagonalReinforcement"))
            << "Entry diagonalReinforcement " << diagonalReinforcement_
            << ": expected >= 0" << exit(FatalIOError);
    }
    pRefValue_ = controls.getOrDefault<scalar>("pRefValue", pRefValue_);

    for (const labelPair& e : work.cloud.walls().segments())
    {
        vertexNeighbours_[e.first()].append(e.second());
        vertexNeighbours_[e.second()].append(e.first());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::pressurePoisson::describe(Ostream& os) const
{
    const string indent("                        ");
    os  << "eqs. (41)-(44) for p + rho g z, wall condition (43), Laplacian "
        << (ownGradient_ ? "(10) with the particle's own gradient" : "(40)")
        << nl << indent.c_str();
    solver_->write(os);
    if (!freeSurface_)
    {
        os  << nl << indent.c_str() << "confined flow (no free surface):"
            << " diagonal x (1 + " << diagonalReinforcement_
            << "), mean fluid p = " << pRefValue_;
    }
    os  << nl << indent.c_str()
        << (
               stopIfNotConverged_
             ? "a solve that does not converge stops the run"
             : "solves that do not converge are accepted (stopIfNotConverged no)"
           );
}


void Foam::SPH::pressurePoisson::execute(const scalar dt)
{
    isphWork& w = work_;
    wallCondition(dt);
    dispatch(w.W, [&](const auto& K)
    {
        usaw::div(K, w.nbrs, w.usaw, w.V, w.Ustar, divU_);
        classifyRows(K);
        assemble(K, dt);
    });
    fillMatrix();
    if (!freeSurface_)
    {
        makeCompatible();
    }

    // Warm start from the last pressure
    const label n = w.parts.size();
    const scalarField& p = w.parts.field<scalar>("p");
    const vector2DField& x = w.parts.positions();
    xA_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        xA_[i] = p[i] - w.rho0*(w.g & x[i]);
    }

    lastSolve_ = solver_->solve(A_, b_, xA_);
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


// ************************************************************************* //
