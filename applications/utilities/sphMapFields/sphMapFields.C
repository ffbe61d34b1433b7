/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    sphMapFields

Description
    Maps the velocity of an SPH result onto the fluid particles of this
    case (constant/sphMesh/fluid), as OpenFOAM's mapFields maps fields
    between meshes: writes <startTime>/U with internalField nonuniform, one
    value per fluid particle, which isphFoam starts from. A fine run can so
    start from the steady state of a coarser one instead of from rest.

    The source is sampled as sphCompare samples an SPH result (quadratic
    MLS over its fluid particles and wall vertices, SPH::sphSource), so
    the velocity of a moving wall enters next to it. The other entries of
    an existing <startTime>/U are kept; the file is written to a temporary
    and renamed, so a failure leaves the old one.

Usage
    sphMapFields sourceCase [-sourceTime t] [-case dir]

    -sourceTime t   time of the source (default: its latest)

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fieldDictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "sigFpe.H"
#include "particles.H"
#include "sampleSource.H"
#include "sphFoamVersion.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Map the velocity of an SPH result onto the fluid particles of this"
        " case: writes <startTime>/U (nonuniform), which isphFoam starts from"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addArgument("sourceCase");
    argList::addOption("sourceTime", "t", "time of the source (default: latest)");

    #include "setRootCase.H"
    #include "createTime.H"

    // A point the source cannot reach is a NaN, counted below
    sigFpe::unset(false);

    Info<< "sphFoam " << SPH::version << nl << endl;

    fileName source(args[1]);
    source.expand();
    if (!source.isAbsolute())
    {
        source = cwd()/source;
    }
    source.clean();

    SPH::particles fluid(runTime, runTime.constant(), "sphMesh/fluid", false);
    fluid.read();
    const List<vector2D>& x = fluid.positions();

    dictionary sourceDict;
    sourceDict.add("type", word("sph"));
    sourceDict.add("case", source);
    sourceDict.add("time", args.getOrDefault<word>("sourceTime", "latestTime"));
    SPH::sampleSource::options opts;
    opts.baseDir = runTime.path();
    autoPtr<SPH::sampleSource> src =
        SPH::sampleSource::New("source", sourceDict, opts);

    const List<scalarField> Uxy(src->sample("U", x));
    vectorField U(x.size());
    label nMissing = 0;
    label example = -1;
    forAll(U, i)
    {
        U[i] = vector(Uxy[0][i], Uxy[1][i], 0);
        if (!std::isfinite(U[i].x()) || !std::isfinite(U[i].y()))
        {
            if (!nMissing++) example = i;
        }
    }
    if (nMissing)
    {
        FatalErrorInFunction
            << nMissing << " of the " << x.size() << " fluid particles of "
            << runTime.constant()/"sphMesh/fluid" << " have no source particle"
            << " near them in " << src->fieldsPath() << ", e.g. "
            << x[example] << nl
            << "The source must cover this case's fluid" << exit(FatalError);
    }

    // <startTime>/U: the other entries kept (boundaryField), written to a
    // temporary first; any class (an FV case's 0/U says volVectorField)
    const SPH::fieldDictionary old
    (
        IOobject
        (
            "U", runTime.timeName(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    const fileName file(runTime.timePath()/"U");
    mkDir(file.path());
    {
        OFstream os(file + ".tmp");
        IOobject("U", runTime.timeName(), runTime).writeHeader(os, "dictionary");
        os  << "// Mapped by sphMapFields from " << src->fieldsPath() << nl
            << "// (one value per particle of constant/sphMesh/fluid)" << nl;
        for (const entry& e : old)
        {
            if (e.keyword() != "internalField") os << e << nl;
        }
        U.writeEntry("internalField", os);
        os  << nl;
        IOobject::writeEndDivider(os);
        if (!os.good())
        {
            FatalErrorInFunction
                << "Could not write " << file + ".tmp" << exit(FatalError);
        }
    }
    mv(file + ".tmp", file);

    scalar maxU = 0;
    for (const vector& u : U) maxU = max(maxU, mag(u));
    Info<< "Mapped U of " << U.size() << " fluid particles from "
        << src->fieldsPath() << " (largest |U| " << maxU << ") into "
        << file << nl << nl
        << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
