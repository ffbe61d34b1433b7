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
    work.motion.moveVertexParticles
    (
        t, work.nFluid, setVelocity, work.parts.positions(),
        work.parts.field<vector2D>("U"), work.wallX, work.wallU, work.usaw
    );
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
