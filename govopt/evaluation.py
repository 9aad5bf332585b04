"""Evaluate a given design: statics, spring, restoring stiffness, and the checks (Hamabe I-III).

Only what the spec asks for is modelled: dynamics run when the spec has engine data, friction
only when the design has a friction moment. Every check is a row of :mod:`govopt.requirements`
evaluated by its :class:`~govopt.requirements.CheckTable` with one design (the bulk evaluation
fills the same table for many), except the spring's own (:meth:`Governor.spring_checks`).
"""

from __future__ import annotations

import numpy as np

from .analysis import loadchange, statics
from .errors import DesignError
from .requirements import (
    CheckTable,
    friction_rows,
    load_change_rows,
    requirement_rows,
    statics_figures,
    statics_rows,
    vibration_rows,
)
from .result import Result
from .spec import Design, Spec
from .springs import helical as hx
from .units import SI_UNITS


def spring_properties(spec: Spec, sd: statics.SpringDesign) -> dict[str, float]:
    """Derived spring quantities (SI) for reports: index, Wahl factor, mass, surge frequency."""
    mat = spec.material
    C = hx.spring_index_r(sd.d, sd.r)
    return {
        "spring_index": C,
        "wahl_factor": float(hx.wahl_factor(C)),
        "mass_kg": hx.wire_mass(sd.d, sd.r, sd.n, mat.density),
        "surge_frequency_Hz": hx.surge_frequency_r(sd.d, sd.r, sd.n, mat.shear_modulus,
                                                     mat.density),
        "body_length_m": (sd.n + 1.0) * sd.d,
    }


def evaluate(spec: Spec, design: Design | None = None) -> Result:
    """Evaluate ``design`` (default: the spec's own ``[design]``) against the spec.

    Statics always; the load-change transient (Hamabe Part III) when the spec has engine data,
    load changes and the design a dash-pot; design-requirement checks (margins, spring index,
    envelope, surge, bounds) when the spec has ``[requirements]`` or ``[bounds]``.
    """
    design = design or spec.design
    if design is not spec.design:  # every analysis reads the design evaluated, never the spec's
        spec = spec.with_design(design)
    try:
        return _evaluate(spec, design)
    except OverflowError:  # Python floats raise where numpy gives inf
        raise DesignError(f"{spec.path}: design: impossible design: a figure overflows the "
                          "floating-point range; the design's inputs are far outside any "
                          "physical range") from None


def _evaluate(spec: Spec, design: Design) -> Result:
    from .fidelity import plan as use_case_plan

    plan = use_case_plan(spec)  # [analysis] use_case: only its analyses, at its settings
    spec = plan.apply(spec) if plan is not None else spec
    wanted = plan.runs if plan is not None else (lambda analysis: True)
    sd = statics.spring_design(spec, design)
    possible(spec, sd)
    char = statics.characteristic(spec, sd)
    k2 = statics.restoring_k2(spec, char.alpha, sd, char.omega**2)
    helical = spec.material is not None and np.isfinite(sd.d)  # a wire spring to check
    _finite(spec, {"equilibrium speed": char.omega, "spring force (generalised)": char.M_f,
                   "centrifugal force (generalised)": char.M_z, "spring force": char.spring_force,
                   "k^2": k2, **({"shear stress": char.stress} if helical else {})})
    rise = characteristic_rise(spec, sd, char)
    req = spec.requirements
    gov = spec.governor
    unit = SI_UNITS[gov.coordinate]
    i_n = int(np.searchsorted(char.alpha, gov.x_normal))  # the normal configuration is on the grid
    w0sq = spec.speed.omega_mean**2 if spec.speed is not None else float(char.omega[i_n]) ** 2
    vib = None  # the type's forced vibration (Hamabe Part II): also the spring's load cycle
    if wanted("vibration") and (design.dashpot is not None or spec.engine is not None):
        vib = gov.vibration(spec, sd, float(k2[i_n]), design.dashpot or 0.0)
    checks = gov.spring_checks(spec, sd, char, vib) if gov.spring is not None else []
    band = (None, None)
    if spec.speed is not None and spec.speed.band:  # the whole operating band in the spec's
        fr = gov.friction(np.array([gov.x_inner, gov.x_outer]), design)
        band = tuple(float(np.sqrt(max(float(w2), 0.0))) for w2 in statics.band_speeds_squared(
            spec, sd.m, sd.kappa, sd.l0, sd.central, fr))
    table = CheckTable(1)
    table.add_rows(statics_rows(spec), statics_figures(char.irregularity, *band, rise, w0sq,
                                                       char.spring_force, k2))
    props = spring_properties(spec, sd) if helical else {}
    dynamics = {}
    if wanted("load_change") and spec.engine is not None and spec.load_changes and \
            design.dashpot is not None:
        changes = [loadchange.analyse(spec, sd, lc, design.dashpot) for lc in spec.load_changes]
        dynamics["load_changes"] = changes
        for lc in changes:
            name = lc["name"]
            table.add_rows(load_change_rows(spec, name), {
                "hurwitz": {name: lc["hurwitz_margin"]},
                "over": {name: lc[f"over_regulation_{unit}"]},
                "over_regulates": {name: lc["over_regulates"]},
                "xi0": {name: lc["initial_state"][f"xi_{unit}"]},
                "settling": {name: lc["settling_time_s"]}})
    if design.dashpot is not None or spec.engine is not None:
        dynamics["k2_normal_rad2_s2"] = float(k2[i_n])
    if vib is not None:  # the type has a periodic forcing (the shaft's valve gear, Part II)
        dynamics["vibration"] = vib.to_dict()
        table.add_rows(vibration_rows(spec), {"p2p": dynamics["vibration"]["peak_to_peak_rad"]})
    if wanted("friction") and spec.engine is not None and spec.load_changes and any(
            float(gov.friction(lc.alpha_to, design)) > 0 for lc in spec.load_changes):
        from .analysis import friction  # only when the design has friction (model what is asked)

        runs = [friction.friction_load_change(spec, sd, lc) for lc in spec.load_changes]
        dynamics["friction"] = [r.to_dict() for r in runs]
        for lc, r in zip(spec.load_changes, runs, strict=True):
            xi0 = lc.alpha_from - lc.alpha_to
            first = r.first_stroke_end
            stuck = r.outcome == "stuck"  # the governor does not follow the load change at all
            table.add_row(friction_rows(spec, lc.name)["stuck" if stuck else "moves"], {
                "xi0": xi0, "rest": abs(r.final_state[0]),
                "past": 0.0 if stuck or first is None
                else max(0.0, -float(np.sign(xi0)) * first)})
    if req is not None and helical:
        table.add_rows(requirement_rows(spec, req), {
            "d": sd.d, "r": sd.r, "n": sd.n, "m": sd.m, "l0": sd.l0, "C": props["spring_index"],
            "body": props["body_length_m"], "surge": props["surge_frequency_Hz"]})
    checks += table.checks()  # the rows in the order added (each name once)
    if plan is not None:
        dynamics["use_case"] = plan.to_dict()
    from .analysis.classic import classic_measures

    return Result(spec=spec, design=design, spring=sd, statics=char, spring_properties=props,
                  checks=checks, k2=k2, dynamics=dynamics,
                  classic=classic_measures(spec, sd, char, k2, design),
                  spring_report=gov.spring_report(spec, sd, char, vib)
                  if gov.spring is not None else None)


