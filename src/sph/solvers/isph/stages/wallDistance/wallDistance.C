/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallDistance.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallDistance::execute(const scalar dt)
{
    nHeld_ = work_.usaw.holdOff
    (
        *work_.xStart, work_.parts.positions(),
        work_.parts.field<vector2D>("U"), work_.nFluid, dMin_
    );
    nHeldTotal_ += nHeld_;
}


// ************************************************************************* //
