/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "initialField.H"
#include "Time.H"
#include "OSspecific.H"
#include "vectorField.H"
#include "scalarField.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::initialField::badKind
(
    ITstream& is,
    const word& kind,
    const word& listType,
    const string& expected
) const
{
    FatalIOErrorInFunction(is)
        << "internalField " << kind << ": expected 'internalField uniform"
        << " <value>;', 'internalField nonuniform List<" << listType
        << "> N (...);' (one value per fluid particle of"
        << " constant/sphMesh/fluid)" << expected.c_str()
        << exit(FatalIOError);
    ::abort();
}


void Foam::SPH::initialField::badSize
(
    ITstream& is,
    const label size,
    const label expected
) const
{
    FatalIOErrorInFunction(is)
        << "internalField nonuniform holds " << size << " values: expected"
        << " one per fluid particle of constant/sphMesh/fluid, " << expected
        << exit(FatalIOError);
    ::abort();
}


template<class FileType>
void Foam::SPH::initialField::checkFinite
(
    ITstream& is,
    const FileType& v,
    const label i
) const
{
    for (direction d = 0; d < pTraits<FileType>::nComponents; ++d)
    {
        if (!std::isfinite(component(v, d)))
        {
            FatalIOErrorInFunction(is)
                << "internalField " << (i < 0 ? "uniform " : "nonuniform ")
                << v << (i < 0 ? "" : " (value " + Foam::name(i) + ")").c_str()
                << ": not a finite value" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::initialField::initialField(const Time& runTime, const word& name)
:
    dict_
    (
        IOobject
        (
            name, runTime.timeName(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::SPH::initialField::found() const
{
    if (dict_.found("internalField"))
    {
        return true;
    }
    // A file without its value would start the fluid from rest (or p = 0)
    // without a word
    if (isFile(dict_.objectPath()) || isFile(dict_.objectPath() + ".gz"))
    {
        FatalIOErrorInFunction(dict_)
            << "Missing entry internalField in " << dict_.objectPath()
            << ": expected 'internalField uniform <value>;' or"
            << " 'internalField nonuniform List<..> N (...);' (or no file:"
            << " the fluid starts at rest, at p = 0)" << exit(FatalIOError);
    }
    return false;
}


Foam::word Foam::SPH::initialField::kind() const
{
    return word(stream());
}


namespace Foam
{
namespace SPH
{
    // The z component of a vector is dropped
    inline void assign(vector2D& to, const vector& from)
    {
        to = vector2D(from.x(), from.y());
    }
    inline void assign(scalar& to, const scalar from)
    {
        to = from;
    }
}
}


template<class Type, class FileType>
bool Foam::SPH::initialField::readAs
(
    UList<Type>& values,
    const word& listType,
    const string& expected
) const
{
    ITstream& is = stream();
    const word kind(is);
    if (kind == "uniform")
    {
        FileType v;
        is >> v;
        checkFinite(is, v, -1);
        forAll(values, i)
        {
            assign(values[i], v);
        }
        return true;
    }
    if (kind != "nonuniform")
    {
        badKind(is, kind, listType, expected);
    }
    const Field<FileType> list(is);
    if (list.size() != values.size())
    {
        badSize(is, list.size(), values.size());
    }
    forAll(list, i)
    {
        checkFinite(is, list[i], i);
        assign(values[i], list[i]);
    }
    return false;
}


bool Foam::SPH::initialField::read
(
    UList<vector2D>& values,
    const string& expected
) const
{
    return readAs<vector2D, vector>(values, "vector", expected);
}


bool Foam::SPH::initialField::read
(
    UList<scalar>& values,
    const string& expected
) const
{
    return readAs<scalar, scalar>(values, "scalar", expected);
}


// ************************************************************************* //
