/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    sphMapFields

Description
    Maps fields of an SPH result onto the fluid particles of this case
    (constant/sphMesh/fluid), as OpenFOAM's mapFields maps fields between
    meshes: writes <startTime>/<field> with internalField nonuniform, one
    value per fluid particle, which isphFoam starts from. A fine run can so
    start from the steady state of a coarser one instead of from rest; a
    k-epsilon run maps U, k and epsilon.

    The source is sampled as sphCompare samples an SPH result (quadratic
    MLS over its fluid particles and wall vertices, SPH::sphSource), so
    the velocity of a moving wall enters next to it. A scalar is bounded
    by the range of the source particles' own values: the quadratic fit
    can overshoot where a field is steep (epsilon at a wall), and k and
    epsilon must stay positive. The other entries of an existing
    <startTime>/<field> are kept (a link, as a tutorial's sph/0/k to the
    FV case's, is replaced by the file, the link's target left as it is);
    each file is written to a temporary and renamed, so a failure leaves
    the old one.

Usage
    sphMapFields sourceCase [-sourceTime t] [-fields '(U k epsilon)']
        [-case dir]

    -sourceTime t   time of the source (default: its latest)
    -fields list    the fields to map (default: (U))

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

namespace
{

// The field sampled at x, one scalarField a component; a point the source
// cannot reach (NaN) is an error naming one
List<scalarField> sampleAt
(
    const SPH::sampleSource& src,
    const word& name,
    const List<vector2D>& x,
    const Time& runTime
)
{
    List<scalarField> values(src.sample(name, x));
    label nMissing = 0, example = -1;
    forAll(x, i)
    {
        for (const scalarField& c : values)
        {
            if (!std::isfinite(c[i]))
            {
                if (!nMissing++) example = i;
                break;
            }
        }
    }
    if (nMissing)
    {
        FatalErrorInFunction
            << name << ": " << nMissing << " of the " << x.size()
            << " fluid particles of " << runTime.constant()/"sphMesh/fluid"
            << " have no source particle near them in " << src.fieldsPath()
            << ", e.g. " << x[example] << nl
            << "The source must cover this case's fluid" << exit(FatalError);
    }
    if (values.size() == 1)
    {
        // Bounded by the source's own values (see the Description)
        const scalarField own(src.ownValues(name)[0]);
        const scalar lo = min(own), hi = max(own);
        for (scalar& v : values[0]) v = min(max(v, lo), hi);
    }
    return values;
}


// <startTime>/<name>: the other entries of an existing file kept
// (boundaryField), written to a temporary first; any class (an FV case's
// 0/U says volVectorField)
template<class Type>
void writeInternalField
(
    const Time& runTime,
    const word& name,
    const Field<Type>& values,
    const fileName& from
)
{
    const SPH::fieldDictionary old
    (
        IOobject
        (
            name, runTime.timeName(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    const fileName file(runTime.timePath()/name);
    mkDir(file.path());
    {
        OFstream os(file + ".tmp");
        IOobject(name, runTime.timeName(), runTime).writeHeader(os, "dictionary");
        os  << "// Mapped by sphMapFields from " << from << nl
            << "// (one value per particle of constant/sphMesh/fluid)" << nl;
        for (const entry& e : old)
        {
            if (e.keyword() != "internalField") os << e << nl;
        }
        values.writeEntry("internalField", os);
        os  << nl;
        IOobject::writeEndDivider(os);
        if (!os.good())
        {
            FatalErrorInFunction
                << "Could not write " << file + ".tmp" << exit(FatalError);
        }
    }
    mv(file + ".tmp", file);
    Info<< "Mapped " << name << " of " << values.size() << " fluid particles"
        << " (" << gMin(values) << " to " << gMax(values) << ") into " << file
        << nl;
}


void mapField
(
    const SPH::sampleSource& src,
    const word& name,
    const List<vector2D>& x,
    const Time& runTime
)
{
    const List<scalarField> c(sampleAt(src, name, x, runTime));
    if (c.size() == 2)
    {
        vectorField U(x.size());
        forAll(U, i) U[i] = vector(c[0][i], c[1][i], 0);
        writeInternalField(runTime, name, U, src.fieldsPath());
    }
    else if (c.size() == 1)
    {
        writeInternalField(runTime, name, c[0], src.fieldsPath());
    }
    else
    {
        FatalErrorInFunction
            << name << " of " << src.fieldsPath() << " has " << c.size()
            << " components: only scalars and 2-D vectors are mapped"
            << exit(FatalError);
    }
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Map fields of an SPH result onto the fluid particles of this case:"
        " writes <startTime>/<field> (nonuniform), which isphFoam starts from"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addArgument("sourceCase");
    argList::addOption("sourceTime", "t", "time of the source (default: latest)");
    argList::addOption("fields", "list", "the fields to map (default: (U))");

    #include "setRootCase.H"
    #include "createTime.H"

    // A point the source cannot reach is a NaN, counted in sampleAt
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

    dictionary sourceDict;
    sourceDict.add("type", word("sph"));
    sourceDict.add("case", source);
    // The source's 'time' entry: latestTime (a word) or a number, which a
    // word holding digits is not
    const word sourceTime(args.getOrDefault<word>("sourceTime", "latestTime"));
    scalar sourceValue = 0;
    if (sourceTime == "latestTime")
    {
        sourceDict.add("time", sourceTime);
    }
    else if (readScalar(sourceTime, sourceValue))
    {
        sourceDict.add("time", sourceValue);
    }
    else
    {
        FatalErrorInFunction
            << "Option -sourceTime " << sourceTime << ": expected a time"
            << " value or latestTime" << exit(FatalError);
    }
    SPH::sampleSource::options opts;
    opts.baseDir = runTime.path();
    autoPtr<SPH::sampleSource> src =
        SPH::sampleSource::New("source", sourceDict, opts);

    const wordList fields(args.getOrDefault<wordList>("fields", wordList{"U"}));
    for (const word& name : fields)
    {
        mapField(*src, name, fluid.positions(), runTime);
    }
    Info<< nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
