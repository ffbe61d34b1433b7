/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class Type>
Type Foam::SPH::shepardInterpolation::interpolate
(
    const UList<Type>& f,
    const scalar minFraction
) const
{
    if (!wet(minFraction))
    {
        return Zero;
    }

    // 004_f29223b75201dc88.txt eq. (10) without the hydrostatic term
    Type sum(Zero);
    forAll(neighbours_, k)
    {
        sum += weights_[k]*f[neighbours_[k]];
    }
    return sum/fraction_;
}


// ************************************************************************* //
