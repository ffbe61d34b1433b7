/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    sphCompare as a user runs it:
    - on a coarse icoFoam cavity (tutorials/cavity/fv at 20 x 20 cells,
      Re = 100, run to steady state) against Ghia et al.'s centreline
      tables: the errors and the run time are written, and are those of a
      converged coarse solution;
    - on an SPH result holding a linear field, against the same field as an
      expression: the MLS-linear sampling adds no error of its own, on a
      line and at the particles (eq. (66)), whatever the dummies carry;
    - on bad input: a missing file, an unknown field, a wrong column, a
      time that is not there, each a fatal error naming the file and entry.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include "particles.H"
#include "Random.H"

#include <fstream>
#include <sstream>

using namespace Foam;
using sphTest::run;

namespace
{
    const std::string sphCompareExe =
        std::string(SPHFOAM_BINARY_DIR) + "/applications/sphCompare";

    const std::string referenceDir =
        std::string(SPHFOAM_SOURCE_DIR) + "/etc/reference";

    const std::string header =
        "FoamFile { version 2.0; format ascii; class dictionary; object sphCompareDict; }\n";

    //- The lines of a file that are not '#' comments, split in words
    List<List<std::string>> readTable(const fileName& file)
    {
        List<List<std::string>> rows;
        std::ifstream is(file);
        std::string line;
        while (std::getline(is, line))
        {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream ls(line);
            List<std::string> words;
            std::string w;
            while (ls >> w) words.append(w);
            rows.append(words);
        }
        return rows;
    }

    //- The line of errors.dat for this set, component and source
    List<std::string> errorRow
    (
        const fileName& errors,
        const std::string& set,
        const std::string& cmpt,
        const std::string& source
    )
    {
        for (const List<std::string>& row : readTable(errors))
        {
            if (row.size() >= 10 && row[0] == set && row[1] == cmpt && row[2] == source)
            {
                return row;
            }
        }
        return List<std::string>();
    }

    //- The lid-driven cavity of tutorials/cavity/fv at n x n cells, Re 100,
    //- run to steady state with icoFoam
    fileName icoFoamCavity(const std::string& name, const int n)
    {
        const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/name;
        rmDir(dir);
        mkDir(dir.path());
        std::string out;
        run
        (
            "cp -r " + std::string(SPHFOAM_SOURCE_DIR) + "/tutorials/cavity/fv " + dir
          + " && sed -i 's/^n .*/n " + std::to_string(n) + ";/; s/^Re .*/Re 100;/' "
          + dir + "/system/cavityParameters",
            out
        );
        EXPECT_EQ
        (
            run("cd " + dir + " && blockMesh > log.blockMesh 2>&1 && icoFoam > log.icoFoam 2>&1", out),
            0
        ) << out;
        return dir;
    }

