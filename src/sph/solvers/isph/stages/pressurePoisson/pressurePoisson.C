/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "pressurePoisson.H"
#include "openMPThreshold.H"
#include "checkedEntry.H"
#include "usawOperators.H"
#include "kernelDispatch.H"
#include "ghostSurface.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The p solver's entries. With a free surface a BoomerAMG hierarchy is
//  rebuilt at every step (reuse 1) unless the case gives reuse: the surface
//  rows change from step to step, and a hierarchy kept for BoomerAMG's
//  default 10 solves doubled the CPU of the obstacle dam-break at 2 mm
//  (benchmarks/README.md, "A free surface")
Foam::dictionary pSolverDict
(
    const Foam::dictionary& solution,
    const bool freeSurface
)
{
    Foam::dictionary dict(solution.subDict("solvers").subDict("p"));
    if
    (
        freeSurface && !dict.found("reuse")
     && dict.getOrDefault<Foam::word>("preconditioner", "none") == "BoomerAMG"
    )
    {
        dict.add("reuse", Foam::label(1));
    }
    return dict;
}

} // End anonymous namespace


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
    label* kind = laplacian_.kinds().data();
    const label equation = laplacianMatrix::interior;
    const label dirichlet = laplacianMatrix::dirichlet;
    const label extension = laplacianMatrix::extension;
    const label copy = laplacianMatrix::copy;


    // Kind of each row: a fluid particle at the free surface, or one no
    // other fluid particle reaches, has p = 0 (Dirichlet); a vertex
    // particle at or above the free surface is an extension row: its A is
    // the mean of its neighbours', the pressure continued, which the wall
    // terms of the fluid particles by the contact line see; a vertex no
    // fluid particle reaches (dry) matters only through the segments it
    // shares with reached vertices, and copies the A of such a neighbour
    // along the wall (else p = 0)
    labelList& copyFrom = laplacian_.copyFrom();
    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        bool reached = false;
        for (label k = off[i]; k < off[i + 1] && !reached; ++k)
        {
            reached = nbr[k] < nF && K.dWdrByR(r[k]) < 0;
        }
        if (i < nF)
        {
            const bool ghosts =
                work_.ghostSurface && work_.surfaceNormal[i] != vector2D::zero;
            kind[i] =
                ((surface[i] && !ghosts) || !reached) ? dirichlet : equation;
            if (kind[i] == dirichlet && work_.ghostSurface)
            {
                work_.surfaceNormal[i] = Zero;
            }
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
void Foam::SPH::pressurePoisson::setSources(const Kernel& K, const scalar dt)
{
    // Eq. (42): L{A} = rho/dt D{u**}
    isphWork& w = work_;
    usaw::div(K, w.nbrs, w.usaw, w.V, w.Ustar, source_);
    const scalar rho = w.rho0;
    forAll(source_, i)
    {
        source_[i] = rho/dt*source_[i];
    }

    if (w.ghostSurface)
    {
        ghostRows(K, dt);
    }
    nCompacted_ = 0;
    if (w.interiorCompaction > 0)
    {
        interiorRows(K, dt);
    }

    // p = 0 at the free surface: A = -rho g.x, i.e. s f with s = -rho
    // (set at construction) and f = g.x
    scalarList& f = laplacian_.dirichletValues();
    const vector2DField& x = w.parts.positions();
    const vector2D g = w.g;
    forAll(f, i)
    {
        f[i] = g & x[i];
    }
    if (w.airPressure)
    {
        // A surface row bordering a pocket: p = pAir, A = pAir - rho g.x
        const scalarField& pAir = *w.airPressure;
        for (label i = 0; i < w.nFluid; ++i)
        {
            f[i] -= pAir[i]/w.rho0;
        }
    }
}


template<class Kernel>
void Foam::SPH::pressurePoisson::ghostRows(const Kernel& K, const scalar dt)
{
    // Row a (minus the equation, B = 1): the ghosts add
    // (A_a + rho g.x_a) M_a/delta + rho g.m_a, m_a = sum_b c_ab r_ab over
    // the real neighbours, c_ab = -2 V_b (dW/dr/r)_ab/gamma_a, M_a = m_a.n,
    // with m_a taken along n (M_a n): its part along the surface comes
    // from the neighbours' disorder and the walls, and with a normal tilted
    // by theta would set p_a off rho |g| delta at first order in theta
    // (along n: rho |g| delta cos(theta))
    isphWork& w = work_;
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const vector2D* rij = w.nbrs.rij().cdata();
    const scalar* r = w.nbrs.r().cdata();
    const scalar* gamma = w.usaw.gamma().cdata();
    const vector2DField& x = w.parts.positions();
    const scalar delta = w.surfaceDistance;
    ghostSp_ = Zero;
    for (label i = 0; i < w.nFluid; ++i)
    {
        vector2D& n = w.surfaceNormal[i];
        if (!w.surface[i] || n == vector2D::zero) continue;
        vector2D m(Zero);
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            m -= 2*w.V[nbr[k]]*K.dWdrByR(r[k])/gamma[i]*rij[k];
        }
        const scalar M = m & n;
        if (!(M > 0))
        {
            n = Zero;
            continue;
        }
        ghostSp_[i] = -M/delta;
        source_[i] += w.rho0*((w.g & x[i]) + delta*(w.g & n))*M/delta;
        if (w.airPressure)
        {
            // The ghosts fall to the pocket's pressure on the surface line
            source_[i] -= (*w.airPressure)[i]*M/delta;
        }
        if (w.compaction > 0)
        {
            source_[i] +=
                w.compaction*w.rho0*diluted(K, i, off, nbr, r)/sqr(dt);
        }
    }
}


