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
#include "wcsph.H"
#include "solverMain.H"
#include "openMPWaitPolicy.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    SPH::waitPassivelyByDefault(argv);

    argList::addNote
    (
        "Weakly compressible SPH with dummy + repulsive wall particles"
        " (Mahdavi & Talebbeydokhti 2015)"
    );
    argList::noParallel();

    #include "setRootCase.H"

    return SPH::solverMain<SPH::wcsph>(args);
}


// ************************************************************************* //
