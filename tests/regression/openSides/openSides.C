/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    openSides of system/sphMeshDict (SPH::domain, SPH::openSideCrossings)
    in both solvers: the hydrostatic tank without its lid (walls: a
    polyline down the left side, along the floor, up the right side) and
    gravity turned upwards, so that the water falls out over the top of the
    walls' box (0.75 m, the domain's margin taking it to 1.14 m at
    dr = 0.05 m; in 0.6 s water falling at g goes 1.77 m). By default the
    first particle beyond the box stops the run (exit 1, the last good state
    written); with openSides (yMax) the run ends, every particle that went
    beyond the top is logged once, where, when and how fast, the summary
    counts the same crossings and as many particles beyond the top as the
    written state has, and no particle is lost (measured: isphFoam 171 of
    190 beyond at 0.6 s, wcsphFoam 110 of 200).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particles.H"

#include <regex>
#include <string>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";

    //- The solver's tank without its lid, g upwards, meshed
    fileName openTank(const std::string& solver, const std::string& name)
    {
        const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/name;
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        const std::string tank
        (
            "tank { type polyline; points ((0 0.75) (0 0) (1 0) (1 0.75)); }"
        );
        EXPECT_EQ
        (
            run
            (
                "cp -r " + std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/"
              + solver + "/hydrostaticTank " + dir
              + " && cd " + dir
              + " && sed -i 's/^dr .*/dr 0.05;/; s/^ *tank .*/    " + tank + "/'"
                " system/sphMeshDict"
              + " && sed -i 's/^endTime .*/endTime 0.6;/; s/^writeInterval .*/"
                "writeInterval 0.6;/' system/controlDict"
              + " && sed -i 's/^value .*/value           (0 9.81 0);/' constant/g",
                out
            ),
            0
        ) << out;
        if (solver == "isph")
        {
            // The liquid holds no tension: it leaves the floor (the wall
            // condition (43) would hold it there, hanging)
            run
            (
                "sed -i 's/^ *stopIfNotConverged .*/&\\n    pMin 0;/' "
              + dir + "/system/sphSolution", out
            );
        }
        EXPECT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
        return dir;
    }

    std::size_t count(const std::string& s, const std::string& what)
    {
        std::size_t n = 0;
        for (auto at = s.find(what); at != std::string::npos; at = s.find(what, at + 1))
        {
            ++n;
        }
        return n;
    }

    std::string tail(const std::string& s, std::size_t n = 3000)
    {
        return s.size() > n ? s.substr(s.size() - n) : s;
    }

    void checkOpenTop(const std::string& solver)
    {
        const fileName dir = openTank(solver, solver + "OpenTop");
        std::string out;
        ASSERT_EQ(run("grep -c polyline " + dir + "/system/sphMeshDict", out), 0) << out;

        // The default: a loud stop that names the way out
        EXPECT_EQ(run(bin + solver + "Foam -case " + dir, out), 1) << tail(out);
        EXPECT_NE(out.find("Left the domain"), std::string::npos) << tail(out);
        EXPECT_NE(out.find("openSides in system/sphMeshDict"), std::string::npos)
            << tail(out);

        // Open above: it runs to the end, and says what went over the top
        run
        (
            "cd " + dir + " && rm -rf 0.* VTK postProcessing constant/sphMesh"
            " && echo 'openSides (yMax);' >> system/sphMeshDict", out
        );
        ASSERT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
        EXPECT_NE(out.find("open sides"), std::string::npos) << out;
        ASSERT_EQ(run(bin + solver + "Foam -case " + dir, out), 0) << tail(out);
        EXPECT_NE(out.find("crossings are logged"), std::string::npos) << tail(out);

        const std::size_t logged = count(out, "went beyond the open side yMax (y = ");
        const std::smatch m = [&]()
        {
            std::smatch r;
            static const std::regex summary
            (
                "Fluid particles beyond the open sides yMax: ([0-9]+) crossings.*"
                ", ([0-9]+) beyond at the end \\(of ([0-9]+) fluid particles, none removed\\)"
            );
            std::regex_search(out, r, summary);
            return r;
        }();
        ASSERT_EQ(m.size(), 4u) << tail(out);
        const label crossings = std::stoi(m[1]);
        const label beyond = std::stoi(m[2]);
        const label nFluid = std::stoi(m[3]);
        EXPECT_GT(crossings, 0) << tail(out);
        EXPECT_EQ(std::size_t(crossings), logged) << tail(out);
        EXPECT_GT(beyond, 0) << tail(out);
        EXPECT_LE(beyond, nFluid) << tail(out);
        EXPECT_NE(out.find("moving at "), std::string::npos) << tail(out);

        // Every particle is still there, and those the summary counts
        // beyond the top are beyond the box's top in the written state
        // (the walls' 0.75 m grown by a quarter of their size and a kernel
        // support, as the crossings' lines give it)
        std::smatch lineMatch;
        ASSERT_TRUE
        (
            std::regex_search
            (
                out, lineMatch,
                std::regex("went beyond the open side yMax \\(y = ([0-9.e+-]+) m\\)")
            )
        ) << tail(out);
        const scalar top = std::stod(lineMatch[1]);
        EXPECT_GT(top, 0.75 + 0.25*0.75);
        auto runTime = sphTest::makeTime(dir);
        SPH::particles parts(*runTime, "0.6", SPH::particles::defaultLocal, false);
        parts.add<label>("type");
        parts.read();
        label nRead = 0, above = 0;
        forAll(parts.positions(), i)
        {
            if (parts.field<label>("type")[i] != 0) continue;
            ++nRead;
            above += parts.positions()[i].y() > top;
        }
        EXPECT_EQ(nRead, nFluid);
        EXPECT_EQ(above, beyond);
    }
}


TEST(openSides, isphWaterFallingOutOfAnOpenTopIsLoggedNotStopped)
{
    checkOpenTop("isph");
}


TEST(openSides, wcsphWaterFallingOutOfAnOpenTopIsLoggedNotStopped)
{
    checkOpenTop("wcsph");
}


// ************************************************************************* //
