/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "heatTransfer.H"
#include "kernelDispatch.H"
#include "initialField.H"
#include "wallConditions.H"
#include "fluidProperties.H"
#include "uniformDimensionedFields.H"
#include "Time.H"
#include "IOdictionary.H"
#include "checkedEntry.H"
#include "OStringStream.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- 'key uniform X;' of a wall patch's entry in 0/T, or a FatalIOError
    //- naming the file, the patch and the entry
    scalar uniformScalar
    (
        const dictionary& d,
        const word& key,
        const word& patch,
        const word& type
    )
    {
        if (!d.found(key))
        {
            FatalIOErrorInFunction(d)
                << "Missing entry '" << key << "' of the " << type << " T of"
                << " wall patch " << patch << ": expected '" << key
                << " uniform <value>;'"
                << (key == "gradient" ? " (K/m along the outward normal)" : "")
                << exit(FatalIOError);
        }
        ITstream& is = d.lookup(key);
        const token first(is);
        if (!first.isWord() || first.wordToken() != "uniform")
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << key << "' of wall patch " << patch << ": expected '"
                << key << " uniform <value>;', found " << first
                << " (a wall patch of the SPH mesh has no faces to give"
                << " values to)" << exit(FatalIOError);
        }
        const token value(is);
        if (!value.isNumber() || !std::isfinite(value.number()))
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << key << "' of wall patch " << patch << ": expected '"
                << key << " uniform <value>;', found " << value
                << exit(FatalIOError);
        }
        return value.number();
    }
}


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace
{
    const Foam::Enum<bool> heatSchemeNames
    ({
        { false, "explicit" },
        { true, "implicit" },
    });
}


