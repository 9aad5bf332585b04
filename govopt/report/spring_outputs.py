"""The files of `govopt spring`: a workbook with the spring maker's sheet, and the
plots, a force-length diagram and the fatigue (Goodman/Haigh) diagram of the load cycle.

They read the sized spring and its checks (:class:`govopt.result.Check`) and never recompute
the design: the maker's sheet is :mod:`govopt.springs.sheet`'s, the fatigue diagram
:func:`govopt.springs.fatigue.body_locus` drawn by :func:`govopt.report.plots.fatigue`, the
numbers in engineering units by :func:`govopt.report.excel.engineering`; files are written
atomically after the checks of :mod:`govopt.report.files` (nothing half-written, nothing
replaced without ``--replace``).
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from ..errors import GovoptError
from ..springs import extension as he
from ..springs import fatigue as ft
from ..springs import sheet as sh

#: the plots `govopt spring --plots` writes (``fatigue`` only with a fatigue load cycle)
PLOTS = ("force-length", "fatigue")


def maker_sheet(outcome) -> sh.SpringSheet | None:
    """The spring maker's sheet of the spring (EN 15800 grade 2 tolerances; a grade is needed
    for the wire standard and its tolerances: None without one)."""
    a = outcome.assessment
    if outcome.values.get("material") is None:
        return None
    sp, mat, loads = a.spring, a.mat, a.loads
    surface = "shot peened" if a.rules.peened else "not shot peened"
    if sp.kind == "compression":
        return sh.compression_sheet(mat, sp.d, sp.D, sp.coils, sp.total_coils, sp.L0,
                                    loads.F1, loads.F2, ends=sp.form, surface=surface)
    return sh.extension_sheet(mat, sp.d, sp.D, sp.coils, sp.F0, loads.F1, loads.F2,
                              hooks=he.HOOKS[sp.form].source.split(",")[0], surface=surface)


def fatigue_cycle(outcome) -> dict | None:
    """The fatigue load cycle's corrected (Bergstraesser) stresses and the body's diagram, a
    record of figures (the assessment's, :func:`govopt.springs.fatigue.cycle_figures`) as a
    governor's spring report holds it, which :func:`govopt.report.plots.fatigue` reads (None
    without a cycle or a grade)."""
    a = outcome.assessment
    if a.loads.cycle is None or outcome.values.get("material") is None:
        return None
    cycle = {k: f for k, f in a.sections["fatigue"].items()
             if k not in ("safety factor", "life")}
    return cycle | {"diagram": ft.body_locus(a.mat, a.spring.d, a.rules.method,
                                             a.rules.peened)}


def force_length(outcome, ax) -> None:
    """Force against length from the assessment's working points: a compression spring's line
    ``F = R (L0 - L)`` from its free length to its solid length ``L_c`` with the least working
    length ``L_n`` (EN 13906-1); an extension spring's ``F = F0 + R (L - L0)`` from its free
    length to past L2; the working points L1 (where a least force is given) and L2 marked,
    not the free length (the spring does not work there). In the units the input used."""
    a, shown = outcome.assessment, outcome.shown
    pts = {p["point"].value: p for p in a.points}
    R = a.value("rate")
    L0 = a.spring.L0
    lu, fu = shown(0.0, "m")[1], shown(0.0, "N")[1]

    def L(x):
        return shown(x, "m")[0]

    def F(x):
        return shown(x, "N")[0]
    if a.spring.kind == "compression":
        Lc, Ln = a.value("solid length"), a.value("least working length")
        x = np.array([L0, Lc])
        ax.plot(L(x), F(R * (L0 - x)), color="tab:blue", lw=2,
                label=f"F = R (L0 - L), R = {shown.text(R, 'N/m', 4)}")
        ax.axvline(L(Lc), color="k", lw=1, label=f"solid length L_c {shown.text(Lc, 'm', 4)}")
        ax.axvline(L(Ln), color="tab:red", ls="--", lw=1,
                   label=f"least working length L_n {shown.text(Ln, 'm', 4)}")
        ax.invert_xaxis()  # compressing: the length falls as the force rises
    else:
        F0, L2 = a.spring.F0, pts["L2"]["length"].value
        x = np.array([L0, L0 + 1.1 * (L2 - L0)])
        ax.plot(L(x), F(F0 + R * (x - L0)), color="tab:blue", lw=2,
                label=f"F = F0 + R (L - L0), F0 = {shown.text(F0, 'N', 4)}")
    for key in ("L1", "L2"):
        if key in pts and not math.isnan(pts[key]["length"].value):  # (past solid: no point)
            p = pts[key]
            length, force = p["length"].value, p["force"].value
            ax.plot(L(length), F(force), "o", color="tab:orange", mec="k",
                    label=f"{key}, F{key[1]}: {shown.text(length, 'm', 4)}, "
                          f"{shown.text(force, 'N', 4)}")
    ax.set_xlabel(f"spring length L ({lu})")
    ax.set_ylabel(f"force F ({fu})")
    ax.set_ylim(bottom=0.0)
    ax.set_title(f"{outcome.name}: force against length")
    ax.legend(loc="best", fontsize=8)


def _plot_input(outcome):
    """What :func:`govopt.report.plots.fatigue` reads of a Result: the fatigue load cycle
    (``spring_report.loads``), the checks and the name."""
    return SimpleNamespace(spring_report=SimpleNamespace(loads={"fatigue": fatigue_cycle(
        outcome)}), checks=outcome.checks, spec=SimpleNamespace(name=outcome.name))


def plot_names(outcome) -> list[str]:
    """The plots this spring has (the fatigue diagram needs a grade and a load cycle)."""
    return [k for k in PLOTS if k != "fatigue" or fatigue_cycle(outcome) is not None]


def planned(xlsx, plots, stem: str, output=None) -> list[tuple[Path, str]]:
    """Every file a run may write, with what it is: the design's spec (``-o``), the workbook,
    each plot in each format (the folder made if only its parent exists)."""
    from .files import output_folder

    paths = [(Path(p), what) for p, what in ((output, "spring spec"), (xlsx, "workbook"))
             if p is not None]
    if plots is not None:
        for path, what in paths:
            if os.path.realpath(path) == os.path.realpath(plots):
                raise GovoptError(f"{path}: cannot write {what}: it is the plots folder of "
                                  "this run")
        folder = output_folder(Path(plots), "plots")
        paths += [(folder / f"{stem}-{k}.{fmt}", "plot") for k in PLOTS for fmt in ("png", "svg")]
    return paths


def check_outputs(xlsx, plots, stem: str, *, replace: bool, inputs=(), output=None) -> None:
    """Before the run: every output of it (:func:`planned`) checked against the input and
    against each other by :func:`govopt.report.files.check_planned` (the rule of `govopt
    evaluate` and `design`), and it exists only if ``replace``. Raises :class:`GovoptError`
    with one line."""
    from .files import check_planned

    check_planned(planned(xlsx, plots, stem, output), overwrite=replace, inputs=inputs)


def write_plots(outcome, folder, stem: str, *, replace: bool = True) -> list[Path]:
    """``<folder>/<stem>-<kind>.png|svg`` of every plot (:func:`plot_names`), atomically (an
    existing file replaced only with ``replace``)."""
    import matplotlib as mpl

    from . import plots
    from .plot_files import save_figure

    written = []
    for kind in plot_names(outcome):
        with mpl.rc_context(plots.STYLE):
            ax = plots.new_axes()
            if kind == "force-length":
                force_length(outcome, ax)
            else:
                plots.fatigue(_plot_input(outcome), ax)
        written += save_figure(ax.figure, Path(folder) / f"{stem}-{kind}", overwrite=replace)
    return written


def workbook_rows(outcome) -> list[tuple[str, object, str]]:
    """The Spring sheet's rows, answer first: (label, SI value or text, SI unit); a section
    title has the value None and the unit ``"section"``: the spring, what it does, the
    optimiser's record (where one), the load cycle."""
    a, rec = outcome.assessment, outcome.record
    rows: list[tuple[str, object, str]] = [("Answer", None, "section")]
    for section in ("spring", "lengths and energy", "dynamics"):
        rows += [(_label(f), f.value, f.unit) for f in a.sections[section].values()
                 if not _missing(f.value)]
    if rec is not None:
        obj = rec.objective
        rows += [("Optimisation", None, "section"),
                 (f"objective: {obj.name} ({obj.sense})", rec.value, obj.unit),
                 (f"certified {'lower' if obj.sense == 'minimise' else 'upper'} bound",
                  rec.bound, obj.unit), ("claim", rec.claim(), ""),
                 ("method", rec.method, ""),
                 ("active", ", ".join(rec.active) or "none", "")]
        rows += [(f"sensitivity: +1 % on {k} (% {obj.name})", v, "")
                 for k, v in rec.sensitivities.items()]
    if a.loads.cycle is not None:
        rows.append(("Fatigue load cycle", None, "section"))
        rows += [(_label(f), f.value, f.unit) for f in a.sections["fatigue"].values()
                 if not (isinstance(f.value, float) and math.isnan(f.value))]
    return rows


