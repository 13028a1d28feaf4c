#!/usr/bin/env python3
"""Convergence plot (SVG) from gaitsynth optimizer CSV logs.

Plain Python 3, no third-party packages (matplotlib is not needed): the SVG is written directly.

    scripts/plot_convergence.py LOG.csv [LOG2.csv ...] -o plot.svg [--label A --label B] [--title T]
                                [--x evaluations|iteration] [--no-median] [--no-step]

Each log is what `gaitsynth::minimize` writes with `run_options::log_file`: one row per
iteration with the columns stage, restart, iteration, evaluations, best, iteration_best,
iteration_median, iteration_worst, step_size, axis_ratio, batch_size, non_finite, elapsed_s
(and optionally one column per parameter). The top panel shows the best value so far (solid) and
the median of each iteration (dotted) on a log scale against evaluations; the bottom panel the step
size (sigma for CMA-ES, alpha for SDS). Continuation stages are laid end to end (cumulative
evaluations) and separated by dashed lines, like Sharon & van de Panne 2005, Fig. 9; restarts are
marked with small ticks.
"""

import argparse
import csv
import math
import os
import sys

COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"]
FLOOR = 1e-300


def read_log(path):
    """Returns a list of dict rows with numeric fields and cumulative evaluations."""
    rows = []
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        required = {"stage", "restart", "iteration", "evaluations", "best", "step_size"}
        missing = required - set(reader.fieldnames or [])
        if missing:
            raise SystemExit(f"{path}: not a gaitsynth optimizer log (missing {sorted(missing)})")
        for r in reader:
            rows.append({k: _num(v) for k, v in r.items() if k is not None})
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


def _finite(v):
    return v is not None and not math.isnan(v) and not math.isinf(v)


class Axis:
    def __init__(self, lo, hi, log):
        self.log = log
        if log:
            lo, hi = math.log10(max(lo, FLOOR)), math.log10(max(hi, FLOOR))
            lo, hi = math.floor(lo), math.ceil(hi)
        if hi <= lo:
            hi = lo + 1
        self.lo, self.hi = lo, hi

    def frac(self, v):
        if self.log:
            v = math.log10(max(v, FLOOR))
        return (v - self.lo) / (self.hi - self.lo)

    def ticks(self):
        if self.log:
            span = int(self.hi - self.lo)
            step = max(1, math.ceil(span / 8))
            return [(10.0 ** e, f"1e{int(e)}") for e in range(int(self.lo), int(self.hi) + 1, step)]
        span = self.hi - self.lo
        raw = span / 6
        mag = 10 ** math.floor(math.log10(raw))
        step = min((m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw), default=mag * 10)
        t = math.ceil(self.lo / step) * step
        out = []
        while t <= self.hi + 1e-9 * span:
            out.append((t, _fmt(t)))
            t += step
        return out


def _fmt(v):
    if v == 0:
        return "0"
    if abs(v) >= 1 and abs(v) < 1e7 and float(v).is_integer():
        return f"{int(v)}"
    if abs(v) >= 1e7 or abs(v) < 1e-3:
        return f"{v:.2g}"
    return f"{v:g}"


