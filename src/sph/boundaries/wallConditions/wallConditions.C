/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallConditions.H"
#include "StringStream.H"
#include "fieldDictionary.H"
#include "Time.H"
#include "Constant.H"
#include "TableBase.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::wallConditions::conditionType>
Foam::SPH::wallConditions::conditionTypeNames
({
    { conditionType::noSlip, "noSlip" },
    { conditionType::slip, "slip" },
    { conditionType::fixedValue, "fixedValue" },
    { conditionType::uniformFixedValue, "uniformFixedValue" },
    { conditionType::movingWallVelocity, "movingWallVelocity" },
    { conditionType::zeroGradient, "zeroGradient" },
    { conditionType::fixedFluxPressure, "fixedFluxPressure" },
    { conditionType::fixedGradient, "fixedGradient" },
    { conditionType::kqRWallFunction, "kqRWallFunction" },
    { conditionType::epsilonWallFunction, "epsilonWallFunction" },
    { conditionType::nutkWallFunction, "nutkWallFunction" },
});


namespace
{
    //- Words as "(a b c)"
    std::string joined(const Foam::UList<Foam::word>& words)
    {
        std::string s("(");
        forAll(words, i)
        {
            s += (i ? " " : "");
            s += words[i];
        }
        return s + ")";
    }

