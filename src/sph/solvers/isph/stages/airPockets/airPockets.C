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
    labelList lastAir(now_.A0.size(), Zero);
    forAll(cells, k)
    {
        const label o = now_.cells.size() ? now_.cells[k] : -1;
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
    labelList nParents(n, Zero), nChildren(now_.A0.size(), Zero);
    scalarList sharedCells(n, Zero), pShared(n, Zero);
    for (const auto& s : shared)
    {
        const label o = s.first.first;
        const label k = s.first.second;
        ++nParents[k];
        ++nChildren[o];
        sharedCells[k] += s.second;
        pShared[k] += now_.p[o]*s.second;
    }
    scalarList A0(n), area(n);
    List<bool> matched(n, false);
    for (const auto& s : shared)
    {
        const label o = s.first.first;
        const label k = s.first.second;
        if (nParents[k] == 1 && nChildren[o] == 1 && lastAir[o] == s.second)
        {
            A0[k] = now_.A0[o];
            area[k] = now_.area[o];
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
    const scalarList pRead
    (
        now_.pressuresFromFields ? restartPressures() : scalarList()
    );
    now_.pressuresFromFields = false;
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
    now_.A0.transfer(A0);
    now_.area.transfer(area);
    now_.cells = cells;

    now_.p.setSize(n);
    forAll(now_.p, k)
    {
        now_.p[k] = pressure(now_.A0[k], now_.area[k]);
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
        pAir_[i] = pocketOf_[i] >= 0 ? now_.p[pocketOf_[i]] : 0;
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
    implicit_(false)
{
    for (label i = 0; i < work.nFluid; ++i)
    {
        now_.pressuresFromFields =
            now_.pressuresFromFields || pAir_[i] != 0;
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
    forAll(now_.p, k)
    {
        now_.p[k] += dP[k];
        now_.area[k] = max(now_.area[k] + dt*areaRate[k], SMALL*now_.area[k]);
    }
    setSurfaceValues();
}


void Foam::SPH::airPockets::writeState(Ostream& os) const
{
    // The cells as runs (first cell, cells, pocket): a pocket's cells
    // are a few runs of the grid's rows, the grid a million cells
    DynamicList<FixedList<label, 3>> runs;
    const labelList& cells = now_.cells;
    for (label k = 0; k < cells.size(); )
    {
        label end = k + 1;
        while (end < cells.size() && cells[end] == cells[k]) ++end;
        if (cells[k] >= 0)
        {
            runs.append(FixedList<label, 3>({k, end - k, cells[k]}));
        }
        k = end;
    }
    os.beginBlock("airPockets");
    os.writeEntry("A0", now_.A0);
    os.writeEntry("area", now_.area);
    os.writeEntry("p", now_.p);
    os.writeEntry("gridCells", grid_.cellLabels().size());
    os.writeEntry("pocketCells", runs);
    os.endBlock();
}


void Foam::SPH::airPockets::readState(const dictionary& state)
{
    const dictionary* dictPtr = state.findDict("airPockets");
    if (!dictPtr) return;
    const dictionary& dict = *dictPtr;
    tracking read;
    read.A0 = dict.get<scalarList>("A0");
    read.area = dict.get<scalarList>("area");
    read.p = dict.get<scalarList>("p");
    const label nPockets = read.A0.size();
    const label nCells = grid_.cellLabels().size();
    if (read.area.size() != nPockets || read.p.size() != nPockets)
    {
        FatalIOErrorInFunction(dict)
            << "airPockets: A0, area and p must have one value per pocket"
            << " (" << nPockets << ", " << read.area.size() << ", "
            << read.p.size() << ")" << exit(FatalIOError);
    }
    if (dict.get<label>("gridCells") != nCells)
    {
        FatalIOErrorInFunction(dict)
            << "airPockets: gridCells " << dict.get<label>("gridCells")
            << ", but this case's grid of dr/2 cells has " << nCells
            << " (dr or the domain changed since the write)"
            << exit(FatalIOError);
    }
    read.cells.setSize(nCells, -1);
    const List<FixedList<label, 3>> runs
    (
        dict.get<List<FixedList<label, 3>>>("pocketCells")
    );
    for (const FixedList<label, 3>& run : runs)
    {
        if
        (
            run[0] < 0 || run[1] < 1 || run[0] + run[1] > nCells
         || run[2] < 0 || run[2] >= nPockets
        )
        {
            FatalIOErrorInFunction(dict)
                << "airPockets: pocketCells entry " << run << " is not"
                << " (first cell, cells, pocket) within " << nCells
                << " cells and " << nPockets << " pockets"
                << exit(FatalIOError);
        }
        SubList<label>(read.cells, run[1], run[0]) = run[2];
    }
    now_ = std::move(read);
}


void Foam::SPH::airPockets::printStep(Ostream& os) const
{
    if (now_.p.empty()) return;
    label largest = 0;
    forAll(now_.p, k)
    {
        if (now_.area[k] > now_.area[largest]) largest = k;
    }
    os  << "Air pockets: " << now_.p.size() << ", the largest "
        << now_.area[largest] << " m^2 about " << grid_.centre(largest)
        << " at p " << now_.p[largest]
        << " Pa (closed at " << now_.A0[largest] << " m^2)" << nl;
}


// ************************************************************************* //
