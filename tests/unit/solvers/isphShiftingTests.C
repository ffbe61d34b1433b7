/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    isphFoam's shifting stage (SPH::shifting, Leroy et al. 2014, eqs.
    (35)-(38)) on the cell-centred lattice of a box periodic in x and y
    (20 x 20, dr = 0.05, Wendland C2, h = 2 dr), no walls:
    - on a jittered lattice in a smooth velocity field the correction (38)
      carries each particle's velocity to its new position: the velocity
      after the shift is nearer the field there than the velocity before
      it;
    - the correction is bounded by the range of the particle's own and
      its neighbours' velocities, component by component: a particle that
      is the fastest of its neighbourhood is not made faster. Unbounded,
      the Taylor step adds to the peak every step (the obstacle dam-break
      at dr = 2 mm, 0.52 s: a particle pinned 0.42 dr off a wall, driven
      into it at 13 m/s and shifted back out by 0.35-0.45 dr a step,
      gained 0.1-0.3 m/s a step, to 26 m/s).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "../functionObjects/functionObjectTestTools.H"
#include "shifting.H"
#include "usawNeighbours.H"
#include "wallBoundaries.H"
#include "Random.H"

#include <cmath>

using namespace Foam;

namespace
{
    const scalar dr = 0.05;
    const label n = 20;
    const scalar L = n*dr;

    //- A periodic lattice with the isph work the stages share
    struct latticeCase
    {
        std::unique_ptr<Time> runTime;
        SPH::domain dom;
        autoPtr<SPH::kernel> W;
        SPH::wallMesh walls;
        std::unique_ptr<SPH::particles> parts;
        std::unique_ptr<SPH::sphCloud> cloud;
        SPH::neighbourList nbrs;
        SPH::verletList verlet;
        SPH::usawWalls usaw;
        SPH::wallBoundaries motion;
        SPH::isphWork work;
        SPH::usawNeighbours neighbours;
        SPH::shifting shift;

        latticeCase()
        :
            runTime(sphTest::makeTime(sphTest::makeCase("isphShifting"))),
            dom(vector2D(0, 0), vector2D(L, L), {true, true}),
            W(SPH::kernel::New(sphTest::dict("kernel wendlandC2; hByDr 2;"), dr)),
            walls(dom),
            parts(sphTest::newParticles(*runTime, 1000, n*n)),
            cloud
            (
                new SPH::sphCloud
                (
                    *runTime, *parts, *W, walls, n*n, dr, 1000,
                    vector2D::zero, dom
                )
            ),
            nbrs(true),
            verlet(0),
            usaw(walls, *W, n*n, dom),
            motion(dictionary(), dictionary(), *runTime, walls),
            work(1000, 1e-6, vector2D::zero, *cloud, nbrs, verlet, usaw, motion),
            neighbours(work, ""),
            // Leroy et al. 2014's C = 0.7 (eq. (36))
            shift(work, 0.7, false)
        {
            work.V = dr*dr;
            vector2DField& x = parts->positions();
            for (label j = 0; j < n; ++j)
            {
                for (label i = 0; i < n; ++i)
                {
                    x[j*n + i] = vector2D((i + 0.5)*dr, (j + 0.5)*dr);
                }
            }
        }

        vector2DField& x() { return parts->positions(); }
        vector2DField& U() { return parts->field<vector2D>("U"); }

        //- Neighbours at the current positions, then one shift
        void apply()
        {
            cloud->updateCells();
            neighbours.execute(0);
            shift.execute(0);
        }
    };

    //- A smooth periodic field of amplitude 1
    vector2D smoothU(const vector2D& x)
    {
        return vector2D
        (
            std::sin(constant::mathematical::twoPi*x.y()/L),
            std::cos(constant::mathematical::twoPi*x.x()/L)
        );
    }
}


TEST(isphShifting, carriesASmoothVelocityToTheShiftedPosition)
{
    latticeCase c;
    Random rnd(7);
    for (vector2D& xi : c.x())
    {
        xi = c.dom.wrap
        (
            xi + 0.2*dr*vector2D(2*rnd.sample01<scalar>() - 1, 2*rnd.sample01<scalar>() - 1)
        );
    }
    forAll(c.U(), i)
    {
        c.U()[i] = smoothU(c.x()[i]);
    }
    const List<vector2D> before(c.U());
    const List<vector2D> xBefore(c.x());

    c.apply();

    scalar errCorrected = 0, errKept = 0, moved = 0;
    forAll(c.U(), i)
    {
        const vector2D exact(smoothU(c.x()[i]));
        errCorrected = max(errCorrected, mag(c.U()[i] - exact));
        errKept = max(errKept, mag(before[i] - exact));
        moved = max(moved, mag(c.dom.separation(c.x()[i], xBefore[i])));
    }
    // Measured: 0.0058 left of 0.053, shifts up to 0.20 dr; the same to
    // the bit without the bound, which a smooth field does not reach
    EXPECT_GT(moved, 0.1*dr);
    EXPECT_GT(errKept, 0.02) << "the shift moved nothing worth correcting";
    EXPECT_LT(errCorrected, 0.5*errKept)
        << "corrected " << errCorrected << ", uncorrected " << errKept;
}


TEST(isphShifting, aParticleFastestAmongItsNeighboursIsNotMadeFaster)
{
    latticeCase c;
    const label a = 10*n + 10;
    const vector2D site(c.x()[a]);
    // Off its site, so G{1} moves it back: a shift of 0.08 dr (measured)
    c.x()[a] += vector2D(0.2*dr, 0.1*dr);
    c.U()[a] = vector2D(10, -4);

    c.apply();

    EXPECT_GT(mag(c.x()[a] - site - vector2D(0.2*dr, 0.1*dr)), 0.05*dr)
        << "the particle was not shifted";
    // Unbounded, (38) gives it (10.023, -4.009) (measured): faster, and
    // its neighbours' velocities of the wrong sign
    EXPECT_LE(c.U()[a].x(), 10);
    EXPECT_GE(c.U()[a].y(), -4);
    forAll(c.U(), i)
    {
        EXPECT_GE(c.U()[i].x(), 0) << "particle " << i;
        EXPECT_LE(c.U()[i].x(), 10) << "particle " << i;
        EXPECT_GE(c.U()[i].y(), -4) << "particle " << i;
        EXPECT_LE(c.U()[i].y(), 0) << "particle " << i;
    }
}


// ************************************************************************* //
