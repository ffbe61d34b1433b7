/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "timeClock.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "uniformDimensionedFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Time keeps its clock protected; a derived class may name the members
//- (pointers to members of Time), which is all the access needed
class clockAccess
:
    public Time
{
public:

    static scalar Time::* startTimeMember() { return &clockAccess::startTime_; }
    static label Time::* startTimeIndexMember()
    {
        return &clockAccess::startTimeIndex_;
    }
    static scalar Time::* writeIntervalMember()
    {
        return &clockAccess::writeInterval_;
    }
    static label TimeState::* writeTimeIndexMember()
    {
        return &clockAccess::writeTimeIndex_;
    }
    static label Time::* purgeWriteMember() { return &clockAccess::purgeWrite_; }
};


//- Move the clock to a time directory: its time, its index
void startAt(Time& runTime, const instant& t)
{
    const IOdictionary timeDict
    (
        IOobject
        (
            "time", t.name(), "uniform", runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    const label index = timeDict.getOrDefault<label>("index", 0);
    runTime.setTime(t, index);
    runTime.*clockAccess::startTimeMember() = t.value();
    runTime.*clockAccess::startTimeIndexMember() = index;
    runTime.*clockAccess::writeTimeIndexMember() = 0;
}

//- Name of the run's start time on Time's registry
const word runStartName("sphRunStart");

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::timeClock::writeTimeIndex(const Time& runTime)
{
    return runTime.*clockAccess::writeTimeIndexMember();
}


void Foam::SPH::timeClock::setWriteTimeIndex(Time& runTime, const label index)
{
    runTime.*clockAccess::writeTimeIndexMember() = index;
}


bool Foam::SPH::timeClock::isWrittenState(const fileName& dir)
{
    return isDir(dir/"uniform") || isDir(dir/"lagrangian");
}


Foam::fileName Foam::SPH::timeClock::positionsFile(const fileName& timeDir)
{
    return timeDir/"lagrangian"/"sph"/"positions";
}


void Foam::SPH::timeClock::write(Ostream& os, const Time& runTime)
{
    os.writeEntry("time", runTime.value());
    os.writeEntry("timeIndex", runTime.timeIndex());
    os.writeEntry("writeTimeOrigin", runTime.*clockAccess::startTimeMember());
    os.writeEntry("writeTimeIndex", runTime.*clockAccess::writeTimeIndexMember());
    os.writeEntry("writeInterval", runTime.*clockAccess::writeIntervalMember());
}


void Foam::SPH::timeClock::restore(Time& runTime, const dictionary& dict)
{
    scalar t = 0;
    if (!dict.readIfPresent("time", t))
    {
        return;
    }
    // Keep the start directory's own name: timeName(t) at the precision
    // Time starts with need not spell it as it was written (the names grow
    // to 17 digits and more), and the particles are read from it (a restart
    // from 1.2115650656307653 looked in 1.211565065630765 and started afresh)
    const word dirName(runTime.timeName());
    runTime.setTime(instant(t, dirName), dict.get<label>("timeIndex"));

    if (dict.get<scalar>("writeInterval") == runTime.*clockAccess::writeIntervalMember())
    {
        runTime.*clockAccess::startTimeMember() = dict.get<scalar>("writeTimeOrigin");
        runTime.*clockAccess::writeTimeIndexMember() = dict.get<label>("writeTimeIndex");
    }
    else
    {
        Info<< "The writeInterval changed: write times counted from the"
            << " restart time " << runTime.timeName() << nl;
        runTime.*clockAccess::startTimeMember() = t;
        runTime.*clockAccess::writeTimeIndexMember() = 0;
    }
}


void Foam::SPH::timeClock::registerRunStart(Time& runTime)
{
    const dimensionedScalar start("runStart", dimTime, runTime.value());
    if (runTime.foundObject<uniformDimensionedScalarField>(runStartName))
    {
        runTime.lookupObjectRef<uniformDimensionedScalarField>(runStartName) =
            start;
        return;
    }
    runTime.store
    (
        new uniformDimensionedScalarField
        (
            IOobject
            (
                runStartName, runTime.timeName(), runTime,
                IOobject::NO_READ, IOobject::NO_WRITE, true
            ),
            start
        )
    );
}


Foam::scalar Foam::SPH::timeClock::runStart(const Time& runTime)
{
    return
        runTime.foundObject<uniformDimensionedScalarField>(runStartName)
      ? runTime.lookupObject<uniformDimensionedScalarField>(runStartName).value()
      : runTime.startTime().value();
}


Foam::label Foam::SPH::timeClock::takeOverPurgeWrite(Time& runTime)
{
    const label n = runTime.*clockAccess::purgeWriteMember();
    runTime.*clockAccess::purgeWriteMember() = 0;
    return n;
}


void Foam::SPH::timeClock::matchStartDirectory(Time& runTime)
{
    // Time looks for a start directory written with more digits than
    // timePrecision from 18 digits down, and stops where two precisions
    // spell the time alike: 1.236806004498073 (18 digits: ...0731, 17: the
    // same) was never tried at 16, and the restart looked in 1.23681.
    // Restarts lengthen the names (OpenFOAM adds digits until the next
    // name reads back as t + deltaT), so a long kill-and-restart run meets
    // it. The directory whose value is the start time gives its own name
    if (isDir(runTime.timePath()))
    {
        return;
    }
    const scalar t = runTime.value();
    for (const instant& dir : runTime.times())
    {
        if
        (
            dir.name() != runTime.constant()
         && mag(dir.value() - t) <= 1e-12*max(mag(t), scalar(1))
         && isDir(runTime.path()/dir.name())
        )
        {
            runTime.setTime(dir, runTime.timeIndex());
            return;
        }
    }
}


void Foam::SPH::timeClock::selectStart(Time& runTime)
{
    const fileName dir(runTime.timePath());
    if (!isWrittenState(dir) || isFile(positionsFile(dir)))
    {
        return;
    }

    const dictionary& control = runTime.controlDict();
    const bool latest =
        control.getOrDefault<word>("startFrom", "latestTime") == "latestTime";
    if (!(latest && control.getOrDefault<bool>("skipIncompleteTimes", false)))
    {
        FatalIOErrorInFunction(control)
            << "The start time directory " << dir << " is incomplete: it has"
            << " no " << positionsFile(dir).relative(dir) << nl
            << "    (a run killed while writing it, or a damaged copy)."
            << " Remove it, or set" << nl
            << "    skipIncompleteTimes yes; (with startFrom latestTime) in "
            << control.name() << " to start" << nl
            << "    from the latest complete time before it"
            << exit(FatalIOError);
    }

    const instantList times(runTime.times());
    for (label i = times.size() - 1; i >= 0; --i)
    {
        const instant& t = times[i];
        if (t.name() == runTime.constant() || t.value() > runTime.value())
        {
            continue;
        }
        const fileName tDir(runTime.path()/t.name());
        if (isWrittenState(tDir) && !isFile(positionsFile(tDir)))
        {
            WarningInFunction
                << "Skipping the incomplete time directory " << tDir
                << " (no " << positionsFile(tDir).relative(tDir)
                << "; skipIncompleteTimes yes)" << endl;
            continue;
        }
        startAt(runTime, t);
        WarningInFunction
            << "Starting from time " << t.name() << ", the latest complete"
            << " time directory" << endl;
        return;
    }
    FatalIOErrorInFunction(control)
        << "No complete time directory to start from in " << runTime.path()
        << exit(FatalIOError);
}


void Foam::SPH::timeClock::checkFreshStart(const Time& runTime)
{
    if (isWrittenState(runTime.timePath()))
    {
        return;
    }
    for (const instant& t : runTime.times())
    {
        const fileName tDir(runTime.path()/t.name());
        if
        (
            t.name() != runTime.constant() && t.value() < runTime.value()
         && isWrittenState(tDir)
        )
        {
            FatalErrorInFunction
                << "No particles to start from at time " << runTime.timeName()
                << ": " << runTime.timePath() << " holds no written state,"
                << " while the earlier time " << t.name() << " does" << nl
                << "    (a start afresh from constant/sphMesh there would not"
                << " be a restart). Start from a time directory that holds"
                << " lagrangian/sph/positions" << exit(FatalError);
        }
    }
}


// ************************************************************************* //
