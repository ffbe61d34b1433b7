/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "particles.H"
#include "Time.H"
#include "OSspecific.H"

#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::fileName Foam::SPH::particles::defaultLocal("lagrangian/sph");

namespace Foam
{
namespace SPH
{
    template<>
    HashPtrTable<scalarIOField>& particles::table<scalar>()
    {
        return scalars_;
    }

    template<>
    HashPtrTable<vector2DIOField>& particles::table<vector2D>()
    {
        return vectors_;
    }

    template<>
    HashPtrTable<labelIOField>& particles::table<label>()
    {
        return labels_;
    }
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::SPH::particles::io
(
    const word& name,
    bool read,
    bool write
) const
{
    return IOobject
    (
        name,
        instance_,
        local_,
        db_,
        read ? IOobject::MUST_READ : IOobject::NO_READ,
        (write && autoWrite_) ? IOobject::AUTO_WRITE : IOobject::NO_WRITE,
        autoWrite_
    );
}


void Foam::SPH::particles::checkNew(const word& name) const
{
    if
    (
        name == "positions"
     || scalars_.found(name) || vectors_.found(name) || labels_.found(name)
    )
    {
        FatalErrorInFunction
            << "Particle field " << name << " already exists" << nl
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::particles::particles
(
    const objectRegistry& db,
    const word& instance,
    const fileName& local,
    bool autoWrite
)
:
    db_(db),
    instance_(instance),
    local_(local),
    autoWrite_(autoWrite),
    size_(0),
    positions_(new vector2DIOField(io("positions", false, true)))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::SPH::particles::path() const
{
    return db_.time().path()/instance_/local_;
}


void Foam::SPH::particles::resize(label n)
{
    size_ = n;
    positions_->setSize(n, vector2D::zero);
    forAllIters(scalars_, iter) { (*iter)->setSize(n, Zero); }
    forAllIters(vectors_, iter) { (*iter)->setSize(n, vector2D::zero); }
    forAllIters(labels_, iter) { (*iter)->setSize(n, Zero); }
}


void Foam::SPH::particles::append(const particles& other)
{
    const label n0 = size_;
    resize(size_ + other.size());

    auto copyTail = [n0](auto& to, const auto& from)
    {
        forAll(from, i)
        {
            to[n0 + i] = from[i];
        }
    };

    copyTail(*positions_, other.positions());
    for (const word& name : order_)
    {
        if (scalars_.found(name))
        {
            copyTail(field<scalar>(name), other.field<scalar>(name));
        }
        else if (vectors_.found(name))
        {
            copyTail(field<vector2D>(name), other.field<vector2D>(name));
        }
        else
        {
            copyTail(field<label>(name), other.field<label>(name));
        }
    }
}


void Foam::SPH::particles::reorder(const labelUList& oldOfNew)
{
    const label n = oldOfNew.size();
    if (n < 0 || n > size_)
    {
        FatalErrorInFunction
            << "A reordering of " << n << " particles for a set of " << size_
            << " in " << path() << exit(FatalError);
    }
    std::vector<bool> taken(std::size_t(n), false);
    for (const label i : oldOfNew)
    {
        if (i < 0 || i >= n || taken[i])
        {
            FatalErrorInFunction
                << "The reordering of the first " << n << " particles of "
                << path() << " is not a permutation: index " << i
                << exit(FatalError);
        }
        taken[i] = true;
    }

    reorderField(*positions_, oldOfNew);
    forAllIters(scalars_, iter) { reorderField(**iter, oldOfNew); }
    forAllIters(vectors_, iter) { reorderField(**iter, oldOfNew); }
    forAllIters(labels_, iter) { reorderField(**iter, oldOfNew); }
}


void Foam::SPH::particles::save(snapshot& s) const
{
    s.positions = *positions_;
    for (const word& name : order_)
    {
        if (!restart_.found(name)) continue;
        if (scalars_.found(name)) s.scalars(name) = *scalars_[name];
        else if (vectors_.found(name)) s.vectors(name) = *vectors_[name];
        else s.labels(name) = *labels_[name];
    }
}


void Foam::SPH::particles::restore(const snapshot& s)
{
    resize(s.positions.size());
    *positions_ = s.positions;
    forAllConstIters(s.scalars, iter) { field<scalar>(iter.key()) = iter.val(); }
    forAllConstIters(s.vectors, iter) { field<vector2D>(iter.key()) = iter.val(); }
    forAllConstIters(s.labels, iter) { field<label>(iter.key()) = iter.val(); }
}


void Foam::SPH::particles::readFields
(
    const wordList& scalarNames,
    const wordList& vectorNames,
    const wordList& labelNames
)
{
    positions_.clear();
    positions_.reset(new vector2DIOField(io("positions", true, true)));
    size_ = positions_->size();

    for (const word& name : scalarNames) { readField<scalar>(name); }
    for (const word& name : vectorNames) { readField<vector2D>(name); }
    for (const word& name : labelNames) { readField<label>(name); }

    // Fields not read keep their values but follow the new size
    resize(size_);
}


void Foam::SPH::particles::read()
{
    wordList s, v, l;
    for (const word& name : order_)
    {
        if (!restart_.found(name)) continue;
        if (scalars_.found(name)) s.append(name);
        else if (vectors_.found(name)) v.append(name);
        else l.append(name);
    }
    readFields(s, v, l);
}


void Foam::SPH::particles::setInstance(const word& instance)
{
    instance_ = instance;
    positions_->instance() = instance;
    forAllIters(scalars_, iter) { (*iter)->instance() = instance; }
    forAllIters(vectors_, iter) { (*iter)->instance() = instance; }
    forAllIters(labels_, iter) { (*iter)->instance() = instance; }
}


void Foam::SPH::particles::write() const
{
    // OpenFOAM writes a field into the current time (or constant/)
    if (instance_ != db_.time().constant())
    {
        const_cast<particles&>(*this).setInstance(db_.time().timeName());
    }
    mkDir(path());
    positions_->write();
    for (const word& name : order_)
    {
        if (!restart_.found(name)) continue;
        if (scalars_.found(name)) scalars_[name]->write();
        else if (vectors_.found(name)) vectors_[name]->write();
        else labels_[name]->write();
    }
}


// ************************************************************************* //
