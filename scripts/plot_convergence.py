#!/usr/bin/env python3
"""Convergence plot (SVG, PNG or PDF) from gaitsynth optimizer CSV logs, drawn with matplotlib.

Needs matplotlib (Debian: python3-matplotlib); it draws off-screen (the Agg backend), so no display
is needed. viz/convergence_plot_svg.hpp draws a similar plot from C++ without any dependency.

    scripts/plot_convergence.py LOG.csv [LOG2.csv ...] -o plot.svg [--label A --label B] [--title T]
                                [--x evaluations|iteration] [--no-median] [--no-step]

The output format is the extension of -o: .svg, .png or .pdf.

Each log is what `gaitsynth::minimize` writes with `run_options::log_file`: one row per
iteration with the columns stage, restart, iteration, evaluations, best, iteration_best,
iteration_median, iteration_worst, step_size, axis_ratio, batch_size, non_finite, elapsed_s
(and optionally one column per parameter). The figure is laid out like pycma's `cma.plot()`: the
top panel shows the best value so far (solid) and the median of each iteration (dotted) on a log
scale against evaluations; the bottom panel the step size (sigma for CMA-ES, alpha for SDS), also
on a log scale. Continuation stages are laid end to end (cumulative evaluations) and separated by
dashed lines, like Sharon & van de Panne 2005, Fig. 9; restarts are marked with small ticks at the
bottom of the top panel. Values that are not finite and positive are not drawn.
"""

import argparse
import csv
import math
import os
import sys

COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"]
FORMATS = ("svg", "png", "pdf")
REQUIRED = {"stage", "restart", "iteration", "evaluations", "best", "step_size"}


def read_log(path):
    """Returns (rows, stage_starts): dict rows with numeric fields and cumulative evaluations and
    iterations, and the cumulative evaluations where each stage after the first begins."""
    rows = []
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            missing = REQUIRED - set(reader.fieldnames or [])
            if missing:
                raise SystemExit(f"{path}: not a gaitsynth optimizer log (missing {sorted(missing)})")
            for r in reader:
                rows.append({k: _num(v) for k, v in r.items() if k is not None})
    except OSError as e:
        raise SystemExit(f"{path}: cannot read ({e.strerror or e})")
    except (UnicodeDecodeError, csv.Error) as e:
        raise SystemExit(f"{path}: not a gaitsynth optimizer log ({e})")
    # Continuation stages restart their counters: make evaluations and iterations cumulative.
    # A resumed run repeats the iterations after its checkpoint: keep the last occurrence.
    dedup = {}
    for r in rows:
        dedup[(r["stage"], r["iteration"])] = r
    rows = sorted(dedup.values(), key=lambda r: (r["stage"], r["iteration"]))
    offset_e = offset_i = 0.0
    last_stage = None
    last_e = last_i = 0.0
    stage_starts = []
    for r in rows:
        if last_stage is not None and r["stage"] != last_stage:
            offset_e += last_e
            offset_i += last_i
            stage_starts.append(offset_e)
        last_stage = r["stage"]
        last_e, last_i = r["evaluations"], r["iteration"]
        r["cum_evaluations"] = offset_e + r["evaluations"]
        r["cum_iteration"] = offset_i + r["iteration"]
    return rows, stage_starts


def _num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return float("nan")


def _positive(v):
    """v if it can be drawn on a log axis, else NaN (matplotlib breaks the line there)."""
    return v if v is not None and math.isfinite(v) and v > 0 else float("nan")


def _boundaries(rows, xk, key):
    """x values where column key ("stage" or "restart") changes; a restart counter that changes
    with the stage (each stage counts from 0) is no restart."""
    return [rows[k - 1][xk] for k in range(1, len(rows))
            if rows[k][key] != rows[k - 1][key]
            and (key == "stage" or rows[k]["stage"] == rows[k - 1]["stage"])]


def _pyplot():
    try:
        import matplotlib
    except ImportError:
        raise SystemExit("plot_convergence.py needs matplotlib "
                         "(Debian: apt-get install python3-matplotlib)")
    matplotlib.use("Agg")
    # Reproducible files: the same logs give the same bytes (no date, fixed SVG ids).
    matplotlib.rcParams["svg.hashsalt"] = "gaitsynth"
    import matplotlib.pyplot as plt
    return plt


