/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "BoomerAMG.H"
#include "error.H"

#include <mpi.h>
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>

#include <cstdlib>
#include <numeric>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::SPH::BoomerAMG::coarseningType>
Foam::SPH::BoomerAMG::coarseningTypeNames
({
    { coarseningType::HMIS, "HMIS" },
    { coarseningType::PMIS, "PMIS" },
    { coarseningType::Falgout, "Falgout" },
});

const Foam::Enum<Foam::SPH::BoomerAMG::interpolationType>
Foam::SPH::BoomerAMG::interpolationTypeNames
({
    { interpolationType::extendedI, "extendedI" },
    { interpolationType::classical, "classical" },
    { interpolationType::direct, "direct" },
});

const Foam::Enum<Foam::SPH::BoomerAMG::smootherType>
Foam::SPH::BoomerAMG::smootherTypeNames
({
    { smootherType::symmetricGaussSeidel, "symmetricGaussSeidel" },
    { smootherType::GaussSeidel, "GaussSeidel" },
    { smootherType::Jacobi, "Jacobi" },
    { smootherType::l1GaussSeidel, "l1GaussSeidel" },
});


namespace
{

// hypre's numbers for the choices (hypre reference manual, BoomerAMG)
int hypreCoarsening(Foam::SPH::BoomerAMG::coarseningType t)
{
    using T = Foam::SPH::BoomerAMG::coarseningType;
    return t == T::HMIS ? 10 : t == T::PMIS ? 8 : 6;
}

int hypreInterpolation(Foam::SPH::BoomerAMG::interpolationType t)
{
    using T = Foam::SPH::BoomerAMG::interpolationType;
    return t == T::extendedI ? 6 : t == T::classical ? 0 : 3;
}

int hypreSmoother(Foam::SPH::BoomerAMG::smootherType t)
{
    using T = Foam::SPH::BoomerAMG::smootherType;
    switch (t)
    {
        case T::symmetricGaussSeidel: return 6;
        case T::GaussSeidel: return 3;
        case T::Jacobi: return 0;
        case T::l1GaussSeidel: return 8;
    }
    return 6;
}


// hypre needs MPI. A parallel OpenFOAM run has initialised it; a serial
// run has not, and then it is started here, once, and finalised at exit
// (after every hypre object, which live no longer than main).
void finaliseMPI()
{
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised)
    {
        HYPRE_Finalize();
        MPI_Finalize();
    }
}

void initialiseHypre()
{
    static const bool done = []
    {
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised)
        {
            MPI_Init(nullptr, nullptr);
            std::atexit(finaliseMPI);
        }
        HYPRE_Init();
        return true;
    }();
    (void)done;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * hierarchy * * * * * * * * * * * * * * * //

class Foam::SPH::BoomerAMG::hierarchy
{
public:

    HYPRE_IJMatrix A = nullptr;
    HYPRE_IJVector b = nullptr;
    HYPRE_IJVector x = nullptr;
    HYPRE_Solver amg = nullptr;
    HYPRE_ParCSRMatrix parA = nullptr;
    HYPRE_ParVector parB = nullptr;
    HYPRE_ParVector parX = nullptr;

    //- Row indices 0 ... n-1, for the vector copies
    std::vector<HYPRE_BigInt> rows;
    std::vector<HYPRE_Complex> zero;

    Eigen::Index n = 0;
    bool setupFailed = false;

    // The rule of reuse
    label nBuilds = 0;
    label solvesSinceBuild = 0;
    label iterationsAfterBuild = -1;
    label lastIterations = 0;
    bool expired = true;

    hierarchy() = default;
    hierarchy(const hierarchy&) = delete;
    void operator=(const hierarchy&) = delete;

    ~hierarchy()
    {
        release();
    }

    void release()
    {
        if (amg) HYPRE_BoomerAMGDestroy(amg);
        if (x) HYPRE_IJVectorDestroy(x);
        if (b) HYPRE_IJVectorDestroy(b);
        if (A) HYPRE_IJMatrixDestroy(A);
        amg = nullptr;
        x = b = nullptr;
        A = nullptr;
    }

    bool mustRebuild(const Eigen::Index size, const label reuse) const
    {
        return
            expired || !amg || size != n || solvesSinceBuild >= reuse
         || (
                iterationsAfterBuild >= 0
             && lastIterations > 2*iterationsAfterBuild + 2
            );
    }

