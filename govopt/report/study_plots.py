"""Plots of a trade study (matplotlib, PNG and SVG), drawn from its database, in the spec's
units (the database's ``columns``: :mod:`govopt.study.shown`).

* ``sweep-<key>``: for each swept key, the objective and the margin of each constraint that
  binds or fails somewhere in the study (``Check.margin``: 0 is the limit, negative fails),
  against the key's value as written; with several keys, one line per combination of the
  others, named in a legend (a colour bar where there are more than :data:`MAX_LEGEND`);
  zipped keys move together, so one plot against the first, the others named on its axis;
* ``pareto``: the Pareto front of the study's objectives (two, or the three pairs of three)
  among the feasible points, the front joined as a staircase;
* ``tolerance``: for a tolerance study, histograms of the speeds, the irregularity and ``k^2``
  at the normal configuration (the irregularity's requirement marked), and of each
  requirement's margin with the limit at 0 (failing samples red). A sample whose values are
  all equal, or a few distinct values, or NaN, is drawn, never refused.

Every series set has a legend or a colour bar; long labels are wrapped, and the figures are
laid out (``constrained``) so that no label is cut. Nothing here recomputes physics; files go
through :func:`govopt.report.files.atomic_write`.
"""

from __future__ import annotations

import math
import re
import textwrap
from pathlib import Path

import numpy as np
import pandas as pd

from ..errors import GovoptError
from ..verdict import ACTIVE_TOL

FORMATS = ("png", "svg")
DPI = 150
STYLE = {"font.size": 9, "axes.titlesize": 10, "axes.labelsize": 9, "legend.fontsize": 8,
         "axes.grid": True, "grid.alpha": 0.35, "svg.hashsalt": "govopt"}
#: constraints drawn per swept key at most (those closest to their limit first)
MAX_CONSTRAINTS = 5
#: series named in a legend at most; more are coloured along a colour bar
MAX_LEGEND = 10
#: characters of an axis label or title on one line (wrapped beyond: never cut)
WRAP = 90
#: rows drawn per plot at most: a larger study is drawn from every k-th point (the Pareto
#: front always whole), its constraints chosen and its histograms counted over every row
MAX_POINTS = 20_000
#: points on a Pareto front labelled with their numbers at most (more would overlap)
MAX_LABELS = 30
#: bars of a histogram
BINS = 40


def check_plot_folder(folder: str | Path) -> Path:
    """Check before a run that plots can go into ``folder`` (an existing folder, or a new one
    in an existing folder)."""
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise GovoptError(f"{folder}: cannot write plots: not a folder")
    if not folder.exists() and not folder.parent.is_dir():
        raise GovoptError(f"{folder}: cannot write plots: folder {folder.parent} does not exist")
    return folder


def _figure(rows: int, cols: int = 1, height: float = 2.3, width: float = 7.0):
    from matplotlib.figure import Figure

    return Figure(figsize=(width, 0.6 + height * rows), dpi=DPI, layout="constrained")


def _wrap(text: str, width: int = WRAP) -> str:
    return "\n".join(textwrap.wrap(text, width)) or text


def _slug(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "-", text).strip("-")


class _Columns:
    """What the plots read of a study's ``columns``: each column's shown unit and factor, the
    inputs by key, the checks by name."""

    def __init__(self, store):
        from ..study.summary import check_columns

        info = store.columns()
        self.unit = dict(zip(info["name"], info["shown_unit"], strict=True))
        self.factor = dict(zip(info["name"], info["shown_factor"], strict=True))
        self.type = dict(zip(info["name"], info["type"], strict=True))
        self.about = dict(zip(info["name"], info["about"], strict=True))
        inputs = info[info["role"] == "input"]
        self.inputs = dict(zip(inputs["label"], inputs["name"], strict=True))
        self.checks = check_columns(store)

    def values(self, frame: pd.DataFrame, name: str) -> np.ndarray:
        """A numeric column in its shown unit."""
        return pd.to_numeric(frame[name], errors="coerce").to_numpy(dtype=float) / float(
            self.factor.get(name, 1.0))

    def label(self, text: str, name: str) -> str:
        unit = self.unit.get(name, "")
        return f"{text} [{unit}]" if unit else text


