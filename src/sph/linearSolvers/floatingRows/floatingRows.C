/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "floatingRows.H"
#include "DynamicList.H"
#include "scalarList.H"

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
    DynamicList<label> front;
    for (label i = 0; i < n; ++i)
    {
        scalar off = 0;
        for (sparseMatrix::InnerIterator it(M, i); it; ++it)
        {
            (it.col() == i ? diag[i] : off) += mag(it.value());
        }
        if (!skip[i] && (anchor[i] || diag[i] > off*(1 + 1e-9)))
        {
            reaches[i] = true;
            front.append(i);
        }
    }

    // From the anchors backwards, to the rows whose equations refer to them
    const sparseMatrix referencedBy(M.transpose());
    while (front.size())
    {
        const label j = front.remove();
        for (sparseMatrix::InnerIterator it(referencedBy, j); it; ++it)
        {
            const label i = it.col();
            if
            (
                !reaches[i] && !skip[i]
             && mag(it.value()) > 1e-10*diag[i]
            )
            {
                reaches[i] = true;
                front.append(i);
            }
        }
    }
    return reaches;
}


// ************************************************************************* //
