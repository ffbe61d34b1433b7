/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "neighbourList.H"
#include "openMPThreshold.H"
#include "error.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::neighbourList::check
(
    const cellLinkedList& cells,
    const UList<vector2D>& targets,
    const scalar radius,
    const bool excludeSelf
)
{
    if (!(radius > 0) || radius > cells.maxRadius())
    {
        FatalErrorInFunction
            << "Search radius " << radius << ": expected > 0 and <= "
            << cells.maxRadius() << " (half the shortest period), beyond which"
            << " a second periodic image could be within reach"
            << exit(FatalError);
    }

    // Self is recognised by index, which only means something when the
    // targets are the points the cell list was built from
    if (excludeSelf && targets.size() != cells.size())
    {
        FatalErrorInFunction
            << "excludeSelf with " << targets.size() << " targets but "
            << cells.size() << " points in the cell list: the targets must be"
            << " those points" << exit(FatalError);
    }
}


void Foam::SPH::neighbourList::count
(
    const cellLinkedList& cells,
    const UList<vector2D>& targets,
    const scalar radius,
    const bool excludeSelf
)
{
    const label n = targets.size();
    const vector2D* __restrict__ x = targets.cdata();
    offsets_.resize(n + 1);
    label* __restrict__ off = offsets_.data();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        const label self = (excludeSelf ? i : -1);
        label c = 0;
        cells.forEachNeighbour
        (
            x[i],
            radius,
            [&](const label j, const vector2D&, const scalar)
            {
                c += (j != self);
            }
        );
        off[i + 1] = c;
    }

    prefixSum(n);
}


template<bool StoreGeometry>
void Foam::SPH::neighbourList::fill
(
    const cellLinkedList& cells,
    const UList<vector2D>& targets,
    const scalar radius,
    const bool excludeSelf
)
{
    const label n = targets.size();
    const vector2D* __restrict__ x = targets.cdata();
    const label* __restrict__ off = offsets_.cdata();
    label* __restrict__ idx = indices_.data();
    vector2D* __restrict__ rij = rij_.data();
    scalar* __restrict__ r = r_.data();

    // Same static schedule as the count pass: a thread revisits the cells it
    // has just read
    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        const label self = (excludeSelf ? i : -1);
        label k = off[i];
        cells.forEachNeighbour
        (
            x[i],
            radius,
            [&](const label j, const vector2D& d, const scalar r2)
            {
                if (j != self)
                {
                    idx[k] = j;
                    if (StoreGeometry)
                    {
                        rij[k] = d;
                        r[k] = std::sqrt(r2);
                    }
                    ++k;
                }
            }
        );
    }
}


void Foam::SPH::neighbourList::prefixSum(const label n)
{
    // In 64 bits, so that a total beyond the label range is caught rather
    // than wrapped
    label* __restrict__ off = offsets_.data();
    off[0] = 0;
    int64_t total = 0;
    for (label i = 0; i < n; ++i)
    {
        total += off[i + 1];
        if (total > labelMax)
        {
            FatalErrorInFunction
                << "More than " << labelMax << " neighbour pairs for " << n
                << " targets: build with WM_LABEL_SIZE=64" << exit(FatalError);
        }
        off[i + 1] = label(total);
    }
}


Foam::label Foam::SPH::neighbourList::buildOrderCoord
(
    const label c,
    const label cTarget,
    const label nCells,
    const bool periodic
)
{
    // A build visits the cells of a target's window in increasing
    // coordinate, a periodic window running across the seam unwrapped
    if (!periodic) return c;
    label d = c - cTarget;
    if (2*d > nCells) d -= nCells;
    else if (2*d < -nCells) d += nCells;
    return cTarget + d;
}