def _axis(frame: pd.DataFrame, cols: _Columns, key: str):
    """``(values, label, ticks)`` of a swept key: its numbers in the unit written, or
    positions of its written values (with them as tick labels)."""
    name = cols.inputs[key]
    if cols.type.get(name) != "TEXT":
        return cols.values(frame, name), cols.label(key, name), None
    written = frame[name].astype(str)
    cats = list(pd.unique(written))
    pos = {c: i for i, c in enumerate(cats)}
    return np.array([pos[v] for v in written], dtype=float), key, cats


def least_margins(frames, checks: dict) -> dict[str, float]:
    """Each check's least margin over the rows of ``frames`` (a table's batches)."""
    least: dict[str, float] = {}
    for frame in frames:
        for label, c in checks.items():
            if c.get("margin") in frame:
                m = np.nanmin(frame[c["margin"]].to_numpy(dtype=float), initial=np.inf)
                least[label] = min(least.get(label, np.inf), float(m))
    return least


def constraints(least: dict[str, float]) -> list[str]:
    """The checks to draw: those active (satisfied within ``ACTIVE_TOL``) or failed in some row,
    closest to their limit first; if none, the three closest."""
    names = [n for n in least if math.isfinite(least[n])]
    binding = [n for n in names if least[n] < ACTIVE_TOL]
    chosen = binding or sorted(names, key=lambda n: least[n])[:3]
    return sorted(chosen, key=lambda n: least[n])[:MAX_CONSTRAINTS]


def _value(v, unit: str) -> str:
    """An input's value as a legend names it: 4 significant digits and the unit."""
    if isinstance(v, float | np.floating | int | np.integer) and not isinstance(v, bool):
        return f"{float(v):.4g}" + (f" {unit}" if unit else "")
    return str(v)


def _groups(frame: pd.DataFrame, cols: _Columns, others: list[str]):
    """The series of a sweep plot: ``(name -> row positions, colour of each, legend or colour
    bar)``: one per combination of the ``others`` keys' values, in order."""
    if not others:
        return {"": np.arange(len(frame))}, {"": "C0"}, None
    names = [cols.inputs[k] for k in others]
    shown = pd.DataFrame({n: [_value(v, cols.unit.get(n, "")) for v in frame[n]] for n in names})
    keyed = shown.agg(", ".join, axis=1) if len(names) > 1 else shown[names[0]]
    groups = {k: np.asarray(v) for k, v in keyed.groupby(keyed, sort=False).indices.items()}
    if len(groups) <= MAX_LEGEND:
        colours = {g: f"C{i}" for i, g in enumerate(groups)}
        return groups, colours, "legend"
    from matplotlib import colormaps
    from matplotlib.colors import Normalize

    numeric = len(others) == 1 and cols.type.get(names[0]) != "TEXT"
    first = {g: cols.values(frame.iloc[idx[:1]], names[0])[0] if numeric else i
             for i, (g, idx) in enumerate(groups.items())}
    norm = Normalize(min(first.values()), max(first.values()) or 1.0)
    cmap = colormaps["viridis"]
    colours = {g: cmap(norm(v)) for g, v in first.items()}
    label = (cols.label(others[0], names[0]) if numeric else
             f"combination of {', '.join(others)} (in order)")
    return groups, colours, (cmap, norm, label)


def _series(ax, frame, groups, colours, y, x, ticks, label_points=False, named=None):
    """Draw ``y`` against the key: a line per series, hollow where a check fails."""
    ok = frame["status"].isin(["pass", "optimal"]).to_numpy()
    lines = len(groups) > 1
    for name, idx in groups.items():
        order = idx[np.argsort(x[idx], kind="stable")]
        colour = colours[name]
        if lines:
            ax.plot(x[order], y[order], "-", color=colour, lw=1.0, alpha=0.7,
                    label=named(name) if named else None)
        good, bad = order[ok[order]], order[~ok[order]]
        ax.plot(x[good], y[good], "o", color=colour, ms=4)
        ax.plot(x[bad], y[bad], "o", mfc="none", color=colour, ms=4)
    if label_points:
        for i in range(len(frame)):
            if np.isfinite(y[i]) and np.isfinite(x[i]):
                ax.annotate(str(int(frame["point"].iloc[i])), (x[i], y[i]), fontsize=7,
                            xytext=(3, 2), textcoords="offset points")
    if ticks is not None:
        ax.set_xticks(range(len(ticks)), [_wrap(t, 20) for t in ticks], rotation=20)


