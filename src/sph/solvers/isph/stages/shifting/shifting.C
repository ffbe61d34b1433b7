/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "shifting.H"
#include "usawOperators.H"
#include "kernelDispatch.H"
#include "neighbourRange.H"

#include <cmath>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::shifting::execute(const scalar dt)
{
    isphWork& w = work_;
    vector2DField& U = w.parts.field<vector2D>("U");
    dispatch(w.W, [&](const auto& K)
    {
        usaw::concentrationGradient(K, w.nbrs, w.usaw, w.V, gradC_);
        usaw::gradMinus(K, w.nbrs, w.usaw, w.V, U, gradU_);
    });

    neighbourRange(w.nbrs, w.nFluid, U, uMin_, uMax_);

    const scalar coeff = coeff_*sqr(w.W.h());
    const label* nearSurface = w.nearSurface.cdata();
    vector2D* x = w.parts.positions().data();
    scalar maxShift2 = 0;
    for (label i = 0; i < w.nFluid; ++i)
    {
        if (nearSurface[i]) continue;
        const vector2D delta(-coeff*gradC_[i]);
        U[i] = min(max(U[i] + (delta & gradU_[i]), uMin_[i]), uMax_[i]);
        x[i] += delta;
        maxShift2 = max(maxShift2, magSqr(delta));
    }
    maxShift_ = std::sqrt(maxShift2);

    // The same correction (38) for the scalars that ride with the fluid
    // (k and epsilon of a RAS model), with the shift just made
    for (const word& name : w.shiftedScalars)
    {
        scalarField& f = w.parts.field<scalar>(name);
        dispatch(w.W, [&](const auto& K)
        {
            usaw::gradMinus(K, w.nbrs, w.usaw, w.V, f, gradF_);
        });
        neighbourRange(w.nbrs, w.nFluid, f, fMin_, fMax_);
        for (label i = 0; i < w.nFluid; ++i)
        {
            if (nearSurface[i]) continue;
            const scalar corrected = f[i] + (-coeff*gradC_[i] & gradF_[i]);
            f[i] = min(max(corrected, fMin_[i]), fMax_[i]);
        }
    }

    const domain& dom = w.cloud.dom();
    if (dom.anyPeriodic())
    {
        for (label i = 0; i < w.nFluid; ++i)
        {
            x[i] = dom.wrap(x[i]);
        }
    }
}


// ************************************************************************* //
