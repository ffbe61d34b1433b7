/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    usawWalls::holdOff: the minWallDistance safety net of isphFoam's
    wallDistance stage and of wcsphFoam's moving walls, on the segments
    where the walls are now (so it follows moving walls).

\*---------------------------------------------------------------------------*/

#include "usawWalls.H"
#include "openMPThreshold.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::usawWalls::holdOff
(
    const UList<vector2D>& x0,
    UList<vector2D>& x,
    UList<vector2D>& U,
    const label nFluid,
    const scalar dMin,
    UList<label>* held
) const
{
    const label* off = offsets().cdata();
    const label* seg = segments().cdata();
    const labelPair* ends = segmentParticles().cdata();
    const vector2D* normal = segmentNormals().cdata();
    const vector2D* xStart = x0.cdata();
    vector2D* xp = x.data();
    vector2D* Up = U.data();
    const SPH::domain& dom = domain();
    label* heldFlag = held ? held->data() : nullptr;

    label nHeld = 0;
    #pragma omp parallel for schedule(static) reduction(+:nHeld) \
        if(SPH::worthThreads(nFluid))
    for (label i = 0; i < nFluid; ++i)
    {
        bool isHeld = false;
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label s = seg[k];
            const vector2D& n = normal[s];
            // Minimum images: a segment may lie across a periodic seam
            const vector2D& a = xp[ends[s].first()];
            const vector2D e(dom.separation(xp[ends[s].second()], a));
            const vector2D xa(dom.separation(xp[i], a));
            const scalar t = (xa & e)/magSqr(e);
            const scalar d = xa & n;
            if
            (
                t <= 0 || t >= 1 || d >= dMin
             || (dom.separation(xStart[i], a) & n) < 0
            )
            {
                continue;
            }
            xp[i] += (dMin - d)*n;
            const vector2D uWall
            (
                (1 - t)*Up[ends[s].first()] + t*Up[ends[s].second()]
            );
            const scalar un = (Up[i] - uWall) & n;
            if (un < 0)
            {
                Up[i] -= un*n;
            }
            isHeld = true;
        }
        if (isHeld)
        {
            xp[i] = dom.wrap(xp[i]);
        }
        if (heldFlag)
        {
            heldFlag[i] = isHeld;
        }
        nHeld += isHeld;
    }
    return nHeld;
}


// ************************************************************************* //
