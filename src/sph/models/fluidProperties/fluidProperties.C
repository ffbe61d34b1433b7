/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fluidProperties.H"
#include "IOdictionary.H"
#include "dimensionedScalar.H"
#include "uniformDimensionedFields.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fluidProperties::fluidProperties(const Time& runTime)
{
    const IOdictionary transport
    (
        IOobject
        (
            "transportProperties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    rho0 = dimensionedScalar("rho", dimDensity, transport).value();
    nu = dimensionedScalar("nu", dimViscosity, transport).value();
    if
    (
        !(rho0 > 0) || !(nu >= 0)
     || !std::isfinite(rho0) || !std::isfinite(nu)
    )
    {
        FatalIOErrorInFunction(transport)
            << "Expected rho > 0 and nu >= 0, found rho " << rho0
            << " and nu " << nu << exit(FatalIOError);
    }

    const uniformDimensionedVectorField gField
    (
        IOobject
        (
            "g", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    if (gField.dimensions() != dimAcceleration)
    {
        FatalErrorInFunction
            << "constant/g has dimensions " << gField.dimensions()
            << ", expected " << dimAcceleration << exit(FatalError);
    }
    g = vector2D(gField.value().x(), gField.value().y());
    if (!std::isfinite(g.x()) || !std::isfinite(g.y()))
    {
        FatalErrorInFunction
            << gField.objectPath() << ": value " << gField.value()
            << " is not finite" << exit(FatalError);
    }
}


// ************************************************************************* //
