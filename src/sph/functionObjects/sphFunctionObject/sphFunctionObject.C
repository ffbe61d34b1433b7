/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sphFunctionObject.H"
#include "Time.H"
#include "scalarList.H"
#include "timeClock.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    const char* const noCloudMessage =
        "no SPH particles registered: this function object runs in sphFoam"
        " solvers";

    //- A point from its components: (x y) or (x y z), z ignored
    vector2D toPoint(const scalarList& c, ITstream& is, const word& key)
    {
        if (c.size() != 2 && c.size() != 3)
        {
            FatalIOErrorInFunction(is)
                << "Entry " << key << ": expected a point (x y) or (x y z),"
                << " found " << c << exit(FatalIOError);
        }
        return vector2D(c[0], c[1]);
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

const Foam::SPH::sphCloud&
Foam::SPH::functionObjects::sphFunctionObject::cloud() const
{
    if (!found(time_))
    {
        FatalErrorInFunction
            << type() << ' ' << name() << ": " << noCloudMessage
            << exit(FatalError);
    }
    return time_.lookupObject<sphCloud>(sphCloud::typeName);
}


Foam::fileName
Foam::SPH::functionObjects::sphFunctionObject::outputDir() const
{
    // The start time as writeFile names it (user time unless useUserTime
    // is off), so that probes files sit beside the .dat files of the others
    const scalar t =
        useUserTime_ ? time_.timeToUserTime(startTime_) : startTime_;
    return baseFileDir()/prefix_/Time::timeName(t);
}


Foam::vector2D Foam::SPH::functionObjects::sphFunctionObject::readPoint
(
    const dictionary& dict,
    const word& key
)
{
    ITstream& is = dict.lookup(key);
    const scalarList c(is);
    return toPoint(c, is, key);
}


Foam::List<Foam::vector2D>
Foam::SPH::functionObjects::sphFunctionObject::readPoints
(
    const dictionary& dict,
    const word& key
)
{
    ITstream& is = dict.lookup(key);
    const List<scalarList> c(is);

    List<vector2D> points(c.size());
    forAll(c, i)
    {
        points[i] = toPoint(c[i], is, key);
    }
    return points;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::sphFunctionObject::sphFunctionObject
(
    const word& name,
    const Time& runTime,
    const dictionary& dict,
    const word& fileName
)
:
    Foam::functionObjects::timeFunctionObject(name, runTime),
    // Files are opened at the first write: an object waiting for its
    // timeStart leaves no empty file behind
    Foam::functionObjects::writeFile(runTime, name, fileName),
    measuredIndex_(-1)
{
    // The check comes first so that an FV solver fails on the cloud, not
    // on a missing entry of the SPH dictionary
    lookupCloud(name, runTime, dict);

    // writeFile names the folder after Time::startTime(), which a restored
    // clock sets to the origin of its write grid (timeClock::restore): a
    // restart from 15.3 wrote into 0/ as force_0.dat. OpenFOAM's folder is
    // the time the run started from, also for an object added to
    // controlDict during the run.
    startTime_ = timeClock::runStart(runTime);
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

bool Foam::SPH::functionObjects::sphFunctionObject::found(const Time& runTime)
{
    return runTime.foundObject<sphCloud>(sphCloud::typeName);
}


const Foam::SPH::sphCloud&
Foam::SPH::functionObjects::sphFunctionObject::lookupCloud
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
{
    // An IO error: functionObjectList stops the run on it (a plain
    // FatalError at construction would only drop this object with a
    // warning), and the message names the controlDict entry
    if (!found(runTime))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name << " (type "
            << dict.lookupOrDefault<word>("type", "unknown") << "): "
            << noCloudMessage << exit(FatalIOError);
    }
    return runTime.lookupObject<sphCloud>(sphCloud::typeName);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::SPH::functionObjects::sphFunctionObject::read
(
    const dictionary& dict
)
{
    Foam::functionObjects::timeFunctionObject::read(dict);
    Foam::functionObjects::writeFile::read(dict);

    // The settings may have changed: measure afresh before writing
    measuredIndex_ = -1;
    return true;
}


bool Foam::SPH::functionObjects::sphFunctionObject::execute()
{
    measure();
    measuredIndex_ = time_.timeIndex();

    if (log)
    {
        writeLog();
    }
    return true;
}


bool Foam::SPH::functionObjects::sphFunctionObject::write()
{
    if (measuredIndex_ != time_.timeIndex())
    {
        measure();
        measuredIndex_ = time_.timeIndex();
    }

    if (writeToFile())
    {
        writeFiles();
    }
    return true;
}


// ************************************************************************* //
