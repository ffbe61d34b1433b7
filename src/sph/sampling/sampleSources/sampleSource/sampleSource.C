/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sampleSource.H"
#include "Time.H"
#include "stringOps.H"
#include "OSspecific.H"

#include <fstream>
#include <cstdlib>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(sampleSource, 0);
    defineRunTimeSelectionTable(sampleSource, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- Do two paths name the same folder (once cleaned)?
    bool sameFolder(Foam::fileName a, Foam::fileName b)
    {
        a.clean();
        b.clean();
        return a == b;
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::string Foam::SPH::sampleSource::expandedString(const string& s) const
{
    // $variables of this dictionary and its parents, then of the
    // environment; <case>/, <system>/ and ~ as OpenFOAM expands them
    std::string str(s);
    stringOps::inplaceExpand(str, dict_, true, false);
    return string(str);
}


Foam::string Foam::SPH::sampleSource::readText
(
    const dictionary& dict,
    const word& key
) const
{
    ITstream& is = dict.lookup(key);
    const token t(is);
    if (!t.isStringType())
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' is " << t << "; expected a word or a"
            << " \"quoted string\"" << nl << exit(FatalIOError);
    }
    return expandedString(t.stringToken());
}


Foam::fileName Foam::SPH::sampleSource::readPath
(
    const word& key,
    const fileName& baseDir,
    const fileName& deflt
) const
{
    std::string raw(deflt);
    if (dict_.found(key))
    {
        ITstream& is = dict_.lookup(key);
        const token t(is);
        if (!t.isStringType())
        {
            FatalIOErrorInFunction(dict_)
                << "Entry '" << key << "' is " << t << "; expected a"
                << " \"quoted path\"" << nl << exit(FatalIOError);
        }
        raw = t.stringToken();
    }
    if (raw.empty())
    {
        return fileName::null;
    }

    // OpenFOAM's expansion reads a leading "." as the working folder: a
    // relative path starts from baseDir instead
    if (raw[0] == '.')
    {
        raw = baseDir + "/" + raw;
    }
    fileName path(expandedString(raw));
    if (!path.isAbsolute())
    {
        path = baseDir/path;
    }
    path.clean();
    return path;
}


bool Foam::SPH::sampleSource::splitComponent
(
    const word& name,
    word& base,
    direction& cmpt
)
{
    if (name.size() < 2)
    {
        return false;
    }
    const char c = name.back();
    if (c != 'x' && c != 'y')
    {
        return false;
    }
    base = name.substr(0, name.size() - 1);
    cmpt = (c == 'x') ? vector2D::X : vector2D::Y;
    return true;
}


Foam::scalar Foam::SPH::sampleSource::scaleFactor(const word& field) const
{
    if (scale_.found(field))
    {
        return scale_[field];
    }
    word base;
    direction cmpt;
    if (splitComponent(field, base, cmpt) && scale_.found(base))
    {
        return scale_[base];
    }
    return 1;
}


Foam::wordList Foam::SPH::sampleSource::namedComponents
(
    const wordList& names,
    const word& field
)
{
    wordList result;
    for (const word& c : names)
    {
        word base;
        direction cmpt;
        if (c == field || (splitComponent(c, base, cmpt) && base == field))
        {
            result.append(c);
        }
    }
    return result;
}


Foam::autoPtr<Foam::Time> Foam::SPH::sampleSource::openCase
(
    const fileName& caseDir,
    const options& opts
) const
{
    if (!isFile(caseDir/"system"/"controlDict"))
    {
        FatalIOErrorInFunction(dict_)
            << "Source " << name_ << ": " << caseDir << " is not a case"
            << " (no system/controlDict)" << nl << exit(FatalIOError);
    }
    autoPtr<Time> runTime
    (
        new Time
        (
            Time::controlDictName, caseDir.path(), caseDir.name(),
            "system", "constant", false, false
        )
    );
    selectTime(*runTime, opts);
    return runTime;
}


Foam::fileName Foam::SPH::sampleSource::runLog
(
    const Time& runTime,
    const fileName& caseDir,
    const word& defaultApp
) const
{
    const word app
    (
        runTime.controlDict().getOrDefault<word>("application", defaultApp)
    );
    return readPath("log", caseDir, "log." + app);
}


void Foam::SPH::sampleSource::selectTime
(
    Time& runTime,
    const options& opts
) const
{
    // The dictionary's 'time' (a value or latestTime), else for a result in
    // the comparison case itself the option's (-time), else the latest
    bool latest = true;
    scalar wanted = 0;
    if (dict_.found("time"))
    {
        ITstream& is = dict_.lookup("time");
        const token t(is);
        if (t.isNumber())
        {
            latest = false;
            wanted = t.number();
        }
        else if (!(t.isWord() && t.wordToken() == "latestTime"))
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'time' is " << t << "; expected a time value or"
                << " latestTime" << nl << exit(FatalIOError);
        }
    }
    else if
    (
        !opts.time.empty() && opts.time != "latestTime"
     && sameFolder(runTime.path(), opts.baseDir)
    )
    {
        latest = false;
        if (!readScalar(opts.time, wanted))
        {
            FatalErrorInFunction
                << "Option -time " << opts.time << ": expected a time value"
                << " or latestTime" << nl << exit(FatalError);
        }
    }

    instantList times;
    for (const instant& t : runTime.times())
    {
        if (t.name() != runTime.constant())
        {
            times.append(t);
        }
    }
    if (times.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "Source " << name_ << ": no time directory in "
            << runTime.path() << nl << exit(FatalIOError);
    }

    label index = times.size() - 1;
    if (!latest)
    {
        index = Time::findClosestTimeIndex(times, wanted);
        if
        (
            index < 0
         || mag(times[index].value() - wanted) > 1e-9*max(scalar(1), mag(wanted))
        )
        {
            wordList names(times.size());
            forAll(times, i) names[i] = times[i].name();
            FatalIOErrorInFunction(dict_)
                << "Source " << name_ << ": no time " << wanted << " in "
                << runTime.path() << nl
                << "Times: " << names << nl << exit(FatalIOError);
        }
    }
    runTime.setTime(times[index], index);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::sampleSource::sampleSource
(
    const word& name,
    const dictionary& dict
)
:
    name_(name),
    dict_(dict.parent(), dict)
{
    // Keep the name (file and scope) of the entry, for error messages
    dict_.name() = dict.name();

    if (dict_.found("scale"))
    {
        const dictionary& scaleDict = dict_.subDict("scale");
        for (const entry& e : scaleDict)
        {
            scale_.set(e.keyword(), scaleDict.get<scalar>(e.keyword()));
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::sampleSource::ownPoints
(
    List<vector2D>& points,
    scalarField& weights
) const
{
    FatalIOErrorInFunction(dict_)
        << "Source " << name_ << " (type " << type() << ") has no points of"
        << " its own: a set of type sourcePoints needs an sph, fv or table"
        << " source" << nl << exit(FatalIOError);
}


Foam::List<Foam::scalarField> Foam::SPH::sampleSource::ownValues
(
    const word& field
) const
{
    List<vector2D> points;
    scalarField weights;
    ownPoints(points, weights);
    return sample(field, points);
}


bool Foam::SPH::sampleSource::readRunTimes
(
    const fileName& log,
    scalar& executionTime,
    scalar& clockTime
)
{
    std::ifstream is(log);
    if (!is)
    {
        return false;
    }

    // The last line of OpenFOAM's form
    //     ExecutionTime = 12.3 s  ClockTime = 13 s
    bool found = false;
    std::string line;
    const std::string exeKey("ExecutionTime = "), clockKey("ClockTime = ");
    while (std::getline(is, line))
    {
        const auto e = line.find(exeKey);
        const auto c = line.find(clockKey);
        if (e != std::string::npos && c != std::string::npos)
        {
            executionTime = std::strtod(line.c_str() + e + exeKey.size(), nullptr);
            clockTime = std::strtod(line.c_str() + c + clockKey.size(), nullptr);
            found = true;
        }
    }
    return found;
}


// ************************************************************************* //
