/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "cubicSpline.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(cubicSpline, 0);
    addToRunTimeSelectionTable(kernel, cubicSpline, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::cubicSpline::cubicSpline(const dictionary& dict, const scalar dr)
:
    // Default hByDr 1.3: see the class description; q < 2
    kernel(dict, dr, 1.3, 2),
    sigma_(10/(7*constant::mathematical::pi*sqr(h()))),
    invH_(1/h()),
    rMax_(support())
{
    Info<< "    sigma 10/(7 pi h^2) = " << sigma_ << endl;
}


// ************************************************************************* //