const Foam::Enum<Foam::SPH::heatTransfer::vertexForm>
Foam::SPH::heatTransfer::vertexFormNames
({
    { vertexForm::shepard, "shepard" },
    { vertexForm::linear, "linear" },
});


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::heatTransfer::isothermalFlux
(
    const scalar Ta,
    const scalar Ts,
    const scalar d,
    const scalar drFloor,
    const scalar K,
    const scalar nu,
    const scalar ka,
    const turbulentWall& tw
)
{
    // dr_as = max(d_as, dr) (22), as the velocity's, or a lower floor
    const scalar dAs = max(d, drFloor);
    if (tw.law && ka > 0)
    {
        // (35)-(37): y+ from u_k
        const scalar uk = std::pow(tw.Cmu, 0.25)*std::sqrt(ka);
        const scalar yPlus = dAs*uk/nu;
        if (yPlus >= tw.law->y1Plus())
        {
            return uk*(Ta - Ts)/tw.law->Tplus(yPlus);
        }
    }
    // (34), also the viscous layer of (37): u_k (T_a - T_s)/(Pr y+)
    return K*(Ta - Ts)/dAs;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::heatTransfer::readWalls(const wallMesh& walls, const label nFluid)
{
    typedef wallConditions::conditionType cType;
    const wallConditions conditions(runTime_, walls, "T");
    conditions.allowOnly
    (
        {cType::fixedValue, cType::fixedGradient, cType::zeroGradient},
        "isphFoam's temperature walls"
    );
    const wordList& names = walls.patchNames();
    scalarList patchValue(names.size(), Zero);
    List<wallKind> patchKind(names.size(), adiabatic);
    forAll(names, patchi)
    {
        const dictionary& d = conditions.dict(patchi);
        switch (conditions.type(patchi))
        {
            case cType::fixedValue:
                patchKind[patchi] = isothermal;
                patchValue[patchi] = uniformScalar(d, "value", names[patchi], "fixedValue");
                break;
            case cType::fixedGradient:
                patchKind[patchi] = fluxImposed;
                patchValue[patchi] =
                    uniformScalar(d, "gradient", names[patchi], "fixedGradient");
                break;
            default:
                break;
        }
        Info<< "    T on " << names[patchi] << ": "
            << conditions.typeName(patchi) << " "
            << (patchKind[patchi] == adiabatic ? "(adiabatic)"
              : patchKind[patchi] == isothermal ? "(isothermal, eqs. (33)-(34))"
              : "(imposed flux, eqs. (31)-(32))")
            << (patchKind[patchi] == adiabatic ? "" : " ")
            << (patchKind[patchi] == adiabatic ? word() : Foam::name(patchValue[patchi]))
            << nl;
    }

    // Per segment, then per vertex particle: an isothermal segment fixes
    // its vertices (a corner with another wall takes the imposed value)
    const labelList& segPatch = walls.segmentPatch();
    const List<labelPair>& segs = walls.segments();
    const label nV = walls.points().size();
    walls_.kind.setSize(segPatch.size());
    walls_.gradient.setSize(segPatch.size(), Zero);
    walls_.fixed.setSize(nV, false);
    walls_.value.setSize(nV, Zero);
    walls_.vertexSegments.setSize(nV);
    forAll(segPatch, s)
    {
        const label patchi = segPatch[s];
        walls_.kind[s] = patchKind[patchi];
        if (patchKind[patchi] == fluxImposed)
        {
            walls_.gradient[s] = patchValue[patchi];
        }
        for (const label v : {segs[s].first(), segs[s].second()})
        {
            walls_.vertexSegments[v].append(s);
            if (patchKind[patchi] == isothermal)
            {
                walls_.fixed[v] = true;
                walls_.value[v] = patchValue[patchi];
            }
        }
    }
}


void Foam::SPH::heatTransfer::readInitial()
{
    const initialField T0(runTime_, "T");
    SubList<scalar> T(parts_.field<scalar>("T"), work_->nFluid);
    if (T0.read(T))
    {
        Info<< "Initial temperature " << T[0] << " from " << T0.path() << nl;
    }
    else
    {
        Info<< "Initial temperature per particle from " << T0.path() << nl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::heatTransfer::heatTransfer(const Time& runTime, particles& parts)
:
    runTime_(runTime),
    parts_(parts),
    props_(runTime),
    wallFunction_(props_.Pr, props_.Prt, 0.41),
    rho_(fluidProperties(runTime).rho0),
    g_(fluidProperties(runTime).g),
    ghRef_(0),
    removeMean_(false),
    fluxMinDistance_(1),
    implicit_(false),
    stopIfNotConverged_(true),
    nut_(nullptr)
{
    // Eq. (43) of Leroy et al. 2015: sphSchemes' meanBuoyancy
    const IOdictionary schemes
    (
        IOobject
        (
            "sphSchemes", runTime.system(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    const word mean = schemes.getOrDefault<word>("meanBuoyancy", "keep");
    if (mean != "keep" && mean != "remove")
    {
        FatalIOErrorInFunction(schemes)
            << "Entry meanBuoyancy " << mean << ": expected keep (the"
            << " default) or remove (the fluid's mean of the Boussinesq force"
            << " taken off, Leroy et al. 2015, eq. (43))" << exit(FatalIOError);
    }
    removeMean_ = (mean == "remove");
    walls_.form = vertexFormNames.getOrDefault
    (
        "vertexTemperature", schemes, vertexForm::shepard
    );
    implicit_ = heatSchemeNames.getOrDefault("heatScheme", schemes, false);
    fluxMinDistance_ = checkedScalar
    (
        schemes, "isothermalFluxMinDistance", 1, {0, 1, true},
        "in dr: the floor of dr_as in eqs. (34)-(37)"
    );

    // OpenFOAM's readhRef.H and gh.H: hRef optional, 0 without the file
    const uniformDimensionedScalarField hRef
    (
        IOobject
        (
            "hRef", runTime.constant(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        ),
        dimensionedScalar("hRef", dimLength, Zero)
    );
    ghRef_ = -mag(g_)*hRef.value();

    Info<< "Heat transfer (0/T): beta " << props_.beta << ", TRef "
        << props_.TRef << ", Pr " << props_.Pr << ", Prt " << props_.Prt
        << ", K = nu/Pr " << props_.K << ", hRef " << hRef.value()
        << (removeMean_ ? ", the fluid's mean force removed (eq. (43))" : "")
        << nl
        << "    isothermal walls: dr_as = max(d_as, " << fluxMinDistance_
        << " dr) in eqs. (34)-(37)" << nl
        << "    heat equation: "
        << (
               implicit_
             ? "backward Euler (heatScheme implicit)"
             : "explicit, as printed (heatScheme explicit)"
           )
        << nl
        << "    vertex T of adiabatic and flux walls: "
        << (
               walls_.form == vertexForm::linear
             ? "eq. (32) with a tangential gradient fitted (vertexTemperature"
               " linear)"
             : "eq. (32) (vertexTemperature shepard)"
           )
        << nl;
    parts_.add<scalar>("T");
    parts_.add<scalar>("p_rgh");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::heatTransfer::connect
(
    const turbulenceCoupling& coupling,
    const wallMesh& walls,
    const bool fresh,
    const scalarField* nut
)
{
    work_.reset(new turbulenceCoupling(coupling));
    nut_ = nut;
    if (parts_.found<scalar>("k"))
    {
        turbulent_.k = &parts_.field<scalar>("k");
        turbulent_.law = &wallFunction_;
    }
    readWalls(walls, coupling.nFluid);
    KE_.setSize(parts_.size(), props_.K);
    L_.setSize(parts_.size(), Zero);
    if (implicit_)
    {
        connectImplicit();
    }
    if (fresh)
    {
        readInitial();
    }
}


void Foam::SPH::heatTransfer::correct(const scalar dt)
{
    if (implicit_)
    {
        correctImplicit(dt);
        return;
    }
    const turbulenceCoupling& w = *work_;
    scalarField& T = parts_.field<scalar>("T");

    // K_E = K + nu_T/Prt (nu_T = 0 at the vertex particles)
    for (label i = 0; i < w.nFluid; ++i)
    {
        KE_[i] = props_.K + (nut_ ? (*nut_)[i]/props_.Prt : 0);
    }
    dispatch(w.W, [&](const auto& K)
    {
        vertexValues(K, w.nbrs, w.usaw, w.V, w.nFluid, walls_, T);
        laplacian
        (
            K, w.nbrs, w.usaw, w.V, w.nFluid, KE_, T, walls_, props_.K,
            props_.nu, fluxMinDistance_*w.dr, turbulent_, L_
        );
    });
    for (label i = 0; i < w.nFluid; ++i)
    {
        T[i] += dt*L_[i];
    }
}


void Foam::SPH::heatTransfer::addBuoyancy
(
    const scalar dt,
    UList<vector2D>& Ustar,
    List<vector2D>& wallForce
)
{
    const turbulenceCoupling& w = *work_;
    scalarField& T = parts_.field<scalar>("T");
    dispatch(w.W, [&](const auto& K)
    {
        vertexValues(K, w.nbrs, w.usaw, w.V, w.nFluid, walls_, T);
    });
    // Eq. (43): -g beta (<T>_F - T0), <T>_F the fluid's volume mean
    vector2D mean = vector2D::zero;
    if (removeMean_ && w.nFluid > 0)
    {
        scalar VT = 0, V = 0;
        for (label i = 0; i < w.nFluid; ++i)
        {
            VT += w.V[i]*T[i];
            V += w.V[i];
        }
        mean = buoyancy(g_, props_.beta, VT/V, props_.TRef);
    }
    forAll(T, i)
    {
        Ustar[i] += dt*(buoyancy(g_, props_.beta, T[i], props_.TRef) - mean);
    }
    const List<labelPair>& ends = w.usaw.segmentParticles();
    wallForce.setSize(ends.size());
    forAll(ends, s)
    {
        const scalar Ts = 0.5*(T[ends[s].first()] + T[ends[s].second()]);
        wallForce[s] = buoyancy(g_, props_.beta, Ts, props_.TRef) - mean;
    }
}


Foam::SPH::buoyantTurbulence
Foam::SPH::heatTransfer::turbulenceTerms() const
{
    buoyantTurbulence terms;
    terms.beta = props_.beta;
    terms.Prt = props_.Prt;
    terms.g = g_;
    terms.T = &parts_.field<scalar>("T");
    return terms;
}


void Foam::SPH::heatTransfer::updatePrgh(const scalar)
{
    const scalarField& T = parts_.field<scalar>("T");
    const scalarField& p = parts_.field<scalar>("p");
    const vector2DField& x = parts_.positions();
    scalarField& pRgh = parts_.field<scalar>("p_rgh");
    forAll(pRgh, i)
    {
        const scalar rhok = 1 - props_.beta*(T[i] - props_.TRef);
        pRgh[i] = p[i] - rho_*rhok*((g_ & x[i]) - ghRef_);
    }
}


Foam::scalar Foam::SPH::heatTransfer::maxDeltaT(const scalar h) const
{
    if (implicit_)
    {
        return VGREAT;
    }
    scalar KMax = props_.K;
    if (nut_)
    {
        for (label i = 0; i < work_->nFluid; ++i)
        {
            KMax = max(KMax, props_.K + (*nut_)[i]/props_.Prt);
        }
    }
    return KMax > 0 ? 0.125*h*h/KMax : VGREAT;
}


void Foam::SPH::heatTransfer::printStep(Ostream& os) const
{
    if (implicit_)
    {
        lastSolve_.print(os);
    }
}


void Foam::SPH::heatTransfer::expireReuse() const
{
    if (solverT_)
    {
        solverT_->expirePreconditioner();
    }
}


Foam::string Foam::SPH::heatTransfer::description() const
{
    if (implicit_)
    {
        OStringStream os;
        if (solverT_) solverT_->write(os);
        return
            "T^{n+1} = T^n + dt L{K, T^{n+1}} (Leroy et al. 2015, eq. (17),"
            " backward Euler), walls (31)-(34), the vertex T of (32) from T^n;"
            " K = nu/Pr = " + Foam::name(props_.K) + "; " + os.str();
    }
    return
        "T^{n+1} = T^n + dt L{K_E, T^n} (Leroy et al. 2015, eq. (17)), walls"
        " (31)-(34)" + string(turbulent_.law ? ", (35)-(38) turbulent" : "")
      + "; K = nu/Pr = " + Foam::name(props_.K);
}


Foam::string Foam::SPH::heatTransfer::buoyancyDescription() const
{
    return
        "u** += -dt g beta (T - TRef) (Leroy et al. 2015, eq. (17)), beta "
      + Foam::name(props_.beta) + ", TRef " + Foam::name(props_.TRef);
}


// ************************************************************************* //
