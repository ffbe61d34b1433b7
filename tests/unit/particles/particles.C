/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Particle storage and its time directories: fields by name, exact binary
    restart, ascii to its precision, clear errors on damaged or missing
    files, Time's write control, foamListTimes.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particles.H"
#include "Random.H"

using namespace Foam;
using SPH::particles;

namespace
{
    //- Fill a set with awkward doubles (all 53 bits in use)
    void fill(particles& parts, label n)
    {
        parts.add<vector2D>("U");
        parts.add<scalar>("p");
        parts.add<label>("id");
        parts.resize(n);
        Random rnd(1234);
        forAll(parts.positions(), i)
        {
            parts.positions()[i] = vector2D(rnd.sample01<scalar>(), rnd.sample01<scalar>()/3);
            parts.field<vector2D>("U")[i] = vector2D(rnd.GaussNormal<scalar>(), 1e-300*rnd.sample01<scalar>());
            parts.field<scalar>("p")[i] = 1e5*rnd.GaussNormal<scalar>();
            parts.field<label>("id")[i] = 7*i;
        }
    }

    template<class Type>
    bool bitwiseEqual(const UList<Type>& a, const UList<Type>& b)
    {
        return a.size() == b.size()
            && std::memcmp(a.cdata(), b.cdata(), a.byteSize()) == 0;
    }
}


TEST(particles, fieldsByNameResizeTogether)
{
    auto runTime = sphTest::makeTime(sphTest::makeCase("particlesResize"));
    particles parts(*runTime, "0");
    parts.add<scalar>("p", 2.0);
    parts.resize(10);
    EXPECT_EQ(parts.positions().size(), 10);
    EXPECT_EQ(parts.field<scalar>("p").size(), 10);
    EXPECT_TRUE(parts.found<scalar>("p"));
    EXPECT_FALSE(parts.found<vector2D>("p"));
    EXPECT_EQ(parts.names().size(), 1);
}


TEST(particles, binaryRestartIsExactToTheBit)
{
    const fileName dir = sphTest::makeCase("particlesBinary");
    auto runTime = sphTest::makeTime(dir);
    runTime->setTime(0.5, 5);
    particles written(*runTime, "0.5");
    fill(written, 1000);
    written.write();

    particles readBack(*runTime, "0.5");
    readBack.add<vector2D>("U");
    readBack.add<scalar>("p");
    readBack.add<label>("id");
    readBack.read();

    ASSERT_EQ(readBack.size(), 1000);
    EXPECT_TRUE(bitwiseEqual(written.positions(), readBack.positions()));
    EXPECT_TRUE(bitwiseEqual(written.field<vector2D>("U"), readBack.field<vector2D>("U")));
    EXPECT_TRUE(bitwiseEqual(written.field<scalar>("p"), readBack.field<scalar>("p")));
    EXPECT_TRUE(bitwiseEqual(written.field<label>("id"), readBack.field<label>("id")));
    EXPECT_TRUE(isFile(dir/"0.5"/"lagrangian"/"sph"/"positions"));
}


TEST(particles, addIfPresentReadsAWrittenFieldElseFillsAndWritesIt)
{
    const fileName dir = sphTest::makeCase("particlesAddIfPresent");
    auto runTime = sphTest::makeTime(dir);
    runTime->setTime(0.5, 5);
    particles written(*runTime, "0.5");
    fill(written, 100);
    written.write();

    // A restart of a run that wrote U: read back as it was
    particles readBack(*runTime, "0.5");
    readBack.add<scalar>("p");
    readBack.add<label>("id");
    readBack.read();
    EXPECT_TRUE(readBack.addIfPresent<vector2D>("U", vector2D(7, 7)));
    EXPECT_TRUE(bitwiseEqual(written.field<vector2D>("U"), readBack.field<vector2D>("U")));

    // A field the run did not write: the value everywhere, a restart
    // field from now on (written at the next write)
    EXPECT_FALSE(readBack.addIfPresent<scalar>("a", 3.0));
    ASSERT_EQ(readBack.field<scalar>("a").size(), 100);
    EXPECT_EQ(readBack.field<scalar>("a")[0], 3.0);
    EXPECT_EQ(readBack.field<scalar>("a")[99], 3.0);
    EXPECT_TRUE(readBack.isRestart("a"));
    runTime->setTime(1, 10);
    readBack.write();
    EXPECT_TRUE(isFile(dir/"1"/"lagrangian"/"sph"/"a"));
}


TEST(particles, asciiRestartKeepsWritePrecision)
{
    const fileName dir = sphTest::makeCase("particlesAscii", "writeFormat ascii; writePrecision 12;");
    // The later writeFormat entry overrides the earlier one
    auto runTime = sphTest::makeTime(dir);
    particles written(*runTime, "0");
    fill(written, 200);
    written.write();

    particles readBack(*runTime, "0");
    readBack.add<vector2D>("U");
    readBack.add<scalar>("p");
    readBack.add<label>("id");
    readBack.read();

    // 12 significant digits: relative error below 1e-11
    forAll(written.positions(), i)
    {
        EXPECT_NEAR(readBack.field<scalar>("p")[i], written.field<scalar>("p")[i],
                    1e-11*mag(written.field<scalar>("p")[i]));
        EXPECT_EQ(readBack.field<label>("id")[i], written.field<label>("id")[i]);
    }
}


