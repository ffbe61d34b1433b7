/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "usawWalls.H"
#include "openMPThreshold.H"
#include "wendlandC2.H"
#include "error.H"

#include <cmath>
#include <typeinfo>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::usawWalls::wendlandH
(
    const wallMesh& walls,
    const kernel& W
)
{
    // Without segments gamma is 1 and no integral is taken: any kernel
    if (walls.segments().size() && typeid(W) != typeid(wendlandC2))
    {
        FatalErrorInFunction
            << "USAW walls need the wendlandC2 kernel: the analytical wall"
            << " renormalisation gamma (000_8c7cd3aabddcf18a.txt eqs."
            << " (56)-(61)) is derived for it alone, and kernel " << W.type()
            << " was selected." << nl
            << "Set 'kernel wendlandC2;' in system/sphSchemes."
            << exit(FatalError);
    }
    return W.h();
}


void Foam::SPH::usawWalls::checkDomain() const
{
    const SPH::domain& wd = walls_.domain();
    for (direction d = 0; d < 2; ++d)
    {
        if
        (
            wd.periodic(d)
         && (
                !domain_.periodic(d)
             || mag(wd.period()[d] - domain_.period()[d]) > 1e-9*wd.period()[d]
            )
        )
        {
            FatalErrorInFunction
                << "The walls are periodic in " << SPH::domain::axisNames[d]
                << " with period " << wd.period()[d] << " (constant/sphMesh/"
                << SPH::domain::dictName << "), the USAW segment search "
                << (domain_.periodic(d) ? "with period " : "is not periodic")
                << (domain_.periodic(d) ? Foam::name(domain_.period()[d]) : "")
                << ": walls joined through a seam need it"
                << exit(FatalError);
        }
    }
}


void Foam::SPH::usawWalls::setGeometry(const UList<vector2D>& points)
{
    const List<labelPair>& segs = walls_.segments();
    const scalarList& angles = walls_.pointAngles();

    if (points.size() != walls_.points().size())
    {
        FatalErrorInFunction
            << points.size() << " wall vertex positions for "
            << walls_.points().size() << " wall vertices" << exit(FatalError);
    }

    mid_.setSize(segs.size());
    tangent_.setSize(segs.size());
    normal_.setSize(segs.size());
    halfLength_.setSize(segs.size());
    theta1_.setSize(segs.size());
    theta2_.setSize(segs.size());
    segmentParticles_.setSize(segs.size());
    maxHalfLength_ = 0;

    forAll(segs, s)
    {
        // The second vertex's image nearest the first: a segment through a
        // periodic seam is as long as the others, not a period
        const vector2D& p1 = points[segs[s].first()];
        const vector2D p2(domain_.image(points[segs[s].second()], p1));
        const vector2D e(p2 - p1);
        const scalar L = mag(e);
        if (!(L > 0))
        {
            FatalErrorInFunction
                << "Wall segment " << s << " from " << p1 << " to " << p2
                << " has no length" << exit(FatalError);
        }
        mid_[s] = domain_.wrap(0.5*(p1 + p2));
        tangent_[s] = e/L;

        // Fluid on the left of the segment (wallMesh): the inward normal is
        // the tangent turned by +90 degrees
        normal_[s] = vector2D(-tangent_[s].y(), tangent_[s].x());
        halfLength_[s] = 0.5*L;
        theta1_[s] = angles[segs[s].first()];
        theta2_[s] = angles[segs[s].second()];
        segmentParticles_[s] = labelPair
        (
            vertexStart_ + segs[s].first(),
            vertexStart_ + segs[s].second()
        );
        maxHalfLength_ = max(maxHalfLength_, halfLength_[s]);
    }
    buildSegmentSearch(points);
}


