/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Application
    writeCaseBi4

Description
    Writes the initial particle file <case>.bi4 that DualSPHysics reads,
    from a plain particle list, for the DualSPHysics side of
    benchmarks/dualSPHysicsZhou. GenCase, which normally writes this file,
    is shipped by DualSPHysics as a closed binary only (and it is not in
    the public snapshot we build from), so the benchmark lays its particles
    out itself and writes them through DualSPHysics' own open-source file
    class (JPartDataBi4): the format is the one the solver reads, written
    by the solver's code.

    This file is compiled by benchmarks/dualSPHysicsZhou against the
    DualSPHysics source tree given with -dsph, outside the project; nothing
    of DualSPHysics is built into sphFoam.

Usage
    writeCaseBi4 particles.txt outDir caseName dp h b rho0 gamma massBound massFluid

    particles.txt: a first line "nBound nFluid", then one line "x z rho" per
    particle, the boundary particles first. The case is 2-D in the x-z
    plane (y = 0), as DualSPHysics writes its 2-D cases.

\*---------------------------------------------------------------------------*/

#include "JPartDataBi4.h"
#include "Functions.h"

#include <cfloat>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{

struct ParticleList
{
    unsigned nBound = 0;
    unsigned nFluid = 0;
    std::vector<tdouble3> pos;
    std::vector<float> rho;
};


// The list the benchmark script writes; a bad file stops with its name
ParticleList readParticles(const char* fileName)
{
    ParticleList list;
    FILE* in = std::fopen(fileName, "r");
    if (!in || std::fscanf(in, "%u %u", &list.nBound, &list.nFluid) != 2)
    {
        std::fprintf(stderr, "writeCaseBi4: cannot read the counts \"nBound nFluid\" of %s\n", fileName);
        std::exit(1);
    }
    const unsigned n = list.nBound + list.nFluid;
    list.pos.resize(n);
    list.rho.resize(n);
    for (unsigned i = 0; i < n; ++i)
    {
        double x, z, rho;
        if (std::fscanf(in, "%lf %lf %lf", &x, &z, &rho) != 3)
        {
            std::fprintf(stderr, "writeCaseBi4: %s: particle %u of %u unreadable\n", fileName, i, n);
            std::exit(1);
        }
        list.pos[i] = TDouble3(x, 0, z);
        list.rho[i] = float(rho);
    }
    std::fclose(in);
    return list;
}

} // End anonymous namespace


int main(int argc, char** argv)
{
    if (argc != 11)
    {
        std::fprintf(stderr, "Usage: writeCaseBi4 particles.txt outDir caseName"
            " dp h b rho0 gamma massBound massFluid\n");
        return 1;
    }
    const ParticleList list = readParticles(argv[1]);
    const std::string outDir = argv[2], caseName = argv[3];
    const double dp = std::atof(argv[4]), h = std::atof(argv[5]), b = std::atof(argv[6]);
    const double rho0 = std::atof(argv[7]), gamma = std::atof(argv[8]);
    const double massBound = std::atof(argv[9]), massFluid = std::atof(argv[10]);

    const unsigned n = list.nBound + list.nFluid;
    tdouble3 posMin = TDouble3(DBL_MAX), posMax = TDouble3(-DBL_MAX);
    for (const tdouble3& p : list.pos)
    {
        posMin = MinValues(posMin, p);
        posMax = MaxValues(posMax, p);
    }
    std::vector<unsigned> idp(n);
    for (unsigned i = 0; i < n; ++i)
    {
        idp[i] = i;
    }
    const std::vector<tfloat3> vel(n, TFloat3(0));

    try
    {
        JPartDataBi4 bi4;
        bi4.ConfigBasic(0, 1, "00000000", "sphFoam writeCaseBi4", caseName, true, 0, outDir);
        bi4.ConfigParticles(n, list.nBound, 0, 0, list.nFluid, posMin, posMax, false, false);
        bi4.ConfigCtes(dp, h, b, rho0, gamma, massBound, massFluid);
        bi4.AddPartInfo(0, 0, n, 0, 0, 0, posMin, posMax, 0, 0);
        bi4.AddPartData(n, idp.data(), list.pos.data(), vel.data(), list.rho.data(), false);
        bi4.SaveFileCase(caseName);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "writeCaseBi4: %s\n", e.what());
        return 1;
    }
    std::printf("writeCaseBi4: %u boundary + %u fluid particles in %s/%s.bi4\n",
        list.nBound, list.nFluid, outDir.c_str(), caseName.c_str());
    return 0;
}
