/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "turbulenceModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(turbulenceModel, 0);
    defineRunTimeSelectionTable(turbulenceModel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::turbulenceModel::turbulenceModel
(
    const Time& runTime,
    particles& parts
)
:
    runTime_(runTime),
    parts_(parts),
    work_()
{}


// ************************************************************************* //
