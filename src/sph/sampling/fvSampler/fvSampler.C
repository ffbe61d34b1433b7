/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fvSampler.H"
#include "boundBox.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fvSampler::fvSampler(const fvMesh& mesh, const word& scheme)
:
    mesh_(mesh),
    scheme_(scheme),
    zMid_(0.5*(mesh.bounds().min().z() + mesh.bounds().max().z()))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::SPH::fvSampler::findCells
(
    const UList<vector2D>& points
) const
{
    labelList cells(points.size(), -1);
    forAll(points, i)
    {
        const point p(toPoint(points[i]));
        label celli = mesh_.findCell(p);
        if (celli < 0)
        {
            // On the boundary, up to rounding: the nearest cell, if the
            // point is within its bounding box
            const label nearest = mesh_.findNearestCell(p);
            if (nearest >= 0)
            {
                boundBox bb(mesh_.points(), mesh_.cellPoints()[nearest], false);
                bb.inflate(1e-6);
                if (bb.contains(p))
                {
                    celli = nearest;
                }
            }
        }
        cells[i] = celli;
    }
    return cells;
}


Foam::List<Foam::vector2D> Foam::SPH::fvSampler::cellCentres() const
{
    const vectorField& C = mesh_.C().primitiveField();
    List<vector2D> centres(C.size());
    forAll(C, celli)
    {
        centres[celli] = vector2D(C[celli].x(), C[celli].y());
    }
    return centres;
}


// ************************************************************************* //