    //- An SPH case holding, at time 1, a jittered 20 x 20 lattice of fluid
    //- particles carrying the linear fields U = (2 + 3x - 1.5y, 1 - 2x + 4y),
    //- p = 5x + 7y, and a row of dummies below y = 0 carrying nonsense; at
    //- time 2 the same particles with U = 0; and a log with a run time
    fileName linearSphCase(const std::string& name)
    {
        const fileName dir = sphTest::makeCase(name, "application isphFoam;\n");
        sphTest::writeFile(dir/"system"/"sphSchemes",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }\n"
            "kernel wendlandC2; hByDr 2;\n");
        sphTest::writeFile(dir/"system"/"sphMeshDict",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphMeshDict; }\n"
            "dr 0.05;\n");
        sphTest::writeFile(dir/"log.isphFoam",
            "Time = 1\nExecutionTime = 1.5 s  ClockTime = 2 s\n\n"
            "Time = 2\nExecutionTime = 3.25 s  ClockTime = 4 s\n\nEnd\n");

        auto runTime = sphTest::makeTime(dir);
        const label n = 20, nDummy = 20;
        const scalar dr = 1.0/n;
        Random rnd(42);

        SPH::particles parts(*runTime, "1", SPH::particles::defaultLocal, false);
        vector2DField& U = parts.add<vector2D>("U");
        scalarField& p = parts.add<scalar>("p");
        scalarField& rho = parts.add<scalar>("rho");
        labelField& type = parts.add<label>("type");
        parts.resize(n*n + nDummy);
        vector2DField& x = parts.positions();
        for (label k = 0; k < n*n; ++k)
        {
            x[k] = vector2D
            (
                (k % n + 0.5 + 0.3*(2*rnd.sample01<scalar>() - 1))*dr,
                (k / n + 0.5 + 0.3*(2*rnd.sample01<scalar>() - 1))*dr
            );
            U[k] = vector2D(2 + 3*x[k].x() - 1.5*x[k].y(), 1 - 2*x[k].x() + 4*x[k].y());
            p[k] = 5*x[k].x() + 7*x[k].y();
            rho[k] = 1000*(1 + 0.01*std::sin(scalar(k)));
            type[k] = 0;
        }
        for (label k = n*n; k < n*n + nDummy; ++k)
        {
            x[k] = vector2D((k - n*n + 0.5)*dr, -0.5*dr);
            U[k] = vector2D(1e3, -1e3);
            p[k] = 1e6;
            rho[k] = 1000;
            type[k] = 2;
        }
        runTime->setTime(1.0, 1);
        parts.write();

        U = vector2D::zero;
        runTime->setTime(2.0, 2);
        parts.write();
        return dir;
    }

    //- The comparison dictionary of the SPH case against the exact fields
    std::string linearDict(const std::string& extraSources = "", const std::string& fields = "(U p)")
    {
        return header +
            "sources\n{\n"
            "    sph { type sph; }\n"
            "    exact\n    {\n        type expression;\n"
            "        fields { Ux \"2 + 3*x - 1.5*y\"; Uy \"1 - 2*x + 4*y\"; p \"5*x + 7*y\"; }\n"
            "    }\n" + extraSources +
            "}\n"
            "sets\n{\n"
            "    diagonal { type line; start (0 0); end (1 1); nPoints 41; fields " + fields + "; sources (sph exact); reference exact; }\n"
            "    L2 { type sourcePoints; source sph; fields " + fields + "; reference exact; }\n"
            "}\n";
    }
}


