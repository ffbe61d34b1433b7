/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "fvOptionForces.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::fvOptionForces::fvOptionForces(const Time& runTime)
:
    dict_
    (
        IOobject
        (
            "fvOptions", runTime.constant(), runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    )
{
    for (const entry& e : dict_)
    {
        if (!e.isDict())
        {
            continue;
        }
        autoPtr<bodyForce> force(bodyForce::New(e.keyword(), e.dict(), runTime));
        if (force)
        {
            append(force.release());
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector2D Foam::SPH::fvOptionForces::acceleration
(
    const UList<vector2D>& U,
    const UList<scalar>& V,
    const scalar dt
)
{
    vector2D a(Zero);
    for (bodyForce& f : *this)
    {
        a += f.acceleration(U, V, dt);
    }
    return a;
}


Foam::vector2D Foam::SPH::fvOptionForces::acceleration
(
    const UList<vector2D>& U,
    const scalar dt
)
{
    return acceleration(U, scalarList(U.size(), 1.0), dt);
}


Foam::vector2D Foam::SPH::fvOptionForces::force() const
{
    vector2D a(Zero);
    for (const bodyForce& f : *this)
    {
        a += f.force();
    }
    return a;
}


void Foam::SPH::fvOptionForces::checkDomain(const domain& dom) const
{
    for (const bodyForce& f : *this) f.checkDomain(dom);
}


void Foam::SPH::fvOptionForces::save()
{
    for (bodyForce& f : *this) f.save();
}


void Foam::SPH::fvOptionForces::restore()
{
    for (bodyForce& f : *this) f.restore();
}


void Foam::SPH::fvOptionForces::write() const
{
    for (const bodyForce& f : *this) f.write();
}


void Foam::SPH::fvOptionForces::printStep(Ostream& os) const
{
    for (const bodyForce& f : *this) f.printStep(os);
}


// ************************************************************************* //
