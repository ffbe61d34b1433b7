/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The probes function object: Shepard values of the hydrostatic block
    (exact inside, bounded on a wall, zero where dry) and its files, which
    must read like OpenFOAM's probes (checked against the byte-for-byte
    layout in ../shared/openfoam-conventions.md section 5.3).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "probes.H"

using namespace Foam;
using sphTest::rho0;
using sphTest::gMag;

namespace
{
    //- Round-off of a Shepard sum of ~50 terms, relative
    const scalar roundOff = 1e-12;

    const SPH::functionObjects::probes& asProbes(const autoPtr<functionObject>& fo)
    {
        return refCast<const SPH::functionObjects::probes>(fo());
    }
}


TEST(probes, linearPressureIsExactInsideTheFluid)
{
    sphTest::sphTank tank("probesInside");
    const scalar H = tank.spec.H;

    // Symmetric interior points (see shepardInterpolation tests), given
    // as (x y) and as (x y z)
    auto fo = tank.fo
    (
        "probes1",
        "type probes; fields (p U rho); probeLocations ((0.5 0.25) (0.21 0.16 0.005));"
    );
    ASSERT_TRUE(fo->execute());

    const auto& pr = asProbes(fo);
    ASSERT_EQ(pr.locations().size(), 2);
    EXPECT_EQ(pr.locations()[1], vector2D(0.21, 0.16));

    const scalarField& p = pr.scalarValues("p");
    EXPECT_NEAR(p[0], rho0*gMag*(H - 0.25), roundOff*rho0*gMag*H);
    EXPECT_NEAR(p[1], rho0*gMag*(H - 0.16), roundOff*rho0*gMag*H);

    const vector2DField& U = pr.vectorValues("U");
    EXPECT_NEAR(U[0].x(), 1.0, roundOff);
    EXPECT_NEAR(U[0].y(), -0.25, roundOff);

    EXPECT_NEAR(pr.scalarValues("rho")[1], rho0, roundOff*rho0);
}


TEST(probes, wallSensorReadsTheFluidNextToIt)
{
    sphTest::sphTank tank("probesWall");
    const scalar H = tank.spec.H;

    // On the left wall at y = 0.1 (five spacings up: the support, 4 dr,
    // clears bed and surface): the fluid side is symmetric in y and p
    // depends on y only, so the half stencil is still exact. On the bed
    // every neighbour lies within the support above it, so the reading is
    // a weighted mean of p over 0 < y < 4 dr; the poison pressure of the
    // dummies behind both walls must not show.
    auto fo = tank.fo
    (
        "wallSensor",
        "type probes; fields (p); probeLocations ((0 0.1) (0.5 0));"
    );
    fo->execute();
    const auto& pr = asProbes(fo);
    const scalarField& p = pr.scalarValues("p");

    EXPECT_NEAR(pr.fluidFractions()[0], 0.5, 1e-3);
    EXPECT_NEAR(p[0], rho0*gMag*(H - 0.1), roundOff*rho0*gMag*H);

    EXPECT_LT(p[1], rho0*gMag*H);
    EXPECT_GT(p[1], rho0*gMag*(H - tank.W->support()));

    // ... and with the hydrostatic term of 004_... eq. (10) it is exact
    auto foH = tank.fo
    (
        "wallSensorH",
        "type probes; fields (p); probeLocations ((0.5 0)); hydrostatic yes;"
    );
    foH->execute();
    EXPECT_NEAR(asProbes(foH).scalarValues("p")[0], rho0*gMag*H, roundOff*rho0*gMag*H);
}


