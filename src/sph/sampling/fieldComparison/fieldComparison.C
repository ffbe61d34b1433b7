/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fieldComparison.H"
#include "Time.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOmanip.H"

#include <sstream>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- A number for the tables: "nan" when missing, -1 run times as "-"
    Foam::string num(const Foam::scalar v, const int precision = 8)
    {
        if (!std::isfinite(v))
        {
            return "nan";
        }
        std::ostringstream os;
        os.precision(precision);
        os << v;
        return os.str();
    }

    Foam::string runTime(const Foam::scalar t)
    {
        return t < 0 ? Foam::string("-") : num(t, 6);
    }

    //- Left-aligned in a column of width w
    std::string pad(const std::string& s, const std::string::size_type w)
    {
        return s.size() >= w ? s + " " : s + std::string(w - s.size(), ' ');
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::fieldComparison::readSources
(
    const sampleSource::options& opts,
    const HashTable<fileName>& cases
)
{
    const dictionary& sourcesDict = dict_.subDict("sources");

    // Sources of the dictionary, then those only given on the command line
    DynamicList<word> names;
    for (const entry& e : sourcesDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(sourcesDict)
                << "Entry '" << e.keyword() << "' of sources is not a"
                << " dictionary: each source is name { type ...; }" << nl
                << exit(FatalIOError);
        }
        names.append(e.keyword());
    }
    for (const word& name : cases.sortedToc())
    {
        if (!names.found(name))
        {
            names.append(name);
        }
    }
    if (names.empty())
    {
        FatalIOErrorInFunction(sourcesDict)
            << "No source to compare: sources { name { type sph|fv|table"
            << "|expression; ... } }" << nl << exit(FatalIOError);
    }

    sources_.setSize(names.size());
    forAll(names, i)
    {
        const word& name = names[i];

        // A copy that keeps its parents, for $variables of the dictionary
        dictionary d(sourcesDict, sourcesDict.subOrEmptyDict(name));
        d.name() = sourcesDict.name() + '.' + name;
        if (!sourcesDict.found(name))
        {
            d.add("type", name);
        }
        if (cases.found(name))
        {
            d.set("case", string(cases[name]));
        }

        sources_.set(i, sampleSource::New(name, d, opts));
        sourceIndex_.set(name, i);
    }

    // The output time: that of the source in this case, else of the first
    // result
    auto cleaned = [](fileName f) { f.clean(); return f; };
    const fileName here(cleaned(runTime_.path()));
    for (const sampleSource& s : sources_)
    {
        if (!s.timeName().empty() && cleaned(s.location()) == here)
        {
            timeName_ = s.timeName();
            break;
        }
    }
    for (const sampleSource& s : sources_)
    {
        if (timeName_.empty() && !s.timeName().empty())
        {
            timeName_ = s.timeName();
        }
    }
    if (timeName_.empty())
    {
        timeName_ = "0";
    }
}


Foam::label Foam::SPH::fieldComparison::sourceOf
(
    const dictionary& dict,
    const word& key
) const
{
    const word name(dict.get<word>(key));
    if (!sourceIndex_.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "': no source " << name << nl
            << "Sources: " << sourceIndex_.sortedToc() << nl
            << exit(FatalIOError);
    }
    return sourceIndex_[name];
}


Foam::autoPtr<Foam::SPH::samplePoints>
Foam::SPH::fieldComparison::setPoints(const dictionary& dict) const
{
    const samplePoints::setType type =
        samplePoints::setTypeNames.get("type", dict);

    if (type == samplePoints::setType::line || type == samplePoints::setType::points)
    {
        return autoPtr<samplePoints>::New(dict);
    }

    const sampleSource& src = sources_[sourceOf(dict, "source")];
    if
    (
        !src.hasOwnPoints()
     || (type == samplePoints::setType::table && !src.ownPointsOnly())
    )
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'source': source " << src.name() << " is of type "
            << src.type() << "; a set of type "
            << samplePoints::setTypeNames[type] << " needs "
            << (type == samplePoints::setType::table ? "a table" : "an sph, fv or table")
            << " source" << nl << exit(FatalIOError);
    }

    List<vector2D> points;
    scalarField weights;
    src.ownPoints(points, weights);
    return autoPtr<samplePoints>::New(type, points, weights);
}


