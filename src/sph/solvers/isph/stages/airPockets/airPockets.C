/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "airPockets.H"
#include "checkedEntry.H"
#include "IOdictionary.H"
#include "Time.H"
#include <map>

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


Foam::scalar Foam::SPH::airPockets::pressure
(
    const scalar A0,
    const scalar A
) const
{
    return pAtm_*(std::pow(A0/A, gamma_) - 1);
}


Foam::scalar Foam::SPH::airPockets::closedArea
(
    const scalar A,
    const scalar p
) const
{
    return A*std::pow(max(1 + p/pAtm_, SMALL), 1/gamma_);
}


void Foam::SPH::airPockets::trackPockets()
{
    // Cells each last pocket shares with each new one, and with any air
    const labelList& cells = grid_.cellLabels();
    std::map<std::pair<label, label>, label> shared;
    labelList lastAir(A0_.size(), Zero);
    forAll(cells, k)
    {
        const label o = lastCells_.size() ? lastCells_[k] : -1;
        if (o < 0 || cells[k] == airPocketGrid::water) continue;
        if (cells[k] == airPocketGrid::solid) continue;
        ++lastAir[o];
        if (cells[k] >= 0) ++shared[{o, cells[k]}];
    }

    // A pocket that is one last pocket (its only part) goes on with its
    // A0 and area; one that merged, split or took part of one, with its
    // parts' pressure (weighted by the cells it took from each) and the
    // grid's area: shares of A0 would make its pressure jump
    const label n = grid_.size();
    labelList nParents(n, Zero), nChildren(A0_.size(), Zero);
    scalarList sharedCells(n, Zero), pShared(n, Zero);
    for (const auto& s : shared)
    {
        const label o = s.first.first;
        const label k = s.first.second;
        ++nParents[k];
        ++nChildren[o];
        sharedCells[k] += s.second;
        pShared[k] += p_[o]*s.second;
    }
    scalarList A0(n), area(n);
    List<bool> matched(n, false);
    for (const auto& s : shared)
    {
        const label o = s.first.first;
        const label k = s.first.second;
        if (nParents[k] == 1 && nChildren[o] == 1 && lastAir[o] == s.second)
        {
            A0[k] = A0_[o];
            area[k] = area_[o];
            if (implicit_)
            {
                area[k] += relaxPerStep*(grid_.area(k) - area[k]);
            }
            else
            {
                area[k] = grid_.area(k);
            }
            matched[k] = true;
        }
    }
    // The first step of a restart: the pressures written
    const scalarList pRead(fromRestart_ ? restartPressures() : scalarList());
    fromRestart_ = false;
    for (label k = 0; k < n; ++k)
    {
        if (matched[k]) continue;
        const scalar p =
            nParents[k] ? pShared[k]/sharedCells[k]
          : pRead.size() ? pRead[k]
          : 0;
        area[k] = grid_.area(k);
        A0[k] = closedArea(area[k], p);
    }
    A0_.transfer(A0);
    area_.transfer(area);
    lastCells_ = cells;

    p_.setSize(n);
    forAll(p_, k)
    {
        p_[k] = pressure(A0_[k], area_[k]);
    }
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
        pAir_[i] = pocketOf_[i] >= 0 ? p_[pocketOf_[i]] : 0;
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
    pAtm_
    (
        checkedScalar
        (
            dict, "pAtm", 101325, {0, VGREAT, true},
            "the air's absolute pressure at p = 0 [Pa]"
        )
    ),
    gamma_
    (
        checkedScalar
        (
            dict, "gamma", 1.4, {1, 5},
            "the exponent of p A^gamma (1.4 adiabatic, 1 isothermal)"
        )
    ),
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
    fromRestart_(false),
    implicit_(false)
{
    for (label i = 0; i < work.nFluid; ++i)
    {
        fromRestart_ = fromRestart_ || pAir_[i] != 0;
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
        << " pAtm " << pAtm_ << " Pa, gamma " << gamma_
        << ", on the free surface it borders (airPockets; beyond 000_...)";
}


void Foam::SPH::airPockets::execute(const scalar dt)
{
    if (movingWalls_) markWalls();
    grid_.find(SubList<vector2D>(work_.parts.positions(), work_.nFluid));
    borderPockets();
    trackPockets();
    setSurfaceValues();
}


void Foam::SPH::airPockets::correct
(
    const scalarUList& dP,
    const scalarUList& areaRate,
    const scalar dt
)
{
    forAll(p_, k)
    {
        p_[k] += dP[k];
        area_[k] = max(area_[k] + dt*areaRate[k], SMALL*area_[k]);
    }
    setSurfaceValues();
}


void Foam::SPH::airPockets::printStep(Ostream& os) const
{
    if (p_.empty()) return;
    label largest = 0;
    forAll(p_, k)
    {
        if (area_[k] > area_[largest]) largest = k;
    }
    os  << "Air pockets: " << p_.size() << ", the largest "
        << area_[largest] << " m^2 about " << grid_.centre(largest)
        << " at p " << p_[largest]
        << " Pa (closed at " << A0_[largest] << " m^2)" << nl;
}


// ************************************************************************* //