def possible(spec: Spec, sd: statics.SpringDesign) -> None:
    """Reject a design no spring can realise, with a diagnosis (:class:`DesignError`): a
    non-finite figure, or a spring's free length ``l0 <= 0`` (where the type's free length is a
    length, :attr:`Governor.free_length_positive`). On the seam
    ``l0 = (A_n - Q_n / kappa) / B_n`` (Hamabe, Example 1: ``l0 = l_n - F_n / (2 kappa)``) rises
    with ``kappa`` towards ``l_inf = A_n / B_n``, so ``l0 > 0`` needs
    ``kappa > kappa (1 - l0 / l_inf)``: the spring is too soft to hold the normal configuration
    at the mean speed even stretched from zero length."""
    gov = spec.governor
    name = gov.free_length_key.replace("_", " ")
    _finite(spec, {f"{gov.mass_name} mass": sd.m, "inertia": sd.inertia,
                   "spring stiffness": sd.kappa, name: sd.l0})
    if gov.spring is not None and gov.free_length_positive and sd.l0 <= 0:
        l_inf = float(statics.free_half_length(spec, sd.m, np.inf, sd.central))
        need = (f"; it needs kappa > {sd.kappa * (1.0 - sd.l0 / l_inf):.6g} N/m (or a lighter "
                "flying mass)" if l_inf > 0 else "")
        raise DesignError(
            f"{spec.path}: design: impossible design: the {name} l0 = {sd.l0:.6g} m is not "
            f"positive: the spring (kappa = {sd.kappa:.6g} N/m) is too soft to hold the normal "
            f"configuration at the mean speed even stretched from zero length{need}")


def _finite(spec: Spec, figures: dict) -> None:
    """:class:`DesignError` naming the first figure that is infinite or not a number."""
    for name, value in figures.items():
        bad = ~np.isfinite(np.asarray(value, dtype=float))
        if np.any(bad):
            shown = np.asarray(value, dtype=float)[bad].flat[0]
            raise DesignError(f"{spec.path}: design: impossible design: the {name} is {shown} "
                              "(not finite); the design's inputs are outside any physical range")


def characteristic_rise(spec: Spec, sd: statics.SpringDesign, char) -> float:
    """Least ``d omega / d x`` over the range (rad/s per unit ``x``): the exact slope of the
    characteristic at every row (:func:`statics.characteristic_slope`) and the secant between
    neighbouring rows, so that a fall between two rows (or a negative irregularity) cannot
    pass."""
    return float(np.min(statics.rising_slopes(spec, sd, char.alpha, char.omega)))
