"""Readers of what an OpenFOAM or sphFoam case writes, shared by the
tutorials' compare scripts: the numeric entries of a parameter
dictionary (or all its entries, $references resolved), the application,
the run summary of a solver log, the time directories, the cell values of
a volField and the values of an IOField (ascii or binary), a function
object's file over restarts.

A compare script finds this folder through FOAM_SPHFOAM_TOOLS (set by
etc/bashrc) or, run from the project's own tutorials, by its path:

    sys.path.insert(0, os.path.join(os.environ.get("FOAM_SPHFOAM_TOOLS",
        os.path.join(here, "..", "..", "..", "bin", "tools")), "python"))
"""
import os
import re
import sys

nan = float("nan")


def strip_comments(text):
    """The text without its C and C++ comments."""
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def read_numeric_entries(path, required=()):
    """The numeric 'key value;' entries of a dictionary outside its
    FoamFile header; each key of required must be there."""
    text = re.sub(r"FoamFile\s*\{[^}]*\}", "", strip_comments(open(path).read()))
    values = {}
    for key, value in re.findall(r"^\s*(\w+)\s+([^;{}$#]+?)\s*;", text, flags=re.M):
        try:
            values[key] = float(value)
        except ValueError:
            pass
    for key in required:
        if key not in values:
            raise RuntimeError("%s: no numeric entry '%s'" % (path, key))
    return values


def read_log(path, until=None):
    """{cpu, clock, t, steps, summary, end, start} of a solver log: the last
    ExecutionTime/ClockTime, the last 'Time =', the number of steps (an SPH
    solver's 'Steps N' summary, the step a failure names, else the count
    of 'Time =' lines; summary says which), whether it reached 'End', and
    the time it started
    from (an SPH solver's 'Restarting from ".../<time>/lagrangian/...', else
    0; of an OpenFOAM solver, whose log does not say, the written time
    before its first step when a killed leg's log is kept beside it);
    NaN where missing. A log that restarts adds the legs before it
    (add_earlier_legs) when their logs were kept beside it as
    log.<app>.unfinished[N] (Allreport keeps a killed run's log so), and
    says on stderr when it cannot: its seconds and steps are then from the
    restart. With until: only the log up to that time (the steps are then
    None: an SPH solver logs every logInterval steps)."""
    out = {"cpu": nan, "clock": nan, "t": nan, "steps": 0, "end": False, "start": 0.0}
    if not os.path.isfile(path):
        return out
    timing = re.compile(r"^ExecutionTime = (\S+) s\s+ClockTime = (\S+) s")
    steps = re.compile(r"^Steps (\d+),")
    failedAt = re.compile(r"\(time step (\d+), deltaT")
    restart = re.compile(r'^Restarting from ".*/([-+.0-9eE]+)/lagrangian/')
    first = None
    with open(path, errors="replace") as f:
        for line in f:
            m = timing.match(line)
            if m:
                out["cpu"], out["clock"] = float(m.group(1)), float(m.group(2))
            elif line.startswith("Time = "):
                try:
                    t = float(line.split()[2])
                except (IndexError, ValueError):
                    t = out["t"]
                if until is not None and t > until*(1 + 1e-9) + 1e-12:
                    out["steps"] = None
                    out.pop("sphSteps", None)
                    break
                out["steps"] += 1
                out["t"] = t
                first = t if first is None else first
            elif m := steps.match(line):
                out["sphSteps"] = int(m.group(1))
            elif m := failedAt.search(line):
                out["sphSteps"] = int(m.group(1))
            elif line.startswith("End"):
                out["end"] = True
            elif m := restart.match(line):
                out["start"] = float(m.group(1))
    # summary: the steps are the SPH solver's own count, not 'Time =' lines
    out["summary"] = "sphSteps" in out
    if out["summary"]:
        out["steps"] = out.pop("sphSteps")
    if out["start"] == 0 and (first is not None or out["end"]) and kept_logs(path):
        # An OpenFOAM solver says nothing of where it started: the written
        # time before its first step, when a killed leg's log is kept (a
        # leg that ended without a step started at the latest written time;
        # one killed before its first step says nothing)
        folder = os.path.dirname(path) or "."
        before = [float(n) for n in time_dirs(folder)
                  if first is None or float(n) < first*(1 - 1e-9)]
        out["start"] = max(before, default=0.0)
    if out["start"] > 0:
        if out["t"] != out["t"]:
            out["t"] = out["start"]         # no step taken: still there
        add_earlier_legs(path, out)
    return out


