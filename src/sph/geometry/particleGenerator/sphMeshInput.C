/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sphMeshInput.H"
#include "IOstreams.H"
#include "OSspecific.H"
#include "IStringStream.H"
#include "OStringStream.H"
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


Foam::SPH::sphMeshDictReader::sphMeshDictReader(const fileName& path)
:
    held_(false)
{
    // A missing file is left to the IOdictionary to report
    if (isFile(path))
    {
        sphMeshInput::checkDuplicates(path);
    }
    std::feholdexcept(&env_);
    held_ = true;
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
    const bool throwing = FatalError.throwExceptions(true);
    const bool ioThrowing = FatalIOError.throwExceptions(true);
    std::string why;
    try
    {
        IStringStream is("#inputMode error " + text.str());
        is.name() = path;
        is.lineNumber() = 1;
        const dictionary dict(is);
    }
    catch (const IOerror& e)
    {
        OStringStream os;
        os  << e.message().c_str() << nl << "file: " << e.ioFileName().c_str();
        if (e.ioStartLineNumber() >= 0)
        {
            os  << " at line " << e.ioStartLineNumber();
        }
        why = os.str();
    }
    catch (const error& e)
    {
        why = e.message() + "\nfile: " + path;
    }
    entry::resetInputMode();
    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(ioThrowing);
    hold.release();

    if (!why.empty())
    {
        FatalErrorInFunction
            << "Cannot read " << path << ":" << nl << why.c_str() << nl
            << exit(FatalError);
    }
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
