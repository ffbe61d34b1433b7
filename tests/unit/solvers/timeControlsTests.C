/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::checkTimeControls (system/controlDict before the time loop) and
    SPH::checkedScalar (a number of a dictionary, finite and in range):
    each bad value is an error naming the file and the entry.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "wallTestTools.H"
#include "timeControls.H"
#include "checkedEntry.H"

using namespace Foam;

namespace
{
    //- The message (with the file name) of checkTimeControls on a case
    //- whose controlDict has these entries after the defaults ("" if none)
    std::string timeError(const std::string& entries)
    {
        sphTest::throwOnFatal();
        const fileName dir = sphTest::makeCase("timeControls", entries);
        try
        {
            // Time reads controlDict first (and refuses some values itself)
            auto runTime = sphTest::makeTime(dir);
            SPH::checkTimeControls(*runTime);
        }
        catch (const IOerror& err)
        {
            return std::string(err.message()) + " file: " + err.ioFileName();
        }
        catch (const error& err)
        {
            return std::string(err.message());
        }
        return "";
    }

    bool has(const std::string& msg, const std::string& s)
    {
        return msg.find(s) != std::string::npos;
    }
}


TEST(timeControls, validControlsPass)
{
    EXPECT_EQ(timeError(""), "");
    EXPECT_EQ(timeError("writeControl adjustable; writeInterval 0.25; adjustTimeStep yes; maxCo 0.2; maxDeltaT 1;"), "");
    EXPECT_EQ(timeError("writeControl runTime; writeInterval 0.5; logInterval 10;"), "");
}


TEST(timeControls, endTimeAtTheStartIsNothingToDo)
{
    // Said in the log, not an error (OpenFOAM's solvers do the same)
    EXPECT_EQ(timeError("endTime 0;"), "");
}


TEST(timeControls, eachBadEntryIsNamedWithItsValue)
{
    struct bad { const char* entries; const char* entry; const char* value; };
    const std::vector<bad> cases
    {
        {"deltaT 0;", "deltaT", " 0"},
        {"deltaT -0.001;", "deltaT", "-0.001"},
        {"deltaT #eval{sqrt(-1)};", "deltaT", "nan"},
        {"endTime -1;", "endTime", "-1"},
        {"endTime #eval{sqrt(-1)};", "endTime", "nan"},
        // (Time's own words for writeControl timeStep: "writeInterval < 1")
        {"writeInterval 0;", "writeInterval", ""},
        {"writeInterval -1;", "writeInterval", ""},
        {"writeInterval 2.5;", "writeInterval", "2.5"},
        {"writeControl adjustable; writeInterval 0;", "writeInterval", " 0"},
        {"writeControl adjustable; writeInterval -1;", "writeInterval", "-1"},
        {"adjustTimeStep yes; maxCo 0;", "maxCo", " 0"},
        {"adjustTimeStep yes; maxCo -1;", "maxCo", "-1"},
        {"adjustTimeStep yes; maxCo 5;", "maxCo", "5"},
        {"maxCo 0;", "maxCo", " 0"},
        {"maxDeltaT 0;", "maxDeltaT", " 0"},
        {"maxDeltaT -1;", "maxDeltaT", "-1"},
        {"logInterval 0;", "logInterval", " 0"},
        {"deltaT 1e-200;", "deltaT", "1e+200 fixed steps"},
        {"deltaT 2;", "deltaT", "no step would run"},
        {"startTime 1e20; deltaT 1;", "deltaT", "too small to advance"},
    };
    for (const bad& c : cases)
    {
        const std::string msg = timeError(c.entries);
        EXPECT_TRUE(has(msg, c.entry)) << c.entries << ": " << msg;
        EXPECT_TRUE(has(msg, c.value)) << c.entries << ": " << msg;
        EXPECT_TRUE(has(msg, "system/controlDict")) << c.entries << ": " << msg;
    }
}


TEST(timeControls, unknownWriteControlListsTheKnownOnes)
{
    // Time itself refuses it while reading controlDict
    const std::string msg = timeError("writeControl everyStep;");
    EXPECT_TRUE(has(msg, "everyStep")) << msg;
    EXPECT_TRUE(has(msg, "adjustable")) << msg;
}


TEST(checkedEntry, rangesAndMessages)
{
    sphTest::throwOnFatal();
    const dictionary d(sphTest::dict("a 1; b -1; c 1e300; z 0;"));
    EXPECT_EQ(SPH::checkedScalar(d, "a", {0, VGREAT, true}), 1);
    EXPECT_EQ(SPH::checkedScalar(d, "missing", 2, {0, 10}), 2);
    EXPECT_EQ(SPH::checkedScalar(d, "c", {0, VGREAT}), 1e300);

    std::string msg = sphTest::errorOf([&]() { SPH::checkedScalar(d, "b", {0, VGREAT}, "m/s"); });
    EXPECT_TRUE(has(msg, "Entry b -1")) << msg;
    EXPECT_TRUE(has(msg, ">= 0 (m/s)")) << msg;

    msg = sphTest::errorOf([&]() { SPH::checkedScalar(d, "z", {0, 1, true}); });
    EXPECT_TRUE(has(msg, "> 0 and <= 1")) << msg;

    msg = sphTest::errorOf([&]() { SPH::checkedScalar(d, "missing", -5, {0, 1}); });
    EXPECT_TRUE(has(msg, "Entry missing -5 (its default")) << msg;

    const scalar inf = std::numeric_limits<scalar>::infinity();
    msg = sphTest::errorOf([&]() { SPH::checkNumber(d, "a", inf, {0, VGREAT}); });
    EXPECT_TRUE(has(msg, "finite")) << msg;
    msg = sphTest::errorOf([&]() { SPH::checkNumber(d, "a", std::nan(""), {-VGREAT, VGREAT}); });
    EXPECT_TRUE(has(msg, "finite")) << msg;
}


// ************************************************************************* //
