/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "vtkParticleFile.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::vtkParticleFile::vtkParticleFile(const UList<vector2D>& positions)
:
    vtkPolyFile(positions)
{
    // Without cells ParaView's default representation draws nothing
    insertVertices();
}


// ************************************************************************* //
