/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    wcsphFoam

Description
    Weakly compressible SPH solver with hybrid dummy + repulsive walls
    (004_f29223b75201dc88.txt): free-surface flows such as dam-breaks.

    Reads the particles made by sphMesh (constant/sphMesh) or, on a restart,
    the particles of the start time (<time>/lagrangian/sph), and writes the
    particle fields at each write time, with a VTK picture in VTK/.

Usage
    wcsphFoam [-case dir]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "sigFpe.H"
#include "wcsph.H"
#include "sphFoamVersion.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Weakly compressible SPH with dummy + repulsive wall particles"
        " (Mahdavi & Talebbeydokhti 2015)"
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

    SPH::wcsph model(runTime);
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
                << "Time = " << runTime.timeName() << nl;
        }

        model.evolve();

        runTime.write();
        if (runTime.writeTime())
        {
            model.writeVTK();
        }

        if (log)
        {
            const label nBounced = model.bouncedSinceLastCall();
            if (nBounced)
            {
                Info<< "Wall bounces since the last report: " << nBounced << nl;
            }
            Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
                << "  ClockTime = " << runTime.elapsedClockTime() << " s"
                << nl << endl;
        }
    }

    model.printTimes();
    Info<< "Fluid particles " << model.nFluid() << ", total mass "
        << model.totalMass() << " kg/m" << nl
        << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
