"""Plots of a trade study (matplotlib, PNG and SVG), drawn from its database's table.

* ``sweep-<key>``: for each swept key, the objective and the margin of each constraint that
  binds or fails somewhere in the study (``Check.margin``: 0 is the limit, negative fails),
  against the key's value in SI; with several keys, one line per combination of the others;
  zipped keys move together, so one plot against the first, the others named on its axis;
* ``pareto``: the Pareto front of the study's objectives (two, or the three pairs of three)
  among the feasible points, the front joined as a staircase;
* ``tolerance``: for a tolerance study, histograms of the speed range, the irregularity and
  ``k^2`` at the normal configuration (the irregularity's requirement marked), and of each
  requirement's margin with the limit at 0 (failing samples red).

Nothing here recomputes physics; files go through :func:`govopt.report.files.atomic_write`.
"""

from __future__ import annotations

import math
import re
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
RPM = 30.0 / math.pi


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

    return Figure(figsize=(width, 0.6 + height * rows), dpi=DPI, layout="constrained"), rows, cols


def _save(fig, folder: Path, name: str, overwrite: bool, formats=FORMATS) -> list[Path]:
    from .plot_files import save_figure  # as every plot is written (an SVG without a date)

    return save_figure(fig, folder / name, overwrite, formats)


def _slug(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "-", text).strip("-")


def _axis(frame: pd.DataFrame, key: str):
    """``(values, label, ticks)`` of a swept key: the numbers as written where every value is
    written in one unit (``12 kgf``), else its SI column, else positions of its written values
    (with them as tick labels)."""
    written = frame[key]
    parts = written.astype(str).str.extract(r"^\s*([-+]?[0-9.]+(?:[eE][-+]?\d+)?)\s*(.*)$")
    if parts[0].notna().all() and parts[1].nunique() == 1:
        unit = parts[1].iloc[0]
        return parts[0].astype(float).to_numpy(), f"{key} [{unit}]" if unit else key, None
    si = [c for c in frame.columns if c.startswith(f"{key} [")]
    if si:
        v = pd.to_numeric(frame[si[0]], errors="coerce").to_numpy(dtype=float)
        if np.isfinite(v).any():
            return v, si[0], None
    cats = pd.unique(written.astype(str))
    pos = {c: i for i, c in enumerate(cats)}
    return np.array([pos[str(v)] for v in written], dtype=float), key, list(cats)


def _least_margins(frames) -> dict[str, float]:
    """Each check's least margin over the rows of ``frames`` (a table's batches)."""
    from ..bulk import check_names, margin_column

    least: dict[str, float] = {}
    for frame in frames:
        for n in check_names(frame.columns):
            m = np.nanmin(pd.to_numeric(frame[margin_column(n)], errors="coerce")
                          .to_numpy(dtype=float), initial=np.inf)
            least[n] = min(least.get(n, np.inf), float(m))
    return least


def _constraints(frame: pd.DataFrame | None, least: dict[str, float] | None = None
                 ) -> list[str]:
    """The checks to draw: those active (satisfied within ``ACTIVE_TOL``) or failed in some row,
    closest to their limit first; if none, the three closest. ``least``: each check's least
    margin over the whole study (:func:`_least_margins`), else over ``frame``'s rows."""
    least = _least_margins([frame]) if least is None else least
    names = list(least)
    binding = [n for n in names if least[n] < ACTIVE_TOL]
    chosen = binding or sorted(names, key=lambda n: least[n])[:3]
    return sorted(chosen, key=lambda n: least[n])[:MAX_CONSTRAINTS]


def _series(ax, frame, others, y, x, ticks, label_points=False):
    """Draw ``y`` against the key: a line per combination of the other keys of a grid (a legend
    for up to 6), else points (numbered for a short study); hollow where a check fails."""
    ok = frame["status"].isin(["pass", "optimal"]).to_numpy()
    groups = frame.groupby([frame[o].astype(str) for o in others], sort=False).indices \
        if others else {"": np.arange(len(frame))}
    lines = bool(others) and len(groups) <= 10
    for gi, (name, idx) in enumerate(groups.items()):
        idx = np.asarray(idx)
        order = idx[np.argsort(x[idx], kind="stable")]
        color = f"C{gi % 10}" if others else "C0"
        label = None
        if lines and len(groups) <= 6:
            label = ", ".join(f"{o} = {v}" for o, v in zip(
                others, name if isinstance(name, tuple) else (name,), strict=True))
        if lines:
            ax.plot(x[order], y[order], "-", color=color, lw=1.0, alpha=0.7, label=label)
        good, bad = order[ok[order]], order[~ok[order]]
        ax.plot(x[good], y[good], "o", color=color, ms=4)
        ax.plot(x[bad], y[bad], "o", mfc="none", color=color, ms=4)
    if label_points:
        for i in range(len(frame)):
            if np.isfinite(y[i]):
                ax.annotate(str(int(frame["point"].iloc[i])), (x[i], y[i]), fontsize=7,
                            xytext=(3, 2), textcoords="offset points")
    if ticks is not None:
        ax.set_xticks(range(len(ticks)), ticks, rotation=20)
    return lines and len(groups) <= 6


