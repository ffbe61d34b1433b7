/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wendlandC2.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(wendlandC2, 0);
    addToRunTimeSelectionTable(kernel, wendlandC2, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wendlandC2::wendlandC2(const dictionary& dict, const scalar dr)
:
    // Default h = 2 dr as in 000_8c7cd3aabddcf18a.txt (after eq. (1)); q < 2
    kernel(dict, dr, 2, 2),
    alpha_(7/(4*constant::mathematical::pi*sqr(h()))),
    invH_(1/h()),
    rMax_(support())
{
    Info<< "    alpha 7/(4 pi h^2) = " << alpha_ << endl;
}


// ************************************************************************* //
