"""One record of an optimisation, whatever solved it: what was optimised, how well, and what
limits it.

A :class:`Record` is what an optimiser says of its answer: the status, the objective (its name,
unit and sense), the value, a certified bound and the gap to it, the constraints that bind,
the sensitivity of the objective to each limit, the solver and the time it took. The spring
designer (an exact GP, or a catalogue of wires and coil counts enumerated against the GP's
bound), the literature's spring problems (Belegundu's GP, Sandgren's enumeration) write one;
``govopt spring check`` optimises nothing and writes none (its JSON's ``optimisation`` is
``null``); the governor's design (:mod:`govopt.optimize.design`, a robust one too) writes one
with its own sections (:attr:`Record.sections`: the chosen design, the bound's design, the
bounds searched, a robust design's box). Every record renders to the same JSON keys
(:meth:`Record.to_dict`, then its sections), in SI; the text, the JSON and the workbook read
it.

Conventions (stated once, here, and in the JSON's ``sensitivity_convention``):

- **units**: ``value`` and ``bound`` are in ``objective.unit`` (SI), a field of its own: the
  objective differs from problem to problem (kg, m^3, m, kg/J) and the key set does not;
- **bound**: for a minimisation a certified *lower* bound (no design can do better), for a
  maximisation an upper one; ``gap`` is how far the value can be from the optimum at most,
  ``value / bound - 1`` (minimise) or ``bound / value - 1`` (maximise), >= 0; ``certified``
  when the gap is at most :data:`CERTIFIED_GAP`;
- **sensitivities** (:data:`SENSITIVITY_CONVENTION`): the dual-based elasticity
  ``d ln(objective) / d ln(limit)`` of each constraint's limit, from the solver's Lagrange
  multipliers (a GP's duals are these elasticities, Boyd et al., "A tutorial on geometric
  programming", Optim. Eng. 8 (2007), section 5.3): the per cent change of the objective per
  per cent increase of the limit, whatever the limit's sense. Negative: raising the limit
  lowers the objective (an upper limit that binds a minimisation); positive: raising it
  costs (a lower limit that binds); zero: the constraint does not bind. An objective that is
  maximised reports the elasticity of the maximised quantity. Where the answer is discrete
  (enumerated), the sensitivities are those of the continuous relaxation that gives the bound,
  and ``sensitivities_of`` says so; where they are not the solver's duals but a +1 % finite
  difference of the bound re-solved (the governor's design), ``sensitivities_of`` says that.

>>> r = Record(status="optimal", objective=Objective("mass", "kg"), value=0.151, bound=0.151,
...            active=["stiffness", "allowable stress"],
...            sensitivities={"allowable stress": -1.93, "stiffness": -0.855},
...            solver="CLARABEL", method="geometric programme")
>>> r.certified, r.gap
(True, 0.0)
>>> sorted(r.to_dict()) == sorted(KEYS)
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

__all__ = ["CERTIFIED_GAP", "KEYS", "SENSITIVITY_CONVENTION", "Objective", "Record"]

#: a gap at most this is a certified optimum (the solvers' own tolerance is ~1e-9)
CERTIFIED_GAP = 1e-6

SENSITIVITY_CONVENTION = (
    "elasticity d ln(objective) / d ln(limit): per cent change of the objective per +1 % on the "
    "constraint's limit (negative: raising the limit lowers the objective; zero: the constraint "
    "does not bind); a dual-based elasticity from the solver's Lagrange multipliers, or a +1 % "
    "finite difference where sensitivities_of says so")

#: the JSON keys of every record (:meth:`Record.to_dict`)
KEYS = ("status", "objective", "value", "bound", "bound_kind", "gap", "certified", "claim",
        "active_constraints", "sensitivities", "sensitivities_of", "sensitivity_convention",
        "method", "solver", "solve_time_s", "search", "notes")


@dataclass(frozen=True)
class Objective:
    """What is optimised: its name, its SI unit and whether it is minimised or maximised;
    ``counts``: what it sums, in words (the moving mass's parts), where it is a sum."""

    name: str
    unit: str
    sense: str = "minimise"
    counts: str = ""

    def __post_init__(self):
        if self.sense not in ("minimise", "maximise"):
            raise ValueError(f"objective sense must be 'minimise' or 'maximise', got "
                             f"{self.sense!r}")


@dataclass
class Record:
    """An optimiser's answer (module docstring): SI values in ``objective.unit``."""

    status: str
    objective: Objective
    value: float = math.nan
    #: a certified bound on the optimum (lower when minimising), nan when none was proved
    bound: float = math.nan
    active: list[str] = field(default_factory=list)
    #: constraint name -> elasticity (:data:`SENSITIVITY_CONVENTION`)
    sensitivities: dict[str, float] = field(default_factory=dict)
    #: what the sensitivities are of: the design, or the relaxation that gives the bound
    sensitivities_of: str = "the optimum"
    #: how the answer and its bound were found (a GP, a bounded enumeration, ...)
    method: str = ""
    solver: str = ""
    solve_time_s: float = math.nan
    #: counts of the search (pairs examined, wires pruned, ...)
    search: dict[str, int] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    #: what one optimiser adds, each under its own JSON key after :data:`KEYS` (the governor's
    #: chosen ``design``, the ``bound_design``, the ``search_bounds``, a ``robust`` box)
    sections: dict[str, object] = field(default_factory=dict)

    def __post_init__(self):
        if clash := set(self.sections) & set(KEYS):
            raise ValueError(f"a record's sections may not reuse its keys: {sorted(clash)}")

    @property
    def ok(self) -> bool:
        """An answer was found (optimal, possibly inaccurate)."""
        return self.status.startswith("optimal")

    @property
    def gap(self) -> float:
        """How far the value can be from the optimum at most, relative (>= 0; nan: no
        bound); rounding below the bound counts as 0."""
        if not (math.isfinite(self.value) and math.isfinite(self.bound)) or self.bound <= 0:
            return math.nan
        ratio = (self.value / self.bound if self.objective.sense == "minimise"
                 else self.bound / self.value)
        return max(0.0, ratio - 1.0)

    @property
    def certified(self) -> bool:
        """The value is a proven optimum (gap at most :data:`CERTIFIED_GAP`)."""
        return self.ok and self.gap <= CERTIFIED_GAP

    def claim(self, bound_text: str | None = None) -> str:
        """What can be said of the answer: a certified optimum, optimal within X % of a
        certified bound (``bound_text``: the bound as a person reads it), or no bound."""
        if not self.ok:
            return f"no answer ({self.status})"
        if self.certified:
            return "global optimum certified"
        if math.isfinite(self.gap):
            shown = f" ({bound_text})" if bound_text else ""
            return f"optimal within {100 * self.gap:.3g} % of a certified bound{shown}"
        return "no certified bound (the relaxation was not solved to optimality)"

    def to_dict(self) -> dict:
        """The record as JSON (:data:`KEYS`, then :attr:`sections`; SI in ``objective.unit``,
        nan as None)."""
        def num(x):
            return float(x) if isinstance(x, int | float) and math.isfinite(x) else None

        return {
            "status": self.status,
            "objective": {"name": self.objective.name, "unit": self.objective.unit,
                          "sense": self.objective.sense,
                          **({"counts": self.objective.counts} if self.objective.counts
                             else {})},
            "value": num(self.value),
            "bound": num(self.bound),
            "bound_kind": "lower" if self.objective.sense == "minimise" else "upper",
            "gap": num(self.gap),
            "certified": bool(self.certified),
            "claim": self.claim(),
            "active_constraints": list(self.active),
            "sensitivities": {k: float(v) for k, v in self.sensitivities.items()},
            "sensitivities_of": self.sensitivities_of,
            "sensitivity_convention": SENSITIVITY_CONVENTION,
            "method": self.method,
            "solver": self.solver,
            "solve_time_s": num(self.solve_time_s),
            "search": dict(self.search),
            "notes": list(self.notes),
            **self.sections,
        }
