"""The Taylor-Green vortex of tutorials/periodic/taylorGreen: its parameters,
the analytic solution, and the OpenFOAM files the case scripts read and
write (python3 and numpy only). Imported by ./setTaylorGreen and ./compare.

The flow, periodic in x and y on the box [0, L]^2 (a = 2 pi/L):

    u =  U0 sin(a x) cos(a y) F(t)
    v = -U0 cos(a x) sin(a y) F(t),     F(t) = exp(-2 nu a^2 t) = exp(-8 pi^2 nu t/L^2)
    p = rho U0^2/4 (cos(2 a x) + cos(2 a y)) F(t)^2

The kinetic energy per unit mass, averaged over the box, is
E(t) = U0^2/4 F(t)^2 = U0^2/4 exp(-16 pi^2 nu t/L^2).
"""
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAM_SPHFOAM_TOOLS", os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "bin", "tools")),
    "python"))
from foamCaseFiles import read_entries  # noqa: E402


# ---------------------------------------------------------------- dictionaries

def read_parameters(case):
    """The plain 'key value;' entries of <case>/system/taylorGreenParameters
    (outside FoamFile), as strings, $name references resolved."""
    return read_entries(os.path.join(case, "system", "taylorGreenParameters"))


# ---------------------------------------------------------------- the flow

class TaylorGreen:
    """The analytic solution for a case's parameters."""

    def __init__(self, p):
        self.L = float(p["L"])
        self.U0 = float(p["U0"])
        self.nu = float(p["nu"])
        self.rho = float(p.get("rho", 1))
        self.n = int(p["n"])
        self.tEnd = float(p["tEnd"])
        self.a = 2*math.pi/self.L
        # Decay rates: the velocity exp(-lamU t), the energy exp(-lamE t)
        self.lamU = 2*self.nu*self.a**2            # 8 pi^2 nu/L^2
        self.lamE = 2*self.lamU                    # 16 pi^2 nu/L^2

    def F(self, t):
        return math.exp(-self.lamU*t)

    def U(self, x, y, t=0.0):
        """(u, v) at the points (x, y), arrays."""
        a, f = self.a, self.U0*self.F(t)
        return np.stack((f*np.sin(a*x)*np.cos(a*y),
                         -f*np.cos(a*x)*np.sin(a*y)), axis=-1)

    def pKinematic(self, x, y, t=0.0):
        """p/rho, of zero mean over the box."""
        a = self.a
        return 0.25*self.U0**2*self.F(t)**2*(np.cos(2*a*x) + np.cos(2*a*y))

    def energy(self, t):
        """E(t) = <|U|^2>/2 over the box, per unit mass."""
        return 0.25*self.U0**2*self.F(t)**2


# ---------------------------------------------------------------- OpenFOAM files

HEADER = """\
/*--------------------------------*- C++ -*----------------------------------*\\
| =========                 |                                                 |
| \\\\      /  F ield         | sphFoam: 2-D SPH on OpenFOAM                    |
|  \\\\    /   O peration     | Version:  v1912                                 |
|   \\\\  /    A nd           |                                                 |
|    \\\\/     M anipulation  |                                                 |
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "%s";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""
FOOTER = "\n// ************************************************************************* //\n"


def write_internal_field(path, cls, location, obj, values, comment):
    """Rewrite path with internalField nonuniform values (one per cell or
    fluid particle), keeping the dimensions and boundaryField of the
    file there (the template's)."""
    old = open(path).read() if os.path.isfile(path) else ""
    body = old.split("// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //", 1)[-1] \
        if old else ""
    dims = re.search(r"^dimensions\s+[^;]*;", body, flags=re.M)
    bf = re.search(r"^boundaryField\s*\{.*^\}", body, flags=re.M | re.S)
    values = np.asarray(values, float)
    out = [HEADER % (cls, location, obj), comment.rstrip() + "\n\n"]
    if dims:
        out.append(dims.group(0) + "\n\n")
    if values.ndim == 1:
        out.append("internalField   nonuniform List<scalar>\n%d\n(\n" % len(values))
        out.extend("%.17g\n" % v for v in values)
    else:
        if values.shape[1] == 2:
            values = np.column_stack((values, np.zeros(len(values))))
        out.append("internalField   nonuniform List<vector>\n%d\n(\n" % len(values))
        out.extend("(%.17g %.17g %.17g)\n" % tuple(v) for v in values)
    out.append(")\n;\n\n")
    if bf:
        out.append(bf.group(0) + "\n")
    out.append(FOOTER)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("".join(out))
    os.replace(tmp, path)


# ---------------------------------------------------------------- errors

def errors(tg, x, y, U, t):
    """(L2, E) of the velocities U at the points (x, y) (equal volumes:
    the FV cells, or the SPH particles of the lattice):

        L2 = sqrt( sum |U - Ua|^2 / sum |Ua|^2 ),  Ua the analytic velocity at t
        E  = <|U|^2>/2, the kinetic energy per unit mass
    """
    Ua = tg.U(x, y, t)
    U = np.asarray(U, float)[:, :2]
    L2 = math.sqrt(np.sum((U - Ua)**2)/np.sum(Ua**2))
    E = 0.5*np.mean(np.sum(U**2, axis=1))
    return L2, E
