"""Evaluate a given design: statics, spring, restoring stiffness, and the checks (Hamabe I-III).

Only what the spec asks for is modelled: dynamics run when the spec has engine data, friction
only when the design has a friction moment.
"""

from __future__ import annotations

import numpy as np

from .analysis import loadchange, statics
from .errors import DesignError
from .model import spring
from .result import Check, Result
from .spec import Design, Spec
from .units import SI_UNITS


def spring_properties(spec: Spec, sd: statics.SpringDesign) -> dict[str, float]:
    """Derived spring quantities (SI) for reports: index, Wahl factor, mass, surge frequency."""
    mat = spec.material
    C = spring.spring_index(sd.d, sd.r)
    return {
        "spring_index": C,
        "wahl_factor": float(spring.wahl_factor(C)),
        "mass_kg": spring.wire_mass(sd.d, sd.r, sd.n, mat.density),
        "surge_frequency_Hz": spring.surge_frequency(sd.d, sd.r, sd.n, mat.shear_modulus,
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
    ev = {"irregularity": char.irregularity, "band_low": band[0], "band_high": band[1],
          "rise": rise, "w0sq": w0sq, "F_min": float(np.min(char.spring_force)),
          "F_top": float(np.max(np.abs(char.spring_force))), "k2_min": float(np.min(k2)),
          "k2_max": float(np.max(k2))}
    for name, sense, unit_, value, limit, scale, source in statics_rows(spec):
        sc = scale(ev)
        checks.append(Check(name, float(value(ev)), float(limit(ev)), sense, unit_, source,
                            scale=None if sc is None else float(sc)))
    props = spring_properties(spec, sd) if helical else {}
    dynamics = {}
    if wanted("load_change") and spec.engine is not None and spec.load_changes and \
            design.dashpot is not None:
        hm = req.hurwitz_margin if req else 0.0
        changes = [loadchange.analyse(spec, sd, lc, design.dashpot) for lc in spec.load_changes]
        dynamics["load_changes"] = changes
        for lc in changes:
            checks.append(Check(f"Hurwitz margin eq. (32): {lc['name']}", lc["hurwitz_margin"],
                                hm, ">=", "", "Hamabe eq. (32): 9 a1 a2 / (a0 a3) - 1",
                                scale=1.0))
            checks.append(Check(f"no over-regulation: {lc['name']}",
                                lc[f"over_regulation_{unit}"], 0.0, "<=", unit,
                                "Hamabe Part III; all t >= 0 (transient.over_regulates)",
                                scale=abs(lc["initial_state"][f"xi_{unit}"]),
                                verdict=not lc["over_regulates"]))
            if req is not None and req.max_settling_time is not None:
                checks.append(Check(f"settling time: {lc['name']}", lc["settling_time_s"],
                                    req.max_settling_time, "<=", "s", "Hamabe Part III"))
    if design.dashpot is not None or spec.engine is not None:
        dynamics["k2_normal_rad2_s2"] = float(k2[i_n])
    if vib is not None:  # the type has a periodic forcing (the shaft's valve gear, Part II)
        dynamics["vibration"] = vib.to_dict()
        if req is not None and req.max_vibration is not None:
            checks.append(Check("vibration peak-to-peak", dynamics["vibration"]["peak_to_peak_rad"],
                                req.max_vibration, "<=", unit, "Hamabe Part II, eqs. (18)-(22)"))
    if wanted("friction") and spec.engine is not None and spec.load_changes and any(
            float(gov.friction(lc.alpha_to, design)) > 0 for lc in spec.load_changes):
        from .analysis import friction  # only when the design has friction (model what is asked)

        runs = [friction.friction_load_change(spec, sd, lc) for lc in spec.load_changes]
        dynamics["friction"] = [r.to_dict() for r in runs]
        for lc, r in zip(spec.load_changes, runs, strict=True):
            xi0 = lc.alpha_from - lc.alpha_to
            if r.outcome == "stuck":  # the governor does not follow the load change at all
                checks.append(Check(f"friction: the governor follows the load change: {lc.name}",
                                    abs(r.final_state[0]), 0.0, "<=", unit,
                                    "Hamabe eqs. (42)-(46): stuck while |C eta - I k^2 xi| <= M0",
                                    scale=abs(xi0)))
                continue
            first = r.first_stroke_end
            past = 0.0 if first is None else max(0.0, -float(np.sign(xi0)) * first)
            checks.append(Check(f"friction: no over-regulation after the first stroke: {lc.name}",
                                past, 0.0, "<=", unit,
                                "Hamabe eqs. (42)-(46)", scale=abs(xi0) or 1.0))
    if req is not None and helical:
        checks += requirement_checks(spec, req, sd, props)
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


def statics_rows(spec: Spec) -> list[tuple]:
    """The statics requirements, declared once for one design and for many:
    ``(name, sense, unit, value(ev), limit(ev), scale(ev), source)`` with ``ev`` a dict of SI
    figures (floats, or arrays over N designs): ``irregularity``; ``band_low``, ``band_high``
    (the operating band's ends with friction, :func:`statics.band_speeds_squared`); ``rise``
    (the least slope of the characteristic, :func:`statics.rising_slopes`); ``w0sq`` (the
    reference ``omega0^2``); ``F_min``, ``F_top`` (the least and the largest absolute spring
    force); ``k2_min``, ``k2_max``. ``scale`` None: the margin on the limit. Read by
    :func:`evaluate` (N = 1) and by the bulk evaluation (:mod:`govopt.bulk`)."""
    gov, sp, req = spec.governor, spec.speed, spec.requirements
    margin = req.k2_margin if req else 0.0
    unit = SI_UNITS[gov.coordinate]

    def none(ev):
        return None

    rows = []
    if sp is not None:
        rows.append(("irregularity", "<=", "", lambda ev: ev["irregularity"],
                     lambda ev: sp.irregularity, none,
                     "Hamabe Part I: (omega_a - omega_i) / omega0, omega0 the spec's mean speed"))
        if sp.band:
            rows += [(statics.BAND_INNER, ">=", "rad/s", lambda ev: ev["band_low"],
                      lambda ev: sp.omega_inner, none, statics.BAND_SOURCE),
                     (statics.BAND_OUTER, "<=", "rad/s", lambda ev: ev["band_high"],
                      lambda ev: sp.omega_outer, none, statics.BAND_SOURCE)]
    rows.append(("characteristic rises (stable)", ">=", f"rad/s/{unit}", lambda ev: ev["rise"],
                 lambda ev: 0.0, lambda ev: statics.slope_scale(spec, np.sqrt(ev["w0sq"])),
                 "d omega/dx > 0 over the range: the equilibrium (eq. 12) differentiated; "
                 "Hamabe Part III, stable by the characteristic curve; margin on omega0 / "
                 "(x_outer - x_inner) (statics.stability)"))
    if gov.spring is not None:
        rows.append((gov.spring_loaded_check, ">=", "N", lambda ev: ev["F_min"], lambda ev: 0.0,
                     lambda ev: ev["F_top"], "the spring stays loaded over the range (Hamabe "
                     "eq. 2: F = 2 kappa (l - l0) > 0)"))
    rows.append(("k^2 > 0 (stability)", ">=", "rad^2/s^2", lambda ev: ev["k2_min"],
                 lambda ev: margin * ev["w0sq"], lambda ev: ev["w0sq"], "Hamabe Part II, case 3"))
    if gov.resonance_ceiling:
        rows.append(("k^2 < omega0^2 (no resonance)", "<=", "rad^2/s^2",
                     lambda ev: ev["k2_max"], lambda ev: (1.0 - margin) * ev["w0sq"], none,
                     "Hamabe Part II, case 2"))
    return rows


#: where the spring index limits come from (the requirements; the standard's scope for reference)
INDEX_SOURCE = ("requirements.spring_index (EN 13906-1 scope, cold coiled: 4 <= w <= 20; "
                "Shigley prefers 4 <= C <= 12)")


def requirement_rows(spec: Spec, req) -> list[tuple]:
    """The design requirements and bounds of `govopt design` as rows, declared once for one
    design and for many: ``(name, sense, unit, value(ev), limit(ev), source)`` with ``ev`` a
    dict of SI values (floats, or arrays over N designs): ``d``, ``r``, ``n`` (wire diameter,
    coil radius, active turns), ``m`` (flying mass), ``l0`` (the type's free length), ``C``
    (spring index), ``body`` (close-wound body length ``(n + 1) d``), ``surge`` (Hz). Read by
    :func:`requirement_checks` (N = 1) and by the bulk evaluation (:mod:`govopt.bulk`)."""
    gov = spec.governor
    factor = gov.spring_length_factor

    def const(v):
        return lambda ev: v

    rows = [
        ("spring index >= min", ">=", "", lambda ev: ev["C"], const(req.spring_index[0]),
         INDEX_SOURCE),
        ("spring index <= max", "<=", "", lambda ev: ev["C"], const(req.spring_index[1]),
         INDEX_SOURCE),
        ("body length within free length", "<=", "m", lambda ev: ev["body"],
         lambda ev: factor * ev["l0"], "close-wound body (n + 1) d within 2 l0"),
    ]
    for name, key, bounds, unit in ((f"{gov.mass_name} mass", "m", req.pendulum_mass, "kg"),
                                    ("wire diameter", "d", req.wire_diameter, "m"),
                                    ("coil radius", "r", req.coil_radius, "m"),
                                    ("active turns", "n", req.active_turns, "")):
        rows += [(f"{name} >= min", ">=", unit, lambda ev, k=key: ev[k], const(bounds[0]), ""),
                 (f"{name} <= max", "<=", unit, lambda ev, k=key: ev[k], const(bounds[1]), "")]
    if req.max_outer_diameter is not None:
        rows.append(("outer diameter", "<=", "m", lambda ev: 2.0 * ev["r"] + ev["d"],
                     const(req.max_outer_diameter), ""))
    if req.min_surge_frequency is not None:
        rows.append(("surge frequency", ">=", "Hz", lambda ev: ev["surge"],
                     const(req.min_surge_frequency), "Wahl 1944 ch. 25"))
    return rows


def requirement_checks(spec: Spec, req, sd: statics.SpringDesign, props) -> list[Check]:
    """Checks of the design requirements and bounds of `govopt design`
    (:func:`requirement_rows` for one design)."""
    ev = {"d": sd.d, "r": sd.r, "n": sd.n, "m": sd.m, "l0": sd.l0, "C": props["spring_index"],
          "body": props["body_length_m"], "surge": props["surge_frequency_Hz"]}
    return [Check(name, value(ev), limit(ev), sense, unit, source)
            for name, sense, unit, value, limit, source in requirement_rows(spec, req)]
