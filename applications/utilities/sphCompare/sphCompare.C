/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    sphCompare

Description
    Samples an SPH result and OpenFOAM results (or reference tables, or
    analytic expressions) on the same lines and points and writes the
    values and the errors of each against a reference: the L2 norm of
    000_8c7cd3aabddcf18a.txt eq. (66) and the largest difference, with the
    wall-clock time of each run.

    The FV result is read with OpenFOAM's fvMesh and volFields and
    interpolated with its interpolation classes (cellPoint by default); the
    SPH result with a first-order consistent (MLS-linear) interpolation
    that reproduces linear fields exactly. So neither side's sampling adds
    an error of its own to the comparison.

    Driven by system/sphCompareDict of the case (sources and sets: see
    fieldComparison.H); writes postProcessing/sphCompare/<time>/<set>.dat,
    errors.dat and sources.dat.

Usage
    sphCompare [-case dir] [-fv dir] [-sph dir] [-time ranges] [-latestTime]
    -fv dir     the case of the source named fv (added if the dictionary
                has none)
    -sph dir    the case of the source named sph (the same)
    -time ranges
                OpenFOAM's time selection ('1', '0.5,1', '50:', ':10') of
                the result in the case itself, unless its dictionary names a
                time: one comparison, postProcessing/sphCompare/<time>/, per
                selected time. A single value must be one of the case's
                times (not the nearest, as OpenFOAM's utilities take it: a
                comparison at another time than asked would pass unseen).
                Without -time or -latestTime, the latest time. The other
                results take their 'time' entry or their latest time
    -noZero     leave 0/ out of a range

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "timeSelector.H"
#include "scalarRanges.H"
#include "stringOps.H"
#include "Time.H"
#include "sigFpe.H"
#include "OSspecific.H"
#include "fieldComparison.H"
#include "sphFoamVersion.H"

using namespace Foam;

namespace
{

// The cases named by -fv and -sph, absolute
HashTable<fileName> commandLineCases(const argList& args)
{
    HashTable<fileName> cases;
    for (const word opt : {"fv", "sph"})
    {
        fileName dir;
        if (args.readIfPresent(opt, dir))
        {
            dir.expand();
            if (!dir.isAbsolute())
            {
                dir = cwd()/dir;
            }
            dir.clean();
            cases.set(opt, dir);
        }
    }
    return cases;
}


// The times to compare at: one empty instant (each source's latest time)
// without -time or -latestTime, else the selected times of the case, each
// single value of -time being one of them
instantList selectedTimes(const Time& runTime, const argList& args)
{
    if (!args.found("time") && !args.found("latestTime"))
    {
        return instantList(1, instant(0, word::null));
    }
    instantList times;
    for (const instant& t : runTime.times())
    {
        if (t.name() != runTime.constant())
        {
            times.append(t);
        }
    }
    wordList names(times.size());
    forAll(times, i) names[i] = times[i].name();

    // OpenFOAM skips a bad item with a warning; here it is an error
    const string option(args.getOrDefault<string>("time", ""));
    for (const auto& item : stringOps::splitAny(option, ", "))
    {
        if (scalarRanges::parse(item.str(), false).empty())
        {
            FatalErrorInFunction
                << "Option -time '" << option.c_str() << "': '"
                << item.str().c_str() << "' is not a time or a range (t, t1:t2,"
                << " t1:, :t2)" << nl << exit(FatalError);
        }
    }
    const instantList selected(timeSelector::select(times, args));
    if (selected.empty())
    {
        FatalErrorInFunction
            << "Options -time/-latestTime select no time of "
            << runTime.path() << nl << "Times: " << names << nl
            << exit(FatalError);
    }
    // OpenFOAM takes a single value as the nearest time; here it is that
    // time or an error
    const scalarRanges ranges(scalarRanges::parse(option, false));
    for (const scalarRange& range : ranges)
    {
        const label i = range.single()
            ? Time::findClosestTimeIndex(times, range.value()) : -1;
        if
        (
            range.single()
         && (
                i < 0
             || mag(times[i].value() - range.value())
              > 1e-9*max(scalar(1), mag(range.value()))
            )
        )
        {
            FatalErrorInFunction
                << "Option -time: no time " << range.value() << " in "
                << runTime.path() << nl << "Times: " << names << nl
                << exit(FatalError);
        }
    }
    return selected;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Sample SPH and OpenFOAM results (and reference tables, analytic"
        " expressions) on the same lines and points, and write their errors"
        " (000_8c7cd3aabddcf18a.txt eq. (66)) and run times, as"
        " system/sphCompareDict says"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption
    (
        "fv",
        "dir",
        "the OpenFOAM case of the source named fv (added if there is none)"
    );
    argList::addOption
    (
        "sph",
        "dir",
        "the SPH case of the source named sph (added if there is none)"
    );
    // -time ranges, -latestTime, -noZero: OpenFOAM's time selection
    timeSelector::addOptions(false, false);

    #include "setRootCase.H"
    #include "createTime.H"

    // A point where a source has no value (outside the mesh or the
    // particles, off a table's rows) holds a NaN, written as 'nan' and left
    // out of the norms, so OpenFOAM's trap is switched off
    sigFpe::unset(false);

    Info<< "sphFoam " << SPH::version << nl << endl;

    SPH::sampleSource::options opts;
    opts.baseDir = runTime.path();
    const HashTable<fileName> cases(commandLineCases(args));

    for (const instant& t : selectedTimes(runTime, args))
    {
        opts.time = t.name();
        if (!opts.time.empty())
        {
            Info<< "Time = " << opts.time << nl << endl;
        }
        SPH::fieldComparison comparison(runTime, opts, cases);
        comparison.write();
        Info<< endl;
    }

    Info<< nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
