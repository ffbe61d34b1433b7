/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "errorNorms.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::SPH::mlsInterpolation::interpolate
(
    const stencils& st,
    const UList<Type>& f
)
{
    auto tresult = tmp<Field<Type>>::New(st.size(), Zero);
    Field<Type>& result = tresult.ref();

    forAll(result, i)
    {
        if (st.status[i] == pointStatus::none)
        {
            result[i] = pTraits<Type>::one*errorNorms::missing();
            continue;
        }
        Type sum(Zero);
        for (label k = st.offsets[i]; k < st.offsets[i+1]; ++k)
        {
            sum += st.weights[k]*f[st.indices[k]];
        }
        result[i] = sum;
    }
    return tresult;
}


// ************************************************************************* //
