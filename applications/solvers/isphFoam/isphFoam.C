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
#include "isph.H"
#include "solverMain.H"
#include "openMPWaitPolicy.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    SPH::waitPassivelyByDefault(argv);

    argList::addNote
    (
        "Incompressible SPH with unified semi-analytical wall boundary"
        " conditions (Leroy et al. 2014)"
    );
    argList::noParallel();

    #include "setRootCase.H"

    return SPH::solverMain<SPH::isph>(args);
}


// ************************************************************************* //
