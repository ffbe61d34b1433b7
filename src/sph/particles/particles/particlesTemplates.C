/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "particles.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::Field<Type>& Foam::SPH::particles::field(const word& name)
{
    auto iter = table<Type>().find(name);
    if (!iter.found())
    {
        FatalErrorInFunction
            << "No particle field " << name << " of type "
            << pTraits<Type>::typeName << " in " << path() << nl
            << "Fields: " << order_ << nl
            << exit(FatalError);
    }
    return **iter;
}


template<class Type>
const Foam::Field<Type>& Foam::SPH::particles::field(const word& name) const
{
    return const_cast<particles&>(*this).field<Type>(name);
}


template<class Type>
Foam::Field<Type>& Foam::SPH::particles::add
(
    const word& name,
    const Type& value,
    bool restart
)
{
    checkNew(name);
    auto* fld = new IOField<Type>(io(name, false, restart), Field<Type>(size_, value));
    table<Type>().set(name, fld);
    order_.append(name);
    if (restart)
    {
        restart_.insert(name);
    }
    return *fld;
}


template<class Type>
bool Foam::SPH::particles::addIfPresent(const word& name, const Type& value)
{
    checkNew(name);
    if (isFile(io(name, false, false).objectPath()))
    {
        readField<Type>(name);
        return true;
    }
    add<Type>(name, value, true);
    return false;
}


template<class Type>
void Foam::SPH::particles::reorderField
(
    UList<Type>& fld,
    const labelUList& oldOfNew
)
{
    const List<Type> old(SubList<Type>(fld, oldOfNew.size()));
    forAll(oldOfNew, k)
    {
        fld[k] = old[oldOfNew[k]];
    }
}


template<class Type>
void Foam::SPH::particles::readField(const word& name)
{
    // The old field (if any) leaves the registry before its successor enters
    table<Type>().erase(name);
    autoPtr<IOField<Type>> fld(new IOField<Type>(io(name, true, true)));
    if (fld->size() != size_)
    {
        FatalErrorInFunction
            << "Particle field file " << fld->objectPath() << " holds "
            << fld->size() << " values but " << io("positions", false, false).objectPath()
            << " holds " << size_ << " particles" << nl
            << exit(FatalError);
    }
    if (!order_.found(name))
    {
        order_.append(name);
    }
    table<Type>().set(name, fld.ptr());
    restart_.insert(name);
}


// ************************************************************************* //
