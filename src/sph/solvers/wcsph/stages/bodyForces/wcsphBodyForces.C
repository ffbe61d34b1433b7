/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsphBodyForces.H"
#include "Ostream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wcsphBodyForces::wcsphBodyForces
(
    wcsphWork& work,
    const wcsphWallModel& wallModel,
    autoPtr<fvOptionForces>&& forces,
    const vector2D& gPeriodic
)
:
    stage("bodyForces", {"U"}, {}),
    work_(work),
    wallModel_(wallModel),
    forces_(std::move(forces)),
    gPeriodic_(gPeriodic),
    f_(forces_->force()),
    f0_(f_)
{
    work_.bodyAcceleration = f_ + gPeriodic_;
}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::wcsphBodyForces> Foam::SPH::wcsphBodyForces::New
(
    const Time& runTime,
    wcsphWork& work,
    const wcsphWallModel& wallModel,
    const domain& dom
)
{
    autoPtr<fvOptionForces> forces(new fvOptionForces(runTime));
    forces->checkDomain(dom);

    const vector2D gAcross(dom.acrossPeriods(work.g));
    const vector2D gPeriodic(work.g - gAcross);
    if (forces->empty() && gPeriodic == vector2D::zero)
    {
        return nullptr;
    }
    work.g = gAcross;
    return autoPtr<wcsphBodyForces>
    (
        new wcsphBodyForces(work, wallModel, std::move(forces), gPeriodic)
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wcsphBodyForces::addTo(List<vector2D>& dUdt) const
{
    const vector2D a = f_ + gPeriodic_;
    for (label i = 0; i < work_.nFluid; ++i)
    {
        dUdt[i] += a;
    }
}


void Foam::SPH::wcsphBodyForces::execute(const scalar dt)
{
    if (forces_->empty())
    {
        return;
    }
    // Eq. (68) over the fluid at the end of the step, eq. (67) with its dt
    wallModel_.fluidVolumes(V_);
    f_ = forces_->acceleration(work_.parts.field<vector2D>("U"), V_, dt);
    work_.bodyAcceleration = f_ + gPeriodic_;
}


void Foam::SPH::wcsphBodyForces::describe(Ostream& os) const
{
    os  << "f added to du/dt of the fluid at each Runge-Kutta stage";
    if (gPeriodic_ != vector2D::zero)
    {
        os  << ", gravity along the period " << gPeriodic_;
    }
    if (!forces_->empty())
    {
        os  << "; constant/fvOptions, updated once per step from the"
            << " velocity at its end:";
    }
    for (const bodyForce& f : *forces_)
    {
        os  << nl << "                            ";
        f.describe(os);
    }
}


void Foam::SPH::wcsphBodyForces::printStep(Ostream& os) const
{
    forces_->printStep(os);
}


void Foam::SPH::wcsphBodyForces::save()
{
    f0_ = f_;
    forces_->save();
}


void Foam::SPH::wcsphBodyForces::restore()
{
    f_ = f0_;
    work_.bodyAcceleration = f_ + gPeriodic_;
    forces_->restore();
}


void Foam::SPH::wcsphBodyForces::write() const
{
    forces_->write();
}


// ************************************************************************* //