def _sweep_figure(frame: pd.DataFrame, key: str, keys: list[str], combine: str,
                  cons: list[str] | None = None, every: int = 1):
    """``cons``: the constraints to draw (:func:`_constraints` of ``frame``); ``every``: the
    frame holds every ``every``-th point of the study (said in the title)."""
    from ..bulk import margin_column

    x, xlabel, ticks = _axis(frame, key)
    others = [k for k in keys if k != key and frame[k].astype(str).nunique() > 1] \
        if combine == "grid" else []
    few = not others and len(frame) <= 12
    cons = _constraints(frame) if cons is None else cons
    fig, rows, _ = _figure(1 + len(cons))
    axes = fig.subplots(rows, 1, sharex=True, squeeze=False)[:, 0]
    obj = str(frame["objective"].dropna().iloc[0]) if frame["objective"].notna().any() \
        else "objective"
    y = pd.to_numeric(frame["objective_value"], errors="coerce").to_numpy(dtype=float)
    if _series(axes[0], frame, others, y, x, ticks, few):
        axes[0].legend(loc="best", fontsize=7)
    from ..bulk import OBJECTIVE_COLUMN

    axes[0].set_ylabel(OBJECTIVE_COLUMN.get(obj, obj))
    note = ("; labels: point numbers" if few else "") + (
        f"; one point in {every} drawn" if every > 1 else "")
    axes[0].set_title(f"objective and binding constraints (hollow: fails a check{note})",
                      fontsize=9)
    for ax, name in zip(axes[1:], cons, strict=True):
        m = pd.to_numeric(frame[margin_column(name)], errors="coerce").to_numpy(dtype=float)
        _series(ax, frame, others, m, x, ticks, few)
        ax.axhline(0.0, color="k", lw=0.8)
        lo = min(np.nanmin(m, initial=0.0), 0.0)
        span = (np.nanmax(m, initial=0.0) - lo) or 1.0
        ax.axhspan(lo - 0.1 * span, 0.0, color="tab:red", alpha=0.08, lw=0)
        ax.set_ylabel("margin")
        ax.set_title(f"{name} (margin < 0: fails)", loc="left", fontsize=8)
    together = [k for k in keys if k != key] if combine == "zip" else []
    axes[-1].set_xlabel(xlabel + (f"; in step with it: {', '.join(together)}"
                                  if together else ""))
    return fig


#: points on a Pareto front labelled with their numbers at most (more would overlap)
MAX_LABELS = 30


