/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fluidLimit.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fluidLimit::fluidLimit(const scalar limit)
:
    limit_(limit),
    reached_(-1),
    tReached_(0)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

bool Foam::SPH::fluidLimit::passes(const scalar v, const scalar t) const
{
    if (v > limit_)
    {
        return false;
    }
    if (v > reached_)
    {
        reached_ = v;
        tReached_ = t;
    }
    return true;
}


// ************************************************************************* //
