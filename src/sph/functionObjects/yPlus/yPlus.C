/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "yPlus.H"
#include "fluidProperties.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace functionObjects
{
    defineTypeNameAndDebug(yPlus, 0);
    addToRunTimeSelectionTable(functionObject, yPlus, dictionary);
}
}
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::yPlus::measure()
{
    const sphCloud& c = cloud();
    const wallMesh& walls = c.walls();
    const label nFluid = c.nFluid();
    const vector2DField& pos = c.parts().positions();
    const vector2DField& U = c.parts().field<vector2D>("U");
    const label nPatches = walls.patchNames().size();
    min_ = List<scalar>(nPatches, VGREAT);
    max_ = List<scalar>(nPatches, Zero);
    sum_ = List<scalar>(nPatches, Zero);
    count_ = labelList(nPatches, Zero);

    // Each vertex's normal and patch: those of its segments
    const label nVertices = walls.points().size();
    List<vector2D> normal(nVertices, Zero);
    labelList patch(nVertices, -1);
    forAll(walls.segments(), s)
    {
        for (const label v : {walls.segments()[s].first(), walls.segments()[s].second()})
        {
            normal[v] += walls.segmentNormals()[s];
            patch[v] = walls.segmentPatch()[s];
        }
    }

    const scalar dr = c.dr();
    for (label v = 0; v < nVertices; ++v)
    {
        const vector2D n(normal[v]/max(mag(normal[v]), VSMALL));
        label nearest = -1;
        scalar nearest2 = VGREAT;
        vector2D rNearest(Zero);
        c.cells().forEachNeighbour
        (
            pos[nFluid + v],
            c.W().support(),
            [&](const label b, const vector2D& rij, const scalar r2)
            {
                if (b < nFluid && r2 < nearest2)
                {
                    nearest = b;
                    nearest2 = r2;
                    rNearest = rij;
                }
            }
        );
        if (nearest < 0 || patch[v] < 0) continue;
        const scalar y = max(mag(rNearest & n), dr);
        const vector2D& u = U[nearest];
        const scalar ut = mag(u - (u & n)*n);
        const scalar yp = y*std::sqrt(law_.uStarSqr(ut, y, nu_))/nu_;
        const label p = patch[v];
        min_[p] = Foam::min(min_[p], yp);
        max_[p] = Foam::max(max_[p], yp);
        sum_[p] += yp;
        ++count_[p];
    }
}


void Foam::SPH::functionObjects::yPlus::writeLog() const
{
    const wordList& names = cloud().walls().patchNames();
    forAll(names, p)
    {
        if (!count_[p]) continue;
        Info<< "    patch " << names[p] << " y+ : min = " << min_[p]
            << ", max = " << max_[p] << ", average = " << sum_[p]/count_[p]
            << endl;
    }
}


void Foam::SPH::functionObjects::yPlus::writeFiles()
{
    if (!filePtr_.valid())
    {
        filePtr_ = createFile(fileName_);
        OFstream& os = filePtr_();
        writeHeader(os, "y+ ()");
        writeCommented(os, "Time");
        writeTabbed(os, "patch");
        writeTabbed(os, "min");
        writeTabbed(os, "max");
        writeTabbed(os, "average");
        os  << endl;
    }
    OFstream& os = file();
    const wordList& names = cloud().walls().patchNames();
    forAll(names, p)
    {
        if (!count_[p]) continue;
        writeCurrentTime(os);
        os  << tab << names[p] << tab << min_[p] << tab << max_[p] << tab
            << sum_[p]/count_[p] << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::yPlus::yPlus
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    sphFunctionObject(name, runTime, dict, typeName),
    law_(0.41, 5.2),
    nu_(fluidProperties(runTime).nu)
{
    read(dict);
    if (!(nu_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name << ": y+ needs a viscosity, nu is "
            << nu_ << " in constant/transportProperties" << exit(FatalIOError);
    }
}


// ************************************************************************* //
