"""The benchmark's report: ``speed-vs-error.md`` (the targets, one table per analysis), ``.csv``
and ``.png`` (log-log, one panel per analysis), and the terminal's summary."""

from __future__ import annotations

import csv
import math
import os
from dataclasses import asdict
from pathlib import Path

from .suites import Point


def _fmt(x: float, digits: int = 2) -> str:
    if x == 0:
        return "0"
    if not math.isfinite(x):
        return "fails" if x > 0 else str(x)
    return f"{x:.{digits}e}"


def markdown(points: list[Point], target_rows: list[dict] | None = None) -> str:
    """The report: the targets, then one table per analysis (Pareto front and defaults
    marked)."""
    lines = ["# Speed against error", ""]
    if target_rows:
        lines += ["## Speed targets", "", "| target | limit | measured | met | notes |",
                  "|---|---|---|---|---|"]
        for r in target_rows:
            lines.append(f"| {r['target']} | {r.get('sense', '<=')} {r['limit']:g} {r['unit']} | "
                         f"{r['measured']:.3g} {r['unit']} | {'yes' if r['met'] else 'NO'} | "
                         f"{r['note']} |")
        lines.append("")
    lines += ["Time: CPU seconds per evaluation (least of repeated runs). Error: relative, worst "
              "over the suite's cases, against a high-precision reference "
              "(see govopt/bench/suites.py). **P**: on the analysis's speed-error Pareto front; "
              "**D**: govopt's default.", ""]
    for analysis in dict.fromkeys(p.analysis for p in points):
        lines += [f"## {analysis}", "", "| method | setting | time per evaluation (s) | error "
                  "| worst case | | |", "|---|---|---|---|---|---|---|"]
        for p in sorted((p for p in points if p.analysis == analysis),
                        key=lambda p: (p.method, p.time_s)):
            lines.append(f"| {p.method} | {p.setting} | {_fmt(p.time_s)} | {_fmt(p.error)} | "
                         f"{p.worst_case} | {'P' if p.pareto else ''} | "
                         f"{'D' if p.default else ''} |")
        lines.append("")
    return "\n".join(lines)


def summary(points: list[Point], target_rows: list[dict] | None = None) -> str:
    """Plain text for the terminal: each target beside what was measured, then per analysis
    the default setting(s) and the Pareto front."""
    lines = []
    if target_rows:
        lines.append("speed targets                  limit        measured     met")
        for r in target_rows:
            lines.append(f"  {r['target']:<28s} {r.get('sense', '<=')} {r['limit']:<6g}"
                         f"{r['unit']:<5s} {r['measured']:<8.3g}{r['unit']:<5s} "
                         f"{'yes' if r['met'] else 'NO'}"
                         f"   {r['note']}")
    lines.append("speed against error (CPU s per evaluation, relative error; * default)")
    for analysis in dict.fromkeys(p.analysis for p in points):
        pts = [p for p in points if p.analysis == analysis]
        lines.append(f"  {analysis}:")
        for p in sorted((p for p in pts if p.pareto or p.default), key=lambda p: p.time_s):
            lines.append(f"    {'*' if p.default else ' '}{'front' if p.pareto else 'OFF  '} "
                         f"{p.method} [{p.setting}]: {_fmt(p.time_s)} s, error {_fmt(p.error)}")
    return "\n".join(lines)


#: Points nearer than this in log10 of time and of error share one label ("grids x2, x4").
LABEL_NEAR = (0.08, 0.2)


def zero_floor(errors) -> float:
    """Where a panel draws an error of 0 (exact): a decade below its least nonzero error,
    never above 1e-3 (a log axis has no 0)."""
    nonzero = [e for e in errors if math.isfinite(e) and e > 0]
    return min(10.0 ** (math.floor(math.log10(min(nonzero))) - 1) if nonzero else 1e-3, 1e-3)


def label_points(ax, marks: list[tuple[float, float, str]]) -> None:
    """Annotate points, one label per cluster of points that would overlap (within
    :data:`LABEL_NEAR` in log space), the cluster's texts joined; a label in the right fifth of
    the (log) x axis is written to the left of its point, inside the axes."""
    groups: list[list[tuple[float, float, str]]] = []
    for x, y, text in marks:
        for g in groups:
            gx, gy, _ = g[0]
            if (abs(math.log10(x / gx)) < LABEL_NEAR[0]
                    and abs(math.log10(y / gy)) < LABEL_NEAR[1]):
                g.append((x, y, text))
                break
        else:
            groups.append([(x, y, text)])
    for g in groups:
        x, y, _ = g[0]
        texts = list(dict.fromkeys(t for _, _, t in g))
        common = os.path.commonprefix(texts).rsplit(" ", 1)[0] + " " if len(texts) > 1 else ""
        text = (common + ", ".join(t[len(common):] for t in texts)) if common.strip() else \
            ", ".join(texts)
        lo, hi = (math.log10(v) for v in ax.get_xlim())
        left = math.log10(x) > hi - 0.2 * (hi - lo)
        ax.annotate(text, (x, y), fontsize=6, xytext=(-4 if left else 3, 3),
                    textcoords="offset points", ha="right" if left else "left")


