/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sphSource.H"
#include "IOdictionary.H"
#include "scalarIOField.H"
#include "vector2DIOField.H"
#include "labelIOField.H"
#include "particles.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(sphSource, 0);
    addToRunTimeSelectionTable(sampleSource, sphSource, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::SPH::sphSource::fieldIO(const word& name) const
{
    return IOobject
    (
        name,
        runTime_->timeName(),
        local_,
        *runTime_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
}


Foam::word Foam::SPH::sphSource::fieldClass(const word& name) const
{
    IOobject io(fieldIO(name));
    if (io.typeHeaderOk<vector2DIOField>(true, true, false))
    {
        return vector2DIOField::typeName;
    }
    if (io.typeHeaderOk<scalarIOField>(true, true, false))
    {
        return scalarIOField::typeName;
    }
    if (io.typeHeaderOk<labelIOField>(true, true, false))
    {
        return labelIOField::typeName;
    }
    return word::null;
}


bool Foam::SPH::sphSource::readField(const word& name) const
{
    if (scalars_.found(name) || vectors_.found(name))
    {
        return true;
    }

    const word cls(fieldClass(name));
    label n = -1;
    if (cls == vector2DIOField::typeName)
    {
        vector2DIOField f(fieldIO(name));
        n = f.size();
        vectors_.set(name, new vector2DField(std::move(f)));
    }
    else if (cls == scalarIOField::typeName)
    {
        scalarIOField f(fieldIO(name));
        n = f.size();
        scalars_.set(name, new scalarField(std::move(f)));
    }
    else if (cls == labelIOField::typeName)
    {
        labelIOField f(fieldIO(name));
        n = f.size();
        scalarField* s = new scalarField(f.size());
        forAll(f, i) (*s)[i] = f[i];
        scalars_.set(name, s);
    }
    else
    {
        return false;
    }

    if (n != positions_.size())
    {
        FatalIOErrorInFunction(dict_)
            << "Particle field " << fieldIO(name).objectPath() << " holds "
            << n << " values but there are " << positions_.size()
            << " particles" << nl << exit(FatalIOError);
    }
    return true;
}


void Foam::SPH::sphSource::readParticles(const dictionary& dict)
{
    IOobject posIO(fieldIO("positions"));
    if (!posIO.typeHeaderOk<vector2DIOField>(true, true, false))
    {
        FatalIOErrorInFunction(dict_)
            << "Source " << name_ << ": no particle positions "
            << posIO.objectPath() << nl
            << "(an SPH case holds its particles in <time>/"
            << particles::defaultLocal << " after its run)" << nl
            << exit(FatalIOError);
    }
    positions_ = vector2DIOField(posIO);

    // Particles taking part: those of the listed types
    const labelList types
    (
        dict.getOrDefault<labelList>("particleTypes", labelList({0, 1}))
    );
    used_.clear();
    if (readField("type"))
    {
        const scalarField& type = *scalars_["type"];
        DynamicList<label> used;
        forAll(type, i)
        {
            if (types.found(label(type[i])))
            {
                used.append(i);
            }
        }
        used_.transfer(used);
    }
    else
    {
        used_ = identity(positions_.size());
    }
    if (used_.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "Source " << name_ << ": none of the " << positions_.size()
            << " particles in " << runTime_->path()/runTime_->timeName()/local_
            << " has a type in particleTypes " << types << nl
            << exit(FatalIOError);
    }

    // Volumes m/rho, or 1/rho: a uniform factor cancels out
    volumes_ = scalarField(positions_.size(), 1.0);
    if (readField("rho"))
    {
        volumes_ /= *scalars_["rho"];
    }
    if (readField("mass"))
    {
        volumes_ *= *scalars_["mass"];
    }
}


void Foam::SPH::sphSource::makeInterpolation()
{
    // Kernel: the source's own entries, else the case's sphSchemes; the
    // spacing: the source's dr, else the case's sphMeshDict
    scalar dr = 0;
    if (!dict_.readIfPresent("dr", dr))
    {
        IOdictionary meshDict
        (
            IOobject
            (
                "sphMeshDict",
                runTime_->system(),
                *runTime_,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        dr = meshDict.get<scalar>("dr");
    }

    if (dict_.found("kernel"))
    {
        kernel_ = kernel::New(dict_, dr);
    }
    else
    {
        IOdictionary schemes
        (
            IOobject
            (
                "sphSchemes",
                runTime_->system(),
                *runTime_,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        if (dict_.found("hByDr"))
        {
            // The case's kernel at the source's smoothing length (errors
            // in hByDr name the source's entry)
            dictionary kernelDict(dict_);
            kernelDict.add("kernel", schemes.get<word>("kernel"));
            kernel_ = kernel::New(kernelDict, dr);
        }
        else
        {
            kernel_ = kernel::New(schemes, dr);
        }
    }

    const label order = dict_.getOrDefault<label>("interpolationOrder", 2);
    if (order != 1 && order != 2)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'interpolationOrder' is " << order << "; expected 1"
            << " (MLS-linear) or 2 (MLS-quadratic)" << nl << exit(FatalIOError);
    }
    interp_.reset
    (
        new mlsInterpolation(positions_, volumes_, used_, *kernel_, order)
    );
}


Foam::List<Foam::scalarField> Foam::SPH::sphSource::particleValues
(
    const word& field
) const
{
    word base;
    direction cmpt;
    const scalar s = scaleFactor(field);

    if (readField(field))
    {
        if (vectors_.found(field))
        {
            const vector2DField& f = *vectors_[field];
            return List<scalarField>({s*f.component(vector2D::X), s*f.component(vector2D::Y)});
        }
        return List<scalarField>({s*(*scalars_[field])});
    }
    if (splitComponent(field, base, cmpt) && readField(base) && vectors_.found(base))
    {
        return List<scalarField>({s*vectors_[base]->component(cmpt)});
    }

    FatalIOErrorInFunction(dict_)
        << "Source " << name_ << ": no particle field " << field << " in "
        << runTime_->path()/runTime_->timeName()/local_ << nl
        << exit(FatalIOError);
    return List<scalarField>();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::sphSource::sphSource
(
    const word& name,
    const dictionary& dict,
    const options& opts
)
:
    sampleSource(name, dict),
    caseDir_(readPath("case", opts.baseDir, ".")),
    executionTime_(-1),
    clockTime_(-1),
    local_(particles::defaultLocal),
    lastPoints_()
{
    runTime_ = openCase(caseDir_, opts);
    log_ = runLog(*runTime_, caseDir_, "isphFoam");
    readRunTimes(log_, executionTime_, clockTime_);

    readParticles(dict_);
    makeInterpolation();

    Info<< "    SPH case " << caseDir_ << ", time " << runTime_->timeName()
        << ": " << positions_.size() << " particles, " << used_.size()
        << " taking part; MLS interpolation of order " << interp_->order()
        << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::SPH::sphSource::components(const word& field) const
{
    return resultComponents
    (
        field,
        [this](const word& f) { return readField(f); },
        [this](const word& f) { return vectors_.found(f); }
    );
}


Foam::List<Foam::scalarField> Foam::SPH::sphSource::sample
(
    const word& field,
    const UList<vector2D>& points
) const
{
    // The same points as the last call (the fields of one set)?
    if (lastPoints_.empty() || lastPoints_ != points)
    {
        lastStencils_ = interp_->weights(points);
        lastPoints_ = points;

        typedef mlsInterpolation::pointStatus status;
        const label nLinear =
            interp_->order() == 2 ? lastStencils_.count(status::linear) : 0;
        const label nConstant = lastStencils_.count(status::constant);
        const label nNone = lastStencils_.count(status::none);
        if (nLinear || nConstant || nNone)
        {
            Info<< "    " << name_ << ": of " << points.size() << " points, "
                << nLinear << " with a linear fit (too few particles for the"
                << " quadratic), " << nConstant << " with a Shepard average"
                << " (too few for the linear), " << nNone << " with no"
                << " particle within reach (no value)" << nl;
        }
    }

    List<scalarField> values(particleValues(field));
    forAll(values, c)
    {
        values[c] = mlsInterpolation::interpolate<scalar>(lastStencils_, values[c]);
    }
    return values;
}


void Foam::SPH::sphSource::ownPoints
(
    List<vector2D>& points,
    scalarField& weights
) const
{
    points = UIndirectList<vector2D>(positions_, used_)();
    weights = scalarField(volumes_, used_);
}


Foam::List<Foam::scalarField> Foam::SPH::sphSource::ownValues
(
    const word& field
) const
{
    List<scalarField> values(particleValues(field));
    forAll(values, c)
    {
        values[c] = scalarField(values[c], used_);
    }
    return values;
}


// ************************************************************************* //