def _missing(value) -> bool:
    return isinstance(value, float) and math.isnan(value)


def _label(f) -> str:
    return f.name + (f" {f.symbol}" if f.symbol else "")


def write_workbook(outcome, path, *, replace: bool = True, command: str = "") -> Path:
    """The workbook (:func:`govopt.report.excel.spring.spring_workbook`: a Summary with the
    command, version, date, verdict and the answer, the spring maker's sheet, the checks, the
    force-length table with its chart and the inputs with their meanings), written atomically
    (an existing file replaced only with ``replace``)."""
    from .excel.spring import spring_workbook

    return spring_workbook(outcome, path, rows=workbook_rows(outcome),
                           sheet=maker_sheet(outcome), points=force_length_points(outcome),
                           replace=replace, command=command)


def force_length_points(outcome) -> list[tuple[str, float, float]]:
    """``(name, length m, force N)`` of the assessment's working points: the free length, L1,
    L2 and a compression spring's least working and solid lengths; a point equal to the one
    before it (no least force: the first working point is the free length) once; a force the
    spring never reaches (past solid: no length) left out, as the report's note says."""
    out: list[tuple[str, float, float]] = []
    for p in outcome.assessment.points:
        name, L, F = str(p["point"].value), float(p["length"].value), float(p["force"].value)
        if math.isnan(L):
            continue
        if out and math.isclose(out[-1][1], L, rel_tol=1e-12) and \
                math.isclose(out[-1][2], F, rel_tol=1e-12, abs_tol=1e-12):
            continue
        out.append((name, L, F))
    return out


