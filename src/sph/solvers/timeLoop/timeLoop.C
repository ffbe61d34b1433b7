/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "timeLoop.H"
#include "timeClock.H"
#include "checkedEntry.H"
#include "stepDisplacement.H"
#include "speedLimit.H"
#include "spreadLimit.H"
#include "atomicTimeDirectory.H"
#include "wallCrossing.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "labelPair.H"
#include "OSspecific.H"
#include "sigFpe.H"
#include "sphFoamVersion.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::timeLoop::timeLoop(Time& runTime, sphSolver& solver)
:
    runTime_(runTime),
    solver_(solver),
    schemes_
    (
        IOobject
        (
            "sphSchemes", runTime.system(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    ),
    minDeltaTFraction_(1e-3),
    deltaT0_(-1),
    lastDeltaT_(-1),
    lastDeltaTStart_(-1),
    timeStart_(runTime.value()),
    purgeWrite_(timeClock::takeOverPurgeWrite(runTime)),
    limits_(3),
    maxRetries_
    (
        runTime.controlDict().getOrDefault<label>("retryOnFailure", 0)
    ),
    nRetries_(0),
    nRescued_(0),
    nRetriesStart_(0),
    writeTimeIndexStart_(0),
    sortInterval_(0),
    nSorts_(0),
    sortCpuSeconds_(0)
{
    checkTimeControls(runTime);
    limits_.set(0, new stepDisplacement(schemes_));
    limits_.set(1, new speedLimit(schemes_));
    limits_.set(2, new spreadLimit(schemes_, solver_.freeSurfaceFlags()));
    minDeltaTFraction_ = checkedScalar
    (
        schemes_, "minDeltaTFraction", minDeltaTFraction_, {0, 1, false, true},
        "of the first time step, below which a step has collapsed"
    );
    readSortInterval();
    readState();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::timeLoop::readSortInterval()
{
    const scalar n = checkedScalar
    (
        schemes_, "particleSortInterval", 20, {0, labelMax},
        "time steps between sorts of the fluid particles by cell (0: never)"
    );
    sortInterval_ = label(n);
    if (sortInterval_ != n)
    {
        FatalIOErrorInFunction(schemes_)
            << "Entry particleSortInterval " << n << ": expected a whole"
            << " number of time steps (0: never)" << exit(FatalIOError);
    }
}


void Foam::SPH::timeLoop::readState()
{
    const IOobject io
    (
        solver_.stateName(), runTime_.timeName(), "uniform", runTime_,
        IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
    );
    if (timeClock::isWrittenState(runTime_.timePath()) && !isFile(io.objectPath()))
    {
        FatalErrorInFunction
            << "Cannot restart from time " << runTime_.timeName() << ": "
            << io.objectPath() << " is missing" << nl
            << "    (the solver's state and clock; a run killed while"
            << " writing, another solver's time directory, or a damaged"
            << " copy)" << exit(FatalError);
    }
    const IOdictionary state(io);
    lastDeltaT_ = state.getOrDefault<scalar>("deltaT", -1);
    timeStart_ = runTime_.value();
    // The run's figures go on through a restart: the summary at the end is
    // the whole run's, not the last leg's
    for (fluidLimit& limit : limits_)
    {
        limit.readState(state);
    }
    labelPair retries(0, 0);
    state.readIfPresent("retries", retries);
    nRetries_ = retries.first();
    nRescued_ = retries.second();
    solver_.readState(state);
}


bool Foam::SPH::timeLoop::writeState() const
{
    // Seventeen digits give the doubles back exactly
    const fileName dir(runTime_.timePath()/"uniform");
    mkDir(dir);
    OFstream os(dir/solver_.stateName());
    os.precision(17);
    IOobject
    (
        solver_.stateName(), runTime_.timeName(), "uniform", runTime_
    ).writeHeader(os, "dictionary");
    solver_.writeState(os);
    os.writeEntry("deltaT", lastDeltaT_);
    for (const fluidLimit& limit : limits_)
    {
        limit.writeState(os);
    }
    if (maxRetries_ > 0)
    {
        // Steps retried and rescued (retryOnFailure)
        os.writeEntry("retries", labelPair(nRetries_, nRescued_));
    }
    timeClock::write(os, runTime_);
    IOobject::writeEndDivider(os);
    return os.good();
}


void Foam::SPH::timeLoop::writeTime()
{
    {
        atomicTimeDirectory dir(runTime_);
        dir.write
        (
            [this]() { return runTime_.writeNow(); },
            "writing the particle fields failed"
        );
        dir.write
        (
            [this]() { return writeState(); },
            "writing uniform/" + solver_.stateName() + " failed"
        );
        dir.commit();
    }
    if (written_.empty() || written_.last() != runTime_.timeName())
    {
        written_.append(runTime_.timeName());
    }
    purge();
    solver_.write();
}


void Foam::SPH::timeLoop::purge()
{
    if (purgeWrite_ <= 0)
    {
        return;
    }
    while (written_.size() > purgeWrite_)
    {
        rmDir(runTime_.path()/written_.first());
        written_.remove(0);
    }
}


Foam::scalar Foam::SPH::timeLoop::nextDeltaT() const
{
    scalar dt = solver_.maxDeltaT();
    const scalar growth = solver_.maxDeltaTGrowth();
    if (lastDeltaT_ > 0 && growth < VGREAT)
    {
        dt = min(dt, growth*lastDeltaT_);
    }
    dt = min(dt, runTime_.controlDict().getOrDefault<scalar>("maxDeltaT", VGREAT));
    return dt < VGREAT ? dt : runTime_.deltaTValue();
}


Foam::label Foam::SPH::timeLoop::findNonFinite(string& what) const
{
    const particles& parts = solver_.cloud().parts();
    const label nFluid = solver_.cloud().nFluid();

    auto finite = [](const vector2D& v)
    {
        return std::isfinite(v.x()) && std::isfinite(v.y());
    };

    const vector2D* x = parts.positions().cdata();
    for (label i = 0; i < nFluid; ++i)
    {
        if (!finite(x[i]))
        {
            what = "NaN or Inf in the position of";
            return i;
        }
    }
    for (const word& name : parts.names())
    {
        if (!parts.isRestart(name)) continue;
        label bad = -1;
        if (parts.isScalar(name))
        {
            const scalar* f = parts.field<scalar>(name).cdata();
            for (label i = 0; i < nFluid && bad < 0; ++i)
            {
                if (!std::isfinite(f[i])) bad = i;
            }
        }
        else if (parts.isVector(name))
        {
            const vector2D* f = parts.field<vector2D>(name).cdata();
            for (label i = 0; i < nFluid && bad < 0; ++i)
            {
                if (!finite(f[i])) bad = i;
            }
        }
        if (bad >= 0)
        {
            what = "NaN or Inf in the field " + name + " of";
            return bad;
        }
    }
    return -1;
}


Foam::label Foam::SPH::timeLoop::findEscaped(string& what) const
{
    const sphCloud& cloud = solver_.cloud();
    const particles& parts = cloud.parts();
    const label nFluid = cloud.nFluid();
    const vector2DField& x = parts.positions();
    for (label i = 0; i < nFluid; ++i)
    {
        if (!cloud.contains(x[i]))
        {
            what =
                "Left the domain (the walls' box with a margin; a side"
                " with nothing beyond it can be opened: openSides in"
                " system/sphMeshDict):";
            return i;
        }
    }

    // Fluid particles whose step crossed a (still) wall segment
    const wallCrossing* crossing = solver_.crossing();
    if (crossing)
    {
        List<vector2D> xEnd(SubList<vector2D>(x, nFluid));
        List<vector2D> UEnd(SubList<vector2D>(parts.field<vector2D>("U"), nFluid));
        if (crossing->bounce(start_.positions, xEnd, UEnd, nFluid))
        {
            for (label i = 0; i < nFluid; ++i)
            {
                if (xEnd[i] != x[i])
                {
                    what = "Crossed a wall:";
                    return i;
                }
            }
        }
    }
    return -1;
}


Foam::label Foam::SPH::timeLoop::findBadParticle(string& what) const
{
    label i = findNonFinite(what);
    if (i >= 0) return i;
    i = findEscaped(what);
    if (i >= 0) return i;

    // A move no valid step makes, the case's bound on the speed, the fluid
    // spreading, then the method's physical bounds
    for (const fluidLimit& limit : limits_)
    {
        i = limit.find(solver_.cloud(), start_.positions, runTime_, what);
        if (i >= 0) return i;
    }
    return solver_.findUnphysical(what);
}


Foam::string Foam::SPH::timeLoop::limitsDescription() const
{
    string s;
    for (const fluidLimit& limit : limits_)
    {
        const string d(limit.describe());
        if (!d.empty()) s += ", " + d;
    }
    return s;
}


Foam::string Foam::SPH::timeLoop::where(const label i) const
{
    if (i < 0)
    {
        return string();
    }
    const particles& parts = solver_.cloud().parts();
    const vector2D& x = parts.positions()[i];
    return
        " particle id " + Foam::name(parts.field<label>("id")[i])
      + " at (" + Foam::name(x.x()) + " " + Foam::name(x.y()) + ")"
      + (i < solver_.cloud().nFluid() ? "" : " (a wall particle)");
}


void Foam::SPH::timeLoop::fail
(
    const string& what,
    const label i,
    const bool restore
)
{
    const scalar tFailed = runTime_.value();

    // The state at the start of the step was good: put it back and write
    // it at the time it belongs to
    if (restore)
    {
        solver_.cloud().parts().restore(start_);
        solver_.restoreState();
        lastDeltaT_ = lastDeltaTStart_;
    }
    runTime_.setTime(timeStart_, runTime_.timeIndex() - 1);
    {
        // Its retries come after the state written; the summary has them
        const label nRetries = nRetries_;
        nRetries_ = nRetriesStart_;
        writeTime();
        nRetries_ = nRetries;
    }
    // The run's figures up to the stop, as at an end (a restart from the
    // state written goes on with them)
    printSummary();

    FatalErrorInFunction
        << what.c_str() << where(i).c_str() << nl
        << "    at time " << tFailed << " s (time step "
        << runTime_.timeIndex() + 1 << ", deltaT " << runTime_.deltaTValue()
        << " s)" << nl
        << "The last good state, time " << runTime_.timeName()
        << ", is written in " << runTime_.timePath() << nl
        << exit(FatalError);
}


void Foam::SPH::timeLoop::checkCollapse()
{
    const scalar dt = runTime_.deltaTValue();
    if (deltaT0_ < 0)
    {
        deltaT0_ = dt;
    }
    if (dt >= minDeltaTFraction_*deltaT0_)
    {
        return;
    }

    // Name the fastest fluid particle: a collapse is usually one particle
    // or a few flung far faster than the flow
    const vector2DField& U = solver_.cloud().parts().field<vector2D>("U");
    label fastest = -1;
    scalar uMax = -1;
    for (label i = 0; i < solver_.cloud().nFluid(); ++i)
    {
        if (mag(U[i]) > uMax)
        {
            uMax = mag(U[i]);
            fastest = i;
        }
    }
    fail
    (
        "The time step collapsed to " + Foam::name(dt) + " s, below "
      + Foam::name(minDeltaTFraction_) + " of the first one ("
      + Foam::name(deltaT0_) + " s): the flow is too violent for this"
        " resolution and time-step control. The fastest fluid particle"
        " moves at " + Foam::name(uMax) + " m/s:",
        fastest, false
    );
}


bool Foam::SPH::timeLoop::trySolve(string& what, label& bad)
{
    const scalar dt = runTime_.deltaTValue();
    try
    {
        solver_.solve(dt);
    }
    catch (const stageFailure& failure)
    {
        what = failure.what();
        bad = failure.particle();
        return false;
    }
    lastDeltaT_ = dt;
    bad = findBadParticle(what);
    return bad < 0;
}


void Foam::SPH::timeLoop::retryHalved(const string& what, const label bad)
{
    const scalar dt = runTime_.deltaTValue();
    const scalar tFailed = runTime_.value();
    solver_.cloud().parts().restore(start_);
    solver_.restoreState();
    lastDeltaT_ = lastDeltaTStart_;
    runTime_.setTime(timeStart_, runTime_.timeIndex() - 1);
    timeClock::setWriteTimeIndex(runTime_, writeTimeIndexStart_);
    runTime_.setDeltaT(0.5*dt, false);
    ++runTime_;
    ++nRetries_;
    Info<< "Step to t = " << tFailed << " failed (" << what.c_str()
        << where(bad).c_str() << "): retried with deltaT = "
        << runTime_.deltaTValue() << " (retryOnFailure)" << endl;
}


void Foam::SPH::timeLoop::step()
{
    nRetriesStart_ = nRetries_;
    checkCollapse();
    solver_.cloud().parts().save(start_);
    solver_.saveState(start_);
    lastDeltaTStart_ = lastDeltaT_;

    string what;
    label bad = -1;
    bool ok = trySolve(what, bad);
    for (label retry = 0; !ok && retry < maxRetries_; ++retry)
    {
        // A halved step below the collapse limit would only fail there
        if (0.5*runTime_.deltaTValue() < minDeltaTFraction_*deltaT0_) break;
        retryHalved(what, bad);
        ok = trySolve(what, bad);
        nRescued_ += ok;
    }
    if (!ok)
    {
        fail(what, bad, true);
    }
    for (fluidLimit& limit : limits_)
    {
        limit.accept();
    }
    solver_.afterStep(runTime_.deltaTValue());
    openSides_.check(solver_.cloud(), start_.positions, runTime_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::timeLoop::switchOffFpe()
{
    sigFpe::unset(false);
    Info<< "sphFoam " << version << nl
        << "Floating-point exceptions are not trapped: NaN and Inf are checked"
        << " after every time step" << nl << endl;
}


void Foam::SPH::timeLoop::prepareStart(Time& runTime, const word& stateName)
{
    atomicTimeDirectory::removeUnfinished(runTime);
    timeClock::matchStartDirectory(runTime);
    timeClock::selectStart(runTime);
    const IOdictionary state
    (
        IOobject
        (
            stateName, runTime.timeName(), "uniform", runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    timeClock::restore(runTime, state);
    timeClock::checkFreshStart(runTime);
    timeClock::registerRunStart(runTime);
}


void Foam::SPH::timeLoop::printHeader() const
{
    Info<< solver_.title().c_str() << ", stages of each time step:" << nl;
    solver_.stages().print(Info);
    solver_.printSettings();
    Info<< "    checks              NaN/Inf in any field, particles leaving"
        << " the domain" << (solver_.cloud().dom().anyOpen()
            ? " (its open sides bound nothing: crossings are logged)" : "")
        << (solver_.crossing() ? " or crossing a wall" : "")
        << limitsDescription().c_str()
        << (solver_.physicalChecks().empty() ? "" : ", ")
        << solver_.physicalChecks().c_str()
        << ", deltaT below " << minDeltaTFraction_ << " of the first; "
        << (
               maxRetries_ > 0
             ? "a failed step is taken again with half the time step up to "
             + Foam::name(maxRetries_) + " times, then the"
             : string("the")
           ).c_str()
        << " last good state is written" << nl;
    if (sortInterval_ > 0)
    {
        Info<< "    particle order      fluid particles renumbered cell by"
            << " cell every " << sortInterval_
            << " steps (particleSortInterval)" << nl;
    }
    Info<< endl;
}


void Foam::SPH::timeLoop::startStep(const bool adjustTimeStep)
{
    if (sortInterval_ > 0 && runTime_.timeIndex() % sortInterval_ == 0)
    {
        const scalar cpu0 = stage::processCpuSeconds();
        solver_.sortParticles();
        sortCpuSeconds_ += stage::processCpuSeconds() - cpu0;
        ++nSorts_;
    }
    if (adjustTimeStep)
    {
        runTime_.setDeltaT(nextDeltaT());
    }
    timeStart_ = runTime_.value();
    writeTimeIndexStart_ = timeClock::writeTimeIndex(runTime_);
    ++runTime_;
}


void Foam::SPH::timeLoop::printSummary() const
{
    for (const fluidLimit& limit : limits_)
    {
        limit.printSummary(Info);
    }
    openSides_.printSummary(solver_.cloud(), Info);
    if (maxRetries_ > 0)
    {
        Info<< "Steps retried with half the time step (retryOnFailure "
            << maxRetries_ << "): " << nRetries_ << " retries, " << nRescued_
            << " steps rescued" << nl;
    }
    if (sortInterval_ > 0)
    {
        Info<< "Fluid particles sorted by cell: " << nSorts_ << " times, "
            << sortCpuSeconds_ << " s of CPU" << nl;
    }
    solver_.printTimes();
}


void Foam::SPH::timeLoop::run()
{
    printHeader();

    const bool adjustTimeStep =
        runTime_.controlDict().getOrDefault<bool>("adjustTimeStep", false);
    const label logInterval =
        max(label(1), runTime_.controlDict().getOrDefault<label>("logInterval", 1));

    if (runTime_.timeIndex() == 0 || !isDir(runTime_.path()/"VTK"))
    {
        solver_.write();
    }

    Info<< "Starting time loop" << nl << endl;

    while (runTime_.run())
    {
        startStep(adjustTimeStep);

        const bool log =
            runTime_.timeIndex() % logInterval == 0 || runTime_.writeTime();
        if (log)
        {
            Info<< "deltaT = " << runTime_.deltaTValue() << nl
                << "Time = " << runTime_.timeName() << nl << nl;
        }

        step();

        if (runTime_.writeTime())
        {
            writeTime();
        }

        if (log)
        {
            solver_.printStep();
            Info<< "ExecutionTime = " << runTime_.elapsedCpuTime() << " s"
                << "  ClockTime = " << runTime_.elapsedClockTime() << " s"
                << nl << endl;
        }
    }

    printSummary();
    Info<< "End" << nl << endl;
}


// ************************************************************************* //