template<class Kernel>
void Foam::SPH::pressurePoisson::interiorRows(const Kernel& K, const scalar dt)
{
    // The density-invariant source of ISPH on the rows whose whole kernel
    // is water (a free-surface neighbour leaves the sum short by the air's
    // side, not by dilution)
    isphWork& w = work_;
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const scalar* r = w.nbrs.r().cdata();
    const scalar* gamma = w.usaw.gamma().cdata();
    const scalar full = latticeSum_;
    const scalar coeff = w.interiorCompaction*w.rho0/sqr(dt);
    for (label i = 0; i < w.nFluid; ++i)
    {
        // By a wall the USAW density is gamma's estimate, whose error on a
        // film carried up a paddle (the water wheel) the pull would feed
        if (w.surface[i] || gamma[i] < 1 - SMALL) continue;
        scalar sum = w.V[i]*K.W(0);
        bool cut = false;
        for (label k = off[i]; k < off[i + 1] && !cut; ++k)
        {
            const label b = nbr[k];
            if (b == i) continue;
            cut = b < w.nFluid && w.surface[b];
            sum += w.V[b]*K.W(r[k]);
        }
        // Below 2 % the disorder of a shifted lattice; above 10 % the edge
        // of a void the surface detection missed, which the pull would
        // close as a jet (the obstacle dam-break's trapped air behind the
        // obstacle, 0.41 s: 13.9 m/s on the floor): left alone
        const scalar deficit = 1 - sum/full;
        if (!cut && deficit > 0.02 && deficit <= 0.1)
        {
            source_[i] += coeff*(deficit - 0.02);
            ++nCompacted_;
        }
    }
}


