#!/usr/bin/python3
"""Allreport's page: report/index.html (static) and report/summary.md from
the errors.csv files of the validation tutorials (errorTable.py), the
tutorials' own pictures, the stability map and the speed benchmarks.

    sphReport.py -out DIR -runs RUNS.tsv [-project DIR] [-title T] [-quick]

RUNS.tsv (written by Allreport), one line per tutorial run or reused:
    case  folder  action  seconds  cpuSeconds  command  log
(case: the report's section, e.g. hydrostaticTank for the three still
tanks; folder: where its errors.csv and pictures are; action: ran, reused,
failed or missing). Writes DIR/<case>.png, DIR/pictures/..., DIR/index.html,
DIR/summary.md and DIR/errors.csv (every row, one table).
"""
import argparse
import csv
import os
import re
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import errorTable       # noqa: E402
import reportFigures    # noqa: E402
import reportPage       # noqa: E402
from reportPage import slug  # noqa: E402

SKIP_DIRS = {"VTK", "postProcessing", "constant", "system", "0", "0.orig",
             "lagrangian", "polyMesh", "sphMesh"}
MAX_PICTURES = 8


def walk(folder, quick):
    """(errors.csv paths, PNG paths) under folder, leaving out the case
    internals (time folders, VTK, postProcessing ...) and, for the full
    report, the quick form's runs/test (a user's Allrun -test: its coarse,
    short runs are not the case's results)."""
    tables, pictures = [], []
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS
                         and not d.startswith("processor")
                         and not re.fullmatch(r"[0-9.e+-]+", d)
                         and (quick or not (d == "test" and os.path.basename(root) == "runs")))
        tables += [os.path.join(root, f) for f in files if f == errorTable.FILE_NAME]
        pictures += sorted(os.path.join(root, f) for f in files if f.endswith(".png"))
    return tables, pictures


def read_runs(path):
    with open(path, newline="") as f:
        return [dict(zip(("case", "folder", "action", "seconds", "cpuSeconds", "command",
                          "log"), row))
                for row in csv.reader(f, delimiter="\t") if row and not row[0].startswith("#")]


class Section:
    """One case of the report: its runs, rows, pictures and problems."""

    def __init__(self, case):
        self.case, self.runs, self.rows, self.pictures, self.problems = case, [], [], [], []
        self.png = None

    def add_run(self, run, quick):
        self.runs.append(run)
        if not os.path.isdir(run["folder"]):
            self.problems.append("%s: no such folder" % run["folder"])
            return
        tables, pictures = walk(run["folder"], quick)
        for t in tables:
            try:
                rows = errorTable.read_errors(t)
            except (ValueError, OSError) as err:
                self.problems.append(str(err))
                continue
            self.rows += [r for r in rows if r["case"] == self.case or not r["case"]]
        self.pictures += pictures
        if not tables:
            self.problems.append("no errors.csv under %s (%s)" % (run["folder"], run["action"]))


def copy_pictures(section, out):
    """The tutorial's own pictures, copied beside the page (at most
    MAX_PICTURES, newest first): the page must not point into runs that
    a later Allrun rewrites."""
    folder = os.path.join(out, "pictures", slug(section.case))
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    chosen = sorted(section.pictures, key=os.path.getmtime, reverse=True)[:MAX_PICTURES]
    copied = []
    for n, p in enumerate(sorted(chosen)):
        name = "%02d_%s" % (n, os.path.basename(p))
        shutil.copy(p, os.path.join(folder, name))
        copied.append((os.path.relpath(os.path.join(folder, name), out), os.path.basename(p)))
    return copied


def read_stability(project):
    folder = os.path.join(project, "tutorials", "stability", "results")
    md = os.path.join(folder, "stability.md")
    rows = []
    path = os.path.join(folder, "stability.csv")
    if os.path.isfile(path):
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    return (open(md).read() if os.path.isfile(md) else None), rows


def read_benchmarks(project):
    folder = os.path.join(project, "benchmarks", "results")
    if not os.path.isdir(folder):
        return []
    return [(name, open(os.path.join(folder, name), errors="replace").read())
            for name in sorted(os.listdir(folder))
            if name.endswith((".dat", ".txt")) and os.path.isfile(os.path.join(folder, name))]


def write_all_rows(sections, out):
    rows = [r for s in sections for r in s.rows]
    if rows:
        path = os.path.join(out, errorTable.FILE_NAME)
        if os.path.exists(path):
            os.remove(path)
        errorTable.write_errors(out, rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-out", required=True)
    ap.add_argument("-runs", required=True)
    ap.add_argument("-project", default=os.path.join(here, "..", "..", ".."))
    ap.add_argument("-title", default="sphFoam validation report")
    ap.add_argument("-note", default="")
    ap.add_argument("-quick", action="store_true",
                    help="the runs are Allreport -quick's: their runs/test counts")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    reportPage.PROJECT[0] = os.path.abspath(a.project)
    sections = {}
    for run in read_runs(a.runs):
        sections.setdefault(run["case"], Section(run["case"])).add_run(run, a.quick)
    for s in sections.values():
        if s.rows:
            s.png = slug(s.case) + ".png"
            s.drawn = reportFigures.plot_case(s.case, s.rows, os.path.join(a.out, s.png))
        s.copied = copy_pictures(s, a.out)
        s.orders = reportFigures.orders(s.rows)
    ordered = list(sections.values())
    write_all_rows(ordered, a.out)
    stabilityMd, stabilityRows = read_stability(a.project)
    benchmarks = read_benchmarks(a.project)
    reportPage.write_html(a, ordered, stabilityRows, benchmarks)
    reportPage.write_markdown(a, ordered, stabilityMd, benchmarks)
    print("Wrote %s/index.html and %s/summary.md: %d cases, %d rows"
          % (a.out, a.out, len(ordered), sum(len(s.rows) for s in ordered)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
