/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    isphFoam's airPockets (constant/transportProperties): a round hole of
    radius 0.1 m, 0.2 m under the surface of the still tank (dr = 0.02 m,
    to t = 0.1 s). Without the model the hole is a free surface at p = 0
    and the water above falls into it: at 0.1 s no 2 dr cell of the hole's
    square is empty. With it the hole is a pocket whose air keeps
    p A^1.4 = pAtm A0^1.4 (each logged line's p against its A and A0):
    - freeSurfaceCondition ghost, the pressure implicit: the law to 1e-3
      pAtm (linearised over a step), the pocket's pressure that of the water
      round it (rho g 0.2 m = 1962 Pa at the start; 1.2-1.9 kPa logged as it
      rises) within 0.25-1.5 times that after 0.02 s, 12 of the 16 cells
      empty at 0.1 s;
    - freeSurfaceCondition dirichlet, explicit: the law to 1e-6, the pocket
      kept (it rings from -7 to +9 kPa, which the implicit coupling is for).
    Bad entries name the file and the entry.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "restartCheck.H"

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string bin = std::string(SPHFOAM_BINARY_DIR) + "/applications/";

    //- The still tank with the hole, airPockets entries appended to
    //- constant/transportProperties (none: no airPockets)
    fileName holeTank(const word& name, const std::string& entries)
    {
        const fileName dir =
            fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/name;
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        EXPECT_EQ
        (
            run
            (
                "cp -r " + std::string(SPHFOAM_SOURCE_DIR)
              + "/tutorials/isph/hydrostaticTank " + dir + " && cd " + dir
              + " && sed -i 's/^dr .*/dr 0.02;/;"
                " s/^\\( *water .*\\)$/\\1\\n    hole { type circle;"
                " centre (0.5 0.3); radius 0.1; operation subtract; }/'"
                " system/sphMeshDict"
                " && sed -i 's/^endTime .*/endTime 0.1;/; s/^writeInterval .*/"
                "writeInterval 0.1;/; s/^logInterval .*/logInterval 1;/'"
                " system/controlDict"
                " && sed -i 's/^freeSurface .*/freeSurface yes;\\n"
                "freeSurfaceCondition ghost;/' system/sphSchemes",
                out
            ),
            0
        ) << out;
        if (!entries.empty())
        {
            std::ofstream os
            (
                dir/"constant"/"transportProperties", std::ios::app
            );
            os << "\nairPockets\n{\n" << entries << "}\n";
        }
        EXPECT_EQ(run(bin + "sphMesh -case " + dir, out), 0) << out;
        return dir;
    }

    //- A logged "Air pockets: n, the largest A m^2 about (x y) at p P Pa
    //- (closed at A0 m^2)" and its time
    struct pocketLine { scalar t; label n; scalar A, p, A0; };

    std::vector<pocketLine> pocketLines(const std::string& out)
    {
        const std::regex line
        (
            "Air pockets: (\\d+), the largest ([-0-9.e+]+) m\\^2 about"
            " \\(([-0-9.e+]+) ([-0-9.e+]+)\\) at p ([-0-9.e+]+) Pa"
            " \\(closed at ([-0-9.e+]+) m\\^2\\)"
        );
        std::vector<pocketLine> lines;
        std::istringstream is(out);
        std::string s;
        scalar t = 0;
        while (std::getline(is, s))
        {
            if (s.rfind("Time = ", 0) == 0) t = std::stod(s.substr(7));
            std::smatch m;
            if (std::regex_search(s, m, line))
            {
                lines.push_back
                ({
                    t, label(std::stoi(m[1])), std::stod(m[2]),
                    std::stod(m[5]), std::stod(m[6])
                });
            }
        }
        return lines;
    }

    //- Empty 2 dr cells of the hole's square in the last VTK file
    label emptyHoleCells(const fileName& dir)
    {
        const std::string script =
            "import glob, sys, numpy as np\n"
            "from vtkmodules.vtkIOXML import vtkXMLPolyDataReader\n"
            "from vtkmodules.util.numpy_support import vtk_to_numpy as v\n"
            "f = max(glob.glob(sys.argv[1] + '/VTK/*_[0-9]*.vtp'),"
            " key=lambda s: int(s.rsplit('_', 1)[1][:-4]))\n"
            "r = vtkXMLPolyDataReader(); r.SetFileName(f); r.Update()\n"
            "o = r.GetOutput(); d = o.GetPointData()\n"
            "x = v(o.GetPoints().GetData()); t = v(d.GetArray('type'))\n"
            "H, _, _ = np.histogram2d(x[t == 0, 0], x[t == 0, 1],"
            " bins=[np.arange(0.42, 0.6, 0.04), np.arange(0.22, 0.4, 0.04)])\n"
            "print('empty', int((H == 0).sum()), 'of', H.size)\n";
        {
            std::ofstream os(dir/"emptyHoleCells.py");
            os << script;
        }
        std::string out;
        EXPECT_EQ
        (
            run
            (
                std::string(SPHFOAM_PYTHON) + " "
              + std::string(dir/"emptyHoleCells.py") + " " + dir, out
            ),
            0
        ) << out;
        std::smatch m;
        EXPECT_TRUE(std::regex_search(out, m, std::regex("empty (\\d+) of")))
            << out;
        return m.empty() ? -1 : std::stoi(m[1]);
    }
}


