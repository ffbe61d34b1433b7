/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wcsphBounds.H"
#include "checkedEntry.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::wcsphBounds::machAction>
Foam::SPH::wcsphBounds::machActionNames
({
    { machAction::warn, "warn" },
    { machAction::stop, "stop" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wcsphBounds::wcsphBounds
(
    const dictionary& schemes,
    const wcsphWork& work
)
:
    work_(work),
    rhoMin_(0.8),
    rhoMax_(1.25),
    maxMach_
    (
        checkedScalar
        (
            schemes, "maxMach", 0.3, {0, VGREAT, true},
            "the largest max|U|/c0 of a weakly compressible flow"
        )
    ),
    onMach_
    (
        machActionNames.getOrDefault("onMachExceeded", schemes, machAction::warn)
    ),
    warned_(false),
    iMin_(-1), iMax_(-1), iFast_(-1),
    extremesKnown_(false),
    rhoMinReached_(VGREAT), tRhoMin_(0),
    rhoMaxReached_(-VGREAT), tRhoMax_(0),
    machReached_(0), tMach_(0)
{
    if (schemes.found("densityBounds"))
    {
        const Pair<scalar> bounds(schemes.get<Pair<scalar>>("densityBounds"));
        rhoMin_ = bounds.first();
        rhoMax_ = bounds.second();
        if
        (
            !(rhoMin_ >= 0 && rhoMin_ < 1)
         || !(rhoMax_ > 1 && std::isfinite(rhoMax_))
        )
        {
            FatalIOErrorInFunction(schemes)
                << "Entry densityBounds (" << rhoMin_ << " " << rhoMax_
                << "): expected (min max) of rho/rho0 with 0 <= min < 1 < max"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wcsphBounds::extremes
(
    label& iMin,
    label& iMax,
    label& iFast
) const
{
    const scalar* rho = work_.parts.field<scalar>("rho").cdata();
    const vector2D* U = work_.parts.field<vector2D>("U").cdata();
    iMin = iMax = iFast = -1;
    scalar rhoMin = VGREAT, rhoMax = -VGREAT, speed2 = -1;
    for (label i = 0; i < work_.nFluid; ++i)
    {
        if (rho[i] < rhoMin) { rhoMin = rho[i]; iMin = i; }
        if (rho[i] > rhoMax) { rhoMax = rho[i]; iMax = i; }
        const scalar s2 = magSqr(U[i]);
        if (s2 > speed2) { speed2 = s2; iFast = i; }
    }
}


Foam::string Foam::SPH::wcsphBounds::density(const scalar rho) const
{
    return
        Foam::name(rho/work_.rho0) + " rho0 (" + Foam::name(rho)
      + " kg/m^3)";
}


Foam::string Foam::SPH::wcsphBounds::machText(const scalar speed) const
{
    return
        "Mach number |U|/c0 = " + Foam::name(speed/work_.c0) + " (|U| "
      + Foam::name(speed) + " m/s, c0 " + Foam::name(work_.c0)
      + " m/s) above maxMach " + Foam::name(maxMach_)
      + " (system/sphSchemes, onMachExceeded "
      + machActionNames[onMach_] + "): the weakly compressible assumption"
        " (density errors of order Ma^2) does not hold";
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::SPH::wcsphBounds::describe() const
{
    return
        "rho/rho0 outside densityBounds (" + Foam::name(rhoMin_) + " "
      + Foam::name(rhoMax_) + "), max|U|/c0 above maxMach "
      + Foam::name(maxMach_) + " (onMachExceeded " + machActionNames[onMach_]
      + ")";
}


Foam::label Foam::SPH::wcsphBounds::find(string& what) const
{
    if (!work_.nFluid) return -1;

    extremes(iMin_, iMax_, iFast_);
    extremesKnown_ = true;
    const label iMin = iMin_, iMax = iMax_, iFast = iFast_;
    const scalarField& rho = work_.parts.field<scalar>("rho");
    const scalar rho0 = work_.rho0;
    auto outside = [&](const label i)
    {
        what =
            "Density " + density(rho[i]) + ", outside densityBounds ("
          + Foam::name(rhoMin_) + " " + Foam::name(rhoMax_) + ") of"
            " system/sphSchemes: the equation of state is out of its weakly"
            " compressible range, at";
        return i;
    };

    if (rho[iMin] < rhoMin_*rho0)
    {
        return outside(iMin);
    }
    if (rho[iMax] > rhoMax_*rho0)
    {
        return outside(iMax);
    }
    const scalar speed = mag(work_.parts.field<vector2D>("U")[iFast]);
    if (onMach_ == machAction::stop && speed > maxMach_*work_.c0)
    {
        what = machText(speed) + ", at";
        return iFast;
    }
    return -1;
}


void Foam::SPH::wcsphBounds::checkStart(const word& timeName) const
{
    string what;
    const label i = find(what);
    extremesKnown_ = false;
    if (i < 0) return;
    const vector2D& x = work_.parts.positions()[i];
    FatalErrorInFunction
        << what.c_str() << " particle id " << work_.parts.field<label>("id")[i]
        << " at (" << x.x() << " " << x.y() << ")" << nl
        << "    in the starting state, time " << timeName << ": no step from"
        << " it can be good. The equation of state, eq. (4), gives rho0 (1 +"
        << " p/b0)^(1/gamma) with b0 = rho0 c0^2/gamma = " << work_.b0
        << " Pa (c0 " << work_.c0 << " m/s): raise c0 or lower the initial"
        << " pressure or speeds (0/p, 0/U)" << nl << exit(FatalError);
}


void Foam::SPH::wcsphBounds::afterStep(const Time& runTime)
{
    if (!work_.nFluid) return;

    if (!extremesKnown_)
    {
        extremes(iMin_, iMax_, iFast_);
    }
    extremesKnown_ = false;
    const label iMin = iMin_, iMax = iMax_, iFast = iFast_;
    const scalarField& rho = work_.parts.field<scalar>("rho");
    const scalar t = runTime.value();
    if (rho[iMin] < rhoMinReached_*work_.rho0)
    {
        rhoMinReached_ = rho[iMin]/work_.rho0;
        tRhoMin_ = t;
    }
    if (rho[iMax] > rhoMaxReached_*work_.rho0)
    {
        rhoMaxReached_ = rho[iMax]/work_.rho0;
        tRhoMax_ = t;
    }
    const scalar speed = mag(work_.parts.field<vector2D>("U")[iFast]);
    if (speed > machReached_*work_.c0)
    {
        machReached_ = speed/work_.c0;
        tMach_ = t;
    }

    if (speed > maxMach_*work_.c0 && !warned_)
    {
        const vector2D& x = work_.parts.positions()[iFast];
        WarningInFunction
            << machText(speed).c_str() << ", at particle id "
            << work_.parts.field<label>("id")[iFast] << " at (" << x.x()
            << " " << x.y() << "), time " << t << " s" << nl
            << "    (warned once per write interval; raise c0, or set"
            << " onMachExceeded stop)" << endl;
        warned_ = true;
    }
    if (runTime.writeTime())
    {
        warned_ = false;
    }
}


void Foam::SPH::wcsphBounds::writeState(Ostream& os) const
{
    os.writeEntry("rhoMinReached", Pair<scalar>(rhoMinReached_, tRhoMin_));
    os.writeEntry("rhoMaxReached", Pair<scalar>(rhoMaxReached_, tRhoMax_));
    os.writeEntry("machReached", Pair<scalar>(machReached_, tMach_));
}


void Foam::SPH::wcsphBounds::readState(const dictionary& state)
{
    const auto read = [&](const word& key, scalar& value, scalar& t)
    {
        Pair<scalar> reached(value, t);
        state.readIfPresent(key, reached);
        value = reached.first();
        t = reached.second();
    };
    read("rhoMinReached", rhoMinReached_, tRhoMin_);
    read("rhoMaxReached", rhoMaxReached_, tRhoMax_);
    read("machReached", machReached_, tMach_);
}


void Foam::SPH::wcsphBounds::printSummary(Ostream& os) const
{
    if (machReached_ <= 0 && rhoMaxReached_ < 0) return;
    os  << "Bounds reached: rho/rho0 from " << rhoMinReached_ << " (t = "
        << tRhoMin_ << " s) to " << rhoMaxReached_ << " (t = " << tRhoMax_
        << " s), densityBounds (" << rhoMin_ << " " << rhoMax_ << ");"
        << " max|U|/c0 " << machReached_ << " (t = " << tMach_
        << " s), maxMach " << maxMach_ << nl;
}


// ************************************************************************* //
