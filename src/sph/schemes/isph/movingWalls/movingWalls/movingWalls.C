/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "movingWalls.H"
#include "IOdictionary.H"
#include "Time.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::movingWalls::read(const dictionary& dict)
{
    const wordList& patches = walls_.patchNames();
    patchMotion_.setSize(patches.size(), -1);

    // Every entry is a sub-dictionary; a literal name must be a patch
    DynamicList<const entry*> entries;
    for (const entry& e : dict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << e.keyword() << " is not a dictionary: expected"
                << " one sub-dictionary per moving wall patch" << nl
                << "Wall patches: " << patches << exit(FatalIOError);
        }
        if (!e.keyword().isPattern() && !patches.found(e.keyword()))
        {
            FatalIOErrorInFunction(e.dict())
                << "No wall patch " << e.keyword() << nl
                << "Wall patches: " << patches << exit(FatalIOError);
        }
        entries.append(&e);
    }

    // The entry of each patch (exact names first, then the last pattern
    // that matches, as OpenFOAM's lookup)
    labelList entryMotion(entries.size(), -1);
    forAll(patches, patchi)
    {
        const entry* e = dict.findEntry(patches[patchi], keyType::REGEX);
        if (!e)
        {
            continue;
        }
        const label k = entries.find(e);
        if (entryMotion[k] < 0)
        {
            entryMotion[k] = motions_.size();
            motions_.append(wallMotion::New(e->keyword(), e->dict()));
        }
        patchMotion_[patchi] = entryMotion[k];
    }
    forAll(entries, k)
    {
        if (entryMotion[k] < 0)
        {
            FatalIOErrorInFunction(entries[k]->dict())
                << "Pattern " << entries[k]->keyword()
                << " matches no wall patch" << nl
                << "Wall patches: " << patches << exit(FatalIOError);
        }
    }
}


void Foam::SPH::movingWalls::setVertexMotion(const dictionary& dict)
{
    const List<labelPair>& segs = walls_.segments();
    const labelList& segPatch = walls_.segmentPatch();
    const List<vector2D>& x0 = walls_.points();

    // -2: no segment seen yet; -3: segments of different motions
    vertexMotion_.setSize(x0.size(), -2);
    forAll(segs, s)
    {
        const label m = patchMotion_[segPatch[s]];
        for (const label v : {segs[s].first(), segs[s].second()})
        {
            if (vertexMotion_[v] == -2) vertexMotion_[v] = m;
            else if (vertexMotion_[v] != m) vertexMotion_[v] = -3;
        }
    }

    forAll(segs, s)
    {
        const label m = patchMotion_[segPatch[s]];
        if (m < 0) continue;
        const wallMotion& motion = motions_[m];
        for (const label v : {segs[s].first(), segs[s].second()})
        {
            if (vertexMotion_[v] == -3 && motion.movesGeometry())
            {
                FatalIOErrorInFunction(dict.subDict(motion.name()))
                    << "Patch " << walls_.patchNames()[segPatch[s]]
                    << " moves (" << motion.type() << ") but shares the wall"
                    << " vertex at " << x0[v] << " with a patch that does"
                    << " not move with it: the wall would tear apart" << nl
                    << exit(FatalIOError);
            }
        }
        if (!motion.movesGeometry())
        {
            // Along the wall at full speed (after any ramp)
            const vector2D n(walls_.segmentNormals()[s]);
            const scalar tFull = motion.rampTime() + 1;
            for (const label v : {segs[s].first(), segs[s].second()})
            {
                const vector2D U(motion.velocity(x0[v], tFull));
                if (mag(U & n) > 1e-9*mag(U))
                {
                    FatalIOErrorInFunction(dict.subDict(motion.name()))
                        << "Patch " << walls_.patchNames()[segPatch[s]]
                        << " slides at " << U << ", which is not along its"
                        << " segment at " << x0[v] << " (normal " << n
                        << "): a sliding wall must move along itself"
                        << exit(FatalIOError);
                }
            }
        }
    }
    for (label& m : vertexMotion_)
    {
        m = max(m, label(-1));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::movingWalls::movingWalls
(
    const dictionary& dict,
    const wallMesh& walls
)
:
    walls_(walls),
    movesGeometry_(false)
{
    read(dict);
    setVertexMotion(dict);
    for (const wallMotion& m : motions_)
    {
        movesGeometry_ = movesGeometry_ || m.movesGeometry();
    }
}


Foam::SPH::movingWalls::movingWalls
(
    const Time& runTime,
    const wallMesh& walls
)
:
    movingWalls
    (
        IOdictionary
        (
            IOobject
            (
                "movingWalls",
                runTime.constant(),
                runTime,
                IOobject::READ_IF_PRESENT,
                IOobject::NO_WRITE,
                false
            )
        ),
        walls
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::movingWalls::vertices
(
    const scalar t,
    UList<vector2D>& x,
    UList<vector2D>& U
) const
{
    const List<vector2D>& x0 = walls_.points();
    forAll(x0, v)
    {
        const label m = vertexMotion_[v];
        if (m < 0)
        {
            x[v] = x0[v];
            U[v] = vector2D::zero;
        }
        else
        {
            x[v] = motions_[m].position(x0[v], t);
            U[v] = motions_[m].velocity(x0[v], t);
        }
    }
}


void Foam::SPH::movingWalls::write(Ostream& os, const string& indent) const
{
    forAll(walls_.patchNames(), patchi)
    {
        const label m = patchMotion_[patchi];
        if (m >= 0)
        {
            os  << indent.c_str() << walls_.patchNames()[patchi] << ": ";
            motions_[m].write(os);
            os  << nl;
        }
    }
}


// ************************************************************************* //
