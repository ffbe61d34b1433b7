/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "neighbourList.H"
#include "openMPThreshold.H"
#include "sortNearlyAscending.H"
#include "error.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>
#include <omp.h>

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


template<bool StoreGeometry>
void Foam::SPH::neighbourList::searchRange
(
    const cellLinkedList& cells,
    const UList<vector2D>& targets,
    const scalar radius,
    const bool excludeSelf,
    const label first,
    const label end,
    threadPairs* mine
)
{
    const vector2D* __restrict__ x = targets.cdata();
    label* __restrict__ off = offsets_.data();
    for (label i = first; i < end; ++i)
    {
        const label self = (excludeSelf ? i : -1);
        label c = 0;
        cells.forEachNeighbour
        (
            x[i],
            radius,
            [&](const label j, const vector2D& d, const scalar r2)
            {
                if (j == self) return;
                ++c;
                if (!mine)
                {
                    indices_.append(j);
                    if (StoreGeometry)
                    {
                        rij_.append(d);
                        r_.append(std::sqrt(r2));
                    }
                }
                else
                {
                    mine->indices.push_back(j);
                    if (StoreGeometry)
                    {
                        mine->rij.push_back(d);
                        mine->r.push_back(std::sqrt(r2));
                    }
                }
            }
        );
        off[i + 1] = c;
    }
}


template<bool StoreGeometry>
void Foam::SPH::neighbourList::placePairs
(
    const threadPairs& mine,
    const label start
)
{
    std::copy(mine.indices.begin(), mine.indices.end(), indices_.begin() + start);
    if (StoreGeometry)
    {
        std::copy(mine.rij.begin(), mine.rij.end(), rij_.begin() + start);
        std::copy(mine.r.begin(), mine.r.end(), r_.begin() + start);
    }
}


template<bool StoreGeometry>
void Foam::SPH::neighbourList::search
(
    const cellLinkedList& cells,
    const UList<vector2D>& targets,
    const scalar radius,
    const bool excludeSelf
)
{
    const label n = targets.size();
    offsets_.resize(n + 1);
    // Emptied, not freed: within the capacity of an earlier build the
    // first thread's appends do not allocate
    indices_.clear();
    rij_.clear();
    r_.clear();

    #pragma omp parallel if(SPH::worthThreads(n))
    {
        const label nThreads = omp_get_num_threads();
        const label t = omp_get_thread_num();
        #pragma omp single
        threadPairs_.resize(nThreads);

        // This thread's targets, in order; the first thread's pairs go in
        // place, the others' into their own lists
        const label first = n*t/nThreads;
        const label end = n*(t + 1)/nThreads;
        threadPairs& mine = threadPairs_[t];
        mine.indices.clear();
        mine.rij.clear();
        mine.r.clear();
        searchRange<StoreGeometry>
        (
            cells, targets, radius, excludeSelf, first, end,
            t == 0 ? nullptr : &mine
        );

        // Every count is in: the offsets, and room behind the first
        // thread's pairs (resize keeps them) for the others'
        #pragma omp barrier
        #pragma omp single
        {
            prefixSum(n);
            indices_.resize(offsets_.last());
            if (StoreGeometry)
            {
                rij_.resize(offsets_.last());
                r_.resize(offsets_.last());
            }
        }
        if (t > 0)
        {
            placePairs<StoreGeometry>(mine, offsets_[first]);
        }
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
                    kept.push_back({key, j, d, r2});
                }
            }
            // The wide list is in its build's order, which the points'
            // small moves since have hardly changed (keys are unique; an
            // ordered list costs one comparison an entry)
            sortNearlyAscending
            (
                kept,
                [](const pair& p, const pair& q) { return p.key < q.key; }
            );
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
    if (storeGeometry_)
    {
        search<true>(cells, targets, radius, excludeSelf);
    }
    else
    {
        search<false>(cells, targets, radius, excludeSelf);
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
