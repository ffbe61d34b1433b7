/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The time loop's promise to a new model: a particle field registered on
    the cloud (here a passive scalar T carried by a toy solver) is in the
    VTK picture, in the restart files and in the rollback to the last good
    state, with no other code naming it.

\*---------------------------------------------------------------------------*/

#include "timeLoop.H"
#include "stageList.H"
#include "sphCloud.H"
#include "kernel.H"
#include "wallMesh.H"
#include "vtkCaseWriter.H"
#include "vtkParticleFile.H"
#include "vtkPolyFileReader.H"
#include "testCase.H"
#include "Random.H"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace Foam;

namespace
{

//- T += dt and r += dt u; at failAt it writes NaN into T of one particle;
//- a step of a full 0.1 s ending at spikeAt throws particle 0 a metre
//- (5 h) at 10 m/s, a shorter one (a retry) does not
class heat
:
    public SPH::stage
{
    SPH::particles& parts_;
    const Time& runTime_;
    const scalar failAt_;
    const scalar spikeAt_;

public:

    heat
    (
        SPH::particles& parts, const Time& runTime, const scalar failAt,
        const scalar spikeAt
    )
    :
        stage("heat", {"T", "U"}, {"T", "U", "positions"}),
        parts_(parts),
        runTime_(runTime),
        failAt_(failAt),
        spikeAt_(spikeAt)
    {}

    void describe(Ostream& os) const override { os << "dT/dt = 1"; }

    void execute(const scalar dt) override
    {
        scalarField& T = parts_.field<scalar>("T");
        vector2DField& x = parts_.positions();
        const vector2DField& U = parts_.field<vector2D>("U");
        forAll(T, i)
        {
            T[i] += dt;
            x[i] += dt*U[i];
        }
        if (std::abs(runTime_.value() - failAt_) < 1e-9)
        {
            T[4] = std::numeric_limits<scalar>::quiet_NaN();
        }
        if (std::abs(runTime_.value() - spikeAt_) < 1e-9 && dt > 0.1 - 1e-9)
        {
            x[0] += vector2D(1, 0);
            parts_.field<vector2D>("U")[0] = vector2D(10, 0);
        }
    }
};


//- One straight wall below the particles (the cloud needs walls)
List<List<SPH::wallChain>> floor()
{
    SPH::wallChain chain;
    chain.points = {vector2D(-0.5, -0.1), vector2D(0.7, -0.1)};
    return List<List<SPH::wallChain>>(1, List<SPH::wallChain>(1, chain));
}


//- Nine particles, one registered field T that only the stage names
class passiveScalar
:
    public SPH::sphSolver
{
    autoPtr<SPH::kernel> kernel_;
    SPH::wallMesh walls_;
    SPH::particles parts_;
    autoPtr<SPH::sphCloud> cloud_;
    mutable autoPtr<SPH::vtkCaseWriter> vtk_;

public:

    passiveScalar(Time& runTime, const scalar failAt, const scalar spikeAt = -1)
    :
        sphSolver(runTime),
        kernel_(SPH::kernel::New(sphTest::dict("kernel wendlandC2; hByDr 2;"), 0.1)),
        walls_(wordList({"floor"}), floor(), 0.1),
        parts_(runTime, runTime.timeName())
    {
        parts_.add<vector2D>("U");
        parts_.add<label>("id");
        parts_.add<label>("type");
        parts_.add<scalar>("T");              // the new field: nothing else
        if (isFile(parts_.path()/"positions"))
        {
            parts_.read();
        }
        else
        {
            parts_.resize(9);
            forAll(parts_.positions(), i)
            {
                parts_.positions()[i] = vector2D(0.1*(i % 3), 0.1*(i/3));
                parts_.field<vector2D>("U")[i] = vector2D(0.01, 0);
                parts_.field<label>("id")[i] = i;
                parts_.field<scalar>("T")[i] = 300 + i;
            }
        }
        cloud_.reset
        (
            new SPH::sphCloud
            (
                runTime, parts_, *kernel_, walls_, 9, 0.1, 1000,
                vector2D::zero, SPH::domain(vector2D(-1, -1), vector2D(2, 2))
            )
        );
        stages_.add(new heat(parts_, runTime, failAt, spikeAt));
    }

    string title() const override { return "passive scalar"; }
    word stateName() const override { return "passiveScalarState"; }
    const SPH::sphCloud& cloud() const override { return *cloud_; }
    SPH::sphCloud& cloud() override { return *cloud_; }
    scalar maxDeltaT() const override { return 0.1; }
    void particlesReordered(const labelUList&) override {}

    void write() const override
    {
        if (!vtk_)
        {
            vtk_.reset
            (
                new SPH::vtkCaseWriter
                (
                    runTime_.path(), runTime_.caseName().name(),
                    SPH::vtkCaseWriter::staticWalls
                )
            );
        }
        SPH::vtkParticleFile file(parts_);
        vtk_->writeParticles(file, runTime_.timeIndex(), runTime_.value());
    }
};


fileName makeCase(const std::string& name, const std::string& start)
{
    const fileName dir = sphTest::makeCase
    (
        name, "writeInterval 2; startFrom " + start + ";\n"
    );
    sphTest::writeFile
    (
        dir/"system"/"sphSchemes",
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object sphSchemes; }\n"
        // The checks find a particle's T by its index: no sort by cell
        "particleSortInterval 0;\n"
    );
    return dir;
}