def kept_logs(path):
    """The killed legs' logs kept beside a log (<log>.unfinished[N], as
    Allreport keeps them) older than it, newest first."""
    base = re.sub(r"\.unfinished\d*$", "", path)
    folder = os.path.dirname(path) or "."
    mtime = os.path.getmtime(path)
    kept = [os.path.join(folder, f) for f in os.listdir(folder)
            if re.fullmatch(re.escape(os.path.basename(base)) + r"\.unfinished\d*", f)]
    return sorted((k for k in kept if os.path.getmtime(k) < mtime),
                  key=os.path.getmtime, reverse=True)


def add_earlier_legs(path, out):
    """Adds to out (read_log's summary of a log that restarts at
    out["start"]) the seconds of the legs before it, from the kept logs
    beside it (<log>.unfinished[N], older than it) that reached the
    restart time: each up to that time, and its own earlier legs. The
    steps become the restart time's index (uniform/time) plus the log's
    own. Without such a log it says on stderr that its figures are from
    the restart."""
    folder = os.path.dirname(path) or "."
    leg, before = earlier_leg(path, out["start"])
    if leg:
        # A leg that started at its end time (killed after its last
        # write, before End) takes no step and prints no seconds
        for key in ("cpu", "clock"):
            if out[key] != out[key] and out["end"]:
                out[key] = 0.0
            out[key] += before[key]
        index = read_time_index(folder, out["start"])
        if index is not None and out["steps"] is not None:
            out["steps"] += index
        out["legs"] = 1 + before.get("legs", 1)
        return
    print("%s: restarts at t = %g s: its CPU and clock seconds and steps are"
          " from there (no kept log of the run before it)" % (path, out["start"]),
          file=sys.stderr)


def earlier_leg(path, start):
    """The kept log (<log>.unfinished[N] beside path, older than it) of the
    leg a run restarting at start came from, and read_log's summary of it
    up to start (with its own earlier legs): the newest that reached start
    (went past it, steps None, or stopped on it) and timed a step; (None,
    None) without one."""
    for leg in kept_logs(path):
        before = read_log(leg, until=start)
        reached = before["steps"] is None or before["t"] >= start*(1 - 1e-9)
        if before["start"] < start and reached and before["cpu"] == before["cpu"]:
            return leg, before
    return None, None


def read_time_index(case, t):
    """The time index (steps from the start) of the written time t of a
    case, from its uniform/time; None without one."""
    for name in time_dirs(case):
        if abs(float(name) - t) <= 1e-9*max(abs(t), 1e-300):
            f = os.path.join(case, name, "uniform", "time")
            if os.path.isfile(f):
                m = re.search(r"^index\s+(\d+)\s*;", open(f).read(), flags=re.M)
                if m:
                    return int(m.group(1))
    return None


def time_dirs(path):
    """The time directories of a case, in time order."""
    names = []
    for name in os.listdir(path) if os.path.isdir(path) else []:
        try:
            names.append((float(name), name))
        except ValueError:
            pass
    return [name for _, name in sorted(names)]


def read_function_object(folder, name):
    """A function object's file postProcessing/<object>/<start>/<name> over
    all its start-time folders (folder is postProcessing/<object>): the
    column names of its last '# Time ...' header line (None without one)
    and its data lines, as text, in time order. A restart writes a new
    start-time folder, whose lines replace the earlier ones between its
    first and last times (a restart from an earlier time that stopped
    short leaves the first run's lines after it). A run made
    again in the same folder writes <stem>_<time><ext> beside the first
    run's file (OpenFOAM's habit): the newest of them is read."""
    stem, ext = os.path.splitext(name)
    variant = re.compile(re.escape(stem) + r"(_.+)?" + re.escape(ext))
    header, lines = None, []
    for start in time_dirs(folder):
        d = os.path.join(folder, start)
        found = [os.path.join(d, f) for f in os.listdir(d) if variant.fullmatch(f)]
        if not found:
            continue
        later = []
        for line in open(max(found, key=os.path.getmtime)):
            if line.startswith("#"):
                fields = line[1:].split()
                if fields and fields[0] == "Time":
                    header = fields
            elif line.strip():
                later.append(line)
        if later:
            first, last = (float(later[k].split()[0]) for k in (0, -1))
            kept = [l for l in lines if not first <= float(l.split()[0]) <= last]
            lines = sorted(kept + later, key=lambda l: float(l.split()[0]))
    return header, lines


def _header(data):
    """(FoamFile entries, offset just past the FoamFile block) of the bytes
    of an OpenFOAM file."""
    m = re.search(rb"FoamFile\s*\{([^}]*)\}", data)
    if not m:
        raise RuntimeError("no FoamFile header")
    entries = re.findall(rb"(\w+)\s+(\"[^\"]*\"|[^;]*);", m.group(1))
    return {k.decode(): v.decode().strip().strip('"') for k, v in entries}, m.end()


