"""Readers shared by the compare scripts of tutorials/heatTransfer/*.

FV side: the cell values of an OpenFOAM field in an ascii time folder, on
the uniform blockMesh grids of these cases (cells numbered x fastest, then
y), the parameters file of a case, the CPU time of a log (ExecutionTime).

SPH side: the particles of the latest (or a given) time of a case's VTK
series (VTK/<name>.vtp.series and <name>_<index>.vtp, point data T, U,
p_rgh, as sphFoam writes them), their average over the last half of a
run, their Shepard average on a grid (the lock exchange's contours), and
the particles sampled on lines by sphCompare (its set files in
postProcessing/sphCompare/<time>/).
"""
import json
import math
import os
import re
import sys
import warnings

import numpy as np

from foamCaseFiles import read_internal_field, read_log


def time_dirs(case):
    """Time folders of a case, sorted by value, without 0."""
    times = []
    for name in os.listdir(case):
        try:
            value = float(name)
        except ValueError:
            continue
        if value > 0 and os.path.isdir(os.path.join(case, name)):
            times.append((value, name))
    return [name for _, name in sorted(times)]


def latest_time(case):
    """The latest time folder of a case (not 0), or None."""
    times = time_dirs(case) if os.path.isdir(case) else []
    return times[-1] if times else None


def read_parameters(path):
    """The 'key value;' lines of a parameters dictionary as floats where
    they are numbers (entries computed by #eval are left out)."""
    values = {}
    with open(path) as f:
        for line in f:
            m = re.match(r"^(\w+)\s+([-+0-9.eE]+)\s*;", line)
            if m:
                values[m.group(1)] = float(m.group(2))
    return values


def read_field(case, time, name):
    """Cell values of an ascii field of the case's time folder
    (foamCaseFiles.read_internal_field)."""
    return read_internal_field(os.path.join(case, time, name))


def grid_field(values, nx, ny):
    """Cell values of a uniform blockMesh grid as array[j, i] (y, x)."""
    if len(values) != nx * ny:
        raise ValueError("%d cells, expected %d x %d" % (len(values), nx, ny))
    return values.reshape((ny, nx) + values.shape[1:])


def peak(s, f):
    """Maximum of a sampled profile, refined by the parabola through the
    largest sample and its neighbours: (value, position)."""
    k = int(np.argmax(f))
    if 0 < k < len(f) - 1:
        h = s[k + 1] - s[k]
        a = 0.5 * (f[k + 1] - 2 * f[k] + f[k - 1])
        b = 0.5 * (f[k + 1] - f[k - 1])
        if a < 0:
            d = -b / (2 * a)
            return f[k] + b * d + a * d * d, s[k] + d * h
    return f[k], s[k]


def wall_gradient(Tw, T1, T2, h):
    """dT/dn into the fluid at a wall from its value Tw and the cells at
    h/2 and 3h/2 from it: the one-sided second-order difference
    (9 T1 - T2 - 8 Tw)/(3 h) of the parabola through the three values."""
    return (9 * T1 - T2 - 8 * Tw) / (3 * h)


def check_balance(case, nuIn, nuOut, tolerance=1e-3):
    """Warn when the heat flowing in and out through the isothermal walls
    (mean Nu from OpenFOAM's snGrad, the fluxes the solver conserves)
    differ by more than tolerance: the run is then not at steady state,
    whatever its residuals said."""
    imbalance = abs(nuIn - nuOut) / max(abs(nuIn), abs(nuOut))
    if imbalance > tolerance:
        print("Warning: %s is not at steady state: the walls' heat fluxes differ by "
              "%.2g (Nu %.4f against %.4f)" % (case, imbalance, nuIn, nuOut))
    return imbalance


def execution_time(log):
    """The CPU seconds of an OpenFOAM log (its last ExecutionTime, the legs
    of a run continued after a kill added: foamCaseFiles.read_log), or
    nan."""
    return read_log(log)["cpu"]


def iterations(log):
    """The time steps (SIMPLE iterations) of an OpenFOAM log, the legs of a
    run continued after a kill counted (foamCaseFiles.read_log); 0 without
    the log."""
    if not os.path.isfile(log):
        return 0
    return read_log(log)["steps"]


def sph_series(case):
    """(name, [(time, file)]) of the particle series in case/VTK: the
    .vtp.series that is neither the walls nor sphMesh's, or None."""
    folder = os.path.join(case, "VTK")
    if not os.path.isdir(folder):
        return None
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".vtp.series"):
            continue
        stem = name[:-len(".vtp.series")]
        if stem.endswith("_walls") or stem.startswith("sphMesh"):
            continue
        with open(os.path.join(folder, name)) as f:
            series = json.load(f)
        files = [(float(e["time"]), os.path.join(folder, e["name"]))
                 for e in series["files"]]
        return stem, sorted(files)
    return None


