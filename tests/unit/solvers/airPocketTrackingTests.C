/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    How isphFoam's air pockets carry their air from step to step
    (src/sph/solvers/isph/stages/airPockets/airPocketTracking.H), on grids
    of a few cells labelled by hand: a pocket that stays itself keeps its
    A0 and its pressure follows its area; merged pockets take their parts'
    pressure weighted by cells; a pocket that takes in air at p = 0 (the
    atmosphere, or enclosed air too small to be a pocket) is diluted, not
    compressed; a split keeps the pressure; a new pocket starts at 0 or
    at the pressure given; a retried step starts from the saved state; the
    state written is read back exactly, and one for another grid is an
    error.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "airPocketTracking.H"
#include "airPocketGrid.H"
#include "dictionary.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "error.H"

using namespace Foam;
using SPH::airPocketTracking;

namespace
{
    const label W = SPH::airPocketGrid::water;
    const label A = SPH::airPocketGrid::atmosphere;
    const label U = SPH::airPocketGrid::unresolved;
    const scalar pAtm = 1e5, gammaAir = 1.4;

    labelList L(std::initializer_list<label> l) { return labelList(l); }
    scalarList S(std::initializer_list<scalar> l) { return scalarList(l); }

    //- One pocket of 4 cells (cells 1-4) closed at area 1 and at p
    airPocketTracking onePocket(const scalar p = 0)
    {
        airPocketTracking t(pAtm, gammaAir);
        if (p != 0)
        {
            t.takePressuresFromFields();
        }
        t.update
        (
            L({W, 0, 0, 0, 0, W}), scalarList(1, 1.0), 1, scalarList(1, p)
        );
        return t;
    }
}


TEST(airPocketTracking, thePressureFollowsTheLawOfTheAir)
{
    const airPocketTracking t(pAtm, gammaAir);
    EXPECT_NEAR(t.pressure(1, 1), 0, 1e-9);
    EXPECT_NEAR(t.pressure(1, 0.5), pAtm*(std::pow(2, 1.4) - 1), 1e-6);
    // closedArea is the inverse: the area at p = 0 of air at A and p
    EXPECT_NEAR(t.pressure(t.closedArea(0.3, 2500), 0.3), 2500, 1e-8);
}


TEST(airPocketTracking, aPocketThatStaysItselfKeepsItsAirAsItsAreaChanges)
{
    airPocketTracking t(onePocket());
    EXPECT_EQ(t.size(), 1);
    EXPECT_DOUBLE_EQ(t.A0()[0], 1);
    EXPECT_NEAR(t.p()[0], 0, 1e-9);

    // The same cells less one (water came in): the grid's area 0.9
    t.update(L({W, 0, 0, 0, W, W}), scalarList(1, 0.9), 1, scalarList());
    EXPECT_DOUBLE_EQ(t.A0()[0], 1);
    EXPECT_DOUBLE_EQ(t.area()[0], 0.9);
    EXPECT_NEAR(t.p()[0], pAtm*(std::pow(1/0.9, gammaAir) - 1), 1e-6);

    // Carried (implicit): the area moves a fraction of the way to the grid's
    t.update(L({W, 0, 0, 0, W, W}), scalarList(1, 0.8), 0.25, scalarList());
    EXPECT_DOUBLE_EQ(t.area()[0], 0.9 + 0.25*(0.8 - 0.9));
    EXPECT_DOUBLE_EQ(t.A0()[0], 1);
}


TEST(airPocketTracking, mergedPocketsTakeTheirPartsPressureByCells)
{
    airPocketTracking t(pAtm, gammaAir);
    // Two pockets, at 1000 Pa (3 cells) and 4000 Pa (1 cell)
    t.takePressuresFromFields();
    t.update(L({0, 0, 0, W, 1, W}), S({0.3, 0.1}), 1, S({1000, 4000}));
    EXPECT_NEAR(t.p()[0], 1000, 1e-8);
    EXPECT_NEAR(t.p()[1], 4000, 1e-8);

    // The water between them gone: one pocket of all their cells
    t.update(L({0, 0, 0, 0, 0, W}), scalarList(1, 0.5), 1, scalarList());
    ASSERT_EQ(t.size(), 1);
    EXPECT_NEAR(t.p()[0], (3*1000 + 4000)/4.0, 1e-8);
    EXPECT_DOUBLE_EQ(t.area()[0], 0.5);
}


