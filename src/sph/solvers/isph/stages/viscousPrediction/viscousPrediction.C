/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "viscousPrediction.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::viscousPrediction::turbulentViscous(const scalar dt)
{
    isphWork& w = work_;
    vector2DField& U = w.parts.field<vector2D>("U");
    slip_.viscousAcceleration(coupling_, *w.nut, *w.wallLaw, U, visc_);
    slip_.moveVertices(w.usaw, w.nFluid, visc_, dt, U);
}


void Foam::SPH::viscousPrediction::execute(const scalar dt)
{
    isphWork& w = work_;
    if (w.nut)
    {
        turbulentViscous(dt);
        const vector2DField& U = w.parts.field<vector2D>("U");
        for (label i = 0; i < w.nFluid; ++i)
        {
            w.Ustar[i] = U[i] + dt*visc_[i];
        }
        for (label i = w.nFluid; i < w.parts.size(); ++i)
        {
            w.Ustar[i] = U[i];
        }
        return;
    }
    const vector2DField& U = w.parts.field<vector2D>("U");
    const scalar nu = w.nu;
    const scalar rho0 = w.rho0;
    if (nu > 0)
    {
        dispatch(w.W, [&](const auto& K)
        {
            usaw::laminarViscous
            (
                K, w.nbrs, w.usaw, w.V, rho0*nu, U, w.cloud.dr(), visc_
            );
        });
    }
    const label n = w.parts.size();
    const label nFluid = w.nFluid;
    for (label i = 0; i < nFluid; ++i)
    {
        w.Ustar[i] = nu > 0 ? U[i] + (dt/rho0)*visc_[i] : U[i];
    }
    for (label i = nFluid; i < n; ++i)
    {
        w.Ustar[i] = U[i];
    }
}


// ************************************************************************* //
