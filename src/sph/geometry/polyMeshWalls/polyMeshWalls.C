/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "polyMeshWalls.H"
#include "polyMesh.H"
#include "IFstream.H"
#include "Time.H"
#include "SubField.H"
#include "wallPolyPatch.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::polyMeshWalls::checkTwoD(scalar& tol)
{
    const pointField& pts = mesh_.points();
    const boundBox bb(pts);
    const scalar zMin = bb.min().z();
    const scalar thickness = bb.max().z() - zMin;
    tol = 1e-6*max(thickness, bb.mag());
    zMid_ = zMin + 0.5*thickness;

    for (const point& p : pts)
    {
        if (mag(p.z() - zMin) > tol && mag(p.z() - bb.max().z()) > tol)
        {
            FatalErrorInFunction
                << "The mesh in " << mesh_.objectPath()
                << " is not 2-D: point " << p << " is neither on z = " << zMin
                << " nor on z = " << bb.max().z() << nl
                << "Make it one cell thick in z (front and back patches empty)."
                << exit(FatalError);
        }
    }

    return zMin;
}


Foam::List<Foam::SPH::wallChain> Foam::SPH::polyMeshWalls::patchChains
(
    const polyPatch& pp,
    const scalar zBack,
    const scalar tol
) const
{
    const pointField& pts = mesh_.points();
    // faceAreas() returns a SubField by value: keep it, not a reference
    const vectorField::subField n = pp.faceAreas();
    DynamicList<wallChain> chains(pp.size());

    forAll(pp, facei)
    {
        // The two corners of the face in the back plane
        DynamicList<vector2D> back;
        for (const label pi : pp[facei])
        {
            if (mag(pts[pi].z() - zBack) <= tol)
            {
                back.append(vector2D(pts[pi].x(), pts[pi].y()));
            }
        }
        if (back.size() != 2)
        {
            continue;   // not a face across the thickness
        }
        // Face normals point out of the domain: fluid on the left of a->b
        // means the left normal of (b - a) points against n
        const vector2D t = back[1] - back[0];
        const vector2D left(-t.y(), t.x());
        const bool keep = (left.x()*n[facei].x() + left.y()*n[facei].y()) < 0;
        wallChain c;
        c.closed = false;
        c.points.setSize(2);
        c.points[0] = keep ? back[0] : back[1];
        c.points[1] = keep ? back[1] : back[0];
        chains.append(c);
    }

    if (chains.empty())
    {
        FatalErrorInFunction
            << "Patch " << pp.name() << " has no face across the 2-D"
            << " mesh's thickness: it cannot be a wall" << exit(FatalError);
    }
    return List<wallChain>(std::move(chains));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::polyMeshWalls::polyMeshWalls
(
    const polyMesh& mesh,
    const wordList& patches
)
:
    mesh_(mesh),
    zMid_(0)
{
    scalar tol = 0;
    const scalar zBack = checkTwoD(tol);

    const polyBoundaryMesh& bm = mesh.boundaryMesh();
    if (patches.empty())
    {
        for (const polyPatch& pp : bm)
        {
            if (isA<wallPolyPatch>(pp))
            {
                patchNames_.append(pp.name());
            }
        }
    }
    else
    {
        patchNames_ = patches;
    }

    chains_.setSize(patchNames_.size());
    forAll(patchNames_, i)
    {
        const label patchi = bm.findPatchID(patchNames_[i]);
        if (patchi < 0)
        {
            FatalErrorInFunction
                << "No patch " << patchNames_[i] << " in "
                << bm.objectPath() << nl << "Patches: " << bm.names()
                << exit(FatalError);
        }
        chains_[i] = patchChains(bm[patchi], zBack, tol);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::polyMeshWalls::readFraction(const word& fieldName)
{
    // The cell values only: no fvMesh (and so no fvSchemes) is needed
    const IOobject io
    (
        fieldName,
        mesh_.time().timeName(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    const fileName file(io.objectPath());
    IFstream is(file);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot read " << file << ": the field that marks the fluid"
            << " (run setFields first?)" << exit(FatalError);
    }
    IOobject header(io);
    header.readHeader(is);          // sets ascii or binary from FoamFile
    const dictionary dict(is);
    fraction_ = scalarField("internalField", dict, mesh_.nCells());
}


bool Foam::SPH::polyMeshWalls::inside(const vector2D& p) const
{
    return mesh_.findCell(point(p.x(), p.y(), zMid_)) >= 0;
}


bool Foam::SPH::polyMeshWalls::isFluid(const vector2D& p) const
{
    const label celli = mesh_.findCell(point(p.x(), p.y(), zMid_));
    return celli >= 0 && fraction_[celli] > 0.5;
}


void Foam::SPH::polyMeshWalls::bounds(vector2D& lo, vector2D& hi) const
{
    const boundBox bb(mesh_.points());
    lo = vector2D(bb.min().x(), bb.min().y());
    hi = vector2D(bb.max().x(), bb.max().y());
}


// ************************************************************************* //