template<class Kernel>
Foam::scalar Foam::SPH::pressurePoisson::diluted
(
    const Kernel& K,
    const label i,
    const label* off,
    const label* nbr,
    const scalar* r
)
{
    // 1 - rho_a/rho0 - 0.02 (in [0, 0.2]) with rho_a/rho0 the USAW density
    // (gamma_a rho_a = sum_b m_b w_ab over the fluid and vertex particles:
    // Ferrand et al. 2013, ref. [10] of Leroy et al. 2014) completed by the
    // ghost lattice beyond the surface line, over the full lattice's kernel
    // sum (1 on the top row of a lattice). By a wall gamma_a counts the
    // wall's side out, so the ghosts beyond the nearest wall's line are
    // left out too. (Not the mirror images of freeSurface's normals: a
    // sheet held at minWallDistance, dr/2, lies on their mirror line and
    // has none, so its wall side would read empty, 50 % diluted)
    const isphWork& w = work_;
    const scalar dr = 2*w.surfaceDistance;
    const label nearest = ghostSurface::nearestSegment(w, i);
    const vector2D nw
    (
        nearest >= 0
      ? w.usaw.segmentNormals()[w.usaw.segments()[nearest]]
      : vector2D::zero
    );
    const scalar dWall = nearest >= 0 ? w.usaw.distances()[nearest] : GREAT;
    scalar sum = w.V[i]*K.W(0)
      + ghostSurface::halfPlaneSum
        (
            K, dr, w.surfaceNormal[i], w.surfaceDistance, nw, dWall
        );
    for (label k = off[i]; k < off[i + 1]; ++k)
    {
        const label b = nbr[k];
        if (b == i) continue;
        // Already closer to a fluid neighbour than 0.7 dr: pulling on would
        // collapse a droplet too small ever to reach rho0 onto a point
        // (3 particles 0.07 dr apart at p = -1e7 Pa stopped the 2 mm
        // obstacle run at 0.134 s)
        if (b < w.nFluid && r[k] < 0.7*dr) return 0;
        sum += w.V[b]*K.W(r[k]);
    }
    const scalar rho = sum/(w.usaw.gamma()[i]*latticeSum_);
    // Below 2 % the lattice's disorder (the shifting), not dilution; at
    // most 20 %, so that the pull stays bounded
    return min(max(1 - rho - 0.02, scalar(0)), scalar(0.2));
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
    solver_(linearSolver::New("p", pSolverDict(solution, freeSurface))),
    stopIfNotConverged_(true),
    diagonalReinforcement_(1e-6),
    pRefValue_(0),
    source_(work.parts.size()),
    vertexNeighbours_(work.cloud.walls().points().size()),
    laplacian_(work.nbrs, work.usaw, work.V, work.nFluid),
    nIterations_(0),
    solveCpuSeconds_(0),
    nFloating_(0),
    latticeSum_(work.W.latticeSum()),
    nCompacted_(0),
    ghostSp_(work.ghostSurface ? work.parts.size() : 0, Zero),
    pMin_(-VGREAT),
    nAtPMin_(0),
    nReleased_(0)
{
    if (work.ghostSurface)
    {
        laplacian_.implicitSource(ghostSp_);
    }
    const dictionary& controls = solution.subOrEmptyDict("ISPH");
    stopIfNotConverged_ =
        controls.getOrDefault<bool>("stopIfNotConverged", stopIfNotConverged_);
    diagonalReinforcement_ = checkedScalar
    (
        controls, "diagonalReinforcement", diagonalReinforcement_, {0, 1}
    );
    if (!(diagonalReinforcement_ >= 0))
    {
        FatalIOErrorInFunction(controls.lookup("diagonalReinforcement"))
            << "Entry diagonalReinforcement " << diagonalReinforcement_
            << ": expected >= 0" << exit(FatalIOError);
    }
    pRefValue_ = checkedScalar
    (
        controls, "pRefValue", pRefValue_, {-VGREAT, VGREAT}, "Pa"
    );
    if (controls.found("pMin"))
    {
        if (!freeSurface_)
        {
            FatalIOErrorInFunction(controls.lookup("pMin"))
                << "Entry pMin: a confined flow's pressure level is"
                << " arbitrary (pRefValue), so a least pressure means"
                << " nothing; pMin is for flows with a free surface"
                << exit(FatalIOError);
        }
        pMin_ = checkedScalar
        (
            controls, "pMin", {-VGREAT, VGREAT},
            "the least pressure the liquid holds [Pa]"
        );
    }

    if (ownGradient_)
    {
        laplacian_.ownGradient(work.R);
    }
    laplacian_.diagonalFactor(freeSurface_ ? 1 : 1 + diagonalReinforcement_);
    laplacian_.dirichletScale(-work.rho0);

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
    if (work_.interiorCompaction > 0)
    {
        os  << nl << indent.c_str() << "rows of water only (no free surface,"
            << " no wall in the kernel): density source "
            << work_.interiorCompaction << " rho0 (deficit - 0.02)/dt^2 where"
            << " the kernel sum is 2-10 % short (interiorCompaction; beyond"
            << " 000_...)";
    }
    if (!freeSurface_)
    {
        os  << nl << indent.c_str() << "confined flow (no free surface):"
            << " diagonal x (1 + " << diagonalReinforcement_
            << "), mean fluid p = " << pRefValue_;
    }
    if (pMin_ > -VGREAT)
    {
        os  << nl << indent.c_str() << "the liquid holds no pressure below"
            << " pMin " << pMin_ << " Pa (it separates from a wall"
            << " instead of pulling on it";
        if (work_.ghostSurface)
        {
            os  << "; a free-surface particle below it is released at"
                << " p = 0";
        }
        os  << ")";
    }
    os  << nl << indent.c_str()
        << (
               stopIfNotConverged_
             ? "a solve that does not converge stops the run"
             : "solves that do not converge are accepted (stopIfNotConverged no)"
           );
}


template<class Kernel>
void Foam::SPH::pressurePoisson::assemble(const Kernel& K)
{
    laplacian_.assemble(K, source_);
    const label nNew = work_.ghostSurface ? anchorFloatingClusters() : 0;
    if (nNew)
    {
        nFloating_ += nNew;
        laplacian_.assemble(K, source_);
    }
}


void Foam::SPH::pressurePoisson::execute(const scalar dt)
{
    isphWork& w = work_;
    wallCondition(dt);
    nFloating_ = 0;
    dispatch(w.W, [&](const auto& K)
    {
        setSources(K, dt);
        classifyRows(K);
        assemble(K);
    });
    if (!freeSurface_)
    {
        makeCompatible();
    }

    solve();

    // The liquid separates rather than pull below pMin: the rows solved
    // below it are held there and the system solved again (a few passes:
    // each can pull others below). Held rows can leave others floating (a
    // vertex extension row averages its non-Dirichlet neighbours only), so
    // each assembly anchors again
    nAtPMin_ = 0;
    nReleased_ = 0;
    for (label pass = 0; pass < 4 && pMin_ > -VGREAT; ++pass)
    {
        const label nNew = holdAtPMin();
        if (!nNew) break;
        nAtPMin_ += nNew;
        dispatch(w.W, [&](const auto& K) { assemble(K); });
        solve();
    }
}


// ************************************************************************* //