def _esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def plot(logs, labels, out, title, xkey, show_median, show_step):
    width, left, right = 760, 80, 20
    top_h, bottom_h, gap, top_margin, bottom_margin = 330, 150 if show_step else 0, 50, 45, 45
    height = top_margin + top_h + (gap + bottom_h if show_step else 0) + bottom_margin + 20 * len(logs)
    pw = width - left - right
    xk = "cum_evaluations" if xkey == "evaluations" else "cum_iteration"

    xs = [r[xk] for rows, _ in logs for r in rows]
    ys = [r[k] for rows, _ in logs for r in rows for k in ("best", "iteration_median")
          if k in r and _finite(r[k]) and r[k] > 0 and (k == "best" or show_median)]
    ss = [r["step_size"] for rows, _ in logs for r in rows if _finite(r["step_size"]) and r["step_size"] > 0]
    if not xs or not ys:
        raise SystemExit("nothing to plot (no finite positive values)")
    xa = Axis(0.0, max(xs), False)
    ya = Axis(min(ys), max(ys), True)
    sa = Axis(min(ss), max(ss), True) if ss else None

    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>']
    if title:
        svg.append(f'<text x="{left + pw / 2}" y="25" text-anchor="middle" font-size="15">{_esc(title)}</text>')

    def panel(y0, h, yaxis, ylabel):
        svg.append(f'<rect x="{left}" y="{y0}" width="{pw}" height="{h}" fill="none" stroke="#444"/>')
        for v, lab in yaxis.ticks():
            y = y0 + h - yaxis.frac(v) * h
            if y0 - 0.5 <= y <= y0 + h + 0.5:
                svg.append(f'<line x1="{left}" y1="{y:.1f}" x2="{left + pw}" y2="{y:.1f}" stroke="#ddd"/>')
                svg.append(f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end">{lab}</text>')
        for v, lab in xa.ticks():
            x = left + xa.frac(v) * pw
            svg.append(f'<line x1="{x:.1f}" y1="{y0}" x2="{x:.1f}" y2="{y0 + h}" stroke="#eee"/>')
            svg.append(f'<text x="{x:.1f}" y="{y0 + h + 16}" text-anchor="middle">{lab}</text>')
        svg.append(f'<text transform="translate({left - 60},{y0 + h / 2}) rotate(-90)" '
                   f'text-anchor="middle">{_esc(ylabel)}</text>')

    def polyline(rows, key, yaxis, y0, h, color, dash=None, width_px=1.8):
        # Decimated to at most the first/lowest/highest/last point of each pixel column, so that
        # runs of 1e5 iterations still give a small file that looks the same.
        segs, cur = [], []
        col, bucket = None, []

        def flush():
            if not bucket:
                return
            keep = {0, len(bucket) - 1,
                    min(range(len(bucket)), key=lambda j: bucket[j][1]),
                    max(range(len(bucket)), key=lambda j: bucket[j][1])}
            cur.extend(bucket[j] for j in sorted(keep))
            bucket.clear()

        for r in rows:
            v = r.get(key)
            if _finite(v) and v > 0:
                px = left + xa.frac(r[xk]) * pw
                py = y0 + h - yaxis.frac(v) * h
                if col is not None and int(px) != col:
                    flush()
                col = int(px)
                bucket.append((px, py))
            else:
                flush()
                if cur:
                    segs.append(cur)
                    cur = []
                col = None
        flush()
        if cur:
            segs.append(cur)
        d = f' stroke-dasharray="{dash}"' if dash else ""
        for s in segs:
            pts = " ".join(f"{x:.1f},{y:.1f}" for x, y in s)
            svg.append(f'<polyline fill="none" stroke="{color}" stroke-width="{width_px}"{d} '
                       f'stroke-linejoin="round" points="{pts}"/>')

    y_top = top_margin
    panel(y_top, top_h, ya, "objective value")
    for i, (rows, stage_starts) in enumerate(logs):
        c = COLORS[i % len(COLORS)]
        if show_median:
            polyline(rows, "iteration_median", ya, y_top, top_h, c, dash="2,3", width_px=1.0)
        polyline(rows, "best", ya, y_top, top_h, c)
        for s in stage_starts:
            x = left + xa.frac(s) * pw
            svg.append(f'<line x1="{x:.1f}" y1="{y_top}" x2="{x:.1f}" y2="{y_top + top_h}" '
                       f'stroke="{c}" stroke-dasharray="6,4"/>')
        prev = None
        for r in rows:
            if prev is not None and r["restart"] != prev:
                x = left + xa.frac(r[xk]) * pw
                svg.append(f'<line x1="{x:.1f}" y1="{y_top + top_h}" x2="{x:.1f}" '
                           f'y2="{y_top + top_h - 8}" stroke="{c}" stroke-width="1.5"/>')
            prev = r["restart"]
    y_bottom = y_top + top_h + gap
    if show_step and sa:
        panel(y_bottom, bottom_h, sa, "step size")
        for i, (rows, _) in enumerate(logs):
            polyline(rows, "step_size", sa, y_bottom, bottom_h, COLORS[i % len(COLORS)], width_px=1.2)
        xlabel_y = y_bottom + bottom_h + 34
    else:
        xlabel_y = y_top + top_h + 34
    svg.append(f'<text x="{left + pw / 2}" y="{xlabel_y}" text-anchor="middle">{xkey}</text>')
    ly = xlabel_y + 22
    for i, lab in enumerate(labels):
        c = COLORS[i % len(COLORS)]
        svg.append(f'<line x1="{left}" y1="{ly - 4}" x2="{left + 30}" y2="{ly - 4}" stroke="{c}" stroke-width="2"/>')
        svg.append(f'<text x="{left + 38}" y="{ly}">{_esc(lab)}</text>')
        ly += 20
    note = "solid: best so far" + (", dotted: median of each iteration" if show_median else "")
    svg.append(f'<text x="{left + pw}" y="{xlabel_y + 22}" text-anchor="end" fill="#555">{note}</text>')
    svg.append("</svg>")
    with open(out, "w") as f:
        f.write("\n".join(svg) + "\n")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("logs", nargs="+", help="CSV logs written by gaitsynth::minimize")
    ap.add_argument("-o", "--output", required=True, help="SVG file to write")
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
