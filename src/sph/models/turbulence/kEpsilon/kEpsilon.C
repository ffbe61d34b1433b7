/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "kEpsilon.H"
#include "usawOperators.H"
#include "kernelDispatch.H"
#include "initialField.H"
#include "wallConditions.H"
#include "checkedEntry.H"
#include "stage.H"
#include "Time.H"
#include "Switch.H"
#include "Enum.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(kEpsilon, 0);
    addToRunTimeSelectionTable(turbulenceModel, kEpsilon, dictionary);
}
}


namespace
{
    // Eq. (20) of Leroy et al. 2014 (after Guimet & Laurence 2002, as
    // Code_Saturne's k-epsilon LP), or nu_T S^2 alone (OpenFOAM's kEpsilon)
    enum class productionForm { linear, quadratic };
    const Foam::Enum<productionForm> productionNames
    ({
        { productionForm::linear, "linear" },
        { productionForm::quadratic, "quadratic" },
    });
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::kEpsilon::production
(
    const scalar k,
    const scalar nut,
    const tensor2D& gradU,
    const scalar Cmu,
    const bool linear
)
{
    // S = sqrt(2 S:S), S the symmetric part of grad u (21)
    const scalar S2 =
        2*(sqr(gradU.xx()) + sqr(gradU.yy())) + sqr(gradU.xy() + gradU.yx());
    return linear ? min(std::sqrt(Cmu)*k*std::sqrt(S2), nut*S2) : nut*S2;
}


Foam::Pair<Foam::scalar> Foam::SPH::kEpsilon::step
(
    const scalar k,
    const scalar eps,
    const scalar P,
    const scalar Lk,
    const scalar Leps,
    const buoyantSource& G,
    const scalar C1,
    const scalar C2,
    const scalar dt
)
{
    // (13): (k' - k)/dt = P + G - eps k'/k + L_k, G = G_explicit - r k'
    const scalar rate = eps/k;
    const scalar kNew =
        (k + dt*(P + G.explicitPart + Lk))/(1 + dt*(rate + G.implicitRate));

    // (14): (eps' - eps)/dt = eps/k (C1 P + C_eps3 G - C2 eps') + L_eps;
    // C_eps3 = 1 only where G <= 0: -(r k'/k) eps', implicit as the
    // destruction of k (a production has C_eps3 = 0)
    const scalar buoyantRate = G.Ceps3*G.implicitRate*max(kNew, scalar(0))/k;
    const scalar epsNew =
        (eps + dt*(rate*C1*P + Leps))/(1 + dt*(C2*rate + buoyantRate));
    return Pair<scalar>(kNew, epsNew);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::kEpsilon::readInitial(const word& name)
{
    const initialField f(runTime_, name);
    if (!f.found())
    {
        FatalErrorInFunction
            << "RASModel kEpsilon needs the initial " << name << ": no "
            << runTime_.timeName()/name << " with an internalField (the FV"
            << " case's 0/" << name << " serves)" << exit(FatalError);
    }
    SubList<scalar> values(parts_.field<scalar>(name), work_->nFluid);
    f.read(values);
    forAll(values, i)
    {
        if (!(values[i] > 0))
        {
            FatalIOErrorInFunction(f.stream())
                << "internalField of " << f.path() << ": " << name
                << " must be positive, found " << values[i]
                << (values.size() > 1 ? " for fluid particle " : "")
                << (values.size() > 1 ? Foam::name(i) : word())
                << exit(FatalIOError);
        }
    }
}


void Foam::SPH::kEpsilon::updateNut()
{
    const scalarField& k = parts_.field<scalar>("k");
    const scalarField& eps = parts_.field<scalar>("epsilon");
    scalarField& nut = parts_.field<scalar>("nut");
    const label nFluid = work_->nFluid;
    for (label i = 0; i < nFluid; ++i)
    {
        nut[i] = eps[i] > 0 ? Cmu_*k[i]*k[i]/eps[i] : 0;
    }

    // nu_T vanishes at a wall: the wall shear enters through the log law
    // of (22) alone, not again through the vertex pairs of the viscous
    // sum; and in the diffusion of epsilon the vertex pair's coefficient
    // nu_T,a + 0 is then 2 nu_T at mid-distance, the flux that the vertex
    // value (A.7) assumes. Cmu k_v^2/epsilon_v instead (epsilon_v of (29)
    // is several times the first row's) slowed the first rows: k+ and
    // eps+ 20-25 % below FV's there (Re* = 640, dr = 0.1 and 0.05)
    for (label v = nFluid; v < nut.size(); ++v)
    {
        nut[v] = 0;
    }
}


template<class Kernel>
void Foam::SPH::kEpsilon::sources(const Kernel& K)
{
    const turbulenceCoupling& w = *work_;
    const scalarField& k = parts_.field<scalar>("k");
    const scalarField& eps = parts_.field<scalar>("epsilon");
    const scalarField& nut = parts_.field<scalar>("nut");
    const vector2DField& U = parts_.field<vector2D>("U");

    // Eqs. (20)-(21)
    usaw::gradMinus(K, w.nbrs, w.usaw, w.V, U, gradU_);
    for (label i = 0; i < w.nFluid; ++i)
    {
        P_[i] = production(k[i], nut[i], gradU_[i], Cmu_, linearProduction_);
    }

    // Leroy et al. 2015, eqs. (3), (16) and C_eps3 of (1), from G-{T} (8)
    if (buoyancy_.T)
    {
        usaw::gradMinus(K, w.nbrs, w.usaw, w.V, *buoyancy_.T, gradT_);
        for (label i = 0; i < w.nFluid; ++i)
        {
            G_[i] = buoyantProduction
            (
                buoyancy_.beta, Cmu_, buoyancy_.Prt, k[i], eps[i], gradT_[i],
                buoyancy_.g
            );
        }
    }

    // Eqs. (25) and (27), with B = nu + nu_T/sigma
    forAll(Dk_, i)
    {
        Dk_[i] = w.nu + nut[i]/sigmak_;
        Deps_[i] = w.nu + nut[i]/sigmaEps_;
    }
    usaw::laplacian(K, w.nbrs, w.usaw, w.V, Dk_, k, noFlux_, Lk_);
    epsilonDiffusion
    (
        K, w.nbrs, w.usaw, w.V, w.nFluid, Deps_, k, eps, noFlux_, Cmu_,
        sigmaEps_, w.dr, Leps_
    );
}


void Foam::SPH::kEpsilon::advance(const scalar dt)
{
    scalarField& k = parts_.field<scalar>("k");
    scalarField& eps = parts_.field<scalar>("epsilon");
    for (label i = 0; i < work_->nFluid; ++i)
    {
        // (18)-(19); with the buoyant terms (13)-(14)
        const Pair<scalar> next = step
        (
            k[i], eps[i], P_[i], Lk_[i], Leps_[i], G_[i], C1_, C2_, dt
        );
        if (!(next.first() > 0)) nonPositive("k", i, next.first());
        if (!(next.second() > 0)) nonPositive("epsilon", i, next.second());
        k[i] = next.first();
        eps[i] = next.second();
    }
}


void Foam::SPH::kEpsilon::nonPositive
(
    const word& name,
    const label i,
    const scalar value
) const
{
    // The time loop adds the particle's id and position
    throw stageFailure
    (
        "kEpsilon: k and epsilon must stay positive (a smaller time step,"
        " maxCo, or initial k and epsilon closer to the flow): " + name
      + " would be " + Foam::name(value) + " in the step to t = "
      + Foam::name(runTime_.value()) + " for",
        i
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::kEpsilon::kEpsilon
(
    const Time& runTime,
    particles& parts,
    const dictionary& ras
)
:
    turbulenceModel(runTime, parts),
    Cmu_(0.09),
    C1_(1.44),
    C2_(1.92),
    sigmak_(1.0),
    sigmaEps_(1.3),
    linearProduction_(true),
    wallLaw_(0.41, 5.2)
{
    const dictionary& coeffs = ras.subOrEmptyDict("kEpsilonCoeffs");
    Cmu_ = checkedScalar(coeffs, "Cmu", Cmu_, {0, VGREAT, true});
    C1_ = checkedScalar(coeffs, "C1", C1_, {0, VGREAT, true});
    C2_ = checkedScalar(coeffs, "C2", C2_, {0, VGREAT, true});
    sigmak_ = checkedScalar(coeffs, "sigmak", sigmak_, {0, VGREAT, true});
    sigmaEps_ = checkedScalar(coeffs, "sigmaEps", sigmaEps_, {0, VGREAT, true});
    linearProduction_ = productionNames.getOrDefault
    (
        "production", coeffs, productionForm::linear
    ) == productionForm::linear;
    if (ras.getOrDefault<Switch>("printCoeffs", false))
    {
        Info<< "kEpsilonCoeffs { Cmu " << Cmu_ << "; C1 " << C1_ << "; C2 "
            << C2_ << "; sigmak " << sigmak_ << "; sigmaEps " << sigmaEps_
            << "; production " << (linearProduction_ ? "linear" : "quadratic")
            << "; } log law kappa " << wallLaw_.kappa() << ", B "
            << wallLaw_.B() << nl;
    }
    parts_.add<scalar>("k");
    parts_.add<scalar>("epsilon");
    parts_.add<scalar>("nut");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::kEpsilon::connect
(
    const turbulenceCoupling& work,
    const wallMesh& walls,
    bool fresh
)
{
    turbulenceModel::connect(work, walls, fresh);
    if (work.movingWalls)
    {
        FatalErrorInFunction
            << "RASModel kEpsilon with moving walls: the wall functions of"
            << " isphFoam and wcsphFoam are for walls at rest"
            << exit(FatalError);
    }
    for (const word name : {"k", "epsilon", "nut"})
    {
        wallConditions(runTime_, walls, name);
    }

    const label nF = work.nFluid;
    const label n = parts_.size();
    vertexSegments_.setSize(n - nF);
    const List<labelPair>& ends = work.usaw.segmentParticles();
    forAll(ends, s)
    {
        vertexSegments_[ends[s].first() - nF].append(s);
        vertexSegments_[ends[s].second() - nF].append(s);
    }
    P_.setSize(n, Zero);
    Lk_.setSize(n, Zero);
    Leps_.setSize(n, Zero);
    gradU_.setSize(n, Zero);
    Dk_.setSize(n, Zero);
    Deps_.setSize(n, Zero);
    noFlux_.setSize(ends.size(), Zero);
    // No buoyant terms until connectBuoyancy: G = 0, C_eps3 irrelevant
    G_.setSize(n, buoyantSource{0, 0, 0, 0});

    // A restart keeps the nu_T it wrote: the step's viscous term takes
    // nu_T of the k and epsilon before the last correct(), so that one
    // of the written k and epsilon would not go on as the run that wrote
    // them did
    if (fresh)
    {
        readInitial("k");
        readInitial("epsilon");
        updateNut();
    }
}


const Foam::scalarField* Foam::SPH::kEpsilon::nut() const
{
    return &parts_.field<scalar>("nut");
}


void Foam::SPH::kEpsilon::connectBuoyancy(const buoyantTurbulence& terms)
{
    buoyancy_ = terms;
    gradT_.setSize(parts_.size(), Zero);
    Info<< "kEpsilon: buoyant production G = beta nu_T/Prt grad T . g"
        << " (Leroy et al. 2015, eqs. (3), (16)), beta " << terms.beta
        << ", Prt " << terms.Prt << ", g " << terms.g << nl;
}


Foam::scalar Foam::SPH::kEpsilon::maxNut() const
{
    const scalarField& nut = parts_.field<scalar>("nut");
    scalar m = 0;
    for (label i = 0; i < work_->nFluid; ++i)
    {
        m = max(m, nut[i]);
    }
    return m;
}


void Foam::SPH::kEpsilon::correct(const scalar dt)
{
    dispatch(work_->W, [&](const auto& K)
    {
        vertexValues
        (
            K, work_->nbrs, work_->usaw, work_->V, work_->nFluid,
            vertexSegments_, Cmu_, wallLaw_.kappa(), work_->dr,
            parts_.field<scalar>("k"), parts_.field<scalar>("epsilon")
        );
        updateNut();
        sources(K);
    });
    advance(dt);
}


Foam::string Foam::SPH::kEpsilon::description() const
{
    return
        "k-epsilon, eqs. (18)-(21), (25)-(29); nu_T (14) in the viscous term"
        " (22) with the log law (23), kappa " + Foam::name(wallLaw_.kappa())
      + ", B " + Foam::name(wallLaw_.B())
      + (buoyancy_.T ? "; buoyant G (Leroy et al. 2015, (13)-(16))" : "");
}


// ************************************************************************* //
