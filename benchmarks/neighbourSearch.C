/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Neighbour search on 10^6 particles on a square lattice of spacing dr
    (1000 x 1000, non-periodic box), search radius 2 dr and 3 dr (the
    supports of wendlandC2 and cubicSpline at their defaults are 4 dr and
    2.6 dr; 2 dr and 3 dr bracket the cheap end), on 1 and 2 OpenMP threads:

    - cellListBuild:      counting sort of the particles into cells
    - neighbourListBuild: CSR lists from a built cell list (arg geometry:
                          also store rij and r)
    - buildAndList:       both, as a solver does every step
    - verletRefresh:      new rij and r for the pairs of a list built with
                          radius + 0.2 radius (the skin), which a solver
                          does instead of buildAndList while no particle
                          has moved half the skin

    Pairs are directed (i, j), self excluded; rates are per wall-clock
    second. One untimed build first: a solver rebuilds into storage sized
    by the previous step, so allocation and first-touch page faults are
    not part of the steady state measured here. On the lattice, pairs at
    exactly the radius are in or out by rounding of (i + 1/2) dr, so the
    pair counts are slightly above 8 and 24 per particle.

    A measurement, not a test: run it with benchmarks/Allrun.

\*---------------------------------------------------------------------------*/

#include "cellLinkedList.H"
#include "neighbourList.H"

#include <benchmark/benchmark.h>
#include <omp.h>

using namespace Foam;

namespace
{
    const label nSide = 1000;
    const scalar dr = 1e-3;

    //- The lattice, built once: (i + 1/2, j + 1/2) dr in [0, nSide dr]^2
    const List<vector2D>& lattice()
    {
        static const List<vector2D> pts = []
        {
            List<vector2D> p(nSide*nSide);
            for (label j = 0; j < nSide; ++j)
            {
                for (label i = 0; i < nSide; ++i)
                {
                    p[j*nSide + i] = vector2D((i + 0.5)*dr, (j + 0.5)*dr);
                }
            }
            return p;
        }();
        return pts;
    }

    SPH::cellLinkedList makeCells(const scalar radius)
    {
        return SPH::cellLinkedList
        (
            vector2D(0, 0), vector2D(nSide*dr, nSide*dr), radius
        );
    }

    //- Particles per second, and pairs per second when pairs were listed
    void setCounters
    (
        benchmark::State& state,
        const label nPairs,
        const label nPoints
    )
    {
        const double n = state.iterations();
        state.counters["particles/s"] =
            benchmark::Counter(n*nPoints, benchmark::Counter::kIsRate);
        if (nPairs)
        {
            state.counters["pairs"] = nPairs;
            state.counters["pairs/s"] =
                benchmark::Counter(n*nPairs, benchmark::Counter::kIsRate);
        }
    }
}


// Args: radius/dr, threads
static void cellListBuild(benchmark::State& state)
{
    const scalar radius = state.range(0)*dr;
    omp_set_num_threads(state.range(1));
    const List<vector2D>& x = lattice();
    SPH::cellLinkedList cells(makeCells(radius));
    cells.build(x);

    for (auto _ : state)
    {
        cells.build(x);
        benchmark::ClobberMemory();
    }
    setCounters(state, 0, x.size());
}


// Args: radius/dr, threads, store geometry (0/1)
static void neighbourListBuild(benchmark::State& state)
{
    const scalar radius = state.range(0)*dr;
    omp_set_num_threads(state.range(1));
    const List<vector2D>& x = lattice();
    SPH::cellLinkedList cells(makeCells(radius));
    cells.build(x);
    SPH::neighbourList nbrs(state.range(2) != 0);
    nbrs.build(cells, x, radius, true);

    for (auto _ : state)
    {
        nbrs.build(cells, x, radius, true);
        benchmark::ClobberMemory();
    }
    setCounters(state, nbrs.nPairs(), x.size());
}


// Args: radius/dr, threads
static void buildAndList(benchmark::State& state)
{
    const scalar radius = state.range(0)*dr;
    omp_set_num_threads(state.range(1));
    const List<vector2D>& x = lattice();
    SPH::cellLinkedList cells(makeCells(radius));
    SPH::neighbourList nbrs;
    cells.build(x);
    nbrs.build(cells, x, radius, true);

    for (auto _ : state)
    {
        cells.build(x);
        nbrs.build(cells, x, radius, true);
        benchmark::ClobberMemory();
    }
    setCounters(state, nbrs.nPairs(), x.size());
}


// Args: radius/dr, threads
static void verletRefresh(benchmark::State& state)
{
    const scalar radius = 1.2*state.range(0)*dr;
    omp_set_num_threads(state.range(1));
    const List<vector2D>& x = lattice();
    SPH::cellLinkedList cells(makeCells(radius));
    SPH::neighbourList nbrs(true);
    cells.build(x);
    nbrs.build(cells, x, radius, true);

    for (auto _ : state)
    {
        nbrs.refresh(cells, x, x);
        benchmark::ClobberMemory();
    }
    setCounters(state, nbrs.nPairs(), x.size());
}


BENCHMARK(cellListBuild)
    ->ArgsProduct({{2, 3}, {1, 2}})
    ->ArgNames({"radiusByDr", "threads"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK(neighbourListBuild)
    ->ArgsProduct({{2, 3}, {1, 2}, {0, 1}})
    ->ArgNames({"radiusByDr", "threads", "geometry"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK(buildAndList)
    ->ArgsProduct({{2, 3}, {1, 2}})
    ->ArgNames({"radiusByDr", "threads"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK(verletRefresh)
    ->ArgsProduct({{2, 3}, {1, 2}})
    ->ArgNames({"radiusByDr", "threads"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();


// ************************************************************************* //
