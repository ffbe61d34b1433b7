/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "boundBox2D.H"

// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::SPH::operator<<(Ostream& os, const boundBox2D& bb)
{
    os  << bb.min() << token::SPACE << bb.max();
    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
