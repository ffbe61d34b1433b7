/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "moveWalls.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::moveWalls::move
(
    isphWork& work,
    const scalar t,
    const bool setVelocity
)
{
    if (!work.motion.any())
    {
        return;
    }
    work.motion.vertices(t, work.wallX, work.wallU);
    vector2DField& x = work.parts.positions();
    vector2DField& U = work.parts.field<vector2D>("U");
    const label nFluid = work.nFluid;
    forAll(work.wallX, v)
    {
        x[nFluid + v] = work.wallX[v];
        if (setVelocity)
        {
            U[nFluid + v] = work.wallU[v];
        }
    }
    if (work.motion.movesGeometry())
    {
        work.usaw.updateGeometry(work.wallX);
    }
}


void Foam::SPH::moveWalls::describe(Ostream& os) const
{
    if (atEnd_)
    {
        os  << "wall vertices at t^{n+1} with the wall velocity (vertex"
            << " particles carry it, segments the mean of theirs)";
    }
    else
    {
        os  << "wall vertices at t^{n+1/2}" << nl;
        work_.motion.write(os, "                            ");
    }
}


// ************************************************************************* //
