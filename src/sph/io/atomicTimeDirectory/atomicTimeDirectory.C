/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "atomicTimeDirectory.H"
#include "fileSync.H"
#include "OSspecific.H"

#include <cstdio>
#include <sys/statvfs.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Copy what 'from' holds and 'to' does not (the initial fields of 0/
//- when the last good state is the start time): a rewrite adds, as
//- OpenFOAM's writes into an existing time do, and never drops a file
void keepOthers(const Foam::fileName& from, const Foam::fileName& to)
{
    using namespace Foam;
    for (const fileName& f : readDir(from, fileName::FILE, false, false))
    {
        if (!exists(to/f, false)) cp(from/f, to/f);
    }
    for (const fileName& d : readDir(from, fileName::DIRECTORY, false, false))
    {
        if (!isDir(to/d)) cp(from/d, to/d);
        else keepOthers(from/d, to/d);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::SPH::atomicTimeDirectory::suffix(".writing");


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::atomicTimeDirectory::restoreCase()
{
    runTime_.caseName() = caseName_;
}


void Foam::SPH::atomicTimeDirectory::fail(const std::string& what)
{
    // Full before the partial write is removed (which frees its space)
    struct statvfs fs;
    const bool full =
        ::statvfs(runTime_.path().c_str(), &fs) == 0
     && fs.f_bavail*fs.f_frsize < 65536;

    restoreCase();
    rmDir(staging_, true);
    committed_ = true;
    FatalErrorInFunction
        << "Cannot write the time directory " << final_ << nl
        << "    " << what.c_str() << nl
        << (
               full
             ? "    The disk holding the case is full."
             : "    (a full disk or a folder that cannot be written?)"
           )
        << " Every earlier time directory is intact; nothing of time "
        << name_ << " is left behind" << exit(FatalError);
    std::abort();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::atomicTimeDirectory::atomicTimeDirectory(Time& runTime)
:
    runTime_(runTime),
    caseName_(runTime.caseName()),
    name_(runTime.timeName()),
    final_(runTime.path()/name_),
    staging_(runTime.path()/(name_ + suffix)),
    committed_(false)
{
    if (exists(staging_, false))
    {
        rmDir(staging_, true) || rm(staging_);
    }
    if (!mkDir(staging_) || !isDir(staging_))
    {
        committed_ = true;
        FatalErrorInFunction
            << "Cannot write the time directory " << final_ << nl
            << "    because the folder " << staging_
            << " cannot be made: " << fileSync::lastError().c_str() << nl
            << "    Every earlier time directory is intact"
            << exit(FatalError);
    }
    runTime_.caseName() = caseName_/(name_ + suffix);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::SPH::atomicTimeDirectory::~atomicTimeDirectory()
{
    if (!committed_)
    {
        restoreCase();
        rmDir(staging_, true);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::atomicTimeDirectory::write
(
    const std::function<bool()>& writer,
    const std::string& what
)
{
    // A stream that fails stops OpenFOAM with a FatalIOError, which would
    // exit with the .writing folder left: catch it here instead
    const bool throwing = FatalError.throwExceptions(true);
    const bool throwingIO = FatalIOError.throwExceptions(true);
    std::string failure;
    try
    {
        if (!writer())
        {
            failure = what;
        }
    }
    catch (const Foam::error& e)
    {
        failure = what + ": " + e.message();
    }
    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(throwingIO);
    if (!failure.empty())
    {
        fail(failure);
    }
}


void Foam::SPH::atomicTimeDirectory::commit()
{
    restoreCase();
    const fileName written(staging_/name_);
    if (isDir(final_) && isDir(written))
    {
        keepOthers(final_, written);
    }
    if (!isDir(written) || !fileSync::syncTree(written))
    {
        fail("syncing " + written + " failed: " + fileSync::lastError());
    }
    if (isDir(final_))
    {
        // Written before (the last good state at its own write time, or
        // the start time's initial fields): swap in one step, everything
        // else it held copied in first; the old one goes with the .writing
        // folder
        if (!fileSync::exchange(written, final_))
        {
            fail("replacing it failed: " + fileSync::lastError());
        }
    }
    else if (::rename(written.c_str(), final_.c_str()) != 0)
    {
        fail("renaming " + written + " to it failed: " + fileSync::lastError());
    }
    fileSync::sync(runTime_.path());
    committed_ = true;
    rmDir(staging_, true);
}


void Foam::SPH::atomicTimeDirectory::removeUnfinished(const Time& runTime)
{
    for
    (
        const fileName& d
      : readDir(runTime.path(), fileName::DIRECTORY, false, false)
    )
    {
        if (d.hasExt() && ("." + d.ext()) == suffix)
        {
            Info<< "Removing " << runTime.path()/d << ": an unfinished write"
                << " of time " << d.lessExt()
                << " (a run stopped while writing it)" << nl;
            rmDir(runTime.path()/d, true);
        }
    }
}


// ************************************************************************* //
