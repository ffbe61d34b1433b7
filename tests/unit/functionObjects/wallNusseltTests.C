/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    wallNusselt (Leroy et al. 2015, eq. (42)) on the channel of USAW walls
    of functionObjectTestTools (D = 1, D/dr = 20, h = 2 dr), pure
    conduction: T = 1 - y, the lower wall at 1, the upper at 0, so Nu = 1
    on both walls with L = D and DeltaT = 1. Measured on the middle
    patches, whose vertices see a whole lattice.

    - On the lattice the renormalised gradient (the default) reads 1 to
      round-off; the paper's gamma form (wallGradient gamma) within the
      lattice's wall quadrature (measured 0.99920).
    - With the particles within 3 dr of the walls moved up to 0.2 dr and
      the first rows 0.02 dr towards their walls (as the shift moves them
      in a heated cavity) the renormalised gradient still reads 1 to
      round-off, and gamma moves away from it (measured 0.979 and 0.990 on
      the lower and upper wall): a bias of the measurement, T being exact.
    - An unknown wallGradient is an error naming the valid ones.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "functionObjectTestTools.H"
#include "Random.H"

using namespace Foam;

namespace
{

//- The channel in pure conduction: T = 1 - y on every particle
struct conductionChannel
:
    public sphTest::usawChannel
{
    explicit conductionChannel(const std::string& name)
    :
        sphTest::usawChannel(name, 20, [](scalar) { return 0.0; }, 0)
    {
        parts->add<scalar>("T", 0, false);
        setT();
    }

    void setT()
    {
        scalarField& T = parts->field<scalar>("T");
        forAll(T, k)
        {
            T[k] = 1 - parts->positions()[k].y();
        }
    }

    //- The fluid particles within 3 dr of a wall moved by up to 0.2 dr,
    //- and the first rows by "towards" to their walls
    void jitterByTheWalls(const scalar towards)
    {
        Random rnd(11);
        vector2DField& x = parts->positions();
        for (label k = 0; k < cloud->nFluid(); ++k)
        {
            const scalar y = x[k].y();
            if (min(y, D - y) < 3.01*dr)
            {
                x[k] += 0.2*dr*vector2D
                (
                    2*rnd.sample01<scalar>() - 1, 2*rnd.sample01<scalar>() - 1
                );
            }
            if (min(y, D - y) < 1.01*dr)
            {
                x[k].y() += (y < 0.5*D ? -towards : towards);
            }
        }
        cloud->updateCells();
        setT();
    }

    //- The patch mean Nu that wallNusselt writes for a patch
    scalar Nu(const word& patch, const word& scheme)
    {
        const word name(patch + scheme);
        autoPtr<functionObject> fo = functionObject::New
        (
            name,
            *runTime,
            sphTest::dict
            (
                "type wallNusselt; patches (" + patch + "); L 1; DeltaT 1;"
                " wallGradient " + scheme + ";"
            )
        );
        fo->execute();
        fo->write();
        const std::vector<std::string> data = sphTest::dataLines
        (
            runTime->globalPath()/"postProcessing"/name/"0"/"wallNusselt.dat"
        );
        if (data.empty()) return NaN;
        // Time patch min max integral average
        IStringStream is(data.back());
        scalar t, lo, hi, integral, average;
        word p;
        is >> t >> p >> lo >> hi >> integral >> average;
        return average;
    }

    static constexpr scalar NaN = std::numeric_limits<scalar>::quiet_NaN();
};

} // End anonymous namespace


TEST(wallNusselt, conductionOnTheLatticeReadsOne)
{
    conductionChannel ch("nusseltLattice");
    for (const word patch : {"lowerMid", "upperMid"})
    {
        EXPECT_NEAR(ch.Nu(patch, "renormalised"), 1, 1e-10) << patch;
        EXPECT_NEAR(ch.Nu(patch, "gamma"), 1, 2e-3) << patch;
    }
}


TEST(wallNusselt, conductionOffTheLatticeReadsOneWhenRenormalised)
{
    conductionChannel ch("nusseltJittered");
    ch.jitterByTheWalls(0.02*ch.dr);
    for (const word patch : {"lowerMid", "upperMid"})
    {
        EXPECT_NEAR(ch.Nu(patch, "renormalised"), 1, 1e-10) << patch;
        EXPECT_GT(mag(ch.Nu(patch, "gamma") - 1), 5e-3) << patch;
    }
}


TEST(wallNusselt, unknownWallGradientNamesTheValidOnes)
{
    sphTest::throwOnFatal();
    conductionChannel ch("nusseltBadEntry");
    try
    {
        ch.Nu("lowerMid", "quadratic");
        FAIL() << "wallGradient quadratic was accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("quadratic"), std::string::npos) << msg;
        EXPECT_NE(msg.find("renormalised"), std::string::npos) << msg;
        EXPECT_NE(msg.find("gamma"), std::string::npos) << msg;
    }
}


// ************************************************************************* //
