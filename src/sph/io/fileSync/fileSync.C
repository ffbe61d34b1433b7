/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fileSync.H"
#include "OSspecific.H"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::SPH::fileSync::sync(const fileName& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        return false;
    }
    const bool ok = ::fsync(fd) == 0;
    const int err = errno;
    ::close(fd);
    errno = err;
    return ok;
}


bool Foam::SPH::fileSync::syncTree(const fileName& dir)
{
    for (const fileName& f : readDir(dir, fileName::FILE, false, false))
    {
        if (!sync(dir/f)) return false;
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY, false, false))
    {
        if (!syncTree(dir/d)) return false;
    }
    return sync(dir);
}


bool Foam::SPH::fileSync::exchange(const fileName& a, const fileName& b)
{
    return
        ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE)
     == 0;
}


std::string Foam::SPH::fileSync::lastError()
{
    return std::strerror(errno);
}


// ************************************************************************* //