TEST(sphCompare, icoFoamCavityAgainstGhiaWritesSensibleErrorsAndRunTime)
{
    const fileName dir = icoFoamCavity("sphCompareCavity", 20);

    // This FV result against Ghia's tables, at their points
    sphTest::writeFile(dir/"system"/"sphCompareDict", header +
        "sources\n{\n"
        "    fv { type fv; }\n"
        "    ghiaU { type table; file \"" + referenceDir + "/ghia1982_u_vertical_centreline.csv\";"
        " x 0.5; y y; columns { Ux Re100; } }\n"
        "    ghiaV { type table; file \"" + referenceDir + "/ghia1982_v_horizontal_centreline.csv\";"
        " x x; y 0.5; columns { Uy Re100; } }\n"
        "}\n"
        "sets\n{\n"
        "    uGhia { type table; source ghiaU; fields (Ux); }\n"
        "    vGhia { type table; source ghiaV; fields (Uy); }\n"
        "    uVertical { type line; start (0.5 0); end (0.5 1); nPoints 51; fields (U p); }\n"
        "}\n");

    std::string out;
    ASSERT_EQ(run(sphCompareExe + " -case " + dir, out), 0) << out;
    EXPECT_NE(out.find("End"), std::string::npos) << out;

    // The steady state of the run (controlDict stops it there)
    const fileName results = dir/"postProcessing"/"sphCompare";
    const fileNameList times(readDir(results, fileName::DIRECTORY));
    ASSERT_EQ(times.size(), 1) << out;
    const scalar tSteady = std::stod(times[0]);
    EXPECT_GT(tSteady, 5.0);
    EXPECT_LT(tSteady, 50.0);

    // Both tables compared at all their 17 points. icoFoam is 0.009 U from
    // Ghia at 32^2 and finer, where Ghia's own accuracy (0.01 U) dominates
    // (../shared/reference/README.md); at 20^2 its second-order error adds
    // about (32/20)^2 times that: within 0.03 U. The norms are of a real
    // difference, so neither is zero (measured: L2 0.005 and 0.007, maxAbs
    // 0.013 and 0.010)
    const fileName errors = results/times[0]/"errors.dat";
    for (const auto& sc : {std::make_pair("uGhia", "Ux"), std::make_pair("vGhia", "Uy")})
    {
        const List<std::string> row = errorRow(errors, sc.first, sc.second, "fv");
        ASSERT_EQ(row.size(), 10) << sc.first << "\n" << out;
        EXPECT_EQ(row[5], "17");
        const scalar L2 = std::stod(row[6]), maxAbs = std::stod(row[7]);
        EXPECT_GT(L2, 1e-4) << sc.first;
        EXPECT_LT(L2, 0.03) << sc.first;
        EXPECT_GE(maxAbs, L2) << sc.first;
        EXPECT_LT(maxAbs, 0.03) << sc.first;

        // The wall-clock time of icoFoam (its last ClockTime) is there
        EXPECT_NE(row[8], "-") << sc.first;
        EXPECT_GE(std::stod(row[8]), 0) << sc.first;
    }

    // The set file: distance x y weight, then each component of each source;
    // the lid velocity is met on the lid, no-slip at the bottom
    const List<List<std::string>> rows = readTable(results/times[0]/"uVertical.dat");
    ASSERT_EQ(rows.size(), 51);
    ASSERT_EQ(rows[0].size(), 4 + 3);           // Ux_fv Uy_fv p_fv
    EXPECT_NEAR(std::stod(rows[0][4]), 0, 1e-12);
    EXPECT_NEAR(std::stod(rows[50][4]), 1, 1e-12);
    EXPECT_NEAR(std::stod(rows[50][2]), 1, 1e-12);
}


TEST(sphCompare, sphSamplingOfALinearFieldAddsNoError)
{
    const fileName dir = linearSphCase("sphCompareLinear");
    sphTest::writeFile(dir/"system"/"sphCompareDict", linearDict());

    std::string out;
    ASSERT_EQ(run(sphCompareExe + " -case " + dir + " -time 1", out), 0) << out;

    // MLS-linear reproduces the linear fields along the diagonal, corners
    // included, and the particles' own values are the fields: round-off
    const fileName errors = dir/"postProcessing"/"sphCompare"/"1"/"errors.dat";
    for (const std::string set : {"diagonal", "L2"})
    {
        for (const std::string c : {"Ux", "Uy", "p"})
        {
            const List<std::string> row = errorRow(errors, set, c, "sph");
            ASSERT_EQ(row.size(), 10) << set << " " << c << "\n" << out;
            EXPECT_LT(std::stod(row[6]), 1e-11) << set << " " << c;
            EXPECT_LT(std::stod(row[7]), 1e-10) << set << " " << c;
            EXPECT_EQ(row[8], "4") << "clock of log.isphFoam";
        }
    }
    // Eq. (66) sums over the 400 fluid particles, not the dummies
    EXPECT_EQ(errorRow(errors, "L2", "Ux", "sph")[5], "400");

    // Without -time, the latest time (2, where U = 0)
    ASSERT_EQ(run(sphCompareExe + " -case " + dir, out), 0) << out;
    const List<std::string> latest =
        errorRow(dir/"postProcessing"/"sphCompare"/"2"/"errors.dat", "L2", "Ux", "sph");
    ASSERT_EQ(latest.size(), 10) << out;
    EXPECT_GT(std::stod(latest[7]), 1.0);
}


