"""Fidelity by use case: run only the analyses a use case needs, each at the cheapest setting
whose measured error fits the tolerance.

A spec asks for it in ``[analysis]``::

    use_case = "spring_sizing"   # or "vibration", "load_change", "friction", "full"
    tolerance = 1e-6             # relative error each analysis must stay within

=================  ============================================================================
``spring_sizing``  statics (characteristic, stresses, k^2, the spring's checks); the forced
                   vibration only as the spring's load cycle when a wire grade asks for fatigue
                   (``material.grade``). Never the load change, never the friction model.
``vibration``      statics and the forced vibration (Hamabe Part II)
``load_change``    statics and the load-change transient (Part III, eq. 28)
``friction``       statics and the load change with fulcrum friction (eqs. 42-46)
``full``           every analysis the spec has data for (what ``evaluate`` does without a use
                   case)
=================  ============================================================================

The errors and costs are the ones ``govopt bench`` measured (:mod:`govopt.bench`; the
full run's CSV is shipped as ``govopt/data/speed-vs-error.csv``): the worst relative error over
the suite's hard cases against high-precision references, and the CPU time per evaluation. Of
the settings an analysis offers, the cheapest whose measured error is within the tolerance is
chosen; where none is, the most accurate, reported as not fitting. The result's JSON carries
the plan under ``use_case``: each analysis with the model and setting used, its measured error
and whether that fits.

>>> loose, tight = choose("vibration", 1e-2), choose("vibration", 1e-6)
>>> loose.setting["harmonics"] < tight.setting["harmonics"], tight.error <= 1e-6 < loose.error
(True, True)
"""

from __future__ import annotations

import csv
import functools
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

#: The measured speed against error (a full ``govopt bench`` run).
MEASURED = Path(__file__).resolve().parent / "data" / "speed-vs-error.csv"

#: Use case -> the analyses it runs (statics always: every other analysis stands on it).
USE_CASES = {
    "spring_sizing": ("statics",),
    "vibration": ("statics", "vibration"),
    "load_change": ("statics", "load_change"),
    "friction": ("statics", "friction"),
    "full": ("statics", "load_change", "vibration", "friction"),
}


@dataclass(frozen=True)
class Option:
    """One way to run an analysis: the ``[analysis]`` settings it takes, the words for the
    report, and its row ``(analysis, method, setting)`` in the measured CSV."""

    model: str
    setting: dict
    row: tuple[str, str, str]
    applies: Callable | None = None  # spec -> whether the option means anything for it


def _has_series_linkage(spec) -> bool:
    """Whether ``[analysis] geometry`` changes the type's statics (a linkage with the paper's
    series, eq. 3, beside the exact eq. 2), found on the seam: the spring's coefficient ``B``
    at the normal configuration under each geometry."""
    from .analysis import statics

    x = spec.governor.x_normal
    exact, series = (float(statics.terms(spec.with_analysis(geometry=g), x, 1.0).B)
                     for g in ("exact", "series"))
    return exact != series


#: Analysis -> the settings govopt can run it at.
OPTIONS = {
    "statics": (
        Option("exact linkage (Hamabe eq. 2)", {"geometry": "exact"},
               ("statics", "exact geometry (eq. 2)", "binary64")),
        Option("the paper's series linkage (Hamabe eq. 3)", {"geometry": "series"},
               ("statics", "series geometry (eq. 3)", "binary64"), _has_series_linkage),
    ),
    "vibration": tuple(
        Option(f"harmonic series, {n} harmonics (Hamabe eqs. 18-22)", {"harmonics": n},
               ("vibration", "harmonic series", f"N = {n}"))
        for n in (1, 2, 4, 8, 12, 16, 24, 32, 48, 64, 96, 128, 256)),
    "load_change": (
        Option("linear eq. (28), govopt's exact solver (Newton form of exp(A t))", {},
               ("transient", "govopt transient", "single")),),
    "friction": (
        Option("closed form: strokes by expm, their ends by brentq (Hamabe eqs. 42-46)", {},
               ("friction", "closed form (govopt)", "expm + brentq")),),
}

