/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "airPocketTracking.H"
#include "airPocketGrid.H"
#include "dictionary.H"
#include "FixedList.H"
#include "DynamicList.H"
#include "SubList.H"
#include <map>
#include <vector>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::airPocketTracking::airPocketTracking
(
    const scalar pAtm,
    const scalar gamma
)
:
    pAtm_(pAtm),
    gamma_(gamma)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::airPocketTracking::pressure
(
    const scalar A0,
    const scalar A
) const
{
    return pAtm_*(std::pow(A0/A, gamma_) - 1);
}


Foam::scalar Foam::SPH::airPocketTracking::closedArea
(
    const scalar A,
    const scalar p
) const
{
    return A*std::pow(max(1 + p/pAtm_, SMALL), 1/gamma_);
}


void Foam::SPH::airPocketTracking::update
(
    const labelUList& cells,
    const scalarUList& gridArea,
    const scalar relax,
    const scalarUList& pNew
)
{
    // The cells each last pocket shares with each new one (the last air at
    // p = 0 as the part freeAir), and each last pocket's cells still air
    const label freeAir = -1;
    std::map<std::pair<label, label>, label> shared;
    labelList lastAir(now_.A0.size(), Zero);
    forAll(cells, k)
    {
        const label o =
            now_.cells.size() ? now_.cells[k] : label(airPocketGrid::water);
        if (cells[k] == airPocketGrid::water) continue;
        if (cells[k] == airPocketGrid::solid) continue;
        if (o >= 0) ++lastAir[o];
        const bool wasFree =
            o == airPocketGrid::atmosphere || o == airPocketGrid::unresolved;
        if (cells[k] >= 0 && (o >= 0 || wasFree))
        {
            ++shared[{o >= 0 ? o : freeAir, cells[k]}];
        }
    }

    const label n = gridArea.size();
    labelList nParts(n, Zero), nChildren(now_.A0.size(), Zero);
    scalarList sharedCells(n, Zero), pShared(n, Zero);
    for (const auto& s : shared)
    {
        const label o = s.first.first;
        const label k = s.first.second;
        ++nParts[k];
        sharedCells[k] += s.second;
        if (o == freeAir) continue;
        ++nChildren[o];
        pShared[k] += now_.p[o]*s.second;
    }

    state next;
    next.A0.setSize(n);
    next.area.setSize(n);
    next.p.setSize(n);
    std::vector<bool> matched(n, false);
    for (const auto& s : shared)
    {
        const label o = s.first.first;
        const label k = s.first.second;
        if (o == freeAir) continue;
        if (nParts[k] == 1 && nChildren[o] == 1 && lastAir[o] == s.second)
        {
            next.A0[k] = now_.A0[o];
            next.area[k] =
                relax < 1
              ? now_.area[o] + relax*(gridArea[k] - now_.area[o])
              : gridArea[k];
            matched[k] = true;
        }
    }
    const bool given = now_.pressuresFromFields && pNew.size() == n;
    for (label k = 0; k < n; ++k)
    {
        if (matched[k]) continue;
        const scalar p =
            nParts[k] ? pShared[k]/sharedCells[k] : given ? pNew[k] : 0;
        next.area[k] = gridArea[k];
        next.A0[k] = closedArea(gridArea[k], p);
    }
    forAll(next.p, k)
    {
        next.p[k] = pressure(next.A0[k], next.area[k]);
    }
    next.cells = cells;
    now_ = std::move(next);
}


void Foam::SPH::airPocketTracking::correct
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
}


void Foam::SPH::airPocketTracking::write
(
    Ostream& os,
    const label nGridCells
) const
{
    // The air cells as runs (first cell, cells, pocket or -2 atmosphere,
    // -1 enclosed air too small to be a pocket): a few runs a row of the
    // grid, where the grid has up to millions of cells; the rest is water
    // or solid, which the tracking does not tell apart
    DynamicList<FixedList<label, 3>> runs;
    const labelList& cells = now_.cells;
    for (label k = 0; k < cells.size(); )
    {
        label end = k + 1;
        while (end < cells.size() && cells[end] == cells[k]) ++end;
        if (cells[k] >= airPocketGrid::atmosphere)
        {
            runs.append(FixedList<label, 3>({k, end - k, cells[k]}));
        }
        k = end;
    }
    os.writeEntry("A0", now_.A0);
    os.writeEntry("area", now_.area);
    os.writeEntry("p", now_.p);
    os.writeEntry("gridCells", nGridCells);
    os.writeEntry("airCells", runs);
}


void Foam::SPH::airPocketTracking::read
(
    const dictionary& dict,
    const label nGridCells
)
{
    state read;
    read.A0 = dict.get<scalarList>("A0");
    read.area = dict.get<scalarList>("area");
    read.p = dict.get<scalarList>("p");
    const label nPockets = read.A0.size();
    if (read.area.size() != nPockets || read.p.size() != nPockets)
    {
        FatalIOErrorInFunction(dict)
            << "airPockets: A0, area and p must have one value per pocket"
            << " (" << nPockets << ", " << read.area.size() << ", "
            << read.p.size() << ")" << exit(FatalIOError);
    }
    const label nCells = dict.get<label>("gridCells");
    if (nCells != nGridCells)
    {
        FatalIOErrorInFunction(dict)
            << "airPockets: gridCells " << nCells << ", but this case's"
            << " grid of dr/2 cells has " << nGridCells
            << " (dr or the domain changed since the write)"
            << exit(FatalIOError);
    }
    read.cells.setSize(nCells, airPocketGrid::water);
    const List<FixedList<label, 3>> runs
    (
        dict.get<List<FixedList<label, 3>>>("airCells")
    );
    for (const FixedList<label, 3>& run : runs)
    {
        if
        (
            run[0] < 0 || run[1] < 1 || run[0] + run[1] > nCells
         || run[2] < airPocketGrid::atmosphere || run[2] >= nPockets
        )
        {
            FatalIOErrorInFunction(dict)
                << "airPockets: airCells entry " << run << " is not"
                << " (first cell, cells, pocket) within " << nCells
                << " cells and " << nPockets << " pockets (-2 atmosphere,"
                << " -1 enclosed air too small to be a pocket)"
                << exit(FatalIOError);
        }
        SubList<label>(read.cells, run[1], run[0]) = run[2];
    }
    now_ = std::move(read);
}


// ************************************************************************* //