void Foam::SPH::usawWalls::buildSegmentSearch(const UList<vector2D>& points)
{
    // The search box: in a non-periodic direction the walls' extent plus a
    // margin (a straight wall has none of its own); positions outside it
    // are still found, only less efficiently. No walls (dummy particles
    // instead): the domain's box, or any box, for a search that finds none
    const scalar radius = support_ + maxHalfLength_;
    vector2D lo(domain_.min()), hi(domain_.max());
    for (direction d = 0; d < 2; ++d)
    {
        if (points.empty() && !(hi[d] > lo[d]))
        {
            lo[d] = 0;
            hi[d] = radius;
        }
        if (!domain_.periodic(d) && points.size())
        {
            lo[d] = GREAT;
            hi[d] = -GREAT;
            for (const vector2D& p : points)
            {
                lo[d] = min(lo[d], p[d]);
                hi[d] = max(hi[d], p[d]);
            }
            lo[d] -= radius;
            hi[d] += radius;
        }
    }

    cells_.reset(new cellLinkedList(lo, hi, radius, domain_.periodic()));
    if (radius > cells_->maxRadius())
    {
        FatalErrorInFunction
            << "Segment search radius 2h + (longest segment)/2 = " << radius
            << " exceeds half the shortest period (" << cells_->maxRadius()
            << "): the periodic box is too small for this kernel"
            << exit(FatalError);
    }
    cells_->build(mid_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::usawWalls::usawWalls
(
    const wallMesh& walls,
    const kernel& W,
    const label vertexStart
)
:
    usawWalls(walls, W, vertexStart, walls.domain())
{}


Foam::SPH::usawWalls::usawWalls
(
    const wallMesh& walls,
    const kernel& W,
    const label vertexStart,
    const vector2D& boxMin,
    const vector2D& boxMax,
    const FixedList<bool, 2>& periodic
)
:
    usawWalls(walls, W, vertexStart, SPH::domain(boxMin, boxMax, periodic))
{}


Foam::SPH::usawWalls::usawWalls
(
    const wallMesh& walls,
    const kernel& W,
    const label vertexStart,
    const SPH::domain& dom
)
:
    walls_(walls),
    integrals_(wendlandH(walls, W)),
    support_(W.support()),
    vertexStart_(vertexStart),
    domain_(dom),
    maxHalfLength_(0),
    offsets_(1, 0)
{
    if (vertexStart < 0)
    {
        FatalErrorInFunction
            << "Index of the first vertex particle " << vertexStart
            << ": expected >= 0" << exit(FatalError);
    }
    checkDomain();
    setGeometry(walls_.points());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::usawWalls::evaluate
(
    const vector2D& p,
    scalar& gamma,
    vector2D& gradGamma
) const
{
    // Eq. (56) and eq. (7)
    gamma = 1;
    gradGamma = vector2D::zero;
    forEachSegment
    (
        p,
        [&](const label s, const scalar, const scalar gt, const scalar gm)
        {
            gamma -= gt;
            gradGamma += gm*normal_[s];
        }
    );
}


Foam::scalar Foam::SPH::usawWalls::gammaAt(const vector2D& p) const
{
    scalar gamma;
    vector2D gradGamma;
    evaluate(p, gamma, gradGamma);
    return gamma;
}


void Foam::SPH::usawWalls::update(const UList<vector2D>& x)
{
    const label n = x.size();

    for (const vector2D& p : x)
    {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        {
            FatalErrorInFunction
                << "Non-finite particle position " << p
                << ": cannot compute the wall renormalisation"
                << exit(FatalError);
        }
    }

    gamma_.setSize(n);
    gradGamma_.setSize(n);
    offsets_.setSize(n + 1);

    // First pass: how many segments each particle sees
    label* off = offsets_.data();
    off[0] = 0;
    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label a = 0; a < n; ++a)
    {
        label count = 0;
        forEachSegment
        (
            x[a],
            [&](const label, const scalar, const scalar, const scalar)
            {
                ++count;
            }
        );
        off[a + 1] = count;
    }
    for (label a = 0; a < n; ++a)
    {
        off[a + 1] += off[a];
    }

    const label nPairs = off[n];
    segments_.setSize(nPairs);
    gradGammaAs_.setSize(nPairs);
    distances_.setSize(nPairs);

    // Second pass: each particle fills its own slots and sums eqs. (56), (7)
    label* seg = segments_.data();
    vector2D* gradAs = gradGammaAs_.data();
    scalar* dist = distances_.data();
    scalar* gamma = gamma_.data();
    vector2D* gradGamma = gradGamma_.data();

    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label a = 0; a < n; ++a)
    {
        label k = off[a];
        scalar g = 1;
        vector2D gg(vector2D::zero);
        forEachSegment
        (
            x[a],
            [&](const label s, const scalar d, const scalar gt, const scalar gm)
            {
                const vector2D gradGammaAs(gm*normal_[s]);
                seg[k] = s;
                gradAs[k] = gradGammaAs;
                dist[k] = d;
                ++k;
                g -= gt;
                gg += gradGammaAs;
            }
        );
        gamma[a] = g;
        gradGamma[a] = gg;
    }
}


void Foam::SPH::usawWalls::updateGeometry(const UList<vector2D>& points)
{
    setGeometry(points);
}


// ************************************************************************* //