template<class Separation>
void Foam::SPH::neighbourList::fillSelected
(
    const neighbourList& wide,
    const cellLinkedList& cells,
    const scalar radius2,
    const Separation& separation
)
{
    struct pair { int64_t key; label j; vector2D rij; scalar r2; };
    const label n = wide.size();
    const label nx = cells.nCellsXY()[0];
    const label ny = cells.nCellsXY()[1];
    const FixedList<bool, 2>& periodic = cells.periodic();
    const label* __restrict__ wOff = wide.offsets_.cdata();
    const label* __restrict__ wIdx = wide.indices_.cdata();
    const label* __restrict__ cx = cellOf_.cdata();
    const label* __restrict__ cy = cellOf_.cdata() + n;
    const label* __restrict__ off = offsets_.cdata();
    label* __restrict__ idx = indices_.data();
    vector2D* __restrict__ rij = rij_.data();
    scalar* __restrict__ r = r_.data();

    #pragma omp parallel if(SPH::worthThreads(n))
    {
        std::vector<pair> kept;
        #pragma omp for schedule(static)
        for (label i = 0; i < n; ++i)
        {
            kept.clear();
            bool sorted = true;
            for (label k = wOff[i]; k < wOff[i + 1]; ++k)
            {
                const label j = wIdx[k];
                scalar r2;
                const vector2D d(separation(i, j, r2));
                if (r2 < radius2)
                {
                    const label x =
                        buildOrderCoord(cx[j], cx[i], nx, periodic[0]);
                    const label y =
                        buildOrderCoord(cy[j], cy[i], ny, periodic[1]);
                    const int64_t key =
                        (int64_t(y + ny)*(3*nx) + (x + nx))*n + j;
                    sorted = sorted && (kept.empty() || kept.back().key < key);
                    kept.push_back({key, j, d, r2});
                }
            }
            // The wide list is in its build's order, which the points'
            // small moves since have hardly changed: insertion sort
            for (size_t a = 1; !sorted && a < kept.size(); ++a)
            {
                const pair p = kept[a];
                size_t b = a;
                for (; b > 0 && kept[b - 1].key > p.key; --b)
                {
                    kept[b] = kept[b - 1];
                }
                kept[b] = p;
            }
            label m = off[i];
            for (const pair& p : kept)
            {
                idx[m] = p.j;
                rij[m] = p.rij;
                r[m] = std::sqrt(p.r2);
                ++m;
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::neighbourList::neighbourList(const bool storeGeometry)
:
    storeGeometry_(storeGeometry)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::neighbourList::build
(
    const cellLinkedList& cells,
    const UList<vector2D>& targets,
    const scalar radius,
    const bool excludeSelf
)
{
    check(cells, targets, radius, excludeSelf);
    count(cells, targets, radius, excludeSelf);

    // Within the capacity of an earlier build these do not allocate
    const label nPairs = offsets_.last();
    indices_.resize(nPairs);
    if (storeGeometry_)
    {
        rij_.resize(nPairs);
        r_.resize(nPairs);
        fill<true>(cells, targets, radius, excludeSelf);
    }
    else
    {
        fill<false>(cells, targets, radius, excludeSelf);
    }
}


void Foam::SPH::neighbourList::refresh
(
    const cellLinkedList& cells,
    const UList<vector2D>& targets,
    const UList<vector2D>& points
)
{
    if (!storeGeometry_ || targets.size() != size())
    {
        FatalErrorInFunction
            << "Refresh of a neighbour list "
            << (storeGeometry_ ? "" : "without stored geometry ")
            << "built for " << size() << " targets with " << targets.size()
            << exit(FatalError);
    }

    const label n = targets.size();
    const vector2D* __restrict__ x = targets.cdata();
    const vector2D* __restrict__ y = points.cdata();
    const label* __restrict__ off = offsets_.cdata();
    const label* __restrict__ idx = indices_.cdata();
    vector2D* __restrict__ rij = rij_.data();
    scalar* __restrict__ r = r_.data();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        const vector2D xi(cells.wrap(x[i]));
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            rij[k] = cells.minimumImage(xi - cells.wrap(y[idx[k]]));
            r[k] = mag(rij[k]);
        }
    }
}


void Foam::SPH::neighbourList::select
(
    const neighbourList& wide,
    const cellLinkedList& cells,
    const UList<vector2D>& x,
    const scalar radius
)
{
    const label n = x.size();
    if (!storeGeometry_ || wide.size() != n)
    {
        FatalErrorInFunction
            << "Selection "
            << (storeGeometry_ ? "" : "into a list without stored geometry ")
            << "from a list of " << wide.size() << " targets for " << n
            << " points" << exit(FatalError);
    }

    // Wrapped positions and cell coordinates (x, then y), as a build at
    // x would have them
    wrapped_.resize(n);
    cellOf_.resize(2*n);
    vector2D* __restrict__ xw = wrapped_.data();
    label* __restrict__ cell = cellOf_.data();
    const label nx = cells.nCellsXY()[0];
    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        xw[i] = cells.wrap(x[i]);
        const label c = cells.cellIndex(x[i]);
        cell[i] = c % nx;
        cell[n + i] = c/nx;
    }

    // The separation exactly as cellLinkedList::scanCells computes it
    const label* __restrict__ wOff = wide.offsets_.cdata();
    const label* __restrict__ wIdx = wide.indices_.cdata();
    const scalar radius2 = radius*radius;
    auto separation = [&](const label i, const label j, scalar& r2)
    {
        const vector2D rij(cells.minimumImage(xw[i] - xw[j]));
        r2 = rij.x()*rij.x() + rij.y()*rij.y();
        return rij;
    };

    offsets_.resize(n + 1);
    label* __restrict__ off = offsets_.data();
    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        label c = 0;
        for (label k = wOff[i]; k < wOff[i + 1]; ++k)
        {
            scalar r2;
            separation(i, wIdx[k], r2);
            c += (r2 < radius2);
        }
        off[i + 1] = c;
    }
    prefixSum(n);
    const label nPairs = offsets_.last();
    indices_.resize(nPairs);
    rij_.resize(nPairs);
    r_.resize(nPairs);
    fillSelected(wide, cells, radius2, separation);
}


// ************************************************************************* //
