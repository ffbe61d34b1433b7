/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fvSource.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(fvSource, 0);
    addToRunTimeSelectionTable(sampleSource, fvSource, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::SPH::fvSource::readField(const word& name) const
{
    if (scalars_.found(name) || vectors_.found(name))
    {
        return true;
    }

    IOobject io
    (
        name,
        runTime_->timeName(),
        *mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (io.typeHeaderOk<volScalarField>(true, true, false))
    {
        scalars_.set(name, new volScalarField(io, *mesh_));
        return true;
    }
    if (io.typeHeaderOk<volVectorField>(true, true, false))
    {
        vectors_.set(name, new volVectorField(io, *mesh_));
        return true;
    }
    return false;
}


Foam::List<Foam::scalarField> Foam::SPH::fvSource::split
(
    const word& field,
    const scalarField& s
) const
{
    return List<scalarField>({scaleFactor(field)*s});
}


Foam::List<Foam::scalarField> Foam::SPH::fvSource::split
(
    const word& field,
    const vectorField& v
) const
{
    const scalar f = scaleFactor(field);
    if (vectors_.found(field))
    {
        return List<scalarField>
        ({
            f*v.component(vector::X),
            f*v.component(vector::Y)
        });
    }
    word base;
    direction cmpt = 0;
    splitComponent(field, base, cmpt);
    return List<scalarField>({f*v.component(cmpt)});
}


Foam::word Foam::SPH::fvSource::baseField(const word& field) const
{
    if (components(field).empty())
    {
        FatalIOErrorInFunction(dict_)
            << "Source " << name_ << ": no volScalarField or volVectorField "
            << field << " in " << runTime_->path()/runTime_->timeName()
            << nl << exit(FatalIOError);
    }
    word base(field);
    direction cmpt;
    if (!scalars_.found(base) && !vectors_.found(base))
    {
        splitComponent(field, base, cmpt);
    }
    return base;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fvSource::fvSource
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
    lastPoints_()
{
    runTime_ = openCase(caseDir_, opts);
    log_ = runLog(*runTime_, caseDir_, "icoFoam");
    readRunTimes(log_, executionTime_, clockTime_);

    mesh_.reset
    (
        new fvMesh
        (
            IOobject
            (
                fvMesh::defaultRegion,
                runTime_->timeName(),
                *runTime_,
                IOobject::MUST_READ
            )
        )
    );
    sampler_.reset
    (
        new fvSampler
        (
            *mesh_,
            dict_.getOrDefault<word>("interpolationScheme", "cellPoint")
        )
    );

    Info<< "    FV case " << caseDir_ << ", time " << runTime_->timeName()
        << ": " << mesh_->nCells() << " cells, " << sampler_->scheme()
        << " interpolation" << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::SPH::fvSource::components(const word& field) const
{
    return resultComponents
    (
        field,
        [this](const word& f) { return readField(f); },
        [this](const word& f) { return vectors_.found(f); }
    );
}


Foam::List<Foam::scalarField> Foam::SPH::fvSource::sample
(
    const word& field,
    const UList<vector2D>& points
) const
{
    // The same points as the last call (the fields of one set)?
    if (lastPoints_.empty() || lastPoints_ != points)
    {
        lastCells_ = sampler_->findCells(points);
        lastPoints_ = points;

        const label nOutside = std::count(lastCells_.begin(), lastCells_.end(), -1);
        if (nOutside)
        {
            Info<< "    " << name_ << ": " << nOutside << " of " << points.size()
                << " points outside the mesh (no value)" << nl;
        }
    }

    const word base(baseField(field));
    if (scalars_.found(base))
    {
        return split(field, sampler_->sample(*scalars_[base], points, lastCells_)());
    }
    return split(field, sampler_->sample(*vectors_[base], points, lastCells_)());
}


void Foam::SPH::fvSource::ownPoints
(
    List<vector2D>& points,
    scalarField& weights
) const
{
    points = sampler_->cellCentres();
    weights = sampler_->cellVolumes();
}


Foam::List<Foam::scalarField> Foam::SPH::fvSource::ownValues
(
    const word& field
) const
{
    const word base(baseField(field));
    if (scalars_.found(base))
    {
        return split(field, scalars_[base]->primitiveField());
    }
    return split(field, vectors_[base]->primitiveField());
}


// ************************************************************************* //