def plot(points: list[Point], path: Path) -> None:
    """Log-log panels, one per analysis: time per evaluation against error. An error of 0
    (exact) is drawn on a dashed line a decade below the panel's least nonzero error, and says
    so; failures at 10 (crosses). Labels of points that would overlap are joined."""
    from matplotlib.figure import Figure
    from matplotlib.ticker import NullFormatter

    analyses = list(dict.fromkeys(p.analysis for p in points))
    cols = 3
    rows = math.ceil(len(analyses) / cols)
    fig = Figure(figsize=(5.2 * cols, 4.2 * rows), layout="constrained")
    axes = fig.subplots(rows, cols, squeeze=False).ravel()
    for ax, analysis in zip(axes, analyses, strict=False):
        pts = [p for p in points if p.analysis == analysis]
        floor = zero_floor(p.error for p in pts)

        def shown(p: Point, floor=floor) -> float:
            return min(max(p.error, floor), 10.0) if math.isfinite(p.error) else 10.0

        methods = list(dict.fromkeys(p.method for p in pts))
        marks = []
        for j, method in enumerate(methods):
            mp_ = [p for p in pts if p.method == method]
            x = [p.time_s for p in mp_]
            y = [shown(p) for p in mp_]
            ax.plot(x, y, marker="o^sDvP*Xh<>"[j % 11], ls="-" if len(mp_) > 1 else "none",
                    label=method, ms=5)
            for p, xi, yi in zip(mp_, x, y, strict=True):
                if not math.isfinite(p.error):
                    ax.plot([xi], [yi], "kx", ms=9)
                if p.default:
                    ax.plot([xi], [yi], "o", mfc="none", mec="k", ms=12)
                if len(mp_) > 1:
                    marks.append((xi, yi, p.setting.split("=")[-1].strip()))
        if any(p.error == 0 for p in pts):
            ax.axhline(floor, color="0.5", ls="--", lw=0.8)
            ax.annotate("error 0 (exact)", (0.01, floor), xycoords=("axes fraction", "data"),
                        xytext=(0, 3), textcoords="offset points", fontsize=7, color="0.3")
        front = sorted((p for p in pts if p.pareto), key=lambda p: p.time_s)
        ax.plot([p.time_s for p in front], [shown(p) for p in front], "k:", lw=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        lo, hi = min(p.time_s for p in pts), max(p.time_s for p in pts)
        span = max(math.sqrt(hi / lo), 4.0)
        ax.set_xlim(math.sqrt(lo * hi) / span / 1.5, math.sqrt(lo * hi) * span * 1.5)
        label_points(ax, marks)  # after the limits: a label near the right edge goes left
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_title(analysis)
        ax.set_xlabel("CPU time per evaluation (s)")
        ax.set_ylabel("relative error")
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=6, loc="best", framealpha=0.4)
    for ax in axes[len(analyses):]:
        ax.set_visible(False)
    fig.suptitle("govopt: speed against error (circled: default; dotted: Pareto front)")
    fig.savefig(path, dpi=110, format="png")


#: the files of :func:`write_report`, in its folder
REPORT_FILES = ("speed-vs-error.md", "speed-vs-error.csv", "speed-vs-error.png")


def check_report(out: str | Path, *, overwrite: bool = False) -> Path:
    """Before the benchmark: the folder ``out`` (made if only its parent exists) can take
    :data:`REPORT_FILES`, none of which exists unless ``overwrite`` (regular files only)."""
    from ..report.files import check_output, output_folder

    out = output_folder(out, "the benchmark report")
    for name in REPORT_FILES:
        check_output(out / name, overwrite=overwrite, what="benchmark report")
    return out


def write_report(points: list[Point], out: str | Path,
                 target_rows: list[dict] | None = None, *,
                 overwrite: bool = True) -> list[Path]:
    """``speed-vs-error.md``, ``.csv`` and ``.png`` in folder ``out`` (:func:`check_report`;
    an existing file replaced only with ``overwrite``)."""
    from ..report.files import atomic_write

    out = check_report(out, overwrite=overwrite)
    md, csv_path, png = (out / name for name in REPORT_FILES)
    text = markdown(points, target_rows)
    atomic_write(md, lambda p: p.write_text(text + "\n"), overwrite=overwrite, what="report")

    def write_csv(p):
        with open(p, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(asdict(points[0])))
            w.writeheader()
            for pt in points:
                w.writerow({**asdict(pt), "time_s": f"{pt.time_s:.6g}",
                            "error": f"{pt.error:.6g}"})

    atomic_write(csv_path, write_csv, overwrite=overwrite, what="CSV")
    atomic_write(png, lambda p: plot(points, p), overwrite=overwrite, what="plot")
    return [md, csv_path, png]


def read_csv(path: str | Path) -> list[Point]:
    """Points from a CSV written by :func:`write_report`."""
    with open(path, newline="") as fh:
        return [Point(r["analysis"], r["method"], r["setting"], float(r["time_s"]),
                      float(r["error"]), r["worst_case"], r["note"], r["pareto"] == "True",
                      r["default"] == "True") for r in csv.DictReader(fh)]
