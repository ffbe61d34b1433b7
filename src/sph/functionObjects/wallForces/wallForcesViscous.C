/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The viscous part of wallForces on USAW walls: Leroy et al. 2014
    eqs. (69)-(70), the velocity gradient at the wall vertices (see
    wallForces.H).

\*---------------------------------------------------------------------------*/

#include "wallForces.H"
#include "shepardInterpolation.H"
#include "fluidProperties.H"
#include "kernelDispatch.H"
#include "scalarMatrices.H"
#include "HashSet.H"
#include "Map.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::SPH::functionObjects::wallForces::hasVertexParticles() const
{
    const sphCloud& c = cloud();
    const label nPoints = c.walls().points().size();
    if (nPoints == 0 || c.size() - c.nFluid() != nPoints)
    {
        return false;
    }
    const labelField& type = c.parts().field<label>("type");
    for (label k = c.nFluid(); k < c.size(); ++k)
    {
        if (type[k] != label(particleKind::wallVertex))
        {
            return false;
        }
    }
    return true;
}


Foam::tensor2D Foam::SPH::functionObjects::wallForces::vertexGradient
(
    const label v
) const
{
    const sphCloud& c = cloud();
    const label nFluid = c.nFluid();
    const scalar m = c.mass();
    const scalar* rho = c.parts().field<scalar>("rho").cdata();
    const vector2D* U = c.parts().field<vector2D>("U").cdata();
    const vector2D& xv = c.walls().points()[v];
    const vector2D& uv = U[nFluid + v];

    // Sums over the fluid particles b of V_b grad w_vb (x) (u_b - u_v) and
    // of V_b grad w_vb (x) (x_b - x_v); rvb = x_v - x_b (minimum image)
    tensor2D G(Zero);
    tensor2D M(Zero);
    dispatch(c.W(), [&](const auto& K)
    {
        c.cells().forEachNeighbour
        (
            xv,
            K.support(),
            [&](const label b, const vector2D& rvb, const scalar r2)
            {
                if (b < nFluid)
                {
                    const vector2D dW(m/rho[b]*K.gradW(rvb, std::sqrt(r2)));
                    G += dW*(U[b] - uv);
                    M -= dW*rvb;
                }
            }
        );
    });

    if (gradScheme_ != wallGradientScheme::gamma)
    {
        // Too few neighbours to span the plane: no gradient to read
        return mag(det(M)) > SMALL ? (inv(M) & G) : tensor2D(Zero);
    }
    const scalar gammaV = usawPtr_->gammaAt(xv);
    return gammaV > SMALL ? G/gammaV : tensor2D(Zero);
}


Foam::tensor2D Foam::SPH::functionObjects::wallForces::vertexGradientQuadratic
(
    const label v
) const
{
    const sphCloud& c = cloud();
    const label nFluid = c.nFluid();
    const scalar m = c.mass();
    const scalar* rho = c.parts().field<scalar>("rho").cdata();
    const vector2D* U = c.parts().field<vector2D>("U").cdata();
    const vector2D& xv = c.walls().points()[v];
    const vector2D& uv = U[nFluid + v];

    // Normal equations of the weighted fit of u_b - u_v by the basis
    // (dx, dy, dx^2/2, dx dy, dy^2/2) of d = (x_b - x_v)/h (scaled, so
    // that the matrix is of order one)
    const scalar h = 0.5*c.W().support();
    scalarSquareMatrix A(5, Zero);
    List<vector2D> rhs(5, Zero);
    label nUsed = 0;
    dispatch(c.W(), [&](const auto& K)
    {
        c.cells().forEachNeighbour
        (
            xv,
            K.support(),
            [&](const label b, const vector2D& rvb, const scalar r2)
            {
                if (b >= nFluid)
                {
                    return;
                }
                const scalar wb = m/rho[b]*K.W(std::sqrt(r2));
                const vector2D d(-rvb/h);
                const scalar phi[5] =
                    {d.x(), d.y(), 0.5*sqr(d.x()), d.x()*d.y(), 0.5*sqr(d.y())};
                for (label i = 0; i < 5; ++i)
                {
                    for (label j = 0; j < 5; ++j)
                    {
                        A(i, j) += wb*phi[i]*phi[j];
                    }
                    rhs[i] += wb*phi[i]*(U[b] - uv);
                }
                ++nUsed;
            }
        );
    });

    // Fewer neighbours than twice the unknowns, or a singular fit: the
    // renormalised (linear) gradient
    const scalarSquareMatrix& Aconst = A;
    if (nUsed < 10 || !(mag(det(Aconst)) > 1e-12*pow(A(0, 0) + A(1, 1), 5)))
    {
        return vertexGradient(v);
    }
    LUsolve(A, rhs);

    // rhs[0] = h du/dx, rhs[1] = h du/dy (each a vector of u_x, u_y)
    return tensor2D
    (
        rhs[0].x(), rhs[0].y(),
        rhs[1].x(), rhs[1].y()
    )/h;
}


