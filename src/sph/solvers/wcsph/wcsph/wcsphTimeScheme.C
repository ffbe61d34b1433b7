/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The choice of wcsphFoam's time integrator, timeScheme in
    system/sphSchemes (RungeKutta4 | symplectic | leapfrog), and its stage
    in the step: the Runge-Kutta update of wcsphRates.C or the symplectic
    ones of wcsphSymplectic.C.

\*---------------------------------------------------------------------------*/

#include "wcsph.H"
#include "memberStage.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::wcsph::timeIntegrator>
Foam::SPH::wcsph::timeIntegratorNames
({
    { timeIntegrator::RungeKutta4, "RungeKutta4" },
    { timeIntegrator::symplectic, "symplectic" },
    { timeIntegrator::leapfrog, "leapfrog" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::string Foam::SPH::wcsph::timeSchemeWords()
{
    std::string words;
    for (const word& w : timeIntegratorNames.names())
    {
        words += (words.empty() ? "" : " | ") + w;
    }
    return words;
}


void Foam::SPH::wcsph::readTimeScheme()
{
    const word scheme =
        schemes_.getOrDefault<word>("timeScheme", "RungeKutta4");
    if (!timeIntegratorNames.found(scheme))
    {
        FatalIOErrorInFunction(schemes_)
            << "Unknown timeScheme '" << scheme << "' in "
            << schemes_.objectPath() << ": expected one of "
            << timeSchemeWords().c_str() << exit(FatalIOError);
    }
    timeScheme_ = timeIntegratorNames[scheme];
}


void Foam::SPH::wcsph::addIntegratorStage(const std::string& rates)
{
    const wordList state({"positions", "U", "rho"});
    if (timeScheme_ == timeIntegrator::RungeKutta4)
    {
        stages_.add
        (
            new memberStage<wcsph>
            (
                "rungeKutta4", state, state,
                "classical Runge-Kutta, eq. (14); at each of its four stages:\n"
              + rates, *this, &wcsph::rungeKutta4, "Runge-Kutta 4"
            )
        );
        return;
    }
    if (wallModel_->movesGeometry())
    {
        FatalIOErrorInFunction(schemes_)
            << "timeScheme " << timeIntegratorNames[timeScheme_] << " in "
            << schemes_.objectPath() << ": walls that move are supported by"
            << " timeScheme RungeKutta4 only (the wall model places them at"
            << " the time of the last rate evaluation)" << exit(FatalIOError);
    }
    const bool symplectic = timeScheme_ == timeIntegrator::symplectic;
    const std::string description =
        std::string
        (
            symplectic
          ? "symplectic predictor-corrector (Monaghan 2005, DualSPHysics):"
            " rates at t^n and t^{n+1/2}, "
          : "leapfrog (position Verlet): the predictor from the last step's"
            " rates, "
        )
      + "density rho^n (2 - eps)/(2 + eps); at each rate evaluation:\n"
      + rates;
    stages_.add
    (
        new memberStage<wcsph>
        (
            symplectic ? "symplectic" : "leapfrog", state, state,
            description, *this,
            symplectic ? &wcsph::symplectic : &wcsph::leapfrog,
            symplectic ? "symplectic" : "leapfrog"
        )
    );
}


// ************************************************************************* //
