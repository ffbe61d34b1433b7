/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "verletList.H"
#include "openMPThreshold.H"
#include "error.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::SPH::verletList::movedTooFar
(
    const cellLinkedList& cells,
    const UList<vector2D>& x
) const
{
    const label n = x.size();
    const vector2D* __restrict__ xNow = x.cdata();
    const vector2D* __restrict__ x0 = xBuild_.cdata();
    const scalar maxMove2 = sqr(0.5*skin_);
    label nFar = 0;
    #pragma omp parallel for schedule(static) reduction(+: nFar) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        // Minimum image: a point wrapped across a periodic seam since the
        // build has moved by a small step, not a period
        nFar += magSqr(cells.minimumImage(xNow[i] - x0[i])) > maxMove2;
    }
    return nFar > 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::verletList::verletList(const scalar skin)
:
    skin_(skin),
    wide_(false),
    valid_(false),
    radius_(0),
    nBuilds_(0),
    nSelections_(0)
{
    if (!(skin >= 0))
    {
        FatalErrorInFunction
            << "Verlet skin " << skin << ": expected >= 0" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::SPH::verletList::update
(
    cellLinkedList& cells,
    const UList<vector2D>& x,
    const scalar radius,
    neighbourList& nbrs
)
{
    if (skin_ == 0)
    {
        cells.build(x);
        nbrs.build(cells, x, radius, true);
        ++nBuilds_;
        return true;
    }

    const bool build =
        !valid_ || radius != radius_ || x.size() != xBuild_.size()
     || movedTooFar(cells, x);
    if (build)
    {
        cells.build(x);
        wide_.build(cells, x, radius + skin_, true);
        xBuild_ = x;
        radius_ = radius;
        valid_ = true;
        ++nBuilds_;
    }
    nbrs.select(wide_, cells, x, radius);
    ++nSelections_;
    return build;
}


// ************************************************************************* //
