/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Fuzz test of sphMesh (issue 12): generated sphMeshDict variants, each
    run as a user would (FOAM_SIGFPE on, `timeout 20`):

    - every number of a small valid case (dr, the fluid box and circle,
      the wall box, arc radius and angles, latticeOrigin, nDummyLayers,
      maxParticles) replaced in turn by nan, inf, -inf, 1e400, -1e400,
      1e300, -1e300, 1e16 and a word;
    - broken shapes, duplicate names, crossing and overlapping walls,
      names that are not words, entries of the wrong kind;
    - the valid dictionary truncated at every 23rd character.

    A variant must fail with exit status 1 and name the file (sphMeshDict)
    or the entry, or, when it is listed as accepted, succeed with fluid
    particles written. Never a signal (exit 128 + n), a timeout (124) or a
    stack trace.

    Accepted (documented): valid cases at the checks' edges: a lattice
    origin off the walls' corner, 100 dummy layers, maxParticles above the
    estimate, a region exactly 2 dr across, names with . - : _, a wall end
    standing on another wall (a T junction), a subtracted hole, an arc of
    about dr (0.1 x 30 degrees = 0.052 >= dr 0.05).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testCase.H"
#include <regex>
#include <vector>

using sphTest::run;

namespace
{
    const std::string sphMesh =
        "FOAM_SIGFPE=true timeout 20 " + std::string(SPHFOAM_BINARY_DIR) + "/applications/sphMesh";

    struct variant
    {
        std::string name;
        std::string body;
        //- Words of which the output must hold one (besides sphMeshDict)
        std::string entry;
        bool accepted;
    };

    //- The valid case, each number a slot @k@
    const std::string templ =
        "dr @0@;\n"
        "nDummyLayers @1@;\n"
        "maxParticles @2@;\n"
        "latticeOrigin (@3@ @4@);\n"
        "fluid\n{\n"
        "    water { type box; min (@5@ @6@); max (@7@ @8@); }\n"
        "    drop { type circle; centre (0.6 0.6); radius @9@; }\n"
        "}\n"
        "walls\n{\n"
        "    tank { type box; min (@10@ @11@); max (@12@ @13@); }\n"
        "    bump { type arc; centre (0.5 1); radius @14@; startAngle @15@; endAngle @16@; side outside; }\n"
        "}\n"
        "// end of the valid case\n";

    const std::vector<std::string> valid =
        {"0.05", "2", "100000", "0", "0", "0", "0", "0.5", "0.4", "0.1",
         "0", "0", "1", "1", "0.2", "200", "340"};

    const std::vector<std::string> slotEntry =
        {"dr", "nDummyLayers", "maxParticles", "latticeOrigin", "latticeOrigin",
         "min", "min", "max", "max", "radius", "min", "min", "max", "max",
         "radius", "startAngle", "endAngle"};

    std::string fill(const std::vector<std::string>& v)
    {
        std::string s = templ;
        for (size_t k = 0; k < v.size(); ++k)
        {
            const std::string key = "@" + std::to_string(k) + "@";
            s.replace(s.find(key), key.size(), v[k]);
        }
        return s;
    }

