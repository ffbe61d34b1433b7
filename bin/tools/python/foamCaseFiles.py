"""Readers of what an OpenFOAM or sphFoam case writes, shared by the
tutorials' compare scripts: the numeric entries of a parameter
dictionary, the run summary of a solver log, the time directories, the
cell values of an ascii field, a function object's file over restarts.

A compare script finds this folder through FOAM_SPHFOAM_TOOLS (set by
etc/bashrc) or, run from the project's own tutorials, by its path:

    sys.path.insert(0, os.path.join(os.environ.get("FOAM_SPHFOAM_TOOLS",
        os.path.join(here, "..", "..", "..", "bin", "tools")), "python"))
"""
import os
import re

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


def read_log(path):
    """{cpu, clock, t, steps, end} of a solver log: the last
    ExecutionTime/ClockTime, the last 'Time =', the number of steps (an SPH
    solver's 'Steps N' summary, the step a failure names, else the count
    of 'Time =' lines) and whether it reached 'End'; NaN where missing."""
    out = {"cpu": nan, "clock": nan, "t": nan, "steps": 0, "end": False}
    if not os.path.isfile(path):
        return out
    timing = re.compile(r"^ExecutionTime = (\S+) s\s+ClockTime = (\S+) s")
    steps = re.compile(r"^Steps (\d+),")
    failedAt = re.compile(r"\(time step (\d+), deltaT")
    with open(path, errors="replace") as f:
        for line in f:
            m = timing.match(line)
            if m:
                out["cpu"], out["clock"] = float(m.group(1)), float(m.group(2))
            elif line.startswith("Time = "):
                out["steps"] += 1
                try:
                    out["t"] = float(line.split()[2])
                except (IndexError, ValueError):
                    pass
            elif steps.match(line):
                out["sphSteps"] = int(steps.match(line).group(1))
            elif failedAt.search(line):
                out["sphSteps"] = int(failedAt.search(line).group(1))
            elif line.startswith("End"):
                out["end"] = True
    if "sphSteps" in out:
        out["steps"] = out.pop("sphSteps")
    return out


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
    and its data lines, as text. A restart writes a new start-time folder,
    whose lines replace the earlier ones from its first time on. A run made
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
            first = float(later[0].split()[0])
            lines = [l for l in lines if float(l.split()[0]) < first] + later
    return header, lines


def read_internal_field(path):
    """Cell values of an ascii volScalarField (n,) or volVectorField (n, 3);
    a uniform internalField is returned as one value."""
    import numpy as np
    with open(path) as f:
        text = f.read()
    m = re.search(r"internalField\s+uniform\s+([^;]+);", text)
    if m:
        return np.array(m.group(1).strip("() ").split(), dtype=float)
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", text)
    if not m:
        raise ValueError("%s: no ascii internalField (writeFormat ascii?)" % path)
    count = int(m.group(2))
    body = text[m.end():]
    if m.group(1) == "scalar":
        return np.array(body.split(None, count)[:count], dtype=float)
    numbers = re.findall(r"\(([^()]*)\)", body[:count * 80 + 100])[:count]
    return np.array([v.split() for v in numbers], dtype=float)
