/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "renormalisation.H"
#include "usawOperators.H"
#include "kernelDispatch.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::renormalisation::execute(const scalar dt)
{
    isphWork& w = work_;
    dispatch(w.W, [&](const auto& K)
    {
        usaw::renormalisation
        (
            K, w.nbrs, w.usaw, w.V, w.parts.positions(), minMomentDet, w.R
        );
    });
}


// ************************************************************************* //