    void build
    (
        const controls& c,
        const Eigen::Index size,
        const int* rowStart,
        const int* columns,
        const scalar* values
    );
};


void Foam::SPH::BoomerAMG::hierarchy::build
(
    const controls& c,
    const Eigen::Index size,
    const int* rowStart,
    const int* columns,
    const scalar* values
)
{
    release();
    n = size;
    const HYPRE_BigInt last = HYPRE_BigInt(n) - 1;

    // The matrix, row by row from Eigen's compressed rows
    HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, last, 0, last, &A);
    HYPRE_IJMatrixSetObjectType(A, HYPRE_PARCSR);
    std::vector<HYPRE_Int> rowSizes(n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        rowSizes[i] = rowStart[i + 1] - rowStart[i];
    }
    HYPRE_IJMatrixSetRowSizes(A, rowSizes.data());
    HYPRE_IJMatrixInitialize(A);

    rows.resize(n);
    std::iota(rows.begin(), rows.end(), HYPRE_BigInt(0));
    zero.assign(n, 0.0);
    const std::vector<HYPRE_BigInt> bigColumns
    (
        columns + rowStart[0], columns + rowStart[n]
    );
    HYPRE_IJMatrixSetValues
    (
        A, HYPRE_Int(n), rowSizes.data(), rows.data(), bigColumns.data(),
        values + rowStart[0]
    );
    HYPRE_IJMatrixAssemble(A);
    HYPRE_IJMatrixGetObject(A, reinterpret_cast<void**>(&parA));

    for (HYPRE_IJVector* v : {&b, &x})
    {
        HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, last, v);
        HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
        HYPRE_IJVectorInitialize(*v);
        HYPRE_IJVectorAssemble(*v);
    }
    HYPRE_IJVectorGetObject(b, reinterpret_cast<void**>(&parB));
    HYPRE_IJVectorGetObject(x, reinterpret_cast<void**>(&parX));

    // One V-cycle from zero per application: a fixed linear operator, as
    // a preconditioner of a Krylov method must be
    HYPRE_BoomerAMGCreate(&amg);
    HYPRE_BoomerAMGSetPrintLevel(amg, 0);
    HYPRE_BoomerAMGSetMaxIter(amg, 1);
    HYPRE_BoomerAMGSetTol(amg, 0.0);
    HYPRE_BoomerAMGSetStrongThreshold(amg, c.strongThreshold);
    HYPRE_BoomerAMGSetCoarsenType(amg, hypreCoarsening(c.coarsening));
    HYPRE_BoomerAMGSetInterpType(amg, hypreInterpolation(c.interpolation));
    HYPRE_BoomerAMGSetPMaxElmts(amg, c.maxInterpolationEntries);
    HYPRE_BoomerAMGSetRelaxType(amg, hypreSmoother(c.smoother));
    HYPRE_BoomerAMGSetNumSweeps(amg, c.nSweeps);
    HYPRE_BoomerAMGSetAggNumLevels(amg, c.aggressiveLevels);

    setupFailed = HYPRE_BoomerAMGSetup(amg, parA, parB, parX) != 0;
    if (setupFailed)
    {
        HYPRE_ClearAllErrors();
    }

    ++nBuilds;
    solvesSinceBuild = 0;
    iterationsAfterBuild = -1;
    lastIterations = 0;
    expired = false;
}


std::shared_ptr<Foam::SPH::BoomerAMG::hierarchy>
Foam::SPH::BoomerAMG::newHierarchy()
{
    // MPI's start (a singleton Open MPI run spawns its daemon, about 0.3 s)
    // here, with the solver's construction, not in the first time step
    initialiseHypre();
    return std::make_shared<hierarchy>();
}


void Foam::SPH::BoomerAMG::record(hierarchy& h, const label nIterations)
{
    ++h.solvesSinceBuild;
    h.lastIterations = nIterations;
    if (h.iterationsAfterBuild < 0)
    {
        h.iterationsAfterBuild = nIterations;
    }
}


void Foam::SPH::BoomerAMG::expire(hierarchy& h)
{
    h.expired = true;
}


bool Foam::SPH::BoomerAMG::wasReused(const hierarchy& h)
{
    return h.solvesSinceBuild > 0;
}


