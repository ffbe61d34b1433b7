/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The wall models of wcsphFoam (src/sph/solvers/wcsph/wallModels): chosen
    by the word boundaryMethod of system/sphSchemes through OpenFOAM's
    run-time selection table; an unknown word is a fatal IO error naming
    the entry and listing the valid words.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wcsphWallModel.H"
#include "wallShape.H"
#include "particles.H"

using namespace Foam;
using namespace Foam::SPH;

namespace
{
    wallMesh tankWalls(const scalar dr)
    {
        const dictionary box(sphTest::dict("type box; min (0 0); max (1 0.5);"));
        const List<List<wallChain>> chains
        (
            1, wallShape::New("tank", box)->chains(dr)
        );
        return wallMesh(wordList(1, "tank"), chains, dr);
    }
}


TEST(wcsphWallModel, bothMethodsAreRegistered)
{
    const wordList names =
        wcsphWallModel::dictionaryConstructorTablePtr_->sortedToc();
    EXPECT_NE(names.find("usaw"), -1);
    EXPECT_NE(names.find("dummyRepulsive"), -1);
}


TEST(wcsphWallModel, unknownBoundaryMethodIsAnErrorListingTheValidOnes)
{
    sphTest::throwOnFatal();
    const fileName dir = sphTest::makeCase("wcsphWallModelUnknown");
    auto runTime = sphTest::makeTime(dir);
    const scalar dr = 0.1;
    const wallMesh walls(tankWalls(dr));
    const dictionary schemes
    (
        sphTest::dict("kernel wendlandC2; hByDr 2; boundaryMethod ghostParticles;")
    );
    const autoPtr<kernel> W(kernel::New(schemes, dr));
    particles parts(*runTime, runTime->timeName());
    neighbourList nbrs(true);
    wcsphWork work(parts, nbrs);
    try
    {
        wcsphWallModel::New(*runTime, schemes, walls, *W, work);
        FAIL() << "boundaryMethod ghostParticles accepted";
    }
    catch (const Foam::IOerror& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("boundaryMethod"), std::string::npos) << msg;
        EXPECT_NE(msg.find("ghostParticles"), std::string::npos) << msg;
        EXPECT_NE(msg.find("usaw"), std::string::npos) << msg;
        EXPECT_NE(msg.find("dummyRepulsive"), std::string::npos) << msg;
    }
}
