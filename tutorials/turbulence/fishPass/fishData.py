"""Readers of the fish-pass runs for ./compare (tutorials/turbulence/
fishPass): a run's system/fishParameters and log, the FV sections
(postProcessing/sections, system/sections) and cell values, the SPH
particles of the last file of VTK/<case>.vtp.series, and the section
lines and pool outline of README.md.
"""
import json
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get(
    "FOAM_SPHFOAM_TOOLS", os.path.join(here, "..", "..", "..", "bin", "tools")),
    "python"))
from foamCaseFiles import (nan, read_internal_field,  # noqa: E402,F401
                           read_numeric_entries, strip_comments, time_dirs)
from foamCaseFiles import read_log as read_solver_log  # noqa: E402


# Quantities along the sections: name -> label
QUANTITIES = (("Umag", "|U| [m/s]"), ("Ux", "Ux [m/s]"), ("Uy", "Uy [m/s]"),
              ("p", "p/rho - mean [m2/s2]"), ("k", "k [m2/s2]"),
              ("epsilon", "epsilon [m2/s3]"))

# The sections in slot widths b (system/sections): start, end
SECTIONS = {"P1": ((1, 0), (1, 8)), "P2": ((3.5, 0), (3.5, 8)),
            "P3": ((6, 0), (6, 8)), "P4": ((0, 0.1), (8, 0.1))}


def slot_geometry(par):
    """The slot's section (across it at mid-length x = 8.5 b), its
    direction and the solids (the baffles, as the blockMeshDict cuts them
    out of the pool), in b, from fishParameters' slotRise: the rise of the
    slot's sides over its 1 b length."""
    rise = par["slotRise"]
    section = ((8.5, 1 + 0.5*rise), (8.5, 2 + 0.5*rise))
    direction = np.array([1.0, rise])/np.hypot(1.0, rise)
    solids = [[(8, 0), (9, 0), (9, 1 + rise), (8, 1)],          # short baffle
              [(7, 2), (8, 2), (9, 2 + rise), (9, 8), (8, 8),  # long baffle
               (8, 3), (7, 3)]]                                 # and its hook
    return section, direction, solids


def read_parameters(case):
    """The numeric 'key value;' entries of system/fishParameters."""
    return read_numeric_entries(
        os.path.join(case, "system", "fishParameters"),
        ("b", "L", "B", "slotRise", "dr", "nb", "rho", "tEnd"))


def read_log(case, app, time=None):
    """{cpu, clock, t, steps, end} from log.<app>, up to time when given;
    NaN where missing."""
    return read_solver_log(os.path.join(case, "log." + app), until=time)


def same_time(t, time):
    """t is time, to 1e-6 relative (time names round their values)."""
    return abs(t - time) <= 1e-6*max(abs(time), 1.0)


def pick_time(times, time, where):
    """Index in times (ascending) to read: the last, or the one equal to
    time."""
    if time is None:
        return len(times) - 1
    for i, t in enumerate(times):
        if same_time(t, time):
            return i
    raise RuntimeError("%s: nothing written at t = %g (written: %s)"
                       % (where, time, " ".join("%g" % t for t in times)))


def fv_set(case, name, time=None):
    """{x, y, Ux, Uy, Umag, p, k, epsilon, nut} along a set of
    system/sections at the last sampled time, or at time (raw: x y z then
    the fields in the order of the file name <set>_<f1>_<f2>...xy)."""
    base = os.path.join(case, "postProcessing", "sections")
    times = time_dirs(base)
    if not times:
        raise RuntimeError("%s: no postProcessing/sections/<time>/" % case)
    chosen = times[pick_time([float(t) for t in times], time, base)]
    folder = os.path.join(base, chosen)
    out = {"time": float(chosen)}
    for fname in sorted(os.listdir(folder)):
        m = re.fullmatch(re.escape(name) + r"_(.+)\.xy", fname)
        if not m:
            continue
        data = np.loadtxt(os.path.join(folder, fname), ndmin=2)
        out["x"], out["y"] = data[:, 0], data[:, 1]
        column = 3
        for field in m.group(1).split("_"):
            if field == "U":
                out["Ux"], out["Uy"] = data[:, column], data[:, column + 1]
                column += 3
            else:
                out[field] = data[:, column]
                column += 1
    if "Ux" not in out:
        raise RuntimeError("%s has no %s_U.xy" % (folder, name))
    out["Umag"] = np.hypot(out["Ux"], out["Uy"])
    return out


