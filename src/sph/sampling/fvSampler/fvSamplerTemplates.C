/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "interpolation.H"
#include "errorNorms.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::SPH::fvSampler::sample
(
    const GeometricField<Type, fvPatchField, volMesh>& fld,
    const UList<vector2D>& points,
    const labelUList& cells
) const
{
    autoPtr<interpolation<Type>> interp =
        interpolation<Type>::New(scheme_, fld);

    auto tresult = tmp<Field<Type>>::New(points.size(), Zero);
    Field<Type>& result = tresult.ref();

    forAll(points, i)
    {
        result[i] =
            cells[i] < 0
          ? pTraits<Type>::one*errorNorms::missing()
          : interp->interpolate(toPoint(points[i]), cells[i]);
    }
    return tresult;
}


// ************************************************************************* //
