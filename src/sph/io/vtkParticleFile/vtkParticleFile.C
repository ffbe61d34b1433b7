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


Foam::SPH::vtkParticleFile::vtkParticleFile(const particles& parts)
:
    vtkParticleFile(parts.positions())
{
    for (const word& name : parts.names())
    {
        if (parts.isScalar(name))
        {
            addPointField(name, parts.field<scalar>(name));
        }
        else if (parts.isVector(name))
        {
            addPointField(name, parts.field<vector2D>(name));
        }
        else
        {
            addPointField(name, parts.field<label>(name));
        }
    }
}


// ************************************************************************* //