def _sweep_figure(frame: pd.DataFrame, cols: _Columns, key: str, keys: list[str],
                  combine: str, cons: list[str], every: int = 1):
    """The objective and the constraints ``cons`` against ``key``; ``every``: the frame holds
    every ``every``-th point of the study (said in the title)."""
    x, xlabel, ticks = _axis(frame, cols, key)
    others = [k for k in keys if k != key and frame[cols.inputs[k]].astype(str).nunique() > 1] \
        if combine == "grid" else []
    groups, colours, key_of = _groups(frame, cols, others)
    few = not others and len(frame) <= 12
    fig = _figure(1 + len(cons))
    axes = fig.subplots(1 + len(cons), 1, sharex=True, squeeze=False)[:, 0]
    obj = str(frame["objective"].dropna().iloc[0]) if "objective" in frame and \
        frame["objective"].notna().any() else "objective"
    y = cols.values(frame, "objective_value") if "objective_value" in frame else \
        np.full(len(frame), np.nan)

    def named(g: str) -> str:
        return _wrap(", ".join(f"{k} = {v}" for k, v in zip(others, g.split(", "),
                                                            strict=False)), 40)

    _series(axes[0], frame, groups, colours, y, x, ticks, few, named)
    from matplotlib.lines import Line2D

    axes[0].legend(handles=[Line2D([], [], ls="", marker="o", color="0.3", ms=4,
                                   label="passes every check"),
                            Line2D([], [], ls="", marker="o", mfc="none", color="0.3", ms=4,
                                   label="fails a check")], loc="best", fontsize=7)
    axes[0].set_ylabel(_wrap(cols.label(obj.replace("_", " "), "objective_value"), 30))
    note = ("; labels: point numbers" if few else "") + (
        f"; one point in {every} drawn" if every > 1 else "")
    axes[0].set_title(_wrap(f"objective and binding constraints (hollow: fails a check{note})"),
                      fontsize=9)
    for ax, name in zip(axes[1:], cons, strict=True):
        m = frame[cols.checks[name]["margin"]].to_numpy(dtype=float)
        _series(ax, frame, groups, colours, m, x, ticks, few)
        ax.axhline(0.0, color="k", lw=0.8)
        lo = min(np.nanmin(m, initial=0.0), 0.0)
        span = (np.nanmax(m, initial=0.0) - lo) or 1.0
        ax.axhspan(lo - 0.1 * span, 0.0, color="tab:red", alpha=0.08, lw=0)
        ax.set_ylabel("margin")
        ax.set_title(_wrap(f"{name} (margin < 0: fails)"), loc="left", fontsize=8)
    together = [k for k in keys if k != key] if combine == "zip" else []
    axes[-1].set_xlabel(_wrap(xlabel + (f"; in step with it: {', '.join(together)}"
                                        if together else "")))
    if key_of == "legend":
        fig.legend(loc="outside right upper", fontsize=7, title=_wrap(", ".join(others), 30),
                   title_fontsize=7)
    elif key_of is not None:
        from matplotlib.cm import ScalarMappable

        cmap, norm, label = key_of
        bar = fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=list(axes), shrink=0.8)
        bar.set_label(_wrap(label, 40))
    return fig