    std::vector<variant> variants()
    {
        std::vector<variant> all;
        all.push_back({"valid", fill(valid), "", true});

        const std::vector<std::string> bad =
            {"nan", "inf", "-inf", "1e400", "-1e400", "1e300", "-1e300", "1e16", "x"};
        for (size_t k = 0; k < valid.size(); ++k)
        {
            for (const std::string& b : bad)
            {
                std::vector<std::string> v(valid);
                v[k] = b;
                all.push_back({slotEntry[k] + "=" + b, fill(v), slotEntry[k], false});
            }
        }

        // Numbers in range but wrong
        auto with = [&](size_t k, const std::string& b, const std::string& entry)
        {
            std::vector<std::string> v(valid);
            v[k] = b;
            all.push_back({slotEntry[k] + "=" + b, fill(v), entry, false});
        };
        with(0, "0", "dr");
        with(0, "-0.05", "dr");
        with(0, "1e-12", "dr");
        with(0, "1e-4", "maxParticles");
        with(0, "0.6", "spacing");
        with(0, "2", "dr");
        with(1, "0", "nDummyLayers");
        with(1, "-3", "nDummyLayers");
        with(1, "1000000000", "nDummyLayers");
        with(2, "0", "maxParticles");
        with(2, "10", "maxParticles");
        with(3, "1e9", "latticeOrigin");
        with(7, "-1", "max");
        with(7, "3", "outside the walls");
        with(9, "0", "radius");
        with(9, "-1", "radius");
        with(10, "1", "tank");
        with(12, "0", "tank");
        with(14, "0", "radius");
        with(14, "1e5", "maxParticles");
        with(15, "340", "startAngle");
        with(16, "200.0000000001", "bump");
        with(16, "1000", "endAngle");

        const std::string head = "dr 0.05;\nfluid { water { type box; min (0 0); max (0.5 0.4); } }\n";
        const std::string tank = "walls { tank { type box; min (0 0); max (1 1); } }\n";
        auto add = [&](const std::string& name, const std::string& body, const std::string& entry)
        {
            all.push_back({name, body, entry, false});
        };
        add("noDr", "fluid { w { type box; min (0 0); max (1 1); } }\n" + tank, "dr");
        add("noFluid", "dr 0.05;\n" + tank, "fluid");
        add("noWalls", head, "walls");
        add("fluidList", "dr 0.05;\nfluid ((0 0) (1 1));\n" + tank, "fluid");
        add("wallsWord", head + "walls tank;\n", "walls");
        add("wallNotDict", head + "walls { tank 1; }\n", "tank");
        add("regionNotDict", "dr 0.05;\nfluid { water 1; }\n" + tank, "water");
        add("emptyFluid", "dr 0.05;\nfluid { }\n" + tank, "fluid");
        add("emptyWalls", head + "walls { }\n", "wall");
        add("drList", "dr (0.05 0.05);\n" + tank, "dr");
        add("unknownWall", head + "walls { tank { type hexagon; } }\n", "hexagon");
        add("unknownRegion", "dr 0.05;\nfluid { w { type blob; } }\n" + tank, "blob");
        add("boxNoMax", head + "walls { tank { type box; min (0 0); } }\n", "max");
        add("boxInverted", head + "walls { tank { type box; min (1 1); max (0 0); } }\n", "tank");
        add("boxFlat", head + "walls { tank { type box; min (0 0); max (1 0); } }\n", "tank");
        add("point3", head + "walls { tank { type box; min (0 0 0 0); max (1 1); } }\n", "min");
        add("point1", head + "walls { tank { type box; min (0); max (1 1); } }\n", "min");
        add("polygon2", head + "walls { tank { type polygon; points ((0 0) (1 1)); } }\n", "tank");
        add("polygonBowTie", head + "walls { tank { type polygon; points ((0 0) (1 1) (1 0) (0 1)); } }\n", "self-intersecting");
        add("polygonRepeat", head + "walls { tank { type polygon; points ((0 0) (1 0) (1 1) (0 1) (0 0)); } }\n", "tank");
        add("polygonCollinear", head + "walls { tank { type polygon; points ((0 0) (1 0) (2 0)); } }\n", "tank");
        add("polylineZero", head + "walls { tank { type polyline; points ((0 1) (0 0) (0 0) (1 0)); } }\n", "zero-length");
        add("polylineOne", head + "walls { tank { type polyline; points ((0 1)); } }\n", "tank");
        add("polylineCrossing", head + "walls { tank { type box; min (0 0); max (1 1); }\n"
            "  zig { type polyline; points ((0.7 0.1) (0.9 0.9) (0.9 0.1) (0.7 0.9)); } }\n", "zig");
        add("badSide", head + "walls { tank { type box; min (0 0); max (1 1); side up; } }\n", "side");
        add("badOperation", "dr 0.05;\nfluid { w { type box; min (0 0); max (1 1); operation xor; } }\n" + tank, "operation");
        add("firstSubtract", "dr 0.05;\nfluid { w { type box; min (0 0); max (1 1); operation subtract; } }\n" + tank, "subtract");
        add("fluidPolygonOpen", "dr 0.05;\nfluid { w { type polygon; points ((0 0) (1 1)); } }\n" + tank, "points");
        add("duplicatePatch", head + "walls { tank { type box; min (0 0); max (1 1); }\n"
            "  tank { type box; min (0 0); max (2 2); } }\n", "tank");
        add("duplicateRegion", "dr 0.05;\nfluid { w { type box; min (0 0); max (0.5 0.5); }\n"
            "  w { type box; min (0 0); max (0.2 0.2); } }\n" + tank, "w");
        add("duplicateDr", "dr 0.05;\ndr 0.1;\nfluid { w { type box; min (0 0); max (0.5 0.5); } }\n" + tank, "dr");
        add("twoBoxes", head + "walls { tank { type box; min (0 0); max (1 1); }\n"
            "  again { type box; min (0 0); max (1 1); } }\n", "overlap");
        add("halfOverlap", head + "walls { tank { type box; min (0 0); max (1 1); }\n"
            "  shelf { type line; points ((0.2 0) (0.6 0)); } }\n", "overlap");
        add("crossingLine", head + "walls { tank { type box; min (0 0); max (1 1); }\n"
            "  baffle { type line; points ((0.75 -0.5) (0.75 0.5)); } }\n", "cross");
        add("sameCircles", head + "walls { tank { type box; min (-1 -1); max (2 2); }\n"
            "  a { type circle; centre (0.5 0.5); radius 0.3; side outside; }\n"
            "  b { type circle; centre (0.5 0.5); radius 0.3; side outside; } }\n", "overlap");
        for (const std::string& name :
             {"\"a b\"", "\"a;b\"", "\"a{b\"", "\"a}b\"", "\"a(b\"", "\"a/b\"", "\"a'b\"", "\"1abc\"", "\".*\""})
        {
            // The name in the message (refused by sphMesh, or by OpenFOAM's
            // reader as a regular expression); a slash scopes the keyword:
            // "a/b" is b in a, which has no type
            const std::string bare = std::string(name).substr(1, std::string(name).size() - 2);
            const std::string why = bare == "a/b" ? "sphMeshDict" : bare;
            add("wallName" + name, head + "walls { " + name + " { type box; min (0 0); max (1 1); } }\n",
                why);
            add("regionName" + name, "dr 0.05;\nfluid { " + name + " { type box; min (0 0); max (0.5 0.5); } }\n" + tank,
                why);
        }
        add("regionOutside", "dr 0.05;\nfluid { w { type box; min (0 0); max (0.5 0.5); }\n"
            "  far { type box; min (3 3); max (4 4); } }\n" + tank, "entirely outside");
        add("regionPartly", "dr 0.05;\nfluid { w { type box; min (0.5 0.5); max (1.5 0.8); } }\n" + tank, "outside the walls");
        add("fluidBehindObstacle", "dr 0.05;\nfluid { w { type box; min (0 0); max (1 1); } }\n"
            "walls { tank { type box; min (0 0); max (1 1); }\n"
            "  block { type box; min (0.4 0.4); max (0.6 0.6); side outside; } }\n", "outside the walls");
        add("periodicNotDict", head + tank + "periodic 1;\n", "periodic");
        add("periodicBadDir", head + tank + "periodic { directions (z); min (0 0); max (1 1); }\n", "directions");
        add("periodicPeriod", head + tank + "periodic { directions (x); min (0 0); max (1.013 1); }\n", "periodic");
        add("periodicNan", head + tank + "periodic { directions (x); min (0 0); max (nan 1); }\n", "max");
        add("includeMissing", "#include \"nonexistent\"\n" + head + tank, "nonexistent");
        add("unbalanced", head + "walls { tank { type box; min (0 0); max (1 1); }\n", "sphMeshDict");
        add("stray", head + tank + "}\n", "sphMeshDict");

        // Accepted (documented): valid cases near the checks' limits
        auto ok = [&](const std::string& name, const std::string& body)
        {
            all.push_back({name, body, "", true});
        };
        ok("acceptOrigin", "latticeOrigin (0.01 0.02);\n" + head + tank);
        ok("acceptLayers", "nDummyLayers 100;\n" + head + tank);
        ok("acceptMaxParticles", "maxParticles 1000;\n" + head + tank);
        ok("acceptTwoAcross", "dr 0.25;\nfluid { w { type box; min (0 0); max (0.5 0.5); } }\n" + tank);
        ok("acceptNames", head + "walls { Tank.left-1 { type line; points ((0 1) (0 0)); }\n"
            "  tank_bottom:2 { type polyline; points ((0 0) (1 0) (1 1) (0 1)); } }\n");
        ok("acceptTJunction", head + "walls { tank { type box; min (0 0); max (1 1); }\n"
            "  baffle { type line; points ((0.75 0) (0.75 0.3)); } }\n");
        ok("acceptSubtract", "dr 0.05;\nfluid { w { type box; min (0 0); max (0.5 0.4); }\n"
            "  hole { type circle; centre (0.25 0.2); radius 0.1; operation subtract; } }\n" + tank);
        ok("acceptArcOfDr", head + "walls { tank { type box; min (0 0); max (1 1); }\n"
            "  bump { type arc; centre (0.8 0.8); radius 0.1; startAngle 0; endAngle 30; side outside; } }\n");

        // The valid case cut short
        const std::string full = fill(valid);
        const size_t endOfData = full.find("// end");
        for (size_t n = 0; n < endOfData; n += 23)
        {
            add("truncated" + std::to_string(n), full.substr(0, n), "");
        }
        return all;
    }

