/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The USAW operators in a channel periodic in x (period 1, walls at y = 0
    and 1 joined through the seam, dr = 0.05, Wendland C2, h = 2 dr) on
    the cell-centred lattice: the lattice is invariant under shifts by dr,
    so every operator of a field that depends on y alone is the same in
    every column, next to the seam too - which holds only if the pair
    separations r_ab and the wall separations r_as are minimum images. And
    the renormalised G- of the linear field A = y, periodic in x, is
    exactly (0, 1) everywhere (exactness for linear fields, through the
    seam).

    Tolerance 1e-12: the same sums in another order (round-off of a few
    hundred terms of order 1/h).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "operatorTestTools.H"
#include "wallTestTools.H"
#include "usawOperators.H"

using namespace Foam;
using namespace operatorTest;

namespace
{
    const scalar dr = 0.05;
    const label nx = 20;
    const label ny = 20;
    const scalar tol = 1e-12;

    //- The channel: fluid at cell centres, then the vertex particles
    struct channelCase
    {
        SPH::domain dom;
        autoPtr<SPH::kernel> W;
        SPH::wallMesh walls;
        label nFluid;
        List<vector2D> x;
        scalarList V;
        SPH::neighbourList nbrs;
        autoPtr<SPH::usawWalls> usaw;

        static SPH::wallMesh makePeriodicWalls(const SPH::domain& dom)
        {
            return sphTest::makeWalls
            (
                "lowerWall { type line; points ((0 0) (1 0)); }"
                " upperWall { type line; points ((1 1) (0 1)); }",
                dr, dom
            );
        }

        channelCase()
        :
            dom(vector2D(0, 0), vector2D(1, 1), {true, false}),
            W(SPH::kernel::New(sphTest::dict("kernel wendlandC2;"), dr)),
            walls(makePeriodicWalls(dom)),
            nFluid(nx*ny),
            nbrs(true)
        {
            DynamicList<vector2D> pts;
            for (label j = 0; j < ny; ++j)
            {
                for (label i = 0; i < nx; ++i)
                {
                    pts.append(vector2D((i + 0.5)*dr, (j + 0.5)*dr));
                }
            }
            pts.append(walls.points());
            x = pts;
            V = scalarList(x.size(), dr*dr);
            for (label v = nFluid; v < x.size(); ++v)
            {
                V[v] = 0;
            }

            SPH::cellLinkedList cells(dom, W->support());
            cells.build(x);
            nbrs.build(cells, x, W->support(), true);
            usaw.reset(new SPH::usawWalls(walls, *W, nFluid));
            usaw->update(x);
        }

        //- Expect f(i, j) == f(0, j) in every row
        template<class F>
        void expectSameInEveryColumn(const F& f, const std::string& what) const
        {
            for (label j = 0; j < ny; ++j)
            {
                for (label i = 1; i < nx; ++i)
                {
                    EXPECT_LT(f(j*nx + i, j*nx), tol)
                        << what << ": row " << j << " column " << i;
                }
            }
        }
    };
}


TEST(usawOperatorsPeriodic, renormalisationIsTheSameInEveryColumn)
{
    sphTest::throwOnFatal();
    const channelCase c;
    List<tensor2D> R(c.x.size());
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::renormalisation(K, c.nbrs, *c.usaw, c.V, c.x, 1e-6, R);
    });
    c.expectSameInEveryColumn
    (
        [&](const label a, const label b) { return mag(R[a] - R[b]); },
        "R"
    );
    // Symmetric about the channel's axis, no x-y coupling
    for (label a = 0; a < c.nFluid; ++a)
    {
        EXPECT_LT(mag(R[a].xy()) + mag(R[a].yx()), tol) << a;
    }
}


