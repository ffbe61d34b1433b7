/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "speedLimit.H"
#include "checkedEntry.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::speedLimit::speedLimit(const dictionary& schemes)
:
    fluidLimit
    (
        schemes.found("maxSpeed")
      ? checkedScalar
        (
            schemes, "maxSpeed", {0, VGREAT, true},
            "in m/s: the largest speed of a fluid particle"
        )
      : VGREAT
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::SPH::speedLimit::describe() const
{
    if (limit_ == VGREAT) return string();
    return
        "a fluid particle faster than maxSpeed " + Foam::name(limit_)
      + " m/s";
}


Foam::label Foam::SPH::speedLimit::find
(
    const sphCloud& cloud,
    const List<vector2D>& start,
    const Time& runTime,
    string& what
) const
{
    const vector2D* U = cloud.parts().field<vector2D>("U").cdata();
    scalar max2 = 0;
    const label iMax = largest
    (
        cloud.nFluid(), [&](const label i) { return magSqr(U[i]); }, max2
    );
    const scalar speed = iMax < 0 ? -1 : std::sqrt(max2);
    if (passes(speed, runTime.value())) return -1;

    what =
        "Speed " + Foam::name(speed) + " m/s, more than maxSpeed "
      + Foam::name(limit_) + " m/s (system/sphSchemes): the flow"
        " has left what the case models:";
    return iMax;
}


void Foam::SPH::speedLimit::printSummary(Ostream& os) const
{
    if (reached_ < 0) return;
    os  << "Largest fluid speed: " << reached_ << " m/s (t = " << tReached_
        << " s)";
    if (limit_ < VGREAT)
    {
        os  << ", maxSpeed " << limit_ << " m/s";
    }
    os  << nl;
}


// ************************************************************************* //
