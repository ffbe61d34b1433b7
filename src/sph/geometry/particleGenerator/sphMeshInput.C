/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sphMeshInput.H"
#include "IOstreams.H"
#include "IStringStream.H"
#include <cmath>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::sphMeshDictReader::sphMeshDictReader()
:
    held_(true)
{
    std::feholdexcept(&env_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::sphMeshDictReader::release()
{
    if (held_)
    {
        // The flags raised while reading are dropped, the traps restored
        std::feclearexcept(FE_ALL_EXCEPT);
        std::fesetenv(&env_);
        held_ = false;
    }
}


void Foam::SPH::sphMeshInput::checkDuplicates(const fileName& path)
{
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();

    // OpenFOAM's own directive on the first line, which keeps the line
    // numbers; the stream named as the file for the messages and #include
    sphMeshDictReader hold;
    IStringStream is("#inputMode error " + text.str());
    is.name() = path;
    const dictionary dict(is);
    entry::resetInputMode();
}


void Foam::SPH::sphMeshInput::checkNumbers(const dictionary& dict)
{
    for (const entry& e : dict)
    {
        if (e.isDict())
        {
            checkNumbers(e.dict());
            continue;
        }
        ITstream& is = e.stream();
        for (const token& t : is)
        {
            if (!t.isNumber())
            {
                continue;
            }
            const scalar v = t.number();
            if (!std::isfinite(v) || mag(v) > maxMagnitude)
            {
                FatalIOErrorInFunction(is)
                    << "Entry '" << e.keyword() << "' holds the number " << v
                    << "; every number in sphMeshDict"
                    << " must be finite and within +/-" << maxMagnitude
                    << " (lengths in metres, angles in degrees)" << nl
                    << exit(FatalIOError);
            }
        }
    }
}


bool Foam::SPH::sphMeshInput::plainWord(const std::string& name)
{
    if (name.empty() || !(std::isalpha(name[0]) || name[0] == '_'))
    {
        return false;
    }
    for (const char c : name)
    {
        if
        (
            !std::isalnum(static_cast<unsigned char>(c))
         && c != '_' && c != '.' && c != ':' && c != '+' && c != '-'
        )
        {
            return false;
        }
    }
    return true;
}


void Foam::SPH::sphMeshInput::checkName
(
    const entry& e,
    const dictionary& dict,
    const char* what
)
{
    const keyType& key = e.keyword();
    if (key.isPattern() || !plainWord(key))
    {
        FatalIOErrorInFunction(dict)
            << "The " << what << " name \"" << key.c_str() << "\" in "
            << dict.name() << " cannot be written and read back as a name:"
            << " use letters, digits and _ . : + - only, starting with a"
            << " letter or _ (no spaces, quotes, slashes, semicolons,"
            << " braces or brackets)" << nl << exit(FatalIOError);
    }
}


// ************************************************************************* //
