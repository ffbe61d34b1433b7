/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The smaller pieces of sphCompare: the norms of 000_8c7cd3aabddcf18a.txt
    eq. (66) (hand-computed values, missing points left out), the points
    and weights of line and point sets, CSV tables, and analytic
    expressions of x and y. Bad input is a fatal error naming the entry.

\*---------------------------------------------------------------------------*/

#include "samplingTestTools.H"
#include "errorNorms.H"
#include "samplePoints.H"
#include "csvTable.H"
#include "expressionSource.H"
#include "mathematicalConstants.H"

using namespace Foam;
using namespace Foam::SPH;

namespace
{
    const scalar roundOff = 1e-14;
    const scalar none = errorNorms::missing();

    scalarField field(std::initializer_list<scalar> values)
    {
        return scalarField(List<scalar>(values));
    }

    //- The message of the fatal error f throws
    template<class F>
    std::string fatalMessage(F&& f)
    {
        try
        {
            f();
        }
        catch (const Foam::error& err)
        {
            return std::string(err.message()) + " | " + std::string(err.what());
        }
        return "no error";
    }
}


TEST(samplingErrorNorms, l2OfEq66IsTheWeightedRmsOverTheScale)
{
    // Differences 0, 1, 2 with weights 1, 1, 2; the NaN point is left out:
    // L2 = sqrt((0 + 1 + 8)/4)/2 = 0.75, maxAbs = 2/2
    const scalarField f({1, 2, 3, none});
    const scalarField ref({1, 1, 1, 5});
    const scalarField w({1, 1, 2, 1});

    const errorNorms::result r = errorNorms::compare(f, ref, w, 2);
    EXPECT_EQ(r.nPoints, 3);
    EXPECT_NEAR(r.L2, 0.75, roundOff);
    EXPECT_NEAR(r.maxAbs, 1.0, roundOff);

    const errorNorms::result empty =
        errorNorms::compare(scalarField(2, none), scalarField(2, 1.0), scalarField(2, 1.0));
    EXPECT_EQ(empty.nPoints, 0);
    EXPECT_TRUE(std::isnan(empty.L2));
}


TEST(samplingErrorNorms, meanLeavesMissingPointsOut)
{
    EXPECT_NEAR
    (
        errorNorms::mean(field({1, 3, none}), field({1, 3, 1})),
        2.5,
        roundOff
    );
}


TEST(samplingSamplePoints, lineIsEvenlySpacedWithTrapezoidalWeights)
{
    sphTest::throwOnFatal();
    const samplePoints set
    (
        sphTest::dict("type line; start (0 0); end (1 0); nPoints 5;")
    );
    ASSERT_EQ(set.size(), 5);
    EXPECT_NEAR(set.points()[1].x(), 0.25, roundOff);
    EXPECT_NEAR(set.distance()[4], 1.0, roundOff);
    const scalarField expected({0.125, 0.25, 0.25, 0.25, 0.125});
    forAll(expected, i)
    {
        EXPECT_NEAR(set.weights()[i], expected[i], roundOff);
    }
    // The weights integrate: their sum is the length
    EXPECT_NEAR(sum(set.weights()), 1.0, roundOff);
}


TEST(samplingSamplePoints, pointListHasEqualWeightsAndPolylineDistance)
{
    sphTest::throwOnFatal();
    const samplePoints set
    (
        sphTest::dict("type points; points ((0 0) (3 4) (3 5));")
    );
    EXPECT_EQ(set.weights(), scalarField(3, 1.0));
    EXPECT_NEAR(set.distance()[2], 6.0, roundOff);
}


TEST(samplingSamplePoints, badEntriesAreFatalIOErrorsNamingThem)
{
    sphTest::throwOnFatal();
    EXPECT_NE
    (
        fatalMessage([]{ samplePoints(sphTest::dict("type line; start (0 0); end (1 0); nPoints 1;")); })
            .find("nPoints"),
        std::string::npos
    );
    const std::string unknown = fatalMessage
    (
        []{ samplePoints(sphTest::dict("type circle;")); }
    );
    EXPECT_NE(unknown.find("circle"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("line"), std::string::npos) << unknown;
}


TEST(samplingCsvTable, readsCommentedCommaAndSpaceSeparatedTables)
{
    sphTest::throwOnFatal();
    const fileName dir = fileName(SPHFOAM_BINARY_DIR)/"tests"/"cases"/"csvTable";
    mkDir(dir);
    sphTest::writeFile(dir/"comma.csv", "# source: a test\ny,Re100\n0,0\n0.5,-0.2\n1.0,1\n");
    sphTest::writeFile(dir/"space.dat", "# x  p\nx p\n0.1 2e-3\n  0.2   -4\n");

    const csvTable comma(dir/"comma.csv");
    EXPECT_EQ(comma.nRows(), 3);
    EXPECT_EQ(comma.column("Re100"), field({0, -0.2, 1}));

    const csvTable space(dir/"space.dat");
    EXPECT_EQ(space.column("p"), field({2e-3, -4}));

    // A missing column names the file and lists the columns
    const std::string missing = fatalMessage([&]{ comma.column("Re400"); });
    EXPECT_NE(missing.find("Re400"), std::string::npos) << missing;
    EXPECT_NE(missing.find("comma.csv"), std::string::npos) << missing;
    EXPECT_NE(missing.find("Re100"), std::string::npos) << missing;

    // A value that is not a number names the line
    sphTest::writeFile(dir/"bad.csv", "a,b\n1,2\n3,x\n");
    const std::string bad = fatalMessage([&]{ csvTable t(dir/"bad.csv"); });
    EXPECT_NE(bad.find("Line 3"), std::string::npos) << bad;

    const std::string absent = fatalMessage([&]{ csvTable t(dir/"none.csv"); });
    EXPECT_NE(absent.find("none.csv"), std::string::npos) << absent;
}


TEST(samplingExpressionSource, evaluatesOpenFoamExpressionsOfXAndY)
{
    sphTest::throwOnFatal();
    const List<vector2D> pts({vector2D(0, 1), vector2D(0.5, 0.25), vector2D(2, -1)});
    const scalarField v
    (
        expressionSource::evaluate("x*x + sin(pi()*y) + 3", pts)
    );
    forAll(pts, i)
    {
        EXPECT_NEAR
        (
            v[i],
            sqr(pts[i].x()) + std::sin(constant::mathematical::pi*pts[i].y()) + 3,
            1e-12
        );
    }
    // A constant is spread over the points
    const scalarField two(expressionSource::evaluate("2", pts));
    EXPECT_EQ(two, scalarField(3, 2.0));
}


// ************************************************************************* //