TEST(sphCompare, aSourcesSmoothingLengthAppliesToTheCasesKernel)
{
    const fileName dir = linearSphCase("sphCompareSourceHByDr");
    auto withSource = [](const std::string& entries)
    {
        std::string d = linearDict();
        const std::string plain = "    sph { type sph; }";
        return d.replace(d.find(plain), plain.size(), "    sph { type sph; " + entries + " }");
    };

    // hByDr 1 alone: the case's wendlandC2 over 2 dr (it was left out, the
    // case's hByDr 2 taken instead), still exact for the linear fields
    sphTest::writeFile(dir/"system"/"sphCompareDict", withSource("interpolationOrder 1; hByDr 1;"));
    std::string out;
    ASSERT_EQ(run(sphCompareExe + " -case " + dir + " -time 1", out), 0) << out;
    EXPECT_NE(out.find("Selecting kernel wendlandC2"), std::string::npos) << out;
    EXPECT_NE(out.find("hByDr 1, dr 0.05"), std::string::npos) << out;
    const List<std::string> row = errorRow
    (
        dir/"postProcessing"/"sphCompare"/"1"/"errors.dat", "diagonal", "Ux", "sph"
    );
    ASSERT_EQ(row.size(), 10) << out;
    EXPECT_LT(std::stod(row[7]), 1e-10);

    // Out of range: an error naming the source's entry
    sphTest::writeFile(dir/"system"/"sphCompareDict", withSource("hByDr 0.5;"));
    EXPECT_EQ(run(sphCompareExe + " -case " + dir + " -time 1", out), 1) << out;
    for (const std::string w : {"FOAM FATAL IO ERROR", "hByDr", "sphCompareDict.sources.sph"})
    {
        EXPECT_NE(out.find(w), std::string::npos) << "'" << w << "' in\n" << out;
    }
}


TEST(sphCompare, timeRangesCompareAtEachSelectedTime)
{
    const fileName dir = linearSphCase("sphCompareRanges");
    sphTest::writeFile(dir/"system"/"sphCompareDict", linearDict());
    const fileName results = dir/"postProcessing"/"sphCompare";

    // OpenFOAM's '1:' selects 1 and 2: one comparison at each, the linear
    // field of 1 exact, the zero velocity of 2 not
    std::string out;
    ASSERT_EQ(run(sphCompareExe + " -case " + dir + " -time '1:'", out), 0) << out;
    EXPECT_NE(out.find("Time = 1"), std::string::npos) << out;
    EXPECT_NE(out.find("Time = 2"), std::string::npos) << out;
    const List<std::string> at1 = errorRow(results/"1"/"errors.dat", "L2", "Ux", "sph");
    const List<std::string> at2 = errorRow(results/"2"/"errors.dat", "L2", "Ux", "sph");
    ASSERT_EQ(at1.size(), 10) << out;
    ASSERT_EQ(at2.size(), 10) << out;
    EXPECT_LT(std::stod(at1[7]), 1e-10);
    EXPECT_GT(std::stod(at2[7]), 1.0);

    // -latestTime: 2 only
    rmDir(results);
    ASSERT_EQ(run(sphCompareExe + " -case " + dir + " -latestTime", out), 0) << out;
    EXPECT_TRUE(isFile(results/"2"/"errors.dat")) << out;
    EXPECT_FALSE(isDir(results/"1")) << out;

    // A single value is that time, not the nearest (OpenFOAM's): 1.4 is an
    // error naming the times there are, and nothing is written
    rmDir(results);
    EXPECT_EQ(run(sphCompareExe + " -case " + dir + " -time 1.4", out), 1) << out;
    for (const std::string w : {"FOAM FATAL ERROR", "no time 1.4", "Times:"})
    {
        EXPECT_NE(out.find(w), std::string::npos) << "'" << w << "' in\n" << out;
    }
    EXPECT_FALSE(isDir(results)) << out;

    // An item that is not a time or a range, beside one that is
    EXPECT_EQ(run(sphCompareExe + " -case " + dir + " -time '1,abc'", out), 1) << out;
    EXPECT_NE(out.find("'abc' is not a time or a range"), std::string::npos) << out;
    EXPECT_FALSE(isDir(results)) << out;

    // A range with no time in it
    EXPECT_EQ(run(sphCompareExe + " -case " + dir + " -time '5:9'", out), 1) << out;
    EXPECT_NE(out.find("select no time"), std::string::npos) << out;
}


