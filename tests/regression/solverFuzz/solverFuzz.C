/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Bad inputs for the solvers, generated on the tiny hydrostatic tanks
    (dr = 0.05, a few steps): damaged controlDict, sphSchemes,
    transportProperties, g, 0/U, 0/p and restart fields (NaN, Inf,
    negative, zero, huge, wrong words, missing entries, wrong dimensions,
    truncated files, a type out of range, duplicate ids, a field one value
    short). Each run, under timeout 30 s with the floating-point trap on,
    must end

    - with exit code 1 and a message naming the file or the entry, or
    - with exit code 0 as a documented acceptance (below) whose result is
      that of the undamaged case, to the bit,

    and never with a signal, a timeout or a stack trace.

    Documented acceptances:
    - another deltaT in controlDict with adjustTimeStep yes: the solver's
      time step is taken from the first step;
    - purgeWrite -1: OpenFOAM's Time warns and takes 0;
    - an entry no solver reads (OpenFOAM's dictionaries allow them);
    - endTime equal to the start time: nothing to do (the log says so),
      nothing written.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "solverCase.H"
#include "vector2DIOField.H"
#include "scalarIOField.H"

#include <functional>
#include <limits>

using namespace Foam;
using sphTest::run;

namespace
{
    const scalar NaN = std::numeric_limits<scalar>::quiet_NaN();
    const scalar Inf = std::numeric_limits<scalar>::infinity();

    enum class expect { error, unchanged, nothingToDo };

    struct variant
    {
        std::string solver;     // wcsph | isph
        bool restart;           // damage a restart (the latest time)
        std::string name;
        std::function<void(const fileName& dir, const std::string& time)> damage;
        expect outcome;
        std::vector<std::string> names;   // one of them in the message
    };

    //- A shell edit run in the case folder ($T: the restart time)
    std::function<void(const fileName&, const std::string&)> sh(const std::string& cmd)
    {
        return [cmd](const fileName& dir, const std::string& time)
        {
            std::string out;
            run("cd " + dir + " && T=" + time + " && " + cmd, out);
        };
    }

    std::string set(const std::string& file, const std::string& key, const std::string& value)
    {
        std::string v;
        for (const char c : value) v += (c == '/' ? std::string("\\/") : std::string(1, c));
        return "sed -i 's/^" + key + " .*/" + key + " " + v + ";/' " + file;
    }

    std::string add(const std::string& file, const std::string& text)
    {
        return "echo '" + text + "' >> " + file;
    }

    std::string cut(const std::string& file, int bytes)
    {
        return "head -c " + std::to_string(bytes) + " " + file + " > x && mv x " + file;
    }

    template<class Type>
    std::function<void(const fileName&, const std::string&)> poke
    (
        const word& field, const label i, const Type& value
    )
    {
        return [=](const fileName& dir, const std::string& time)
        {
            sphTest::pokeRestart<Type>(dir, time, field, i, value);
        };
    }

    const std::string cd = "system/controlDict";
    const std::string ss = "system/sphSchemes";
    const std::string tp = "constant/transportProperties";
    const std::string sph = "$T/lagrangian/sph/";

    std::vector<variant> controlDictVariants(const std::string& s)
    {
        const std::vector<std::string> e{"controlDict"};
        auto v = [&](const std::string& n, const std::string& cmd, const std::string& entry)
        {
            return variant{s, false, n, sh(cmd), expect::error, {entry, "system/controlDict"}};
        };
        return
        {
            v("deltaT0Fixed", set(cd, "deltaT", "0") + " && " + set(cd, "adjustTimeStep", "no"), "deltaT"),
            v("deltaT0", set(cd, "deltaT", "0"), "deltaT"),
            v("deltaTNegative", set(cd, "deltaT", "-0.001"), "deltaT"),
            v("deltaTNegativeFixed", set(cd, "deltaT", "-0.001") + " && " + set(cd, "adjustTimeStep", "no"), "deltaT"),
            v("deltaTWord", set(cd, "deltaT", "small"), "deltaT"),
            v("deltaTNaN", set(cd, "deltaT", "#eval{sqrt(-1)}"), "deltaT"),
            v("deltaTTinyFixed", set(cd, "deltaT", "1e-300") + " && " + set(cd, "adjustTimeStep", "no"), "deltaT"),
            v("deltaTHuge", set(cd, "deltaT", "1e300"), "deltaT"),
            v("deltaTMissing", "sed -i '/^deltaT /d' " + cd, "deltaT"),
            v("endTimeNegative", set(cd, "endTime", "-1"), "endTime"),
            v("endTimeNaN", set(cd, "endTime", "#eval{sqrt(-1)}"), "endTime"),
            v("endTimeMissing", "sed -i '/^endTime /d' " + cd, "endTime"),
            v("writeInterval0", set(cd, "writeInterval", "0"), "writeInterval"),
            v("writeIntervalNegative", set(cd, "writeInterval", "-1"), "writeInterval"),
            v("writeInterval0TimeStep", set(cd, "writeInterval", "0") + " && " + set(cd, "writeControl", "timeStep"), "writeInterval"),
            v("writeIntervalFractionTimeStep", set(cd, "writeInterval", "2.5") + " && " + set(cd, "writeControl", "timeStep"), "writeInterval"),
            v("writeControlUnknown", set(cd, "writeControl", "sometimes"), "writeControl"),
            v("maxCo0", set(cd, "maxCo", "0"), "maxCo"),
            v("maxCoNegative", set(cd, "maxCo", "-0.2"), "maxCo"),
            v("maxCoHuge", set(cd, "maxCo", "1e300"), "maxCo"),
            v("maxCoWord", set(cd, "maxCo", "fast"), "maxCo"),
            v("maxDeltaT0", add(cd, "maxDeltaT 0;"), "maxDeltaT"),
            v("maxDeltaTNegative", add(cd, "maxDeltaT -1;"), "maxDeltaT"),
            v("adjustTimeStepWord", set(cd, "adjustTimeStep", "maybe"), "adjustTimeStep"),
            v("logInterval0", add(cd, "logInterval 0;"), "logInterval"),
            v("stopAtUnknown", set(cd, "stopAt", "whenever"), "stopAt"),
            v("startTimeAfterEnd", set(cd, "startTime", "5"), "endTime"),
            v("truncated", cut(cd, 700), "controlDict"),
        };
    }

    std::vector<variant> wcsphSchemeVariants()
    {
        auto v = [](const std::string& n, const std::string& cmd, const std::string& entry)
        {
            return variant{"wcsph", false, n, sh(cmd), expect::error, {entry}};
        };
        return
        {
            v("c00", set(ss, "c0", "0"), "c0"),
            v("c0Negative", set(ss, "c0", "-31"), "c0"),
            v("c0Word", set(ss, "c0", "fast"), "c0"),
            v("c0Inf", set(ss, "c0", "#eval{1/0}"), "c0"),
            v("c0Huge", set(ss, "c0", "1e300"), "c0"),
            v("c0Missing", "sed -i '/^c0 /d' " + ss, "c0"),
            v("gamma0", set(ss, "gamma", "0"), "gamma"),
            v("gammaWord", set(ss, "gamma", "seven"), "gamma"),
            v("hByDrSmall", set(ss, "hByDr", "0.5"), "hByDr"),
            v("hByDrHuge", set(ss, "hByDr", "1e300"), "hByDr"),
            v("kernelUnknown", set(ss, "kernel", "gaussian"), "gaussian"),
            v("boundaryMethodUnknown", set(ss, "boundaryMethod", "ghosts"), "ghosts"),
            v("ksNegative", "sed -i 's/^ks .*/ks -1;/' " + ss, "ks"),
            v("artificialViscosityNegative", set(ss, "artificialViscosity", "-0.01"), "artificialViscosity"),
            v("artificialViscosityInf", set(ss, "artificialViscosity", "#eval{1/0}"), "artificialViscosity"),
            v("neighbourSkinNegative", add(ss, "neighbourSkin -1;"), "neighbourSkin"),
            v("minDeltaTFractionNegative", add(ss, "minDeltaTFraction -1;"), "minDeltaTFraction"),
            v("minDeltaTFractionOne", add(ss, "minDeltaTFraction 1;"), "minDeltaTFraction"),
            v("densityDiffusionWord", set(ss, "densityDiffusion", "perhaps"), "densityDiffusion"),
            v("truncated", cut(ss, 900), "sphSchemes"),
        };
    }

    std::vector<variant> physicsVariants(const std::string& s)
    {
        auto v = [&](const std::string& n, const std::string& cmd, const std::string& entry, const std::string& file)
        {
            return variant{s, false, n, sh(cmd), expect::error, {entry, file}};
        };
        const std::string rho = "sed -i 's/^rho .*/rho ";
        return
        {
            v("rhoDimensions", rho + "[0 1 0 0 0 0 0] 1000;/' " + tp, "dimensions", "transportProperties"),
            v("rhoNegative", rho + "[1 -3 0 0 0 0 0] -1000;/' " + tp, "rho", "transportProperties"),
            v("rho0", rho + "[1 -3 0 0 0 0 0] 0;/' " + tp, "rho", "transportProperties"),
            v("rhoWord", rho + "[1 -3 0 0 0 0 0] water;/' " + tp, "rho", "transportProperties"),
            v("rhoInf", rho + "[1 -3 0 0 0 0 0] #eval{1\\/0};/' " + tp, "rho", "transportProperties"),
            v("rhoMissing", "sed -i '/^rho /d' " + tp, "rho", "transportProperties"),
            v("nuNegative", "sed -i 's/^nu .*/nu [0 2 -1 0 0 0 0] -1;/' " + tp, "nu", "transportProperties"),
            v("transportTruncated", cut(tp, 700), "transportProperties", "transportProperties"),
            v("gDimensions", "sed -i 's/^dimensions .*/dimensions [0 1 0 0 0 0 0];/' constant/g", "g", "g"),
            v("gNaN", "sed -i 's/^value .*/value #eval{sqrt(-1)*vector(0,1,0)};/' constant/g", "g", "g"),
            v("UNoInternalField", "sed -i '/^internalField/d' 0/U", "internalField", "0/U"),
            v("UNaN", "sed -i 's/^internalField .*/internalField uniform (nan 0 0);/' 0/U", "internalField", "0/U"),
            v("UHuge", "sed -i 's/^internalField .*/internalField uniform (1e300 0 0);/' 0/U", "time step", "0/U"),
            v("UInf", "sed -i 's/^internalField .*/internalField uniform #eval{vector(1,0,0)\\/0};/' 0/U", "internalField", "0/U"),
            v("UWord", "sed -i 's/^internalField .*/internalField uniform still;/' 0/U", "internalField", "0/U"),
            v("UScalar", "sed -i 's/^internalField .*/internalField uniform 0;/' 0/U", "internalField", "0/U"),
            v("UListTooShort", "sed -i 's/^internalField .*/internalField nonuniform List<vector> 2((0 0 0) (0 0 0));/' 0/U", "internalField", "0/U"),
            v("UTruncated", cut("0/U", 800), "U", "0/U"),
            v("pNoInternalField", "sed -i '/^internalField/d' 0/p", "internalField", "0/p"),
            v("pHuge", "sed -i 's/^internalField .*/internalField uniform 1e300;/' 0/p", "time step", "0/p"),
            v("pHugeNegative", "sed -i 's/^internalField .*/internalField uniform -1e300;/' 0/p", "time step", "0/p"),
            v("pInf", "sed -i 's/^internalField .*/internalField uniform #eval{1\\/0};/' 0/p", "internalField", "0/p"),
            v("movingWalls", "echo 'walls { tank { velocity (1 0); } }' > constant/movingWalls", "movingWalls", "movingWalls"),
            v("turbulence", "printf 'FoamFile { version 2.0; format ascii; class dictionary; object turbulenceProperties; }\\nsimulationType RAS;\\n' > constant/turbulenceProperties", "simulationType", "turbulenceProperties"),
        };
    }

    std::vector<variant> restartVariants(const std::string& s)
    {
        auto v = [&](const std::string& n, const std::function<void(const fileName&, const std::string&)>& f, const std::string& file)
        {
            return variant{s, true, n, f, expect::error, {"lagrangian/sph" + (file.empty() ? "" : "/" + file)}};
        };
        return
        {
            v("UNaN", poke<vector2D>("U", 3, vector2D(NaN, 0)), "U"),
            v("UInf", poke<vector2D>("U", 3, vector2D(0, -Inf)), "U"),
            v("pNaN", poke<scalar>("p", 5, NaN), "p"),
            v("positionsNaN", poke<vector2D>("positions", 7, vector2D(NaN, NaN)), "positions"),
            v("positionsFar", poke<vector2D>("positions", 7, vector2D(1e300, 0.2)), "positions"),
            v("typeAll7", sh("sed -i 's/^0$/7/' " + sph + "type"), "type"),
            v("typeOne7", poke<label>("type", 2, 7), "type"),
            v("typeNegative", poke<label>("type", 0, -1), "type"),
            v("typeWord", sh("sed -i '0,/^0$/s//fluid/' " + sph + "type"), "type"),
            v("idDuplicate", poke<label>("id", 4, 0), "id"),
            v("patchOutOfRange", poke<label>("patch", 1, 99), "patch"),
            v("pOneShort", sh("n=$(sed -n 19p " + sph + "p) && sed -i \"19s/.*/$((n - 1))/; 21d\" " + sph + "p"), "p"),
            v("positionsTruncated", sh(cut(sph + "positions", 1500)), "positions"),
            v("UTruncated", sh(cut(sph + "U", 1500)), "U"),
            v("UMissing", sh("rm " + sph + "U"), "U"),
            v("UHuge", poke<vector2D>("U", 3, vector2D(1e300, 0)), ""),
        };
    }

    std::vector<variant> variants()
    {
        std::vector<variant> all;
        auto append = [&all](const std::vector<variant>& v)
        {
            all.insert(all.end(), v.begin(), v.end());
        };
        append(controlDictVariants("wcsph"));
        append(wcsphSchemeVariants());
        append(physicsVariants("wcsph"));
        append(restartVariants("wcsph"));
        for (const std::string s : {"wcsph", "isph"})
        {
            // No 0/U: its boundaryField gives the walls' conditions
            all.push_back({s, false, "noU", sh("rm 0/U"), expect::error, {"0/U"}});
        }

        // isphFoam: what it reads of its own, and a sample of the shared
        append
        ({
            {"isph", false, "deltaT0Fixed", sh(set(cd, "deltaT", "0") + " && " + set(cd, "adjustTimeStep", "no")), expect::error, {"deltaT"}},
            {"isph", false, "maxCo0", sh(set(cd, "maxCo", "0")), expect::error, {"maxCo"}},
            {"isph", false, "endTimeNegative", sh(set(cd, "endTime", "-1")), expect::error, {"endTime"}},
            {"isph", false, "writeInterval0", sh(set(cd, "writeInterval", "0")), expect::error, {"writeInterval"}},
            {"isph", false, "shiftCoeffNegative", sh(set(ss, "shiftCoeff", "-1")), expect::error, {"shiftCoeff"}},
            {"isph", false, "shiftCoeffInf", sh(add(ss, "shiftCoeff #eval{1/0};")), expect::error, {"shiftCoeff"}},
            {"isph", false, "freeSurfaceDivR3", sh(add(ss, "freeSurfaceDivR 3;")), expect::error, {"freeSurfaceDivR"}},
            {"isph", false, "hByDrHuge", sh(set(ss, "hByDr", "1e300")), expect::error, {"hByDr"}},
            {"isph", false, "rhoDimensions", sh("sed -i 's/^rho .*/rho [0 1 0 0 0 0 0] 1000;/' " + tp), expect::error, {"transportProperties"}},
            {"isph", false, "UNoInternalField", sh("sed -i '/^internalField/d' 0/U"), expect::error, {"0/U"}},
            {"isph", false, "movingWalls", sh("echo 'lid { velocity (1 0); }' > constant/movingWalls"), expect::error, {"movingWalls"}},
            {"isph", false, "sphSolutionTruncated", sh(cut("system/sphSolution", 700)), expect::error, {"sphSolution"}},
        });
        const std::vector<variant> isphRestart = restartVariants("isph");
        for (const std::string n : {"UNaN", "typeAll7", "idDuplicate", "pOneShort", "positionsFar"})
        {
            for (const variant& r : isphRestart)
            {
                if (r.name == n) all.push_back(r);
            }
        }

        // Documented acceptances: exit 0, the result of the undamaged case
        for (const std::string s : {"wcsph", "isph"})
        {
            append
            ({
                {s, false, "deltaTOtherAdjustable", sh(set(cd, "deltaT", "0.0005")), expect::unchanged, {}},
                {s, false, "purgeWriteNegative", sh(set(cd, "purgeWrite", "-1")), expect::unchanged, {}},
                {s, false, "unreadEntry", sh(add(ss, "notAnEntry 1e300;")), expect::unchanged, {}},
                {s, false, "endTimeIsStart", sh(set(cd, "endTime", "0")), expect::nothingToDo, {}},
            });
        }
        return all;
    }

    //- The fields of a case's latest time, for "the result is unchanged"
    std::string latestFields(const fileName& dir)
    {
        return run
        (
            "cd " + dir + " && t=$(ls -d [0-9]* | sort -g | tail -1) && echo $t"
            " && cat $t/lagrangian/sph/positions $t/lagrangian/sph/U"
            " $t/lagrangian/sph/p | md5sum"
        );
    }
}


TEST(solverFuzz, badInputsAreErrorsNamingTheFileOrEntryNeverCrashes)
{
    const std::vector<variant> all = variants();
    ASSERT_GE(all.size(), 60u);

    std::map<std::string, std::string> baseline;
    for (const std::string s : {"wcsph", "isph"})
    {
        const fileName dir = sphTest::tankCase(s, "fuzzBaseline." + s);
        const sphTest::solverRun r = sphTest::runSolver(s + "Foam", dir);
        ASSERT_EQ(r.status, 0) << r.tail();
        baseline[s] = latestFields(dir);
    }

    label nError = 0, nAccepted = 0;
    for (const variant& v : all)
    {
        const std::string what = v.solver + (v.restart ? " restart " : " ") + v.name;
        std::string time;
        const fileName dir =
            v.restart
          ? sphTest::restartCase(v.solver, "fuzz." + v.solver + "Restart." + v.name, time)
          : sphTest::tankCase(v.solver, "fuzz." + v.solver + "." + v.name);
        v.damage(dir, time);
        const sphTest::solverRun r = sphTest::runSolver(v.solver + "Foam", dir);

        EXPECT_NE(r.status, 124) << what << ": timeout";
        EXPECT_LT(r.status, 124) << what << ": a signal: " << r.tail();
        EXPECT_FALSE(r.stackTrace()) << what << ": " << r.tail();
        if (v.outcome == expect::error)
        {
            ++nError;
            EXPECT_EQ(r.status, 1) << what << ": " << r.tail();
            bool named = false;
            for (const std::string& n : v.names) named = named || r.has(n);
            EXPECT_TRUE(named) << what << ": names none of the expected: " << r.tail();
        }
        else
        {
            ++nAccepted;
            EXPECT_EQ(r.status, 0) << what << ": " << r.tail();
            if (v.outcome == expect::unchanged)
            {
                EXPECT_EQ(latestFields(dir), baseline[v.solver]) << what;
            }
            else
            {
                EXPECT_TRUE(r.has("nothing to do")) << what << ": " << r.tail();
                EXPECT_EQ(run("ls -d " + dir + "/[1-9]* " + dir + "/0.* 2>/dev/null | cat"), "") << what;
            }
        }
    }
    std::cout << all.size() << " variants: " << nError << " errors, "
              << nAccepted << " documented acceptances" << std::endl;
}


// ************************************************************************* //
