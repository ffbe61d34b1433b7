/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The sphFoam function objects are OpenFOAM function objects: selected
    by type name from functionObject's run-time table, run by Time's
    functionObjectList from controlDict with OpenFOAM's controls
    (timeStart, writeControl, enabled), and refused with a clear error
    where no SPH particles are registered.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "functionObjectList.H"

using namespace Foam;

namespace
{
    //- A minimal dictionary for each type
    const std::vector<std::pair<std::string, std::string>> minimal =
    {
        {"probes", "type probes; fields (p); probeLocations ((0.5 0.25));"},
        {"waveGauges", "type waveGauges; x (0.5);"},
        {"surgeFront", "type surgeFront;"},
        {"wallForces", "type wallForces; patches (bottom);"}
    };

    //- Times (first column) of the data rows of a file
    std::vector<double> rowTimes(const fileName& file)
    {
        std::vector<double> t;
        for (const std::string& line : sphTest::dataLines(file))
        {
            t.push_back(sphTest::firstNumber(line));
        }
        return t;
    }

    void expectTimes(const fileName& file, const std::vector<double>& expected)
    {
        const std::vector<double> t = rowTimes(file);
        ASSERT_EQ(t.size(), expected.size()) << file;
        for (size_t i = 0; i < t.size(); ++i)
        {
            // Times are written with 8 digits
            EXPECT_NEAR(t[i], expected[i], 1e-9) << file << " row " << i;
        }
    }
}


TEST(functionObjects, selectableByTypeName)
{
    sphTest::sphTank tank("selectByName");
    for (const auto& [typeName, text] : minimal)
    {
        ASSERT_TRUE(functionObject::dictionaryConstructorTablePtr_->found(typeName))
            << typeName << " is not in functionObject's run-time table";

        autoPtr<functionObject> fo = tank.fo("fo_" + typeName, text);
        ASSERT_TRUE(fo.valid());
        EXPECT_EQ(fo->type(), typeName);
        EXPECT_EQ(fo->name(), "fo_" + typeName);
        EXPECT_TRUE(fo->execute());
        EXPECT_TRUE(fo->write());
    }
}


TEST(functionObjects, missingCloudIsAClearError)
{
    sphTest::throwOnFatal();
    auto runTime = sphTest::makeTime(sphTest::makeCase("selectNoCloud"));

    for (const auto& [typeName, text] : minimal)
    {
        try
        {
            functionObject::New("fo", *runTime, sphTest::dict(text));
            FAIL() << typeName << " built without an sphCloud";
        }
        catch (const Foam::error& e)
        {
            const std::string msg(e.message());
            EXPECT_NE
            (
                msg.find
                (
                    "no SPH particles registered: this function object runs"
                    " in sphFoam solvers"
                ),
                std::string::npos
            ) << msg;
            EXPECT_NE(msg.find(typeName), std::string::npos) << msg;
        }
    }
}


TEST(functionObjects, missingCloudStopsAnFVRunInsteadOfBeingDropped)
{
    // Time's functionObjectList turns a plain FatalError at construction
    // into a warning and drops the object; the IO error we raise makes it
    // stop the run with exit code 1 (its message goes to stdout, through
    // Info, so only the exit code is checked here)
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT
    (
        {
            auto runTime = sphTest::makeTime
            (
                sphTest::makeCase
                (
                    "selectNoCloudRun",
                    "functions { front { type surgeFront; } }\n"
                )
            );
            while (runTime->run())
            {
                ++(*runTime);
            }
            std::exit(0);
        },
        ::testing::ExitedWithCode(1),
        ""
    );
}


TEST(functionObjects, controlDictControlsAreHonouredInATimeLoop)
{
    // deltaT 0.1, endTime 1 (sphTest::makeCase); the cloud is registered
    // before the first runTime.run(), as the solver does. OpenFOAM's
    // timeControl is active for timeStart - deltaT/2 <= t <= timeEnd +
    // deltaT/2, so the window [0.5, 0.7] holds exactly three steps
    sphTest::sphTank tank
    (
        "selectTimeLoop",
        sphTest::tankSpec(),
        "functions\n{\n"
        "    every { type surgeFront; }\n"
        "    late { type waveGauges; x (0.5); timeStart 0.3; }\n"
        "    third { type wallForces; patches (bottom);\n"
        "            writeControl timeStep; writeInterval 3; }\n"
        "    window { type probes; fields (p); probeLocations ((0.5 0.25));\n"
        "             timeStart 0.5; timeEnd 0.7; }\n"
        "    off { type surgeFront; enabled no; }\n"
        "}\n"
    );

    Time& runTime = *tank.runTime;
    while (runTime.run())
    {
        ++runTime;
    }
    EXPECT_NEAR(runTime.value(), 1, 1e-12);

    expectTimes
    (
        tank.postProcessing("every/0/surgeFront.dat"),
        {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}
    );
    expectTimes
    (
        tank.postProcessing("late/0/waveGauges.dat"),
        {0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}
    );
    expectTimes(tank.postProcessing("third/0/force.dat"), {0.3, 0.6, 0.9});
    expectTimes(tank.postProcessing("window/0/p"), {0.5, 0.6, 0.7});
    EXPECT_FALSE(isDir(tank.postProcessing("off")));
}


TEST(functionObjects, functionObjectListDrivenByHand)
{
    sphTest::sphTank tank("selectByHand");
    Time& runTime = *tank.runTime;

    // functionObjectList keeps a reference to its parent dictionary
    const dictionary parent
    (
        sphTest::dict
        (
            "functions { front { type surgeFront; timeStart 0.2;"
            " writeControl timeStep; writeInterval 2; } }"
        )
    );
    functionObjectList functions(runTime, parent);
    ASSERT_TRUE(functions.start());
    ASSERT_EQ(functions.size(), 1);

    for (label i = 0; i < 5; ++i)
    {
        ++runTime;
        functions.execute();
    }

    // Steps 1..5 at t = 0.1..0.5: active from 0.2, written on even steps
    expectTimes(tank.postProcessing("front/0/surgeFront.dat"), {0.2, 0.4});
}


// ************************************************************************* //
