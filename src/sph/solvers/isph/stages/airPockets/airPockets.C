/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "airPockets.H"
#include "checkedEntry.H"
#include "IOdictionary.H"
#include "Time.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::airPockets::markWalls()
{
    const SubList<vector2D> vertices
    (
        work_.parts.positions(),
        work_.cloud.walls().points().size(),
        work_.nFluid
    );
    grid_.setWalls(vertices, work_.cloud.walls().segments());
}


void Foam::SPH::airPockets::borderPockets()
{
    // Each free-surface particle's pocket: the air its outward normal meets
    const vector2DField& x = work_.parts.positions();
    const bool normals = work_.surfaceNormal.size() > 0;
    for (label i = 0; i < work_.nFluid; ++i)
    {
        pocketOf_[i] = -1;
        if (!work_.surface[i] || grid_.size() == 0) continue;
        const vector2D n(normals ? work_.surfaceNormal[i] : vector2D::zero);
        pocketOf_[i] = grid_.borderedPocket(x[i], n);
    }
}


Foam::scalarList Foam::SPH::airPockets::restartPressures() const
{
    scalarList sum(grid_.size(), Zero);
    labelList count(grid_.size(), Zero);
    for (label i = 0; i < work_.nFluid; ++i)
    {
        const label k = pocketOf_[i];
        if (k >= 0 && pAir_[i] != 0)
        {
            sum[k] += pAir_[i];
            ++count[k];
        }
    }
    forAll(sum, k)
    {
        sum[k] /= max(count[k], label(1));
    }
    return sum;
}


void Foam::SPH::airPockets::setSurfaceValues()
{
    for (label i = 0; i < work_.nFluid; ++i)
    {
        pAir_[i] = pocketOf_[i] >= 0 ? tracking_.p()[pocketOf_[i]] : 0;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::airPockets::airPockets
(
    isphWork& work,
    const dictionary& dict,
    const scalar dr,
    const bool movingWalls
)
:
    stage("airPockets", {"positions", "freeSurface"}, {"pAir"}),
    work_(work),
    grid_
    (
        work.cloud.dom(), dr,
        checkedScalar
        (
            dict, "minArea", sqr(4*dr), {0, VGREAT},
            "the least enclosed area [m^2] that is a pocket"
        )
    ),
    movingWalls_(movingWalls),
    pAir_(work.parts.field<scalar>("pAir")),
    pocketOf_(work.nFluid, -1),
    tracking_
    (
        checkedScalar
        (
            dict, "pAtm", 101325, {0, VGREAT, true},
            "the air's absolute pressure at p = 0 [Pa]"
        ),
        checkedScalar
        (
            dict, "gamma", 1.4, {1, 5},
            "the exponent of p A^gamma (1.4 adiabatic, 1 isothermal)"
        )
    ),
    implicit_(false)
{
    // Fields with pocket pressures and no tracking state yet (read after
    // construction) are another run's: new pockets take their pressures
    for (label i = 0; i < work.nFluid; ++i)
    {
        if (pAir_[i] != 0)
        {
            tracking_.takePressuresFromFields();
            break;
        }
    }
    markWalls();
    work.airPressure = &pAir_;
}


Foam::autoPtr<Foam::SPH::airPockets> Foam::SPH::airPockets::New
(
    isphWork& work,
    const Time& runTime,
    const scalar dr,
    const bool freeSurface,
    const bool movingWalls
)
{
    const IOdictionary transport
    (
        IOobject
        (
            "transportProperties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    if (!transport.found("airPockets"))
    {
        return nullptr;
    }
    const dictionary& dict = transport.subDict("airPockets");
    if (!freeSurface)
    {
        FatalIOErrorInFunction(dict)
            << "airPockets in a flow without a free surface: there is no"
            << " air to close off" << exit(FatalIOError);
    }
    const scalar nCells = airPocketGrid::nCells(work.cloud.dom(), dr);
    if (nCells > 5e7)
    {
        FatalIOErrorInFunction(dict)
            << "airPockets: the pockets' grid of dr/2 cells over the domain"
            << " would have " << nCells << " cells (more than 5e7)"
            << exit(FatalIOError);
    }
    work.parts.addIfPresent<scalar>("pAir", 0);
    return autoPtr<airPockets>(new airPockets(work, dict, dr, movingWalls));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::airPockets::describe(Ostream& os) const
{
    os  << "air closed off by the water keeps p = pAtm ((A0/A)^gamma - 1),"
        << " pAtm " << tracking_.pAtm() << " Pa, gamma " << tracking_.gamma()
        << ", on the free surface it borders (airPockets; beyond 000_...)";
}


void Foam::SPH::airPockets::execute(const scalar dt)
{
    if (movingWalls_) markWalls();
    grid_.find(SubList<vector2D>(work_.parts.positions(), work_.nFluid));
    borderPockets();
    tracking_.update
    (
        grid_.cellLabels(),
        grid_.areas(),
        implicit_ ? relaxPerStep : 1,
        tracking_.pressuresFromFields() ? restartPressures() : scalarList()
    );
    setSurfaceValues();
}


void Foam::SPH::airPockets::correct
(
    const scalarUList& dP,
    const scalarUList& areaRate,
    const scalar dt
)
{
    tracking_.correct(dP, areaRate, dt);
    setSurfaceValues();
}


void Foam::SPH::airPockets::writeState(Ostream& os) const
{
    os.beginBlock("airPockets");
    tracking_.write(os, grid_.cellLabels().size());
    os.endBlock();
}


void Foam::SPH::airPockets::readState(const dictionary& state)
{
    const dictionary* dict = state.findDict("airPockets");
    if (dict) tracking_.read(*dict, grid_.cellLabels().size());
}


void Foam::SPH::airPockets::printStep(Ostream& os) const
{
    const scalarList& A = tracking_.area();
    if (A.empty()) return;
    label largest = 0;
    forAll(A, k)
    {
        if (A[k] > A[largest]) largest = k;
    }
    os  << "Air pockets: " << A.size() << ", the largest "
        << A[largest] << " m^2 about " << grid_.centre(largest)
        << " at p " << tracking_.p()[largest]
        << " Pa (closed at " << tracking_.A0()[largest] << " m^2)" << nl;
}


// ************************************************************************* //
