"""The two renderings of Allreport's report (sphReport.py gathers the
sections): index.html, a static page that needs no server, and summary.md.
"""
import datetime
import html
import os
import re

import errorTable
import reportFigures

PROJECT = ["."]     # the project folder: the page names folders relative to it

CSS = """
body { font-family: sans-serif; max-width: 1250px; margin: 1em auto; padding: 0 1em;
       color: #222; line-height: 1.4; }
h1 { border-bottom: 2px solid #555; } h2 { margin-top: 2em; border-bottom: 1px solid #aaa; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.85em; }
th, td { border: 1px solid #bbb; padding: 2px 6px; text-align: left; vertical-align: top; }
th { background: #eee; } td.num { text-align: right; font-family: monospace; }
img.figure { max-width: 100%; border: 1px solid #ccc; }
.pictures { display: flex; flex-wrap: wrap; gap: 8px; }
.pictures figure { margin: 0; width: 300px; font-size: 0.75em; }
.pictures img { width: 300px; border: 1px solid #ccc; }
.problem { background: #fff3cd; border: 1px solid #e0c060; padding: 4px 8px; }
pre { background: #f6f6f6; padding: 6px; overflow-x: auto; font-size: 0.8em; }
nav ul { columns: 3; }
"""

HOW_TO_BENCHMARK = ("No benchmark results yet. Run them (minutes each, on an idle machine): "
                    "`benchmarks/Allrun` (Google Benchmark programs, results/<name>.json "
                    "and .txt), `benchmarks/isphCavity` (isphFoam s/step, pressure "
                    "iterations, split of a step), `benchmarks/wcsphDamBreak` (wcsphFoam "
                    "particle-steps/s), `benchmarks/againstBuild -other DIR` (this build "
                    "against another); they write benchmarks/results/, which the next "
                    "./Allreport includes.")
HOW_TO_STABILITY = ("Not written yet: tutorials/stability/Allrun writes "
                    "tutorials/stability/results/stability.md and stability.csv, which "
                    "the next ./Allreport includes.")


def slug(case):
    return re.sub(r"[^A-Za-z0-9]+", "_", case).strip("_")


def fmt(v):
    if isinstance(v, float):
        return "-" if v != v else "%.3g" % v
    return str(v)


def table_rows(section):
    """The rows of a case's error table, sorted by measure, method, particles."""
    return sorted(section.rows, key=lambda r: (r["measure"], r["method"], r["particles"]))


def e(text):
    return html.escape(str(text))


def prose(text):
    """Escaped text with its `commands` as <code>."""
    return re.sub(r"`([^`]*)`", r"<code>\1</code>", e(text))


def html_table(header, rows, numeric=()):
    out = ["<table><tr>" + "".join("<th>%s</th>" % e(h) for h in header) + "</tr>"]
    for row in rows:
        out.append("<tr>" + "".join(
            '<td class="num">%s</td>' % e(v) if i in numeric else "<td>%s</td>" % e(v)
            for i, v in enumerate(row)) + "</tr>")
    return "\n".join(out + ["</table>"])


def runs_rows(sections):
    return [(s.case, r["action"], r["seconds"], r["cpuSeconds"],
             os.path.relpath(r["folder"], PROJECT[0]), r["command"])
            for s in sections for r in s.runs]


def cost_sentence(rows, what):
    """What the runs behind rows cost: their solvers' own seconds, read from
    the errors.csv rows (the report may have reused them, so its own time
    says nothing of theirs)."""
    cpu, wall, runs, untimed = errorTable.run_times(rows)
    if not runs:
        return ""
    text = "%s %d run%s: %.0f s of solver CPU (%.1f h), %.0f s of wall clock" % (
        what, runs, "" if runs == 1 else "s", cpu, cpu/3600, wall)
    if untimed:
        text += "; %d without a CPU time, not counted" % untimed
    return text + "."


def references(section):
    return sorted({r["reference"] for r in section.rows})


def section_html(s):
    out = ['<section id="case-%s"><h2>%s</h2>' % (slug(s.case), e(s.case))]
    out.append("<p><b>Runs:</b> %s</p>" % "; ".join(
        "%s (%s, %s s, %s s CPU)" % (e(os.path.relpath(r["folder"], PROJECT[0])),
                                     e(r["action"]), e(r["seconds"]), e(r["cpuSeconds"]))
        for r in s.runs))
    if s.rows:
        out.append("<p>%s</p>" % e(cost_sentence(s.rows, "The rows below come from")))
        out.append("<p><b>Reference:</b> %s<br><b>Error measures:</b> %s</p>" % (
            "; ".join(e(x) for x in references(s)),
            "; ".join(e(m) for m in reportFiguresMeasures(s))))
        out.append('<img class="figure" src="%s" alt="%s: error against run time">'
                   % (e(s.png), e(s.case)))
        if len(s.drawn) < len(reportFigures.panels(s.rows)):
            out.append("<p>The figure shows the first %d of %d measure and reference pairs; "
                       "the tables have all.</p>" % (len(s.drawn),
                                                     len(reportFigures.panels(s.rows))))
        out.append("<h3>Observed orders</h3><p>error ~ h<sup>p</sup> (h ~ particles or "
                   "cells<sup>-1/2</sup>) and error ~ CPU<sup>-s</sup>, least squares over "
                   "the runs of a method; - with fewer than two resolutions.</p>")
        out.append(html_table(("measure", "against", "method", "runs", "p", "s"),
                              [o[:4] + (fmt(o[4]), fmt(o[5])) for o in s.orders],
                              numeric=(3, 4, 5)))
        out.append("<details><summary>All rows (errors.csv)</summary>")
        out.append(html_table(
            ("method", "resolution", "particles/cells", "measure", "value", "reference",
             "wall s", "CPU s"),
            [(r["method"], r["resolution"], r["particles"], r["measure"], fmt(r["value"]),
              r["reference"], fmt(r["wallSeconds"]), fmt(r["cpuSeconds"]))
             for r in table_rows(s)], numeric=(2, 4, 6, 7)))
        out.append("</details>")
    for p in s.problems:
        out.append('<p class="problem">%s</p>' % e(p))
    if s.copied:
        out.append("<h3>The tutorial's pictures</h3><div class=\"pictures\">")
        out += ['<figure><a href="%s"><img src="%s" alt="%s"></a><figcaption>%s'
                "</figcaption></figure>" % (e(src), e(src), e(name), e(name))
                for src, name in s.copied]
        out.append("</div>")
    return "\n".join(out + ["</section>"])