def _pareto_figure(frame: pd.DataFrame, cols: _Columns, objectives: list[str], every: int,
                   feasible_n: int):
    from ..study import feasible, objective_column

    chosen = [objective_column(o) for o in objectives]
    pairs = [(0, 1)] if len(chosen) == 2 else [(0, 1), (0, 2), (1, 2)]
    fig = _figure(1, len(pairs), height=3.6, width=max(6.0, 4.2 * len(pairs)))
    axes = fig.subplots(1, len(pairs), squeeze=False)[0]
    ok = feasible(frame)
    front = frame["pareto"].to_numpy(dtype=bool)
    for ax, (i, j) in zip(axes, pairs, strict=True):
        (ci, si), (cj, sj) = chosen[i], chosen[j]
        xi, xj = cols.values(frame, ci), cols.values(frame, cj)
        ax.plot(xi[~ok], xj[~ok], "x", color="0.7", ms=4, label="infeasible")
        ax.plot(xi[ok & ~front], xj[ok & ~front], "o", color="C0", ms=4, alpha=0.6,
                label="feasible")
        f = np.nonzero(front)[0]
        f = f[np.argsort(xi[f])]
        if len(chosen) == 2 and f.size:
            ax.step(xi[f], xj[f], where="post", color="C3", lw=1.0)
        ax.plot(xi[f], xj[f], "o", color="C3", ms=6, label="Pareto front")
        for k in f if f.size <= MAX_LABELS else ():
            ax.annotate(str(int(frame["point"].iloc[k])), (xi[k], xj[k]), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel(_wrap(cols.label(ci, ci) + f" ({'maximise' if si == 'max' else 'minimise'})",
                            40))
        ax.set_ylabel(_wrap(cols.label(cj, cj) + f" ({'maximise' if sj == 'max' else 'minimise'})",
                            40))
        ax.legend(loc="best")
    fig.suptitle(_wrap(f"Pareto front of {', '.join(objectives)}: {int(front.sum())} of "
                       f"{feasible_n} feasible points on it"
                       + (" (labels: point numbers)" if front.sum() <= MAX_LABELS else "")
                       + (f"; off it one point in {every} drawn" if every > 1 else "")),
                 fontsize=9)
    return fig


def check_limit(frame: pd.DataFrame, value: str, margin: str) -> float | None:
    """A ``<=`` check's limit read back from its value and margin columns (``Check.margin``
    = (limit - value) / limit), the median over the rows; None without the columns."""
    if value not in frame or margin not in frame:
        return None
    v = frame[value].to_numpy(dtype=float)
    m = frame[margin].to_numpy(dtype=float)
    with np.errstate(all="ignore"):
        limits = v / (1.0 - m)
    limits = limits[np.isfinite(limits)]
    return float(np.median(limits)) if limits.size else None


def bin_edges(lo: float, hi: float, bins: int = BINS) -> np.ndarray:
    """Edges of ``bins`` equal bars from ``lo`` to ``hi``; one bar around the value where the
    values are equal (to rounding), none without values. Never refused: the samples of a
    tolerance study may be all equal, a few distinct values, or none.

    >>> bin_edges(2.0, 2.0).tolist(), bin_edges(0.0, 0.0).tolist()
    ([1.98, 2.02], [-0.5, 0.5])
    >>> bin_edges(0.0, 1.0, 4).tolist()
    [0.0, 0.25, 0.5, 0.75, 1.0]
    >>> bin_edges(1e6, 1e6 + 1e-9).size, bin_edges(np.inf, -np.inf).size
    (2, 0)
    """
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi < lo:
        return np.zeros(0)
    scale = max(abs(lo), abs(hi))
    if hi - lo <= 1e-9 * scale or hi == lo:
        half = 0.5 if scale == 0 else max(0.5 * (hi - lo), 1e-2 * scale)  # a visible bar
        centre = 0.5 * (lo + hi)
        return np.array([centre - half, centre + half])
    return np.linspace(lo, hi, bins + 1)


def histograms(batches, columns: dict, bins: int = BINS) -> dict:
    """Histograms of the study's columns over the rows that ran, read a batch at a time
    (``batches()`` twice: the range, then the counts): ``columns`` maps a name to ``(column,
    scale, split)``, values divided by ``scale`` and, with ``split``, the negative ones counted
    apart (a margin's failing samples). Returns name -> ``(edges, counts, negative
    counts)``."""
    lo = {n: np.inf for n in columns}
    hi = {n: -np.inf for n in columns}

    def values(part, col, scale):
        ok = (part["status"] != "error").to_numpy()
        v = part[col].to_numpy(dtype=float)[ok] / scale if col in part else np.zeros(0)
        return v[np.isfinite(v)]

    for part in batches():
        for n, (col, scale, _) in columns.items():
            v = values(part, col, scale)
            if v.size:
                lo[n], hi[n] = min(lo[n], float(v.min())), max(hi[n], float(v.max()))
    out = {}
    for n in columns:
        edges = bin_edges(lo[n], hi[n], bins)
        k = max(edges.size - 1, 0)
        out[n] = (edges, np.zeros(k), np.zeros(k))
    for part in batches():
        for n, (col, scale, split) in columns.items():
            edges, counts, negative = out[n]
            if not edges.size:
                continue
            v = values(part, col, scale)
            if split:
                counts += np.histogram(v[v >= 0], bins=edges)[0]
                negative += np.histogram(v[v < 0], bins=edges)[0]
            else:
                counts += np.histogram(v, bins=edges)[0]
    return out


def _tolerance_figure(store, cols: _Columns):
    """The tolerance study's histograms, read a batch at a time."""
    from matplotlib.ticker import MaxNLocator

    from ..study.summary import SPREAD, tolerance_summary

    checks = {n: c for n, c in cols.checks.items() if "margin" in c and "passed" in c}
    needed = ["status", *SPREAD, *(c["passed"] for c in checks.values()),
              *(c["margin"] for c in checks.values()),
              *(c["value"] for c in checks.values() if "value" in c)]

    def batches():
        return store.batches(needed)

    s = tolerance_summary(batches(), {n: c["passed"] for n, c in checks.items()})
    figs = [c for c in SPREAD if c in cols.unit]
    irregularity = checks.get("irregularity", {})
    limit = None
    if "irregularity" in figs and "value" in irregularity:
        first = next(iter(batches()), None)
        if first is not None:
            ok = first["status"] != "error"
            limit = check_limit(first.loc[ok], irregularity["value"], irregularity["margin"])
    hists = histograms(batches, {**{("value", c): (c, float(cols.factor[c]), False)
                                    for c in figs},
                                 **{("margin", n): (c["margin"], 1.0, True)
                                    for n, c in checks.items()}})
    panels = len(figs) + len(checks)
    ncols = 3
    rows = max(1, math.ceil(panels / ncols))
    fig = _figure(rows, ncols, height=2.3, width=10.0)
    axes = fig.subplots(rows, ncols, squeeze=False).ravel()
    for ax, col in zip(axes, figs, strict=False):
        edges, counts, _ = hists["value", col]
        scale = float(cols.factor[col])
        if edges.size:
            ax.hist(edges[:-1], bins=edges, weights=counts, color="C0", alpha=0.8,
                    label="samples")
        sp = s["spread"].get(col)
        if sp:
            for q in ("p2.5", "p97.5"):
                ax.axvline(sp[q] / scale, color="k", ls="--", lw=0.8,
                           label="95 % of samples" if q == "p2.5" else None)
        if col == "irregularity" and limit is not None:
            ax.axvline(limit, color="C3", lw=1.2, label=f"required <= {limit:.4g}")
        ax.legend(loc="upper right", fontsize=6)
        ax.xaxis.set_major_locator(MaxNLocator(5))
        ax.set_title(_wrap(cols.label(cols.about.get(col, col), col), 40), fontsize=8)
    for ax, name in zip(axes[len(figs):], checks, strict=False):
        edges, passing, failing = hists["margin", name]
        if edges.size:
            ax.hist(edges[:-1], bins=edges, weights=passing, color="C2", alpha=0.8,
                    label="pass")
            ax.hist(edges[:-1], bins=edges, weights=failing, color="C3", alpha=0.8,
                    label="fail")
        ax.axvline(0.0, color="C3", lw=1.0)
        ax.legend(loc="upper right", fontsize=6)
        ax.xaxis.set_major_locator(MaxNLocator(5))
        c = s["checks"][name]
        ax.set_title(_wrap(f"{name}: P = {c['probability']:.3f} ({c['ci95'][0]:.3f}-"
                           f"{c['ci95'][1]:.3f})", 45), fontsize=7)
        ax.set_xlabel("margin (limit at 0)", fontsize=7)
    for ax in axes[panels:]:
        ax.set_visible(False)
    a = s["all_requirements"]
    fig.suptitle(_wrap(f"tolerance study, {s['samples']} samples: every requirement holds with "
                       f"P = {a['probability']:.3f} (95 % CI {a['ci95'][0]:.3f}-"
                       f"{a['ci95'][1]:.3f})", 110))
    return fig


def _sample(store, columns: list[str], every: int, *, keep=None) -> pd.DataFrame:
    """Every ``every``-th row of the study (and the points ``keep``), only ``columns`` (a
    column no row has, as in a study whose every point was an error, empty), read a batch at a
    time."""
    parts, seen = [], 0
    for part in store.batches(columns):
        take = (np.arange(seen, seen + len(part)) % every) == 0
        if keep is not None and len(keep):
            take |= part["point"].isin(keep).to_numpy()
        seen += len(part)
        parts.append(part.loc[take])
    frame = pd.concat(parts, ignore_index=True) if parts else pd.DataFrame()
    return frame.reindex(columns=list(dict.fromkeys(["point", *columns])))


def study_figures(store, *, max_points: int = MAX_POINTS) -> list[tuple[str, object]]:
    """The study's figures as ``(name, matplotlib Figure)``: the database read a batch at a
    time (a study of more than ``max_points`` points draws every k-th of them, said on the
    plot, its Pareto front whole; the constraints are chosen and the tolerance histograms
    counted over every row)."""
    import matplotlib

    from ..study import objective_column, pareto_points

    study = store.study()
    n = store.count()
    if not n:
        raise GovoptError(f"{store.path}: the study has no rows to plot yet")
    every = max(1, math.ceil(n / max_points))
    cols = _Columns(store)
    out: list[tuple[str, object]] = []
    with matplotlib.rc_context(STYLE):
        if study.get("tolerances"):
            out.append(("tolerance", _tolerance_figure(store, cols)))
        else:
            keys = [k for k in study.get("keys", []) if k in cols.inputs]
            combine = study.get("combine", "grid")
            margins = {n_: c for n_, c in cols.checks.items() if "margin" in c}
            cons = constraints(least_margins(store.batches(
                ["status", *(c["margin"] for c in margins.values())]), margins))
            needed = ["status", "objective", "objective_value",
                      *(cols.inputs[k] for k in keys), *(margins[c]["margin"] for c in cons)]
            frame = _sample(store, needed, every)
            drawn = keys[:1] if combine == "zip" and len(keys) > 1 else keys  # in step: one
            for key in drawn:
                out.append((f"sweep-{_slug(key)}",
                            _sweep_figure(frame, cols, key, keys, combine, cons, every)))
        if study.get("pareto"):
            front = pareto_points(store)
            frame = _sample(store, ["status", *(objective_column(o)[0]
                                                for o in study["pareto"])], every, keep=front)
            frame["pareto"] = frame["point"].isin(front).to_numpy()
            feasible_n = store.conn.execute(
                "SELECT COUNT(*) FROM points WHERE status IN ('pass', 'optimal')").fetchone()[0]
            out.append(("pareto", _pareto_figure(frame, cols, list(study["pareto"]), every,
                                                 feasible_n)))
    return out


def plot_study(store, folder: str | Path, *, overwrite: bool = False,
               max_points: int = MAX_POINTS, formats=FORMATS) -> list[Path]:
    """Draw the study in ``store`` into ``folder`` (created if missing), each plot in each of
    ``formats`` (:func:`study_figures`); returns the files."""
    from .plot_files import save_figure  # as every plot is written (an SVG without a date)

    folder = check_plot_folder(folder)
    figures = study_figures(store, max_points=max_points)
    folder.mkdir(exist_ok=True)
    out: list[Path] = []
    for name, fig in figures:
        out += save_figure(fig, folder / name, overwrite, formats)
    return out
