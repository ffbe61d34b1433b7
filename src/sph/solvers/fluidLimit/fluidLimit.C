/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fluidLimit.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fluidLimit::fluidLimit(const scalar limit)
:
    limit_(limit),
    stepValue_(-1),
    stepTime_(0),
    reached_(-1),
    tReached_(0)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

bool Foam::SPH::fluidLimit::passes(const scalar v, const scalar t) const
{
    stepValue_ = v;
    stepTime_ = t;
    return v <= limit_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::fluidLimit::writeState(Ostream& os) const
{
    os.writeEntry(stateEntry(), Pair<scalar>(reached_, tReached_));
}


void Foam::SPH::fluidLimit::readState(const dictionary& state)
{
    Pair<scalar> reached(-1, 0);
    if (state.readIfPresent(stateEntry(), reached))
    {
        reached_ = reached.first();
        tReached_ = reached.second();
    }
}


void Foam::SPH::fluidLimit::accept()
{
    if (stepValue_ > reached_)
    {
        reached_ = stepValue_;
        tReached_ = stepTime_;
    }
}


// ************************************************************************* //
