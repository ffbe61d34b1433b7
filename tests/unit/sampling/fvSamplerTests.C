/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The FV side of sphCompare: OpenFOAM's cellPoint interpolation through
    fvSampler on a small uniform blockMesh reproduces a linear field (given
    at the cell centres and boundary faces) exactly away from the corners,
    finds a cell for points on the boundary, gives no value outside, and
    the cell centres and volumes are the mesh's.

    On a uniform mesh volPointInterpolation's inverse-distance average of
    the cells (or boundary faces) around a mesh point is symmetric, hence
    exact for a linear field, except at the four corners where the two
    boundary faces meeting there are not symmetric about it; cellPoint is
    then linear in each tetrahedron. So: round-off (1e-12 on values of
    O(10)) in every cell that has no corner point.

\*---------------------------------------------------------------------------*/

#include "samplingTestTools.H"
#include "fvSampler.H"
#include "calculatedFvPatchFields.H"

using namespace Foam;
using namespace Foam::SPH;
using samplingTest::str;

namespace
{
    const scalar roundOff = 1e-12;

    //- A uniform 8 x 8 mesh of [0, 1]^2 with its Time
    struct smallMesh
    {
        std::unique_ptr<Time> runTime;
        std::unique_ptr<fvMesh> mesh;

        explicit smallMesh(const std::string& name)
        {
            const fileName dir = samplingTest::blockMeshCase(name, 8, 1);
            runTime = sphTest::makeTime(dir);
            mesh.reset
            (
                new fvMesh
                (
                    IOobject
                    (
                        fvMesh::defaultRegion,
                        runTime->timeName(),
                        *runTime,
                        IOobject::MUST_READ
                    )
                )
            );
        }
    };

    vector linearVector(const point& p)
    {
        return vector(samplingTest::linear(vector2D(p.x(), p.y())), 1 - 2*p.x() + 4*p.y(), 0);
    }

    //- Points in cells without a mesh corner, some on the walls
    List<vector2D> probePoints()
    {
        return List<vector2D>
        ({
            vector2D(0.5, 0.5), vector2D(0.3127, 0.4419), vector2D(0.61, 0.77),
            vector2D(0.2, 0.2), vector2D(0.5, 0.0), vector2D(0.0, 0.43),
            vector2D(1.0, 0.55), vector2D(0.71, 1.0), vector2D(0.13, 0.87)
        });
    }
}


TEST(samplingFvSampler, cellPointReproducesALinearFieldAwayFromTheCorners)
{
    smallMesh m("fvSamplerLinear");
    sphTest::throwOnFatal();
    const fvMesh& mesh = *m.mesh;

    volScalarField f
    (
        IOobject("f", m.runTime->timeName(), mesh),
        mesh,
        dimensionedScalar(dimless, Zero),
        calculatedFvPatchScalarField::typeName
    );
    volVectorField U
    (
        IOobject("U", m.runTime->timeName(), mesh),
        mesh,
        dimensionedVector(dimless, Zero),
        calculatedFvPatchVectorField::typeName
    );
    forAll(f, celli)
    {
        const point& c = mesh.C()[celli];
        f[celli] = samplingTest::linear(vector2D(c.x(), c.y()));
        U[celli] = linearVector(c);
    }
    forAll(mesh.boundary(), patchi)
    {
        const vectorField& Cf = mesh.boundary()[patchi].Cf();
        forAll(Cf, facei)
        {
            f.boundaryFieldRef()[patchi][facei] =
                samplingTest::linear(vector2D(Cf[facei].x(), Cf[facei].y()));
            U.boundaryFieldRef()[patchi][facei] = linearVector(Cf[facei]);
        }
    }

    fvSampler sampler(mesh, "cellPoint");
    const List<vector2D> pts(probePoints());
    const labelList cells(sampler.findCells(pts));
    const scalarField fi(sampler.sample(f, pts, cells));
    const vectorField Ui(sampler.sample(U, pts, cells));

    forAll(pts, i)
    {
        ASSERT_GE(cells[i], 0) << str(pts[i]);
        EXPECT_NEAR(fi[i], samplingTest::linear(pts[i]), roundOff) << str(pts[i]);
        const vector exact(linearVector(point(pts[i].x(), pts[i].y(), 0)));
        EXPECT_NEAR(Ui[i].x(), exact.x(), roundOff) << str(pts[i]);
        EXPECT_NEAR(Ui[i].y(), exact.y(), roundOff) << str(pts[i]);
    }

    // The cell scheme is the cell value: exact only at the cell centres
    fvSampler cellSampler(mesh, "cell");
    const List<vector2D> centre({vector2D(0.5625, 0.3125)});
    const scalarField fc(cellSampler.sample(f, centre, cellSampler.findCells(centre)));
    EXPECT_NEAR(fc[0], samplingTest::linear(centre[0]), roundOff);
}


TEST(samplingFvSampler, boundaryPointsFindACellAndOutsidePointsHaveNoValue)
{
    smallMesh m("fvSamplerBoundary");
    sphTest::throwOnFatal();
    fvSampler sampler(*m.mesh);

    const List<vector2D> onBoundary
    ({
        vector2D(0.5, 0), vector2D(0, 0.5), vector2D(1, 1), vector2D(0, 0),
        vector2D(1, 0.25)
    });
    for (const label c : sampler.findCells(onBoundary))
    {
        EXPECT_GE(c, 0);
    }

    volScalarField f
    (
        IOobject("f", m.runTime->timeName(), *m.mesh),
        *m.mesh,
        dimensionedScalar("one", dimless, 1.0)
    );
    const List<vector2D> outside({vector2D(1.2, 0.5), vector2D(0.5, -0.01)});
    const labelList cells(sampler.findCells(outside));
    EXPECT_EQ(cells, labelList({-1, -1}));
    const scalarField values(sampler.sample(f, outside, cells));
    for (const scalar v : values)
    {
        EXPECT_TRUE(std::isnan(v));
    }
}


TEST(samplingFvSampler, cellCentresAndVolumesAreTheMeshs)
{
    smallMesh m("fvSamplerCells");
    sphTest::throwOnFatal();
    fvSampler sampler(*m.mesh);

    const List<vector2D> C(sampler.cellCentres());
    ASSERT_EQ(C.size(), 64);
    EXPECT_NEAR(C[0].x(), 1.0/16, roundOff);
    EXPECT_NEAR(C[0].y(), 1.0/16, roundOff);
    // [0, 1]^2 x 0.1 thick
    EXPECT_NEAR(sum(sampler.cellVolumes()), 0.1, roundOff);
}


// ************************************************************************* //