void Foam::SPH::functionObjects::wallForces::measureViscous()
{
    viscousForce_ = vector2D::zero;
    viscousMoment_ = 0;
    if (!usawPtr_.valid())
    {
        return;
    }

    const sphCloud& c = cloud();
    const wallMesh& walls = c.walls();
    const labelHashSet selected(patches_);

    // Moving walls: gamma at the vertices where they are now
    usawPtr_->updateGeometry(walls.points());

    // Each vertex's gradient once, although two segments share it
    Map<tensor2D> vertexGrad;
    auto gradAt = [&](const label v) -> tensor2D
    {
        if (!vertexGrad.found(v))
        {
            vertexGrad.insert
            (
                v,
                gradScheme_ == wallGradientScheme::quadratic
              ? vertexGradientQuadratic(v)
              : vertexGradient(v)
            );
        }
        return vertexGrad[v];
    };

    shepardInterpolation interp(c);

    forAll(walls.segments(), s)
    {
        if (!selected.found(walls.segmentPatch()[s]))
        {
            continue;
        }
        const labelPair& ends = walls.segments()[s];
        const vector2D mid
        (
            0.5*(walls.points()[ends.first()] + walls.points()[ends.second()])
        );
        interp.setPoint(mid);
        if (!interp.wet(minFraction_))
        {
            continue;
        }

        // Eq. (70): the mean of the two vertex gradients; eq. (69): the
        // viscous stress on the wall, whose normal points into the fluid
        const tensor2D gradU
        (
            0.5*(gradAt(ends.first()) + gradAt(ends.second()))
        );
        const vector2D& n = walls.segmentNormals()[s];
        const vector2D dF =
            mu_*((gradU + gradU.T()) & n)*walls.segmentLength(s);
        const vector2D arm = mid - CofR_;

        viscousForce_ += dF;
        viscousMoment_ += arm.x()*dF.y() - arm.y()*dF.x();
    }
}


void Foam::SPH::functionObjects::wallForces::readViscous
(
    const dictionary& dict
)
{
    const word scheme(dict.lookupOrDefault<word>("wallGradient", "gamma"));
    if (scheme == "gamma")
    {
        gradScheme_ = wallGradientScheme::gamma;
    }
    else if (scheme == "renormalised")
    {
        gradScheme_ = wallGradientScheme::renormalised;
    }
    else if (scheme == "quadratic")
    {
        gradScheme_ = wallGradientScheme::quadratic;
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": wallGradient " << scheme
            << ", expected gamma, renormalised or quadratic"
            << exit(FatalIOError);
    }
    gradName_ = scheme;

    const word pressure
    (
        dict.lookupOrDefault<word>("wallPressure", "vertices")
    );
    if (pressure != "vertices" && pressure != "shepard")
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": wallPressure " << pressure
            << ", expected vertices or shepard"
            << exit(FatalIOError);
    }

    // The viscous part needs the wall velocity at the vertices: USAW only
    usawPtr_.clear();
    if (hasVertexParticles())
    {
        const sphCloud& c = cloud();
        const fluidProperties props(time_);
        mu_ = props.rho0*props.nu;
        usawPtr_.reset(new usawWalls(c.walls(), c.W(), c.nFluid(), c.dom()));
    }
    vertexPressure_ = usawPtr_.valid() && pressure == "vertices";
}


// ************************************************************************* //
