/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "modifiedGaussian.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(modifiedGaussian, 0);
    addToRunTimeSelectionTable(kernel, modifiedGaussian, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::modifiedGaussian::readK(const dictionary& dict)
{
    const dictionary coeffs(dict.subOrEmptyDict("modifiedGaussianCoeffs"));

    // k = 3 as in 004_f29223b75201dc88.txt (after eq. (5))
    const scalar k = coeffs.getOrDefault<scalar>("k", 3);

    // With k < 1 the support would be shorter than h, hence possibly than
    // one particle spacing: no neighbours at all
    if (!(k >= 1 && k <= 10))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry k = " << k << " in modifiedGaussianCoeffs"
            << ": expected a support radius in units of h >= 1 and <= 10"
            << exit(FatalIOError);
    }

    Info<< "    k " << k
        << (coeffs.found("k") ? "" : " (default)") << endl;

    return k;
}


Foam::scalar Foam::SPH::modifiedGaussian::normIntegral(const scalar k)
{
    // (1 - e^{-k^2})/2 - k^2 e^{-k^2}/2, with expm1 for accuracy at small k
    const scalar k2 = k*k;
    return 0.5*(-std::expm1(-k2) - k2*std::exp(-k2));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::modifiedGaussian::modifiedGaussian
(
    const dictionary& dict,
    const scalar dr
)
:
    // Default h = dr as in 004_f29223b75201dc88.txt (after eq. (5)); q < k
    kernel(dict, dr, 1, readK(dict)),
    c_(1/(2*constant::mathematical::pi*sqr(h())*normIntegral(k()))),
    expMinusK2_(std::exp(-sqr(k()))),
    invH_(1/h()),
    rMax_(support())
{
    Info<< "    I(k) " << normIntegral(k())
        << ", 1/(2 pi h^2 I(k)) = " << c_ << endl;
}


// ************************************************************************* //
