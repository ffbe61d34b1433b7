/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallCrossing.H"
#include "openMPThreshold.H"

namespace
{
    inline Foam::scalar cross2D(const Foam::vector2D& a, const Foam::vector2D& b)
    {
        return a.x()*b.y() - a.y()*b.x();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallCrossing::wallCrossing(const wallMesh& walls, const scalar cellSize)
:
    walls_(walls)
{
    const SPH::domain& dom = walls.domain();
    vector2D lo, hi;
    walls.bounds(lo, hi);
    for (direction d = 0; d < 2; ++d)
    {
        if (dom.periodic(d))
        {
            min_[d] = dom.min()[d];
            n_[d] = max(label(1), label(std::floor(dom.period()[d]/cellSize)));
            cell_[d] = dom.period()[d]/n_[d];
        }
        else
        {
            min_[d] = lo[d] - cellSize;
            cell_[d] = cellSize;
            n_[d] = label((hi[d] - min_[d])/cellSize) + 2;
        }
    }

    // Each segment goes into every bin its bounding box touches; a segment
    // through a periodic seam is its minimum image, its bins wrapped
    List<DynamicList<label>> bins(n_[0]*n_[1]);
    forAll(walls.segments(), s)
    {
        const vector2D& a = walls.points()[walls.segments()[s].first()];
        const vector2D b(dom.image(walls.points()[walls.segments()[s].second()], a));
        label i0, i1, j0, j1;
        binRange(min(a.x(), b.x()), max(a.x(), b.x()), 0, i0, i1);
        binRange(min(a.y(), b.y()), max(a.y(), b.y()), 1, j0, j1);
        for (label j = j0; j <= j1; ++j)
        {
            for (label i = i0; i <= i1; ++i)
            {
                bins[bin(wrapCoord(i, 0), wrapCoord(j, 1))].append(s);
            }
        }
    }
    binStart_.setSize(bins.size() + 1);
    binStart_[0] = 0;
    forAll(bins, k)
    {
        binStart_[k + 1] = binStart_[k] + bins[k].size();
    }
    binSegments_.setSize(binStart_.last());
    forAll(bins, k)
    {
        forAll(bins[k], m)
        {
            binSegments_[binStart_[k] + m] = bins[k][m];
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wallCrossing::binRange
(
    const scalar lo,
    const scalar hi,
    const direction d,
    label& c0,
    label& c1
) const
{
    if (!walls_.domain().periodic(d))
    {
        // Truncation, as the coordinates are above min_ in the grid
        const auto clamp = [&](scalar x)
        {
            return max(label(0), min(n_[d] - 1, label((x - min_[d])/cell_[d])));
        };
        c0 = clamp(lo);
        c1 = clamp(hi);
        return;
    }

    // Positions may be unwrapped: the bins a period away are the same
    const scalar L = walls_.domain().period()[d];
    const scalar base = std::floor((lo - min_[d])/L);
    const scalar shift = min_[d] + base*L;
    c0 = label(std::floor((lo - shift)/cell_[d]));
    c1 = label(std::floor((hi - shift)/cell_[d]));
    if (c1 - c0 + 1 >= n_[d])
    {
        c0 = 0;
        c1 = n_[d] - 1;
    }
}


Foam::label Foam::SPH::wallCrossing::firstCrossing
(
    const vector2D& a,
    const vector2D& bGiven,
    scalar& tFirst
) const
{
    // The move's minimum image: its end next to its start
    const SPH::domain& dom = walls_.domain();
    const vector2D b(dom.image(bGiven, a));

    label i0, i1, j0, j1;
    binRange(min(a.x(), b.x()), max(a.x(), b.x()), 0, i0, i1);
    binRange(min(a.y(), b.y()), max(a.y(), b.y()), 1, j0, j1);

    const vector2D d = b - a;
    label found = -1;
    tFirst = GREAT;
    for (label j = j0; j <= j1; ++j)
    {
        for (label i = i0; i <= i1; ++i)
        {
            const label k = bin(wrapCoord(i, 0), wrapCoord(j, 1));
            for (label m = binStart_[k]; m < binStart_[k + 1]; ++m)
            {
                // The segment's image next to the move
                const label s = binSegments_[m];
                const vector2D p(dom.image(walls_.points()[walls_.segments()[s].first()], a));
                const vector2D e(walls_.segmentVector(s));

                // Only moves from the fluid side to the other side count
                const vector2D& n = walls_.segmentNormals()[s];
                if (((a - p) & n) < 0 || ((b - p) & n) >= 0) continue;

                const scalar denom = cross2D(d, e);
                if (mag(denom) < VSMALL) continue;
                const scalar t = cross2D(p - a, e)/denom;     // along the move
                const scalar u = cross2D(p - a, d)/denom;     // along the wall
                if (t >= 0 && t <= 1 && u >= 0 && u <= 1 && t < tFirst)
                {
                    tFirst = t;
                    found = s;
                }
            }
        }
    }
    return found;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::wallCrossing::bounce
(
    const UList<vector2D>& x0,
    UList<vector2D>& x,
    UList<vector2D>& U,
    const label n,
    const scalar elasticity
) const
{
    label nBounced = 0;

    #pragma omp parallel for schedule(static) reduction(+: nBounced) \
        if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        scalar t;
        label s = firstCrossing(x0[i], x[i], t);
        if (s < 0) continue;

        // Mirror in the wall line and turn the normal velocity; in a
        // corner the mirror image can be behind the other wall, so test the
        // move again (twice at most), else stay where the step started
        for (label bounces = 0; s >= 0; ++bounces)
        {
            if (bounces == 3)
            {
                x[i] = x0[i];
                break;
            }
            const vector2D p
            (
                walls_.domain().image(walls_.points()[walls_.segments()[s].first()], x[i])
            );
            const vector2D& nrm = walls_.segmentNormals()[s];
            x[i] -= 2*((x[i] - p) & nrm)*nrm;
            const scalar un = U[i] & nrm;
            if (un < 0)
            {
                U[i] -= (1 + elasticity)*un*nrm;
            }
            s = firstCrossing(x0[i], x[i], t);
        }
        ++nBounced;
    }
    return nBounced;
}


// ************************************************************************* //