scalarField readT(const fileName& dir, const word& time)
{
    auto runTime = sphTest::makeTime(dir);
    SPH::particles parts(*runTime, time);
    parts.add<scalar>("T");
    parts.read();
    return parts.field<scalar>("T");
}


void registeredFieldCase()
{
    // A run that fails at t = 0.5: the NaN the stage wrote is not what is
    // written; T at the last good state, 0.4, is
    const fileName dir = makeCase("timeLoopFields", "startTime");
    {
        auto runTime = sphTest::makeTime(dir);
        passiveScalar solver(*runTime, 0.5);
        std::string message;
        try
        {
            SPH::timeLoop(*runTime, solver).run();
        }
        catch (const Foam::error& err)
        {
            message = err.message();
        }
        EXPECT_NE(message.find("NaN or Inf in the field T of particle id 4"),
                  std::string::npos) << message;
        EXPECT_NE(message.find("The last good state, time 0.4"),
                  std::string::npos) << message;
    }
    const scalarField T04(readT(dir, "0.4"));
    ASSERT_EQ(T04.size(), 9);
    forAll(T04, i)
    {
        // Four additions of 0.1 to 300 + i: exact to round-off of each sum
        EXPECT_NEAR(T04[i], 300 + i + 0.4, 1e-12) << i;
    }

    // The picture of every write time holds T without the writer naming it
    // (the writer names the files after the case folder)
    const SPH::vtkPolyFileReader vtp(dir/"VTK"/(dir.name() + "_4.vtp"));
    const wordList names(vtp.pointFieldNames());
    EXPECT_TRUE(names.found("T"));

    // Restart from the last good state to the end: T is bit for bit that
    // of a run that never failed
    ASSERT_EQ
    (
        sphTest::run
        (
            "foamDictionary -entry startFrom -set latestTime "
          + dir/"system"/"controlDict"
        ).find("rror"),
        std::string::npos
    );
    {
        auto runTime = sphTest::makeTime(dir);
        EXPECT_EQ(runTime->timeName(), "0.4");
        SPH::timeLoop::prepareStart(*runTime, "passiveScalarState");
        passiveScalar solver(*runTime, -1);
        SPH::timeLoop(*runTime, solver).run();
    }
    const fileName ref = makeCase("timeLoopFieldsReference", "startTime");
    {
        auto runTime = sphTest::makeTime(ref);
        passiveScalar solver(*runTime, -1);
        SPH::timeLoop(*runTime, solver).run();
    }
    const scalarField T1(readT(dir, "1"));
    const scalarField T1ref(readT(ref, "1"));
    ASSERT_EQ(T1.size(), 9);
    forAll(T1, i)
    {
        EXPECT_EQ(T1[i], T1ref[i]) << i;
    }
}

} // End anonymous namespace


TEST(timeLoop, registeredFieldIsRolledBackWrittenToVTKAndRestarted)
{
    sphTest::throwOnFatal();
    try
    {
        registeredFieldCase();
    }
    catch (const Foam::error& err)
    {
        FAIL() << err.message();
    }
}


