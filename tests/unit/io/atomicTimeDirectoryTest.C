/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    SPH::atomicTimeDirectory: what is written while it lives goes into
    <case>/<time>.writing/<time> with the time's own header location, and
    appears as <time> at commit; a rewrite of an existing time (the last
    good state at the start time) keeps the files it does not replace
    (0/U); without commit nothing is left; removeUnfinished clears
    leftovers.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "atomicTimeDirectory.H"
#include "IOdictionary.H"

using namespace Foam;

namespace
{
    //- A dictionary written into the current time, as Time::write does
    void writeDict(Time& runTime, const word& name)
    {
        IOdictionary d
        (
            IOobject
            (
                name, runTime.timeName(), "uniform", runTime,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            )
        );
        d.add("value", 1.5);
        d.regIOobject::write();
    }
}


TEST(atomicTimeDirectory, writesIntoASiblingAndRenamesAtCommit)
{
    sphTest::throwOnFatal();
    const fileName dir = sphTest::makeCase("atomicTime");
    auto runTime = sphTest::makeTime(dir);
    runTime->setTime(0.25, 1);
    {
        SPH::atomicTimeDirectory atomic(*runTime);
        writeDict(*runTime, "state");
        EXPECT_TRUE(isFile(dir/"0.25.writing"/"0.25"/"uniform"/"state"));
        EXPECT_FALSE(isDir(dir/"0.25"));
        atomic.commit();
    }
    EXPECT_TRUE(isFile(dir/"0.25"/"uniform"/"state"));
    EXPECT_FALSE(exists(dir/"0.25.writing"));
    EXPECT_EQ(runTime->caseName(), fileName(dir.name()));
    EXPECT_NE
    (
        sphTest::run("cat " + dir/"0.25"/"uniform"/"state")
            .find("location    \"0.25/uniform\""),
        std::string::npos
    );
}


TEST(atomicTimeDirectory, rewritingTheStartTimeKeepsItsInitialFields)
{
    sphTest::throwOnFatal();
    const fileName dir = sphTest::makeCase("atomicRewrite");
    sphTest::writeFile(dir/"0"/"U", "// the user's initial velocity\n");
    auto runTime = sphTest::makeTime(dir);
    {
        SPH::atomicTimeDirectory atomic(*runTime);
        writeDict(*runTime, "state");
        atomic.commit();
    }
    EXPECT_TRUE(isFile(dir/"0"/"U"));
    EXPECT_TRUE(isFile(dir/"0"/"uniform"/"state"));
    EXPECT_FALSE(exists(dir/"0.writing"));
}


TEST(atomicTimeDirectory, withoutCommitNothingIsLeftAndLeftoversAreRemoved)
{
    sphTest::throwOnFatal();
    const fileName dir = sphTest::makeCase("atomicAbandon");
    auto runTime = sphTest::makeTime(dir);
    runTime->setTime(0.5, 2);
    {
        SPH::atomicTimeDirectory atomic(*runTime);
        writeDict(*runTime, "state");
    }
    EXPECT_FALSE(exists(dir/"0.5.writing"));
    EXPECT_FALSE(exists(dir/"0.5"));
    EXPECT_EQ(runTime->caseName(), fileName(dir.name()));

    // A killed run's leftover
    sphTest::writeFile(dir/"0.7.writing"/"0.7"/"uniform"/"time", "cut");
    SPH::atomicTimeDirectory::removeUnfinished(*runTime);
    EXPECT_FALSE(exists(dir/"0.7.writing"));
}


// ************************************************************************* //
