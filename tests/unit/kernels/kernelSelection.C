/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    Run-time selection of the kernels: names, defaults, entries read and the
    errors for bad input.

\*---------------------------------------------------------------------------*/

#include "kernelTestTools.H"
#include "kernelDispatch.H"
#include "wordList.H"

#include <gtest/gtest.h>

using namespace Foam;
using kernelTest::makeKernel;

namespace
{
    // h = hByDr*dr is one multiplication: it must equal the product exactly
    const scalar dr = 0.01;

    class kernelSelection : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            kernelTest::throwFatalErrors();
        }
    };
}


TEST_F(kernelSelection, tableHoldsTheThreeKernels)
{
    const wordList names(SPH::kernel::dictionaryConstructorTablePtr_->sortedToc());
    EXPECT_EQ(names, wordList({"cubicSpline", "modifiedGaussian", "wendlandC2"}));
}


TEST_F(kernelSelection, selectsEachKernelByName)
{
    for (const word name : {"wendlandC2", "cubicSpline", "modifiedGaussian"})
    {
        const auto W = makeKernel("kernel " + name + ";", dr);
        EXPECT_EQ(W->type(), name);
    }
}


TEST_F(kernelSelection, unknownNameIsFatalIOErrorListingValidNames)
{
    EXPECT_THROW(makeKernel("kernel quinticSpline;", dr), Foam::error);
    try
    {
        makeKernel("kernel quinticSpline;", dr);
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("quinticSpline"), std::string::npos) << msg;
        for (const char* valid : {"wendlandC2", "cubicSpline", "modifiedGaussian"})
        {
            EXPECT_NE(msg.find(valid), std::string::npos) << msg;
        }
    }
}


TEST_F(kernelSelection, missingKernelEntryIsFatalIOError)
{
    EXPECT_THROW(makeKernel("hByDr 2;", dr), Foam::error);
}


TEST_F(kernelSelection, defaultHByDrIsPerKernel)
{
    // wendlandC2: h = 2 dr (000_8c7c... after eq. (1)); cubicSpline: our
    // documented 1.3; modifiedGaussian: h = dr (004_f29... after eq. (5))
    EXPECT_EQ(makeKernel("kernel wendlandC2;", dr)->hByDr(), 2);
    EXPECT_EQ(makeKernel("kernel cubicSpline;", dr)->hByDr(), 1.3);
    EXPECT_EQ(makeKernel("kernel modifiedGaussian;", dr)->hByDr(), 1);

    const auto W = makeKernel("kernel wendlandC2;", dr);
    EXPECT_EQ(W->h(), 2*dr);
    EXPECT_EQ(W->dr(), dr);
}


TEST_F(kernelSelection, hByDrEntryOverridesDefault)
{
    const auto W = makeKernel("kernel cubicSpline; hByDr 1.5;", dr);
    EXPECT_EQ(W->hByDr(), 1.5);
    EXPECT_EQ(W->h(), 1.5*dr);
}


TEST_F(kernelSelection, supportIsQMaxTimesH)
{
    const auto wendland = makeKernel("kernel wendlandC2;", dr);
    EXPECT_EQ(wendland->qMax(), 2);
    EXPECT_EQ(wendland->support(), 2*wendland->h());

    EXPECT_EQ(makeKernel("kernel cubicSpline;", dr)->qMax(), 2);
    EXPECT_EQ(makeKernel("kernel modifiedGaussian;", dr)->qMax(), 3);
}


TEST_F(kernelSelection, modifiedGaussianReadsKFromCoeffs)
{
    const auto W = makeKernel
    (
        "kernel modifiedGaussian; modifiedGaussianCoeffs { k 2.5; }",
        dr
    );
    EXPECT_EQ(W->qMax(), 2.5);
    EXPECT_EQ(W->support(), 2.5*dr);
}


TEST_F(kernelSelection, hByDrBelowOneIsFatalIOError)
{
    for (const word name : {"wendlandC2", "cubicSpline", "modifiedGaussian"})
    {
        EXPECT_THROW(makeKernel("kernel " + name + "; hByDr 0.5;", dr), Foam::error)
            << name;
    }
}


TEST_F(kernelSelection, nonPositiveDrIsFatalIOError)
{
    EXPECT_THROW(makeKernel("kernel wendlandC2;", 0), Foam::error);
    EXPECT_THROW(makeKernel("kernel wendlandC2;", -dr), Foam::error);
}


TEST_F(kernelSelection, modifiedGaussianKBelowOneIsFatalIOError)
{
    EXPECT_THROW
    (
        makeKernel("kernel modifiedGaussian; modifiedGaussianCoeffs { k 0.5; }", dr),
        Foam::error
    );
}


TEST_F(kernelSelection, dispatchVisitsTheConcreteType)
{
    for (const word name : {"wendlandC2", "cubicSpline", "modifiedGaussian"})
    {
        const auto W = makeKernel("kernel " + name + ";", dr);
        word visited;
        SPH::dispatch(*W, [&](const auto& concrete)
        {
            visited = std::decay_t<decltype(concrete)>::typeName;
        });
        EXPECT_EQ(visited, name);
    }
}


// ************************************************************************* //
