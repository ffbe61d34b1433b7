/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The heat-transfer part of an isphFoam run (a case with a 0/T): the
    model connected to the cloud, T among the shifted fields, and the
    stages of the heat equation and of p_rgh (SPH::heatTransfer).

\*---------------------------------------------------------------------------*/

#include "isph.H"
#include "memberStage.H"
#include "heatEquation.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::isph::connectThermal()
{
    if (!thermal_)
    {
        return;
    }
    isphWork& w = *work_;
    thermal_->connect
    (
        {w.W, w.nbrs, w.usaw, w.V, w.nu, w.nFluid, dr_, w.motion.any()},
        *walls_, fresh_, turbulence_->nut()
    );
    // Leroy et al. 2015, eqs. (3), (16): G in k-epsilon (laminar: nothing)
    turbulence_->connectBuoyancy(thermal_->turbulenceTerms());
    // Leroy et al. 2015 after eq. (18): T corrected by the shift as u
    w.shiftedScalars.append("T");
}


void Foam::SPH::isph::addHeatTransfer()
{
    stages_.add(new heatEquation(*thermal_));
}


void Foam::SPH::isph::addDynamicPressure()
{
    stages_.add
    (
        new memberStage<heatTransfer>
        (
            "dynamicPressure", {"p", "T"}, {"p_rgh"},
            "p_rgh = p - rho (1 - beta (T - TRef)) gh, as"
            " buoyantBoussinesqPimpleFoam", *thermal_,
            &heatTransfer::updatePrgh
        )
    );
}


// ************************************************************************* //