TEST(isphFoamAirPockets, withoutThemTheWaterFallsIntoAnEnclosedHole)
{
    const fileName dir = holeTank("isphNoAirPocket", "");
    std::string out;
    ASSERT_EQ(run(bin + "isphFoam -case " + dir, out), 0)
        << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
    EXPECT_EQ(out.find("Air pockets"), std::string::npos);
    EXPECT_EQ(emptyHoleCells(dir), 0);
}


TEST(isphFoamAirPockets, theAirInAnEnclosedHoleHoldsItAtThePressureOfTheWaterRound)
{
    // Ghost surface rows: the pressure is implicit (airPocketCoupling)
    const fileName dir = holeTank("isphAirPocket", "    gamma 1.4;\n");
    std::string out;
    ASSERT_EQ(run(bin + "isphFoam -case " + dir, out), 0)
        << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
    EXPECT_NE(out.find("air closed off by the water keeps p = pAtm"), std::string::npos)
        << out.substr(0, 5000);
    EXPECT_NE(out.find("the pockets' pressure implicit"), std::string::npos);

    const std::vector<pocketLine> lines(pocketLines(out));
    ASSERT_GT(lines.size(), 5u) << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
    const scalar pWater = 1000*9.81*0.2;
    for (const pocketLine& l : lines)
    {
        // The air's law, linearised over a step
        EXPECT_NEAR(l.p, 101325*(std::pow(l.A0/l.A, 1.4) - 1), 1e-3*101325);
        if (l.t > 0.02)
        {
            EXPECT_GT(l.p, 0.25*pWater) << "t = " << l.t;
            EXPECT_LT(l.p, 1.5*pWater) << "t = " << l.t;
        }
    }
    EXPECT_EQ(lines.back().n, 1);
    EXPECT_NEAR(lines.back().A, lines.back().A0, 0.05*lines.back().A0);
    EXPECT_GE(emptyHoleCells(dir), 12);
}


TEST(isphFoamAirPockets, withTheDirichletSurfaceThePressureIsTheAreasOfTheStepsStart)
{
    // The paper's p = 0 rows take the pocket's pressure, explicit: the
    // pocket rings from -7 to +9 kPa, but holds
    const fileName dir = holeTank("isphAirPocketDirichlet", "");
    std::string out;
    ASSERT_EQ
    (
        run
        (
            "cd " + dir + " && sed -i 's/^freeSurfaceCondition .*/"
            "freeSurfaceCondition dirichlet;/' system/sphSchemes"
            " && printf '\\nairPockets {}\\n' >> constant/transportProperties",
            out
        ),
        0
    ) << out;
    ASSERT_EQ(run(bin + "isphFoam -case " + dir, out), 0)
        << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
    EXPECT_EQ(out.find("the pockets' pressure implicit"), std::string::npos);
    const std::vector<pocketLine> lines(pocketLines(out));
    ASSERT_GT(lines.size(), 5u) << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
    for (const pocketLine& l : lines)
    {
        EXPECT_NEAR(l.p, 101325*(std::pow(l.A0/l.A, 1.4) - 1), 1e-6*101325);
    }
    EXPECT_EQ(lines.back().n, 1);
    EXPECT_GE(emptyHoleCells(dir), 8);
}


TEST(isphFoamAirPockets, aRestartGoesOnWithThePocketsAsTracked)
{
    // The pockets' A0, area, pressure and cells are in uniform/isphState:
    // run to 0.1 s and run to 0.05 s restarted to 0.1 s give the same files
    const fileName dir = holeTank("isphAirPocketRestart", "");
    std::string out;
    ASSERT_EQ
    (
        run("printf '\\nairPockets {}\\n' >> " + dir/"constant/transportProperties", out),
        0
    ) << out;
    sphTest::expectExactRestart("isphFoam", dir, "0.1", "0.05", "Air pockets: 1");
    const fileName state = dir/"0.1"/"uniform"/"isphState";
    EXPECT_EQ(run("grep -q airCells " + state, out), 0);

    // A state written for another grid is an error naming it
    const fileName twice(dir + "Twice");
    rmDir(twice/"0.1");
    run
    (
        "sed -i 's/^\\( *gridCells *\\).*/\\17;/' "
      + twice/"0.05"/"uniform"/"isphState", out
    );
    EXPECT_NE(run(bin + "isphFoam -case " + twice, out), 0) << out;
    EXPECT_NE(out.find("isphState"), std::string::npos) << out;
    EXPECT_NE(out.find("gridCells 7"), std::string::npos) << out;
}


TEST(isphFoamAirPockets, badEntriesNameTheFileAndEntry)
{
    for
    (
        const std::string entries :
        {
            "    gamma 0.5;\n", "    pAtm -1;\n", "    minArea abc;\n"
        }
    )
    {
        const fileName dir = holeTank("isphAirPocketBad", entries);
        std::string out;
        EXPECT_NE(run(bin + "isphFoam -case " + dir, out), 0) << out;
        EXPECT_NE(out.find("transportProperties"), std::string::npos) << out;
        const std::string key = entries.substr(4, entries.find(' ', 4) - 4);
        EXPECT_NE(out.find(key), std::string::npos) << out;
    }

    // Without a free surface there is no air to close off
    const fileName dir = holeTank("isphAirPocketConfined", "");
    std::string out;
    ASSERT_EQ
    (
        run
        (
            "cd " + dir + " && sed -i 's/^freeSurface .*/freeSurface no;/'"
            " system/sphSchemes && printf '\\nairPockets {}\\n'"
            " >> constant/transportProperties",
            out
        ),
        0
    );
    EXPECT_NE(run(bin + "isphFoam -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("airPockets in a flow without a free surface"), std::string::npos)
        << out;
}


// ************************************************************************* //
