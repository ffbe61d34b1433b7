/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallDistance.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallDistance::execute(const scalar dt)
{
    const usawWalls& usaw = work_.usaw;
    const label* off = usaw.offsets().cdata();
    const label* seg = usaw.segments().cdata();
    const labelPair* ends = usaw.segmentParticles().cdata();
    const vector2D* normal = usaw.segmentNormals().cdata();
    const vector2D* x0 = work_.xStart->cdata();
    vector2D* x = work_.parts.positions().data();
    vector2D* U = work_.parts.field<vector2D>("U").data();
    const scalar dMin = dMin_;
    const label nFluid = work_.nFluid;
    const domain& dom = work_.cloud.dom();

    label nHeld = 0;
    #pragma omp parallel for schedule(static) reduction(+:nHeld)
    for (label i = 0; i < nFluid; ++i)
    {
        bool held = false;
        for (label k = off[i]; k < off[i + 1]; ++k)
        {
            const label s = seg[k];
            const vector2D& n = normal[s];
            // Minimum images: a segment may lie across a periodic seam
            const vector2D& a = x[ends[s].first()];
            const vector2D e(dom.separation(x[ends[s].second()], a));
            const vector2D xa(dom.separation(x[i], a));
            const scalar t = (xa & e)/magSqr(e);
            const scalar d = xa & n;
            if
            (
                t <= 0 || t >= 1 || d >= dMin
             || (dom.separation(x0[i], a) & n) < 0
            )
            {
                continue;
            }
            x[i] += (dMin - d)*n;
            const vector2D uWall
            (
                (1 - t)*U[ends[s].first()] + t*U[ends[s].second()]
            );
            const scalar un = (U[i] - uWall) & n;
            if (un < 0)
            {
                U[i] -= un*n;
            }
            held = true;
        }
        if (held)
        {
            x[i] = dom.wrap(x[i]);
        }
        nHeld += held;
    }
    nHeld_ = nHeld;
    nHeldTotal_ += nHeld;
}


// ************************************************************************* //
