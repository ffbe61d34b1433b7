/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "domain.H"
#include "IOdictionary.H"
#include "Time.H"
#include "error.H"
#include "IStringStream.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::word Foam::SPH::domain::dictName("domain");

const char* const Foam::SPH::domain::axisNames[2] = {"x", "y"};

const char* const Foam::SPH::domain::sideNames[4] =
    {"xMin", "xMax", "yMin", "yMax"};


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- constant/sphMesh/domain
    Foam::IOobject domainIO
    (
        const Foam::objectRegistry& db,
        const Foam::IOobject::readOption r,
        const Foam::fileName& local = "sphMesh"
    )
    {
        return Foam::IOobject
        (
            Foam::SPH::domain::dictName,
            db.time().constant(),
            local,
            db,
            r,
            Foam::IOobject::NO_WRITE,
            false
        );
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::domain::setPeriods()
{
    for (direction d = 0; d < 2; ++d)
    {
        if (periodic_[d])
        {
            const scalar L = max_[d] - min_[d];
            if (!(L > 0) || !std::isfinite(L))
            {
                FatalErrorInFunction
                    << "Periodic in " << axisNames[d] << " from " << min_[d]
                    << " to " << max_[d] << ": expected max > min"
                    << exit(FatalError);
            }
            period_[d] = L;
            halfPeriod_[d] = 0.5*L;
        }
        else
        {
            period_[d] = 0;
            halfPeriod_[d] = VGREAT;
        }
    }
}


Foam::FixedList<bool, 2> Foam::SPH::domain::readDirections
(
    const dictionary& dict,
    const bool allowNone
)
{
    // One word (directions x;) or a list of them (directions (x y);)
    const ITstream& is = dict.lookup("directions");
    wordList names;
    if (is.size() == 1 && is[0].isWord())
    {
        names = wordList(1, is[0].wordToken());
    }
    else
    {
        names = dict.get<wordList>("directions");
    }

    FixedList<bool, 2> periodic(false);
    for (const word& w : names)
    {
        if (w == axisNames[0])
        {
            periodic[0] = true;
        }
        else if (w == axisNames[1])
        {
            periodic[1] = true;
        }
        else
        {
            FatalIOErrorInFunction(dict.lookup("directions"))
                << "Unknown periodic direction '" << w << "' in entry"
                << " 'directions'; valid directions are x and y, as"
                << " 'directions (x);', '(y)' or '(x y)'" << nl
                << exit(FatalIOError);
        }
    }
    if (!allowNone && !periodic[0] && !periodic[1])
    {
        FatalIOErrorInFunction(dict.lookup("directions"))
            << "Entry 'directions' names no direction; give x, y or (x y),"
            << " or remove the 'periodic' entry for a case that is not"
            << " periodic" << nl << exit(FatalIOError);
    }
    return periodic;
}


void Foam::SPH::domain::readOpenSides(const dictionary& dict)
{
    open_ = false;
    if (!dict.found("openSides"))
    {
        return;
    }
    // One word (openSides yMax;) or a list of them (openSides (yMax);)
    const ITstream& is = dict.lookup("openSides");
    const wordList names
    (
        is.size() == 1 && is[0].isWord()
      ? wordList(1, is[0].wordToken())
      : dict.get<wordList>("openSides")
    );
    for (const word& w : names)
    {
        label side = -1;
        for (label k = 0; k < 4; ++k)
        {
            if (w == sideNames[k]) side = k;
        }
        if (side < 0)
        {
            FatalIOErrorInFunction(dict.lookup("openSides"))
                << "Unknown side '" << w << "' in entry 'openSides'; valid"
                << " sides are xMin, xMax, yMin and yMax (the box's sides,"
                << " e.g. 'openSides (yMax);' for nothing above the water)"
                << nl << exit(FatalIOError);
        }
        if (periodic_[side/2])
        {
            FatalIOErrorInFunction(dict.lookup("openSides"))
                << "Side '" << w << "' in entry 'openSides' is a side of the"
                << " periodic direction " << axisNames[side/2] << ", which"
                << " has no outside; open only sides of a direction that is"
                << " not periodic" << nl << exit(FatalIOError);
        }
        open_[side] = true;
    }
}


Foam::wordList Foam::SPH::domain::openSideNames() const
{
    wordList names;
    for (label k = 0; k < 4; ++k)
    {
        if (open_[k])
        {
            names.append(word(sideNames[k]));
        }
    }
    return names;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::domain::domain
(
    const vector2D& min,
    const vector2D& max,
    const FixedList<bool, 2>& periodic,
    const FixedList<bool, 4>& open
)
:
    min_(min),
    max_(max),
    periodic_(periodic),
    period_(Zero),
    halfPeriod_(VGREAT, VGREAT),
    open_(open)
{
    setPeriods();
}


Foam::SPH::domain::domain
(
    const dictionary& dict,
    const vector2D& wallsMin,
    const vector2D& wallsMax
)
:
    domain(wallsMin, wallsMax)
{
    const dictionary* pd = dict.findDict("periodic");
    if (!pd)
    {
        if (dict.found("periodic"))
        {
            FatalIOErrorInFunction(dict.lookup("periodic"))
                << "Entry 'periodic' must be a dictionary:" << nl
                << "    periodic { directions (x); min (0 0); max (1 1); }"
                << nl << exit(FatalIOError);
        }
        readOpenSides(dict);
        return;
    }

    periodic_ = readDirections(*pd, false);
    const vector2D lo(pd->get<vector2D>("min"));
    const vector2D hi(pd->get<vector2D>("max"));
    for (direction d = 0; d < 2; ++d)
    {
        if (!periodic_[d])
        {
            continue;
        }
        if (!(hi[d] > lo[d]))
        {
            FatalIOErrorInFunction(*pd)
                << "Periodic in " << axisNames[d] << " from min " << lo[d]
                << " to max " << hi[d] << ": expected max > min (the period"
                << " is max - min)" << nl << exit(FatalIOError);
        }
        min_[d] = lo[d];
        max_[d] = hi[d];
    }
    setPeriods();
    readOpenSides(dict);
}


Foam::SPH::domain::domain
(
    const objectRegistry& db,
    const vector2D& wallsMin,
    const vector2D& wallsMax
)
:
    domain(wallsMin, wallsMax)
{
    IOobject io(domainIO(db, IOobject::MUST_READ));
    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        return;
    }
    const IOdictionary dict(io);
    periodic_ = readDirections(dict, true);
    min_ = dict.get<vector2D>("min");
    max_ = dict.get<vector2D>("max");
    setPeriods();
    readOpenSides(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::SPH::domain::directionNames() const
{
    wordList names;
    for (direction d = 0; d < 2; ++d)
    {
        if (periodic_[d])
        {
            names.append(word(axisNames[d]));
        }
    }
    return names;
}


Foam::SPH::domain Foam::SPH::domain::grown(const scalar margin) const
{
    domain g(*this);
    for (direction d = 0; d < 2; ++d)
    {
        if (!periodic_[d])
        {
            g.min_[d] -= margin;
            g.max_[d] += margin;
        }
    }
    return g;
}


Foam::scalar Foam::SPH::domain::gSum(const UList<scalar>& f) const
{
    scalar s = 0;
    for (const scalar v : f)
    {
        s += v;
    }
    return s;
}


Foam::scalar Foam::SPH::domain::gMax(const UList<scalar>& f) const
{
    scalar m = -VGREAT;
    for (const scalar v : f)
    {
        m = (v > m ? v : m);
    }
    return m;
}


Foam::scalar Foam::SPH::domain::gMin(const UList<scalar>& f) const
{
    scalar m = VGREAT;
    for (const scalar v : f)
    {
        m = (v < m ? v : m);
    }
    return m;
}


void Foam::SPH::domain::report(Ostream& os) const
{
    if (anyOpen())
    {
        os  << "Domain: open sides (nothing bounds them; a fluid particle"
            << " beyond one is logged):";
        for (const word& w : openSideNames())
        {
            os  << ' ' << w;
        }
        os  << nl;
    }
    if (!anyPeriodic())
    {
        os  << "Domain: not periodic, box " << min_ << " to " << max_ << nl;
        return;
    }
    os  << "Domain: periodic in";
    for (const word& w : directionNames())
    {
        os  << ' ' << w;
    }
    os  << nl;
    for (direction d = 0; d < 2; ++d)
    {
        os  << "    " << axisNames[d] << ": [" << min_[d] << ", " << max_[d]
            << (periodic_[d] ? "), period " : "], the walls' extent");
        if (periodic_[d])
        {
            os  << period_[d];
        }
        os  << nl;
    }
}


void Foam::SPH::domain::write
(
    const objectRegistry& db,
    const fileName& local
) const
{
    IOobject io(domainIO(db, IOobject::NO_READ, local));
    io.note() =
        "box of the case and its periodic directions, written by sphMesh";
    IOdictionary dict(io);

    // As a user would type it, directions (x); not the list's 1(x)
    OStringStream text;
    text<< "directions (";
    for (const word& w : directionNames())
    {
        text<< ' ' << w;
    }
    text<< " );";
    dict.merge(dictionary(IStringStream(text.str())()));
    dict.add("min", min_);
    dict.add("max", max_);
    if (anyOpen())
    {
        OStringStream sides;
        sides<< "openSides (";
        for (const word& w : openSideNames())
        {
            sides<< ' ' << w;
        }
        sides<< " );";
        dict.merge(dictionary(IStringStream(sides.str())()));
    }

    // A small text file whatever the case's writeFormat
    dict.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
}


// ************************************************************************* //
