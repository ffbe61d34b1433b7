/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "openMPWaitPolicy.H"
#include "openMPThreshold.H"

#include <cstdlib>
#include <unistd.h>
#include <omp.h>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

void Foam::SPH::waitPassivelyByDefault(char* argv[])
{
    if (std::getenv("OMP_WAIT_POLICY") != nullptr)
    {
        return;
    }
    // Set before the attempt, so that the new copy never tries again; taken
    // back if the attempt fails, so that the log does not claim it
    if (::setenv("OMP_WAIT_POLICY", "PASSIVE", 1) == 0)
    {
        ::execv("/proc/self/exe", argv);
        ::unsetenv("OMP_WAIT_POLICY");
    }
}


void Foam::SPH::printOpenMPSettings(Ostream& os)
{
    const char* policy = std::getenv("OMP_WAIT_POLICY");
    os  << "OpenMP: " << omp_get_max_threads()
        << " thread(s) (OMP_NUM_THREADS), wait policy "
        << (policy ? policy : "unset: spin, then sleep")
        << " (OMP_WAIT_POLICY); loops of fewer than "
        << minParticlesPerThread << " particles a thread run on one"
        << nl;
}


// ************************************************************************* //
