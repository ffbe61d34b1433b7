/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "projection.H"
#include "usawOperators.H"
#include "kernelDispatch.H"
#include "ghostSurface.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::projection::gradientForm>
Foam::SPH::projection::gradientFormNames
({
    { gradientForm::antisymmetric, "antisymmetric" },
    { gradientForm::symmetric, "symmetric" },
    { gradientForm::renormalised, "renormalised" },
});


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const char* Foam::SPH::projection::formDescription(const gradientForm form)
{
    switch (form)
    {
        case gradientForm::symmetric:
            return "G-{p} (8) (pressureGradient symmetric)";
        case gradientForm::renormalised:
            return
                "G-{p} (8) renormalised by G-{r}^-1 (pressureGradient"
                " renormalised; beyond 000_...)";
        default:
            return "G+{p} (5) (pressureGradient antisymmetric)";
    }
}


void Foam::SPH::projection::describe(Ostream& os) const
{
    os  << "eq. (32) with " << formDescription(form_);
    if (work_.dynamicPressureGradient)
    {
        os  << " of the dynamic pressure p - rho g.x (confined; Leroy et"
            << " al. 2015 eq. (17))";
    }
    else
    {
        os  << ", gravity " << work_.g;
    }
}


template<class Kernel>
Foam::vector2D Foam::SPH::projection::ghostGradient
(
    const Kernel& K,
    const isphWork& w,
    const scalarUList& p,
    const label a
)
{
    // Eq. (8) for p and r over the real neighbours and the walls
    const label* off = w.nbrs.offsets().cdata();
    const label* nbr = w.nbrs.indices().cdata();
    const vector2D* rij = w.nbrs.rij().cdata();
    const scalar* r = w.nbrs.r().cdata();
    vector2D Gp(Zero);
    tensor2D Gr(Zero);
    for (label k = off[a]; k < off[a + 1]; ++k)
    {
        const label b = nbr[k];
        const vector2D gradW(K.gradW(rij[k], r[k]));
        Gp -= w.V[b]*(p[a] - p[b])*gradW;
        Gr -= w.V[b]*(gradW*rij[k]);
    }
    const label* wOff = w.usaw.offsets().cdata();
    const label* seg = w.usaw.segments().cdata();
    const vector2D* gradGammaAs = w.usaw.gradGammaAs().cdata();
    const labelPair* ends = w.usaw.segmentParticles().cdata();
    const vector2DField& x = w.parts.positions();
    for (label k = wOff[a]; k < wOff[a + 1]; ++k)
    {
        const labelPair& e = ends[seg[k]];
        Gp += (p[a] - 0.5*(p[e.first()] + p[e.second()]))*gradGammaAs[k];
        Gr +=
            gradGammaAs[k]
           *w.usaw.fromSegment(x[a], x[e.first()], x[e.second()]);
    }

    // The ghosts': -sum_v dr^2 (p_a - p_v) grad w_av with grad w_av =
    // -F r_va, and -sum_v dr^2 r_av (x) grad w_av = -T_g, both along n
    // only (t = n.T_g.n): the tangential gradient comes from the real
    // neighbours, and a normal tilted by theta changes the gradient of a
    // linear pressure at second order in theta (with T_g itself, at first:
    // still water by a wall disordered by the shifting drifted at 3e-4 m/s).
    // Where the real neighbours hardly span the surface's direction (the
    // tip of a jet: det below a tenth of the completed support's), T_g
    // itself: the ghosts' tangential part, without which the tip's
    // gradient is singular
    const tensor2D Tg(w.latticeMoment - ghostSurface::neighbourMoment(K, w, a));
    const vector2D& n = w.surfaceNormal[a];
    const scalar t = n & (Tg & n);
    const scalar pSurface = w.airPressure ? (*w.airPressure)[a] : 0;
    const scalar pByDelta = (p[a] - pSurface)/w.surfaceDistance;
    const tensor2D GrAlongN(Gr - t*(n*n));
    if (det(GrAlongN) > 0.1*det(Gr - Tg))
    {
        return inv(GrAlongN) & (Gp + pByDelta*t*n);
    }
    return inv(Gr - Tg) & (Gp + pByDelta*(Tg & n));
}



void Foam::SPH::projection::gradient
(
    const gradientForm form,
    const kernel& W,
    const neighbourList& nbrs,
    const usawWalls& usaw,
    const scalarUList& V,
    const UList<tensor2D>& R,
    const scalarUList& p,
    UList<vector2D>& gradP
)
{
    dispatch(W, [&](const auto& K)
    {
        switch (form)
        {
            case gradientForm::antisymmetric:
                usaw::gradPlus(K, nbrs, usaw, V, p, gradP);
                break;
            case gradientForm::symmetric:
                usaw::gradMinus(K, nbrs, usaw, V, p, gradP);
                break;
            case gradientForm::renormalised:
                usaw::gradMinus(K, nbrs, usaw, V, R, p, gradP);
                break;
        }
    });
}


void Foam::SPH::projection::pressureGradient
(
    const isphWork& w,
    const gradientForm form,
    UList<vector2D>& gradP
)
{
    pressureGradient(w, form, w.parts.field<scalar>("p"), gradP);
}


void Foam::SPH::projection::pressureGradient
(
    const isphWork& w,
    const gradientForm form,
    const scalarField& p,
    UList<vector2D>& gradP
)
{
    if (w.dynamicPressureGradient)
    {
        // G{A} + rho g, so that u** + dt (g - G{p}/rho) is u** - dt G{A}/rho
        const vector2DField& x = w.parts.positions();
        scalarField A(p.size());
        forAll(A, i)
        {
            A[i] = p[i] - w.rho0*(w.g & x[i]);
        }
        gradient(form, w.W, w.nbrs, w.usaw, w.V, w.R, A, gradP);
        for (vector2D& gp : gradP)
        {
            gp += w.rho0*w.g;
        }
        return;
    }
    gradient(form, w.W, w.nbrs, w.usaw, w.V, w.R, p, gradP);
    if (w.ghostSurface && form == gradientForm::renormalised)
    {
        dispatch(w.W, [&](const auto& K)
        {
            for (label i = 0; i < w.nFluid; ++i)
            {
                if (w.surfaceNormal[i] != vector2D::zero)
                {
                    gradP[i] = ghostGradient(K, w, p, i);
                }
            }
        });
    }
}


void Foam::SPH::projection::execute(const scalar dt)
{
    isphWork& w = work_;
    pressureGradient(w, form_, gradP_);

    vector2D* U = w.parts.field<vector2D>("U").data();
    const vector2D g = w.g;
    const scalar rho0 = w.rho0;
    const label nFluid = w.nFluid;
    for (label i = 0; i < nFluid; ++i)
    {
        U[i] = w.Ustar[i] + dt*(g - gradP_[i]/rho0);
    }
    if (w.pressureAcceleration)
    {
        vector2DField& a = *w.pressureAcceleration;
        for (label i = 0; i < nFluid; ++i)
        {
            a[i] = g - gradP_[i]/rho0;
        }
    }
}


// ************************************************************************* //