def _pareto_figure(frame: pd.DataFrame, objectives: list[str], every: int = 1):
    from ..study import feasible, objective_column

    cols = [objective_column(o) for o in objectives]
    pairs = [(0, 1)] if len(cols) == 2 else [(0, 1), (0, 2), (1, 2)]
    fig, rows, _ = _figure(1, len(pairs), height=3.6, width=max(6.0, 4.2 * len(pairs)))
    axes = fig.subplots(1, len(pairs), squeeze=False)[0]
    ok = feasible(frame)
    front = frame["pareto"].to_numpy(dtype=bool)
    for ax, (i, j) in zip(axes, pairs, strict=True):
        (ci, si), (cj, sj) = cols[i], cols[j]
        xi = pd.to_numeric(frame[ci], errors="coerce").to_numpy(dtype=float)
        xj = pd.to_numeric(frame[cj], errors="coerce").to_numpy(dtype=float)
        ax.plot(xi[~ok], xj[~ok], "x", color="0.7", ms=4, label="infeasible")
        ax.plot(xi[ok & ~front], xj[ok & ~front], "o", color="C0", ms=4, alpha=0.6,
                label="feasible")
        f = np.nonzero(front)[0]
        f = f[np.argsort(xi[f])]
        if len(cols) == 2 and f.size:
            ax.step(xi[f], xj[f], where="post", color="C3", lw=1.0)
        ax.plot(xi[f], xj[f], "o", color="C3", ms=6, label="Pareto front")
        for k in f if f.size <= MAX_LABELS else ():
            ax.annotate(str(int(frame["point"].iloc[k])), (xi[k], xj[k]), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel(f"{ci} ({'maximise' if si == 'max' else 'minimise'})")
        ax.set_ylabel(f"{cj} ({'maximise' if sj == 'max' else 'minimise'})")
        ax.legend(loc="best")
    feasible_n = int(ok.sum()) if every == 1 else int(frame.attrs["feasible"])
    fig.suptitle(f"Pareto front of {', '.join(objectives)}\n{int(front.sum())} of "
                 f"{feasible_n} feasible points on it"
                 + (" (labels: point numbers)" if front.sum() <= MAX_LABELS else "")
                 + (f"; off it one point in {every} drawn" if every > 1 else ""), fontsize=9)
    return fig


def check_limit(frame: pd.DataFrame, check: str) -> float | None:
    """A ``<=`` check's limit read back from its value column and margin (``Check.margin`` =
    (limit - value) / limit), the median over the rows; None without the columns."""
    from ..bulk import margin_column

    if check not in frame or margin_column(check) not in frame:
        return None
    v = pd.to_numeric(frame[check], errors="coerce").to_numpy(dtype=float)
    m = pd.to_numeric(frame[margin_column(check)], errors="coerce").to_numpy(dtype=float)
    limits = v / (1.0 - m)
    limits = limits[np.isfinite(limits)]
    return float(np.median(limits)) if limits.size else None


def _histograms(batches, columns: dict, bins: int = 40) -> dict:
    """Histograms of the study's columns over the rows that ran, read a batch at a time
    (``batches()`` twice: the range, then the counts): ``columns`` maps a name to ``(column,
    split)``, ``split`` counting the negative values apart (a margin's failing samples). Returns
    name -> ``(edges, counts, negative counts)``; the edges are ``numpy.histogram``'s over all
    the values (``bins`` between the least and the largest)."""
    lo = {n: np.inf for n in columns}
    hi = {n: -np.inf for n in columns}

    def values(part, col):
        ok = (part["status"] != "error").to_numpy()
        v = pd.to_numeric(part.loc[ok, col], errors="coerce").to_numpy(dtype=float)
        return v[np.isfinite(v)]

    for part in batches():
        for n, (col, _) in columns.items():
            v = values(part, col)
            if v.size:
                lo[n], hi[n] = min(lo[n], float(v.min())), max(hi[n], float(v.max()))
    out = {}
    for n in columns:
        span = np.array([lo[n], hi[n]]) if np.isfinite(lo[n]) else np.zeros(0)
        edges = np.histogram_bin_edges(span, bins=bins)
        out[n] = (edges, np.zeros(bins), np.zeros(bins))
    for part in batches():
        for n, (col, split) in columns.items():
            v = values(part, col)
            edges, counts, negative = out[n]
            if split:
                counts += np.histogram(v[v >= 0], bins=edges)[0]
                negative += np.histogram(v[v < 0], bins=edges)[0]
            else:
                counts += np.histogram(v, bins=edges)[0]
    return out


def _tolerance_figure(source):
    """The tolerance study's histograms; ``source``: its table, or a callable returning its
    batches (:meth:`govopt.study.Store.batches`: read a batch at a time, three times)."""
    from ..bulk import check_names, margin_column
    from ..study import tolerance_summary

    batches = (lambda: [source]) if isinstance(source, pd.DataFrame) else source
    s = tolerance_summary(batches())
    from matplotlib.ticker import MaxNLocator

    labels = {"omega_inner_rad_s": "innermost speed [rpm]", "omega_outer_rad_s":
              "outermost speed [rpm]", "irregularity": "irregularity",
              "k2_normal_rad2_s2": "k^2 at the normal configuration [1/s^2]"}
    first = next(iter(batches()))
    figs = [(c, RPM, "rpm") for c in ("omega_inner_rad_s", "omega_outer_rad_s") if c in first]
    figs += [(c, 1.0, "") for c in ("irregularity", "k2_normal_rad2_s2") if c in first]
    names = check_names(first.columns)
    ok_first = first["status"] != "error"
    limit = check_limit(first.loc[ok_first], "irregularity") if any(
        c == "irregularity" for c, _, _ in figs) else None
    hists = _histograms(batches, {**{("value", c): (c, False) for c, _, _ in figs},
                                  **{("margin", n): (margin_column(n), True) for n in names}})
    panels = len(figs) + len(names)
    cols = 3
    rows = math.ceil(panels / cols)
    fig, _, _ = _figure(rows, cols, height=2.2, width=10.0)
    axes = fig.subplots(rows, cols, squeeze=False).ravel()
    for k, (ax, (col, scale, _unit)) in enumerate(zip(axes, figs, strict=False)):
        edges, counts, _ = hists["value", col]
        ax.hist(edges[:-1] * scale, bins=edges * scale, weights=counts, color="C0", alpha=0.8)
        sp = s["spread"].get(col)
        if sp:
            for q in ("p2.5", "p97.5"):
                ax.axvline(sp[q] * scale, color="k", ls="--", lw=0.8)
        if col == "irregularity" and limit is not None:
            ax.axvline(limit, color="C3", lw=1.2)
            ax.annotate(f"required <= {limit:.4g}", (limit, 1.0), xycoords=("data", "axes "
                        "fraction"), xytext=(-3, -3), textcoords="offset points", ha="right",
                        va="top", fontsize=7, color="C3")
        ax.xaxis.set_major_locator(MaxNLocator(5))
        ax.set_title(labels[col] + (" (dashed: 95 % of samples)" if k == 0 else ""),
                     fontsize=8)
    for ax, name in zip(axes[len(figs):], names, strict=False):
        edges, passing, failing = hists["margin", name]
        ax.hist(edges[:-1], bins=edges, weights=passing, color="C2", alpha=0.8, label="pass")
        if failing.any():  # failing samples in red, beside the passing ones' green
            ax.hist(edges[:-1], bins=edges, weights=failing, color="C3", alpha=0.8,
                    label="fail")
            ax.legend(loc="upper right", fontsize=7)
        ax.axvline(0.0, color="C3", lw=1.0)
        ax.xaxis.set_major_locator(MaxNLocator(5))
        c = s["checks"][name]
        ax.set_title(f"{name}: P = {c['probability']:.3f} ({c['ci95'][0]:.3f}-"
                     f"{c['ci95'][1]:.3f})", fontsize=7)
        ax.set_xlabel("margin (limit at 0)", fontsize=7)
    for ax in axes[panels:]:
        ax.set_visible(False)
    a = s["all_requirements"]
    fig.suptitle(f"tolerance study, {s['samples']} samples: every requirement holds with "
                 f"P = {a['probability']:.3f} (95 % CI {a['ci95'][0]:.3f}-{a['ci95'][1]:.3f})")
    return fig


#: rows drawn per plot at most: a larger study is drawn from every k-th point (the Pareto
#: front always whole), its constraints chosen and its histograms counted over every row
MAX_POINTS = 20_000


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


def plot_study(store, folder: str | Path, *, overwrite: bool = False,
               max_points: int = MAX_POINTS, formats=FORMATS) -> list[Path]:
    """Draw the study in ``store`` into ``folder`` (created if missing), each plot in each of
    ``formats``; returns the files.
    The database is read a batch at a time (:meth:`govopt.study.Store.batches`): the plots of
    a study of more than ``max_points`` points draw every k-th of them (said on the plot),
    its Pareto front whole; the constraints are chosen and the tolerance histograms counted
    over every row."""
    import matplotlib

    from ..bulk import check_names, margin_column, passed_column
    from ..study import SPREAD, objective_column

    folder = check_plot_folder(folder)
    study = store.meta("study") or {}
    n = store.count()
    if not n:
        raise GovoptError(f"{store.path}: the study has no rows to plot yet")
    folder.mkdir(exist_ok=True)
    every = max(1, math.ceil(n / max_points))
    columns = store.columns()
    checks = check_names(columns)
    out: list[Path] = []
    with matplotlib.rc_context(STYLE):
        if study.get("tolerances"):
            needed = ["status", *SPREAD, *(passed_column(c) for c in checks),
                      *(margin_column(c) for c in checks), *checks]
            out += _save(_tolerance_figure(lambda: store.batches(needed)), folder, "tolerance",
                         overwrite, formats)
        else:
            keys = [k for k in study.get("keys", []) if k in columns]
            combine = study.get("combine", "grid")
            cons = _constraints(None, _least_margins(store.batches(
                ["status", *(margin_column(c) for c in checks)])))
            needed = ["status", "objective", "objective_value", *keys,
                      *(c for c in columns if any(c.startswith(f"{k} [") for k in keys)),
                      *(margin_column(c) for c in cons)]
            frame = _sample(store, needed, every)
            drawn = keys[:1] if combine == "zip" and len(keys) > 1 else keys  # in step: one
            for key in drawn:
                out += _save(_sweep_figure(frame, key, keys, combine, cons, every),
                             folder, f"sweep-{_slug(key)}", overwrite, formats)
        if study.get("pareto"):
            front = store.pareto()
            frame = _sample(store, ["status", *(objective_column(o)[0]
                                                for o in study["pareto"])], every, keep=front)
            frame["pareto"] = frame["point"].isin(front).to_numpy()
            frame.attrs["feasible"] = store.conn.execute(
                "SELECT COUNT(*) FROM points WHERE status IN ('pass', 'optimal')").fetchone()[0]
            out += _save(_pareto_figure(frame, study["pareto"], every), folder, "pareto",
                         overwrite, formats)
    return out
