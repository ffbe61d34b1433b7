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
        work_.parts.field<vector2D>("U"), work_.nFluid, dMin_, &held_
    );
    nHeldSurface_ = 0;
    if (nHeld_ > 0 && freeSurface_)
    {
        forAll(held_, i)
        {
            nHeldSurface_ += held_[i] && work_.surface[i];
        }
    }
    nHeldTotal_ += nHeld_;
    nHeldSurfaceTotal_ += nHeldSurface_;
}


// ************************************************************************* //
