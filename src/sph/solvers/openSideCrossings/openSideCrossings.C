/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "openSideCrossings.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::openSideCrossings::openSideCrossings()
:
    nCrossings_(0),
    nBeyond_(0),
    farthest_(0),
    tFarthest_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::openSideCrossings::check
(
    const sphCloud& cloud,
    const List<vector2D>& start,
    const Time& runTime
)
{
    const domain& dom = cloud.dom();
    if (!dom.anyOpen())
    {
        return;
    }
    const vector2DField& x = cloud.parts().positions();
    const vector2DField& U = cloud.parts().field<vector2D>("U");
    const labelField& id = cloud.parts().field<label>("id");
    nBeyond_ = 0;
    for (label i = 0; i < cloud.nFluid(); ++i)
    {
        const label side = dom.beyondOpenSide(x[i]);
        if (side < 0)
        {
            continue;
        }
        ++nBeyond_;

        // How far beyond the side's line
        const direction d = side/2;
        const scalar bound = (side % 2) ? dom.max()[d] : dom.min()[d];
        const scalar beyond = mag(x[i][d] - bound);
        if (beyond > farthest_)
        {
            farthest_ = beyond;
            tFarthest_ = runTime.value();
        }
        if (dom.beyondOpenSide(start[i]) == side)
        {
            continue;
        }
        ++nCrossings_;
        Info<< "Particle id " << id[i] << " went beyond the open side "
            << domain::sideNames[side] << " (" << domain::axisNames[d]
            << " = " << bound << " m) at (" << x[i].x() << ' ' << x[i].y()
            << ") at t = " << runTime.value() << " s, moving at "
            << mag(U[i]) << " m/s (U " << U[i] << ")" << endl;
    }
}


void Foam::SPH::openSideCrossings::printSummary
(
    const sphCloud& cloud,
    Ostream& os
) const
{
    const domain& dom = cloud.dom();
    if (!dom.anyOpen())
    {
        return;
    }
    os  << "Fluid particles beyond the open sides";
    for (const word& w : dom.openSideNames())
    {
        os  << ' ' << w;
    }
    os  << ": " << nCrossings_ << " crossings";
    if (nCrossings_)
    {
        os  << ", the farthest " << farthest_ << " m beyond (t = "
            << tFarthest_ << " s)";
    }
    os  << ", " << nBeyond_ << " beyond at the end (of " << cloud.nFluid()
        << " fluid particles, none removed)" << nl;
}


// ************************************************************************* //
