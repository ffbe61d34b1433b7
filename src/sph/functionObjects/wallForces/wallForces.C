/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallForces.H"
#include "shepardInterpolation.H"
#include "particles.H"
#include "Time.H"
#include "HashSet.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace functionObjects
{
    defineTypeNameAndDebug(wallForces, 0);
    addToRunTimeSelectionTable(functionObject, wallForces, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::wallForces::selectPatches
(
    const dictionary& dict
)
{
    const wordList& names = cloud().walls().patchNames();

    DynamicList<label> selected(names.size());
    forAll(names, patchi)
    {
        if (patchNames_.match(names[patchi]))
        {
            selected.append(patchi);
        }
    }

    // Each entry must name something: a misspelt patch is an error, not a
    // zero force
    for (const wordRe& key : patchNames_)
    {
        bool matched = false;
        for (const word& n : names)
        {
            matched = matched || key.match(n);
        }
        if (!matched)
        {
            FatalIOErrorInFunction(dict)
                << "Function object " << name() << ": no wall patch "
                << key << ". The wall patches are " << names
                << exit(FatalIOError);
        }
    }

    patches_.transfer(selected);
}


void Foam::SPH::functionObjects::wallForces::writeFileHeader
(
    Ostream& os,
    const word& title
) const
{
    writeHeader(os, title);
    writeHeaderValue(os, "CofR", vector(CofR_.x(), CofR_.y(), 0));
    writeHeader(os, "");
    writeCommented(os, "Time");
    writeTabbed(os, "(total_x total_y total_z)");
    writeTabbed(os, "(pressure_x pressure_y pressure_z)");
    writeTabbed(os, "(viscous_x viscous_y viscous_z)");
    os  << endl;
}


void Foam::SPH::functionObjects::wallForces::writeRow
(
    Ostream& os,
    const vector& pressure,
    const vector& viscous
) const
{
    writeCurrentTime(os);
    os  << tab << (pressure + viscous) << tab << pressure << tab << viscous
        << endl;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::vector2D Foam::SPH::functionObjects::wallForces::vertexNow
(
    const label v,
    const labelUList& type
) const
{
    // USAW walls carry their vertices as particles nFluid + v (laid out in
    // the wall mesh's order, moved by the solvers' moveWalls stage); the
    // walls of the dummy-particle method do not move
    const sphCloud& c = cloud();
    const label i = c.nFluid() + v;
    if (i < type.size() && type[i] == label(particleKind::wallVertex))
    {
        return c.parts().positions()[i];
    }
    return c.walls().points()[v];
}


Foam::vector2D Foam::SPH::functionObjects::wallForces::normalNow
(
    const label s,
    const vector2D& a,
    const vector2D& b
) const
{
    // The normal at t = 0 is +-(the tangent turned by 90 degrees); the same
    // sign on the segment now gives its normal now, times its length
    const wallMesh& walls = cloud().walls();
    const labelPair& ends = walls.segments()[s];
    const vector2D t0
    (
        walls.points()[ends.second()] - walls.points()[ends.first()]
    );
    const vector2D n0 = walls.segmentNormals()[s];
    const scalar side = (-t0.y()*n0.x() + t0.x()*n0.y()) >= 0 ? 1 : -1;
    const vector2D t = b - a;
    return side*vector2D(-t.y(), t.x());
}


void Foam::SPH::functionObjects::wallForces::measure()
{
    measurePressure();
    measureViscous();
}


void Foam::SPH::functionObjects::wallForces::measurePressure()
{
    const sphCloud& c = cloud();
    const wallMesh& walls = c.walls();
    const scalarField& p = c.parts().field<scalar>("p");
    const labelField& type = c.parts().field<label>("type");

    const labelHashSet selected(patches_);

    shepardInterpolation interp(c);

    pressureForce_ = vector2D::zero;
    pressureMoment_ = 0;
    nSegments_ = 0;
    nDry_ = 0;

    forAll(walls.segments(), s)
    {
        if (!selected.found(walls.segmentPatch()[s]))
        {
            continue;
        }
        ++nSegments_;

        // The segment where its ends are now: a wall moved by
        // constant/dynamicMeshDict is not in the wall mesh, which keeps the
        // walls of t = 0, but in the vertex particles
        const labelPair& ends = walls.segments()[s];
        const vector2D a = vertexNow(ends.first(), type);
        const vector2D b = vertexNow(ends.second(), type);
        const vector2D mid(0.5*(a + b));

        interp.setPoint(mid);
        if (!interp.wet(minFraction_))
        {
            ++nDry_;
            continue;
        }

        // USAW: the segment value of eq. (69), the mean of its vertex
        // particles' pressures (which the solvers compute at the wall)
        const scalar pMid =
            vertexPressure_
          ? 0.5*(p[c.nFluid() + ends.first()] + p[c.nFluid() + ends.second()])
          : hydrostatic_
          ? interp.hydrostaticPressure(minFraction_)
          : interp.interpolate(p, minFraction_);

        // The fluid pushes the wall against its inward normal, turned with
        // the segment (rigid motion keeps its length and its side)
        const vector2D dF = -pMid*normalNow(s, a, b);
        const vector2D arm = mid - CofR_;

        pressureForce_ += dF;
        pressureMoment_ += arm.x()*dF.y() - arm.y()*dF.x();
    }
}


void Foam::SPH::functionObjects::wallForces::writeLog() const
{
    Info<< "    wallForces " << name() << ": force " << force()
        << " (pressure " << pressureForce_ << ", viscous " << viscousForce_
        << "), moment " << moment() << " about " << CofR_
        << " (" << nDry_ << " of " << nSegments_ << " segments dry)" << endl;
}


void Foam::SPH::functionObjects::wallForces::writeFiles()
{
    if (!filePtr_.valid())
    {
        filePtr_ = createFile(fileName_);
        writeFileHeader(filePtr_(), "Force");
    }
    if (!momentFilePtr_.valid())
    {
        momentFilePtr_ = createFile("moment");
        writeFileHeader(momentFilePtr_(), "Moment");
    }

    writeRow
    (
        file(),
        vector(pressureForce_.x(), pressureForce_.y(), 0),
        vector(viscousForce_.x(), viscousForce_.y(), 0)
    );
    writeRow
    (
        momentFilePtr_(),
        vector(0, 0, pressureMoment_),
        vector(0, 0, viscousMoment_)
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::wallForces::wallForces
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    sphFunctionObject(name, runTime, dict, "force"),
    patchNames_(),
    patches_(),
    CofR_(vector2D::zero),
    minFraction_(0.1),
    hydrostatic_(false),
    vertexPressure_(false),
    gradScheme_(wallGradientScheme::gamma),
    gradName_("gamma"),
    mu_(0),
    usawPtr_(),
    pressureForce_(vector2D::zero),
    viscousForce_(vector2D::zero),
    pressureMoment_(0),
    viscousMoment_(0),
    nSegments_(0),
    nDry_(0),
    momentFilePtr_()
{
    read(dict);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::SPH::functionObjects::wallForces::read(const dictionary& dict)
{
    sphFunctionObject::read(dict);

    patchNames_ = dict.get<wordRes>("patches");
    selectPatches(dict);

    CofR_ = dict.found("CofR") ? readPoint(dict, "CofR") : vector2D::zero;

    minFraction_ = dict.lookupOrDefault<scalar>("minFluidFraction", 0.1);
    if (!(minFraction_ >= 0 && minFraction_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": minFluidFraction = "
            << minFraction_ << ", expected a fluid fraction in [0, 1)"
            << exit(FatalIOError);
    }
    hydrostatic_ = dict.lookupOrDefault<bool>("hydrostatic", false);
    readViscous(dict);

    wordList selectedNames(patches_.size());
    forAll(patches_, i)
    {
        selectedNames[i] = cloud().walls().patchNames()[patches_[i]];
    }
    Info<< type() << ' ' << name() << ": patches " << inParentheses(selectedNames)
        << ", CofR " << CofR_ << ", minFluidFraction " << minFraction_
        << (hydrostatic_ ? ", hydrostatic pressure" : "") << endl;
    if (usawPtr_.valid())
    {
        Info<< "    wall pressure: "
            << (vertexPressure_ ? "vertex particles" : "Shepard")
            << (vertexPressure_ && hydrostatic_ ? " (hydrostatic: Shepard only)" : "")
            << nl
            << "    viscous force: mu " << mu_ << ", wall velocity gradient "
            << gradName_ << endl;
    }
    else
    {
        Info<< "    viscous force: not computed (the walls have no vertex"
            << " particles)" << endl;
    }

    return true;
}


// ************************************************************************* //
