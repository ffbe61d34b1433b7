/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "stage.H"

#include <cctype>
#include <chrono>
#include <ctime>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- "freeSurface" -> "free surface"
    Foam::string words(const Foam::word& name)
    {
        Foam::string s;
        for (const char c : name)
        {
            if (std::isupper(static_cast<unsigned char>(c)))
            {
                s += ' ';
                s += char(std::tolower(static_cast<unsigned char>(c)));
            }
            else
            {
                s += c;
            }
        }
        return s;
    }
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::stage::stage
(
    const word& name,
    const wordList& reads,
    const wordList& writes,
    const string& title
)
:
    name_(name),
    title_(title.empty() ? words(name) : title),
    reads_(reads),
    writes_(writes),
    seconds_(0),
    calls_(0),
    cpuSeconds_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::stage::processCpuSeconds()
{
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9*t.tv_nsec;
}


void Foam::SPH::stage::run(const scalar dt)
{
    const scalar cpuStart = processCpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    execute(dt);
    seconds_ += std::chrono::duration<scalar>
    (
        std::chrono::steady_clock::now() - start
    ).count();
    cpuSeconds_ += processCpuSeconds() - cpuStart;
    ++calls_;
}


// ************************************************************************* //
