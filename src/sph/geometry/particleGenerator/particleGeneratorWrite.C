/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    particleGenerator's writing: the old constant/sphMesh moved aside, the
    new one written and every file checked complete; a read-only folder or
    a failed write is an error and the old mesh is put back (issue 12).

\*---------------------------------------------------------------------------*/

#include "particleGenerator.H"
#include "particles.H"
#include "Time.H"
#include "OSspecific.H"
#include "IFstream.H"
#include <fstream>
#include <unistd.h>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::particleGenerator::checkWritable() const
{
    const fileName constDir(runTime_.path()/runTime_.constant());
    const fileName meshDir(constDir/"sphMesh");
    if (!isDir(constDir) && !mkDir(constDir))
    {
        FatalErrorInFunction
            << "Cannot create " << constDir << ": nothing written"
            << exit(FatalError);
    }
    const fileName blocked
    (
        ::access(constDir.c_str(), W_OK) != 0 ? constDir
      : (isDir(meshDir) && ::access(meshDir.c_str(), W_OK) != 0) ? meshDir
      : fileName()
    );
    if (!blocked.empty())
    {
        FatalErrorInFunction
            << blocked << " is read-only: sphMesh cannot replace "
            << meshDir << ". Nothing written; make it writable (chmod u+w)"
            << " and run sphMesh again" << exit(FatalError);
    }
}


Foam::fileName Foam::SPH::particleGenerator::incompleteFile
(
    const fileName& dir
)
{
    // OpenFOAM ends every file it writes with this line, after the data
    const std::string end =
        "// ************************************************************************* //";
    for (const fileName& f : readDir(dir, fileName::FILE))
    {
        const fileName path(dir/f);
        if (path.hasExt("gz"))
        {
            // Compressed: read through, the last line decompressed
            IFstream is(path);
            std::string line, last;
            while (is.good())
            {
                is.getLine(line);
                if (!line.empty()) last = line;
            }
            if (last.find(end) == std::string::npos) return path;
            continue;
        }
        std::ifstream is(path, std::ios::binary | std::ios::ate);
        const std::streamoff size = is ? std::streamoff(is.tellg()) : 0;
        const std::streamoff n = std::min<std::streamoff>(size, 256);
        std::string tail(n, '\0');
        is.seekg(size - n);
        is.read(&tail[0], n);
        if (!is || tail.find(end) == std::string::npos)
        {
            return path;
        }
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY))
    {
        const fileName bad(incompleteFile(dir/d));
        if (!bad.empty()) return bad;
    }
    return fileName();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::particleGenerator::writeInto(const fileName& local) const
{
    const word inst = runTime_.constant();

    particles fluid(runTime_, inst, local/"fluid", false);
    fluid.resize(fluid_.size());
    fluid.positions() = fluid_;
    fluid.write();

    particles dummy(runTime_, inst, local/"dummy", false);
    dummy.add<label>("layer");
    dummy.add<label>("patch");
    dummy.resize(dummy_.size());
    dummy.positions() = dummy_;
    dummy.field<label>("layer") = dummyLayer_;
    dummy.field<label>("patch") = dummyPatch_;
    dummy.write();

    walls_->write(runTime_, local);
    walls_->domain().write(runTime_, local);
    wallModel_->writeLayout(runTime_, local, dr_, nLayers_);
}


void Foam::SPH::particleGenerator::write() const
{
    // The old mesh moved aside, the new one written in its place and every
    // file checked: a failed write (disk full, read-only) puts the old mesh
    // back and says so (written in place, the headers' location is right)
    checkWritable();
    const fileName constDir(runTime_.path()/runTime_.constant());
    const fileName meshDir(constDir/"sphMesh");
    const fileName oldDir
    (
        constDir/("sphMesh.old-" + Foam::name(label(::getpid())))
    );
    rmDir(oldDir, true);

    auto fail = [&](const std::string& what)
    {
        rmDir(meshDir, true);
        if (isDir(oldDir))
        {
            mv(oldDir, meshDir);
        }
        FatalErrorInFunction
            << "Writing the mesh failed: " << what.c_str() << nl
            << meshDir << " is as it was (disk full? read-only?); nothing"
            << " written" << exit(FatalError);
    };

    if (isDir(meshDir) && !mv(meshDir, oldDir))
    {
        FatalErrorInFunction
            << "Cannot move the old " << meshDir << " aside: nothing written"
            << exit(FatalError);
    }
    if (!mkDir(meshDir))
    {
        fail("cannot create " + meshDir);
    }
    writeInto("sphMesh");
    const fileName bad(incompleteFile(meshDir));
    if (!bad.empty())
    {
        fail(bad + " is incomplete or missing");
    }
    if (isDir(oldDir) && !rmDir(oldDir, true))
    {
        WarningInFunction
            << "Could not remove the previous mesh, now in " << oldDir << nl;
    }

    Info<< "Written " << meshDir << nl;
}


// ************************************************************************* //
