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
import struct

import numpy as np


# ---------------------------------------------------------------- dictionaries

def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def read_parameters(case):
    """The plain 'key value;' entries of <case>/system/taylorGreenParameters
    (outside FoamFile), as strings, $name references resolved."""
    path = os.path.join(case, "system", "taylorGreenParameters")
    text = strip_comments(open(path).read())
    text = re.sub(r"FoamFile\s*\{[^}]*\}", "", text)
    raw = dict(re.findall(r"^\s*(\w+)\s+([^;{}]+?)\s*;", text, flags=re.M))
    values = {}
    for key, value in raw.items():
        seen = set()
        while value.startswith("$") and value[1:] in raw and value not in seen:
            seen.add(value)
            value = raw[value[1:]]
        values[key] = value
    return values


def application(case):
    """The application named in <case>/system/controlDict, or None."""
    path = os.path.join(case, "system", "controlDict")
    if not os.path.isfile(path):
        return None
    m = re.search(r"^\s*application\s+(\w+)\s*;",
                  strip_comments(open(path).read()), flags=re.M)
    return m.group(1) if m else None


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


def _header_end(data):
    """(FoamFile entries, offset just past the FoamFile block) of the bytes
    of an OpenFOAM file."""
    m = re.search(rb"FoamFile\s*\{([^}]*)\}", data)
    if not m:
        raise RuntimeError("no FoamFile header")
    entries = re.findall(rb"(\w+)\s+(\"[^\"]*\"|[^;]*);", m.group(1))
    return {k.decode(): v.decode().strip().strip('"') for k, v in entries}, m.end()


def _skip(data, pos):
    """pos past white space and comments."""
    while True:
        m = re.compile(rb"\s*(//[^\n]*\n|/\*.*?\*/)?", re.S).match(data, pos)
        if m.end() == pos:
            return pos
        pos = m.end()


def _read_list(data, pos, nComp, binary, what):
    """A list of n-component items (nComp 1: scalars or labels) starting at
    data[pos]: 'N(...)' or 'N{v}'. Returns (array, position after it)."""
    pos = _skip(data, pos)
    m = re.compile(rb"(\d+)\s*").match(data, pos)
    if not m:
        raise RuntimeError("%s: expected a list size at byte %d" % (what, pos))
    size = int(m.group(1))
    pos = m.end()
    if data[pos:pos + 1] == b"{":
        end = data.index(b"}", pos)
        item = _numbers(data[pos + 1:end])
        return np.tile(np.array(item, float), (size, 1)).reshape(size, -1)[:, :nComp] \
            if nComp > 1 else np.full(size, item[0]), end + 1
    if data[pos:pos + 1] != b"(":
        raise RuntimeError("%s: expected '(' after the size %d" % (what, size))
    pos += 1
    if binary:
        nBytes = 8*nComp*size
        values = np.frombuffer(data[pos:pos + nBytes], dtype="<f8")
        if values.size != nComp*size or data[pos + nBytes:pos + nBytes + 1] != b")":
            raise RuntimeError("%s: binary list of %d items is cut short" % (what, size))
        return values.reshape(size, nComp) if nComp > 1 else values.copy(), pos + nBytes + 1
    depth, end = 1, pos
    while depth:
        c = data[end:end + 1]
        if not c:
            raise RuntimeError("%s: unterminated list" % what)
        depth += {b"(": 1, b")": -1}.get(c, 0)
        end += 1
    values = np.array(_numbers(data[pos:end - 1]), float)
    if values.size != nComp*size:
        raise RuntimeError("%s: %d numbers for %d items of %d components"
                           % (what, values.size, size, nComp))
    return values.reshape(size, nComp) if nComp > 1 else values, end


def _numbers(chunk):
    return [float(v) for v in re.findall(rb"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", chunk)]


def read_iofield(path, nComp):
    """An IOField (the particle files: constant/sphMesh/fluid/positions,
    <time>/lagrangian/sph/U, ...), ascii or binary with 64-bit scalars."""
    data = open(path, "rb").read()
    header, pos = _header_end(data)
    binary = header.get("format", "ascii") == "binary"
    if binary and "scalar=64" not in header.get("arch", "scalar=64"):
        raise RuntimeError("%s: only 64-bit binary scalars are read (arch %s)"
                           % (path, header.get("arch")))
    values, _ = _read_list(data, pos, nComp, binary, path)
    return values


def read_internal_field(path, nComp):
    """The internalField of a volField file: uniform or nonuniform, ascii
    or binary."""
    data = open(path, "rb").read()
    header, pos = _header_end(data)
    binary = header.get("format", "ascii") == "binary"
    m = re.compile(rb"internalField\s+(uniform|nonuniform)\s*").search(data, pos)
    if not m:
        raise RuntimeError("%s: no internalField" % path)
    pos = m.end()
    if m.group(1) == b"uniform":
        end = data.index(b";", pos)
        return np.array(_numbers(data[pos:end]), float)
    m = re.compile(rb"List<\w+>\s*").match(data, pos)
    if m:
        pos = m.end()
    values, _ = _read_list(data, pos, nComp, binary, path)
    return values


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


def time_dirs(path):
    """The time folders of path, sorted by value: [(t, name)]."""
    if not os.path.isdir(path):
        return []
    times = []
    for name in os.listdir(path):
        try:
            times.append((float(name), name))
        except ValueError:
            pass
    return sorted(times)


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
