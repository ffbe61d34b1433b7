/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "neighbourList.H"
#include "error.H"

#include <cmath>
#include <cstdint>

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

    #pragma omp parallel for schedule(static)
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

    // In 64 bits, so that a total beyond the label range is caught rather
    // than wrapped
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
    #pragma omp parallel for schedule(static)
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

    #pragma omp parallel for schedule(static)
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


// ************************************************************************* //
