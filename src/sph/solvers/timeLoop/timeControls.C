/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "timeControls.H"
#include "checkedEntry.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    void checkWriteControls(const dictionary& dict)
    {
        const word control(dict.getOrDefault<word>("writeControl", "timeStep"));
        if (!Time::writeControlNames.found(control))
        {
            FatalIOErrorInFunction(dict.lookup("writeControl"))
                << "Entry writeControl " << control << ": expected one of "
                << Time::writeControlNames.sortedToc() << exit(FatalIOError);
        }
        const word key(dict.found("writeInterval") ? "writeInterval" : "writeFrequency");
        if (!dict.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Missing entry writeInterval" << exit(FatalIOError);
        }
        const scalar interval = dict.get<scalar>(key);
        if
        (
            Time::writeControlNames[control] == Time::wcTimeStep
         && !(interval >= 1 && std::floor(interval) == interval)
        )
        {
            FatalIOErrorInFunction(dict.lookup(key))
                << "Entry " << key << " " << interval << ": expected a whole"
                << " number of time steps >= 1 for writeControl timeStep"
                << exit(FatalIOError);
        }
        SPH::checkNumber(dict, key, interval, {0, VGREAT, true});
    }

    //- endTime: not before the start, reachable by the fixed step, and
    //- after at least one step (Time::run() runs while t < endTime - dt/2)
    void checkEndTime(const Time& runTime, const dictionary& dict, const scalar deltaT)
    {
        const word stopAt(dict.getOrDefault<word>("stopAt", "endTime"));
        if (stopAt == "endTime" || dict.found("endTime"))
        {
            const scalar tEnd = SPH::checkedScalar(dict, "endTime", {-VGREAT, VGREAT});
            const scalar tStart = runTime.value();
            if (tEnd < tStart && stopAt == "endTime")
            {
                FatalIOErrorInFunction(dict.lookup("endTime"))
                    << "Entry endTime " << tEnd << ": before the start time "
                    << tStart << " (startFrom "
                    << dict.getOrDefault<word>("startFrom", "latestTime")
                    << "): expected endTime > " << tStart << exit(FatalIOError);
            }
            // A fixed step so small that the run would never end (or stop
            // advancing the time when t + deltaT rounds to t)
            const scalar nSteps = (tEnd - tStart)/deltaT;
            if
            (
                stopAt == "endTime" && nSteps > 1e10
             && !dict.getOrDefault<bool>("adjustTimeStep", false)
            )
            {
                FatalIOErrorInFunction(dict.lookup("deltaT"))
                    << "Entry deltaT " << deltaT << ": " << nSteps << " fixed"
                    << " steps from " << tStart << " to endTime " << tEnd
                    << " (more than 1e10)" << exit(FatalIOError);
            }
            // Time::run() runs while t < endTime - deltaT/2: a larger first
            // step would end the run before it starts, without a word
            const scalar dt0 = runTime.deltaTValue();
            if (stopAt == "endTime" && tEnd > tStart && !(tStart < tEnd - 0.5*dt0))
            {
                FatalIOErrorInFunction(dict.lookup("deltaT"))
                    << "Entry deltaT " << dt0
                    << (
                           runTime.timeIndex() > 0
                         ? " (the last step, from uniform/time of the start time)"
                         : ""
                       )
                    << ": not less than twice the time from the start "
                    << tStart << " to endTime " << tEnd
                    << ", so no step would run" << exit(FatalIOError);
            }
            if (tEnd == tStart && stopAt == "endTime")
            {
                Info<< "endTime " << tEnd << " in " << dict.name()
                    << " is the start time: nothing to do" << nl << endl;
            }
        }
    }
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::SPH::checkTimeControls(const Time& runTime)
{
    const dictionary& dict = runTime.controlDict();

    const scalar deltaT = checkedScalar(dict, "deltaT", {0, VGREAT, true}, "s");
    if (runTime.value() + deltaT == runTime.value())
    {
        FatalIOErrorInFunction(dict.lookup("deltaT"))
            << "Entry deltaT " << deltaT << ": too small to advance the start"
            << " time " << runTime.value() << exit(FatalIOError);
    }

    checkEndTime(runTime, dict, deltaT);

    checkWriteControls(dict);

    if
    (
        dict.getOrDefault<bool>("adjustTimeStep", false)
     || dict.found("maxCo")
    )
    {
        checkedScalar
        (
            dict, "maxCo", 0.2, {0, 1, true},
            "the Courant number of the time step; above 1 a particle would"
            " travel more than a smoothing length in a step"
        );
    }
    if (dict.found("maxDeltaT"))
    {
        checkedScalar(dict, "maxDeltaT", {0, VGREAT, true}, "s");
    }
    if (dict.found("retryOnFailure"))
    {
        const label n = dict.get<label>("retryOnFailure");
        if (n < 0 || n > 20)
        {
            FatalIOErrorInFunction(dict.lookup("retryOnFailure"))
                << "Entry retryOnFailure " << n << ": expected how many times"
                << " a failed step is taken again with half the time step,"
                << " 0 (off) to 20" << exit(FatalIOError);
        }
        if (n > 0 && !dict.getOrDefault<bool>("adjustTimeStep", false))
        {
            FatalIOErrorInFunction(dict.lookup("retryOnFailure"))
                << "Entry retryOnFailure " << n << " needs adjustTimeStep yes:"
                << " the halved step of a retry is an adjusted time step"
                << exit(FatalIOError);
        }
    }
    if (dict.found("logInterval"))
    {
        const label n = dict.get<label>("logInterval");
        if (n < 1)
        {
            FatalIOErrorInFunction(dict.lookup("logInterval"))
                << "Entry logInterval " << n << ": expected a number of"
                << " time steps >= 1" << exit(FatalIOError);
        }
    }
}


void Foam::SPH::checkDeltaT
(
    const Time& runTime,
    const scalar dt,
    const std::string& state
)
{
    const scalar t = runTime.value();
    const bool toEndTime =
        runTime.controlDict().getOrDefault<word>("stopAt", "endTime")
     == "endTime";
    const scalar nSteps =
        toEndTime ? (runTime.endTime().value() - t)/dt : scalar(0);
    if (!(dt > 0 && std::isfinite(dt) && t + dt > t && nSteps < 1e10))
    {
        FatalErrorInFunction
            << "The time step at time " << t << " s is " << dt << " s: it"
            << " cannot advance the time, or would take " << nSteps
            << " steps to endTime (" << state.c_str() << ")" << nl
            << "Check the initial fields (0/U, 0/p) or, on a restart, "
            << runTime.timePath()/"lagrangian/sph" << exit(FatalError);
    }
}


// ************************************************************************* //
