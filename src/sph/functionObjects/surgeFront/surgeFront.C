/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "surgeFront.H"
#include <algorithm>
#include "Time.H"
#include "SortableList.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace functionObjects
{
    defineTypeNameAndDebug(surgeFront, 0);
    addToRunTimeSelectionTable(functionObject, surgeFront, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::SPH::functionObjects::surgeFront::nFluidNeighbours
(
    const sphCloud& cloud,
    const label b
) const
{
    const label nFluid = cloud.nFluid();
    label n = 0;
    cloud.cells().forEachNeighbour
    (
        cloud.parts().positions()[b],
        2*cloud.dr(),
        [&](const label j, const vector2D&, const scalar)
        {
            if (j < nFluid && j != b)
            {
                ++n;
            }
        }
    );
    return n;
}


void Foam::SPH::functionObjects::surgeFront::writeFileHeader
(
    Ostream& os
) const
{
    writeHeader(os, "Surge front: leading edge of the fluid along the direction");
    writeHeaderValue(os, "direction", direction_);
    writeHeaderValue(os, "minNeighbours", minNeighbours_);
    if (maxHeight_ < VGREAT)
    {
        writeHeaderValue(os, "maxHeight", maxHeight_);
    }
    writeHeader(os, "");
    writeCommented(os, "Time");
    writeTabbed(os, "front");
    os  << endl;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::surgeFront::measure()
{
    const sphCloud& c = cloud();
    const vector2DField& pos = c.parts().positions();

    // Candidates below maxHeight, furthest along the direction first: the
    // first one in the main body is the front, so few are tested
    DynamicList<scalar> s(c.nFluid());
    DynamicList<label> index(c.nFluid());
    for (label b = 0; b < c.nFluid(); ++b)
    {
        if (pos[b].y() <= maxHeight_)
        {
            s.append(pos[b] & direction_);
            index.append(b);
        }
    }

    // Furthest first (a SortableList built from s is sorted already, so
    // its reverseSort() would index the sorted copy, not s)
    labelList order(identity(s.size()));
    std::stable_sort
    (
        order.begin(), order.end(),
        [&](label a, label b) { return s[a] > s[b]; }
    );

    front_ = -VGREAT;
    frontParticle_ = -1;
    for (const label k : order)
    {
        const label b = index[k];
        if (nFluidNeighbours(c, b) >= minNeighbours_)
        {
            front_ = s[k];
            frontParticle_ = b;
            break;
        }
    }
}


void Foam::SPH::functionObjects::surgeFront::writeLog() const
{
    Info<< "    surgeFront " << name() << ": front " << front_;
    if (frontParticle_ >= 0)
    {
        Info<< " (particle " << frontParticle_ << " at "
            << cloud().parts().positions()[frontParticle_] << ')';
    }
    else
    {
        Info<< " (no fluid particle in the main body)";
    }
    Info<< endl;
}


void Foam::SPH::functionObjects::surgeFront::writeFiles()
{
    if (!filePtr_.valid())
    {
        filePtr_ = createFile(fileName_);
        writeFileHeader(filePtr_());
    }

    OFstream& os = file();
    writeCurrentTime(os);
    os  << tab << front_ << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::surgeFront::surgeFront
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    sphFunctionObject(name, runTime, dict, typeName),
    direction_(1, 0),
    minNeighbours_(3),
    maxHeight_(VGREAT),
    front_(-VGREAT),
    frontParticle_(-1)
{
    read(dict);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::SPH::functionObjects::surgeFront::read(const dictionary& dict)
{
    sphFunctionObject::read(dict);

    direction_ =
        dict.found("direction")
      ? readPoint(dict, "direction")
      : vector2D(1, 0);

    if (mag(direction_) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": direction " << direction_
            << " has no length" << exit(FatalIOError);
    }
    direction_ /= mag(direction_);

    minNeighbours_ = dict.lookupOrDefault<label>("minNeighbours", 3);
    if (minNeighbours_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": minNeighbours = "
            << minNeighbours_ << ", expected a count >= 0"
            << exit(FatalIOError);
    }

    maxHeight_ = dict.lookupOrDefault<scalar>("maxHeight", VGREAT);

    Info<< type() << ' ' << name() << ": direction " << direction_
        << ", minNeighbours " << minNeighbours_ << " within 2 dr";
    if (maxHeight_ < VGREAT)
    {
        Info<< ", y <= " << maxHeight_;
    }
    Info<< endl;

    return true;
}


// ************************************************************************* //
