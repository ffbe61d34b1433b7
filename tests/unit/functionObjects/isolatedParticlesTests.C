/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The isolatedParticles function object on the test tank's lattice block
    (dr = 0.02, 50 x 25 particles) with particles added beside it:
    - the block alone has none isolated and none sparse (a lattice
      particle has 12 others within 2 dr, a face 8, a corner 5);
    - a lone particle far away is isolated and sparse; a pair 1.2 dr apart
      is sparse, not isolated; a particle 1.6 dr from the block's face is
      isolated (none within 1.5 dr) and sparse (3 within 2 dr); a lone
      particle dr/2 from the right wall is sparse by a wall, the others not;
    - the file has the fractions and the counts;
    - a radius beyond the search's reach is refused, naming the entry.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "isolatedParticles.H"

using namespace Foam;

namespace
{
    const SPH::functionObjects::isolatedParticles& asSpray
    (
        const autoPtr<functionObject>& fo
    )
    {
        return refCast<const SPH::functionObjects::isolatedParticles>(fo());
    }
}


TEST(isolatedParticles, latticeBlockHasNoneIsolatedNorSparse)
{
    sphTest::sphTank tank("sprayBlock");
    auto fo = tank.fo("spray", "type isolatedParticles;");
    fo->execute();
    EXPECT_EQ(asSpray(fo).nIsolated(), 0);
    EXPECT_EQ(asSpray(fo).nSparse(), 0);
}


TEST(isolatedParticles, countsLoneParticlesPairsAndNearOnes)
{
    sphTest::tankSpec spec;
    const scalar dr = spec.dr;
    // The block's last column is at x = 1 - dr/2, its top row y = H - dr/2
    spec.extraFluid = List<vector2D>
    ({
        vector2D(1.6, 0.8),                             // lone
        vector2D(1.4, 0.8), vector2D(1.4 + 1.2*dr, 0.8),  // a pair
        vector2D(1 - 0.5*dr + 1.6*dr, 0.25 + 0.5*dr),  // beside the face
        vector2D(2 - 0.5*dr, 0.8)                       // on the right wall
    });
    sphTest::sphTank tank("spraySome", spec);
    auto fo = tank.fo("spray", "type isolatedParticles;");
    fo->execute();
    // The lone ones (in the air, on the wall) and the near one
    EXPECT_EQ(asSpray(fo).nIsolated(), 3);
    EXPECT_EQ(asSpray(fo).nSparse(), 5);        // all five
    EXPECT_EQ(asSpray(fo).nSparseByWall(), 1);  // the one on the wall

    // One neighbour is enough: only the lone ones are sparse
    auto two = tank.fo("two", "type isolatedParticles; minNeighbours 1;");
    two->execute();
    EXPECT_EQ(asSpray(two).nSparse(), 2);
}


TEST(isolatedParticles, fileHasFractionsAndCounts)
{
    sphTest::tankSpec spec;
    spec.extraFluid = List<vector2D>({vector2D(1.6, 0.8)});
    sphTest::sphTank tank("sprayFile", spec);
    auto fo = tank.fo("spray", "type isolatedParticles;");
    tank.runTime->setTime(0.1, 1);
    fo->execute();
    fo->write();

    const fileName file = tank.postProcessing("spray/0/isolatedParticles.dat");
    const std::vector<std::string> lines = sphTest::readLines(file);
    ASSERT_GE(lines.size(), 2u);
    EXPECT_EQ(lines[0].rfind("# Isolated and sparse", 0), 0u) << lines[0];
    const std::vector<std::string> data = sphTest::dataLines(file);
    ASSERT_EQ(data.size(), 1u);
    std::istringstream row(data[0]);
    double t, isolated, sparse;
    label nIsolated, nSparse, nFluid, nSparseByWall = -1;
    row >> t >> isolated >> sparse >> nIsolated >> nSparse >> nFluid >> nSparseByWall;
    EXPECT_EQ(nFluid, tank.nFluid);
    EXPECT_EQ(nIsolated, 1);
    EXPECT_EQ(nSparse, 1);
    EXPECT_EQ(nSparseByWall, 0);
    EXPECT_NEAR(isolated, 1.0/tank.nFluid, 1e-8);
}


TEST(isolatedParticles, radiusBeyondTheSearchIsRefused)
{
    sphTest::throwOnFatal();
    sphTest::sphTank tank("sprayBad");
    try
    {
        tank.fo("spray", "type isolatedParticles; sparseRadius 3;");
        FAIL() << "sparseRadius 3 accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("sparseRadius"), std::string::npos) << msg;
    }
}
