/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "speedLimit.H"
#include "checkedEntry.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::speedLimit::speedLimit(const dictionary& schemes)
:
    maxSpeed_(VGREAT),
    reached_(-1),
    tReached_(0)
{
    if (schemes.found("maxSpeed"))
    {
        maxSpeed_ = checkedScalar
        (
            schemes, "maxSpeed", {0, VGREAT, true},
            "in m/s: the largest speed of a fluid particle"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::SPH::speedLimit::describe() const
{
    if (maxSpeed_ == VGREAT) return string();
    return
        "a fluid particle faster than maxSpeed " + Foam::name(maxSpeed_)
      + " m/s";
}


Foam::label Foam::SPH::speedLimit::find
(
    const sphCloud& cloud,
    const Time& runTime,
    string& what
) const
{
    const vector2D* U = cloud.parts().field<vector2D>("U").cdata();
    label iMax = -1;
    scalar max2 = -1;
    for (label i = 0; i < cloud.nFluid(); ++i)
    {
        const scalar u2 = magSqr(U[i]);
        if (u2 > max2)
        {
            max2 = u2;
            iMax = i;
        }
    }
    if (iMax < 0) return -1;

    const scalar speed = std::sqrt(max2);
    if (speed > maxSpeed_)
    {
        what =
            "Speed " + Foam::name(speed) + " m/s, more than maxSpeed "
          + Foam::name(maxSpeed_) + " m/s (system/sphSchemes): the flow"
            " has left what the case models:";
        return iMax;
    }
    if (speed > reached_)
    {
        reached_ = speed;
        tReached_ = runTime.value();
    }
    return -1;
}


void Foam::SPH::speedLimit::printSummary(Ostream& os) const
{
    if (reached_ < 0) return;
    os  << "Largest fluid speed: " << reached_ << " m/s (t = " << tReached_
        << " s)";
    if (maxSpeed_ < VGREAT)
    {
        os  << ", maxSpeed " << maxSpeed_ << " m/s";
    }
    os  << nl;
}


// ************************************************************************* //