def _is_binary(header, path):
    binary = header.get("format", "ascii") == "binary"
    if binary and "scalar=64" not in header.get("arch", "scalar=64"):
        raise RuntimeError("%s: only 64-bit binary scalars are read (arch %s)"
                           % (path, header.get("arch")))
    return binary


def _skip(data, pos):
    """pos past white space and comments."""
    space = re.compile(rb"\s*(//[^\n]*\n|/\*.*?\*/)?", re.S)
    while True:
        m = space.match(data, pos)
        if m.end() == pos:
            return pos
        pos = m.end()


def _numbers(chunk):
    return [float(v) for v in
            re.findall(rb"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", chunk)]


def _read_list(data, pos, nComp, binary, what):
    """A list of nComp-component items (1: scalars or labels) at data[pos]:
    'N(...)' or 'N{v}', ascii or binary. Returns (array, position after)."""
    import numpy as np
    pos = _skip(data, pos)
    m = re.compile(rb"(\d+)\s*").match(data, pos)
    if not m:
        raise RuntimeError("%s: expected a list size at byte %d" % (what, pos))
    size, pos = int(m.group(1)), m.end()
    if data[pos:pos + 1] == b"{":
        end = data.index(b"}", pos)
        item = np.array(_numbers(data[pos + 1:end]), float)
        values = np.tile(item[:nComp], (size, 1))
        return (values if nComp > 1 else values[:, 0]), end + 1
    if data[pos:pos + 1] != b"(":
        raise RuntimeError("%s: expected '(' after the size %d" % (what, size))
    pos += 1
    if binary:
        nBytes = 8*nComp*size
        values = np.frombuffer(data[pos:pos + nBytes], dtype="<f8")
        if values.size != nComp*size or data[pos + nBytes:pos + nBytes + 1] != b")":
            raise RuntimeError("%s: binary list of %d items is cut short" % (what, size))
        return (values.reshape(size, nComp) if nComp > 1 else values.copy()), \
            pos + nBytes + 1
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
    return (values.reshape(size, nComp) if nComp > 1 else values), end


def _components(text):
    """Components of an OpenFOAM type name: scalar 1, vector 3, ..."""
    for name, n in (("scalar", 1), ("label", 1), ("vector2D", 2), ("vector", 3),
                    ("symmTensor", 6), ("tensor", 9)):
        if name in text:
            return n
    return None


def read_iofield(path, nComp):
    """An IOField (the particle files: constant/sphMesh/fluid/positions,
    <time>/lagrangian/sph/U, ...), ascii or binary with 64-bit scalars:
    (n,) for nComp 1, else (n, nComp)."""
    data = open(path, "rb").read()
    header, pos = _header(data)
    values, _ = _read_list(data, pos, nComp, _is_binary(header, path), path)
    return values


def read_internal_field(path, nComp=None):
    """Cell values of a volField, ascii or binary: (n,) for a scalar field,
    (n, nComp) otherwise, nComp from List<type> or the class when not
    given; a uniform internalField is returned as its one value."""
    import numpy as np
    data = open(path, "rb").read()
    header, pos = _header(data)
    m = re.compile(rb"internalField\s+(uniform|nonuniform)\s*").search(data, pos)
    if not m:
        raise RuntimeError("%s: no internalField" % path)
    pos = m.end()
    if m.group(1) == b"uniform":
        return np.array(_numbers(data[pos:data.index(b";", pos)]), float)
    m = re.compile(rb"List<(\w+)>\s*").match(data, pos)
    if m:
        pos = m.end()
    nComp = nComp or _components(m.group(1).decode() if m else header.get("class", ""))
    if not nComp:
        raise RuntimeError("%s: the field's type is not known (class %s)"
                           % (path, header.get("class")))
    values, _ = _read_list(data, pos, nComp, _is_binary(header, path), path)
    return values


def application(case):
    """The application named in <case>/system/controlDict, or None."""
    path = os.path.join(case, "system", "controlDict")
    if not os.path.isfile(path):
        return None
    m = re.search(r"^\s*application\s+(\w+)\s*;",
                  strip_comments(open(path).read()), flags=re.M)
    return m.group(1) if m else None


def read_entries(path):
    """The plain 'key value;' entries of a dictionary outside its FoamFile
    header, as strings, $name references to other entries resolved."""
    text = re.sub(r"FoamFile\s*\{[^}]*\}", "", strip_comments(open(path).read()))
    raw = dict(re.findall(r"^\s*(\w+)\s+([^;{}]+?)\s*;", text, flags=re.M))
    values = {}
    for key, value in raw.items():
        seen = set()
        while value.startswith("$") and value[1:] in raw and value not in seen:
            seen.add(value)
            value = raw[value[1:]]
        values[key] = value
    return values