TEST(sphCompare, fvCaseFromTheCommandLine)
{
    const fileName dir = linearSphCase("sphCompareWithFv");
    const fileName fv = icoFoamCavity("sphCompareWithFvCavity", 10);
    sphTest::writeFile(dir/"system"/"sphCompareDict", linearDict("    fv { type fv; case \"nowhere\"; }\n"));

    // -fv replaces the case of the source named fv
    std::string out;
    ASSERT_EQ(run(sphCompareExe + " -case " + dir + " -time 1 -fv " + fv, out), 0) << out;
    const List<List<std::string>> rows =
        readTable(dir/"postProcessing"/"sphCompare"/"1"/"L2.dat");
    ASSERT_EQ(rows.size(), 400);
    // distance x y weight, Ux of sph exact fv, Uy ..., p ...
    ASSERT_EQ(rows[0].size(), 4 + 3*3);
    for (const List<std::string>& r : rows)
    {
        EXPECT_NE(r[6], "nan");     // every particle lies in the mesh
    }
}


TEST(sphCompare, badInputIsAFatalErrorNamingTheFileAndEntry)
{
    const fileName dir = linearSphCase("sphCompareBadInput");
    const std::string dictFile = dir/"system"/"sphCompareDict";
    std::string out;

    auto expectFailure = [&](const std::string& args, const List<std::string>& words)
    {
        EXPECT_EQ(run(sphCompareExe + " -case " + dir + " " + args, out), 1) << out;
        for (const std::string& w : words)
        {
            EXPECT_NE(out.find(w), std::string::npos) << "'" << w << "' in\n" << out;
        }
    };

    // A table file that is not there
    sphTest::writeFile(dictFile, linearDict
    (
        "    ghia { type table; file \"" + referenceDir + "/ghia1982_missing.csv\";"
        " x 0.5; y y; columns { Ux Re100; } }\n"
    ));
    expectFailure("", {"FOAM FATAL IO ERROR", "ghia1982_missing.csv", "sphCompareDict.sources.ghia"});

    // A column that the table does not have
    sphTest::writeFile(dictFile, linearDict
    (
        "    ghia { type table; file \"" + referenceDir + "/ghia1982_u_vertical_centreline.csv\";"
        " x 0.5; y y; columns { Ux Re999; } }\n"
    ));
    expectFailure
    (
        "",
        {"FOAM FATAL IO ERROR", "Re999", "ghia1982_u_vertical_centreline.csv",
         "sphCompareDict.sources.ghia.columns", "Re1000"}
    );

    // A field the SPH result does not hold
    sphTest::writeFile(dictFile, linearDict("", "(U T)"));
    expectFailure("", {"FOAM FATAL IO ERROR", "no field T", "sphCompareDict.sets.diagonal", "fields"});

    // A time that is not there
    sphTest::writeFile(dictFile, linearDict());
    expectFailure("-time 7", {"FOAM FATAL ERROR", "-time", "no time 7", "Times:"});

    // An FV case that is not there
    expectFailure("-fv " + dir + "/nowhere", {"FOAM FATAL IO ERROR", "nowhere", "is not a case"});

    // An unknown source type lists the valid ones
    sphTest::writeFile(dictFile, linearDict("    other { type tabel; }\n"));
    expectFailure("", {"tabel", "expression", "table", "sphCompareDict.sources.other"});
}


// ************************************************************************* //
