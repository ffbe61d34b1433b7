/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wendlandC2WallIntegrals.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wendlandC2WallIntegrals::wendlandC2WallIntegrals
(
    const scalar h,
    const scalar snapFraction
)
:
    h_(h),
    invH_(1/h),
    gradFactor_(7/(4*constant::mathematical::pi*h)),
    snapTol_(snapFraction*h)
{
    if (!(h > 0) || !(snapFraction >= 0 && snapFraction < 1e-3))
    {
        FatalErrorInFunction
            << "Smoothing length " << h << " and snap fraction " << snapFraction
            << ": expected h > 0 and 0 <= snap fraction < 1e-3"
            << exit(FatalError);
    }
}


// ************************************************************************* //