TEST(airPocketTracking, airAtZeroPressureJoiningAPocketDilutesIt)
{
    for (const label free : {A, U})
    {
        // A pocket at 3000 Pa (cells 1-4) beside air at p = 0 (cells 5-6)
        airPocketTracking t(pAtm, gammaAir);
        t.takePressuresFromFields();
        t.update
        (
            L({W, 0, 0, 0, 0, free, free}), scalarList(1, 0.4), 1, S({3000})
        );
        EXPECT_NEAR(t.p()[0], 3000, 1e-8);

        // They join: 4 cells at 3000 and 2 at 0, at the grid's area 0.6
        t.update
        (
            L({W, 0, 0, 0, 0, 0, 0}), scalarList(1, 0.6), 0.05, scalarList()
        );
        EXPECT_NEAR(t.p()[0], 2000, 1e-8) << "joined air " << free;
        EXPECT_DOUBLE_EQ(t.area()[0], 0.6) << "joined air " << free;
    }
}


TEST(airPocketTracking, aSplitPocketsPartsKeepItsPressure)
{
    airPocketTracking t(onePocket(1500));
    EXPECT_NEAR(t.p()[0], 1500, 1e-8);
    t.update(L({W, 0, 0, W, 1, W}), S({0.5, 0.25}), 1, scalarList());
    ASSERT_EQ(t.size(), 2);
    EXPECT_NEAR(t.p()[0], 1500, 1e-8);
    EXPECT_NEAR(t.p()[1], 1500, 1e-8);
}


TEST(airPocketTracking, aNewPocketStartsAtTheAtmospheresPressure)
{
    airPocketTracking t(pAtm, gammaAir);
    t.update(L({W, W, W}), scalarList(), 1, scalarList());
    EXPECT_EQ(t.size(), 0);
    // Water closes off air that was the atmosphere: a pocket at p = 0
    // (pressures given are only taken when asked for, after a restart)
    t.update(L({W, 0, 0}), scalarList(1, 0.2), 1, S({777}));
    ASSERT_EQ(t.size(), 1);
    EXPECT_NEAR(t.p()[0], 0, 1e-9);
    EXPECT_NEAR(t.A0()[0], 0.2, 1e-15);
}


TEST(airPocketTracking, aRetriedStepStartsFromTheSavedState)
{
    airPocketTracking t(onePocket(800));
    t.save();
    t.update(L({W, 0, 0, 0, W, W}), scalarList(1, 0.7), 1, scalarList());
    t.correct(scalarList(1, 50.0), scalarList(1, -2.0), 0.01);
    EXPECT_NE(t.p()[0], 800);
    t.restore();
    EXPECT_NEAR(t.p()[0], 800, 1e-8);
    EXPECT_DOUBLE_EQ(t.area()[0], 1);
}


TEST(airPocketTracking, theStateWrittenIsReadBackExactly)
{
    airPocketTracking t(pAtm, gammaAir);
    t.takePressuresFromFields();
    t.update
    (
        L({W, 0, 0, A, A, 1, U, W}), S({0.123456789012345, 0.1}), 1,
        S({1234.5, -67.8})
    );

    OStringStream os;
    os.precision(17);
    t.write(os, 8);
    IStringStream is(os.str());
    const dictionary dict(is);
    airPocketTracking r(pAtm, gammaAir);
    r.read(dict, 8);
    ASSERT_EQ(r.size(), 2);
    for (label k = 0; k < 2; ++k)
    {
        EXPECT_EQ(r.A0()[k], t.A0()[k]);
        EXPECT_EQ(r.area()[k], t.area()[k]);
        EXPECT_EQ(r.p()[k], t.p()[k]);
    }
    // The cells too: the same next step from both
    t.update(L({W, 0, 0, A, W, 1, 1, W}), S({0.12, 0.11}), 1, scalarList());
    r.update(L({W, 0, 0, A, W, 1, 1, W}), S({0.12, 0.11}), 1, scalarList());
    EXPECT_EQ(r.p()[0], t.p()[0]);
    EXPECT_EQ(r.p()[1], t.p()[1]);

    // A state for another grid, or cells of no pocket, is an error
    FatalIOError.throwExceptions();
    EXPECT_THROW(r.read(dict, 9), Foam::error);
    OStringStream bad;
    bad << "A0 1(1); area 1(1); p 1(0); gridCells 8; airCells 1((2 3 5));";
    IStringStream badIs(bad.str());
    EXPECT_THROW(r.read(dictionary(badIs), 8), Foam::error);
}


// ************************************************************************* //
