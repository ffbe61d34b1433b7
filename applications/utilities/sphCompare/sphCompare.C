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
    sphCompare [-case dir] [-fv dir] [-sph dir] [-time t]

    -fv dir     the case of the source named fv (added if the dictionary
                has none)
    -sph dir    the case of the source named sph (the same)
    -time t     time of the result in the case itself (-case), unless its
                dictionary names one (a value or latestTime; default
                latestTime); the other results take their 'time' entry or
                their latest time

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "sigFpe.H"
#include "OSspecific.H"
#include "fieldComparison.H"
#include "sphFoamVersion.H"

using namespace Foam;

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
    argList::addOption
    (
        "time",
        "time",
        "time of the result in the case itself, unless its dictionary names"
        " one (a value or latestTime; default latestTime)"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    // A point where a source has no value (outside the mesh or the
    // particles, off a table's rows) holds a NaN, written as 'nan' and left
    // out of the norms, so OpenFOAM's trap is switched off
    sigFpe::unset(false);

    Info<< "sphFoam " << SPH::version << nl << endl;

    SPH::sampleSource::options opts;
    opts.baseDir = runTime.path();
    opts.time = args.getOrDefault<word>("time", word::null);

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

    SPH::fieldComparison comparison(runTime, opts, cases);
    comparison.write();

    Info<< nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
