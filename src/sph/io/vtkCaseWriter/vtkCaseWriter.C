/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "vtkCaseWriter.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::vtkCaseWriter::vtkCaseWriter
(
    const fileName& caseDir,
    const word& base,
    const wallMotion walls
)
:
    vtkDir_(caseDir/"VTK"),
    base_(base),
    wallMotion_(walls),
    wallsWritten_(false),
    particleSeries_(vtkDir_/(base + ".vtp.series")),
    wallSeries_(vtkDir_/(base + "_walls.vtp.series"))
{
    if (base_.empty())
    {
        FatalErrorInFunction
            << "Empty base name for the VTK files in " << vtkDir_
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::SPH::vtkCaseWriter::particleFile(const label timeIndex) const
{
    return vtkDir_/(base_ + "_" + Foam::name(timeIndex) + ".vtp");
}


Foam::fileName Foam::SPH::vtkCaseWriter::wallFile(const label timeIndex) const
{
    return vtkDir_/(base_ + "_walls_" + Foam::name(timeIndex) + ".vtp");
}


void Foam::SPH::vtkCaseWriter::writeParticles
(
    const vtkParticleFile& particles,
    const label timeIndex,
    const scalar time
)
{
    const fileName file(particleFile(timeIndex));

    // File first: the series must never list a file that is not there
    particles.write(file, time);
    particleSeries_.append(file, time);
}


bool Foam::SPH::vtkCaseWriter::writeWalls
(
    const vtkWallFile& walls,
    const label timeIndex,
    const scalar time
)
{
    if (!wallsDue())
    {
        return false;
    }

    const fileName file(wallFile(timeIndex));

    walls.write(file, time);
    wallSeries_.append(file, time);
    wallsWritten_ = true;

    return true;
}


// ************************************************************************* //