    //- Types an FV case's 0/ files give the patches that are no wall of
    //- the SPH mesh: its front and back (empty), its periodic and its
    //- processor patches. Accepted and ignored.
    const Foam::wordList ignoredTypes
    ({
        "empty", "cyclic", "cyclicAMI", "cyclicACMI", "cyclicSlip",
        "processor", "processorCyclic"
    });
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::wallConditions::readEntry(const entry& e)
{
    const dictionary& d = e.dict();
    const label k = entries_.size();
    entries_.append(new dictionary(d));
    keys_.append(e.keyword());
    values_.resize(k + 1);

    const word name(d.get<word>("type"));
    const List<Pair<word>> valid(validTypes());
    bool found = false;
    for (const Pair<word>& v : valid)
    {
        found = found || v.first() == name;
    }
    if (!found)
    {
        FatalIOErrorInFunction(d)
            << "Unknown " << fieldName_ << " wall condition type " << name
            << " for " << e.keyword() << nl << nl
            << "Valid types on a wall patch of the SPH mesh:" << nl;
        for (const Pair<word>& v : valid)
        {
            FatalIOError
                << "    " << v.first().c_str()
                << string(max(label(1), label(20 - v.first().size())), ' ').c_str()
                << v.second().c_str() << nl;
        }
        FatalIOError
            << "(type empty or cyclic patches of an FV case are no SPH walls:"
            << " their entries are ignored)" << exit(FatalIOError);
    }
    if (d.found("rampTime"))
    {
        FatalIOErrorInFunction(d)
            << "Entry rampTime of " << e.keyword() << " is a keyword of the"
            << " former constant/movingWalls: give the ramp as the velocity's"
            << " Function1, e.g." << nl
            << "    type            uniformFixedValue;" << nl
            << "    uniformValue    table ((0 (0 0 0)) (1 (1 0 0)));"
            << exit(FatalIOError);
    }
    const conditionType type = conditionTypeNames[name];
    types_.append(type);

    // The temperature's values are SPH::heatTransfer's to read
    if (type == conditionType::fixedValue && fieldName_ == "U")
    {
        if (!d.found("value"))
        {
            FatalIOErrorInFunction(d)
                << "Missing entry 'value' of the fixedValue " << fieldName_
                << " of " << e.keyword() << ": expected"
                << " 'value uniform (Ux Uy 0);'" << exit(FatalIOError);
        }
        ITstream& is = d.lookup("value");
        const word kind(is);
        if (kind != "uniform")
        {
            FatalIOErrorInFunction(d)
                << "Entry 'value' of " << e.keyword() << ": expected"
                << " 'value uniform (Ux Uy 0);', found " << kind
                << " (a wall patch of the SPH mesh has no faces to give"
                << " values to)" << exit(FatalIOError);
        }
        values_.set(k, new Function1Types::Constant<vector>("value", vector(is)));
    }
    else if (type == conditionType::uniformFixedValue)
    {
        if (!d.found("uniformValue"))
        {
            FatalIOErrorInFunction(d)
                << "Missing entry 'uniformValue' of the uniformFixedValue "
                << fieldName_ << " of " << e.keyword() << ": a Function1 of"
                << " time, e.g. 'uniformValue table ((0 (0 0 0)) (1 (1 0 0)));'"
                << exit(FatalIOError);
        }
        values_.set(k, Function1<vector>::New("uniformValue", d).ptr());
    }
}


void Foam::SPH::wallConditions::refuseUnused
(
    const dictionary& boundaryField,
    const entry& e
) const
{
    const wordList& patches = walls_.patchNames();
    if (!e.isDict())
    {
        FatalIOErrorInFunction(boundaryField)
            << "Entry " << e.keyword() << " of boundaryField is not a"
            << " dictionary: expected one per patch" << exit(FatalIOError);
    }
    const word type(e.dict().getOrDefault<word>("type", word::null));
    if (ignoredTypes.found(type))
    {
        return;
    }
    // The keyword as OpenFOAM writes it (a pattern in quotes)
    OStringStream what;
    if (e.keyword().isPattern())
    {
        bool matches = false;
        for (const word& p : patches)
        {
            matches = matches || e.keyword().match(p);
        }
        what<< "Pattern " << e.keyword()
            << (
                   matches
                 ? " is overridden for every wall patch it matches"
                 : " matches no wall patch"
               )
            << " of the SPH mesh";
    }
    else
    {
        what<< "No wall patch " << e.keyword() << " in the SPH mesh";
    }
    FatalIOErrorInFunction(e.dict())
        << what.str().c_str() << " (constant/sphMesh/walls/patchNames)" << nl
        << "Wall patches: " << joined(patches).c_str() << nl
        << "(only entries of type " << joined(ignoredTypes).c_str()
        << " may name other patches)" << exit(FatalIOError);
}


void Foam::SPH::wallConditions::read(const dictionary& boundaryField)
{
    const wordList& patches = walls_.patchNames();

    // The entry of each patch: its own name first, then the last pattern
    // that matches, as OpenFOAM's lookup
    List<const entry*> patchEntry(patches.size(), nullptr);
    DynamicList<const entry*> used;
    forAll(patches, patchi)
    {
        patchEntry[patchi] = boundaryField.findEntry(patches[patchi], keyType::REGEX);
        if (patchEntry[patchi] && !used.found(patchEntry[patchi]))
        {
            used.append(patchEntry[patchi]);
        }
    }

    // Entries that give no wall patch its condition
    for (const entry& e : boundaryField)
    {
        if (!used.found(&e))
        {
            refuseUnused(boundaryField, e);
        }
    }

    forAll(patches, patchi)
    {
        if (!patchEntry[patchi])
        {
            FatalIOErrorInFunction(boundaryField)
                << "No entry for the wall patch " << patches[patchi]
                << " in the boundaryField of " << boundaryField.name() << nl
                << "Every wall patch of the SPH mesh"
                << " (constant/sphMesh/walls/patchNames) needs one, by its"
                << " name or a pattern: " << joined(patches).c_str()
                << exit(FatalIOError);
        }
    }

    patchEntry_.setSize(patches.size());
    for (const entry* e : used)
    {
        readEntry(*e);
    }
    forAll(patches, patchi)
    {
        patchEntry_[patchi] = used.find(patchEntry[patchi]);
    }
}


void Foam::SPH::wallConditions::checkAlongWall
(
    const label patchi,
    const vector2D& U,
    const scalar t
) const
{
    for (const label s : patchSegments_[patchi])
    {
        const vector2D& n = walls_.segmentNormals()[s];
        if (mag(U & n) > 1e-9*mag(U))
        {
            const labelPair& seg = walls_.segments()[s];
            FatalIOErrorInFunction(dict(patchi))
                << "Patch " << walls_.patchNames()[patchi] << " slides at "
                << U << " at t = " << t << ", which is not along its segment"
                << " from " << walls_.points()[seg.first()] << " to "
                << walls_.points()[seg.second()] << " (normal " << n << ")"
                << nl << "A wall that stays in place must move along itself:"
                << " eq. (43) of 000_8c7cd3aabddcf18a.txt imposes the wall's"
                << " normal velocity, so the fluid would go through it. A wall"
                << " that moves is type movingWallVelocity, its motion in"
                << " constant/dynamicMeshDict" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallConditions::wallConditions
(
    const dictionary& boundaryField,
    const wallMesh& walls,
    const word& fieldName
)
:
    walls_(walls),
    fieldName_(fieldName),
    patchSegments_(walls.patchNames().size())
{
    forAll(walls.segmentPatch(), s)
    {
        patchSegments_[walls.segmentPatch()[s]].append(s);
    }
    read(boundaryField);

    // A velocity along z, or across a wall, is an error from the start
    forAll(walls.patchNames(), patchi)
    {
        if (slides(patchi))
        {
            velocity(patchi, 0);
        }
    }
}


Foam::SPH::wallConditions::wallConditions
(
    const Time& runTime,
    const wallMesh& walls,
    const word& fieldName
)
:
    wallConditions
    (
        [&]() -> dictionary
        {
            const fileName file(runTime.path()/"0"/fieldName);
            if (!isFile(file))
            {
                FatalErrorInFunction
                    << "No " << file << nl
                    << "The wall patches " << joined(walls.patchNames()).c_str()
                    << " take their " << fieldName << " conditions from its"
                    << " boundaryField, as in OpenFOAM, e.g." << nl
                    << "    boundaryField" << nl
                    << "    {" << nl
                    << "        \".*\" { type "
                    << (fieldName == "U" ? "noSlip" : "zeroGradient") << "; }"
                    << nl << "    }" << exit(FatalError);
            }
            // Always 0/: a restart's time folder holds the particle fields.
            // Any class: an FV case's files say volVectorField
            const fieldDictionary fieldDict
            (
                IOobject
                (
                    fieldName, "0", runTime,
                    IOobject::MUST_READ, IOobject::NO_WRITE, false
                )
            );
            if (!fieldDict.isDict("boundaryField"))
            {
                FatalIOErrorInFunction(fieldDict)
                    << "No boundaryField in " << fieldDict.name() << ": every"
                    << " wall patch " << joined(walls.patchNames()).c_str()
                    << " needs its condition there" << exit(FatalIOError);
            }
            return fieldDict.subDict("boundaryField");
        }(),
        walls,
        fieldName
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::SPH::wallConditions::slides(const label patchi) const
{
    return values_.set(patchEntry_[patchi]);
}


Foam::vector2D Foam::SPH::wallConditions::velocity
(
    const label patchi,
    const scalar t
) const
{
    const label k = patchEntry_[patchi];
    if (!values_.set(k))
    {
        if (types_[k] == conditionType::movingWallVelocity)
        {
            FatalErrorInFunction
                << "The velocity of " << walls_.patchNames()[patchi]
                << " (movingWallVelocity) is that of its motion in"
                << " constant/dynamicMeshDict, not of 0/U"
                << abort(FatalError);
        }
        return vector2D::zero;
    }
    const vector v(values_[k].value(t));
    if (v.z() != 0)
    {
        FatalIOErrorInFunction(entries_[k])
            << "The velocity of " << walls_.patchNames()[patchi] << " at t = "
            << t << " is " << v << ": its z component must be 0 (the SPH"
            << " walls are in the x-y plane)" << exit(FatalIOError);
    }
    const vector2D U(v.x(), v.y());
    checkAlongWall(patchi, U, t);
    return U;
}


void Foam::SPH::wallConditions::allowOnly
(
    const List<conditionType>& types,
    const string& who
) const
{
    forAll(walls_.patchNames(), patchi)
    {
        if (!types.found(type(patchi)))
        {
            wordList names;
            for (const conditionType t : types)
            {
                names.append(conditionTypeNames[t]);
            }
            FatalIOErrorInFunction(dict(patchi))
                << "Wall patch " << walls_.patchNames()[patchi] << " has "
                << fieldName_ << " type " << typeName(patchi) << ": " << who.c_str()
                << " support only " << joined(names).c_str() << exit(FatalIOError);
        }
    }
}


Foam::string Foam::SPH::wallConditions::describe(const label patchi) const
{
    OStringStream os;
    const label k = patchEntry_[patchi];
    switch (types_[k])
    {
        case conditionType::noSlip:
            os  << "still, no slip";
            break;
        case conditionType::slip:
            os  << "still, free slip";
            break;
        case conditionType::fixedValue:
            os  << "slides along itself at U " << velocity(patchi, 0);
            break;
        case conditionType::uniformFixedValue:
        {
            const Function1<vector>& f = values_[k];
            const auto* table = dynamic_cast<const Function1Types::TableBase<vector>*>(&f);
            if (isA<Function1Types::Constant<vector>>(f))
            {
                os  << "slides along itself at U " << velocity(patchi, 0);
            }
            else if (table && table->x()().size() == 2 && table->x()()[0] == 0
                  && table->y()()[0] == vector::zero)
            {
                const scalar tFull = table->x()()[1];
                os  << "slides along itself at U " << velocity(patchi, tFull)
                    << ", from rest over " << tFull << " s";
            }
            else
            {
                os  << "slides along itself at U(t) = uniformValue " << f.type();
            }
            os  << " (uniformFixedValue)";
            break;
        }
        case conditionType::movingWallVelocity:
            os  << "moves as constant/dynamicMeshDict says";
            break;
        case conditionType::zeroGradient:
        case conditionType::fixedFluxPressure:
            os  << (fieldName_ == "T" ? "adiabatic" : "Neumann wall condition (eq. (43))");
            break;
        case conditionType::fixedGradient:
            os  << "imposed gradient (heat flux)";
            break;
        case conditionType::kqRWallFunction:
            os  << "no flux, wall value from the fluid (eqs. (25)-(26))";
            break;
        case conditionType::epsilonWallFunction:
            os  << "log-layer flux and wall value (eqs. (27)-(29))";
            break;
        case conditionType::nutkWallFunction:
            os  << "log-law wall friction (eqs. (22)-(23))";
            break;
    }
    return os.str();
}


// ************************************************************************* //
