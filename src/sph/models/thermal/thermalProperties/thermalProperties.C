/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "thermalProperties.H"
#include "IOdictionary.H"
#include "dimensionedScalar.H"
#include "OSspecific.H"
#include <cmath>

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

bool Foam::SPH::thermalProperties::present(const Time& runTime)
{
    return isFile(runTime.path()/"0"/"T");
}


Foam::scalar Foam::SPH::thermalProperties::readDimensioned
(
    const dictionary& dict,
    const word& key,
    const dimensionSet& dims,
    const std::string& meaning
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        FatalIOErrorInFunction(dict)
            << "Missing entry " << key << " (" << meaning.c_str() << "): a"
            << " case with a 0/T needs beta, TRef, Pr and Prt in "
            << dict.name() << ", as buoyantBoussinesqPimpleFoam does, e.g."
            << nl << "    " << key << "    " << dims << " <value>;"
            << exit(FatalIOError);
    }
    // OpenFOAM's dimensioned reading: [name] [dimensions] value. A number
    // must come after the optional name word and dimensions
    const ITstream& is = e->stream();
    label i = 0;
    if (i < is.size() && is[i].isWord()) ++i;
    if (i < is.size() && is[i].isPunctuation() && is[i].pToken() == token::BEGIN_SQR)
    {
        while (i < is.size() && !(is[i].isPunctuation() && is[i].pToken() == token::END_SQR)) ++i;
        ++i;
    }
    if (i >= is.size() || !is[i].isNumber())
    {
        FatalIOErrorInFunction(is)
            << "Entry " << key << " (" << meaning.c_str() << ") of "
            << dict.name() << " is not a number: found '"
            << (is.size() ? is[0] : token()) << "'" << nl
            << "Expected '" << key << " <value>;' or '" << key << " " << dims
            << " <value>;'" << exit(FatalIOError);
    }
    const scalar value = dimensionedScalar(key, dims, dict).value();
    if (!std::isfinite(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " of " << dict.name() << " is " << value
            << ": expected a finite number" << exit(FatalIOError);
    }
    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::thermalProperties::thermalProperties(const dictionary& transport)
:
    beta
    (
        readDimensioned
        (
            transport, "beta", dimless/dimTemperature,
            "thermal expansion coefficient [1/K]"
        )
    ),
    TRef
    (
        readDimensioned
        (
            transport, "TRef", dimTemperature,
            "reference temperature of the Boussinesq force [K]"
        )
    ),
    Pr(readDimensioned(transport, "Pr", dimless, "laminar Prandtl number")),
    Prt(readDimensioned(transport, "Prt", dimless, "turbulent Prandtl number")),
    nu(readDimensioned(transport, "nu", dimViscosity, "kinematic viscosity")),
    K(0)
{
    for (const auto& check : {std::make_pair("Pr", Pr), std::make_pair("Prt", Prt)})
    {
        if (!(check.second > 0))
        {
            FatalIOErrorInFunction(transport)
                << "Entry " << check.first << " of " << transport.name()
                << " is " << check.second << ": expected a Prandtl number > 0"
                << exit(FatalIOError);
        }
    }
    K = nu/Pr;
}


Foam::SPH::thermalProperties::thermalProperties(const Time& runTime)
:
    thermalProperties
    (
        static_cast<const dictionary&>
        (
            IOdictionary
            (
                IOobject
                (
                    "transportProperties", runTime.constant(), runTime,
                    IOobject::MUST_READ, IOobject::NO_WRITE, false
                )
            )
        )
    )
{}


// ************************************************************************* //
