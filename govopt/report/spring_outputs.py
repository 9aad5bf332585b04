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
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from ..springs import fatigue as ft
from ..springs import helical as hx
from ..springs import materials as mt
from ..springs import sheet as sh

#: the plots `govopt spring --plots` writes (``fatigue`` only with a fatigue load cycle)
PLOTS = ("force-length", "fatigue")


def material(v: dict) -> mt.Material | None:
    """The wire grade of the options (None without ``material``), as the sizing built it."""
    if v.get("material") is None:
        return None
    return mt.material(v["material"], tensile_strength=v.get("tensile_strength"),
                       G=v.get("shear_modulus"), density=v.get("density"))


def maker_sheet(sizing, v: dict) -> sh.SpringSheet | None:
    """The spring maker's sheet of the sized spring (EN 15800 grade 2 tolerances; a grade is
    needed for the wire standard and its tolerances: None without one)."""
    mat = material(v)
    if mat is None:
        return None
    sol = sizing.solution
    d, D, n = sol.d, 2.0 * sol.r, sol.n
    F1, F2 = v.get("min_force") or 0.0, v["force"]
    surface = "shot peened" if v["peened"] else "not shot peened"
    if sizing.kind == "compression":
        return sh.compression_sheet(mat, d, D, n, n + sol.end_coils, sizing.free_length, F1, F2,
                                    ends=v["ends"], surface=surface)
    G, E = float(mat.shear_modulus(d)), float(mat.elastic_modulus(d))
    return sh.extension_sheet(mat, d, D, n - G / E, sizing.initial_tension, F1, F2,
                              surface=surface)


def fatigue_cycle(sizing, v: dict) -> dict | None:
    """The fatigue load cycle's corrected (Bergstraesser) stresses and the body's diagram, a
    record of figures (:func:`govopt.springs.fatigue.cycle_figures`) as a governor's spring
    report holds it, which :func:`govopt.report.plots.fatigue` reads (None without a cycle or a
    grade)."""
    mat = material(v)
    if mat is None or v.get("fatigue_min_force") is None:
        return None
    sol = sizing.solution
    d, D = sol.d, 2.0 * sol.r
    K = hx.bergstrasser_factor(hx.spring_index(d, D))
    forces = v["fatigue_min_force"], v["fatigue_max_force"]
    return ft.cycle_figures(*forces, *(float(K * hx.shear_stress(f, d, D)) for f in forces)
                            ) | {"diagram": ft.body_locus(mat, d, v["rules"], v["peened"])}


def force_length(sizing, v: dict, ax, name: str) -> None:
    """Force against length: the line ``F = R (L0 - L)`` of a compression spring from its free
    length to its solid length ``L_c``, the working points (L1, F1) and (L2, F2), the least
    working length ``L_n = L_c + S_a`` (EN 13906-1); an extension spring's ``F = F0 + R (L -
    L0)`` from its free length (initial tension F0) to past L2. mm and N."""
    R, F1, F2 = sizing.solution.stiffness, v.get("min_force") or 0.0, v["force"]
    L0 = sizing.free_length  # the sizing's lengths (spring_sizing.lengths), as the workbook's
    if sizing.kind == "compression":
        Lc, Ln = sizing.solid_length, sizing.least_length
        L = np.array([L0, Lc])
        ax.plot(L * 1e3, R * (L0 - L), color="tab:blue", lw=2,
                label=f"F = R (L0 - L), R = {R * 1e-3:.4g} N/mm")
        ax.axvline(Lc * 1e3, color="k", lw=1, label=f"solid length L_c {Lc * 1e3:.4g} mm")
        ax.axvline(Ln * 1e3, color="tab:red", ls="--", lw=1,
                   label=f"least working length L_n {Ln * 1e3:.4g} mm")
        points = ((L0 - F1 / R, F1, "L1, F1"), (L0 - F2 / R, F2, "L2, F2"))
        ax.invert_xaxis()  # compressing: the length falls as the force rises
    else:
        F0 = _initial_tension(sizing)
        L2 = L0 + (F2 - F0) / R
        L = np.array([L0, L0 + 1.1 * (L2 - L0)])
        ax.plot(L * 1e3, F0 + R * (L - L0), color="tab:blue", lw=2,
                label=f"F = F0 + R (L - L0), F0 = {F0:.4g} N")
        points = ((L0 + (F1 - F0) / R, F1, "L1, F1"), (L2, F2, "L2, F2"))
    for x, f, label in points:
        ax.plot(x * 1e3, f, "o", color="tab:orange", mec="k",
                label=f"{label}: {x * 1e3:.4g} mm, {f:.4g} N")
    ax.set_xlabel("spring length L (mm)")
    ax.set_ylabel("force F (N)")
    ax.set_ylim(bottom=0.0)
    ax.set_title(f"{name}: force against length")
    ax.legend(loc="best", fontsize=8)