def fv_cells(case, time=None):
    """Cell centres and U at the last time, or at time (writeCellCentres:
    field C)."""
    times = [t for t in time_dirs(case) if float(t) > 0]
    if not times:
        raise RuntimeError("%s: no time folder after 0" % case)
    chosen = times[pick_time([float(t) for t in times], time, case)]
    last = os.path.join(case, chosen)
    return read_internal_field(os.path.join(last, "C")), \
        read_internal_field(os.path.join(last, "U")), float(chosen)


def sph_series(case):
    """VTK/<case>.vtp.series of the fluid (not the walls', not sphMesh's)."""
    vtk = os.path.join(case, "VTK")
    own = os.path.join(vtk, os.path.basename(os.path.abspath(case)) + ".vtp.series")
    if os.path.isfile(own):
        return own
    raise RuntimeError("%s: no VTK/<case>.vtp.series" % case)


def read_vtp(path):
    """The fluid particles (type 0): {x, y, Ux, Uy, Umag, p, k, epsilon,
    nut} (p as written, in Pa)."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    pd = data.GetPointData()
    if data.GetPoints() is None or pd.GetArray("type") is None:
        raise RuntimeError("%s has no points or no point data type" % path)
    x = vtk_to_numpy(data.GetPoints().GetData())
    fluid = vtk_to_numpy(pd.GetArray("type")).ravel() == 0
    out = {"x": x[fluid, 0].astype(float), "y": x[fluid, 1].astype(float)}
    U = vtk_to_numpy(pd.GetArray("U")).reshape(len(x), -1)
    out["Ux"], out["Uy"] = U[fluid, 0].astype(float), U[fluid, 1].astype(float)
    out["Umag"] = np.hypot(out["Ux"], out["Uy"])
    for name in ("p", "k", "epsilon", "nut"):
        if pd.GetArray(name) is not None:
            out[name] = vtk_to_numpy(pd.GetArray(name)).ravel()[fluid].astype(float)
    return out


def sph_last(case, time=None):
    """The particles of the first and the last file of the series (or the
    file of time), and its time."""
    series = sph_series(case)
    files = json.load(open(series)).get("files", [])
    if not files:
        raise RuntimeError("%s lists no files" % series)
    files = sorted(files, key=lambda f: float(f["time"]))
    if time is None and len(files) == 1:
        raise RuntimeError("%s: nothing written after the start (t = %s) yet"
                           % (series, files[0]["time"]))
    last = files[pick_time([float(f["time"]) for f in files], time, series)]
    folder = os.path.dirname(series)
    return read_vtp(os.path.join(folder, files[0]["name"])), \
        read_vtp(os.path.join(folder, last["name"])), float(last["time"])


def sph_line(particles, start, end, dr):
    """The particles within dr/2 of the segment start-end [m], binned along
    it in bins dr long: {s, x, y, <fields>} per non-empty bin (means)."""
    start, end = np.asarray(start, float), np.asarray(end, float)
    length = np.linalg.norm(end - start)
    t = (end - start)/length
    n = np.array([-t[1], t[0]])
    rel = np.stack([particles["x"] - start[0], particles["y"] - start[1]], axis=1)
    s, d = rel @ t, rel @ n
    near = (np.abs(d) <= 0.5*dr + 1e-12) & (s >= -0.5*dr) & (s <= length + 0.5*dr)
    nBins = int(np.floor(length/dr)) + 1
    bins = np.clip(np.rint(s[near]/dr).astype(int), 0, nBins - 1)
    count = np.bincount(bins, minlength=nBins)
    held = count > 0
    out = {"s": (np.arange(nBins)*dr)[held]}
    for key in ("Ux", "Uy", "Umag", "p", "k", "epsilon", "nut"):
        if key in particles:
            out[key] = (np.bincount(bins, weights=particles[key][near],
                                    minlength=nBins)[held]/count[held])
    out["x"] = start[0] + out["s"]*t[0]
    out["y"] = start[1] + out["s"]*t[1]
    return out
