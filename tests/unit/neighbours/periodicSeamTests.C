/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The neighbour search at a periodic seam, with the box of an SPH::domain:
    cellLinkedList wraps as domain::wrap does (x = min - 1e-17 is min, not
    max; -0.0 and points inside unchanged), and neighbourList's rij is the
    minimum image: particles at x = 0.01 and 0.99 of a period 1 are 0.02
    apart, points given on either side of the seam are the same point.

    Tolerances: separations through the seam carry the round-off of one
    subtraction of the period, 2 ulp of 1.

\*---------------------------------------------------------------------------*/

#include "neighbourTestTools.H"
#include "neighbourList.H"
#include "domain.H"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace Foam;
using namespace neighbourTest;

namespace
{
    const scalar eps = std::numeric_limits<scalar>::epsilon();
    const SPH::domain channel(vector2D(0, 0), vector2D(1, 1), {true, false});
}


TEST(periodicSeam, cellListWrapsAsTheDomain)
{
    const SPH::cellLinkedList cells(channel, 0.1);
    EXPECT_EQ(cells.min(), channel.min());
    EXPECT_EQ(cells.max(), channel.max());
    EXPECT_EQ(cells.periodic(), channel.periodic());

    for
    (
        const scalar x :
        {0.0, -0.0, 1.0, -1e-17, std::nextafter(1.0, 0.0), 0.5, 3.7, -2.2, 1 + 1e-16}
    )
    {
        const vector2D p(x, 0.3);
        const vector2D w(cells.wrap(p));
        EXPECT_EQ(std::signbit(w.x()), std::signbit(channel.wrap(p).x())) << x;
        EXPECT_EQ(w, channel.wrap(p)) << x;
        EXPECT_GE(w.x(), 0) << x;
        EXPECT_LT(w.x(), 1) << x;
    }
    // The cell of the seam's point is the first one, from either side
    EXPECT_EQ(cells.cellIndex(vector2D(-1e-17, 0.3)), cells.cellIndex(vector2D(0, 0.3)));
    EXPECT_EQ(cells.cellIndex(vector2D(1, 0.3)), cells.cellIndex(vector2D(0, 0.3)));
}


TEST(periodicSeam, neighbourSeparationsAreMinimumImages)
{
    throwFatalErrors();
    const List<vector2D> x
    ({
        vector2D(0.01, 0.5),    // 0
        vector2D(0.99, 0.5),    // 1: 0.02 from 0 through the seam
        vector2D(0, 0.2),       // 2
        vector2D(1, 0.25),      // 3: 0.05 above 2, given on the far side
        vector2D(-1e-17, 0.8),  // 4
        vector2D(0.97, 0.8),    // 5: 0.03 from 4
        vector2D(0.5, 0.5)      // 6: no neighbour
    });
    SPH::cellLinkedList cells(channel, 0.1);
    cells.build(x);
    SPH::neighbourList nbrs(true);
    nbrs.build(cells, x, 0.1, true);

    auto rij = [&](const label i, const label j)
    {
        for (label k = nbrs.offsets()[i]; k < nbrs.offsets()[i + 1]; ++k)
        {
            if (nbrs.indices()[k] == j)
            {
                EXPECT_NEAR(nbrs.r()[k], mag(nbrs.rij()[k]), 2*eps);
                return nbrs.rij()[k];
            }
        }
        ADD_FAILURE() << j << " is not a neighbour of " << i;
        return vector2D(VGREAT, VGREAT);
    };

    EXPECT_NEAR(rij(0, 1).x(), 0.02, 2*eps);
    EXPECT_NEAR(rij(1, 0).x(), -0.02, 2*eps);
    EXPECT_EQ(rij(0, 1).y(), 0);
    EXPECT_EQ(rij(2, 3).x(), 0);
    EXPECT_NEAR(rij(2, 3).y(), -0.05, 2*eps);
    EXPECT_NEAR(rij(4, 5).x(), 0.03, 2*eps);
    for (label i = 0; i < 6; ++i)
    {
        EXPECT_EQ(nbrs.nNeighbours(i), 1) << i;
    }
    EXPECT_EQ(nbrs.nNeighbours(6), 0);

    // The same as the domain's separation
    for (label i = 0; i < x.size(); ++i)
    {
        for (label k = nbrs.offsets()[i]; k < nbrs.offsets()[i + 1]; ++k)
        {
            const vector2D d(channel.separation(x[i], x[nbrs.indices()[k]]));
            EXPECT_LT(mag(nbrs.rij()[k] - d), 2*eps) << i;
        }
    }

    // A Verlet refresh after moving 0 across the seam to -0.005: still
    // its minimum image
    List<vector2D> moved(x);
    moved[0] = vector2D(-0.005, 0.5);
    nbrs.refresh(cells, moved, moved);
    EXPECT_NEAR(rij(0, 1).x(), 0.005, 2*eps);
}


// ************************************************************************* //
