/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "BoomerAMG.H"
#include "error.H"

#include <mpi.h>
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <type_traits>
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
// run has not, and then it is started here, once, and finalised by the
// solver's end (BoomerAMG::finalise) or at exit, after every hypre object
bool hypreStarted = false;
bool mpiStartedHere = false;

void finaliseHypre()
{
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised && mpiStartedHere)
    {
        if (hypreStarted) HYPRE_Finalize();
        MPI_Finalize();
    }
    hypreStarted = mpiStartedHere = false;
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
            mpiStartedHere = true;
            std::atexit(finaliseHypre);
        }
        HYPRE_Init();
        hypreStarted = true;
        return true;
    }();
    (void)done;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * hierarchy * * * * * * * * * * * * * * * //

struct Foam::SPH::BoomerAMG::hierarchy::hypreObjects
{
    HYPRE_IJMatrix A = nullptr;
    HYPRE_IJVector b = nullptr;
    HYPRE_IJVector x = nullptr;
    HYPRE_Solver amg = nullptr;
    HYPRE_ParCSRMatrix parA = nullptr;
    HYPRE_ParVector parB = nullptr;
    HYPRE_ParVector parX = nullptr;

    //- Row indices 0 ... n-1, for the matrix and the vector copies
    std::vector<HYPRE_BigInt> rows;

    bool setupFailed = false;

    hypreObjects(const controls& c, const Eigen::Index n);

    hypreObjects(const hypreObjects&) = delete;
    void operator=(const hypreObjects&) = delete;

    ~hypreObjects()
    {
        HYPRE_BoomerAMGDestroy(amg);
        HYPRE_IJVectorDestroy(x);
        HYPRE_IJVectorDestroy(b);
        HYPRE_IJMatrixDestroy(A);
    }
};


Foam::SPH::BoomerAMG::hierarchy::hypreObjects::hypreObjects
(
    const controls& c,
    const Eigen::Index n
)
:
    rows(n)
{
    std::iota(rows.begin(), rows.end(), HYPRE_BigInt(0));
    const HYPRE_BigInt last = HYPRE_BigInt(n) - 1;

    HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, last, 0, last, &A);
    HYPRE_IJMatrixSetObjectType(A, HYPRE_PARCSR);
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
}


void Foam::SPH::BoomerAMG::finalise()
{
    finaliseHypre();
}


Foam::SPH::BoomerAMG::compressedRows Foam::SPH::BoomerAMG::filtered
(
    const Eigen::Index n,
    const int* rowStart,
    const int* columns,
    const scalar* values,
    const scalar tolerance
)
{
    compressedRows f;
    f.start.reserve(n + 1);
    f.columns.reserve(rowStart[n] - rowStart[0]);
    f.values.reserve(rowStart[n] - rowStart[0]);
    f.start.push_back(0);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        const int begin = rowStart[i];
        const int end = rowStart[i + 1];
        scalar largest = 0;
        bool hasDiagonal = false;
        for (int k = begin; k < end; ++k)
        {
            if (columns[k] == i) hasDiagonal = true;
            else largest = std::max(largest, std::abs(values[k]));
        }
        const scalar limit = hasDiagonal ? tolerance*largest : 0;

        label diagonal = -1;
        scalar lumped = 0;
        for (int k = begin; k < end; ++k)
        {
            if (columns[k] != i && std::abs(values[k]) < limit)
            {
                lumped += values[k];
                continue;
            }
            if (columns[k] == i) diagonal = label(f.values.size());
            f.columns.push_back(columns[k]);
            f.values.push_back(values[k]);
        }
        if (diagonal >= 0) f.values[diagonal] += lumped;
        f.start.push_back(int(f.columns.size()));
    }
    return f;
}


Foam::SPH::BoomerAMG::hierarchy::hierarchy()
{
    // MPI's start (a singleton Open MPI run spawns its daemon, about 0.3 s)
    // here, with the solver's construction, not in the first time step
    initialiseHypre();
}


Foam::SPH::BoomerAMG::hierarchy::~hierarchy() = default;


bool Foam::SPH::BoomerAMG::hierarchy::mustRebuild
(
    const Eigen::Index n,
    const controls& c
) const
{
    return
        expired_ || !hypre_ || n != size() || solvesSinceBuild_ >= c.reuse
     || (
            iterationsAfterBuild_ >= 0
         && lastIterations_ > 2*iterationsAfterBuild_ + 2
        );
}


