/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallBoundaries.H"
#include "usawWalls.H"
#include "IOdictionary.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

// Long beside wallMotion's velocity step (1e-6 s), whose central difference
// of positions would leave eps |x|/(1e-6 d) in the acceleration; short
// beside the motions' own times (a ramp over 0.2 s, a period of 1 s): the
// difference's error h^2/6 |d3u/dt3| is below 1e-7 m/s^2 for a wheel of
// 1 m at pi/2 rad/s
const Foam::scalar Foam::SPH::wallBoundaries::accelerationStep = 1e-4;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::Time& Foam::SPH::wallBoundaries::noMovingWallsFile
(
    const Time& runTime
)
{
    const fileName old(runTime.path()/runTime.constant()/"movingWalls");
    if (isFile(old))
    {
        FatalErrorInFunction
            << old << " is no longer read: the wall conditions come from the"
            << " boundaryField of 0/U (and 0/p), the wall motion from"
            << " constant/dynamicMeshDict, as in OpenFOAM. Remove it and"
            << " write, for a lid sliding at U = 1 reached over 1 s," << nl
            << "    0/U:  lid { type uniformFixedValue;"
            << " uniformValue table ((0 (0 0 0)) (1 (1 0 0))); }" << nl
            << "for a wall turning about (0.5 0.5) at 2 rad/s," << nl
            << "    0/U:  stirrer { type movingWallVelocity; }" << nl
            << "    constant/dynamicMeshDict:" << nl
            << "        motionSolver multiSolidBodyMotionSolver;" << nl
            << "        multiSolidBodyMotionSolverCoeffs" << nl
            << "        {" << nl
            << "            stirrer" << nl
            << "            {" << nl
            << "                solidBodyMotionFunction rotatingMotion;" << nl
            << "                rotatingMotionCoeffs"
            << " { origin (0.5 0.5 0); axis (0 0 1); omega 2; }" << nl
            << "            }" << nl
            << "        }" << nl
            << "and for each still wall 0/U: wall { type noSlip; }; in 0/p"
            << " every wall is type zeroGradient" << exit(FatalError);
    }
    return runTime;
}


void Foam::SPH::wallBoundaries::setPatchMotion()
{
    using cond = wallConditions::conditionType;
    const wordList& patches = walls_.patchNames();
    patchMotion_.setSize(patches.size(), -1);

    labelList geometryMotion(geometry_.size(), -1);
    labelList slideMotion(U_.nEntries(), -1);
    forAll(patches, patchi)
    {
        const label g = geometry_.patchMotion()[patchi];
        const cond type = U_.type(patchi);
        if (type == cond::slip)
        {
            FatalIOErrorInFunction(U_.dict(patchi))
                << "Wall patch " << patches[patchi] << ": type slip is not"
                << " supported by the USAW walls yet (their viscous term is"
                << " no-slip); use noSlip" << exit(FatalIOError);
        }
        if (g >= 0 && type != cond::movingWallVelocity)
        {
            FatalIOErrorInFunction(U_.dict(patchi))
                << "Wall patch " << patches[patchi] << " moves ("
                << geometry_.type(g) << " in constant/dynamicMeshDict) but"
                << " its U is type " << U_.typeName(patchi) << ": the velocity"
                << " of a moving wall is that of its motion, type"
                << " movingWallVelocity" << exit(FatalIOError);
        }
        if (g < 0 && type == cond::movingWallVelocity)
        {
            FatalIOErrorInFunction(U_.dict(patchi))
                << "Wall patch " << patches[patchi] << " is type"
                << " movingWallVelocity but has no motion: give it one in"
                << " multiSolidBodyMotionSolverCoeffs of"
                << " constant/dynamicMeshDict, or make it noSlip"
                << exit(FatalIOError);
        }

        // One motion per entry of either file
        label& m = g >= 0 ? geometryMotion[g] : slideMotion[U_.entryIndex(patchi)];
        if (g < 0 && !U_.slides(patchi))
        {
            continue;
        }
        if (m < 0)
        {
            m = motions_.size();
            motions_.append(g >= 0 ? geometry_.key(g) : U_.key(U_.entryIndex(patchi)));
            motionGeometry_.append(g);
            motionPatches_.append(labelList());
            movesGeometry_ = movesGeometry_ || g >= 0;
        }
        patchMotion_[patchi] = m;
        motionPatches_[m].append(patchi);
    }
}


