/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsphShifting.H"
#include "checkedEntry.H"
#include "kernelDispatch.H"
#include "freeSurfaceRegion.H"
#include "spreadLimit.H"
#include "neighbourRange.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::wcsphShifting::velocityScale>
Foam::SPH::wcsphShifting::velocityScaleNames
({
    { velocityScale::local, "local" },
    { velocityScale::max, "max" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wcsphShifting::wcsphShifting
(
    const dictionary& schemes,
    wcsphWork& work,
    wcsphWallModel& wallModel,
    const kernel& W,
    const std::function<void()>& searchNeighbours
)
:
    stage("shifting", {"positions", "U", "rho"}, {"positions", "U", "rho"}),
    work_(work),
    wallModel_(wallModel),
    kernel_(W),
    searchNeighbours_(searchNeighbours),
    coeff_
    (
        checkedScalar
        (
            schemes, "shiftCoeff", 2, {0, 100, true},
            "A of the shift's D = A h U dt; 2 by default"
        )
    ),
    velocity_
    (
        velocityScaleNames.getOrDefault
        (
            "shiftVelocity", schemes, velocityScale::local
        )
    ),
    walls_(wallModel.operatorWalls()),
    maxShift_(0),
    // Section 3.2: "D{r} <= 1.5 in 2-D"
    freeSurfaceDivR_
    (
        checkedScalar
        (
            schemes, "freeSurfaceDivR", 1.5, {0, 2, true, true},
            "D{r} is 2 inside the fluid"
        )
    ),
    nSurface_(0),
    hasFreeSurface_(true),
    compaction_
    (
        checkedScalar
        (
            schemes, "interiorCompaction", scalar(0), {0, 1},
            "alpha: the fraction of a whole kernel's deficit beyond 2 %"
            " taken off its density each step"
        )
    ),
    latticeSum_(W.latticeSum()),
    nCompacted_(0)
{
    if (!(coeff_ > 0))
    {
        FatalIOErrorInFunction(schemes.lookup("shiftCoeff"))
            << "Entry shiftCoeff " << coeff_ << ": expected > 0 (A of the"
            << " shift's D = A h U dt; 2 by default)" << exit(FatalIOError);
    }
    if (!walls_)
    {
        noWalls_.reset(new wallMesh(work.cloud->dom()));
        noUsaw_.reset(new usawWalls(*noWalls_, W, work.nFluid, work.cloud->dom()));
        walls_ = noUsaw_.get();
    }
    wallModel.particleMasses(mass_);
    V_.setSize(mass_.size());
    D_.setSize(work.nFluid);
    gradF_.setSize(mass_.size());
    divR_.setSize(mass_.size());
    nearSurface_.setSize(work.nFluid);

    // A flow with no free-surface particle at the start is confined: the
    // step then skips the detection (one pass over the neighbours, 4 % of
    // the Taylor-Green vortex's run)
    prepare();
    D_ = 0;
    freeSurfaceOff();
    hasFreeSurface_ = nSurface_ > 0;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wcsphShifting::prepare()
{
    searchNeighbours_();
    walls_->update(work_.parts.positions());
    const scalar* rho = work_.parts.field<scalar>("rho").cdata();
    forAll(V_, b)
    {
        V_[b] = mass_[b]/rho[b];
    }
}


void Foam::SPH::wcsphShifting::freeSurfaceOff()
{
    dispatch(kernel_, [&](const auto& K)
    {
        usaw::divPosition(K, work_.nbrs, *walls_, V_, divR_);
    });
    nSurface_ = markFreeSurfaceRegion
    (
        work_.nbrs, work_.nFluid, divR_, freeSurfaceDivR_,
        0.5*kernel_.support(), nearSurface_
    );
    for (label i = 0; i < work_.nFluid; ++i)
    {
        if (nearSurface_[i])
        {
            D_[i] = 0;
        }
    }
}


template<class Kernel>
void Foam::SPH::wcsphShifting::compact(const Kernel& K)
{
    const label nFluid = work_.nFluid;
    const label* off = work_.nbrs.offsets().cdata();
    const label* nbr = work_.nbrs.indices().cdata();
    const vector2D* rij = work_.nbrs.rij().cdata();
    const scalar* r = work_.nbrs.r().cdata();
    scalarField& rho = work_.parts.field<scalar>("rho");
    const scalar dr2ByFull = sqr(work_.dr)/latticeSum_;
    nCompacted_ = 0;
    for (label i = 0; i < nFluid; ++i)
    {
        scalar sum = K.W(0);
        vector2D moment(0, 0);
        bool byWall = false;
        for (label k = off[i]; k < off[i + 1] && !byWall; ++k)
        {
            byWall = nbr[k] >= nFluid;
            const scalar w = K.W(r[k]);
            sum += w;
            moment += w*rij[k];
        }
        const scalar fill =
            spreadLimit::wholeKernelFill(sum, moment, byWall, K.h(), dr2ByFull);
        const scalar deficit = 1 - fill;
        if (fill < 0 || deficit <= 0.02 || deficit > 0.1)
        {
            continue;
        }
        rho[i] *= 1 - compaction_*(deficit - 0.02);
        V_[i] = mass_[i]/rho[i];
        ++nCompacted_;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wcsphShifting::describe(Ostream& os) const
{
    os  << "Lind et al. 2012 with D = A h U dt of Skillen et al. 2013,"
        << " A = shiftCoeff " << coeff_ << ", U = "
        << (velocity_ == velocityScale::local ? "|u_a|" : "max |u|")
        << "; G{1} (37), u and rho corrected by (38); "
        << (
               hasFreeSurface_
             ? "off within h q_max/2 of a free surface (D{r} <= "
             : "a confined flow (no particle with D{r} <= "
           )
        << freeSurfaceDivR_ << (hasFreeSurface_ ? ")" : " at the start)")
        << (walls_ == noUsaw_.get() ? " (SPH sums over fluid and walls)" : "");
    if (compaction_ > 0)
    {
        os  << "; density lowered by " << compaction_
            << " (deficit - 0.02) a step where a whole kernel is 2-10 % short"
            << " (interiorCompaction)";
    }
}


void Foam::SPH::wcsphShifting::execute(const scalar dt)
{
    prepare();
    if (compaction_ > 0)
    {
        dispatch(kernel_, [&](const auto& K) { compact(K); });
    }

    vector2DField& U = work_.parts.field<vector2D>("U");
    const label nFluid = work_.nFluid;
    const scalar coeff = coeff_*kernel_.h()*dt;
    if (velocity_ == velocityScale::local)
    {
        for (label i = 0; i < nFluid; ++i)
        {
            D_[i] = coeff*mag(U[i]);
        }
    }
    else
    {
        scalar maxU2 = 0;
        for (label i = 0; i < nFluid; ++i)
        {
            maxU2 = max(maxU2, magSqr(U[i]));
        }
        D_ = coeff*std::sqrt(maxU2);
    }
    if (hasFreeSurface_)
    {
        freeSurfaceOff();
    }

    dispatch(kernel_, [&](const auto& K)
    {
        maxShift_ = shift_.apply
        (
            K, work_.nbrs, *walls_, V_, work_.cloud->dom(), nFluid, D_,
            work_.parts.positions(), U, work_.parts.field<scalar>("rho")
        );
    });
    correctScalars();
}


void Foam::SPH::wcsphShifting::correctScalars()
{
    const List<vector2D>& gradC = shift_.concentrationGradient();
    for (const word& name : work_.shiftedScalars)
    {
        scalarField& f = work_.parts.field<scalar>(name);
        dispatch(kernel_, [&](const auto& K)
        {
            usaw::gradMinus(K, work_.nbrs, *walls_, V_, f, gradF_);
        });
        neighbourRange(work_.nbrs, work_.nFluid, f, fMin_, fMax_);
        for (label i = 0; i < work_.nFluid; ++i)
        {
            const scalar corrected = f[i] + (-D_[i]*gradC[i] & gradF_[i]);
            f[i] = min(max(corrected, fMin_[i]), fMax_[i]);
        }
    }
}


// ************************************************************************* //