def plot(logs, labels, out, title, xkey, show_median, show_step):
    fmt = os.path.splitext(out)[1].lower().lstrip(".")
    if fmt not in FORMATS:
        raise SystemExit(f"{out}: unknown output format (the -o extension must be "
                         f"{', '.join('.' + f for f in FORMATS)})")
    xk = "cum_evaluations" if xkey == "evaluations" else "cum_iteration"
    keys = ("best", "iteration_median") if show_median else ("best",)
    if not any(math.isfinite(_positive(r.get(k))) for rows, _ in logs for r in rows for k in keys):
        raise SystemExit("nothing to plot (no finite positive values)")
    has_step = any(math.isfinite(_positive(r["step_size"])) for rows, _ in logs for r in rows)
    show_step = show_step and has_step

    plt = _pyplot()
    from matplotlib.lines import Line2D
    if show_step:
        fig, (ax, ax_step) = plt.subplots(2, 1, sharex=True, figsize=(8, 6.4),
                                          gridspec_kw={"height_ratios": [2.2, 1]})
    else:
        fig, ax = plt.subplots(figsize=(8, 4.6))
        ax_step = None
    axes = [a for a in (ax, ax_step) if a is not None]

    for i, (rows, stage_starts) in enumerate(logs):
        c = COLORS[i % len(COLORS)]
        xs = [r[xk] for r in rows]
        ax.plot(xs, [_positive(r["best"]) for r in rows], color=c, lw=1.8, label=labels[i])
        if show_median:
            ax.plot(xs, [_positive(r.get("iteration_median")) for r in rows], color=c, lw=1.0,
                    ls=":")
        if ax_step is not None:
            ax_step.plot(xs, [_positive(r["step_size"]) for r in rows], color=c, lw=1.2)
        # Stage boundaries and restarts: at the cumulative evaluation (or iteration) count where
        # the new stage or restart begins, i.e. the last one of the row before.
        for x in _boundaries(rows, xk, "stage"):
            for a in axes:
                a.axvline(x, color=c, ls="--", lw=1.0, alpha=0.8)
        for x in _boundaries(rows, xk, "restart"):
            ax.axvline(x, ymin=0.0, ymax=0.05, color=c, lw=1.5)

    ax.set_yscale("log")
    ax.set_ylabel("objective value")
    if ax_step is not None:
        ax_step.set_yscale("log")
        ax_step.set_ylabel("step size")
    for a in axes:
        a.grid(True, which="major", color="#dddddd", lw=0.8)
        a.set_axisbelow(True)
    axes[-1].set_xlabel(xkey)
    axes[-1].set_xlim(left=0)
    if title:
        ax.set_title(title)

    # Legend: one entry per log, then what the line styles mean (in grey).
    handles, _ = ax.get_legend_handles_labels()
    grey = "#555555"
    handles.append(Line2D([], [], color=grey, lw=1.8, label="best so far"))
    if show_median:
        handles.append(Line2D([], [], color=grey, lw=1.0, ls=":", label="median of each iteration"))
    if any(_boundaries(rows, xk, "stage") for rows, _ in logs):
        handles.append(Line2D([], [], color=grey, lw=1.0, ls="--", label="stage boundary"))
    if any(_boundaries(rows, xk, "restart") for rows, _ in logs):
        handles.append(Line2D([], [], color=grey, lw=0, marker="|", markersize=8, label="restart"))
    ax.legend(handles=handles, loc="upper right", fontsize="small", framealpha=0.9)

    fig.tight_layout()
    metadata = {"svg": {"Date": None}, "pdf": {"CreationDate": None}, "png": {}}[fmt]
    try:
        fig.savefig(out, format=fmt, metadata=metadata, dpi=120)
    except OSError as e:
        raise SystemExit(f"{out}: cannot write ({e.strerror or e})")
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("logs", nargs="+", help="CSV logs written by gaitsynth::minimize")
    ap.add_argument("-o", "--output", required=True,
                    help="file to write; its extension (.svg, .png, .pdf) gives the format")
    ap.add_argument("--label", action="append", dest="labels",
                    help="legend label of the next log (repeat once per log; default: file names)")
    ap.add_argument("--title", default="")
    ap.add_argument("--x", choices=["evaluations", "iteration"], default="evaluations")
    ap.add_argument("--no-median", action="store_true")
    ap.add_argument("--no-step", action="store_true")
    a = ap.parse_args(argv)
    labels = a.labels if a.labels else [os.path.basename(p) for p in a.logs]
    if len(labels) != len(a.logs):
        raise SystemExit("give one --label per log")
    logs = [read_log(p) for p in a.logs]
    plot(logs, labels, a.output, a.title, a.x, not a.no_median, not a.no_step)
    return 0


if __name__ == "__main__":
    sys.exit(main())