void Foam::SPH::fieldComparison::compareSet
(
    const word& setName,
    const dictionary& dict
)
{
    const autoPtr<samplePoints> setPtr(setPoints(dict));
    const samplePoints& set = *setPtr;
    const List<vector2D>& points = set.points();
    const label nPoints = set.size();
    const bool ownPoints = set.type() == samplePoints::setType::sourcePoints;
    const label owner =
        (set.type() == samplePoints::setType::line
      || set.type() == samplePoints::setType::points)
      ? -1 : sourceOf(dict, "source");

    Info<< nl << "Set " << setName << ": "
        << samplePoints::setTypeNames[set.type()] << ", " << nPoints
        << " points" << nl;

    // The sources sampled: those listed, else all but the tables, which
    // give values only on sets of their own rows
    labelList used;
    if (dict.found("sources"))
    {
        for (const word& name : dict.get<wordList>("sources"))
        {
            if (!sourceIndex_.found(name))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'sources': no source " << name << nl
                    << "Sources: " << sourceIndex_.sortedToc() << nl
                    << exit(FatalIOError);
            }
            used.append(sourceIndex_[name]);
        }
    }
    else
    {
        forAll(sources_, s)
        {
            if (s == owner || !sources_[s].ownPointsOnly())
            {
                used.append(s);
            }
        }
    }

    // The reference: the entry, else the table giving a table set's points
    label ref = -1;
    if (dict.found("reference"))
    {
        ref = sourceOf(dict, "reference");
        if (!used.found(ref))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'reference': source " << sources_[ref].name()
                << " is not among the sources of the set" << nl
                << exit(FatalIOError);
        }
    }
    else if (set.type() == samplePoints::setType::table)
    {
        ref = owner;
    }

    // Components of every field, in order of the fields, then the sources
    const wordList fields(dict.get<wordList>("fields"));
    if (fields.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'fields' is empty: name the fields to compare, e.g."
            << " fields (U p);" << nl << exit(FatalIOError);
    }
    DynamicList<word> cmpts;
    DynamicList<word> cmptField;
    for (const word& field : fields)
    {
        bool found = false;
        for (const label s : used)
        {
            const wordList c(sources_[s].components(field));
            if (c.empty() && sources_[s].complete())
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'fields': source " << sources_[s].name()
                    << " (" << sources_[s].type() << ") has no field "
                    << field << " in " << sources_[s].fieldsPath() << nl
                    << exit(FatalIOError);
            }
            for (const word& ci : c)
            {
                found = true;
                if (!cmpts.found(ci))
                {
                    cmpts.append(ci);
                    cmptField.append(field);
                }
            }
        }
        if (!found)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'fields': no source of this set holds " << field
                << nl << exit(FatalIOError);
        }
    }

    // Values: [source in used][component], NaN where a source has none
    List<List<scalarField>> values(used.size());
    forAll(used, u)
    {
        const sampleSource& src = sources_[used[u]];
        values[u].setSize(cmpts.size(), scalarField(nPoints, errorNorms::missing()));
        for (const word& field : fields)
        {
            const wordList c(src.components(field));
            if (c.empty())
            {
                continue;
            }
            const List<scalarField> v
            (
                (ownPoints && used[u] == owner)
              ? src.ownValues(field)
              : src.sample(field, points)
            );
            forAll(c, k)
            {
                values[u][cmpts.find(c[k])] = v[k];
            }
        }
    }

    // Fields compared up to a constant: each source's mean removed
    const wordList zeroMean(dict.getOrDefault<wordList>("zeroMean", wordList()));
    forAll(cmpts, c)
    {
        if (zeroMean.found(cmptField[c]) || zeroMean.found(cmpts[c]))
        {
            forAll(used, u)
            {
                values[u][c] -= errorNorms::mean(values[u][c], set.weights());
            }
        }
    }

    // Errors against the reference
    const scalar errorScale = dict.getOrDefault<scalar>("errorScale", 1);
    if (errorScale <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'errorScale' is " << errorScale << "; expected a"
            << " positive scale (u_max of eq. (66))" << nl
            << exit(FatalIOError);
    }
    if (ref >= 0)
    {
        const label uRef = used.find(ref);
        Info<< "    against " << sources_[ref].name() << " (errors over "
            << errorScale << "):" << nl
            << ("    " + pad("component", 12) + pad("source", 12)
              + pad("L2", 14) + pad("maxAbs", 14) + "points").c_str() << nl;
        forAll(cmpts, c)
        {
            const scalarField& r = values[uRef][c];
            forAll(used, u)
            {
                if (u == uRef) continue;
                const errorNorms::result e =
                    errorNorms::compare(values[u][c], r, set.weights(), errorScale);
                if (e.nPoints == 0) continue;
                errors_.append
                (
                    errorRow{setName, cmpts[c], sources_[used[u]].name(),
                        sources_[ref].name(), errorScale, e}
                );
                Info<< ("    " + pad(cmpts[c], 12)
                      + pad(sources_[used[u]].name(), 12)
                      + pad(num(e.L2, 6), 14) + pad(num(e.maxAbs, 6), 14)).c_str()
                    << e.nPoints << nl;
            }
        }
    }

    // The set file
    const fileName dir(outputDir());
    mkDir(dir);
    OFstream os(dir/setName + ".dat");
    os  << "# sphCompare set " << setName << " ("
        << samplePoints::setTypeNames[set.type()] << ", " << nPoints
        << " points) at time " << timeName_ << nl;
    for (const label s : used)
    {
        os  << "# source " << sources_[s].name() << ": " << sources_[s].type()
            << " " << sources_[s].location().c_str();
        if (!sources_[s].timeName().empty())
        {
            os  << " time " << sources_[s].timeName().c_str();
        }
        os  << nl;
    }
    if (!zeroMean.empty())
    {
        os  << "# zeroMean " << zeroMean << ": each source's mean over the set"
            << " removed" << nl;
    }
    os  << "# distance x y weight";
    for (const word& c : cmpts)
    {
        for (const label s : used)
        {
            os  << ' ' << c.c_str() << '_' << sources_[s].name().c_str();
        }
    }
    os  << nl;
    for (label i = 0; i < nPoints; ++i)
    {
        os  << num(set.distance()[i]).c_str() << ' '
            << num(points[i].x()).c_str() << ' '
            << num(points[i].y()).c_str() << ' '
            << num(set.weights()[i]).c_str();
        forAll(cmpts, c)
        {
            forAll(used, u)
            {
                os  << ' ' << num(values[u][c][i]).c_str();
            }
        }
        os  << nl;
    }
}