TEST(timeLoop, aStepRetriedAfterAFailedCheckDoesNotCountForTheRunsLargest)
{
    // The full step to t = 0.5 moves particle 0 by 5 h at 10 m/s: within
    // maxStepDisplacement 10, beyond maxSpeed 5. Retried with half the
    // step, it moves 0.0025 h. The run's largest move is that of the
    // steps it kept (0.005 h each), not the rejected 5 h
    sphTest::throwOnFatal();
    const fileName dir = makeCase("timeLoopLimits", "startTime");
    sphTest::run
    (
        "echo 'adjustTimeStep yes; retryOnFailure 1;' >> "
      + dir/"system"/"controlDict"
     + " && echo 'maxStepDisplacement 10; maxSpeed 5;' >> "
      + dir/"system"/"sphSchemes"
    );
    testing::internal::CaptureStdout();
    try
    {
        auto runTime = sphTest::makeTime(dir);
        passiveScalar solver(*runTime, -1, 0.5);
        SPH::timeLoop(*runTime, solver).run();
    }
    catch (const Foam::error& err)
    {
        testing::internal::GetCapturedStdout();
        FAIL() << err.message();
    }
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_NE(out.find("1 retries, 1 steps rescued"), std::string::npos) << out;
    const std::size_t move = out.find("Largest move in a step: ");
    ASSERT_NE(move, std::string::npos) << out;
    EXPECT_NEAR(std::stod(out.substr(move + 24)), 0.005, 1e-9) << out;
    const std::size_t speed = out.find("Largest fluid speed: ");
    ASSERT_NE(speed, std::string::npos) << out;
    EXPECT_NEAR(std::stod(out.substr(speed + 21)), 0.01, 1e-12) << out;
}


// ************************************************************************* //


TEST(sphCloud, sortFluidByCellOrdersTheFluidAndLeavesTheWalls)
{
    auto runTime = sphTest::makeTime(sphTest::makeCase("cloudSortByCell"));
    autoPtr<SPH::kernel> W
    (
        SPH::kernel::New(sphTest::dict("kernel wendlandC2; hByDr 2;"), 0.05)
    );
    SPH::wallMesh walls(wordList({"floor"}), floor(), 0.05);
    SPH::particles parts(*runTime, runTime->timeName());
    parts.add<vector2D>("U");
    parts.add<label>("id");

    // 200 fluid particles scattered over the box, then 5 wall particles
    const label nFluid = 200;
    parts.resize(nFluid + 5);
    Random rnd(7);
    forAll(parts.positions(), i)
    {
        parts.positions()[i] =
            vector2D(rnd.sample01<scalar>(), rnd.sample01<scalar>());
        parts.field<vector2D>("U")[i] = 2*parts.positions()[i];
        parts.field<label>("id")[i] = i;
    }
    const List<vector2D> x0(parts.positions());
    SPH::sphCloud cloud
    (
        *runTime, parts, *W, walls, nFluid, 0.05, 1000, vector2D::zero,
        SPH::domain(vector2D(-0.1, -0.2), vector2D(1.1, 1.1))
    );

    const labelList oldOfNew(cloud.sortFluidByCell());
    ASSERT_EQ(oldOfNew.size(), nFluid);

    const SPH::cellLinkedList& cells = cloud.cells();
    const vector2DField& x = parts.positions();
    const labelField& id = parts.field<label>("id");
    for (label k = 0; k < nFluid; ++k)
    {
        // Each particle kept its own fields: id, position and U together
        EXPECT_EQ(id[k], oldOfNew[k]);
        EXPECT_EQ(x[k], x0[oldOfNew[k]]);
        EXPECT_EQ(parts.field<vector2D>("U")[k], 2*x[k]);
        if (k > 0)
        {
            // Cell by cell, ascending old index within a cell
            const label c0 = cells.cellIndex(x[k - 1]);
            const label c1 = cells.cellIndex(x[k]);
            EXPECT_TRUE(c0 < c1 || (c0 == c1 && id[k - 1] < id[k])) << k;
        }
    }
    for (label i = nFluid; i < x.size(); ++i)
    {
        EXPECT_EQ(id[i], i);
        EXPECT_EQ(x[i], x0[i]);
    }

    // The cell list was rebuilt on the new numbering
    label nListed = 0;
    forAll(x, i)
    {
        cells.forEachNeighbour(x[i], 1e-12, [&](const label j, const vector2D&, const scalar)
        {
            nListed += (j == i);
        });
    }
    EXPECT_EQ(nListed, x.size());
}