    Foam::label count(const std::string& out, const std::string& what)
    {
        const std::smatch m = [&]
        {
            std::smatch r;
            std::regex_search(out, r, std::regex(what + " *([0-9]+)"));
            return r;
        }();
        return m.size() > 1 ? std::stol(m[1]) : -1;
    }
}


TEST(sphMeshFuzz, everyVariantFailsCleanlyOrIsAccepted)
{
    const std::vector<variant> all(variants());
    ASSERT_GE(all.size(), 150u);

    Foam::label nError = 0, nAccepted = 0;
    for (const variant& v : all)
    {
        std::string safe;
        for (const char c : v.name) safe += std::isalnum(c) ? c : '_';
        const Foam::fileName dir = sphTest::makeCase("sphMeshFuzz_" + safe);
        sphTest::writeFile(dir/"system"/"sphSchemes",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }\n"
            "kernel wendlandC2;\nhByDr 1.3;\n");
        sphTest::writeFile(dir/"system"/"sphMeshDict",
            "FoamFile { version 2.0; format ascii; class dictionary; object sphMeshDict; }\n"
            + v.body);

        std::string out;
        const int rc = run(sphMesh + " -case " + dir, out);
        const std::string where = "variant " + v.name + ":\n" + v.body + "\n---\n" + out;

        // Never a signal, a timeout or a stack trace
        EXPECT_TRUE(rc == 0 || rc == 1) << "exit " << rc << ", " << where;
        EXPECT_EQ(out.find("printStack"), std::string::npos) << where;

        if (rc == 0)
        {
            ++nAccepted;
            EXPECT_TRUE(v.accepted) << "accepted: " << where;
            EXPECT_GT(count(out, "Fluid particles:"), 0) << where;
            EXPECT_TRUE(Foam::isFile(dir/"constant"/"sphMesh"/"fluid"/"positions")) << where;
        }
        else
        {
            ++nError;
            EXPECT_FALSE(v.accepted) << "refused: " << where;
            EXPECT_NE(out.find("sphMeshDict"), std::string::npos) << where;
            if (!v.entry.empty())
            {
                EXPECT_NE(out.find(v.entry), std::string::npos)
                    << "'" << v.entry << "' not named, " << where;
            }
            EXPECT_EQ(out.find("Written"), std::string::npos) << where;
        }
    }
    std::cout << all.size() << " variants: " << nError << " refused, "
        << nAccepted << " accepted" << std::endl;
}


// ************************************************************************* //
