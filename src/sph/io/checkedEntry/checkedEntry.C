/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "checkedEntry.H"
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::SPH::numberRange::contains(const scalar x) const
{
    return
        std::isfinite(x)
     && (loOpen ? x > lo : x >= lo)
     && (hiOpen ? x < hi : x <= hi);
}


std::string Foam::SPH::numberRange::describe() const
{
    std::string s;
    if (lo > -VGREAT)
    {
        s += std::string(loOpen ? "> " : ">= ") + Foam::name(lo);
    }
    if (hi < VGREAT)
    {
        s += std::string(s.empty() ? "" : " and ")
          + (hiOpen ? "< " : "<= ") + Foam::name(hi);
    }
    return s;
}


void Foam::SPH::checkNumber
(
    const dictionary& dict,
    const word& key,
    const scalar x,
    const numberRange& range,
    const std::string& note
)
{
    if (range.contains(x))
    {
        return;
    }
    const std::string expected =
        "expected a finite number " + range.describe()
      + (note.empty() ? "" : " (" + note + ")");
    if (dict.found(key))
    {
        FatalIOErrorInFunction(dict.lookup(key))
            << "Entry " << key << " " << x << ": " << expected.c_str()
            << exit(FatalIOError);
    }
    FatalIOErrorInFunction(dict)
        << "Entry " << key << " " << x << " (its default, or computed from"
        << " other entries): " << expected.c_str() << exit(FatalIOError);
}


Foam::scalar Foam::SPH::checkedScalar
(
    const dictionary& dict,
    const word& key,
    const numberRange& range,
    const std::string& note
)
{
    const scalar x = dict.get<scalar>(key);
    checkNumber(dict, key, x, range, note);
    return x;
}


Foam::scalar Foam::SPH::checkedScalar
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const numberRange& range,
    const std::string& note
)
{
    const scalar x = dict.getOrDefault<scalar>(key, deflt);
    checkNumber(dict, key, x, range, note);
    return x;
}


// ************************************************************************* //