void Foam::SPH::BoomerAMG::hierarchy::build
(
    const controls& c,
    const Eigen::Index n,
    const int* rowStart,
    const int* columns,
    const scalar* values
)
{
    hypre_.reset();
    hypre_.reset(new hypreObjects(c, n));
    hypreObjects& h = *hypre_;

    nEntries_ += rowStart[n] - rowStart[0];
    compressedRows kept;
    if (c.filterTolerance > 0)
    {
        kept = filtered(n, rowStart, columns, values, c.filterTolerance);
        rowStart = kept.start.data();
        columns = kept.columns.data();
        values = kept.values.data();
    }
    nEntriesKept_ += rowStart[n] - rowStart[0];

    // The matrix, row by row from Eigen's compressed rows
    std::vector<HYPRE_Int> rowSizes(n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        rowSizes[i] = rowStart[i + 1] - rowStart[i];
    }
    HYPRE_IJMatrixSetRowSizes(h.A, rowSizes.data());
    HYPRE_IJMatrixInitialize(h.A);
    // Debian's hypre has 32-bit global indices, Eigen's: no copy then
    if constexpr (std::is_same<HYPRE_BigInt, int>::value)
    {
        HYPRE_IJMatrixSetValues
        (
            h.A, HYPRE_Int(n), rowSizes.data(), h.rows.data(),
            columns + rowStart[0], values + rowStart[0]
        );
    }
    else
    {
        const std::vector<HYPRE_BigInt> bigColumns
        (
            columns + rowStart[0], columns + rowStart[n]
        );
        HYPRE_IJMatrixSetValues
        (
            h.A, HYPRE_Int(n), rowSizes.data(), h.rows.data(),
            bigColumns.data(), values + rowStart[0]
        );
    }
    HYPRE_IJMatrixAssemble(h.A);
    HYPRE_IJMatrixGetObject(h.A, reinterpret_cast<void**>(&h.parA));

    h.setupFailed = HYPRE_BoomerAMGSetup(h.amg, h.parA, h.parB, h.parX) != 0;
    if (h.setupFailed)
    {
        HYPRE_ClearAllErrors();
    }

    ++nBuilds_;
    solvesSinceBuild_ = 0;
    iterationsAfterBuild_ = -1;
    lastIterations_ = 0;
    expired_ = false;
}


void Foam::SPH::BoomerAMG::hierarchy::cycle(vectorN& x) const
{
    const hypreObjects& h = *hypre_;
    const HYPRE_Int n = HYPRE_Int(h.rows.size());

    HYPRE_IJVectorSetValues(h.b, n, h.rows.data(), x.data());
    HYPRE_ParVectorSetConstantValues(h.parX, 0.0);

    HYPRE_BoomerAMGSolve(h.amg, h.parA, h.parB, h.parX);
    // One cycle "fails" to reach tolerance 0 by design
    HYPRE_ClearAllErrors();

    HYPRE_IJVectorGetValues(h.x, n, h.rows.data(), x.data());
}


Eigen::Index Foam::SPH::BoomerAMG::hierarchy::size() const
{
    return hypre_ ? Eigen::Index(hypre_->rows.size()) : 0;
}


bool Foam::SPH::BoomerAMG::hierarchy::built() const
{
    return hypre_ && !hypre_->setupFailed;
}


void Foam::SPH::BoomerAMG::hierarchy::record(const label nIterations)
{
    ++solvesSinceBuild_;
    lastIterations_ = nIterations;
    if (iterationsAfterBuild_ < 0)
    {
        iterationsAfterBuild_ = nIterations;
    }
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
    reuse(dict.getOrDefault<label>("reuse", 10)),
    filterTolerance(dict.getOrDefault<scalar>("filterTolerance", 0))
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
    if (!(filterTolerance >= 0 && filterTolerance < 1))
    {
        FatalIOErrorInFunction(dict.lookup("filterTolerance"))
            << "Entry filterTolerance " << filterTolerance
            << ": expected 0 <= filterTolerance < 1 (0: no filter)"
            << exit(FatalIOError);
    }
    if (reuse < 1)
    {
        FatalIOErrorInFunction(dict.lookup("reuse"))
            << "Entry reuse " << reuse
            << ": expected >= 1 (solves one hierarchy serves)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::BoomerAMG::controls::write(Ostream& os) const
{
    os  << "BoomerAMG (" << coarseningTypeNames[coarsening]
        << ", " << interpolationTypeNames[interpolation]
        << " interpolation, " << smootherTypeNames[smoother]
        << " x" << nSweeps << ", strongThreshold " << strongThreshold
        << ", maxInterpolationEntries " << maxInterpolationEntries
        << ", aggressiveLevels " << aggressiveLevels << ", reuse " << reuse
        << ", filterTolerance " << filterTolerance << ")";
}


// ************************************************************************* //
