/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "errorNorms.H"

#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::errorNorms::missing()
{
    return std::numeric_limits<scalar>::quiet_NaN();
}


Foam::SPH::errorNorms::result Foam::SPH::errorNorms::compare
(
    const scalarField& f,
    const scalarField& ref,
    const scalarField& weights,
    const scalar scale
)
{
    // 000_8c7cd3aabddcf18a.txt eq. (66), over the points with both values
    label n = 0;
    scalar sumW = 0, sumW2 = 0, maxAbs = 0;
    forAll(f, i)
    {
        if (std::isfinite(f[i]) && std::isfinite(ref[i]))
        {
            const scalar d = f[i] - ref[i];
            ++n;
            sumW += weights[i];
            sumW2 += weights[i]*d*d;
            maxAbs = std::max(maxAbs, std::abs(d));
        }
    }

    if (n == 0 || sumW <= 0)
    {
        return result{n, missing(), missing()};
    }
    return result{n, std::sqrt(sumW2/sumW)/scale, maxAbs/scale};
}


Foam::scalar Foam::SPH::errorNorms::mean
(
    const scalarField& f,
    const scalarField& weights
)
{
    scalar sumW = 0, sumWf = 0;
    forAll(f, i)
    {
        if (std::isfinite(f[i]))
        {
            sumW += weights[i];
            sumWf += weights[i]*f[i];
        }
    }
    return sumW > 0 ? sumWf/sumW : missing();
}


// ************************************************************************* //