def write_check_spec(outcome, path, *, replace: bool = True, drawing=None) -> Path:
    """The spring as a spec for `govopt spring check` (its geometry, material, loads and
    rules), in the units the input was written in; each number at the shortest precision that
    reads back to the same float (checking it reproduces the design's report, without the
    optimiser's record), or with ``drawing`` the spring's lengths as a drawing gives them
    (:func:`drawn_length`; the command chose them so that the spring read back passes the
    checks the design passes)."""
    from .files import atomic_write

    text = check_spec_text(outcome, drawing)
    return atomic_write(Path(path), lambda tmp: Path(tmp).write_text(text, encoding="utf-8"),
                        overwrite=replace, what="spring spec")


def drawn_length(shown, value: float, digits: int, way: int = 0) -> tuple[float, float]:
    """A length as a drawing gives it: ``digits`` significant digits in the shown unit, the
    last one rounded to the nearest (``way`` 0), up (1) or down (-1); ``(the number shown,
    its value in m)``.

    >>> from govopt.report.spring_report import Shown
    >>> drawn_length(Shown(), 0.0954426, 4), drawn_length(Shown(), 0.0954426, 4, way=1)[0]
    ((95.44, 0.09544), 95.45)
    """
    x, _ = shown(value, "m")
    r = float(f"{x:.{digits - 1}e}")
    if way and (r - x) * way < 0:  # rounded the other way: one unit of the last digit on
        unit = 10.0 ** (int(f"{x:.{digits - 1}e}".split("e")[1]) - digits + 1)
        r = float(f"{r + way * unit:.{digits - 1}e}")
    return r, r * shown.table.get("m", ("m", 1.0))[1]


