/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "thermalWallFunction.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::thermalWallFunction::thermalWallFunction
(
    const scalar Pr,
    const scalar Prt,
    const scalar kappa
)
:
    Pr_(Pr),
    Prt_(Prt),
    kappa_(kappa),
    a4_(1000)
{
    // Leroy et al. 2015, eq. (38)
    a1_ = Prt_/a4_;
    a2_ = 15*std::pow(Pr_, 2.0/3.0);
    a3_ = a2_ - Prt_/(2*kappa_)*(1 + std::log(a4_*kappa_/Prt_));
    y1_ = std::cbrt(a4_/Pr_);
    y2_ = std::sqrt(a4_*kappa_/Prt_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::thermalWallFunction::Tplus(const scalar yPlus) const
{
    // Eq. (37)
    if (yPlus < y1_)
    {
        return Pr_*yPlus;
    }
    if (yPlus < y2_)
    {
        return a2_ - Prt_/(2*a1_*yPlus*yPlus);
    }
    return Prt_/kappa_*std::log(yPlus) + a3_;
}


// ************************************************************************* //
