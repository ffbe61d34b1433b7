/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "viscousPrediction.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

#include <cmath>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::viscousPrediction::turbulentViscous()
{
    isphWork& w = work_;
    const scalarField& nut = *w.nut;
    nuEff_.setSize(nut.size());
    forAll(nut, i)
    {
        nuEff_[i] = w.nu + nut[i];
    }
    const vector2DField& U = w.parts.field<vector2D>("U");
    dispatch(w.W, [&](const auto& K)
    {
        usaw::wallFunctionViscous
        (
            K, w.nbrs, w.usaw, w.V, nuEff_, U, w.cloud.dr(), w.nu,
            *w.wallLaw, visc_
        );
    });
}


void Foam::SPH::viscousPrediction::moveVertexVelocities(const scalar dt)
{
    isphWork& w = work_;
    const label nF = w.nFluid;
    const label n = w.parts.size();
    if (vertexTangent_.size() != n - nF)
    {
        // The wall's tangent at each vertex: its segments' normals agree
        const List<labelPair>& ends = w.usaw.segmentParticles();
        const List<vector2D>& normal = w.usaw.segmentNormals();
        List<vector2D> sumN(n - nF, Zero);
        List<vector2D> firstN(n - nF, Zero);
        labelList turns(n - nF, Zero);
        forAll(ends, s)
        {
            for (const label v : {ends[s].first() - nF, ends[s].second() - nF})
            {
                if (magSqr(firstN[v]) == 0) firstN[v] = normal[s];
                if ((firstN[v] & normal[s]) < std::cos(25*M_PI/180)) turns[v] = 1;
                sumN[v] += normal[s];
            }
        }
        vertexTangent_.setSize(n - nF);
        forAll(vertexTangent_, v)
        {
            const scalar m = mag(sumN[v]);
            vertexTangent_[v] =
                (turns[v] || m == 0)
              ? vector2D::zero
              : vector2D(-sumN[v].y()/m, sumN[v].x()/m);
        }
    }
    vector2D* U = w.parts.field<vector2D>("U").data();
    for (label i = nF; i < n; ++i)
    {
        const vector2D& t = vertexTangent_[i - nF];
        U[i] = ((U[i] + dt*visc_[i]) & t)*t;
    }
}


void Foam::SPH::viscousPrediction::execute(const scalar dt)
{
    isphWork& w = work_;
    if (w.nut)
    {
        turbulentViscous();
        moveVertexVelocities(dt);
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
