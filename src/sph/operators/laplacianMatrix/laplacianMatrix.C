/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "laplacianMatrix.H"
#include "sortNearlyAscending.H"
#include "openMPThreshold.H"
#include "error.H"

#include <algorithm>
#include <functional>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::laplacianMatrix::laplacianMatrix
(
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const label nFluid
)
:
    nbrs_(nbrs),
    walls_(walls),
    V_(V),
    nFluid_(nFluid),
    B_(nullptr),
    ones_(V.size(), scalar(1)),
    R_(nullptr),
    diagonalFactor_(1),
    kinds_(V.size(), label(interior)),
    copyFrom_(V.size(), label(-1)),
    dirichletValues_(V.size(), Zero),
    dirichletScale_(1),
    wallFlux_(walls.segmentParticles().size(), Zero),
    Sp_(nullptr),
    robinK_(nullptr),
    robinG_(nullptr),
    robinMinDistance_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::laplacianMatrix::check(const scalarUList& S) const
{
    // O(1) checks, always on: the row loop has none of its own
    const label n = V_.size();
    const bool sizesFit =
        nbrs_.size() == n && walls_.size() >= n && S.size() == n
     && kinds_.size() == n && copyFrom_.size() == n
     && dirichletValues_.size() == n
     && (B_ ? B_->size() : ones_.size()) == n && (!R_ || R_->size() == n)
     && wallFlux_.size() == walls_.segmentParticles().size()
     && (!Sp_ || Sp_->size() == n)
     && (!robinK_ || robinK_->size() == wallFlux_.size())
     && (!robinG_ || robinG_->size() == wallFlux_.size());
    if (!nbrs_.storesGeometry() || !sizesFit)
    {
        FatalErrorInFunction
            << "laplacianMatrix: " << n << " particles (V), "
            << nbrs_.size() << " neighbour-list targets (with geometry: "
            << nbrs_.storesGeometry() << "), gamma of " << walls_.size()
            << ", source " << S.size() << ", kinds " << kinds_.size()
            << ", copyFrom " << copyFrom_.size() << ", Dirichlet values "
            << dirichletValues_.size() << ", B " << (B_ ? B_->size() : ones_.size())
            << ", R " << (R_ ? R_->size() : n) << "; wall fluxes "
            << wallFlux_.size() << " for "
            << walls_.segmentParticles().size() << " segments; Sp "
            << (Sp_ ? Sp_->size() : n) << ", Robin k "
            << (robinK_ ? robinK_->size() : wallFlux_.size()) << ", g "
            << (robinG_ ? robinG_->size() : wallFlux_.size())
            << exit(FatalError);
    }
}


Foam::SPH::laplacianMatrix::operands
Foam::SPH::laplacianMatrix::view(const scalarUList& S) const
{
    operands o;
    o.off = nbrs_.offsets().cdata();
    o.nbr = nbrs_.indices().cdata();
    o.rij = nbrs_.rij().cdata();
    o.r = nbrs_.r().cdata();
    o.gamma = walls_.gamma().cdata();
    o.gradGamma = walls_.gradGamma().cdata();
    o.wOff = walls_.offsets().cdata();
    o.seg = walls_.segments().cdata();
    o.gradGammaAs = walls_.gradGammaAs().cdata();
    o.dAs = walls_.distances().cdata();
    o.ends = walls_.segmentParticles().cdata();
    o.V = V_.cdata();
    o.B = B_ ? B_->cdata() : ones_.cdata();
    o.R = R_ ? R_->cdata() : nullptr;
    o.kind = kinds_.cdata();
    o.copyFrom = copyFrom_.cdata();
    o.f = dirichletValues_.cdata();
    o.flux = wallFlux_.cdata();
    o.S = S.cdata();
    o.Sp = Sp_ ? Sp_->cdata() : nullptr;
    o.robinK = robinK_ ? robinK_->cdata() : nullptr;
    o.robinG = robinG_ ? robinG_->cdata() : nullptr;
    o.robinMinDistance = robinMinDistance_;
    o.s = dirichletScale_;
    o.diagonalFactor = diagonalFactor_;
    o.nFluid = nFluid_;
    return o;
}


void Foam::SPH::laplacianMatrix::sortRow(matrixRow& row)
{
    // The pairs' own order is total up to equal pairs, so this is
    // std::sort's order and the sums of compress() do not change
    sortNearlyAscending(row, std::less<std::pair<int, scalar>>());
}


void Foam::SPH::laplacianMatrix::compress(matrixRow& row)
{
    sortRow(row);
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


void Foam::SPH::laplacianMatrix::fillMatrix()
{
    const label n = rows_.size();
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
    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::laplacianMatrix::coefficient(const scalarUList& B)
{
    B_ = &B;
    ones_.clear();
}


void Foam::SPH::laplacianMatrix::ownGradient(const UList<tensor2D>& R)
{
    R_ = &R;
}


void Foam::SPH::laplacianMatrix::diagonalFactor(const scalar factor)
{
    diagonalFactor_ = factor;
}


void Foam::SPH::laplacianMatrix::dirichletScale(const scalar scale)
{
    dirichletScale_ = scale;
}


void Foam::SPH::laplacianMatrix::implicitSource(const scalarUList& Sp)
{
    Sp_ = &Sp;
}


void Foam::SPH::laplacianMatrix::robinWalls
(
    const scalarUList& k,
    const scalarUList& g,
    const scalar dMin
)
{
    if (!(dMin > 0))
    {
        FatalErrorInFunction
            << "laplacianMatrix::robinWalls: the least wall distance " << dMin
            << " must be > 0 (the wall gradient divides by it)"
            << exit(FatalError);
    }
    robinK_ = &k;
    robinG_ = &g;
    robinMinDistance_ = dMin;
}


// ************************************************************************* //
