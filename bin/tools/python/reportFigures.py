"""The numbers and figures of Allreport's page (bin/tools/python/sphReport.py)
from the rows of the tutorials' errors.csv files (errorTable.py): the
observed orders and, per case, one PNG of error against wall-clock and CPU
time with every method on the same axes.
"""
import math

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import FixedLocator, FormatStrFormatter, LogLocator, NullFormatter

# One colour and marker per method family, the same on every figure; a
# variant (ISPH-USAW implicit, FV transient) takes its family's colour and
# a dashed line
STYLES = [("FV", "black", "s"), ("ISPH-USAW", "tab:red", "o"),
          ("WCSPH-USAW", "tab:green", "D"), ("WCSPH", "tab:blue", "^")]
MAX_PANELS = 4             # measures per figure: more make unreadable rows


def style(method):
    """(colour, marker, line style) of a method."""
    for family, colour, marker in STYLES:
        if method == family:
            return colour, marker, "-"
        if method.startswith(family):
            return colour, marker, "--"
    return "tab:purple", "v", ":"


def finite(v):
    return isinstance(v, float) and math.isfinite(v)


def measures(rows):
    """The case's error measures in the order they first appear (those
    with at least one error: not a reference's run time alone)."""
    return list(dict.fromkeys(m for m, _ in panels(rows)))


def panels(rows):
    """(measure, reference) of each panel, in the order they first appear,
    with at least one error (not a reference's run time alone)."""
    return list(dict.fromkeys((r["measure"], r["reference"]) for r in rows
                              if finite(r["value"])))


def of_panel(rows, panel):
    """The rows of one panel: its measure, and its reference or none (a
    reference run's time, drawn on every panel of its measure)."""
    measure, reference = panel
    return [r for r in rows if r["measure"] == measure
            and (r["reference"] == reference or not finite(r["value"]))]


def methods(rows):
    names = sorted({r["method"] for r in rows},
                   key=lambda m: ([f for f, _, _ in STYLES].index(style_family(m)), m))
    return names


def style_family(method):
    for family, _, _ in STYLES:
        if method.startswith(family):
            return family
    return "FV"


def slope(x, y):
    """Least-squares slope of log y against log x; NaN with fewer than two
    distinct positive points."""
    pts = [(a, b) for a, b in zip(x, y) if finite(a) and finite(b) and a > 0 and b > 0]
    if len({a for a, _ in pts}) < 2:
        return float("nan")
    lx, ly = np.log([a for a, _ in pts]), np.log([b for _, b in pts])
    return float(np.polyfit(lx, ly, 1)[0])


def orders(rows):
    """[(measure, reference, method, runs, order in the spacing, order in
    CPU time)]: error ~ h^p with h ~ particles^(-1/2) (2-D), error ~ CPU^(-s)."""
    out = []
    for panel in panels(rows):
        for method in methods(rows):
            group = [r for r in of_panel(rows, panel) if r["method"] == method
                     and finite(r["value"])]
            if not group:
                continue
            p = slope([math.sqrt(r["particles"]) if r["particles"] > 0 else float("nan")
                       for r in group], [r["value"] for r in group])
            s = slope([r["cpuSeconds"] for r in group], [r["value"] for r in group])
            out.append(panel + (method, len(group), -p, -s))
    return out


def seconds(r, key):
    """A row's time; OpenFOAM's ClockTime counts whole seconds, so a run
    under one second of wall-clock time is placed at its CPU time."""
    t = r[key]
    if key == "wallSeconds" and finite(t) and t < 1 and finite(r["cpuSeconds"]):
        return max(r["cpuSeconds"], 1e-3)
    return t


def _panel(ax, rows, timeKey):
    drawn = False
    for method in methods(rows):
        group = sorted((r for r in rows if r["method"] == method),
                       key=lambda r: r["particles"])
        colour, marker, line = style(method)
        points = [r for r in group if finite(r["value"]) and r["value"] > 0
                  and finite(seconds(r, timeKey)) and seconds(r, timeKey) > 0]
        if points:
            ax.loglog([seconds(r, timeKey) for r in points], [r["value"] for r in points],
                      marker=marker, color=colour, ls=line, label=method,
                      mfc=colour if line == "-" else "none")     # variants open
            for r in points:
                ax.annotate(str(r["resolution"]), (seconds(r, timeKey), r["value"]),
                            fontsize=6, xytext=(3, 3), textcoords="offset points",
                            color=colour)
            drawn = True
        # A reference run (no error of its own): its run time as a line
        for r in group:
            t = seconds(r, timeKey)
            if not finite(r["value"]) and finite(t) and t > 0:
                ax.axvline(t, color=colour, ls=":", lw=1,
                           label="%s (reference) %s" % (method, r["resolution"]))
                ax.set_xscale("log")
                drawn = True
    return drawn


def label_axis(axis, limits):
    """A few short labels on a log axis whatever its span: the decades, or
    1, 2, 5 of them, or for less than a factor 2.5 four values between."""
    lo, hi = limits
    if not (lo > 0 and hi > lo) or axis.get_scale() != "log":
        return
    span = hi / lo
    if span < 2.5:
        axis.set_major_locator(FixedLocator(np.geomspace(lo, hi, 6)[1:-1]))
    else:
        axis.set_major_locator(LogLocator(10, subs=(1.0,) if span > 1e3 else (1.0, 2.0, 5.0)))
    axis.set_major_formatter(FormatStrFormatter("%.3g"))
    axis.set_minor_formatter(NullFormatter())


def plot_case(case, rows, path):
    """The case's PNG: one row per (measure, reference) (at most
    MAX_PANELS), error against wall-clock seconds (left) and CPU seconds
    (right). Returns the panels drawn."""
    shown = panels(rows)[:MAX_PANELS]
    fig, axes = plt.subplots(len(shown), 2, figsize=(10, 3.2 * len(shown)),
                             squeeze=False)
    for (axWall, axCpu), panel in zip(axes, shown):
        group = of_panel(rows, panel)
        for ax, key, label in ((axWall, "wallSeconds",
                                "wall-clock time [s] (CPU time if under 1 s)"),
                               (axCpu, "cpuSeconds", "CPU time [s]")):
            if not _panel(ax, group, key):
                ax.text(0.5, 0.5, "no run with both an error and a %s"
                        % label.split(" [")[0], ha="center", va="center",
                        transform=ax.transAxes, fontsize=8)
            ax.set_xlabel(label)
            ax.margins(0.12)            # no marker cut by the frame
            ax.autoscale_view()
            label_axis(ax.xaxis, ax.get_xlim())
            label_axis(ax.yaxis, ax.get_ylim())
            ax.grid(alpha=0.3, which="both")
        axWall.set_title("%s, against %s" % panel, fontsize=8, loc="left")
        axWall.set_ylabel("error")
        axWall.legend(fontsize=7)
    fig.suptitle("%s: error against run time (labels: resolution)" % case, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return shown
