/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "laplacianMatrix.H"
#include "openMPThreshold.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

inline void Foam::SPH::laplacianMatrix::rowBuilder::add
(
    const label j,
    const scalar c
)
{
    // c (phi_i - phi_j); a Dirichlet phi_j = s f_j goes to the right-hand
    // side
    diag += c;
    if (o.kind[j] == dirichlet)
    {
        b += c*o.s*o.f[j];
    }
    else
    {
        row.emplace_back(j, -c);
    }
}


template<class Kernel>
inline void Foam::SPH::laplacianMatrix::pairTerms
(
    const Kernel& K,
    const label i,
    const scalar invGamma,
    const bool sources,
    const bool own,
    const vector2D& q,
    rowBuilder& r
)
{
    // One entry per neighbour (an extension row averages over the fluid
    // and the vertices that are unknowns)
    const operands& o = r.o;
    for (label k = o.off[i]; k < o.off[i + 1]; ++k)
    {
        const label j = o.nbr[k];
        if
        (
            sources || j < o.nFluid
         || o.kind[j] == interior || o.kind[j] == extension
        )
        {
            scalar c = -(o.B[i] + o.B[j])*invGamma*o.V[j]*K.dWdrByR(o.r[k]);
            if (own)
            {
                c -= invGamma*o.V[j]*(K.gradW(o.rij[k], o.r[k]) & q);
            }
            r.add(j, c);
        }
    }
}


inline void Foam::SPH::laplacianMatrix::wallTerms
(
    const label i,
    const scalar invGamma,
    const bool own,
    const vector2D& q,
    rowBuilder& r
)
{
    const operands& o = r.o;
    for (label k = o.wOff[i]; k < o.wOff[i + 1]; ++k)
    {
        const labelPair& e = o.ends[o.seg[k]];
        if (own)
        {
            // (phi_a - phi_s) grad gamma_as . q, phi_s the vertices' mean
            const scalar f = invGamma*(o.gradGammaAs[k] & q);
            r.add(e.first(), 0.5*f);
            r.add(e.second(), 0.5*f);
        }
        // B_s dphi/dn_s, and B_a dphi/dn_s where the particle's own
        // gradient is not implicit (eq. (40))
        const scalar Bs = 0.5*(o.B[e.first()] + o.B[e.second()]);
        const scalar Bw = own ? Bs : Bs + o.B[i];
        r.b -= Bw*invGamma*o.flux[o.seg[k]]*mag(o.gradGammaAs[k]);

        // Robin: dphi/dn_as = (k_s phi_a - g_s)/max(d_as, d_min)
        if (o.robinK)
        {
            const label s = o.seg[k];
            const scalar w =
                Bw*invGamma*mag(o.gradGammaAs[k])
               /max(o.dAs[k], o.robinMinDistance);
            r.robinDiag += w*o.robinK[s];
            r.b += w*o.robinG[s];
        }
    }
}


template<class Kernel>
inline Foam::scalar Foam::SPH::laplacianMatrix::equationRow
(
    const Kernel& K,
    const operands& o,
    const label i,
    matrixRow& row
)
{
    rowBuilder r{o, row, 0, 0, 0};
    const scalar invGamma = 1/o.gamma[i];
    const bool sources = o.kind[i] == interior;

    // The fluid particle's own normal gradient, eq. (10) as printed:
    // B_a (grad phi)_a . grad gamma_a/gamma_a with (grad phi)_a = R G-{phi},
    // the gradient of the pressure's projection (eq. (40) doubles the
    // wall's instead, and the projection then leaves the divergence of a
    // particle driven towards a wall); q = B_a R^T grad gamma_a/gamma_a
    const bool own = sources && o.R && i < o.nFluid;
    const vector2D q
    (
        own
      ? o.B[i]*invGamma*(o.R[i].T() & o.gradGamma[i])
      : vector2D::zero
    );

    pairTerms(K, i, invGamma, sources, own, q, r);
    if (sources)
    {
        r.b -= o.S[i];
        wallTerms(i, invGamma, own, q, r);
    }
    scalar diag = o.diagonalFactor*r.diag;
    if (sources && (o.Sp || o.robinK))
    {
        diag += r.robinDiag - (o.Sp ? o.Sp[i] : 0);
    }
    row.emplace_back(i, diag);
    return r.b;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Kernel>
void Foam::SPH::laplacianMatrix::assemble
(
    const Kernel& K,
    const scalarUList& S
)
{
    check(S);
    const operands o(view(S));
    const label n = nbrs_.size();

    rows_.resize(n);
    b_.resize(n);
    #pragma omp parallel for schedule(static) if(SPH::worthThreads(n))
    for (label i = 0; i < n; ++i)
    {
        matrixRow& row = rows_[i];
        row.clear();
        if (o.kind[i] == dirichlet)
        {
            row.emplace_back(i, 1);
            b_[i] = o.s*o.f[i];
            continue;
        }
        if (o.kind[i] == copy)
        {
            row.emplace_back(i, 1);
            row.emplace_back(o.copyFrom[i], -1);
            b_[i] = 0;
        }
        else
        {
            b_[i] = equationRow(K, o, i, row);
        }
        compress(row);
    }
    fillMatrix();
}


// ************************************************************************* //
