/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fluidRegion.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::fluidRegion::operation>
Foam::SPH::fluidRegion::operationNames
({
    { operation::add, "add" },
    { operation::subtract, "subtract" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The words joined for a message: "a, b or c"
std::string wordsOr(const Foam::wordList& words)
{
    std::string result;

    forAll(words, i)
    {
        if (i > 0)
        {
            result += (i == words.size() - 1) ? " or " : ", ";
        }
        result += words[i];
    }

    return result;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::SPH::fluidRegion::report() const
{
    Info<< "Fluid: " << size() << " region(s), applied in order" << nl;

    forAll(regions_, i)
    {
        Info<< "    " << operationNames[operations_[i]] << ' '
            << regions_[i].name() << " (area " << regions_[i].area() << ')'
            << nl;
    }

    Info<< "    bounds " << bounds() << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fluidRegion::fluidRegion(const dictionary& dict)
:
    regions_(),
    operations_()
{
    DynamicList<operation> operations;

    for (const entry& e : dict)
    {
        const word& name = e.keyword();

        if (!e.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << name << " is not a region: expected a"
                << " sub-dictionary " << name << " { type <shape>; ... } with"
                << " <shape> "
                << wordsOr
                   (
                       region::dictionaryConstructorTablePtr_->sortedToc()
                   ).c_str()
                << nl << exit(FatalIOError);
        }

        const dictionary& regionDict = e.dict();

        const word opName
        (
            regionDict.getOrDefault<word>
            (
                "operation",
                operationNames[operation::add]
            )
        );

        if (!operationNames.found(opName))
        {
            FatalIOErrorInFunction(regionDict)
                << "Region " << name << ": entry operation " << opName
                << ": expected " << wordsOr(operationNames.names()).c_str()
                << nl << exit(FatalIOError);
        }

        const operation op = operationNames[opName];

        if (regions_.empty() && op == operation::subtract)
        {
            FatalIOErrorInFunction(regionDict)
                << "Region " << name << ": entry operation subtract on the"
                << " first region; the first region must be add, as nothing"
                << " precedes it to subtract from" << nl
                << exit(FatalIOError);
        }

        regions_.append(region::New(name, regionDict));
        operations.append(op);
    }

    if (regions_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "No regions in dictionary " << dict.dictName()
            << ": expected at least one sub-dictionary such as" << nl
            << "    water { type box; min (0 0); max (1 1); }" << nl
            << exit(FatalIOError);
    }

    operations_.transfer(operations);

    report();
}


Foam::SPH::fluidRegion::fluidRegion
(
    PtrList<region>&& regions,
    const List<operation>& operations
)
:
    regions_(std::move(regions)),
    operations_(operations)
{
    if (regions_.empty())
    {
        FatalErrorInFunction
            << "No regions: expected at least one" << nl
            << exit(FatalError);
    }

    if (operations_.size() != regions_.size())
    {
        FatalErrorInFunction
            << regions_.size() << " regions but " << operations_.size()
            << " operations: expected one operation per region" << nl
            << exit(FatalError);
    }

    forAll(regions_, i)
    {
        if (!regions_.set(i))
        {
            FatalErrorInFunction
                << "Region " << i << " is not set" << nl
                << exit(FatalError);
        }
    }

    if (operations_.first() == operation::subtract)
    {
        FatalErrorInFunction
            << "Region " << regions_[0].name() << ": operation subtract on"
            << " the first region; the first region must be add, as nothing"
            << " precedes it to subtract from" << nl
            << exit(FatalError);
    }

    report();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::fluidRegion::size() const
{
    return regions_.size();
}


Foam::wordList Foam::SPH::fluidRegion::names() const
{
    wordList result(regions_.size());

    forAll(regions_, i)
    {
        result[i] = regions_[i].name();
    }

    return result;
}


const Foam::PtrList<Foam::SPH::region>&
Foam::SPH::fluidRegion::regions() const
{
    return regions_;
}


const Foam::List<Foam::SPH::fluidRegion::operation>&
Foam::SPH::fluidRegion::operations() const
{
    return operations_;
}


bool Foam::SPH::fluidRegion::contains(const vector2D& p) const
{
    // The last region holding p decides, so search from the end
    forAllReverse(regions_, i)
    {
        if (regions_[i].contains(p))
        {
            return operations_[i] == operation::add;
        }
    }

    return false;
}


Foam::SPH::boundBox2D Foam::SPH::fluidRegion::bounds() const
{
    // The first region is added (checked on construction)
    boundBox2D bb(regions_[0].bounds());

    forAll(regions_, i)
    {
        if (operations_[i] == operation::add)
        {
            bb.add(regions_[i].bounds());
        }
    }

    return bb;
}


// ************************************************************************* //
