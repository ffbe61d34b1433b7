/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallMotion.H"
#include "IOdictionary.H"
#include "Time.H"
#include "OStringStream.H"

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
}

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::SPH::wallMotion::differenceStep = 1e-6;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::SPH::wallMotion::identityAtZero(const dictionary& d)
{
    const word name(d.get<word>("solidBodyMotionFunction"));
    if (name == "multiMotion")
    {
        for (const entry& e : d.optionalSubDict("multiMotionCoeffs"))
        {
            if (e.isDict() && !identityAtZero(e.dict()))
            {
                return false;
            }
        }
        return true;
    }
    return
        name == "rotatingMotion" || name == "linearMotion"
     || name == "oscillatingLinearMotion" || name == "oscillatingRotatingMotion";
}


void Foam::SPH::wallMotion::readEntry(const entry& e)
{
    const dictionary& d = e.dict();
    const label m = functions_.size();
    keys_.append(e.keyword());
    dicts_.append(new dictionary(d));
    functions_.append(solidBodyMotionFunction::New(d, *time_));
    Info<< "    for the wall patches of " << e.keyword() << endl;

    origin_.append(vector::zero);
    axis_.append(vector::zero);
    velocity_.append(vector::zero);
    omega_.resize(m + 1);

    // Where the function's own coefficients give the velocity exactly
    const word name(d.get<word>("solidBodyMotionFunction"));
    const dictionary& coeffs = d.optionalSubDict(name + "Coeffs");
    if (name == "rotatingMotion")
    {
        origin_[m] = coeffs.get<vector>("origin");
        axis_[m] = coeffs.get<vector>("axis");
        const vector& a = axis_[m];
        if (a.x() != 0 || a.y() != 0 || mag(mag(a.z()) - 1) > 1e-12)
        {
            FatalIOErrorInFunction(coeffs)
                << "Entry axis " << a << " of " << e.keyword() << ": a wall of"
                << " the x-y plane turns about (0 0 1) or (0 0 -1)"
                << exit(FatalIOError);
        }
        omega_.set(m, Function1<scalar>::New("omega", coeffs).ptr());
    }
    else if (name == "linearMotion")
    {
        velocity_[m] = coeffs.get<vector>("velocity");
        if (velocity_[m].z() != 0)
        {
            FatalIOErrorInFunction(coeffs)
                << "Entry velocity " << velocity_[m] << " of " << e.keyword()
                << ": its z component must be 0 (the walls are in the x-y"
                << " plane)" << exit(FatalIOError);
        }
    }
}


void Foam::SPH::wallMotion::read(const dictionary& dynamicMeshDict)
{
    const wordList& patches = walls_.patchNames();
    patchMotion_.setSize(patches.size(), -1);

    // No file, or a static mesh: no wall moves
    if
    (
        dynamicMeshDict.empty()
     || dynamicMeshDict.getOrDefault<word>("dynamicFvMesh", word::null)
     == "staticFvMesh"
    )
    {
        return;
    }
    const word solver(dynamicMeshDict.getOrDefault<word>("motionSolver", word::null));
    if (solver != "multiSolidBodyMotionSolver")
    {
        FatalIOErrorInFunction(dynamicMeshDict)
            << "motionSolver '" << solver << "': sphFoam moves wall patches"
            << " with 'motionSolver multiSolidBodyMotionSolver;', the patches"
            << " named in multiSolidBodyMotionSolverCoeffs, e.g." << nl
            << "    multiSolidBodyMotionSolverCoeffs" << nl
            << "    {" << nl
            << "        stirrer" << nl
            << "        {" << nl
            << "            solidBodyMotionFunction rotatingMotion;" << nl
            << "            rotatingMotionCoeffs" << nl
            << "            {" << nl
            << "                origin (0.5 0.5 0); axis (0 0 1); omega 2;" << nl
            << "            }" << nl
            << "        }" << nl
            << "    }" << exit(FatalIOError);
    }

    // As multiSolidBodyMotionSolver: every sub-dictionary of the Coeffs
    // (or of the file when it has none) is an entry
    const dictionary& coeffs =
        dynamicMeshDict.optionalSubDict("multiSolidBodyMotionSolverCoeffs");

    // The entry of each patch: its own name, then the last pattern that
    // matches
    List<const entry*> patchEntry(patches.size(), nullptr);
    DynamicList<const entry*> used;
    forAll(patches, patchi)
    {
        const entry* e = coeffs.findEntry(patches[patchi], keyType::REGEX);
        if (e && e->isDict())
        {
            patchEntry[patchi] = e;
            if (!used.found(e)) used.append(e);
        }
    }
    for (const entry& e : coeffs)
    {
        if (!e.isDict() || used.found(&e))
        {
            continue;
        }
        FatalIOErrorInFunction(e.dict())
            << (e.keyword().isPattern() ? "Pattern " : "No wall patch ")
            << e.keyword()
            << (e.keyword().isPattern() ? " matches no wall patch" : "")
            << " of the SPH mesh (constant/sphMesh/walls/patchNames): the keys"
            << " of multiSolidBodyMotionSolverCoeffs name wall patches (where"
            << " OpenFOAM's name cellZones)" << nl
            << "Wall patches: " << joined(patches).c_str() << exit(FatalIOError);
    }

    for (const entry* e : used)
    {
        readEntry(*e);
    }
    forAll(patches, patchi)
    {
        patchMotion_[patchi] = used.find(patchEntry[patchi]);
    }
}