def check_spec_text(outcome, drawing=None) -> str:
    """The TOML of :func:`write_check_spec`; ``drawing``: ``(digits, ways)``, the lengths as a
    drawing gives them (:func:`drawn_length`; ``ways`` the rounding of the wire diameter, the
    mean diameter and the free length)."""
    a, v, shown = outcome.assessment, outcome.values, outcome.shown
    sp = a.spring
    ways = dict(zip(("d", "D", "L0"), drawing[1], strict=True)) if drawing else {}

    def q(value, si, length=None):
        x, unit = shown(value, si)
        if drawing is not None and length is not None:
            x = drawn_length(shown, value, drawing[0], ways[length])[0]
        return f'"{x!r} {unit}"'

    name = outcome.name.replace('"', "'")
    lines = [f'name = "{name}"',
             'description = "written by govopt spring -o: check it with govopt spring check"',
             "", "[spring]", f'kind = "{sp.kind}"', f"wire_diameter = {q(sp.d, 'm', 'd')}",
             f"mean_diameter = {q(sp.D, 'm', 'D')}"]
    if sp.kind == "compression":
        lines += [f"active_coils = {sp.coils!r}", f"total_coils = {sp.total_coils!r}",
                  f'ends = "{sp.form}"']
    else:
        lines += [f"total_coils = {sp.coils!r}  # the body's", f'loops = "{sp.form}"',
                  f"initial_tension = {q(sp.F0, 'N')}"]
    lines.append(f"free_length = {q(sp.L0, 'm', 'L0')}")
    # the grade given, or a catalogue's spring's own (its row names it)
    material = v.get("material") or (a.mat.grade if v.get("catalogue") else None)
    if material is not None:
        lines.append(f'material = "{material}"')
    for key, si in (("tensile_strength", "Pa"), ("shear_modulus", "Pa"),
                    ("allowable_stress", "Pa")):
        if v.get(key) is not None:
            lines.append(f"{key} = {q(v[key], si)}")
    if v.get("density") is not None or material is None:
        lines.append(f'density = "{a.mat.density!r} kg/m^3"')
    lines.append(f"force = {q(a.loads.F2, 'N')}")
    if a.loads.F1 > 0:
        lines.append(f"min_force = {q(a.loads.F1, 'N')}")
    if a.loads.cycle is not None:
        lines += [f"fatigue_min_force = {q(a.loads.cycle[0], 'N')}",
                  f"fatigue_max_force = {q(a.loads.cycle[1], 'N')}"]
    r = a.rules
    lines += [f'rules = "{r.method}"', f"peened = {str(r.peened).lower()}",
              f'load = "{"dynamic" if r.dynamic else "static"}"', f'seating = "{r.seating}"',
              f"index_min = {float(r.index[0])!r}",
              f"index_max = {float(r.index[1])!r}", f"min_fatigue_safety = {r.fatigue_safety!r}",
              f"life = {float(r.cycles)!r}"]
    if v.get("correction") is not None or material is None:
        lines.append(f'correction = "{r.correction}"')
    return "\n".join(lines) + "\n"