def read_particles(path, fields=("T", "U")):
    """Points (n, 3) and {field: values} of a particle .vtp file; fields
    missing from the file are left out. Only fluid particles when the file
    has a 'type' array (0 = fluid)."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    points = vtk_to_numpy(data.GetPoints().GetData())
    point_data = data.GetPointData()
    values = {}
    for name in fields + ("type",):
        array = point_data.GetArray(name)
        if array is not None:
            values[name] = vtk_to_numpy(array)
    if "type" in values:
        fluid = values.pop("type") == 0
        points = points[fluid]
        values = {k: v[fluid] for k, v in values.items()}
    return points, values


def sph_at_time(case, time=None):
    """Particles of an SPH case at the latest time (or the nearest to
    time): (time, points, values), or None when there is no series."""
    found = sph_series(case)
    if not found or not found[1]:
        return None
    files = found[1]
    if time is None:
        t, path = files[-1]
    else:
        t, path = min(files, key=lambda e: abs(e[0] - time))
    points, values = read_particles(path, ("T", "U", "p_rgh"))
    return t, points, values


def sph_time_average(case, result_of, last=0.5, fields=("T",)):
    """The average of result_of(t, points, values) (a dict, or None to
    leave that time out) over the written times of an SPH case in the last
    fraction of its run, or None; values holds the particle fields named
    (those the file has).
    A particle flow at steady state still moves its particles past the
    sampling lines, so one snapshot's profiles and maxima scatter by a few
    per cent at 16^2; their average over the last half does not. Floats
    and arrays are averaged (nan-aware); other entries (n, cells: ints)
    are the latest's; 'time' is the latest time used, 'averaged' says
    over what."""
    found = sph_series(case)
    if not found:
        return None
    files = [e for e in found[1] if e[0] > 0]
    if not files:
        return None
    tLast = files[-1][0]
    files = [e for e in files if e[0] >= (1 - last) * tLast]
    runs, used = [], []
    for t, path in files:
        points, values = read_particles(path, fields)
        run = result_of(t, points, values)
        if run is not None:
            runs.append(run)
            used.append(t)
    if not runs:
        return None
    out = dict(runs[-1])
    for key, value in runs[-1].items():
        if isinstance(value, (float, np.floating, np.ndarray)):
            stack = np.array([r[key] for r in runs], dtype=float)
            with warnings.catch_warnings():     # all-nan columns stay nan
                warnings.simplefilter("ignore", RuntimeWarning)
                out[key] = np.nanmean(stack, axis=0)
    out.update(time=used[-1], averaged=(len(runs), used[0], used[-1]))
    return out


def _weighted_neighbours(points, samples, radius):
    """For each sample point (m, 2) with a particle within radius: its
    index k, the particles' indices near it, their offsets from it and
    their Wendland C2 weights (support radius). The particles are binned
    in squares of side radius (numpy only)."""
    xy = points[:, :2]
    origin = xy.min(axis=0)
    keys = np.floor((xy - origin) / radius).astype(int)
    bins = {}
    for index, key in enumerate(map(tuple, keys)):
        bins.setdefault(key, []).append(index)
    for k, sample in enumerate(np.asarray(samples, dtype=float)):
        ci, cj = np.floor((sample - origin) / radius).astype(int)
        near = [i for di in (-1, 0, 1) for dj in (-1, 0, 1)
                for i in bins.get((ci + di, cj + dj), ())]
        if not near:
            continue
        r = xy[near] - sample
        q = np.linalg.norm(r, axis=1) / radius
        w = np.where(q < 1, (1 - q) ** 4 * (1 + 4 * q), 0.0)
        if w.sum() > 0:
            yield k, near, r, w


def shepard(points, values, samples, radius):
    """Shepard average (Wendland C2 weights, support radius) of particle
    values at sample points (m, 2); nan where no particle is near."""
    out = np.full((len(samples),) + values.shape[1:], np.nan)
    for k, near, _, w in _weighted_neighbours(points, samples, radius):
        out[k] = np.tensordot(w, values[near], axes=1) / w.sum()
    return out


def sphcompare_folders(case):
    """[(time, folder)] of postProcessing/sphCompare/<time>/ in a case, in
    time order (sphCompare -time writes one per selected time)."""
    base = os.path.join(case, "postProcessing", "sphCompare")
    out = []
    for name in os.listdir(base) if os.path.isdir(base) else []:
        try:
            out.append((float(name), os.path.join(base, name)))
        except ValueError:
            pass
    return sorted(out)


def read_sphcompare_set(folder, name):
    """A set file <name>.dat of sphCompare as {column: array}, 'nan' where a
    source has no value (columns distance x y weight <component>_<source>)."""
    columns, rows = None, []
    with open(os.path.join(folder, name + ".dat")) as f:
        for line in f:
            if line.startswith("# distance"):
                columns = line[1:].split()
            elif line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    data = np.array(rows, dtype=float).reshape(len(rows), len(columns))
    return {c: data[:, i] for i, c in enumerate(columns)}


def centreline_profiles(folders, time, scaleU):
    """The SPH profiles at one written time from sphCompare's sets
    'vertical' (x = L/2) and 'horizontal' (y = L/2) of the heated
    cavities' sph/system/sphCompareDict, folders being
    sphcompare_folders(case): (s, u, Tv, v, Th), s the position along
    either line (the two sets share it), the velocities times scaleU; None
    when sphCompare has no folder at that time."""
    for t, folder in folders:
        if abs(t - time) <= 1e-6 * max(1.0, abs(time)):
            vert = read_sphcompare_set(folder, "vertical")
            horiz = read_sphcompare_set(folder, "horizontal")
            if not np.allclose(vert["y"], horiz["x"]):
                sys.exit("compare: %s: the sets vertical and horizontal of"
                         " sphCompareDict must have the same points along"
                         " their lines" % folder)
            return (vert["y"], vert["Ux_sph"] * scaleU, vert["T_sph"],
                    horiz["Uy_sph"] * scaleU, horiz["T_sph"])
    return None


def warn_missing_profiles(case, times):
    """Say on stderr which written times of an SPH run have no sphCompare
    output (their profiles left out of the average)."""
    if times:
        print("compare: %s: no sphCompare output at t = %s: left out (Allrun"
              " runs 'sphCompare -time <half>:' after the run; purgeWrite may"
              " have removed those times' particles)"
              % (case, ", ".join("%g" % t for t in times)), file=sys.stderr)


def spacing(points, area):
    """Mean particle spacing of particles filling an area."""
    return math.sqrt(area / max(len(points), 1))
