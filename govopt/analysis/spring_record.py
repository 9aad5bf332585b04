"""The record of a governor's helical spring: what the maker needs and what tolerances do.

:func:`report` gathers, for one design, the spring maker's sheet (:mod:`govopt.springs.sheet`),
the spread of the rate and of the forces over the EN 15800 tolerances (:func:`spread`,
:class:`Spread`) and the life of an extension spring's hooks under the type's forcing
(:func:`hook_cycles`), with the checks of :func:`govopt.analysis.spring_engineering.checks`,
as a :class:`SpringReport`. SI inside.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..springs import checks as ck
from ..springs import extension as he
from ..springs import fatigue as ft
from ..springs import helical as hx
from ..springs import materials as mt
from ..springs import sheet as sh
from ..verdict import Figure
from .spring_engineering import (
    KINDS,
    NO_FORCING,
    fatigue_forces,
    harmonics_hz,
    initial_tension,
    wire,
)


@dataclass(frozen=True)
class Spread:
    """Manufacturing spread of a helical spring in a governor (SI): wire and coil diameter
    tolerances ``d_tol``, ``D_tol`` (+-), the rate's worst-case range, the free length's
    tolerance ``l0_tol`` in the type's form, and the governed speed range's spread."""

    d_tol: float
    D_tol: float
    kappa: tuple[float, float]
    l0_tol: float
    omega_inner: tuple[float, float]
    omega_outer: tuple[float, float]
    notes: tuple[str, ...] = ()

    def sample(self, sd, rng, size: int):
        """Monte-Carlo draws ``(kappa, l0)`` (arrays of ``size``): wire and coil diameter
        uniform within their tolerances (the rate ``~ d^4 / D^3`` follows) and the free length
        uniform within its tolerance - for the studies."""
        d = sd.d + self.d_tol * rng.uniform(-1.0, 1.0, size)
        D = 2.0 * sd.r + self.D_tol * rng.uniform(-1.0, 1.0, size)
        kappa = sd.kappa * (d / sd.d) ** 4 * (2.0 * sd.r / D) ** 3
        return kappa, sd.l0 + self.l0_tol * rng.uniform(-1.0, 1.0, size)

    def figures(self) -> dict:
        """The spread as a record of figures (:func:`govopt.springs.sheet.record_json`)."""
        return {f.name: f for f in (
            Figure("wire diameter tolerance", self.d_tol, "m"),
            Figure("coil diameter tolerance", self.D_tol, "m"),
            Figure("stiffness range", list(self.kappa), "N/m"),
            Figure("free length tolerance", self.l0_tol, "m"),
            Figure("omega inner range", list(self.omega_inner), "rad/s"),
            Figure("omega outer range", list(self.omega_outer), "rad/s"))} | {
            "notes": list(self.notes)}

    def to_dict(self) -> dict:
        return sh.record_json(self.figures())


def spread(spec, sd, sheet: sh.SpringSheet) -> Spread:
    """The spring's spread under the tolerance model of a made governor (a :class:`Spread`, SI).

    At the sheet's EN 15800 grade (:mod:`govopt.analysis.tolerance`): the wire (EN 10270), coil
    diameter (EN 15800 Table 1) and free length (EN 15800 ``A_L0`` of a compression spring)
    tolerances, the rate's range over them, and the equilibrium speeds' worst case at both ends
    of the range (at the box's corners, exact: :func:`govopt.analysis.tolerance.speed_band`): the
    spread of the governed speed range.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds and ``[material]``.
    sd : SpringDesign [-]
        The design (m, kg, N/m).
    sheet : SpringSheet [-]
        The spring maker's sheet (its tolerance grade).

    Returns
    -------
    Spread [-]
        Tolerances in m, rates in N/m, speeds in rad/s.

    References
    ----------
    [en15800] Table 1; [en10270-1]; [hamabe] Part I, eqs. (2), (12).

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    EN 10270-1: d = 17 mm +- 0.090 mm (row to 18 mm); EN 15800 grade 2, D = 120 mm (row to
    125 mm), w = 7.06 (4-8): +- 1.40 mm, so the rate lies in ``kappa (d -+ A_d)^4 / d^4 x
    D^3 / (D +- A_D)^3`` = 59.5 to 66.6 kN/m about its 62.95 kN/m.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> rep = report(spec, sd, chs.characteristic(spec, sd))
    >>> sp = spread(spec, sd, rep.sheet)
    >>> round(sp.d_tol * 1e3, 3), round(sp.D_tol * 1e3, 2)
    (0.09, 1.4)
    >>> [round(k / 1e3, 1) for k in sp.kappa]
    [59.5, 66.6]
    """
    from . import tolerance as tm

    cols = {"flying_mass": np.array([sd.m]), "wire_diameter": np.array([sd.d]),
            "coil_radius": np.array([sd.r]), "active_turns": np.array([sd.n]),
            "free_half_length": np.array([sd.l0]), "central_mass": np.array([sd.central]),
            "flying_inertia": np.array([sd.inertia if sd.inertia_given else np.nan])}
    bx = tm.box(spec, cols, sheet.tolerance_grade).known()
    half = {k: float(bx.fields[k][0]) for k in ("wire_diameter", "coil_radius",
                                                  "free_half_length")}
    d = sd.d + np.array([-1.0, 1.0]) * half["wire_diameter"]
    r = sd.r - np.array([-1.0, 1.0]) * half["coil_radius"]
    kappa = hx.stiffness_r(d, r, sd.n, spec.material.shear_modulus)
    band = tm.speed_band(spec, cols, bx)
    return Spread(half["wire_diameter"], 2.0 * half["coil_radius"],
                  (float(kappa[0]), float(kappa[1])), half["free_half_length"],
                  tuple(band["inner_rad_s"]), tuple(band["outer_rad_s"]), bx.notes)


@dataclass
class SpringReport:
    """The spring maker's sheet and the engineering figures of one governor spring (SI):
    ``material`` and ``loads`` are records (:func:`govopt.springs.sheet.record_json`) whose
    numbers are :class:`~govopt.verdict.Figure` keyed by name (``loads["force min"]``,
    ``loads["fatigue"]["corrected stress max"]``, each with its unit as a field)."""

    kind: str
    sheet: sh.SpringSheet
    material: dict
    loads: dict
    spread: Spread
    notes: list[str] = field(default_factory=list)

    def record(self) -> dict:
        """The whole report as one record: what the Spring sheet lists, row by row
        (:func:`govopt.springs.sheet.record_rows`), and the JSON writes (:meth:`to_dict`)."""
        return {"kind": self.kind, "sheet": self.sheet.figures(), "material": self.material,
                "loads": self.loads, "tolerance_spread": self.spread.figures(),
                "notes": list(self.notes)}

    def to_dict(self) -> dict:
        return sh.record_json(self.record())


def hook_cycles(mat, d, D, F_lo, F_hi, r2=None, r1=None,
                criterion: str = ck.DEFAULTS["criterion"]) -> dict:
    """The fatigue cycle of an extension spring's hooks between the forces ``F_lo`` and ``F_hi``.

    As the hook checks read it (:mod:`govopt.springs.checks`: Shigley section 10-11, hooks taken
    unpeened; ``r1`` default ``D/2``, ``r2`` default ``2 d``): for point A (bending, Shigley
    Example 10-7: ``S_e = S_se / 0.577`` with the tensile ``S_ut``) and point B (torsion,
    ``S_se`` with ``S_su = 0.67 S_ut``) the midrange and amplitude stresses and the line's
    intercepts (``endurance`` on the amplitude axis, ``ultimate`` on the midrange axis), Pa; the
    safety factor is where the load line through the cycle meets the line.

    Parameters
    ----------
    mat : Material [-]
        The wire (R_m in Pa).
    d : float [m]
        Wire diameter.
    D : float [m]
        Mean coil diameter.
    F_lo : float [N]
        Least force of the cycle.
    F_hi : float [N]
        Largest force of the cycle.
    r2 : float [m], optional
        Bend radius where the hook leaves the body.
    r1 : float [m], optional
        The hook's mean radius.
    criterion : str [-], optional
        The fatigue line (dimensionless name: ``"goodman"`` ...).

    Returns
    -------
    dict [-]
        ``criterion``, ``source`` and points ``A`` and ``B`` of :class:`Figure` in Pa.

    References
    ----------
    [shigley] 9th ed. section 10-11 and Example 10-7.

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    The stresses are linear in the force, so amplitude over midrange is
    ``(F_hi - F_lo) / (F_hi + F_lo) = 200 / 10000``:

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> A = hook_cycles(wire(spec.material), 0.017, 0.12, 4900.0, 5100.0)["A"]
    >>> round(A["amplitude"].value / A["midrange"].value, 6), A["stress"]
    (0.02, 'bending')
    """
    r1 = D / 2.0 if r1 is None else r1
    r2 = 2.0 * d if r2 is None else r2
    Sut = float(mat.tensile_strength(d))
    Ssu = float(ft.torsional_ultimate(Sut))
    Ssa, Ssm = ft.ZIMMERLI[False]
    Sse = float(ft.endurance_intercept(Ssa, Ssm, Ssu, criterion))
    half, mid = abs(F_hi - F_lo) / 2.0, (F_hi + F_lo) / 2.0
    def point(stress: str, midrange, amplitude, endurance, ultimate) -> dict:
        return {"stress": stress} | {f.name: f for f in (
            Figure("midrange", float(midrange), "Pa"), Figure("amplitude", float(amplitude), "Pa"),
            Figure("endurance", float(endurance), "Pa"), Figure("ultimate", float(ultimate), "Pa"))}

    return {"criterion": criterion, "source": ft.ZIMMERLI_SOURCE,
            "A": point("bending", he.hook_bending_stress(mid, d, D, r1),
                       he.hook_bending_stress(half, d, D, r1), Sse / ft.SHEAR_TO_NORMAL, Sut),
            "B": point("torsion", he.hook_torsion_stress(mid, d, D, r2),
                       he.hook_torsion_stress(half, d, D, r2), Sse, Ssu)}


def report(spec, sd, char, vib=None) -> SpringReport:
    """The spring maker's sheet and the engineering figures of one helical governor spring.

    The sheet (material, d, D, n, ends or hooks, free length, rate, the loads at the range's two
    ends, tolerance grade, surface), the material's figures at ``d``, the static and fatigue
    loads (the cycle of the type's forcing, Hamabe Part II, where ``vib`` is given), and the
    tolerance spread (:func:`spread`).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]`` and ``[spring]``.
    sd : SpringDesign [-]
        The design (m, kg, N/m).
    char : Characteristic [-]
        Its statics (spring force in N).
    vib : VibrationResult [-], optional
        The forced vibration; None: no fatigue (and a note saying so).

    Returns
    -------
    SpringReport [-]
        Figures in SI, each with its unit.

    References
    ----------
    [en13906-1] (surge frequency, sheet); [shigley] 9th ed. section 10-11; [en15800];
    [hamabe] Part II.

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    Its surge frequency with both ends fixed, by hand
    ``d / (2 pi n D^2) sqrt(G / (2 rho)) = 0.017 / (2 pi 8 0.0144) x sqrt(83.36e9 / 15700)``
    ``= 54.1 Hz``; no forcing given, so no fatigue.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> rep = report(spec, sd, chs.characteristic(spec, sd))
    >>> rep.kind, round(rep.loads["surge frequency"].value, 1), rep.notes == [NO_FORCING]
    ('extension', 54.1, True)
    """
    m, form = spec.material, spec.spring_form
    kind = KINDS[spec.governor.spring]
    mat = wire(m)
    d, D, n = sd.d, 2.0 * sd.r, sd.n
    F = np.asarray(char.spring_force, dtype=float)
    F1, F2 = sorted((float(F[0]), float(F[-1])))
    graded = m.grade is not None
    surface = m.surface if graded else "not stated (no wire grade: no fatigue check)"
    L = spec.governor.spring_length_factor * sd.l0
    if kind == "compression":
        sheet = sh.compression_sheet(mat, d, D, n, n + form.inactive_turns, L, F1, F2,
                                     ends=form.ends, grade=m.tolerance_grade, surface=surface)
    else:
        F0 = float(initial_tension(spec, d, D, float(np.min(F))))
        sheet = sh.extension_sheet(mat, d, D, n - float(mat.shear_modulus(d))
                                   / float(mat.elastic_modulus(d)), F0, F1, F2,
                                   grade=m.tolerance_grade, surface=surface)
    notes = []
    material = {"grade": mat.grade, "standard": mat.standard,
                "shear modulus": Figure("shear modulus", float(mat.shear_modulus(d)), "Pa"),
                "elastic modulus": Figure("elastic modulus", float(mat.elastic_modulus(d)), "Pa"),
                "density": Figure("density", mat.density, "kg/m^3", json="density_kg_m3"),
                "moduli_source": mat.moduli_source, "surface": surface}
    if graded:
        place = "compression" if kind == "compression" else "extension"
        rule = mt.static_rule(mat, place, m.rules)
        material.update({
            "tensile strength": Figure("tensile strength", float(mat.tensile_strength(d)), "Pa"),
            "rm_source": mat.rm_source,
            "rules": m.rules, "static_correction": m.stress_correction,
            "fatigue_correction": hx.DEFAULT_CORRECTION[(m.rules, "fatigue")],
            "allowable static stress": Figure("allowable static stress", float(
                mt.allowable_static_stress(mat, d, place, m.rules, m.allowable_shear_stress)),
                "Pa"),
            "allowable_source": "material.allowable_shear_stress (given in the spec)"
            if m.allowable_shear_stress is not None else rule.source,
            "life_cycles": m.life_cycles})
    loads = {f.name: f for f in (
        Figure("force min", float(np.min(F)), "N"), Figure("force max", float(np.max(F)), "N"),
        Figure("surge frequency", sheet.surge_frequency, "Hz"),
        Figure("excitation harmonics", list(harmonics_hz(vib)), "Hz"))}
    if vib is None:
        loads["fatigue"] = None
        notes.append(NO_FORCING)
    else:
        swing = float(vib.peak_to_peak_rad)
        unit = "rad" if spec.governor.coordinate == "angle" else "m"
        fat = {"forcing": "the valve gear's fluctuating reaction (Hamabe Part II, with the "
                          "dash-pot)", "peak to peak": Figure("peak to peak", swing, unit)}
        if math.isfinite(swing):
            lo, hi = fatigue_forces(spec, sd, swing)
            K = hx.bergstrasser_factor(hx.spring_index(d, D))
            fat.update(ft.cycle_figures(lo, hi, *(float(K * hx.shear_stress(f, d, D))
                                                  for f in (lo, hi))))
            if graded:  # the diagram the body's fatigue check reads (for the plot)
                fat["diagram"] = ft.body_locus(mat, d, m.rules, m.surface == "shot peened",
                                               ck.DEFAULTS["criterion"])
                if kind == "extension":  # and the hooks' (the check's own line and cycle)
                    fat["hooks"] = hook_cycles(mat, d, D, lo, hi, form.hook_bend_radius)
        loads["fatigue"] = fat
        if not graded:
            notes.append("no material.grade: the fatigue and spring engineering checks need "
                         "a wire grade")
    return SpringReport(kind, sheet, material, loads, spread(spec, sd, sheet), notes)
