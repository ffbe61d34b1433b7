/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallMotion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wallMotion, 0);
    defineRunTimeSelectionTable(wallMotion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallMotion::wallMotion(const word& name, const dictionary& dict)
:
    name_(name),
    rampTime_(dict.getOrDefault<scalar>("rampTime", 0))
{
    if (!(rampTime_ >= 0))
    {
        FatalIOErrorInFunction(dict.lookup("rampTime"))
            << "Entry rampTime " << rampTime_ << ": expected a time >= 0"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::SPH::wallMotion::ramp(const scalar t) const
{
    if (t <= 0)
    {
        return 0;
    }
    return t < rampTime_ ? t/rampTime_ : 1;
}


Foam::scalar Foam::SPH::wallMotion::rampIntegral(const scalar t) const
{
    if (t <= 0)
    {
        return 0;
    }
    return t < rampTime_ ? 0.5*t*t/rampTime_ : t - 0.5*rampTime_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallMotion::write(Ostream& os) const
{
    if (rampTime_ > 0)
    {
        os  << ", from rest over " << rampTime_ << " s";
    }
}


// ************************************************************************* //
