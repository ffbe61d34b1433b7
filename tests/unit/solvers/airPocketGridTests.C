/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The pockets of isphFoam's airPockets (src/sph/solvers/isph/stages/
    airPockets/airPocketGrid.H): a ring of water encloses one pocket whose
    area is the hole's out to the surface line dr/2 beyond the particles;
    a U open upwards encloses none; in a closed tank the headspace is the
    atmosphere and a ring in the water still a pocket; a ring across a
    periodic seam is one pocket; the gaps of a disordered liquid are no
    pockets; a surface particle borders the pocket its normal points into.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "airPocketGrid.H"
#include "Random.H"
#include "DynamicList.H"

using namespace Foam;

namespace
{
    const scalar dr = 0.01;

    //- A lattice block [x0, x1) x [y0, y1) at spacing dr, minus the hole
    //- [hx0, hx1) x [hy0, hy1) (centres inside it are left out)
    void addBlock
    (
        DynamicList<vector2D>& x,
        const vector2D& lo, const vector2D& hi,
        const vector2D& holeLo = vector2D(1, 1)*GREAT,
        const vector2D& holeHi = vector2D(1, 1)*GREAT
    )
    {
        for (scalar y = lo.y() + 0.5*dr; y < hi.y(); y += dr)
        {
            for (scalar xx = lo.x() + 0.5*dr; xx < hi.x(); xx += dr)
            {
                const bool inHole =
                    xx > holeLo.x() && xx < holeHi.x()
                 && y > holeLo.y() && y < holeHi.y();
                if (!inHole) x.append(vector2D(xx, y));
            }
        }
    }

    const SPH::domain unitBox(vector2D(0, 0), vector2D(1, 1));

    //- The grid over the unit box after find() on a block with a hole
    SPH::airPocketGrid findBlock
    (
        const vector2D& lo, const vector2D& hi,
        const vector2D& holeLo, const vector2D& holeHi
    )
    {
        SPH::airPocketGrid grid(unitBox, dr, sqr(4*dr));
        DynamicList<vector2D> x;
        addBlock(x, lo, hi, holeLo, holeHi);
        grid.find(x);
        return grid;
    }

    //- The four walls of the box [0, L]^2
    void closedBox
    (
        SPH::airPocketGrid& grid,
        const scalar L
    )
    {
        const List<vector2D> points
        ({
            vector2D(0, 0), vector2D(L, 0), vector2D(L, L), vector2D(0, L)
        });
        const List<labelPair> segments
        ({
            labelPair(0, 1), labelPair(1, 2), labelPair(2, 3), labelPair(3, 0)
        });
        grid.setWalls(points, segments);
    }
}


TEST(airPocketGrid, aRingOfWaterEnclosesOnePocketOfItsHolesArea)
{
    // Water 0.1-0.5 m square with a 0.2 m hole: the rows round the hole sit
    // dr/2 outside its edge, so the surface lines dr/2 beyond them are the
    // edge and the air is 0.2^2
    const SPH::airPocketGrid grid
    (
        findBlock(vector2D(0.1, 0.1), vector2D(0.5, 0.5), vector2D(0.2, 0.2), vector2D(0.4, 0.4))
    );
    ASSERT_EQ(grid.size(), 1);
    EXPECT_NEAR(grid.area(0), sqr(0.2), 0.03*sqr(0.2));
    EXPECT_EQ(grid.at(vector2D(0.3, 0.3)), 0);
    EXPECT_EQ(grid.at(vector2D(0.7, 0.7)), label(SPH::airPocketGrid::atmosphere));
    EXPECT_EQ(grid.at(vector2D(0.15, 0.15)), label(SPH::airPocketGrid::water));
}


TEST(airPocketGrid, aUOpenUpwardsEnclosesNone)
{
    const SPH::airPocketGrid grid
    (
        findBlock(vector2D(0.1, 0.1), vector2D(0.5, 0.5), vector2D(0.2, 0.2), vector2D(0.4, 0.6))
    );
    EXPECT_EQ(grid.size(), 0);
    EXPECT_EQ(grid.at(vector2D(0.3, 0.3)), label(SPH::airPocketGrid::atmosphere));
}


