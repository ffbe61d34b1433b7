/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "isolatedParticles.H"
#include "openMPThreshold.H"
#include "checkedEntry.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace functionObjects
{
    defineTypeNameAndDebug(isolatedParticles, 0);
    addToRunTimeSelectionTable(functionObject, isolatedParticles, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::isolatedParticles::writeFileHeader
(
    Ostream& os
) const
{
    writeHeader(os, "Isolated and sparse fluid particles");
    writeHeaderValue(os, "isolatedRadius [dr]", isolatedRadius_);
    writeHeaderValue(os, "sparseRadius [dr]", sparseRadius_);
    writeHeaderValue(os, "minNeighbours", minNeighbours_);
    writeHeader(os, "");
    writeCommented(os, "Time");
    writeTabbed(os, "isolated");
    writeTabbed(os, "sparse");
    writeTabbed(os, "nIsolated");
    writeTabbed(os, "nSparse");
    writeTabbed(os, "nFluid");
    writeTabbed(os, "nSparseByWall");
    os  << endl;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::isolatedParticles::measure()
{
    const sphCloud& c = cloud();
    const vector2DField& pos = c.parts().positions();
    const label nFluid = c.nFluid();
    const scalar rIsolated2 = sqr(isolatedRadius_*c.dr());
    const scalar rSparse2 = sqr(sparseRadius_*c.dr());
    // The search finds |r| < radius; sparse counts |r| <= 2 dr (a lattice's
    // 12), so it reaches a hair further
    const scalar reach = (1 + 1e-9)*max(isolatedRadius_, sparseRadius_)*c.dr();

    label nIsolated = 0;
    label nSparse = 0;
    label nSparseByWall = 0;
    #pragma omp parallel for schedule(static) \
        reduction(+:nIsolated, nSparse, nSparseByWall) \
        if(SPH::worthThreads(nFluid))
    for (label a = 0; a < nFluid; ++a)
    {
        label nNear = 0;
        bool isolated = true;
        bool byWall = false;
        c.cells().forEachNeighbour
        (
            pos[a],
            reach,
            [&](const label b, const vector2D&, const scalar r2)
            {
                if (b >= nFluid)
                {
                    byWall = byWall || r2 <= rSparse2;
                    return;
                }
                if (b == a) return;
                if (r2 < rIsolated2) isolated = false;
                if (r2 <= rSparse2) ++nNear;
            }
        );
        if (isolated) ++nIsolated;
        if (nNear < minNeighbours_)
        {
            ++nSparse;
            if (byWall) ++nSparseByWall;
        }
    }
    nIsolated_ = nIsolated;
    nSparse_ = nSparse;
    nSparseByWall_ = nSparseByWall;
    nFluid_ = nFluid;
}


void Foam::SPH::functionObjects::isolatedParticles::writeLog() const
{
    Info<< "    isolatedParticles " << name() << ": isolated "
        << 100*fraction(nIsolated_) << " % (" << nIsolated_ << "), sparse "
        << 100*fraction(nSparse_) << " % (" << nSparse_ << "; "
        << nSparseByWall_ << " by a wall) of " << nFluid_
        << " fluid particles" << endl;
}


void Foam::SPH::functionObjects::isolatedParticles::writeFiles()
{
    if (!filePtr_.valid())
    {
        filePtr_ = createFile(fileName_);
        writeFileHeader(filePtr_());
    }

    OFstream& os = file();
    writeCurrentTime(os);
    os  << tab << fraction(nIsolated_) << tab << fraction(nSparse_)
        << tab << nIsolated_ << tab << nSparse_ << tab << nFluid_
        << tab << nSparseByWall_ << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::isolatedParticles::isolatedParticles
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    sphFunctionObject(name, runTime, dict, typeName),
    isolatedRadius_(1.5),
    sparseRadius_(2),
    minNeighbours_(5),
    nIsolated_(0),
    nSparse_(0),
    nSparseByWall_(0),
    nFluid_(0)
{
    read(dict);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::SPH::functionObjects::isolatedParticles::read(const dictionary& dict)
{
    sphFunctionObject::read(dict);

    // The cell list reaches one kernel support (at least 2 dr)
    isolatedRadius_ =
        checkedScalar(dict, "isolatedRadius", 1.5, {0, 2, true}, "in dr");
    sparseRadius_ =
        checkedScalar(dict, "sparseRadius", 2, {0, 2, true}, "in dr");
    minNeighbours_ = dict.getOrDefault<label>("minNeighbours", 5);
    if (minNeighbours_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": minNeighbours = "
            << minNeighbours_ << ", expected a count >= 1"
            << exit(FatalIOError);
    }

    Info<< type() << ' ' << name() << ": isolated with no fluid within "
        << isolatedRadius_ << " dr, sparse with fewer than " << minNeighbours_
        << " within " << sparseRadius_ << " dr" << endl;

    return true;
}


// ************************************************************************* //
