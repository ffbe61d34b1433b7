/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The second-order USAW operators: the Laplacians L{B, phi} (Leroy et al.
    2014, eqs. (10), (15)-(17)), the laminar viscous term and the
    concentration gradient of the shifting. Included by usawOperators.H
    after usawOperatorsTemplates.C, whose local functions they share.

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::usaw::laplacian
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& A,
    const scalarUList& dAdn,
    UList<scalar>& result
)
{
    checkOperands
    (
        "laplacian", nbrs, walls, V.size(), {A.size()}, dAdn.size(), result.size()
    );
    const scalar* v = V.cdata();
    const scalar* a = A.cdata();
    const scalar* g = dAdn.cdata();

    // Eq. (40): B = 1 and (grad A)_a . n_s = (grad A)_s . n_s;
    // r_ab . grad w_ab/r_ab^2 = dW/dr/r
    detail::sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D&, const scalar r)
        {
            return 2*v[j]*(a[i] - a[j])*K.dWdrByR(r);
        },
        [&](const label, const label s, const vector2D& gradGammaAs, const scalar)
        {
            return -2*g[s]*mag(gradGammaAs);
        },
        result
    );
}


template<class Kernel>
void Foam::SPH::usaw::laplacian
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& B,
    const scalarUList& A,
    const scalarUList& dAdn,
    UList<scalar>& result
)
{
    checkOperands
    (
        "laplacian", nbrs, walls, V.size(), {B.size(), A.size()}, dAdn.size(),
        result.size()
    );
    const scalar* v = V.cdata();
    const scalar* b = B.cdata();
    const scalar* a = A.cdata();
    const scalar* g = dAdn.cdata();
    const labelPair* ends = walls.segmentParticles().cdata();

    // Eq. (10) with (grad A)_a . n_s = (grad A)_s . n_s (section 3.3)
    detail::sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D&, const scalar r)
        {
            return v[j]*(b[i] + b[j])*(a[i] - a[j])*K.dWdrByR(r);
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar)
        {
            return -(detail::segmentValue(ends, b, s) + b[i])*g[s]*mag(gradGammaAs);
        },
        result
    );
}


template<class Kernel>
void Foam::SPH::usaw::laplacian
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& B,
    const scalarUList& A,
    const scalarUList& dAdn,
    const UList<vector2D>& gradA,
    UList<scalar>& result
)
{
    checkOperands
    (
        "laplacian", nbrs, walls, V.size(), {B.size(), A.size(), gradA.size()},
        dAdn.size(), result.size()
    );
    const scalar* v = V.cdata();
    const scalar* b = B.cdata();
    const scalar* a = A.cdata();
    const scalar* g = dAdn.cdata();
    const vector2D* ga = gradA.cdata();
    const labelPair* ends = walls.segmentParticles().cdata();

    // Eq. (10) as printed: grad gamma_as = |grad gamma_as| n_s, so
    // (grad A)_s . grad gamma_as = dAdn_s |grad gamma_as|
    detail::sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D&, const scalar r)
        {
            return v[j]*(b[i] + b[j])*(a[i] - a[j])*K.dWdrByR(r);
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar)
        {
            return
              - detail::segmentValue(ends, b, s)*g[s]*mag(gradGammaAs)
              - b[i]*(ga[i] & gradGammaAs);
        },
        result
    );
}


template<class Kernel>
void Foam::SPH::usaw::laminarViscous
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalar mu,
    const UList<vector2D>& u,
    const scalar dr,
    UList<vector2D>& result
)
{
    checkOperands("laminarViscous", nbrs, walls, V.size(), {u.size()}, -1, result.size());
    const scalar* v = V.cdata();
    const vector2D* U = u.cdata();
    const labelPair* ends = walls.segmentParticles().cdata();
    const vector2D* normal = walls.segmentNormals().cdata();

    // Eq. (15)
    detail::sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D&, const scalar r)
        {
            return (2*mu*v[j]*K.dWdrByR(r))*(U[i] - U[j]);
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar d)
        {
            // Velocity relative to the segment, its part along the wall
            // ((u^R . t_as) t_as of eq. (16)) and eq. (17)
            const vector2D& n = normal[s];
            const vector2D uR(U[i] - detail::segmentValue(ends, U, s));
            const vector2D uRt(uR - (uR & n)*n);
            const scalar drAs = max(d, dr);
            return (-2*mu*mag(gradGammaAs)/drAs)*uRt;
        },
        result
    );
}


template<class Kernel>
void Foam::SPH::usaw::wallFunctionViscous
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    const scalarUList& nuEff,
    const UList<vector2D>& u,
    const scalar dr,
    const scalar nu,
    const logLaw& law,
    UList<vector2D>& result
)
{
    checkOperands("wallFunctionViscous", nbrs, walls, V.size(), {nuEff.size(), u.size()}, -1, result.size());
    const scalar* v = V.cdata();
    const scalar* nuE = nuEff.cdata();
    const vector2D* U = u.cdata();
    const vector2D* normal = walls.segmentNormals().cdata();

    // Eq. (22): the wall at rest, u^R_as = u_a (the vertex particles'
    // velocities are the fluid's slip there, eq. (24), not the wall's)
    detail::sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label i, const label j, const vector2D&, const scalar r)
        {
            return (v[j]*(nuE[i] + nuE[j])*K.dWdrByR(r))*(U[i] - U[j]);
        },
        [&](const label i, const label s, const vector2D& gradGammaAs, const scalar d)
        {
            const vector2D& n = normal[s];
            const vector2D uRt(U[i] - (U[i] & n)*n);
            const scalar ut = mag(uRt);
            if (ut == 0)
            {
                return vector2D(Zero);
            }
            const scalar uStar2 = law.uStarSqr(ut, max(d, dr), nu);
            return vector2D((-2*uStar2*mag(gradGammaAs)/ut)*uRt);
        },
        result
    );
}


template<class Kernel>
void Foam::SPH::usaw::concentrationGradient
(
    const Kernel& K,
    const neighbourList& nbrs,
    const usawWalls& walls,
    const scalarUList& V,
    UList<vector2D>& result
)
{
    checkOperands("concentrationGradient", nbrs, walls, V.size(), {}, -1, result.size());
    const scalar* v = V.cdata();

    // Eq. (37)
    detail::sumOverNeighboursAndWalls
    (
        nbrs,
        walls,
        [&](const label, const label j, const vector2D& rij, const scalar r)
        {
            return v[j]*K.gradW(rij, r);
        },
        [&](const label, const label, const vector2D& gradGammaAs, const scalar)
        {
            return -gradGammaAs;
        },
        result
    );
}


// ************************************************************************* //
