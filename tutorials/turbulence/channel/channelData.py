"""Readers of the turbulent channel's runs and of the DNS, for ./compare
(tutorials/turbulence/channel): a run's system/channelParameters and log,
the FV profiles (postProcess -func profile) and wall shear stress, the SPH
particles of VTK/<case>.vtp.series binned by rows, and the DNS of Moser,
Kim and Mansour (1999) in the units of Leroy et al. 2014, eq. (72).
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
from foamCaseFiles import (nan, read_function_object, read_numeric_entries,  # noqa: E402,F401
                           strip_comments, time_dirs)
from foamCaseFiles import read_log as read_solver_log  # noqa: E402

QUANTITIES = ("u", "k", "eps", "nut")

# The DNS kept with the project (etc/reference), or SPHFOAM_REFERENCE
dnsFile = os.environ.get(
    "SPHFOAM_REFERENCE",
    os.path.join(os.environ.get("SPHFOAM_PROJECT_DIR", os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")),
        "etc", "reference", "channel_dns_retau590.csv"))


def read_parameters(case):
    """The numeric 'key value;' entries of system/channelParameters."""
    return read_numeric_entries(
        os.path.join(case, "system", "channelParameters"),
        ("e", "f", "nu", "dr", "Re"))


def read_log(case, app):
    """(CPU s, clock s, last time) from log.<app>; NaN where missing."""
    log = read_solver_log(os.path.join(case, "log." + app))
    return log["cpu"], log["clock"], log["t"]


def fold(y, e):
    return np.minimum(y, 2*e - y)


def fv_profiles(case):
    """{y, u, k, eps, nut} at the cell centres over the whole channel, from
    the last sampled time (raw sets: y then the fields, in the order of
    the file name cellCentres_<f1>_<f2>...xy)."""
    base = os.path.join(case, "postProcessing", "profile")
    times = time_dirs(base)
    if not times:
        raise RuntimeError("no postProcessing/profile/<time>/ (run "
                           "'postProcess -func profile -latestTime')")
    folder = os.path.join(base, times[-1])
    out = {}
    rename = {"U": "u", "epsilon": "eps"}
    for name in sorted(os.listdir(folder)):
        m = re.fullmatch(r"cellCentres_(.+)\.xy", name)
        if not m:
            continue
        data = np.loadtxt(os.path.join(folder, name), ndmin=2)
        out["y"] = data[:, 0]
        column = 1
        for field in m.group(1).split("_"):
            out[rename.get(field, field)] = data[:, column]
            column += 3 if field == "U" else 1
    if "u" not in out:
        raise RuntimeError("%s has no cellCentres_U.xy" % folder)
    return out


def fv_wall_shear(case):
    """u*^2 = the mean of -tau_x over lowerWall and upperWall, last time."""
    last = {}
    for line in read_function_object(
            os.path.join(case, "postProcessing", "wallShearStress"),
            "wallShearStress.dat")[1]:
        words = line.replace("(", " ").replace(")", " ").split()
        if len(words) >= 5:
            last[words[1]] = float(words[2])
    if not last:
        return nan
    return -np.mean(list(last.values()))


def sph_series(case):
    """VTK/<case>.vtp.series, else the only particle series there (not the
    walls', not sphMesh's)."""
    vtk = os.path.join(case, "VTK")
    own = os.path.join(vtk, os.path.basename(os.path.normpath(case)) + ".vtp.series")
    if os.path.isfile(own):
        return own
    found = sorted(f for f in os.listdir(vtk)
                   if f.endswith(".vtp.series") and not f.endswith("_walls.vtp.series")
                   and f != "sphMesh.vtp.series") \
        if os.path.isdir(vtk) else []
    if len(found) != 1:
        raise RuntimeError("no VTK/<case>.vtp.series (found: %s)" % (found or "none"))
    return os.path.join(vtk, found[0])


def read_vtp(path):
    """Points' y and the fluid particles' fields {y, u, k, eps, nut}."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    pd = data.GetPointData()
    if data.GetPoints() is None or pd.GetArray("type") is None \
            or pd.GetArray("U") is None:
        raise RuntimeError("%s has no points, or no point data U or type" % path)
    x = vtk_to_numpy(data.GetPoints().GetData())
    fluid = vtk_to_numpy(pd.GetArray("type")).ravel() == 0
    out = {"y": x[fluid, 1].astype(float)}
    U = vtk_to_numpy(pd.GetArray("U")).reshape(len(x), -1)
    out["u"] = U[fluid, 0].astype(float)
    for name, key in (("k", "k"), ("epsilon", "eps"), ("nut", "nut")):
        if pd.GetArray(name) is not None:
            out[key] = vtk_to_numpy(pd.GetArray(name)).ravel()[fluid].astype(float)
    return out


def sph_profiles(case, e, dr, average):
    """Row means of the fluid particles over the files of the last
    'average' seconds of the series, folded onto the lower half, and the
    largest distance of a particle from its row's nominal y (the rows
    are dr apart from the lowest, taken at the nearest multiple of dr/2)
    over those files, in dr."""
    series = sph_series(case)
    files = json.load(open(series)).get("files", [])
    if not files:
        raise RuntimeError("%s lists no files" % series)
    tLast = max(float(f["time"]) for f in files)
    chosen = [f for f in files if float(f["time"]) >= tLast - average - 1e-9]
    sums, count, missing = {}, None, set()
    for entry in chosen:
        p = read_vtp(os.path.join(os.path.dirname(series), entry["name"]))
        y = fold(p["y"], e)
        if count is None:
            # The rows k dr from the lowest one, up to the centre
            y0 = 0.5*dr*np.rint(2*y.min()/dr)
            drift = 0.0
            nRows = int(round((e - y0)/dr)) + 1
            count = np.zeros(nRows)
        row = np.clip(np.rint((y - y0)/dr).astype(int), 0, nRows - 1)
        count += np.bincount(row, minlength=nRows)
        drift = max(drift, np.abs(y - y0 - row*dr).max()/dr)
        for key in ("y",) + QUANTITIES:
            if key not in p:
                missing.add(key)
                continue
            sums[key] = sums.get(key, 0) + np.bincount(
                row, weights=y if key == "y" else p[key], minlength=nRows)
    held = count > 0
    out = {key: s[held]/count[held] for key, s in sums.items() if key not in missing}
    if missing:
        print("compare: %s: no point data %s: skipped"
              % (case, ", ".join(sorted(missing))), file=sys.stderr)
    return out, len(chosen), drift


def read_dns():
    """The DNS in the units of eq. (72), and its Re_tau."""
    header = open(dnsFile).readline()
    # The title says "up to Re_tau=590", the data "Re_tau = 587.19": the last
    found = re.findall(r"Re_tau\s*=\s*([0-9]+(?:\.[0-9]+)?)", header)
    reTau = float(found[-1]) if found else 590.0
    lines = [l for l in open(dnsFile) if l.strip() and not l.startswith("#")]
    names = lines[0].strip().split(",")
    values = np.array([[float(v) for v in l.split(",")] for l in lines[1:]])
    data = {name: values[:, i] for i, name in enumerate(names)}
    yp, up = data["y_plus"], data["U_plus"]
    dudy = np.gradient(up, yp)
    with np.errstate(divide="ignore", invalid="ignore"):
        nut = np.where((dudy > 1e-3) & (data["y_over_h"] < 0.9),
                       -data["R_uv"]/dudy/reTau, nan)
    return {"reTau": reTau, "yPlus": yp, "yOverE": data["y_over_h"],
            "u": up, "k": data["k_plus"], "eps": data["eps_plus"]*reTau,
            "nut": nut}