TEST(probes, drySensorReadsZero)
{
    sphTest::sphTank tank("probesDry");
    const scalar dr = tank.spec.dr;

    // Far from the block; and just outside its free side, where the
    // fluid fraction is positive but below the threshold asked for
    auto fo = tank.fo
    (
        "dry",
        "type probes; fields (p U); minFluidFraction 0.3;"
        "probeLocations ((1.5 0.1) (" + std::to_string(1.0 + 2*dr) + " 0.2));"
    );
    fo->execute();
    const auto& pr = asProbes(fo);

    EXPECT_EQ(pr.fluidFractions()[0], 0);
    ASSERT_GT(pr.fluidFractions()[1], 0);
    ASSERT_LT(pr.fluidFractions()[1], 0.3);
    EXPECT_EQ(pr.scalarValues("p")[0], 0);
    EXPECT_EQ(pr.scalarValues("p")[1], 0);
    EXPECT_EQ(pr.vectorValues("U")[1], vector2D::zero);
}


TEST(probes, filesReadLikeOpenFOAMProbes)
{
    sphTest::sphTank tank("probesFiles");

    // writePrecision 6, as in the conventions' example: columns 13 wide
    auto fo = tank.fo
    (
        "probes1",
        "type probes; fields (p U); writePrecision 6;"
        "probeLocations ((0.5 0.25) (1.5 0.1));"
    );
    tank.runTime->setTime(0.1, 1);
    fo->execute();
    fo->write();
    tank.runTime->setTime(0.2, 2);
    fo->execute();
    fo->write();

    // One file per field, no extension, under the start time
    const fileName dir = tank.postProcessing("probes1/0");
    EXPECT_FALSE(isFile(dir/"p.dat"));
    const std::vector<std::string> p = sphTest::readLines(dir/"p");
    ASSERT_EQ(p.size(), 6u);
    EXPECT_EQ(p[0], "# Probe 0 (0.5 0.25)");
    EXPECT_EQ(p[1], "# Probe 1 (1.5 0.1)");
    EXPECT_EQ(p[2], "#       Probe             0             1");
    EXPECT_EQ(p[3], "#        Time");
    // rho0 g (H - 0.25) = 2452.5; the dry probe reads 0
    EXPECT_EQ(p[4], "          0.1        2452.5             0");
    EXPECT_EQ(p[5], "          0.2        2452.5             0");

    // A vector is written (x y z), the column width applying to "(",
    // as OpenFOAM writes U
    const std::vector<std::string> U = sphTest::readLines(dir/"U");
    ASSERT_EQ(U.size(), 6u);
    EXPECT_EQ(U[4], "          0.1             (1 -0.25 0)             (0 0 0)");
}


TEST(probes, rerunOverwritesTheFiles)
{
    sphTest::sphTank tank("probesRerun");
    const std::string text = "type probes; fields (p); probeLocations ((0.5 0.25));";
    {
        auto fo = tank.fo("probes1", text);
        fo->write();
        tank.runTime->setTime(0.1, 1);
        fo->write();
    }
    {
        // Same start time: OpenFOAM's probes truncate, no p_0 copy
        auto fo = tank.fo("probes1", text);
        fo->write();
    }
    const fileName dir = tank.postProcessing("probes1/0");
    EXPECT_EQ(sphTest::dataLines(dir/"p").size(), 1u);
    EXPECT_FALSE(isFile(dir/"p_0"));
}


TEST(probes, unknownFieldIsAnErrorListingTheFields)
{
    sphTest::throwOnFatal();
    sphTest::sphTank tank("probesUnknown");
    try
    {
        tank.fo("probes1", "type probes; fields (T); probeLocations ((0.5 0.25));");
        FAIL() << "unknown field accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("particle field T"), std::string::npos) << msg;
        EXPECT_NE(msg.find("rho"), std::string::npos) << msg;
    }
}


TEST(probes, pointWithFourComponentsIsAnError)
{
    sphTest::throwOnFatal();
    sphTest::sphTank tank("probesBadPoint");
    EXPECT_THROW
    (
        tank.fo("probes1", "type probes; fields (p); probeLocations ((0.5 0.25 0 1));"),
        Foam::error
    );
}


// ************************************************************************* //