Foam::septernion Foam::SPH::wallMotion::transformation
(
    const label m,
    const scalar t
) const
{
    // At t = 0 these motions are at rest by their formulas; and OpenFOAM
    // v1912's table, integrating omega over [0, 0] for rotatingMotion,
    // writes outside its index list (TableBase::integrate with t2 at the
    // first sample): so they are not called there
    if (t == 0 && identityAtZero(dicts_[m]))
    {
        return septernion::I;
    }

    // The functions read time_.value(); nothing else of the private Time
    time_->value() = t;
    return functions_[m].transformation();
}


Foam::vector2D Foam::SPH::wallMotion::transform
(
    const label m,
    const septernion& tr,
    const vector2D& x0
) const
{
    const vector x(tr.transformPoint(vector(x0.x(), x0.y(), 0)));
    if (mag(x.z()) > 1e-12*(1 + mag(x)))
    {
        FatalIOErrorInFunction(dicts_[m])
            << "The " << type(m) << " of " << keys_[m] << " moves the wall"
            << " point " << x0 << " to " << x << ", out of the x-y plane: a"
            << " wall moves along x and y and turns about z"
            << exit(FatalIOError);
    }
    return vector2D(x.x(), x.y());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::wallMotion::wallMotion
(
    const dictionary& dynamicMeshDict,
    const Time& runTime,
    const wallMesh& walls
)
:
    walls_(walls),
    time_(Time::New(runTime.path()))
{
    read(dynamicMeshDict);
}


Foam::SPH::wallMotion::wallMotion(const Time& runTime, const wallMesh& walls)
:
    wallMotion
    (
        IOdictionary
        (
            IOobject
            (
                "dynamicMeshDict",
                runTime.constant(),
                runTime,
                IOobject::READ_IF_PRESENT,
                IOobject::NO_WRITE,
                false
            )
        ),
        runTime,
        walls
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::wallMotion::move
(
    const label m,
    const scalar t,
    const UList<vector2D>& x0,
    const labelUList& points,
    UList<vector2D>& x,
    UList<vector2D>& U
) const
{
    const septernion T(transformation(m, t));
    for (const label p : points)
    {
        x[p] = transform(m, T, x0[p]);
    }

    if (omega_.set(m))
    {
        // omega(t) e x (x - origin)
        const scalar omega = omega_[m].value(t);
        for (const label p : points)
        {
            const vector d(x[p].x() - origin_[m].x(), x[p].y() - origin_[m].y(), 0);
            const vector u(omega*(axis_[m] ^ d));
            U[p] = vector2D(u.x(), u.y());
        }
    }
    else if (functions_[m].type() == "linearMotion")
    {
        for (const label p : points)
        {
            U[p] = vector2D(velocity_[m].x(), velocity_[m].y());
        }
    }
    else if (t >= differenceStep)
    {
        // Central difference, error h^2/6 |x'''| + eps |x|/h
        const scalar h = differenceStep;
        const septernion Tm(transformation(m, t - h));
        const septernion Tp(transformation(m, t + h));
        for (const label p : points)
        {
            U[p] = (transform(m, Tp, x0[p]) - transform(m, Tm, x0[p]))/(2*h);
        }
    }
    else
    {
        // One-sided, second order: the functions may not go before t = 0
        const scalar h = differenceStep;
        const septernion T1(transformation(m, t + h));
        const septernion T2(transformation(m, t + 2*h));
        for (const label p : points)
        {
            U[p] =
                (
                  - 3*x[p]
                  + 4*transform(m, T1, x0[p])
                  - transform(m, T2, x0[p])
                )/(2*h);
        }
    }
}


Foam::string Foam::SPH::wallMotion::describe(const label m) const
{
    OStringStream os;
    os  << type(m) << " (constant/dynamicMeshDict)";
    if (omega_.set(m))
    {
        os  << " about " << vector2D(origin_[m].x(), origin_[m].y())
            << " at omega " << omega_[m].type() << " [rad/s]; velocity exact";
    }
    else if (type(m) == "linearMotion")
    {
        os  << " at " << vector2D(velocity_[m].x(), velocity_[m].y());
    }
    else
    {
        os  << "; velocity by a central difference over "
            << 2*differenceStep << " s";
    }
    return os.str();
}


// ************************************************************************* //
