/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sphMeshVTK.H"
#include "particles.H"
#include "vtkCaseWriter.H"
#include "vtkParticleFile.H"
#include "vtkWallFile.H"

void Foam::SPH::writeSphMeshVTK(const Time& runTime, const particleGenerator& gen)
{
    const wallMesh& walls = gen.walls();
    const label nFluid = gen.fluid().size();
    const label nWall = walls.points().size();
    const label nDummy = gen.dummy().size();
    const label n = nFluid + nWall + nDummy;

    List<vector2D> pos(n);
    labelList type(n), patch(n, -1), layer(n, -1);

    label i = 0;
    for (const vector2D& p : gen.fluid())
    {
        pos[i] = p;
        type[i++] = label(particleKind::fluid);
    }
    forAll(walls.points(), v)
    {
        pos[i] = walls.points()[v];
        patch[i] = walls.pointPatch()[v];
        type[i++] = label(particleKind::wallVertex);
    }
    forAll(gen.dummy(), d)
    {
        pos[i] = gen.dummy()[d];
        patch[i] = gen.dummyPatch()[d];
        layer[i] = gen.dummyLayer()[d];
        type[i] = label
        (
            layer[i] == 0 ? particleKind::interfacial : particleKind::dummy
        );
        ++i;
    }

    vtkCaseWriter vtk(runTime.path(), "sphMesh", vtkCaseWriter::staticWalls);

    vtkParticleFile particleFile(pos);
    particleFile.addPointField("type", type);
    particleFile.addPointField("patch", patch);
    particleFile.addPointField("layer", layer);
    vtk.writeParticles(particleFile, runTime.timeIndex(), runTime.value());

    // A segment through a periodic seam is drawn to the image of its
    // second vertex, not across the domain: that image is an extra point
    DynamicList<vector2D> wallPoints(walls.points());
    DynamicList<scalar> angles(walls.pointAngles());
    List<labelPair> segments(walls.segments());
    forAll(segments, s)
    {
        const vector2D& a = walls.points()[segments[s].first()];
        const vector2D& b = walls.points()[segments[s].second()];
        const vector2D bImage(walls.domain().image(b, a));
        if (bImage != b)
        {
            angles.append(walls.pointAngles()[segments[s].second()]);
            segments[s].second() = wallPoints.size();
            wallPoints.append(bImage);
        }
    }

    vtkWallFile wallFile(wallPoints, segments);
    wallFile.addCellField("normal", walls.segmentNormals());
    wallFile.addCellField("patch", walls.segmentPatch());
    wallFile.addPointField("angle", angles);
    vtk.writeWalls(wallFile, runTime.timeIndex(), runTime.value());

    Info<< "Written " << vtk.particleFile(runTime.timeIndex()) << nl
        << "    and " << vtk.wallFile(runTime.timeIndex()) << nl;
}


// ************************************************************************* //
