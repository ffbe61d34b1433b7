/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallFunctionSlip.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wallFunctionSlip::setTangents
(
    const usawWalls& walls,
    const label nFluid
)
{
    // The wall's tangent at each vertex: its segments' normals agree
    const List<labelPair>& ends = walls.segmentParticles();
    const List<vector2D>& normal = walls.segmentNormals();
    const label nV = vertexTangent_.size();
    List<vector2D> sumN(nV, Zero);
    List<vector2D> firstN(nV, Zero);
    labelList turns(nV, Zero);
    forAll(ends, s)
    {
        for (const label v : {ends[s].first() - nFluid, ends[s].second() - nFluid})
        {
            if (magSqr(firstN[v]) == 0) firstN[v] = normal[s];
            if ((firstN[v] & normal[s]) < std::cos(25*M_PI/180)) turns[v] = 1;
            sumN[v] += normal[s];
        }
    }
    forAll(vertexTangent_, v)
    {
        const scalar m = mag(sumN[v]);
        vertexTangent_[v] =
            (turns[v] || m == 0)
          ? vector2D::zero
          : vector2D(-sumN[v].y()/m, sumN[v].x()/m);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallFunctionSlip::viscousAcceleration
(
    const turbulenceCoupling& c,
    const scalarField& nut,
    const logLaw& law,
    const UList<vector2D>& U,
    UList<vector2D>& visc
)
{
    nuEff_.setSize(nut.size());
    forAll(nut, i)
    {
        nuEff_[i] = c.nu + nut[i];
    }
    dispatch(c.W, [&](const auto& K)
    {
        usaw::wallFunctionViscous
        (
            K, c.nbrs, c.usaw, c.V, nuEff_, U, c.dr, c.nu, law, visc
        );
    });
}


void Foam::SPH::wallFunctionSlip::moveVertices
(
    const usawWalls& walls,
    const label nFluid,
    const UList<vector2D>& visc,
    const scalar dt,
    UList<vector2D>& U
)
{
    const label n = U.size();
    if (vertexTangent_.size() != n - nFluid)
    {
        vertexTangent_.setSize(n - nFluid);
        setTangents(walls, nFluid);
    }
    for (label i = nFluid; i < n; ++i)
    {
        const vector2D& t = vertexTangent_[i - nFluid];
        U[i] = ((U[i] + dt*visc[i]) & t)*t;
    }
}


// ************************************************************************* //