def reportFiguresMeasures(s):
    return reportFigures.measures(s.rows)


def write_html(a, sections, stabilityRows, benchmarks):
    now = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC")
    out = ["<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>%s</title>"
           "<style>%s</style></head><body>" % (e(a.title), CSS),
           "<h1>%s</h1><p>Written %s by ./Allreport. %s</p>" % (e(a.title), now, e(a.note)),
           "<nav><ul>" + "".join('<li><a href="#case-%s">%s</a></li>' % (slug(s.case), e(s.case))
                                 for s in sections)
           + '<li><a href="#stability">stability map</a></li>'
           '<li><a href="#benchmarks">speed benchmarks</a></li></ul></nav>',
           "<h2>Runs</h2>",
           "<p>%s</p>" % e(cost_sentence([r for s in sections for r in s.rows],
                                         "The page shows")),
           html_table(("case", "action", "wall s", "CPU s", "folder", "command"),
                      runs_rows(sections), numeric=(2, 3)),
           '<p>All rows in one table: <a href="errors.csv">errors.csv</a>; methods: FV '
           "(OpenFOAM), ISPH-USAW, WCSPH (dummy + repulsive walls), WCSPH-USAW.</p>"]
    out += [section_html(s) for s in sections]
    out.append('<section id="stability"><h2>Stability map</h2>')
    if stabilityRows:
        out.append("<p>tutorials/stability/results/stability.csv</p>")
        out.append(html_table(stabilityRows[0], stabilityRows[1:]))
    else:
        out.append("<p>%s</p>" % prose(HOW_TO_STABILITY))
    out.append('</section><section id="benchmarks"><h2>Speed benchmarks</h2>')
    if benchmarks:
        for name, text in benchmarks:
            out.append("<h3>benchmarks/results/%s</h3><pre>%s</pre>" % (e(name), e(text)))
    else:
        out.append("<p>%s</p>" % prose(HOW_TO_BENCHMARK))
    out.append("</section></body></html>")
    with open(os.path.join(a.out, "index.html"), "w") as f:
        f.write("\n".join(out) + "\n")


def md_table(header, rows):
    clean = lambda v: str(v).replace("|", "\\|").replace("\n", " ")
    return "\n".join(["| " + " | ".join(clean(h) for h in header) + " |",
                      "|" + "---|" * len(header)]
                     + ["| " + " | ".join(clean(v) for v in r) + " |" for r in rows]) + "\n"


def write_markdown(a, sections, stabilityMd, benchmarks):
    now = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC")
    out = ["# %s" % a.title, "", "Written %s by ./Allreport. %s" % (now, a.note), "",
           "## Runs", "", cost_sentence([r for s in sections for r in s.rows], "The page shows"),
           "", md_table(("case", "action", "wall s", "CPU s", "folder", "command"),
                                   runs_rows(sections))]
    for s in sections:
        out += ["## %s" % s.case, ""]
        if s.rows:
            out += [cost_sentence(s.rows, "The rows below come from"), "",
                    "Reference: %s  " % "; ".join(references(s)),
                    "Error measures: %s" % "; ".join(reportFiguresMeasures(s)), "",
                    "![%s: error against run time](%s)" % (s.case, s.png), "",
                    "Observed orders (error ~ h^p, error ~ CPU^-s):", "",
                    md_table(("measure", "against", "method", "runs", "p", "s"),
                             [o[:4] + (fmt(o[4]), fmt(o[5])) for o in s.orders]),
                    md_table(("method", "resolution", "particles/cells", "measure", "value",
                              "wall s", "CPU s"),
                             [(r["method"], r["resolution"], r["particles"], r["measure"],
                               fmt(r["value"]), fmt(r["wallSeconds"]), fmt(r["cpuSeconds"]))
                              for r in table_rows(s)])]
        out += ["**%s**" % p for p in s.problems]
        if s.copied:
            out += ["", "Pictures: " + ", ".join("[%s](%s)" % (n, src) for src, n in s.copied)]
        out.append("")
    out += ["## Stability map", "", stabilityMd or HOW_TO_STABILITY, "", "## Speed benchmarks", ""]
    if benchmarks:
        for name, text in benchmarks:
            out += ["### benchmarks/results/%s" % name, "", "```", text.rstrip(), "```", ""]
    else:
        out.append(HOW_TO_BENCHMARK)
    with open(os.path.join(a.out, "summary.md"), "w") as f:
        f.write("\n".join(out) + "\n")
