/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "vtkAtomicFile.H"
#include "OSspecific.H"
#include "fileSync.H"
#include "error.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The nearest ancestor of dir that exists (dir itself if it exists)
Foam::fileName nearestExisting(Foam::fileName dir)
{
    while (!Foam::exists(dir, false) && dir.hasPath() && dir != dir.path())
    {
        dir = dir.path();
    }
    return dir;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::vtkAtomicFile::vtkAtomicFile(const fileName& file)
:
    file_(file),
    tmp_(file + ".tmp"),
    committed_(false)
{
    if (file_.empty())
    {
        FatalErrorInFunction
            << "Empty output file name" << exit(FatalError);
    }

    if (isDir(file_))
    {
        // rename() would move the temporary file into it instead
        FatalErrorInFunction
            << "Cannot write " << file_ << nl
            << "    because it is a folder" << exit(FatalError);
    }

    const fileName dir(file_.path());

    if (!isDir(dir))
    {
        // mkDir would stop with a message about the folder only; checking the
        // common failure first lets the message name the file being written
        const fileName existing(nearestExisting(dir));

        if (exists(existing, false) && !isDir(existing))
        {
            FatalErrorInFunction
                << "Cannot write " << file_ << nl
                << "    because " << existing
                << " exists and is not a folder, so the folder " << dir
                << " cannot be created" << exit(FatalError);
        }

        if (!mkDir(dir) || !isDir(dir))
        {
            FatalErrorInFunction
                << "Cannot write " << file_ << nl
                << "    because the folder " << dir << " cannot be created"
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::SPH::vtkAtomicFile::~vtkAtomicFile()
{
    if (!committed_ && isFile(tmp_))
    {
        rm(tmp_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::vtkAtomicFile::commit()
{
    if (!isFile(tmp_))
    {
        fail("the temporary file " + tmp_ + " was not written");
    }

    // On disk before the rename, or a crash could leave an empty file
    if (!fileSync::sync(tmp_))
    {
        fail("syncing " + tmp_ + " failed: " + fileSync::lastError());
    }

    // rename() replaces an existing file in one step (POSIX), which is the
    // point of writing a temporary file first
    if (!mv(tmp_, file_))
    {
        fail("renaming " + tmp_ + " over it failed");
    }

    committed_ = true;
}


void Foam::SPH::vtkAtomicFile::fail(const std::string& reason)
{
    if (isFile(tmp_))
    {
        rm(tmp_);
    }

    FatalErrorInFunction
        << "Cannot write " << file_ << nl
        << "    " << reason.c_str() << exit(FatalError);
}


// ************************************************************************* //
