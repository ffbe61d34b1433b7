/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "floatingRows.H"
#include "DynamicList.H"
#include "scalarList.H"
#include "ListOps.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The least share of a row's diagonal that makes an entry a link, and
//- the least excess of the diagonal over the off-diagonal sum that makes
//- the row an anchor (see floatingRows.H)
constexpr scalar minLink = 1e-4;
constexpr scalar minExcess = 1e-4;

//- A significant link: an entry of row i at or above minLink of its diagonal
inline bool links(const scalar value, const scalar diag)
{
    return mag(value) > minLink*diag;
}


//- Does row i (not yet reached) link to a reached row?
inline bool linksToReached
(
    const SPH::sparseMatrix& M,
    const label i,
    const scalarList& diag,
    const boolList& reaches
)
{
    for (SPH::sparseMatrix::InnerIterator it(M, i); it; ++it)
    {
        if (it.col() != i && reaches[it.col()] && links(it.value(), diag[i]))
        {
            return true;
        }
    }
    return false;
}


//- Breadth-first from the reached rows backwards, over the transpose: exact
//- whatever the order of the rows, at the price of building the transpose
void searchBackwards
(
    const SPH::sparseMatrix& M,
    const boolList& skip,
    const scalarList& diag,
    boolList& reaches
)
{
    DynamicList<label> front;
    forAll(reaches, i)
    {
        if (reaches[i]) front.append(i);
    }
    const SPH::sparseMatrix referencedBy(M.transpose());
    while (front.size())
    {
        const label j = front.remove();
        for (SPH::sparseMatrix::InnerIterator it(referencedBy, j); it; ++it)
        {
            const label i = it.col();
            if (!reaches[i] && !skip[i] && links(it.value(), diag[i]))
            {
                reaches[i] = true;
                front.append(i);
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::boolList Foam::SPH::reachesAnAnchor
(
    const sparseMatrix& M,
    const boolList& skip,
    const boolList& anchor
)
{
    const label n = M.rows();
    scalarList diag(n, Zero);
    boolList reaches(n, false);

    // One pass finds the anchors and, rows sorted in space as the
    // particles are, already carries most rows to one through their
    // earlier neighbours
    DynamicList<label> open;
    for (label i = 0; i < n; ++i)
    {
        scalar off = 0;
        for (sparseMatrix::InnerIterator it(M, i); it; ++it)
        {
            (it.col() == i ? diag[i] : off) += mag(it.value());
        }
        if (skip[i]) continue;
        reaches[i] =
            anchor[i] || diag[i] > off*(1 + minExcess)
         || linksToReached(M, i, diag, reaches);
        if (!reaches[i]) open.append(i);
    }

    // The rest in sweeps, backwards then forwards, over the open rows only
    // (building the transpose at every assembly took a tenth of the matrix
    // assembly on the 4 mm obstacle dam-break); a sweep that reaches none
    // leaves the floating rows
    for (label sweep = 0; sweep < 6 && open.size(); ++sweep)
    {
        const bool backwards = sweep % 2 == 0;
        DynamicList<label> stillOpen(open.size());
        forAll(open, k)
        {
            const label i = open[backwards ? open.size() - 1 - k : k];
            reaches[i] = linksToReached(M, i, diag, reaches);
            if (!reaches[i]) stillOpen.append(i);
        }
        if (stillOpen.size() == open.size()) return reaches;
        if (backwards) reverse(stillOpen);
        open.transfer(stillOpen);
    }

    // Rows in an order the sweeps are slow on: the exact search
    if (open.size()) searchBackwards(M, skip, diag, reaches);
    return reaches;
}


// ************************************************************************* //
