/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::checkRestartParticles: the particles of a restart checked before
    use, each error naming the file and the first bad particle.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallTestTools.H"
#include "particleChecks.H"

#include <limits>

using namespace Foam;

namespace
{
    const scalar NaN = std::numeric_limits<scalar>::quiet_NaN();
    const scalar Inf = std::numeric_limits<scalar>::infinity();

    //- Four fluid particles, then two dummies of patch 0 and 1
    class particleChecks : public ::testing::Test
    {
    protected:
        std::unique_ptr<Time> runTime_;
        std::unique_ptr<SPH::particles> parts_;
        const SPH::domain dom_{vector2D(-1, -1), vector2D(2, 2)};

        void SetUp() override
        {
            sphTest::throwOnFatal();
            runTime_ = sphTest::makeTime(sphTest::makeCase("particleChecks"));
            parts_.reset(new SPH::particles(*runTime_, "0.5"));
            SPH::particles& p = *parts_;
            p.add<vector2D>("U");
            p.add<scalar>("rho", 1000);
            p.add<scalar>("p");
            p.add<label>("id");
            p.add<label>("type");
            p.add<label>("patch");
            p.resize(6);
            forAll(p.positions(), i)
            {
                p.positions()[i] = vector2D(0.1*i, 0.5);
                p.field<scalar>("rho")[i] = 1000;
                p.field<label>("id")[i] = 10 + i;
                p.field<label>("type")[i] = i < 4 ? 0 : 2;
                p.field<label>("patch")[i] = i < 4 ? -1 : i - 4;
            }
        }

        std::string check()
        {
            return sphTest::errorOf
            (
                [&]() { SPH::checkRestartParticles(*parts_, 2, dom_); }
            );
        }

        //- The message names the file and the particle (index and id)
        void expectNamed(const std::string& msg, const std::string& file, label i)
        {
            EXPECT_NE(msg.find("0.5/lagrangian/sph/" + file), std::string::npos) << msg;
            if (i >= 0)
            {
                const std::string who =
                    "particle " + std::to_string(i) + " (id "
                  + std::to_string(parts_->field<label>("id")[i]) + ")";
                EXPECT_NE(msg.find(who), std::string::npos) << msg;
            }
        }
    };
}


TEST_F(particleChecks, validParticlesPass)
{
    EXPECT_EQ(check(), "");
}


TEST_F(particleChecks, nonFiniteValuesNameTheirField)
{
    parts_->field<vector2D>("U")[2] = vector2D(NaN, 0);
    std::string msg = check();
    expectNamed(msg, "U", 2);
    EXPECT_NE(msg.find("nan"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("positions"), std::string::npos) << msg;

    parts_->field<vector2D>("U")[2] = vector2D(0, 0);
    parts_->field<scalar>("rho")[1] = Inf;
    msg = check();
    expectNamed(msg, "rho", 1);
    EXPECT_NE(msg.find("inf"), std::string::npos) << msg;

    parts_->field<scalar>("rho")[1] = 1000;
    parts_->positions()[3] = vector2D(0, -Inf);
    expectNamed(check(), "positions", 3);
}


TEST_F(particleChecks, typeOutOfRangeIsAnError)
{
    parts_->field<label>("type")[1] = 7;
    const std::string msg = check();
    expectNamed(msg, "type", 1);
    EXPECT_NE(msg.find("type 7"), std::string::npos) << msg;
}


TEST_F(particleChecks, noFluidParticleIsAnError)
{
    // Every particle a dummy: the run would "succeed" with nothing in it
    forAll(parts_->positions(), i)
    {
        parts_->field<label>("type")[i] = 2;
        parts_->field<label>("patch")[i] = 0;
    }
    const std::string msg = check();
    expectNamed(msg, "type", -1);
    EXPECT_NE(msg.find("no fluid particle"), std::string::npos) << msg;
}


TEST_F(particleChecks, fluidAfterAWallParticleIsAnError)
{
    parts_->field<label>("type")[5] = 0;
    parts_->field<label>("patch")[5] = -1;
    const std::string msg = check();
    expectNamed(msg, "type", 5);
    EXPECT_NE(msg.find("come first"), std::string::npos) << msg;
}


TEST_F(particleChecks, duplicateIdIsAnError)
{
    parts_->field<label>("id")[4] = 11;
    const std::string msg = check();
    expectNamed(msg, "id", 4);
    EXPECT_NE(msg.find("particle 1"), std::string::npos) << msg;
}


TEST_F(particleChecks, badPatchIsAnError)
{
    parts_->field<label>("patch")[5] = 2;
    std::string msg = check();
    expectNamed(msg, "patch", 5);
    EXPECT_NE(msg.find("patch 2"), std::string::npos) << msg;

    parts_->field<label>("patch")[5] = 1;
    parts_->field<label>("patch")[0] = 0;
    msg = check();
    expectNamed(msg, "patch", 0);
    EXPECT_NE(msg.find("-1 for a fluid particle"), std::string::npos) << msg;
}


TEST_F(particleChecks, positionOutsideTheDomainIsAnError)
{
    parts_->positions()[2] = vector2D(1e300, 0.5);
    const std::string msg = check();
    expectNamed(msg, "positions", 2);
    EXPECT_NE(msg.find("outside the domain"), std::string::npos) << msg;
}


TEST_F(particleChecks, nonPositiveDensityIsAnError)
{
    parts_->field<scalar>("rho")[3] = -1000;
    const std::string msg = check();
    expectNamed(msg, "rho", 3);
    EXPECT_NE(msg.find("-1000"), std::string::npos) << msg;
}


TEST_F(particleChecks, wrongFieldSizeIsAnError)
{
    parts_->field<scalar>("p").setSize(5);
    const std::string msg = check();
    expectNamed(msg, "p", -1);
    EXPECT_NE(msg.find("holds 5 values, positions 6"), std::string::npos) << msg;
}


// ************************************************************************* //
