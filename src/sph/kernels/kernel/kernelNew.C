/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "kernel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::SPH::kernel> Foam::SPH::kernel::New
(
    const dictionary& dict,
    const scalar dr
)
{
    const word kernelType(dict.get<word>("kernel"));

    Info<< "Selecting kernel " << kernelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(kernelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "kernel",
            kernelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<kernel>(cstrIter()(dict, dr));
}


// ************************************************************************* //
