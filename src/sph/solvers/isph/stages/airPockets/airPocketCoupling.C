/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "airPocketCoupling.H"
#include <Eigen/Dense>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalarList Foam::SPH::airPocketCoupling::areaRates
(
    const UList<vector2D>& gradP,
    const scalar dt,
    const bool pressureOnly
) const
{
    const isphWork& w = work_;
    const labelList& pocketOf = pockets_.pocketOf();
    const scalar dr = w.cloud.dr();
    scalarList rate(pockets_.size(), Zero);
    for (label i = 0; i < w.nFluid; ++i)
    {
        const label k = pocketOf[i];
        if (k < 0) continue;
        const vector2D U
        (
            pressureOnly
          ? -dt*gradP[i]/w.rho0
          : w.Ustar[i] + dt*(w.g - gradP[i]/w.rho0)
        );
        rate[k] -= (U & w.surfaceNormal[i])*dr;
    }
    return rate;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::airPocketCoupling::airPocketCoupling
(
    isphWork& work,
    airPockets& pockets,
    pressurePoisson& pressure,
    const projection::gradientForm form
)
:
    stage("airPocketCoupling", {"p", "pAir", "Ustar"}, {"p", "pAir"}),
    work_(work),
    pockets_(pockets),
    pressure_(pressure),
    form_(form),
    nSolves_(0),
    gradP_(work.parts.size()),
    unit_(work.nFluid)
{
    pockets.makeImplicit();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::airPocketCoupling::describe(Ostream& os) const
{
    os  << "the pockets' pressure implicit: one more solve a pocket, the"
        << " pressure that gives each the area change its air's law asks"
        << " (beyond 000_...)";
}


Eigen::MatrixXd Foam::SPH::airPocketCoupling::responses(const scalar dt)
{
    // Per pocket k facing any particle: phi_k (one solve) and the pockets'
    // dA/dt per unit rise of P_k, G(., k), with its surface value 1 on the
    // rows facing k in the gradient's ghosts
    isphWork& w = work_;
    const labelList& pocketOf = pockets_.pocketOf();
    const label nP = pockets_.size();
    Eigen::MatrixXd G(Eigen::MatrixXd::Zero(nP, nP));
    labelList nFacing(nP, Zero);
    for (const label k : pocketOf)
    {
        if (k >= 0) ++nFacing[k];
    }
    const scalarField* pAir = w.airPressure;
    phi_.resize(max(phi_.size(), nP));
    nSolves_ = 0;
    for (label k = 0; k < nP; ++k)
    {
        if (!phi_.set(k)) phi_.set(k, new scalarField(w.parts.size()));
        if (!nFacing[k])
        {
            phi_[k] = Zero;
            continue;
        }
        pressure_.pocketResponse(pocketOf, k, phi_[k]);
        ++nSolves_;
        forAll(unit_, i)
        {
            unit_[i] = pocketOf[i] == k ? 1 : 0;
        }
        w.airPressure = &unit_;
        projection::pressureGradient(w, form_, phi_[k], gradP_);
        const scalarList rate(areaRates(gradP_, dt, true));
        for (label j = 0; j < nP; ++j)
        {
            G(j, k) = rate[j];
        }
    }
    w.airPressure = pAir;
    return G;
}


void Foam::SPH::airPocketCoupling::execute(const scalar dt)
{
    const label nP = pockets_.size();
    nSolves_ = 0;
    if (nP == 0) return;

    scalarField& p = work_.parts.field<scalar>("p");
    projection::pressureGradient(work_, form_, gradP_);
    const scalarList rate0(areaRates(gradP_, dt, false));
    const Eigen::MatrixXd G(responses(dt));

    // (I - dt P' G) dP = dt P' F0
    Eigen::MatrixXd M(Eigen::MatrixXd::Identity(nP, nP));
    Eigen::VectorXd rhs(nP);
    for (label j = 0; j < nP; ++j)
    {
        const scalar Pj = pockets_.stiffness(j);
        M.row(j) -= dt*Pj*G.row(j);
        rhs(j) = dt*Pj*rate0[j];
    }
    const Eigen::VectorXd dPv(M.partialPivLu().solve(rhs));
    const Eigen::VectorXd rateNew
    (
        Eigen::Map<const Eigen::VectorXd>(rate0.cdata(), nP) + G*dPv
    );

    scalarList dP(nP), areaRate(nP);
    for (label k = 0; k < nP; ++k)
    {
        dP[k] = dPv(k);
        areaRate[k] = rateNew(k);
        if (dP[k] == 0) continue;
        forAll(p, i)
        {
            p[i] += dP[k]*phi_[k][i];
        }
    }
    pockets_.correct(dP, areaRate, dt);
}


void Foam::SPH::airPocketCoupling::printStep(Ostream& os) const
{
    if (nSolves_)
    {
        os  << "Air pocket response solves: " << nSolves_ << nl;
    }
}


// ************************************************************************* //
