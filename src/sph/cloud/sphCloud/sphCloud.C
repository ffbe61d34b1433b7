/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "sphCloud.H"
#include "Time.H"

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(sphCloud, 0);
}
}


Foam::SPH::sphCloud::sphCloud
(
    const Time& runTime,
    particles& parts,
    const kernel& W,
    const wallMesh& walls,
    const label nFluid,
    const scalar dr,
    const scalar rho0,
    const vector2D& g,
    const domain& dom
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            runTime.timeName(),
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            true
        )
    ),
    particles_(parts),
    kernel_(W),
    walls_(walls),
    nFluid_(nFluid),
    dr_(dr),
    rho0_(rho0),
    g_(g),
    domain_(dom),
    cells_(dom, W.support())
{
    updateCells();
}


Foam::SPH::domain Foam::SPH::sphCloud::solverDomain
(
    const wallMesh& walls,
    const scalar support
)
{
    vector2D lo, hi;
    walls.bounds(lo, hi);
    const vector2D margin = 0.25*(hi - lo) + vector2D(1, 1)*support;
    lo -= margin;
    hi += margin;

    // A periodic direction has no outside: its box is the period
    const domain& wallsDomain = walls.domain();
    for (direction d = 0; d < 2; ++d)
    {
        if (wallsDomain.periodic(d))
        {
            lo[d] = wallsDomain.min()[d];
            hi[d] = wallsDomain.max()[d];
        }
    }
    return domain(lo, hi, wallsDomain.periodic(), wallsDomain.openSides());
}


void Foam::SPH::sphCloud::updateCells()
{
    cells_.build(particles_.positions());
}


const Foam::labelList& Foam::SPH::sphCloud::sortFluidByCell()
{
    updateCells();
    oldOfNew_.setSize(nFluid_);
    label k = 0;
    for (const label i : cells_.sortedIndex())
    {
        if (i < nFluid_)
        {
            oldOfNew_[k++] = i;
        }
    }
    particles_.reorder(oldOfNew_);
    updateCells();
    return oldOfNew_;
}


Foam::label Foam::SPH::sphCloud::layOut
(
    const Time& runTime,
    particles& parts,
    const UList<vector2D>& wallX,
    const labelUList& wallType,
    const labelUList& wallPatch
)
{
    particles fluid(runTime, runTime.constant(), "sphMesh/fluid", false);
    fluid.read();

    const label nFluid = fluid.size();
    parts.resize(nFluid + wallX.size());
    vector2DField& x = parts.positions();
    labelField& type = parts.field<label>("type");
    labelField& patch = parts.field<label>("patch");
    labelField& id = parts.field<label>("id");
    forAll(fluid.positions(), i)
    {
        x[i] = fluid.positions()[i];
        type[i] = label(particleKind::fluid);
        patch[i] = -1;
    }
    forAll(wallX, w)
    {
        const label i = nFluid + w;
        x[i] = wallX[w];
        type[i] = wallType[w];
        patch[i] = wallPatch[w];
    }
    forAll(id, i)
    {
        id[i] = i;
    }
    return nFluid;
}


Foam::label Foam::SPH::sphCloud::countFluid(const particles& parts)
{
    const labelField& type = parts.field<label>("type");
    label nFluid = 0;
    while (nFluid < type.size() && type[nFluid] == label(particleKind::fluid))
    {
        ++nFluid;
    }
    return nFluid;
}


// ************************************************************************* //
