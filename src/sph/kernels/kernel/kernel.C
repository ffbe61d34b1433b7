/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "kernel.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(kernel, 0);
    defineRunTimeSelectionTable(kernel, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::kernel::readHByDr
(
    const dictionary& dict,
    const scalar dr,
    const scalar deflt
)
{
    // Checked here, before h is formed from them, so that a bad value is
    // reported against the dictionary rather than as a NaN much later
    if (!(dr > 0) || !std::isfinite(dr))
    {
        FatalIOErrorInFunction(dict)
            << "The particle spacing dr = " << dr
            << " given to the kernel must be > 0" << exit(FatalIOError);
    }

    const scalar hByDr = dict.getOrDefault<scalar>("hByDr", deflt);

    // h < dr leaves too few neighbours for any SPH sum to approximate an
    // integral
    // Above 10 a particle would have hundreds of neighbours in 2-D (and a
    // huge value one cell for the whole domain): no SPH scheme uses it
    if (!(hByDr >= 1 && hByDr <= 10))
    {
        // The entry's own stream: the error names its line
        FatalIOErrorInFunction(dict.lookup("hByDr"))
            << "Entry hByDr = " << hByDr
            << ": expected a smoothing length over particle spacing >= 1"
            << " and <= 10"
            << exit(FatalIOError);
    }

    return hByDr;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::kernel::kernel
(
    const dictionary& dict,
    const scalar dr,
    const scalar defaultHByDr,
    const scalar qMax
)
:
    dr_(dr),
    hByDr_(readHByDr(dict, dr, defaultHByDr)),
    h_(hByDr_*dr_),
    qMax_(qMax)
{
    Info<< "    hByDr " << hByDr_
        << (dict.found("hByDr") ? "" : " (default)")
        << ", dr " << dr_ << ", h " << h_
        << ", support " << support() << " (" << qMax_ << " h)" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::kernel::latticeSum() const
{
    const label m = label(support()/dr_) + 1;
    scalar sum = 0;
    for (label i = -m; i <= m; ++i)
    {
        for (label j = -m; j <= m; ++j)
        {
            const scalar r = mag(vector2D(dr_*i, dr_*j));
            if (r < support())
            {
                sum += dr_*dr_*W(r);
            }
        }
    }
    return sum;
}


// ************************************************************************* //
