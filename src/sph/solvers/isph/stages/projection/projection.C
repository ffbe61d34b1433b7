/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "projection.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::projection::pressureGradient
(
    const isphWork& w,
    const bool renormalised,
    UList<vector2D>& gradP
)
{
    const scalarField& p = w.parts.field<scalar>("p");
    dispatch(w.W, [&](const auto& K)
    {
        if (renormalised)
        {
            usaw::gradMinus(K, w.nbrs, w.usaw, w.V, w.R, p, gradP);
        }
        else
        {
            usaw::gradPlus(K, w.nbrs, w.usaw, w.V, p, gradP);
        }
    });
}


void Foam::SPH::projection::execute(const scalar dt)
{
    isphWork& w = work_;
    pressureGradient(w, renormalised_, gradP_);

    vector2D* U = w.parts.field<vector2D>("U").data();
    const vector2D g = w.g;
    const scalar rho0 = w.rho0;
    const label nFluid = w.nFluid;
    for (label i = 0; i < nFluid; ++i)
    {
        U[i] = w.Ustar[i] + dt*(g - gradP_[i]/rho0);
    }
}


// ************************************************************************* //
