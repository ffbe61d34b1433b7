/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "probes.H"
#include "shepardInterpolation.H"
#include "Time.H"
#include "IOmanip.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace functionObjects
{
    defineTypeNameAndDebug(probes, 0);
    addToRunTimeSelectionTable(functionObject, probes, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::probes::checkFields
(
    const dictionary& dict
) const
{
    const particles& parts = cloud().parts();

    for (const word& fieldName : fieldNames_)
    {
        if
        (
            !parts.found<scalar>(fieldName)
         && !parts.found<vector2D>(fieldName)
        )
        {
            FatalIOErrorInFunction(dict)
                << "Function object " << name() << ": no scalar or vector"
                << " particle field " << fieldName << " to probe."
                << nl << "The particle fields are " << parts.names()
                << exit(FatalIOError);
        }
    }
}


Foam::label Foam::SPH::functionObjects::probes::width() const
{
    return writePrecision_ + 7;
}


void Foam::SPH::functionObjects::probes::createFiles()
{
    const fileName dir(outputDir());
    mkDir(dir);

    const label w = width();

    files_.setSize(fieldNames_.size());
    forAll(fieldNames_, fieldi)
    {
        // Overwritten on a rerun, as OpenFOAM's probes (no "_<time>" copy)
        files_.set(fieldi, new OFstream(dir/fieldNames_[fieldi]));
        OFstream& os = files_[fieldi];

        if (!os.good())
        {
            FatalIOErrorInFunction(os)
                << "Cannot open " << os.name() << exit(FatalIOError);
        }
        os.precision(writePrecision_);

        forAll(locations_, i)
        {
            os  << "# Probe " << i << ' ' << locations_[i] << nl;
        }

        os  << '#' << setw(w - 1) << "Probe";
        forAll(locations_, i)
        {
            os  << ' ' << setw(w) << i;
        }
        os  << nl;

        os  << '#' << setw(w - 1) << "Time" << endl;
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::probes::measure()
{
    const sphCloud& c = cloud();
    const particles& parts = c.parts();

    shepardInterpolation interp(c);

    fractions_.setSize(locations_.size());
    for (const word& fieldName : fieldNames_)
    {
        if (parts.found<scalar>(fieldName))
        {
            scalarValues_.set(fieldName, scalarField(locations_.size()));
        }
        else
        {
            vectorValues_.set(fieldName, vector2DField(locations_.size()));
        }
    }

    forAll(locations_, i)
    {
        fractions_[i] = interp.setPoint(locations_[i]);

        for (const word& fieldName : fieldNames_)
        {
            if (parts.found<scalar>(fieldName))
            {
                scalarValues_[fieldName][i] =
                    (
                        hydrostatic_ && fieldName == "p"
                      ? interp.hydrostaticPressure(minFraction_)
                      : interp.interpolate
                        (
                            parts.field<scalar>(fieldName),
                            minFraction_
                        )
                    );
            }
            else
            {
                vectorValues_[fieldName][i] =
                    interp.interpolate
                    (
                        parts.field<vector2D>(fieldName),
                        minFraction_
                    );
            }
        }
    }
}


void Foam::SPH::functionObjects::probes::writeLog() const
{
    label nDry = 0;
    for (const scalar f : fractions_)
    {
        if (!(f > 0 && f >= minFraction_))
        {
            ++nDry;
        }
    }

    Info<< "    probes " << name() << ':';
    if (fieldNames_.size())
    {
        const word& fieldName = fieldNames_.first();
        Info<< ' ' << fieldName << " (";
        forAll(locations_, i)
        {
            Info<< (i ? " " : "");
            if (scalarValues_.found(fieldName))
            {
                Info<< scalarValues_[fieldName][i];
            }
            else
            {
                Info<< vectorValues_[fieldName][i];
            }
        }
        Info<< ')';
    }
    Info<< ", " << nDry << " of " << locations_.size() << " dry" << endl;
}


void Foam::SPH::functionObjects::probes::writeFiles()
{
    if (files_.empty() && fieldNames_.size())
    {
        createFiles();
    }

    const label w = width();
    const scalar t = time_.timeOutputValue();

    forAll(fieldNames_, fieldi)
    {
        const word& fieldName = fieldNames_[fieldi];
        OFstream& os = files_[fieldi];

        os  << setw(w) << t;
        forAll(locations_, i)
        {
            if (scalarValues_.found(fieldName))
            {
                os  << ' ' << setw(w) << scalarValues_[fieldName][i];
            }
            else
            {
                // Written as OpenFOAM writes a 3-D vector, so a script
                // reading FV probes reads these
                const vector2D& v = vectorValues_[fieldName][i];
                os  << ' ' << setw(w) << vector(v.x(), v.y(), 0);
            }
        }
        os  << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::probes::probes
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    sphFunctionObject(name, runTime, dict, typeName),
    fieldNames_(),
    locations_(),
    minFraction_(0.1),
    hydrostatic_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

const Foam::scalarField&
Foam::SPH::functionObjects::probes::scalarValues(const word& fieldName) const
{
    if (!scalarValues_.found(fieldName))
    {
        FatalErrorInFunction
            << "Probes " << name() << ": no scalar field " << fieldName
            << " measured; the scalar fields are " << scalarValues_.sortedToc()
            << exit(FatalError);
    }
    return scalarValues_[fieldName];
}


const Foam::vector2DField&
Foam::SPH::functionObjects::probes::vectorValues(const word& fieldName) const
{
    if (!vectorValues_.found(fieldName))
    {
        FatalErrorInFunction
            << "Probes " << name() << ": no vector field " << fieldName
            << " measured; the vector fields are " << vectorValues_.sortedToc()
            << exit(FatalError);
    }
    return vectorValues_[fieldName];
}


bool Foam::SPH::functionObjects::probes::read(const dictionary& dict)
{
    sphFunctionObject::read(dict);

    const wordList fieldNames(dict.get<wordList>("fields"));
    const List<vector2D> locations(readPoints(dict, "probeLocations"));

    minFraction_ = dict.lookupOrDefault<scalar>("minFluidFraction", 0.1);
    if (!(minFraction_ >= 0 && minFraction_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": minFluidFraction = "
            << minFraction_ << ", expected a fluid fraction in [0, 1)"
            << exit(FatalIOError);
    }
    hydrostatic_ = dict.lookupOrDefault<bool>("hydrostatic", false);

    // New columns need new files (with their header)
    if (fieldNames != fieldNames_ || locations != locations_)
    {
        files_.clear();
    }
    fieldNames_ = fieldNames;
    locations_ = locations;
    scalarValues_.clear();
    vectorValues_.clear();
    fractions_.clear();

    checkFields(dict);

    Info<< type() << ' ' << name() << ": " << locations_.size()
        << " probes of " << inParentheses(fieldNames_) << ", minFluidFraction "
        << minFraction_ << (hydrostatic_ ? ", hydrostatic p" : "") << endl;

    return true;
}


// ************************************************************************* //
