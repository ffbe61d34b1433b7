/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "turbulenceModel.H"
#include "IOdictionary.H"
#include "Time.H"
#include "Switch.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::turbulenceModel> Foam::SPH::turbulenceModel::New
(
    const Time& runTime,
    particles& parts
)
{
    IOdictionary props
    (
        IOobject
        (
            "turbulenceProperties", runTime.constant(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    word modelName("laminar");
    dictionary coeffs;
    if (!props.headerOk())
    {
        Info<< "No constant/turbulenceProperties: laminar" << nl;
    }
    else
    {
        const word simulationType(props.get<word>("simulationType"));
        if (simulationType == "RAS")
        {
            const dictionary& ras = props.subDict("RAS");
            if (!ras.getOrDefault<Switch>("turbulence", true))
            {
                Info<< "RAS turbulence off in " << props.name()
                    << ": laminar" << nl;
            }
            else
            {
                modelName = ras.get<word>("RASModel");
                coeffs = ras;
            }
        }
        else if (simulationType != "laminar")
        {
            FatalIOErrorInFunction(props)
                << "simulationType " << simulationType << ": the SPH solvers"
                << " have laminar and RAS (LES is not an SPH model here)"
                << exit(FatalIOError);
        }
    }

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelName);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(props)
            << "Unknown RASModel " << modelName << nl << nl
            << "Valid models:" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }
    return cstrIter()(runTime, parts, coeffs);
}


// ************************************************************************* //