def _plot_input(outcome):
    """What :func:`govopt.report.plots.fatigue` reads of a Result: the fatigue load cycle
    (``spring_report.loads``), the checks and the name."""
    cycle = fatigue_cycle(outcome.sizing, outcome.values)
    return SimpleNamespace(spring_report=SimpleNamespace(loads={"fatigue": cycle}),
                           checks=outcome.sizing.checks, spec=SimpleNamespace(name=outcome.name))


def plot_names(outcome) -> list[str]:
    """The plots this spring has (the fatigue diagram needs a grade and a load cycle)."""
    has_cycle = fatigue_cycle(outcome.sizing, outcome.values) is not None
    return [k for k in PLOTS if k != "fatigue" or has_cycle]


def check_outputs(xlsx, plots, stem: str, *, replace: bool, inputs=()) -> None:
    """Before the run: each output can be written, and exists only if ``replace``
    (:func:`govopt.report.files.check_output`; a folder for the plots is made if only its
    parent exists). Raises :class:`GovoptError` with one line."""
    from .files import check_output, output_folder

    paths = [] if xlsx is None else [(Path(xlsx), "workbook")]
    if plots is not None:
        folder = output_folder(Path(plots), "plots")
        paths += [(folder / f"{stem}-{k}.{fmt}", "plot") for k in PLOTS for fmt in ("png", "svg")]
    for path, what in paths:  # in `govopt spring` (--replace: files.overwrite_option)
        check_output(path, overwrite=replace, inputs=inputs, what=what,
                     others=[p for p, _ in paths if p != path])


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
                force_length(outcome.sizing, outcome.values, ax, outcome.name)
            else:
                plots.fatigue(_plot_input(outcome), ax)
        written += save_figure(ax.figure, Path(folder) / f"{stem}-{kind}", overwrite=replace)
    return written


def workbook_rows(outcome) -> list[tuple[str, object, str]]:
    """The Spring sheet's rows, answer first: (label, SI value or text, SI unit); a section
    title has the value None and the unit ``"section"``."""
    sizing, data = outcome.sizing, outcome.data
    sol = sizing.solution
    rows = [("Answer", None, "section"),
            ("wire diameter d", sol.d, "m"), ("mean coil diameter D", 2.0 * sol.r, "m"),
            ("active coils n", sol.n, ""), ("end coils", sol.end_coils, ""),
            ("mass (all coils)", sol.mass, "kg"), ("stiffness R", sol.stiffness, "N/m"),
            ("shear stress at the force", sol.stress, "Pa"),
            ("stress correction", sol.correction, ""), ("spring index D/d", sol.index, ""),
            ("surge frequency", sol.surge_frequency, "Hz"),
            (f"objective: {outcome.values['objective']}", data["objective_value"], ""),
            ("certified lower bound", data["lower_bound"], ""),
            ("claim", outcome.claim, ""),
            ("active in the last GP", ", ".join(sol.active), "")]
    life = data.get("fatigue_life_cycles")
    if life is not None:
        rows.append(("estimated fatigue life (cycles)", life if math.isfinite(life) else
                     "at least the data's 1e7 (the body passes there)", ""))
    return rows


def write_workbook(outcome, path, *, replace: bool = True, command: str = "") -> Path:
    """The workbook (:func:`govopt.report.excel.spring.spring_workbook`: a Summary with the
    command, version, date, verdict and the answer, the spring maker's sheet, the checks and
    the force-length table with its chart), written atomically (an existing file replaced only
    with ``replace``)."""
    from .excel.spring import spring_workbook

    return spring_workbook(outcome, path, rows=workbook_rows(outcome),
                           sheet=maker_sheet(outcome.sizing, outcome.values),
                           points=force_length_points(outcome), replace=replace,
                           command=command)


def force_length_points(outcome) -> list[tuple[float, float]]:
    """(length m, force N) at the free length and the working points, solid length last
    (compression), from the sizing's lengths as the force-length plot draws them; a point
    equal to the one before it (no least force: the first working point is the free length)
    once."""
    sizing, v = outcome.sizing, outcome.values
    R, F1, F2 = sizing.solution.stiffness, v.get("min_force") or 0.0, v["force"]
    L0 = sizing.free_length
    if sizing.kind == "compression":
        Lc = sizing.solid_length
        points = [(L0 - F / R, F) for F in (0.0, F1, F2)] + [(Lc, R * (L0 - Lc))]
    else:
        F0 = _initial_tension(sizing)
        points = [(L0, F0)] + [(L0 + (F - F0) / R, F) for F in (F1, F2)]
    return [p for i, p in enumerate(points) if i == 0 or p != points[i - 1]]


def _initial_tension(sizing) -> float:
    """An extension spring's initial tension (N): the sizing's, 0 where none was set (no
    grade: the GP has no initial-tension rule)."""
    F0 = sizing.initial_tension
    return F0 if math.isfinite(F0) else 0.0
