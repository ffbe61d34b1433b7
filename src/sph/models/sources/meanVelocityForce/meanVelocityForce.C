/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "meanVelocityForce.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(meanVelocityForce, 0);
    addToRunTimeSelectionTable(bodyForce, meanVelocityForce, dictionary);
}
}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::SPH::meanVelocityForce::propertiesIO
(
    const word& instance
) const
{
    return IOobject
    (
        name_ + "Properties", instance, "uniform", runTime_,
        IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::meanVelocityForce::meanVelocityForce
(
    const word& name,
    const dictionary& dict,
    const Time& runTime
)
:
    bodyForce(name, dict, runTime),
    flowDir_(Zero),
    Ubar_(0),
    relaxation_(coeffs_.getOrDefault<scalar>("relaxation", 1)),
    gradient_(0),
    lastMean_(-VGREAT),
    mean_(0),
    gradient0_(0),
    lastMean0_(-VGREAT)
{
    const vector Ubar(coeffs_.get<vector>("Ubar"));
    Ubar_ = mag(Ubar);
    if (Ubar.z() != 0 || !(Ubar_ > 0) || !(relaxation_ > 0 && relaxation_ <= 1))
    {
        FatalIOErrorInFunction(coeffs_)
            << "fvOption " << name << ": Ubar " << Ubar << ", relaxation "
            << relaxation_ << ": expected a velocity (Ux Uy 0) that is not"
            << " zero and 0 < relaxation <= 1" << exit(FatalIOError);
    }
    flowDir_ = vector2D(Ubar.x(), Ubar.y())/Ubar_;

    // As OpenFOAM's: the force of the start time, if it was written
    const IOdictionary props(propertiesIO(runTime.timeName()));
    if (props.found("gradient"))
    {
        Info<< "    Reading pressure gradient from file" << nl;
        gradient_ = props.get<scalar>("gradient");
        lastMean_ = props.getOrDefault<scalar>("meanVelocity", -VGREAT);
    }
    Info<< "    Initial pressure gradient = " << gradient_ << nl;

    const fileName dir
    (
        runTime.path()/"postProcessing"/name/runTime.timeName()
    );
    mkDir(dir);
    file_.reset(new OFstream(dir/(name + ".dat")));
    file_->precision(12);
    *file_ << "# meanVelocityForce " << name << ": mean velocity along "
           << flowDir_ << " (uncorrected Ubar) and force per unit mass"
           << " (pressure gradient) of each step" << nl
           << "# Time\tUbar\tgradient" << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector2D Foam::SPH::meanVelocityForce::acceleration
(
    const UList<vector2D>& U,
    const UList<scalar>& V,
    const scalar dt
)
{
    // Eq. (68), the volume-weighted mean (selectionMode all)
    scalar sum = 0, volume = 0;
    forAll(U, i)
    {
        sum += V[i]*(U[i] & flowDir_);
        volume += V[i];
    }
    mean_ = volume > 0 ? sum/volume : 0;

    // Eq. (67); the first step has no v^{n-2}: it takes v^{n-1}
    const scalar before = lastMean_ > -VGREAT ? lastMean_ : mean_;
    gradient_ += relaxation_*(Ubar_ - 2*mean_ + before)/dt;
    lastMean_ = mean_;

    *file_ << runTime_.value() << tab << mean_ << tab << gradient_ << nl;
    return gradient_*flowDir_;
}


void Foam::SPH::meanVelocityForce::describe(Ostream& os) const
{
    os  << name_.c_str() << ": meanVelocityForce, Ubar " << Ubar_*flowDir_
        << ", controller eqs. (67)-(68), relaxation " << relaxation_;
}


void Foam::SPH::meanVelocityForce::write() const
{
    // Seventeen digits: a restart takes the same force
    const fileName dir(runTime_.timePath()/"uniform");
    mkDir(dir);
    OFstream os(dir/(name_ + "Properties"));
    os.precision(17);
    propertiesIO(runTime_.timeName()).writeHeader(os, "dictionary");
    os.writeEntry("gradient", gradient_);
    os.writeEntry("meanVelocity", lastMean_);
    IOobject::writeEndDivider(os);
}


void Foam::SPH::meanVelocityForce::printStep(Ostream& os) const
{
    os  << "Pressure gradient source: uncorrected Ubar = " << mean_
        << ", pressure gradient = " << gradient_ << nl;
}


void Foam::SPH::meanVelocityForce::checkDomain(const domain& dom) const
{
    for (direction d = 0; d < 2; ++d)
    {
        if (!dom.periodic(d) && mag(flowDir_[d]) > SMALL)
        {
            const vector2D U(Ubar_*flowDir_);
            string periodic;
            for (const word& w : dom.directionNames())
            {
                periodic += (periodic.empty() ? "" : " ") + w;
            }
            FatalIOErrorInFunction(coeffs_)
                << "fvOption " << name_ << ": Ubar (" << U.x() << ' '
                << U.y() << " 0) has a component along "
                << domain::axisNames[d] << ", which is not periodic"
                << " (periodic directions (" << periodic.c_str()
                << ") in the periodic entry of system/sphMeshDict): a mean"
                << " velocity can only be held along a period"
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
