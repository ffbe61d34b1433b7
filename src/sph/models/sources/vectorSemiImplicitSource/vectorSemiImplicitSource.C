/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "vectorSemiImplicitSource.H"
#include "Tuple2.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(vectorSemiImplicitSource, 0);
    addToRunTimeSelectionTable(bodyForce, vectorSemiImplicitSource, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::vectorSemiImplicitSource::vectorSemiImplicitSource
(
    const word& name,
    const dictionary& dict,
    const Time& runTime
)
:
    bodyForce(name, dict, runTime),
    Su_(Zero)
{
    const word mode(coeffs_.get<word>("volumeMode"));
    if (mode != "specific")
    {
        FatalIOErrorInFunction(coeffs_)
            << "fvOption " << name << ": volumeMode " << mode
            << ": expected specific (Su per unit volume of the U equation,"
            << " an acceleration; particles have no cell volume to divide by)"
            << exit(FatalIOError);
    }
    const dictionary& rates = coeffs_.subDict("injectionRateSuSp");
    const Tuple2<vector, scalar> SuSp(rates.get<Tuple2<vector, scalar>>("U"));
    if (SuSp.second() != 0 || SuSp.first().z() != 0)
    {
        FatalIOErrorInFunction(rates)
            << "fvOption " << name << ": U " << SuSp << ": expected"
            << " ((Sux Suy 0) 0): a body force in the plane, without the"
            << " implicit part Sp" << exit(FatalIOError);
    }
    Su_ = vector2D(SuSp.first().x(), SuSp.first().y());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::vectorSemiImplicitSource::describe(Ostream& os) const
{
    os  << name_.c_str() << ": constant force " << Su_ << " m/s^2"
        << " (vectorSemiImplicitSource)";
}


// ************************************************************************* //
