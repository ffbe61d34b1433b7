/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "cellLinkedList.H"
#include "openMPThreshold.H"
#include "error.H"

#include <algorithm>
#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace
{
    // 2^27 cells is 1 GB of offsets and cursors: a box that needs more for
    // its radius is a set-up mistake, not a case to run
    const Foam::scalar maxCells = 134217728;

    const char* const axisName[2] = {"x", "y"};

    // Cells of half the radius: a query's window of cells is then 2.5
    // radii wide instead of 3, so 31 % fewer points are tested against the
    // radius (side by side: benchmarks/README.md)
    const Foam::scalar cellsPerRadius = 2;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::cellLinkedList::setCells()
{
    if (!(radius_ > 0) || !std::isfinite(radius_))
    {
        FatalErrorInFunction
            << "Search radius " << radius_ << ": expected a finite value > 0"
            << exit(FatalError);
    }

    scalar coordScale = 0;
    for (direction d = 0; d < 2; ++d)
    {
        const scalar L = max_[d] - min_[d];
        if (!(L > 0) || !std::isfinite(L))
        {
            FatalErrorInFunction
                << "Box " << min_ << " to " << max_ << ": expected max > min"
                << " in " << axisName[d] << exit(FatalError);
        }

        // As many cells as fit with size >= radius/cellsPerRadius; the
        // decrement undoes a floor that rounding pushed one too high
        const scalar minSize = radius_/cellsPerRadius;
        const scalar nFit = std::floor(L/minSize);
        label n = (nFit < 1 ? 1 : label(Foam::min(nFit, maxCells)));
        while (n > 1 && L/n < minSize)
        {
            --n;
        }

        // A period below two radii would put a second image of a point
        // within the radius, which the minimum image cannot report
        if (periodic_[d] && L < 2*radius_)
        {
            FatalErrorInFunction
                << "Periodic in " << axisName[d] << " with period " << L
                << " and search radius " << radius_
                << ": expected a period >= 2 search radii" << exit(FatalError);
        }

        n_[d] = n;
        cellSize_[d] = L/n;
        invCellSize_[d] = n/L;
        period_[d] = (periodic_[d] ? L : 0);
        halfPeriod_[d] = (periodic_[d] ? 0.5*L : VGREAT);
        coordScale = Foam::max(coordScale, Foam::max(mag(min_[d]), mag(max_[d])));
    }

    if (scalar(n_[0])*scalar(n_[1]) > maxCells)
    {
        FatalErrorInFunction
            << "Box " << min_ << " to " << max_ << " with search radius "
            << radius_ << " needs " << n_[0] << " x " << n_[1]
            << " cells, more than " << maxCells << exit(FatalError);
    }

    // Cells are chosen from x +- radius, pairs from the rounded p - x_j: the
    // two can disagree by a few ulp of the coordinates, e.g. points at 0
    // and 0.6 in a period of 0.7 are 0.09999999999999998 apart through the
    // seam, yet 0.6 + 0.1 maps to the last cell, not past it. A margin well
    // above that rounding costs an extra row of cells only for a query
    // within it of a cell border
    pad_ = 64*std::numeric_limits<scalar>::epsilon()*(coordScale + radius_);

    cellStart_.setSize(nCells() + 1, 0);
    cellCursor_.setSize(nCells());
}


void Foam::SPH::cellLinkedList::assignCells(const UList<vector2D>& points)
{
    const label n = points.size();
    const vector2D* __restrict__ x = points.cdata();
    label* __restrict__ cell = pointCell_.data();
    label nBad = 0;

    // The floating-point part of the sort: worth the threads
    #pragma omp parallel for schedule(static) reduction(+:nBad) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        nBad += !(std::isfinite(x[i].x()) && std::isfinite(x[i].y()));
        cell[i] = cellIndex(x[i]);
    }

    if (nBad)
    {
        label first = 0;
        while (std::isfinite(x[first].x()) && std::isfinite(x[first].y()))
        {
            ++first;
        }
        FatalErrorInFunction
            << nBad << " of " << n << " points have a non-finite position;"
            << " the first is point " << first << " at " << x[first]
            << exit(FatalError);
    }
}


void Foam::SPH::cellLinkedList::countingSort()
{
    // Serial on purpose: integer increments over memory, where threads would
    // need per-thread histograms of every cell to stay deterministic
    const label n = pointCell_.size();
    const label nc = nCells();
    const label* __restrict__ cell = pointCell_.cdata();
    label* __restrict__ start = cellStart_.data();
    label* __restrict__ cursor = cellCursor_.data();
    label* __restrict__ sorted = sortedIndex_.data();

    std::fill(start, start + nc + 1, 0);
    for (label i = 0; i < n; ++i)
    {
        ++start[cell[i] + 1];
    }
    for (label c = 0; c < nc; ++c)
    {
        start[c + 1] += start[c];
    }

    // Ascending i within each cell: the order of every neighbour sum is then
    // fixed by the data, not by the thread count
    std::copy(start, start + nc, cursor);
    for (label i = 0; i < n; ++i)
    {
        sorted[cursor[cell[i]]++] = i;
    }
}


void Foam::SPH::cellLinkedList::gatherPoints(const UList<vector2D>& points)
{
    const label n = points.size();
    const vector2D* __restrict__ x = points.cdata();
    const label* __restrict__ sorted = sortedIndex_.cdata();
    vector2D* __restrict__ sortedX = sortedPoints_.data();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label k = 0; k < n; ++k)
    {
        sortedX[k] = wrap(x[sorted[k]]);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::cellLinkedList::cellLinkedList
(
    const vector2D& min,
    const vector2D& max,
    const scalar radius,
    const FixedList<bool, 2>& periodic
)
:
    min_(min),
    max_(max),
    periodic_(periodic),
    radius_(radius),
    n_(label(1)),
    cellSize_(Zero),
    invCellSize_(Zero),
    period_(Zero),
    halfPeriod_(Zero),
    pad_(0)
{
    setCells();
}


Foam::SPH::cellLinkedList::cellLinkedList
(
    const domain& dom,
    const scalar radius
)
:
    cellLinkedList(dom.min(), dom.max(), radius, dom.periodic())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::cellLinkedList::maxRadius() const
{
    scalar r = VGREAT;
    for (direction d = 0; d < 2; ++d)
    {
        if (periodic_[d])
        {
            r = Foam::min(r, halfPeriod_[d]);
        }
    }
    return r;
}


void Foam::SPH::cellLinkedList::build(const UList<vector2D>& points)
{
    // Within the capacity of an earlier build these do not allocate
    const label n = points.size();
    pointCell_.resize(n);
    sortedIndex_.resize(n);
    sortedPoints_.resize(n);

    assignCells(points);
    countingSort();
    gatherPoints(points);
}


// ************************************************************************* //