TEST(airPocketGrid, aClosedTanksHeadspaceIsTheAtmosphereAndARingInItsWaterAPocket)
{
    SPH::airPocketGrid grid(unitBox, dr, sqr(4*dr));
    closedBox(grid, 1);
    DynamicList<vector2D> x;
    addBlock(x, vector2D(0, 0), vector2D(1, 0.5), vector2D(0.3, 0.1), vector2D(0.5, 0.3));
    grid.find(x);
    ASSERT_EQ(grid.size(), 1);
    EXPECT_NEAR(grid.area(0), sqr(0.2), 0.03*sqr(0.2));
    EXPECT_EQ(grid.at(vector2D(0.5, 0.8)), label(SPH::airPocketGrid::atmosphere));

    // The water up to the lid: then nothing is left to be the atmosphere
    // but the enclosed hole, the largest wet air, at p = 0
    x.clear();
    addBlock(x, vector2D(0, 0), vector2D(1, 1), vector2D(0.3, 0.1), vector2D(0.5, 0.3));
    grid.find(x);
    EXPECT_EQ(grid.size(), 0);
}


TEST(airPocketGrid, aWalledObstaclesInsideIsNoPocket)
{
    // A square of walls in open water: the water's distances reach into it,
    // but no fluid particle is inside
    SPH::airPocketGrid grid(unitBox, dr, sqr(4*dr));
    const List<vector2D> points
    ({
        vector2D(0.4, 0.2), vector2D(0.6, 0.2), vector2D(0.6, 0.4), vector2D(0.4, 0.4)
    });
    grid.setWalls
    (
        points,
        List<labelPair>
        ({labelPair(0, 1), labelPair(1, 2), labelPair(2, 3), labelPair(3, 0)})
    );
    DynamicList<vector2D> x;
    addBlock(x, vector2D(0.1, 0.1), vector2D(0.9, 0.6), vector2D(0.4, 0.2), vector2D(0.6, 0.4));
    grid.find(x);
    EXPECT_EQ(grid.size(), 0);
    EXPECT_EQ(grid.at(vector2D(0.5, 0.3)), label(SPH::airPocketGrid::solid));
}


TEST(airPocketGrid, aRingAcrossAPeriodicSeamIsOnePocket)
{
    const SPH::domain dom(vector2D(0, 0), vector2D(1, 1), {true, false});
    SPH::airPocketGrid grid(dom, dr, sqr(4*dr));
    DynamicList<vector2D> x;
    addBlock(x, vector2D(0, 0.1), vector2D(0.2, 0.5), vector2D(-1, 0.2), vector2D(0.1, 0.4));
    addBlock(x, vector2D(0.8, 0.1), vector2D(1, 0.5), vector2D(0.9, 0.2), vector2D(2, 0.4));
    grid.find(x);
    ASSERT_EQ(grid.size(), 1);
    EXPECT_NEAR(grid.area(0), sqr(0.2), 0.03*sqr(0.2));
    EXPECT_EQ(grid.at(vector2D(0.02, 0.3)), grid.at(vector2D(0.98, 0.3)));
}


TEST(airPocketGrid, theGapsOfADisorderedLiquidAreNoPockets)
{
    SPH::airPocketGrid grid(unitBox, dr, sqr(4*dr));
    DynamicList<vector2D> x;
    addBlock(x, vector2D(0.1, 0.1), vector2D(0.9, 0.6));
    Random rnd(7);
    for (vector2D& xi : x)
    {
        xi += 0.25*dr*vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
    }
    grid.find(x);
    EXPECT_EQ(grid.size(), 0);
    for (const label l : grid.cellLabels())
    {
        ASSERT_NE(l, label(SPH::airPocketGrid::unresolved));
    }
}


TEST(airPocketGrid, aSurfaceParticleBordersThePocketItsNormalPointsInto)
{
    const SPH::airPocketGrid grid
    (
        findBlock(vector2D(0.1, 0.1), vector2D(0.5, 0.5), vector2D(0.2, 0.2), vector2D(0.4, 0.4))
    );
    ASSERT_EQ(grid.size(), 1);
    // The hole's top row (y = 0.405) faces down into it, the block's top
    // row (y = 0.495) up into the atmosphere
    EXPECT_EQ(grid.borderedPocket(vector2D(0.3, 0.405), vector2D(0, -1)), 0);
    EXPECT_EQ(grid.borderedPocket(vector2D(0.3, 0.495), vector2D(0, 1)), -1);
    EXPECT_EQ(grid.borderedPocket(vector2D(0.3, 0.405), vector2D::zero), 0);
    EXPECT_EQ(grid.borderedPocket(vector2D(0.3, 0.495), vector2D::zero), -1);
}


// ************************************************************************* //
