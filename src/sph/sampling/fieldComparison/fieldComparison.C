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


Foam::labelList Foam::SPH::fieldComparison::setSources
(
    const dictionary& dict,
    const label owner
) const
{
    // Those listed, else all but the tables, which give values only on sets
    // of their own rows
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
    return used;
}


Foam::label Foam::SPH::fieldComparison::setReference
(
    const dictionary& dict,
    const setData& set
) const
{
    // The entry, else the table giving a table set's points, else none
    if (dict.found("reference"))
    {
        const label ref = sourceOf(dict, "reference");
        if (!set.used.found(ref))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'reference': source " << sources_[ref].name()
                << " is not among the sources of the set" << nl
                << exit(FatalIOError);
        }
        return ref;
    }
    return set.points->type() == samplePoints::setType::table ? set.owner : -1;
}


void Foam::SPH::fieldComparison::setComponents
(
    const dictionary& dict,
    setData& set
) const
{
    // Components of every field, in order of the fields, then the sources
    set.fields = dict.get<wordList>("fields");
    if (set.fields.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'fields' is empty: name the fields to compare, e.g."
            << " fields (U p);" << nl << exit(FatalIOError);
    }
    for (const word& field : set.fields)
    {
        bool found = false;
        for (const label s : set.used)
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
                if (!set.components.found(ci))
                {
                    set.components.append(ci);
                    set.componentField.append(field);
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
}


void Foam::SPH::fieldComparison::sampleSet(setData& set) const
{
    // values[source in used][component], NaN where a source has none. On
    // the points of a source, that source's own values (eq. (66)).
    const bool ownPoints =
        set.points->type() == samplePoints::setType::sourcePoints;
    const label nPoints = set.points->size();

    set.values.setSize(set.used.size());
    forAll(set.used, u)
    {
        const sampleSource& src = sources_[set.used[u]];
        set.values[u].setSize
        (
            set.components.size(),
            scalarField(nPoints, errorNorms::missing())
        );
        for (const word& field : set.fields)
        {
            const wordList c(src.components(field));
            if (c.empty())
            {
                continue;
            }
            const List<scalarField> v
            (
                (ownPoints && set.used[u] == set.owner)
              ? src.ownValues(field)
              : src.sample(field, set.points->points())
            );
            forAll(c, k)
            {
                set.values[u][set.components.find(c[k])] = v[k];
            }
        }
    }

    // Fields compared up to a constant: each source's mean removed
    forAll(set.components, c)
    {
        if
        (
            set.zeroMean.found(set.componentField[c])
         || set.zeroMean.found(set.components[c])
        )
        {
            forAll(set.used, u)
            {
                set.values[u][c] -=
                    errorNorms::mean(set.values[u][c], set.points->weights());
            }
        }
    }
}


void Foam::SPH::fieldComparison::setErrors
(
    const dictionary& dict,
    const setData& set
)
{
    if (set.reference < 0)
    {
        return;
    }

    const scalar errorScale = dict.getOrDefault<scalar>("errorScale", 1);
    if (errorScale <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'errorScale' is " << errorScale << "; expected a"
            << " positive scale (u_max of eq. (66))" << nl
            << exit(FatalIOError);
    }

    const word& refName = sources_[set.reference].name();
    const label uRef = set.used.find(set.reference);
    Info<< "    against " << refName << " (errors over " << errorScale
        << "):" << nl
        << ("    " + pad("component", 12) + pad("source", 12)
          + pad("L2", 14) + pad("maxAbs", 14) + "points").c_str() << nl;

    forAll(set.components, c)
    {
        forAll(set.used, u)
        {
            if (u == uRef) continue;
            const errorNorms::result e = errorNorms::compare
            (
                set.values[u][c],
                set.values[uRef][c],
                set.points->weights(),
                errorScale
            );
            if (e.nPoints == 0) continue;

            const word& name = sources_[set.used[u]].name();
            errors_.append
            (
                errorRow{set.name, set.components[c], name, refName, errorScale, e}
            );
            Info<< ("    " + pad(set.components[c], 12) + pad(name, 12)
                  + pad(num(e.L2, 6), 14) + pad(num(e.maxAbs, 6), 14)).c_str()
                << e.nPoints << nl;
        }
    }
}


void Foam::SPH::fieldComparison::writeSet(const setData& set) const
{
    const samplePoints& pts = *set.points;
    const fileName dir(outputDir());
    mkDir(dir);
    OFstream os(dir/set.name + ".dat");

    os  << "# sphCompare set " << set.name << " ("
        << samplePoints::setTypeNames[pts.type()] << ", " << pts.size()
        << " points) at time " << timeName_ << nl;
    for (const label s : set.used)
    {
        os  << "# source " << sources_[s].name() << ": " << sources_[s].type()
            << " " << sources_[s].location().c_str();
        if (!sources_[s].timeName().empty())
        {
            os  << " time " << sources_[s].timeName().c_str();
        }
        os  << nl;
    }
    if (!set.zeroMean.empty())
    {
        os  << "# zeroMean " << set.zeroMean << ": each source's mean over"
            << " the set removed" << nl;
    }

    os  << "# distance x y weight";
    for (const word& c : set.components)
    {
        for (const label s : set.used)
        {
            os  << ' ' << c.c_str() << '_' << sources_[s].name().c_str();
        }
    }
    os  << nl;

    for (label i = 0; i < pts.size(); ++i)
    {
        os  << num(pts.distance()[i]).c_str() << ' '
            << num(pts.points()[i].x()).c_str() << ' '
            << num(pts.points()[i].y()).c_str() << ' '
            << num(pts.weights()[i]).c_str();
        forAll(set.components, c)
        {
            forAll(set.used, u)
            {
                os  << ' ' << num(set.values[u][c][i]).c_str();
            }
        }
        os  << nl;
    }
}


void Foam::SPH::fieldComparison::compareSet
(
    const word& name,
    const dictionary& dict
)
{
    setData set;
    set.name = name;
    set.points = setPoints(dict);
    const samplePoints::setType type = set.points->type();
    set.owner =
        (type == samplePoints::setType::line || type == samplePoints::setType::points)
      ? -1 : sourceOf(dict, "source");

    Info<< nl << "Set " << name << ": " << samplePoints::setTypeNames[type]
        << ", " << set.points->size() << " points" << nl;

    set.used = setSources(dict, set.owner);
    set.reference = setReference(dict, set);
    set.zeroMean = dict.getOrDefault<wordList>("zeroMean", wordList());
    setComponents(dict, set);
    sampleSet(set);
    setErrors(dict, set);
    writeSet(set);
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
