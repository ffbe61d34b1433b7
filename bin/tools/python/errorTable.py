"""errors.csv, the one file of errors and run times that every validation
tutorial writes and Allreport reads (bin/tools/report): a case joins the
report by writing it in its results folder (or its run folder).

Columns, one row per run and error measure:

    case         the tutorial, as the report names its section (cavity,
                 damBreak/zhou, ...)
    method       FV, ISPH-USAW, WCSPH (dummy + repulsive walls) or
                 WCSPH-USAW; a variant adds to the name (ISPH-USAW implicit)
    resolution   what the case calls its resolution (n, H/dr, dr, N)
    particles    fluid particles, or cells for FV
    measure      the error's name (L2 u eq. (66), pressure RMS, ...)
    value        the error
    reference    what it is measured against (analytic, experiment, DNS,
                 OpenFOAM ...)
    wallSeconds  wall-clock seconds of the solver (NaN when unknown)
    cpuSeconds   CPU seconds of the solver

A compare script finds this folder as for foamCaseFiles.py and calls

    errorTable.write_errors(folder, [errorTable.row(...), ...])

which merges its rows into folder/errors.csv: a row replaces the one with
the same case, method, resolution, measure and reference, so compare
scripts run once per resolution build the table up.
"""
import csv
import math
import os

import foamCaseFiles

COLUMNS = ("case", "method", "resolution", "particles", "measure", "value",
           "reference", "wallSeconds", "cpuSeconds")
KEY = ("case", "method", "resolution", "measure", "reference")
FILE_NAME = "errors.csv"


def number(value):
    """A float of value; NaN for None, '' or anything not a number."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return float("nan")


def row(case, method, resolution, particles, measure, value, reference,
        wallSeconds=None, cpuSeconds=None):
    """One row of errors.csv; run times of None are NaN."""
    return dict(case=case, method=method, resolution=resolution,
                particles=int(particles) if particles else 0,
                measure=measure, value=number(value), reference=reference,
                wallSeconds=number(wallSeconds), cpuSeconds=number(cpuSeconds))


def log_seconds(log):
    """(wall, cpu) seconds: the last ExecutionTime/ClockTime of a solver log."""
    summary = foamCaseFiles.read_log(log)
    return summary["clock"], summary["cpu"]


def particle_count(case):
    """The fluid particles of an SPH case: the size of the list in
    constant/sphMesh/fluid/positions (0 when there is none)."""
    path = os.path.join(case, "constant", "sphMesh", "fluid", "positions")
    if not os.path.isfile(path):
        return 0
    with open(path, "rb") as f:
        text = f.read(8192).decode("latin-1")
    body = text.split("}", 1)[-1] if "FoamFile" in text else text
    for line in body.splitlines():
        line = line.strip()
        if line.startswith("//"):
            continue
        digits = line.split("(")[0].strip()
        if digits.isdigit():
            return int(digits)
    return 0


def run_times(rows):
    """(cpu, wall, runs, untimed): the solver seconds of the runs behind
    rows, each run once. A run gives one row per error measure and
    reference, so the rows of one run are those with the same case, method,
    resolution, particles and times (a case of several Rayleigh numbers has
    one run per number at each resolution: their times differ). runs counts
    the runs, untimed those with no CPU time (NaN), which the sums leave out."""
    runs = {}
    for r in rows:
        key = (r["case"], r["method"], r["resolution"], r["particles"],
               _format(number(r["cpuSeconds"])), _format(number(r["wallSeconds"])))
        runs[key] = (number(r["cpuSeconds"]), number(r["wallSeconds"]))
    cpu = sum(c for c, _ in runs.values() if math.isfinite(c))
    wall = sum(w for c, w in runs.values() if math.isfinite(c) and math.isfinite(w))
    untimed = sum(1 for c, _ in runs.values() if not math.isfinite(c))
    return cpu, wall, len(runs), untimed


def _format(value):
    if isinstance(value, float):
        return "nan" if math.isnan(value) else "%.6g" % value
    return str(value)


def write_errors(folder, rows):
    """Merge rows into folder/errors.csv (see the module's description)."""
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, FILE_NAME)
    new = [dict(r) for r in rows]
    for r in new:
        missing = [c for c in COLUMNS if c not in r]
        if missing:
            raise ValueError("errorTable: a row for %s lacks %s" % (path, missing))
    keys = {tuple(str(r[k]) for k in KEY) for r in new}
    kept = [r for r in read_errors(path) if tuple(str(r[k]) for k in KEY) not in keys] \
        if os.path.isfile(path) else []
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for r in kept + new:
            w.writerow([_format(r[c]) for c in COLUMNS])
    os.replace(path + ".tmp", path)
    return path


def read_errors(path):
    """The rows of an errors.csv, the numbers as floats; a bad file is an
    error naming the file, the line and what is wrong."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if header is None or tuple(h.strip() for h in header) != COLUMNS:
            raise ValueError("%s: line 1: the header must be %s, not %s"
                             % (path, ",".join(COLUMNS), header))
        rows = []
        for n, fields in enumerate(reader, start=2):
            if not fields:
                continue
            if len(fields) != len(COLUMNS):
                raise ValueError("%s: line %d: %d fields, expected %d"
                                 % (path, n, len(fields), len(COLUMNS)))
            r = dict(zip(COLUMNS, (v.strip() for v in fields)))
            for c in ("value", "wallSeconds", "cpuSeconds", "particles"):
                try:
                    r[c] = float(r[c])
                except ValueError:
                    raise ValueError("%s: line %d: %s '%s' is not a number"
                                     % (path, n, c, r[c]))
            r["particles"] = int(r["particles"]) if math.isfinite(r["particles"]) else 0
            rows.append(r)
    return rows
