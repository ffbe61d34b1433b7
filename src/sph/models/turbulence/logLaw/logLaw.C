/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "logLaw.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::logLaw::logLaw(const scalar kappa, const scalar B)
:
    kappa_(kappa),
    B_(B),
    yPlusLam_(11)
{
    // y+ = ln(y+)/kappa + B: the fixed point iteration contracts there
    for (label i = 0; i < 50; ++i)
    {
        yPlusLam_ = std::log(std::max(yPlusLam_, scalar(1)))/kappa_ + B_;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::logLaw::uStarLog
(
    const scalar u,
    const scalar y,
    const scalar nu
) const
{
    if (!(u > 0))
    {
        return 0;
    }
    // f(u*) = u/u* - ln(y u*/nu)/kappa - B, convex and decreasing
    scalar uStar = std::min(nu/y, u/(2*B_));
    for (label i = 0; i < maxNewton; ++i)
    {
        const scalar f = u/uStar - std::log(y*uStar/nu)/kappa_ - B_;
        const scalar df = -u/(uStar*uStar) - 1/(kappa_*uStar);
        const scalar step = f/df;
        uStar -= step;
        if (std::abs(step) <= 1e-13*uStar) break;
    }
    return uStar;
}


Foam::scalar Foam::SPH::logLaw::uStarSqr
(
    const scalar u,
    const scalar y,
    const scalar nu
) const
{
    const scalar laminar = nu*u/y;
    if (std::sqrt(laminar)*y/nu < yPlusLam_)
    {
        return laminar;
    }
    const scalar uStar = uStarLog(u, y, nu);
    return uStar*uStar;
}


// ************************************************************************* //
