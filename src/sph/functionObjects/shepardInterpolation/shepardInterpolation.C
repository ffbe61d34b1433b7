/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "shepardInterpolation.H"
#include "kernelDispatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::shepardInterpolation::shepardInterpolation(const sphCloud& cloud)
:
    cloud_(cloud),
    point_(vector2D::zero),
    neighbours_(),
    weights_(),
    fraction_(0)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::SPH::shepardInterpolation::setPoint(const vector2D& x)
{
    point_ = x;
    neighbours_.clear();
    weights_.clear();
    fraction_ = 0;

    const label nFluid = cloud_.nFluid();
    const scalar m = cloud_.mass();
    const scalar* rho = cloud_.parts().field<scalar>("rho").cdata();

    dispatch(cloud_.W(), [&](const auto& K)
    {
        cloud_.cells().forEachNeighbour
        (
            x,
            K.support(),
            [&](const label b, const vector2D&, const scalar r2)
            {
                // Wall and dummy particles carry wall values, not the
                // fluid's: the sensor sees the fluid only
                if (b < nFluid)
                {
                    // V_b W(|x - x_b|), V_b = m/rho_b
                    const scalar w = m/rho[b]*K.W(std::sqrt(r2));
                    neighbours_.append(b);
                    weights_.append(w);
                    fraction_ += w;
                }
            }
        );
    });

    return fraction_;
}


Foam::scalar Foam::SPH::shepardInterpolation::hydrostaticPressure
(
    const scalar minFraction
) const
{
    if (!wet(minFraction))
    {
        return 0;
    }

    const vector2D* x = cloud_.parts().positions().cdata();
    const scalar* p = cloud_.parts().field<scalar>("p").cdata();
    const scalar* rho = cloud_.parts().field<scalar>("rho").cdata();
    const vector2D& g = cloud_.g();

    // 004_f29223b75201dc88.txt eq. (10): each fluid particle's pressure
    // carried to the point through the hydrostatic column between them
    scalar sum = 0;
    forAll(neighbours_, k)
    {
        const label b = neighbours_[k];
        sum += weights_[k]*(p[b] + rho[b]*(g & (point_ - x[b])));
    }
    return sum/fraction_;
}


Foam::scalar Foam::SPH::shepardInterpolation::fluidFraction
(
    const sphCloud& cloud,
    const vector2D& x
)
{
    const label nFluid = cloud.nFluid();
    const scalar m = cloud.mass();
    const scalar* rho = cloud.parts().field<scalar>("rho").cdata();

    scalar fraction = 0;
    dispatch(cloud.W(), [&](const auto& K)
    {
        cloud.cells().forEachNeighbour
        (
            x,
            K.support(),
            [&](const label b, const vector2D&, const scalar r2)
            {
                if (b < nFluid)
                {
                    fraction += m/rho[b]*K.W(std::sqrt(r2));
                }
            }
        );
    });
    return fraction;
}


Foam::scalar Foam::SPH::shepardInterpolation::latticeFraction
(
    const kernel& W,
    const scalar dr
)
{
    // Lattice points (i dr, j dr) within the support: |i|, |j| <= n
    const label n = label(std::ceil(W.support()/dr));

    scalar sum = 0;
    for (label j = -n; j <= n; ++j)
    {
        for (label i = -n; i <= n; ++i)
        {
            sum += W.W(dr*std::sqrt(scalar(i*i + j*j)));
        }
    }
    return sqr(dr)*sum;
}


// ************************************************************************* //