TEST(usawOperatorsPeriodic, renormalisedGradientOfALinearFieldIsExactThroughTheSeam)
{
    sphTest::throwOnFatal();
    const channelCase c;
    List<tensor2D> R(c.x.size());
    scalarList A(c.x.size());
    forAll(A, a)
    {
        A[a] = 3 - 2*c.x[a].y();
    }
    List<vector2D> G(c.x.size());
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::renormalisation(K, c.nbrs, *c.usaw, c.V, c.x, 1e-6, R);
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, R, A, G);
    });
    for (label a = 0; a < c.nFluid; ++a)
    {
        EXPECT_LT(mag(G[a] - vector2D(0, -2)), tol) << "at " << c.x[a];
    }
}


TEST(usawOperatorsPeriodic, operatorsOfFieldsAlongYAreTheSameInEveryColumn)
{
    sphTest::throwOnFatal();
    const channelCase c;
    scalarList A(c.x.size()), B(c.x.size());
    List<vector2D> u(c.x.size());
    forAll(A, a)
    {
        const scalar y = c.x[a].y();
        A[a] = y*(1 - y);
        B[a] = 1 + y;
        u[a] = vector2D(4*y*(1 - y), 0);
    }
    const scalarList dAdn(c.walls.segments().size(), 1.0);

    scalarList div(c.x.size()), divR(c.x.size()), lap(c.x.size()), lapB(c.x.size());
    List<vector2D> gPlus(c.x.size()), gMinus(c.x.size()), visc(c.x.size()), conc(c.x.size());
    List<tensor2D> gradU(c.x.size());
    SPH::dispatch(*c.W, [&](const auto& K)
    {
        SPH::usaw::divPosition(K, c.nbrs, *c.usaw, c.V, divR);
        SPH::usaw::gradPlus(K, c.nbrs, *c.usaw, c.V, A, gPlus);
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, A, gMinus);
        SPH::usaw::gradMinus(K, c.nbrs, *c.usaw, c.V, u, gradU);
        SPH::usaw::div(K, c.nbrs, *c.usaw, c.V, u, div);
        SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, A, dAdn, lap);
        SPH::usaw::laplacian(K, c.nbrs, *c.usaw, c.V, B, A, dAdn, lapB);
        SPH::usaw::laminarViscous(K, c.nbrs, *c.usaw, c.V, 1e-3, u, dr, visc);
        SPH::usaw::concentrationGradient(K, c.nbrs, *c.usaw, c.V, conc);
    });

    const scalar h = c.W->h();
    auto scalarDiff = [](const scalarList& f)
    {
        return [&f](const label a, const label b) { return mag(f[a] - f[b]); };
    };
    auto vectorDiff = [h](const List<vector2D>& f)
    {
        return [&f, h](const label a, const label b) { return h*mag(f[a] - f[b]); };
    };
    c.expectSameInEveryColumn(scalarDiff(divR), "D{r}");
    c.expectSameInEveryColumn(scalarDiff(div), "D{u}");
    c.expectSameInEveryColumn
    (
        [&](const label a, const label b) { return h*h*mag(lap[a] - lap[b]); }, "L{A}"
    );
    c.expectSameInEveryColumn
    (
        [&](const label a, const label b) { return h*h*mag(lapB[a] - lapB[b]); }, "L{B, A}"
    );
    c.expectSameInEveryColumn(vectorDiff(gPlus), "G+{A}");
    c.expectSameInEveryColumn(vectorDiff(gMinus), "G-{A}");
    c.expectSameInEveryColumn(vectorDiff(visc), "L{mu, u}");
    c.expectSameInEveryColumn(vectorDiff(conc), "G{1}");
    c.expectSameInEveryColumn
    (
        [&](const label a, const label b) { return h*mag(gradU[a] - gradU[b]); }, "G-{u}"
    );

    // Nothing along x: the fields do not vary along the channel
    for (label a = 0; a < c.nFluid; ++a)
    {
        EXPECT_LT(h*mag(gMinus[a].x()), tol) << a;
        EXPECT_LT(h*mag(conc[a].x()), tol) << a;
    }
}


// ************************************************************************* //
