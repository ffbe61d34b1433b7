/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "stepDisplacement.H"
#include "checkedEntry.H"
#include "IOdictionary.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::stepDisplacement::stepDisplacement(const dictionary& schemes)
:
    fluidLimit
    (
        checkedScalar
        (
            schemes, "maxStepDisplacement", 1, {0, VGREAT, true},
            "in h: the largest move of a particle in one step"
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::SPH::stepDisplacement::describe() const
{
    return
        "a fluid particle moving more than maxStepDisplacement "
      + Foam::name(limit_) + " h in a step";
}


Foam::label Foam::SPH::stepDisplacement::find
(
    const sphCloud& cloud,
    const List<vector2D>& start,
    const Time& runTime,
    string& what
) const
{
    const domain& dom = cloud.dom();
    const vector2D* x = cloud.parts().positions().cdata();
    scalar max2 = 0;
    const label iMax = largest
    (
        cloud.nFluid(),
        [&](const label i) { return magSqr(dom.separation(x[i], start[i])); },
        max2
    );
    const scalar h = cloud.W().h();
    const scalar d = iMax < 0 ? -1 : std::sqrt(max2);
    if (passes(d/h, runTime.value())) return -1;

    const scalar dt = runTime.deltaTValue();
    what =
        "Moved " + Foam::name(d/h) + " h (" + Foam::name(d) + " m, a mean"
        " speed of " + Foam::name(d/dt) + " m/s) in one step of "
      + Foam::name(dt) + " s, more than maxStepDisplacement "
      + Foam::name(limit_) + " h (system/sphSchemes): the step is too"
        " long for the flow, or the state is blowing up:";
    return iMax;
}


void Foam::SPH::stepDisplacement::printSummary(Ostream& os) const
{
    if (reached_ < 0) return;
    os  << "Largest move in a step: " << reached_ << " h (t = " << tReached_
        << " s), maxStepDisplacement " << limit_ << " h" << nl;
}


// ************************************************************************* //
