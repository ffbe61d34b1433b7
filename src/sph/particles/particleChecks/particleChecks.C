/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "particleChecks.H"
#include "HashTable.H"
#include "error.H"
#include "OStringStream.H"

#include <cmath>
#include <cstdlib>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;
    using namespace Foam::SPH;

    bool finite(const scalar x)
    {
        return std::isfinite(x);
    }

    bool finite(const vector2D& v)
    {
        return std::isfinite(v.x()) && std::isfinite(v.y());
    }

    //- "particle 20 (id 20)": its id when the id field is there
    std::string particleName(const particles& parts, const label i)
    {
        std::string s = "particle " + std::to_string(i);
        if (parts.found<label>("id") && parts.field<label>("id").size() > i)
        {
            s += " (id " + std::to_string(parts.field<label>("id")[i]) + ")";
        }
        return s;
    }

    [[noreturn]] void bad
    (
        const particles& parts,
        const word& file,
        const label i,
        const std::string& what
    )
    {
        FatalErrorInFunction
            << parts.path()/file << ": "
            << (i >= 0 ? particleName(parts, i) + " " : std::string()).c_str()
            << what.c_str() << nl
            << "(the particles of a restart; fix or remove the time"
            << " directory)" << exit(FatalError);
        std::abort();
    }

    template<class Type>
    void checkFinite(const particles& parts, const word& name, const Field<Type>& f)
    {
        forAll(f, i)
        {
            if (!finite(f[i]))
            {
                OStringStream os;
                os << f[i];
                bad(parts, name, i, "holds " + os.str() + ": not a finite value");
            }
        }
    }

    //- Sizes and finite values of every restart field
    void checkValues(const particles& parts)
    {
        const label n = parts.size();
        checkFinite(parts, "positions", parts.positions());
        for (const word& name : parts.names())
        {
            if (!parts.isRestart(name)) continue;
            label size = -1;
            if (parts.isScalar(name))
            {
                size = parts.field<scalar>(name).size();
                if (size == n) checkFinite(parts, name, parts.field<scalar>(name));
            }
            else if (parts.isVector(name))
            {
                size = parts.field<vector2D>(name).size();
                if (size == n) checkFinite(parts, name, parts.field<vector2D>(name));
            }
            else
            {
                size = parts.field<label>(name).size();
            }
            if (size != n)
            {
                bad
                (
                    parts, name, -1, "holds " + std::to_string(size)
                  + " values, positions " + std::to_string(n)
                );
            }
        }
    }

    //- type: a kind, the fluid first, some fluid; returns the fluid count
    label checkTypes(const particles& parts)
    {
        const labelField& type = parts.field<label>("type");
        label nFluid = 0;
        while (nFluid < type.size() && type[nFluid] == label(particleKind::fluid))
        {
            ++nFluid;
        }
        forAll(type, i)
        {
            if (type[i] < 0 || type[i] > label(particleKind::interfacial))
            {
                bad
                (
                    parts, "type", i, "has type " + std::to_string(type[i])
                  + ": expected 0 (fluid), 1 (wall vertex), 2 (dummy) or 3"
                    " (interfacial dummy)"
                );
            }
            if (i > nFluid && type[i] == label(particleKind::fluid))
            {
                bad
                (
                    parts, "type", i, "is a fluid particle after the first"
                    " wall particle (" + std::to_string(nFluid) + "): the"
                    " fluid particles come first"
                );
            }
        }
        if (nFluid == 0)
        {
            bad
            (
                parts, "type", -1, "holds no fluid particle (type 0) among "
              + std::to_string(type.size()) + " particles: nothing to run"
            );
        }
        return nFluid;
    }

    void checkIds(const particles& parts)
    {
        const labelField& id = parts.field<label>("id");
        HashTable<label, label, Hash<label>> first(2*id.size());
        forAll(id, i)
        {
            if (!first.insert(id[i], i))
            {
                bad
                (
                    parts, "id", i, "has the id of particle "
                  + std::to_string(first[id[i]]) + ": ids must be unique"
                );
            }
        }
    }

    void checkPatches(const particles& parts, const label nFluid, const label nPatches)
    {
        const labelField& patch = parts.field<label>("patch");
        forAll(patch, i)
        {
            const bool fluid = i < nFluid;
            if (fluid ? patch[i] != -1 : patch[i] < 0 || patch[i] >= nPatches)
            {
                bad
                (
                    parts, "patch", i, "has patch " + std::to_string(patch[i])
                  + (
                        fluid
                      ? ": expected -1 for a fluid particle"
                      : ": expected a wall patch, 0 to "
                      + std::to_string(nPatches - 1)
                    )
                );
            }
        }
    }
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::SPH::checkRestartParticles
(
    const particles& parts,
    const label nPatches,
    const domain& dom
)
{
    checkValues(parts);
    const label nFluid = checkTypes(parts);
    if (parts.found<label>("id"))
    {
        checkIds(parts);
    }
    if (parts.found<label>("patch"))
    {
        checkPatches(parts, nFluid, nPatches);
    }
    const vector2DField& x = parts.positions();
    forAll(x, i)
    {
        if (!dom.contains(x[i]))
        {
            bad
            (
                parts, "positions", i, "at (" + std::string(Foam::name(x[i].x())) + " "
              + Foam::name(x[i].y()) + ") is outside the domain (the"
                " walls' box with a margin)"
            );
        }
    }
    if (parts.isRestart("rho") && parts.isScalar("rho"))
    {
        const scalarField& rho = parts.field<scalar>("rho");
        forAll(rho, i)
        {
            if (!(rho[i] > 0))
            {
                bad
                (
                    parts, "rho", i, "has density " + Foam::name(rho[i])
                  + ": expected > 0"
                );
            }
        }
    }
}


// ************************************************************************* //