Foam::label Foam::SPH::BoomerAMG::nBuilds(const hierarchy& h)
{
    return h.nBuilds;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::BoomerAMG::controls::controls(const dictionary& dict)
:
    strongThreshold(dict.getOrDefault<scalar>("strongThreshold", 0.5)),
    coarsening
    (
        coarseningTypeNames.getOrDefault
        (
            "coarsening", dict, coarseningType::HMIS
        )
    ),
    interpolation
    (
        interpolationTypeNames.getOrDefault
        (
            "interpolation", dict, interpolationType::extendedI
        )
    ),
    smoother
    (
        smootherTypeNames.getOrDefault
        (
            "smoother", dict, smootherType::GaussSeidel
        )
    ),
    nSweeps(dict.getOrDefault<label>("nSweeps", 1)),
    maxInterpolationEntries
    (
        dict.getOrDefault<label>("maxInterpolationEntries", 4)
    ),
    aggressiveLevels(dict.getOrDefault<label>("aggressiveLevels", 0)),
    reuse(dict.getOrDefault<label>("reuse", 10))
{
    if (!(strongThreshold > 0 && strongThreshold < 1))
    {
        FatalIOErrorInFunction(dict.lookup("strongThreshold"))
            << "Entry strongThreshold " << strongThreshold
            << ": expected 0 < strongThreshold < 1"
            << exit(FatalIOError);
    }
    if (nSweeps < 1)
    {
        FatalIOErrorInFunction(dict.lookup("nSweeps"))
            << "Entry nSweeps " << nSweeps << ": expected >= 1"
            << exit(FatalIOError);
    }
    if (maxInterpolationEntries < 0)
    {
        FatalIOErrorInFunction(dict.lookup("maxInterpolationEntries"))
            << "Entry maxInterpolationEntries " << maxInterpolationEntries
            << ": expected >= 0 (0: no limit)" << exit(FatalIOError);
    }
    if (aggressiveLevels < 0)
    {
        FatalIOErrorInFunction(dict.lookup("aggressiveLevels"))
            << "Entry aggressiveLevels " << aggressiveLevels
            << ": expected >= 0" << exit(FatalIOError);
    }
    if (reuse < 1)
    {
        FatalIOErrorInFunction(dict.lookup("reuse"))
            << "Entry reuse " << reuse
            << ": expected >= 1 (solves one hierarchy serves)"
            << exit(FatalIOError);
    }
}


Foam::SPH::BoomerAMG::BoomerAMG()
:
    controls_(),
    hierarchy_()
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::SPH::BoomerAMG::~BoomerAMG() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::BoomerAMG::controls::write(Ostream& os) const
{
    os  << "BoomerAMG (" << coarseningTypeNames[coarsening]
        << ", " << interpolationTypeNames[interpolation]
        << " interpolation, " << smootherTypeNames[smoother]
        << " x" << nSweeps << ", strongThreshold " << strongThreshold
        << ", maxInterpolationEntries " << maxInterpolationEntries
        << ", aggressiveLevels " << aggressiveLevels << ", reuse " << reuse
        << ")";
}


Eigen::Index Foam::SPH::BoomerAMG::rows() const
{
    return hierarchy_ ? hierarchy_->n : 0;
}


void Foam::SPH::BoomerAMG::setup
(
    const Eigen::Index n,
    const int* rowStart,
    const int* columns,
    const scalar* values
)
{
    initialiseHypre();
    if (!hierarchy_)
    {
        hierarchy_ = newHierarchy();
    }
    if (hierarchy_->mustRebuild(n, controls_.reuse))
    {
        hierarchy_->build(controls_, n, rowStart, columns, values);
    }
}


void Foam::SPH::BoomerAMG::solveInPlace(vectorN& x) const
{
    const hierarchy& d = *hierarchy_;
    const HYPRE_Int n = HYPRE_Int(d.n);

    HYPRE_IJVectorSetValues(d.b, n, d.rows.data(), x.data());
    HYPRE_IJVectorSetValues(d.x, n, d.rows.data(), d.zero.data());

    HYPRE_BoomerAMGSolve(d.amg, d.parA, d.parB, d.parX);
    // One cycle "fails" to reach tolerance 0 by design
    HYPRE_ClearAllErrors();

    HYPRE_IJVectorGetValues(d.x, n, d.rows.data(), x.data());
}


Eigen::ComputationInfo Foam::SPH::BoomerAMG::info() const
{
    return (hierarchy_ && hierarchy_->amg && !hierarchy_->setupFailed)
        ? Eigen::Success
        : Eigen::NumericalIssue;
}


// ************************************************************************* //
