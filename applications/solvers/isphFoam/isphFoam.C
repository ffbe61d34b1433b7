/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    isphFoam

Description
    Incompressible SPH solver with unified semi-analytical wall boundary
    conditions (ISPH-USAW, 000_8c7cd3aabddcf18a.txt): a projection method
    with a pressure Poisson equation solved at every step, for confined and
    free-surface laminar flows, with walls that may slide or rotate.

    Reads the particles made by sphMesh (constant/sphMesh, with
    boundaryMethod usaw in system/sphSchemes) or, on a restart, the
    particles of the start time (<time>/lagrangian/sph), and writes the
    particle fields at each write time, with a VTK picture in VTK/.

Usage
    isphFoam [-case dir]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "sigFpe.H"
#include "isph.H"
#include "sphFoamVersion.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Incompressible SPH with unified semi-analytical wall boundary"
        " conditions (Leroy et al. 2014)"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    // NaN and Inf are found after every step, reported with the particle
    // and the last good state written, so OpenFOAM's trap (which would kill
    // the run without a word about where) is switched off
    sigFpe::unset(false);

    Info<< "sphFoam " << SPH::version << nl
        << "Floating-point exceptions are not trapped: NaN and Inf are checked"
        << " after every time step" << nl << endl;

    SPH::isph model(runTime);
    model.printStages();

    const bool adjustTimeStep =
        runTime.controlDict().getOrDefault<bool>("adjustTimeStep", false);
    const label logInterval =
        max(label(1), runTime.controlDict().getOrDefault<label>("logInterval", 1));

    if (runTime.timeIndex() == 0 || !isDir(runTime.path()/"VTK"))
    {
        model.writeVTK();
    }

    Info<< "Starting time loop" << nl << endl;

    while (runTime.run())
    {
        if (adjustTimeStep)
        {
            runTime.setDeltaT(model.stableDeltaT());
        }
        ++runTime;

        const bool log = runTime.timeIndex() % logInterval == 0 || runTime.writeTime();
        if (log)
        {
            Info<< "deltaT = " << runTime.deltaTValue() << nl
                << "Time = " << runTime.timeName() << nl << nl;
        }

        model.evolve();

        runTime.write();
        if (runTime.writeTime())
        {
            model.write();
        }

        if (log)
        {
            model.printStep();
            Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
                << "  ClockTime = " << runTime.elapsedClockTime() << " s"
                << nl << endl;
        }
    }

    model.printTimes();
    Info<< "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
