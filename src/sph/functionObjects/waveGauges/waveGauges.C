/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "waveGauges.H"
#include "shepardInterpolation.H"
#include "Time.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace functionObjects
{
    defineTypeNameAndDebug(waveGauges, 0);
    addToRunTimeSelectionTable(functionObject, waveGauges, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::SPH::functionObjects::waveGauges::depth
(
    const sphCloud& cloud,
    const scalar x
) const
{
    const scalar support = cloud.W().support();
    const scalar threshold = surfaceFraction_*interiorFraction_;

    // Above the highest fluid particle within reach of the line phi is 0:
    // start there, so a droplet far away does not lengthen the scan
    const vector2D* pos = cloud.parts().positions().cdata();
    scalar yTop = -GREAT;
    for (label b = 0; b < cloud.nFluid(); ++b)
    {
        if (mag(pos[b].x() - x) < support)
        {
            yTop = max(yTop, pos[b].y());
        }
    }
    yTop += support;

    if (yTop <= bed_)
    {
        return 0;
    }

    // Scan down in steps of dr/4 to the first sample at or above the
    // threshold; the last sample is the bed itself
    const scalar step = 0.25*cloud.dr();
    const label nSteps = label(std::ceil((yTop - bed_)/step));

    scalar yAbove = yTop;
    scalar phiAbove = shepardInterpolation::fluidFraction(cloud, {x, yTop});

    for (label k = 1; k <= nSteps; ++k)
    {
        const scalar y = max(yTop - k*step, bed_);
        const scalar phi = shepardInterpolation::fluidFraction(cloud, {x, y});

        if (phi >= threshold)
        {
            // phi is linear between the two samples to O(step^2)
            const scalar ys =
                (phiAbove < threshold)
              ? y + (phi - threshold)/(phi - phiAbove)*(yAbove - y)
              : yAbove;
            return ys - bed_;
        }

        yAbove = y;
        phiAbove = phi;
    }

    return 0;
}


void Foam::SPH::functionObjects::waveGauges::writeFileHeader
(
    Ostream& os
) const
{
    writeHeader(os, "Water depth above the bed");
    writeHeaderValue(os, "bed", bed_);
    writeHeader(os, "");
    writeCommented(os, "Time");
    for (const scalar xi : x_)
    {
        writeTabbed(os, "x=" + Foam::name(xi));
    }
    os  << endl;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::waveGauges::measure()
{
    const sphCloud& c = cloud();

    depths_.setSize(x_.size());
    forAll(x_, i)
    {
        depths_[i] = depth(c, x_[i]);
    }
}


void Foam::SPH::functionObjects::waveGauges::writeLog() const
{
    Info<< "    waveGauges " << name() << ": depth";
    forAll(x_, i)
    {
        Info<< (i ? ", " : " ") << depths_[i] << " at x = " << x_[i];
    }
    Info<< endl;
}


void Foam::SPH::functionObjects::waveGauges::writeFiles()
{
    if (!filePtr_.valid())
    {
        filePtr_ = createFile(fileName_);
        writeFileHeader(filePtr_());
    }

    OFstream& os = file();
    writeCurrentTime(os);
    for (const scalar d : depths_)
    {
        os  << tab << d;
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::waveGauges::waveGauges
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    sphFunctionObject(name, runTime, dict, typeName),
    x_(),
    bed_(0),
    surfaceFraction_(0.5),
    interiorFraction_(1),
    depths_()
{
    read(dict);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::SPH::functionObjects::waveGauges::read(const dictionary& dict)
{
    sphFunctionObject::read(dict);

    const sphCloud& c = cloud();

    const scalarList x(dict.get<scalarList>("x"));
    if (x != x_)
    {
        // New columns: a new file (waveGauges_<startTime>.dat if the old
        // one is there) with its own header
        filePtr_.clear();
    }
    x_ = x;

    if (dict.found("bed"))
    {
        bed_ = dict.get<scalar>("bed");
    }
    else if (c.walls().points().size())
    {
        vector2D lo, hi;
        c.walls().bounds(lo, hi);
        bed_ = lo.y();
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": the case has no walls, so"
            << " there is no default bed: give the entry bed (y of the bed)"
            << exit(FatalIOError);
    }

    surfaceFraction_ = dict.lookupOrDefault<scalar>("surfaceFraction", 0.5);
    if (!(surfaceFraction_ > 0 && surfaceFraction_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": surfaceFraction = "
            << surfaceFraction_ << ", expected a fraction of the interior"
            << " fluid fraction in (0, 1)" << exit(FatalIOError);
    }

    interiorFraction_ = shepardInterpolation::latticeFraction(c.W(), c.dr());
    depths_.clear();

    Info<< type() << ' ' << name() << ": gauges at x = " << inParentheses(x_)
        << ", bed y = " << bed_ << (dict.found("bed") ? "" : " (lowest wall)")
        << ", surface at " << surfaceFraction_ << " of the interior fluid"
        << " fraction " << interiorFraction_ << endl;

    return true;
}


// ************************************************************************* //
