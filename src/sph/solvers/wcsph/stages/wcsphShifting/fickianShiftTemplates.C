/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fickianShift.H"
#include "neighbourRange.H"

#include <cmath>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Kernel>
Foam::scalar Foam::SPH::fickianShift::apply
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const domain& dom,
    const label nFluid,
    const scalarUList& D,
    UList<vector2D>& x,
    UList<vector2D>& U,
    UList<scalar>& rho
)
{
    const label n = nbrs.size();
    gradC_.setSize(n);
    gradU_.setSize(n);
    const bool correctRho = !rho.empty();
    if (correctRho)
    {
        gradRho_.setSize(n);
    }

    // Every gradient at the positions before the shift
    usaw::concentrationGradient(K, nbrs, walls, V, gradC_);
    usaw::gradMinus(K, nbrs, walls, V, U, gradU_);
    if (correctRho)
    {
        usaw::gradMinus(K, nbrs, walls, V, rho, gradRho_);
        neighbourRange(nbrs, nFluid, rho, rhoMin_, rhoMax_);
    }
    neighbourRange(nbrs, nFluid, U, uMin_, uMax_);

    scalar maxShift2 = 0;
    for (label i = 0; i < nFluid; ++i)
    {
        const vector2D delta(-D[i]*gradC_[i]);
        U[i] = min(max(U[i] + (delta & gradU_[i]), uMin_[i]), uMax_[i]);
        if (correctRho)
        {
            const scalar corrected = rho[i] + (delta & gradRho_[i]);
            rho[i] = min(max(corrected, rhoMin_[i]), rhoMax_[i]);
        }
        x[i] = dom.wrap(x[i] + delta);
        maxShift2 = max(maxShift2, magSqr(delta));
    }
    return std::sqrt(maxShift2);
}


// ************************************************************************* //
