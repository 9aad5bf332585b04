"""Evaluate a given design: statics, spring, restoring stiffness, and the checks (Hamabe I-III).

:func:`evaluate` is the one evaluator (:func:`govopt.evaluator.core`) with one design: every
check and figure comes from it; this module adds what a :class:`~govopt.result.Result` reports
beside them (the characteristic table, ``k^2`` over the range, the load changes' responses, the
spring maker's sheet, the classic measures). Only what the spec asks for is modelled: dynamics
run when the spec has engine data, friction only when the design has a friction moment.
"""

from __future__ import annotations

import numpy as np

from .analysis import statics
from .errors import DesignError, located
from .evaluator import core, design_columns, finite, overflow_message, possible
from .result import Result
from .spec import Design, Spec

#: the spring's report figures (:attr:`Result.spring_properties`, SI) and the evaluator's names
SPRING_PROPERTIES = (("spring_index", "spring_index"), ("wahl_factor", "wahl_factor"),
                     ("mass_kg", "spring_mass_kg"), ("surge_frequency_Hz", "surge_frequency_Hz"),
                     ("body_length_m", "body_length_m"))


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
        raise DesignError(overflow_message(spec)) from None


def _evaluate(spec: Spec, design: Design) -> Result:
    if design is None:  # the parser's diagnosis: no design to evaluate
        try:
            statics.spring_design(spec, design)
        except DesignError as exc:
            raise DesignError(located(spec.path, str(exc))) from None
    ev = core(spec, design_columns([design]), report=True)
    if ev.error[0] is not None:
        raise DesignError(ev.error[0])
    spec, sd, char, k2 = ev.spec, ev.spring, ev.char, ev.k2  # spec: with the use case's plan
    gov = spec.governor
    helical = spec.material is not None and np.isfinite(sd.d)  # a wire spring
    i_n = int(np.searchsorted(char.alpha, gov.x_normal))  # the normal configuration is on the grid
    dynamics = dict(ev.dynamics)
    if design.dashpot is not None or spec.engine is not None:
        dynamics["k2_normal_rad2_s2"] = float(k2[i_n])
    for key in ("vibration", "friction"):  # the report's order: the forcing, then friction
        if key in dynamics:
            dynamics[key] = dynamics.pop(key)
    if ev.plan is not None:
        dynamics["use_case"] = ev.plan.to_dict()
    return Result(spec=spec, design=design, spring=sd, statics=char,
                  spring_properties={k: float(ev.figures[f][0]) for k, f in SPRING_PROPERTIES}
                  if helical else {},
                  checks=ev.table.checks(), k2=k2, dynamics=dynamics,
                  classic=ev.classic,
                  spring_report=gov.spring_report(spec, sd, char, ev.vib)
                  if gov.spring is not None else None, evaluation=ev)


__all__ = ["evaluate", "finite", "possible"]