#: The linear model's own error against the nonlinear equations (reported, not chosen).
LINEARISATION = {"large": ("load change, large", "linear eq. 28 (govopt)", "exact solver"),
                 "small": ("load change, small", "linear eq. 28 (govopt)", "exact solver")}


@functools.cache
def measured(path: str | Path = MEASURED) -> dict[tuple[str, str, str], tuple[float, float]]:
    """``(analysis, method, setting) -> (CPU s per evaluation, relative error)``."""
    with open(path, newline="") as fh:
        return {(r["analysis"], r["method"], r["setting"]): (float(r["time_s"]),
                                                             float(r["error"]))
                for r in csv.DictReader(fh)}


@dataclass(frozen=True)
class Choice:
    """The setting chosen for one analysis, with what was measured for it."""

    analysis: str
    model: str
    setting: dict
    error: float
    time_s: float
    fits: bool
    note: str = ""

    def to_dict(self) -> dict:
        return {"analysis": self.analysis, "model": self.model, "setting": self.setting,
                "measured_error": self.error, "cpu_s_per_evaluation": self.time_s,
                "fits_tolerance": self.fits, **({"note": self.note} if self.note else {})}


def choose(analysis: str, tolerance: float, spec=None) -> Choice:
    """The cheapest option of ``analysis`` whose measured error is within ``tolerance``;
    if none is, the most accurate (``fits=False``). Options without a measurement, or
    meaningless for ``spec``'s governor, are skipped."""
    table = measured()
    cands = [(table[o.row], o) for o in OPTIONS[analysis]
             if o.row in table and (spec is None or o.applies is None or o.applies(spec))]
    if not cands:
        raise ValueError(f"no measured setting for analysis {analysis!r} in {MEASURED}")
    fitting = [c for c in cands if c[0][1] <= tolerance]
    (t, err), opt = (min(fitting, key=lambda c: (c[0][0], c[0][1])) if fitting
                     else min(cands, key=lambda c: (c[0][1], c[0][0])))
    note = ""
    if analysis == "load_change":
        lin = {k: table[v][1] for k, v in LINEARISATION.items() if v in table}
        if lin:
            note = ("the linear model itself differs from the nonlinear equations by "
                    + ", ".join(f"{v:.1e} ({k} load change)" for k, v in lin.items())
                    + " of the initial deviation (measured on Hamabe's case a)")
    return Choice(analysis, opt.model, dict(opt.setting), err, t, bool(fitting), note)


@dataclass(frozen=True)
class Plan:
    """What an evaluation under a use case runs, and at which settings."""

    use_case: str
    tolerance: float
    choices: tuple[Choice, ...]
    skipped: tuple[str, ...] = field(default=())

    def runs(self, analysis: str) -> bool:
        return any(c.analysis == analysis for c in self.choices)

    def apply(self, spec):
        """The spec with every chosen setting in its ``[analysis]``."""
        changes = {k: v for c in self.choices for k, v in c.setting.items()}
        return spec.with_analysis(**changes) if changes else spec

    def to_dict(self) -> dict:
        return {"name": self.use_case, "tolerance": self.tolerance,
                "analyses": [c.to_dict() for c in self.choices],
                "not_run": list(self.skipped)}


def plan(spec) -> Plan | None:
    """The plan for the spec's ``[analysis] use_case`` and ``tolerance``; None without a use
    case (every analysis the spec has data for runs, at the spec's settings)."""
    an = spec.analysis
    use_case = getattr(an, "use_case", None)
    if use_case is None:
        return None
    tol = float(getattr(an, "tolerance", 1e-6))
    if use_case not in USE_CASES:
        raise ValueError(f"use case must be one of {tuple(USE_CASES)}, got {use_case!r}")
    if not tol > 0:
        raise ValueError(f"tolerance must be positive, got {tol!r}")
    wanted = list(USE_CASES[use_case])
    if use_case == "spring_sizing" and spec.material is not None and \
            getattr(spec.material, "grade", None) is not None:
        wanted.append("vibration")  # the spring's load cycle, for its fatigue check
    choices = tuple(choose(a, tol, spec) for a in wanted)
    skipped = tuple(a for a in USE_CASES["full"] if a not in wanted)
    return Plan(use_case, tol, choices, skipped)