void Foam::SPH::wallBoundaries::setVertexMotion()
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
        if (m < 0 || motionGeometry_[m] < 0) continue;
        for (const label v : {segs[s].first(), segs[s].second()})
        {
            if (vertexMotion_[v] == -3)
            {
                const label g = motionGeometry_[m];
                FatalIOErrorInFunction(geometry_.dict(g))
                    << "Patch " << walls_.patchNames()[segPatch[s]]
                    << " moves (" << geometry_.type(g) << ") but shares the"
                    << " wall vertex at " << x0[v] << " with a patch that"
                    << " does not move with it: the wall would tear apart"
                    << exit(FatalIOError);
            }
        }
    }

    motionVertices_.setSize(motions_.size());
    forAll(vertexMotion_, v)
    {
        label& m = vertexMotion_[v];
        m = max(m, label(-1));
        if (m >= 0)
        {
            motionVertices_[m].append(v);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallBoundaries::wallBoundaries
(
    const dictionary& UBoundaryField,
    const dictionary& dynamicMeshDict,
    const Time& runTime,
    const wallMesh& walls
)
:
    walls_(walls),
    U_(UBoundaryField, walls, "U"),
    geometry_(dynamicMeshDict, runTime, walls),
    movesGeometry_(false)
{
    setPatchMotion();
    setVertexMotion();
}


Foam::SPH::wallBoundaries::wallBoundaries
(
    const Time& runTime,
    const wallMesh& walls
)
:
    walls_(walls),
    U_(noMovingWallsFile(runTime), walls, "U"),
    p_(new wallConditions(runTime, walls, "p")),
    geometry_(runTime, walls),
    movesGeometry_(false)
{
    setPatchMotion();
    setVertexMotion();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallBoundaries::vertices
(
    const scalar t,
    UList<vector2D>& x,
    UList<vector2D>& U
) const
{
    const List<vector2D>& x0 = walls_.points();
    forAll(x0, v)
    {
        x[v] = x0[v];
        U[v] = vector2D::zero;
    }
    forAll(motions_, m)
    {
        const label g = motionGeometry_[m];
        if (g >= 0)
        {
            geometry_.move(g, t, x0, motionVertices_[m], x, U);
            continue;
        }
        // Each patch of the entry checks that it slides along itself
        vector2D Um(vector2D::zero);
        for (const label patchi : motionPatches_[m])
        {
            Um = U_.velocity(patchi, t);
        }
        for (const label v : motionVertices_[m])
        {
            U[v] = Um;
        }
    }
}


void Foam::SPH::wallBoundaries::accelerations
(
    const scalar t,
    UList<vector2D>& a
) const
{
    const label n = walls_.points().size();
    List<vector2D> x(n), U1(n), U2(n);
    const scalar d = accelerationStep;
    const scalar t1 = max(t - d, scalar(0));
    const scalar t2 = t1 + 2*d;
    vertices(t1, x, U1);
    vertices(t2, x, U2);
    forAll(a, v)
    {
        const label m = vertexMotion_[v];
        a[v] =
            m >= 0 && motionGeometry_[m] >= 0
          ? (U2[v] - U1[v])/(t2 - t1)
          : vector2D::zero;
    }
}


void Foam::SPH::wallBoundaries::moveVertexParticles
(
    const scalar t,
    const label nFluid,
    const bool setVelocity,
    UList<vector2D>& x,
    UList<vector2D>& U,
    List<vector2D>& wallX,
    List<vector2D>& wallU,
    usawWalls& usaw
) const
{
    if (!any())
    {
        return;
    }
    vertices(t, wallX, wallU);
    forAll(wallX, v)
    {
        x[nFluid + v] = wallX[v];
        if (setVelocity)
        {
            U[nFluid + v] = wallU[v];
        }
    }
    if (movesGeometry_)
    {
        usaw.updateGeometry(wallX);
    }
}


void Foam::SPH::wallBoundaries::write(Ostream& os, const string& indent) const
{
    forAll(walls_.patchNames(), patchi)
    {
        const label m = patchMotion_[patchi];
        if (m < 0)
        {
            continue;
        }
        const label g = motionGeometry_[m];
        os  << indent.c_str() << walls_.patchNames()[patchi] << ": "
            << (g >= 0 ? geometry_.describe(g) : U_.describe(patchi)).c_str()
            << nl;
    }
}


// ************************************************************************* //
