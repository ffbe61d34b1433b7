/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The pressure Poisson equation of ISPH-USAW, 000_8c7cd3aabddcf18a.txt
    eqs. (40)-(44), for A = p - rho g.x (eq. (41): the Laplacian of p and
    of A agree, and A is uniform in a fluid at rest):

        2/gamma_a sum_b V_b (A_a - A_b)/r_ab^2 r_ab . grad w_ab
      = rho/dt D_a{u**} + 2/gamma_a sum_s dA/dn_s |grad gamma_as|

    with dA/dn_s = rho (u_w^n - u_w^{n+1}).n_s/dt, eq. (43) for the vertex
    particles' u* = u_w^n + dt g (45). Row a of the matrix is minus this
    equation, so that the diagonal is positive:

        sum_b c_ab (A_a - A_b) = b_a,   c_ab = -2 V_b (dW/dr/r)_ab/gamma_a >= 0

    Free-surface fluid particles (and isolated ones) have p = 0, i.e.
    A = -rho g.x: an identity row, and the value moved to the right-hand
    side of the others. Vertex particles at or above the free surface have
    rows without sources instead: their A is the mean of their neighbours',
    the pressure continued (uniform A at rest), and those out of the
    fluid's reach copy the A of a reached neighbour along the wall, so the
    wall terms by the contact line see no kink to p = 0 along the dry
    wall.

\*---------------------------------------------------------------------------*/

#include "isph.H"
#include "Time.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::isph::assemblePressure(const Kernel& K, const scalar dt)
{
    const label n = parts_.size();
    const label nF = nFluid_;
    const label* off = nbrs_.offsets().cdata();
    const label* nbr = nbrs_.indices().cdata();
    const vector2D* rij = nbrs_.rij().cdata();
    const scalar* r = nbrs_.r().cdata();
    const scalar* gamma = usaw_->gamma().cdata();
    const vector2D* gradGamma = usaw_->gradGamma().cdata();
    const label* wOff = usaw_->offsets().cdata();
    const label* seg = usaw_->segments().cdata();
    const vector2D* gradGammaAs = usaw_->gradGammaAs().cdata();
    const labelPair* ends = usaw_->segmentParticles().cdata();
    const vector2D* x = parts_.positions().cdata();
    const scalar* V = V_.cdata();
    const scalar* divU = divU_.cdata();
    const scalar* dAdn = dAdn_.cdata();
    const label* surface = surface_.cdata();
    const tensor2D* R = R_.cdata();
    label* kind = rowKind_.data();
    const bool ownGradient = pressureGradient_ == pressureGradientType::renormalised;
    const scalar diagFactor = freeSurface_ ? 1 : 1 + diagonalReinforcement_;
    const scalar rho = rho0_;
    const vector2D g = g_;

    // Kind of each row: a fluid particle at the free surface, or one no
    // other fluid particle reaches, has p = 0 (Dirichlet); a vertex
    // particle at or above the free surface is an extension row: its A is
    // the mean of its neighbours', the pressure continued, which the wall
    // terms of the fluid particles by the contact line see; a vertex no
    // fluid particle reaches (dry) matters only through the segments it
    // shares with reached vertices, and copies the A of such a neighbour
    // along the wall (else p = 0)
    enum rowKind : label
    {
        equation = 0, dirichlet = 1, extension = 2, copy = 3
    };
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
            std::sort(row.begin(), row.end());
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

        // Eigen's compressed rows hold each column once, in ascending order
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

    // Compressed row storage
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


void Foam::SPH::isph::makeCompatible()
{
    // Without a Dirichlet row the fluid rows hold A only through
    // differences: sum_a V_a gamma_a (row a) = 0 for any A (the pair sums
    // are antisymmetric), so only a right-hand side with
    // sum_a V_a gamma_a b_a = 0 has a solution
    const scalar* gamma = usaw_->gamma().cdata();
    const label n = parts_.size();
    scalar sumW = 0, sumWB = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar w = V_[i]*gamma[i];
        sumW += w;
        sumWB += w*b_[i];
    }
    const scalar mean = sumWB/sumW;
    for (label i = 0; i < n; ++i)
    {
        if (V_[i] > 0)
        {
            b_[i] -= mean;
        }
    }
}


void Foam::SPH::isph::solvePressure
(
    const scalar dt,
    const scalar tOld,
    const scalar tNew
)
{
    const auto start = now();

    // Wall condition (43) for A: the wall's acceleration along its normal
    const label nSegments = dAdn_.size();
    if (motion_->any())
    {
        motion_->vertices(tNew, wallX_, wallU_);
        const vector2DField& U = parts_.field<vector2D>("U");
        const List<labelPair>& ends = usaw_->segmentParticles();
        const List<vector2D>& normal = usaw_->segmentNormals();
        for (label s = 0; s < nSegments; ++s)
        {
            const label v1 = ends[s].first();
            const label v2 = ends[s].second();
            const vector2D uOld(0.5*(U[v1] + U[v2]));
            const vector2D uNew(0.5*(wallU_[v1 - nFluid_] + wallU_[v2 - nFluid_]));
            dAdn_[s] = rho0_*((uOld - uNew) & normal[s])/dt;
        }
    }

    dispatch(*kernel_, [&](const auto& K)
    {
        usaw::div(K, nbrs_, *usaw_, V_, Ustar_, divU_);
    });
    times_.operators += secondsSince(start);

    const auto assemblyStart = now();
    dispatch(*kernel_, [&](const auto& K)
    {
        assemblePressure(K, dt);
    });
    if (!freeSurface_)
    {
        makeCompatible();
    }

    // Warm start from the last pressure
    const label n = parts_.size();
    scalarField& p = parts_.field<scalar>("p");
    const vector2DField& x = parts_.positions();
    xA_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        xA_[i] = p[i] - rho0_*(g_ & x[i]);
    }
    times_.assembly += secondsSince(assemblyStart);

    const auto solveStart = now();
    lastSolve_ = pSolver_->solve(A_, b_, xA_);
    times_.solve += secondsSince(solveStart);

    for (label i = 0; i < n; ++i)
    {
        p[i] = xA_[i] + rho0_*(g_ & x[i]);
    }
    if (!freeSurface_)
    {
        // The level of a confined flow's pressure: its mean over the fluid
        scalar mean = 0;
        for (label i = 0; i < nFluid_; ++i)
        {
            mean += p[i];
        }
        mean /= nFluid_;
        for (label i = 0; i < n; ++i)
        {
            p[i] += pRefValue_ - mean;
        }
    }
}


// ************************************************************************* //