TEST(particles, timeWritesRestartFieldsAtWriteTimes)
{
    const fileName dir = sphTest::makeCase("particlesTimeWrite");
    auto runTime = sphTest::makeTime(dir);
    particles parts(*runTime, runTime->timeName());
    parts.add<scalar>("p", 1.0);
    parts.add<scalar>("scratch", 0.0, false);
    parts.resize(5);

    ++(*runTime);
    runTime->write();
    ++(*runTime);
    runTime->write();

    EXPECT_TRUE(isFile(dir/"0.1"/"lagrangian"/"sph"/"p"));
    EXPECT_TRUE(isFile(dir/"0.2"/"lagrangian"/"sph"/"positions"));
    EXPECT_FALSE(isFile(dir/"0.2"/"lagrangian"/"sph"/"scratch"));

    // OpenFOAM's own tool sees our time directories
    const std::string out =
        sphTest::run("WM_PROJECT_DIR=/usr/share/openfoam foamListTimes -case " + dir);
    EXPECT_NE(out.find("0.1"), std::string::npos) << out;
    EXPECT_NE(out.find("0.2"), std::string::npos) << out;
}


TEST(particles, damagedFileIsAnErrorNamingIt)
{
    sphTest::throwOnFatal();
    const fileName dir = sphTest::makeCase("particlesDamaged", "writeFormat ascii;");
    auto runTime = sphTest::makeTime(dir);
    {
        particles parts(*runTime, "0");
        fill(parts, 10);
        parts.write();
    }
    const fileName pFile = dir/"0"/"lagrangian"/"sph"/"p";
    const std::string before = sphTest::run("md5sum " + dir/"0"/"lagrangian"/"sph"/"U");
    sphTest::writeFile(pFile, "FoamFile { version 2.0; format ascii; class scalarField; object p; }\n10 ( 1 2 3 oops");

    particles readBack(*runTime, "0");
    readBack.add<vector2D>("U");
    readBack.add<scalar>("p");
    readBack.add<label>("id");
    try
    {
        readBack.read();
        FAIL() << "a damaged file was read without an error";
    }
    catch (const Foam::IOerror& e)
    {
        // OpenFOAM's IO error names the file and the line
        EXPECT_NE(std::string(e.ioFileName()).find("lagrangian/sph/p"), std::string::npos)
            << e.ioFileName();
        EXPECT_EQ(e.ioStartLineNumber(), 2);
    }
    // Reading never changes what was written
    EXPECT_EQ(before, sphTest::run("md5sum " + dir/"0"/"lagrangian"/"sph"/"U"));
}


TEST(particles, missingFileIsAnErrorNamingIt)
{
    sphTest::throwOnFatal();
    const fileName dir = sphTest::makeCase("particlesMissing");
    auto runTime = sphTest::makeTime(dir);
    {
        particles parts(*runTime, "0");
        fill(parts, 10);
        parts.write();
    }
    rm(dir/"0"/"lagrangian"/"sph"/"U");

    particles readBack(*runTime, "0");
    readBack.add<vector2D>("U");
    try
    {
        readBack.read();
        FAIL() << "a missing file was not reported";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(std::string(e.message()).find("U"), std::string::npos) << e.message();
    }
}


TEST(particles, sizeMismatchIsAnErrorNamingTheFile)
{
    sphTest::throwOnFatal();
    const fileName dir = sphTest::makeCase("particlesSize", "writeFormat ascii;");
    auto runTime = sphTest::makeTime(dir);
    {
        particles parts(*runTime, "0");
        fill(parts, 10);
        parts.write();
    }
    sphTest::writeFile(dir/"0"/"lagrangian"/"sph"/"p",
        "FoamFile { version 2.0; format ascii; class scalarField; object p; }\n3(1 2 3)\n");
    particles readBack(*runTime, "0");
    readBack.add<scalar>("p");
    try
    {
        readBack.read();
        FAIL() << "a short field was not reported";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(std::string(e.message()).find("lagrangian/sph/p"), std::string::npos)
            << e.message();
    }
}


TEST(particles, reorderMovesEveryFieldAndKeepsTheTailAndStorage)
{
    sphTest::throwOnFatal();
    auto runTime = sphTest::makeTime(sphTest::makeCase("particlesReorder"));
    particles parts(*runTime, "0");
    fill(parts, 10);
    parts.add<scalar>("scratch", 0, false);
    forAll(parts.positions(), i) { parts.field<scalar>("scratch")[i] = i; }

    const List<vector2D> x0(parts.positions());
    const List<vector2D> U0(parts.field<vector2D>("U"));
    const scalarList p0(parts.field<scalar>("p"));
    const labelList id0(parts.field<label>("id"));
    const vector2D* storage = parts.positions().cdata();

    // The first 6 particles reversed; 6 .. 9 untouched
    const labelList oldOfNew({5, 4, 3, 2, 1, 0});
    parts.reorder(oldOfNew);

    EXPECT_EQ(parts.positions().cdata(), storage);
    for (label k = 0; k < 10; ++k)
    {
        const label old = k < 6 ? oldOfNew[k] : k;
        EXPECT_EQ(parts.positions()[k], x0[old]) << k;
        EXPECT_EQ(parts.field<vector2D>("U")[k], U0[old]) << k;
        EXPECT_EQ(parts.field<scalar>("p")[k], p0[old]) << k;
        EXPECT_EQ(parts.field<label>("id")[k], id0[old]) << k;
        EXPECT_EQ(parts.field<scalar>("scratch")[k], scalar(old)) << k;
    }

    // Not a permutation: a repeated index, one out of range, too many
    for (const labelList& bad : {labelList({0, 0, 1}), labelList({0, 3, 1}), labelList(11, 0)})
    {
        try
        {
            parts.reorder(bad);
            FAIL() << "a reordering that is not a permutation was accepted";
        }
        catch (const Foam::error& e)
        {
            EXPECT_NE(std::string(e.message()).find("particles"), std::string::npos)
                << e.message();
        }
    }
}
