/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    sphMesh

Description
    Generate the particles and walls of an SPH case: fluid particles on a
    lattice, wall vertices and segments (USAW) and dummy particle layers
    (WCSPH), from system/sphMeshDict, or with -fromPolyMesh from the 2-D
    OpenFOAM mesh in constant/polyMesh (the mesh of the FV case).

    Writes constant/sphMesh/{fluid,walls,dummy}/, constant/sphMesh/domain,
    constant/sphMesh/layout (the wall model the particles were laid out for,
    which the solvers check) and a VTK picture in VTK/sphMesh.vtp and
    VTK/sphMesh_walls.vtp.

    Every input is checked before it is used (SPH::particleGenerator): a
    number out of range, a count above maxParticles (estimated before
    seeding), a duplicate or unwritable name, crossing or overlapping walls,
    fluid outside the walls, a too coarse dr, a read-only constant/sphMesh
    are fatal errors naming the file and entry; never a signal or a hang.

Usage
    sphMesh [-fromPolyMesh] [-case dir]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "particleGenerator.H"
#include "sphMeshVTK.H"
#include "sphFoamVersion.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Generate the SPH particles, wall vertices and segments and dummy"
        " particle layers of a case from system/sphMeshDict"
    );
    argList::addBoolOption
    (
        "fromPolyMesh",
        "take the walls from the wall patches of the 2-D mesh in"
        " constant/polyMesh and the fluid from alpha.water"
    );
    argList::addBoolOption("noVTK", "do not write the VTK picture");
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    Info<< "sphFoam " << SPH::version << nl << endl;

    autoPtr<polyMesh> mesh;
    if (args.found("fromPolyMesh"))
    {
        Info<< "Reading the 2-D mesh in constant/polyMesh" << nl;
        mesh.reset
        (
            new polyMesh
            (
                IOobject
                (
                    polyMesh::defaultRegion,
                    runTime.timeName(),
                    runTime,
                    IOobject::MUST_READ
                )
            )
        );
    }

    SPH::particleGenerator generator(runTime, mesh.get());
    generator.report();
    generator.write();

    if (!args.found("noVTK"))
    {
        SPH::writeSphMeshVTK(runTime, generator);
    }

    Info<< nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
