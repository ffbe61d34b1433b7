/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
-------------------------------------------------------------------------------
Description
    The wall condition types each field takes, with what each means (the
    list an unknown type's error message prints).

\*---------------------------------------------------------------------------*/

#include "wallConditions.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::Pair<Foam::word>>
Foam::SPH::wallConditions::validTypes() const
{
    if (fieldName_ == "U")
    {
        return
        {
            {"noSlip", "a still wall"},
            {"slip", "a still wall without friction"},
            {"fixedValue", "a wall sliding along itself at 'value uniform (Ux Uy 0)'"},
            {
                "uniformFixedValue",
                "a wall sliding along itself at 'uniformValue', a Function1 of"
                " time (table, constant, sine, ...)"
            },
            {
                "movingWallVelocity",
                "the velocity of the wall's motion in constant/dynamicMeshDict"
                " (rotatingMotion, linearMotion, ...: a rotating or translating"
                " wall)"
            },
        };
    }
    if (fieldName_ == "p" || fieldName_ == "p_rgh")
    {
        return
        {
            {"zeroGradient", "the Neumann wall condition of USAW (eq. (43))"},
            {"fixedFluxPressure", "the same Neumann wall condition (eq. (43))"},
        };
    }
    if (fieldName_ == "T")
    {
        return
        {
            {"fixedValue", "an isothermal wall at 'value uniform T'"},
            {
                "fixedGradient",
                "an imposed heat flux, 'gradient uniform G' (K/m along the"
                " outward normal)"
            },
            {"zeroGradient", "an adiabatic wall"},
        };
    }
    if (fieldName_ == "k")
    {
        return
        {{
            "kqRWallFunction",
            "no flux through the wall, the wall particles' k from the fluid's"
            " (Leroy et al. 2014, eqs. (25)-(26))"
        }};
    }
    if (fieldName_ == "epsilon")
    {
        return
        {{
            "epsilonWallFunction",
            "the log-layer wall flux and wall value (Leroy et al. 2014,"
            " eqs. (27)-(29))"
        }};
    }
    if (fieldName_ == "nut")
    {
        return
        {{
            "nutkWallFunction",
            "the log-law wall friction on the velocity (Leroy et al. 2014,"
            " eqs. (22)-(23))"
        }};
    }
    FatalErrorInFunction
        << "No wall conditions for the field " << fieldName_
        << ": sphFoam reads those of U, p, k, epsilon, nut and T"
        << exit(FatalError);
    return {};
}


// ************************************************************************* //
