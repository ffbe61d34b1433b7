/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "flowRate.H"
#include "Time.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace functionObjects
{
    defineTypeNameAndDebug(flowRate, 0);
    addToRunTimeSelectionTable(functionObject, flowRate, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::functionObjects::flowRate::volumeBehind() const
{
    const sphCloud& c = cloud();
    const vector2DField& pos = c.parts().positions();
    const vector2D along(-normal_.y(), normal_.x());

    // Mass over rho0: the volume a particle carries whatever its density
    const scalar volumePerParticle = c.mass()/c.rho0();

    label n = 0;
    for (label b = 0; b < c.nFluid(); ++b)
    {
        const vector2D d(pos[b] - point_);
        if ((d & normal_) < 0 && mag(d & along) <= halfWidth_)
        {
            ++n;
        }
    }
    return n*volumePerParticle;
}


void Foam::SPH::functionObjects::flowRate::writeFileHeader
(
    Ostream& os
) const
{
    writeHeader(os, "Discharge per unit width through a section");
    writeHeaderValue(os, "point", point_);
    writeHeaderValue(os, "normal", normal_);
    if (halfWidth_ < VGREAT)
    {
        writeHeaderValue(os, "halfWidth", halfWidth_);
    }
    writeHeader(os, "");
    writeCommented(os, "Time");
    writeTabbed(os, "volumeBehind");
    writeTabbed(os, "q");
    os  << endl;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::flowRate::measure()
{
    volume_ = volumeBehind();
}


void Foam::SPH::functionObjects::flowRate::writeLog() const
{
    Info<< "    flowRate " << name() << ": volume behind " << volume_ << endl;
}


void Foam::SPH::functionObjects::flowRate::writeFiles()
{
    if (!filePtr_.valid())
    {
        filePtr_ = createFile(fileName_);
        writeFileHeader(filePtr_());
    }

    const scalar t = time().value();
    q_ =
        (writtenTime_ > -VGREAT && t > writtenTime_)
      ? -(volume_ - writtenVolume_)/(t - writtenTime_)
      : -VGREAT;
    writtenVolume_ = volume_;
    writtenTime_ = t;

    OFstream& os = file();
    writeCurrentTime(os);
    os  << tab << volume_ << tab << q_ << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::flowRate::flowRate
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    sphFunctionObject(name, runTime, dict, typeName),
    point_(Zero),
    normal_(1, 0),
    halfWidth_(VGREAT),
    volume_(0),
    q_(-VGREAT),
    writtenVolume_(0),
    writtenTime_(-VGREAT)
{
    read(dict);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::SPH::functionObjects::flowRate::read(const dictionary& dict)
{
    sphFunctionObject::read(dict);

    point_ = readPoint(dict, "point");
    normal_ = dict.found("normal") ? readPoint(dict, "normal") : vector2D(1, 0);
    if (mag(normal_) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": normal " << normal_
            << " has no length" << exit(FatalIOError);
    }
    normal_ /= mag(normal_);

    halfWidth_ = dict.lookupOrDefault<scalar>("halfWidth", VGREAT);
    if (halfWidth_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": halfWidth = " << halfWidth_
            << ", expected a length > 0" << exit(FatalIOError);
    }

    Info<< type() << ' ' << name() << ": section through " << point_
        << ", flow along " << normal_;
    if (halfWidth_ < VGREAT)
    {
        Info<< ", within " << halfWidth_ << " of the point";
    }
    Info<< endl;

    return true;
}


// ************************************************************************* //
