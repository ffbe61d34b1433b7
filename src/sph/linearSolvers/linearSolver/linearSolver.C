/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "linearSolver.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(linearSolver, 0);
    defineRunTimeSelectionTable(linearSolver, dictionary);
}
}

const Foam::Enum<Foam::SPH::linearSolver::preconditionerType>
Foam::SPH::linearSolver::preconditionerTypeNames
({
    { preconditionerType::none, "none" },
    { preconditionerType::diagonal, "diagonal" },
    { preconditionerType::ILU0, "ILU0" },
    { preconditionerType::ILUT, "ILUT" },
    { preconditionerType::BoomerAMG, "BoomerAMG" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::linearSolver::linearSolver
(
    const word& fieldName,
    const dictionary& dict
)
:
    fieldName_(fieldName),
    dictName_(dict.name()),
    preconditioner_(preconditionerTypeNames.get("preconditioner", dict)),
    tolerance_(dict.get<scalar>("tolerance")),
    relTol_(dict.getOrDefault<scalar>("relTol", 0)),
    maxIter_(dict.getOrDefault<label>("maxIter", 1000)),
    dropTolerance_(dict.getOrDefault<scalar>("dropTolerance", 1e-4)),
    fillFactor_(dict.getOrDefault<label>("fillFactor", 10)),
    amgControls_(),
    amgHierarchy_()
{
    // Each entry's own stream: the error names its line
    if (!(tolerance_ > 0))
    {
        FatalIOErrorInFunction(dict.lookup("tolerance"))
            << "Entry tolerance " << tolerance_
            << ": expected the residual to reach, > 0" << exit(FatalIOError);
    }
    if (!(relTol_ >= 0 && relTol_ < 1))
    {
        FatalIOErrorInFunction(dict.lookup("relTol"))
            << "Entry relTol " << relTol_ << ": expected 0 <= relTol < 1"
            << exit(FatalIOError);
    }
    if (maxIter_ < 1)
    {
        FatalIOErrorInFunction(dict.lookup("maxIter"))
            << "Entry maxIter " << maxIter_ << ": expected >= 1"
            << exit(FatalIOError);
    }
    if (preconditioner_ == preconditionerType::ILUT)
    {
        if (!(dropTolerance_ >= 0))
        {
            FatalIOErrorInFunction(dict.lookup("dropTolerance"))
                << "Entry dropTolerance " << dropTolerance_
                << ": expected >= 0" << exit(FatalIOError);
        }
        if (fillFactor_ < 1)
        {
            FatalIOErrorInFunction(dict.lookup("fillFactor"))
                << "Entry fillFactor " << fillFactor_ << ": expected >= 1"
                << exit(FatalIOError);
        }
    }
    if (preconditioner_ == preconditionerType::BoomerAMG)
    {
        amgControls_ = BoomerAMG::controls(dict);
        amgHierarchy_ = std::make_shared<BoomerAMG::hierarchy>();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::linearSolver::write(Ostream& os) const
{
    os  << type() << " for " << fieldName_ << ", preconditioner "
        << preconditionerTypeNames[preconditioner_];
    if (preconditioner_ == preconditionerType::ILUT)
    {
        os  << " (dropTolerance " << dropTolerance_ << ", fillFactor "
            << fillFactor_ << ")";
    }
    if (preconditioner_ == preconditionerType::BoomerAMG)
    {
        os  << ": ";
        amgControls_.write(os);
    }
    os  << ", tolerance " << tolerance_ << ", relTol " << relTol_
        << ", maxIter " << maxIter_;
}


void Foam::SPH::linearSolver::expirePreconditioner() const
{
    if (amgHierarchy_)
    {
        amgHierarchy_->expire();
    }
}


Foam::label Foam::SPH::linearSolver::nPreconditionerBuilds() const
{
    return amgHierarchy_ ? amgHierarchy_->nBuilds() : 0;
}


Foam::scalar Foam::SPH::linearSolver::preconditionerEntriesKept() const
{
    return amgHierarchy_ ? amgHierarchy_->keptFraction() : 1;
}


// ************************************************************************* //
