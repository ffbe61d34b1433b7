/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallCrossing.H"

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
    walls_(walls),
    cell_(cellSize)
{
    vector2D hi;
    walls.bounds(min_, hi);
    min_ -= vector2D(cell_, cell_);
    nx_ = label((hi.x() - min_.x())/cell_) + 2;
    ny_ = label((hi.y() - min_.y())/cell_) + 2;

    // Each segment goes into every bin its bounding box touches
    List<DynamicList<label>> bins(nx_*ny_);
    forAll(walls.segments(), s)
    {
        const vector2D& a = walls.points()[walls.segments()[s].first()];
        const vector2D& b = walls.points()[walls.segments()[s].second()];
        const label i0 = label((min(a.x(), b.x()) - min_.x())/cell_);
        const label i1 = label((max(a.x(), b.x()) - min_.x())/cell_);
        const label j0 = label((min(a.y(), b.y()) - min_.y())/cell_);
        const label j1 = label((max(a.y(), b.y()) - min_.y())/cell_);
        for (label j = j0; j <= j1; ++j)
        {
            for (label i = i0; i <= i1; ++i)
            {
                bins[bin(i, j)].append(s);
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

Foam::label Foam::SPH::wallCrossing::firstCrossing
(
    const vector2D& a,
    const vector2D& b,
    scalar& tFirst
) const
{
    const auto clampI = [&](scalar x) { return max(label(0), min(nx_ - 1, label((x - min_.x())/cell_))); };
    const auto clampJ = [&](scalar y) { return max(label(0), min(ny_ - 1, label((y - min_.y())/cell_))); };
    const label i0 = clampI(min(a.x(), b.x())), i1 = clampI(max(a.x(), b.x()));
    const label j0 = clampJ(min(a.y(), b.y())), j1 = clampJ(max(a.y(), b.y()));

    const vector2D d = b - a;
    label found = -1;
    tFirst = GREAT;
    for (label j = j0; j <= j1; ++j)
    {
        for (label i = i0; i <= i1; ++i)
        {
            const label k = bin(i, j);
            for (label m = binStart_[k]; m < binStart_[k + 1]; ++m)
            {
                const label s = binSegments_[m];
                const vector2D& p = walls_.points()[walls_.segments()[s].first()];
                const vector2D e = walls_.points()[walls_.segments()[s].second()] - p;

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
    const label n
) const
{
    label nBounced = 0;

    #pragma omp parallel for schedule(static) reduction(+: nBounced)
    for (label i = 0; i < n; ++i)
    {
        scalar t;
        label s = firstCrossing(x0[i], x[i], t);
        if (s < 0) continue;

        // Mirror in the wall line and reverse the normal velocity; in a
        // corner the mirror image can be behind the other wall, so test the
        // move again (twice at most), else stay where the step started
        for (label bounces = 0; s >= 0; ++bounces)
        {
            if (bounces == 3)
            {
                x[i] = x0[i];
                break;
            }
            const vector2D& p = walls_.points()[walls_.segments()[s].first()];
            const vector2D& nrm = walls_.segmentNormals()[s];
            x[i] -= 2*((x[i] - p) & nrm)*nrm;
            const scalar un = U[i] & nrm;
            if (un < 0)
            {
                U[i] -= 2*un*nrm;
            }
            s = firstCrossing(x0[i], x[i], t);
        }
        ++nBounced;
    }
    return nBounced;
}


// ************************************************************************* //
