/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "laminarFlow.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(laminarFlow, 0);
    addToRunTimeSelectionTable(turbulenceModel, laminarFlow, dictionary);
}
}


// ************************************************************************* //