void Foam::SPH::fieldComparison::writeSources(const fileName& dir) const
{
    OFstream os(dir/"sources.dat");
    os  << "# sphCompare sources; clockTime, executionTime: wall-clock and CPU"
        << " seconds of the run (the last ClockTime, ExecutionTime of its log),"
        << " - if unknown" << nl
        << ("# " + pad("source", 12) + pad("type", 12) + pad("time", 12)
          + pad("clockTime", 12) + pad("executionTime", 15) + "location").c_str()
        << nl;
    for (const sampleSource& s : sources_)
    {
        os  << ("  " + pad(s.name(), 12) + pad(s.type(), 12)
              + pad(s.timeName().empty() ? "-" : s.timeName(), 12)
              + pad(runTime(s.clockTime()), 12)
              + pad(runTime(s.executionTime()), 15)
              + s.location()).c_str() << nl;
    }
}


void Foam::SPH::fieldComparison::writeErrors(const fileName& dir) const
{
    OFstream os(dir/"errors.dat");
    os  << "# sphCompare errors at time " << timeName_ << " of "
        << runTime_.path().c_str() << nl
        << "# L2 = sqrt(sum_i w_i (f_i - f_ref,i)^2 / sum_i w_i)/scale"
        << " (000_8c7cd3aabddcf18a.txt eq. (66)); maxAbs = max_i"
        << " |f_i - f_ref,i|/scale; w_i: the set's weights" << nl
        << "# clock, clockRef: wall-clock seconds of the runs of the source"
        << " and of the reference (- if unknown)" << nl
        << ("# " + pad("set", 16) + pad("component", 10) + pad("source", 12)
          + pad("reference", 12) + pad("scale", 8) + pad("points", 8)
          + pad("L2", 16) + pad("maxAbs", 16) + pad("clock", 10)
          + "clockRef").c_str() << nl;
    for (const errorRow& e : errors_)
    {
        const sampleSource& s = sources_[sourceIndex_[e.source]];
        const sampleSource& r = sources_[sourceIndex_[e.reference]];
        os  << ("  " + pad(e.set, 16) + pad(e.component, 10)
              + pad(e.source, 12) + pad(e.reference, 12)
              + pad(num(e.scale, 6), 8) + pad(Foam::name(e.norms.nPoints), 8)
              + pad(num(e.norms.L2), 16) + pad(num(e.norms.maxAbs), 16)
              + pad(runTime(s.clockTime()), 10) + runTime(r.clockTime())).c_str()
            << nl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fieldComparison::fieldComparison
(
    const Time& runTime,
    const sampleSource::options& opts,
    const HashTable<fileName>& cases
)
:
    runTime_(runTime),
    dict_
    (
        IOobject
        (
            "sphCompareDict",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    )
{
    Info<< "Reading " << dict_.name() << nl;
    readSources(opts, cases);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::SPH::fieldComparison::outputDir() const
{
    return runTime_.path()/"postProcessing"/"sphCompare"/timeName_;
}


void Foam::SPH::fieldComparison::write()
{
    errors_.clear();

    const dictionary& setsDict = dict_.subDict("sets");
    for (const entry& e : setsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(setsDict)
                << "Entry '" << e.keyword() << "' of sets is not a"
                << " dictionary: each set is name { type ...; }" << nl
                << exit(FatalIOError);
        }
        compareSet(e.keyword(), e.dict());
    }

    const fileName dir(outputDir());
    mkDir(dir);
    writeSources(dir);
    writeErrors(dir);

    Info<< nl << "Written " << dir << "/{<set>.dat,errors.dat,sources.dat}"
        << nl;
}


// ************************************************************************* //
