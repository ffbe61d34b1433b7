/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fieldDictionary.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fieldDictionary::fieldDictionary(const IOobject& io)
:
    baseIOdictionary(io)
{
    // No expected class name: any header class is read
    readHeaderOk(IOstream::ASCII, word::null);
}


// ************************************************************************* //
