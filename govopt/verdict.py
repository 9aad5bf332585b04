"""Checks and figures: the typed cells of a result, on the ground floor (imports nothing of
govopt but :mod:`govopt.jsonable`, which imports nothing of govopt).

A :class:`Check` is one requirement held against its limit, a :class:`Figure` one reported
number; each carries its SI unit, its source and its group as fields, so that every writer (text,
JSON, workbook, plots, a pandas frame) reads the unit from the field and none parses it back
from a name. Physics (the spring tables, the governors, the evaluator) builds them; the result and
its writers only format them.

JSON keys still name their unit (govopt's JSON rule, ``"wire_diameter_m"``); :func:`json_key`
derives such a key from a figure's name and unit, one way only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .jsonable import jsonable

__all__ = ["ACTIVE_TOL", "GROUPS", "PASS_TOL", "SHOWN", "Check", "Figure", "holds", "json_key",
           "margins", "shown"]

#: Relative margin below which a satisfied check is reported as active (binding).
ACTIVE_TOL = 1e-3
#: The least relative margin that passes: a check holds at equality (an equality by
#: construction, such as the coil-clash row ``L0 = L_n + F/R``, rounds either way by ~1e-16).
PASS_TOL = -1e-9


def margins(value, limit, sense: str, scale=None):
    """:attr:`Check.margin` over arrays: ``(limit - value)`` for ``<=`` (``value - limit`` for
    ``>=``) over ``scale``, else ``|limit|``, else 1 where the limit is zero.

    >>> margins([1.0, 2.0], 2.0, "<=").tolist()
    [0.5, 0.0]
    """
    value, limit = np.asarray(value, dtype=float), np.asarray(limit, dtype=float)
    if scale is None:
        scale = np.where(limit != 0, np.abs(limit), 1.0)
    diff = limit - value if sense == "<=" else value - limit
    with np.errstate(invalid="ignore"):
        return diff / scale


def holds(value, limit, sense: str, scale=None):
    """Where a row ``value sense limit`` passes, over arrays: as :attr:`Check.passed` does,
    its margin (:func:`margins`) at least :data:`PASS_TOL` (NaN fails). Every feasibility
    test of a search reads this, so a design the search keeps is one whose checks pass.

    >>> holds([1.0, 1.0 + 1e-16, 1.1], 1.0, "<=").tolist()
    [True, True, False]
    """
    with np.errstate(invalid="ignore"):
        return margins(value, limit, sense, scale) >= PASS_TOL

#: How an SI unit is shown to a person (text, workbook, notebook, ``to_frame(engineering=True)``):
#: SI unit -> (shown unit, factor to multiply by). Units not listed are shown as they are.
SHOWN: dict[str, tuple[str, float]] = {
    "rad": ("deg", 180.0 / math.pi),
    "m": ("mm", 1e3),
    "Pa": ("MPa", 1e-6),
    "N/m": ("N/mm", 1e-3),
    "rad/s": ("rpm", 30.0 / math.pi),
    "rad/s/rad": ("rad/s per deg", math.pi / 180.0),
    "rad/s/m": ("rad/s per mm", 1e-3),
    "rad^2/s^2": ("1/s^2", 1.0),
    "N*m": ("N m", 1.0),
    "kg*m^2": ("kg m^2", 1.0),
}


def shown(value: Any, unit: str, only=None) -> tuple[Any, str]:
    """``(value, unit)`` converted from SI to the unit people read (:data:`SHOWN`); numbers,
    arrays and lists of numbers are converted, anything else is returned as is. ``only``: the
    SI units to convert (the rest stay SI).

    >>> shown(0.5, "rad")[1], round(shown(0.5, "rad")[0], 4), shown(2e8, "Pa")
    ('deg', 28.6479, (200.0, 'MPa'))
    """
    if unit not in SHOWN or (only is not None and unit not in only):
        return value, unit
    new, factor = SHOWN[unit]
    if isinstance(value, bool) or value is None:
        return value, new
    if isinstance(value, list | tuple):
        return [shown(v, unit)[0] for v in value], new
    try:
        return value * factor, new
    except TypeError:
        return value, new


#: The groups checks and figures fall in, in the order reports list them. ``"spring"``: the
#: spring engineering tables (:mod:`govopt.springs.checks`: static stresses, geometry, fatigue,
#: surge, an extension spring's fit), which the spring sheet cites by source.
GROUPS = ("speed", "statics", "dynamics", "spring", "design", "")


@dataclass(frozen=True)
class Check:
    """One requirement: ``value`` against ``limit`` in the sense ``"<="`` or ``">="``, both in
    ``unit`` (SI: ``"m"``, ``"Pa"``, ``"rad"``, ``"s"``; ``""`` dimensionless).

    >>> c = Check("shear stress", 4.0e8, 5.0e8, "<=", "Pa", "EN 13906-1", group="spring")
    >>> round(c.margin, 3), c.passed, c.active, c.unit
    (0.2, True, False, 'Pa')
    """

    name: str
    value: float
    limit: float
    sense: str
    unit: str = ""
    source: str = ""
    scale: float | None = None
    #: Pass/fail decided elsewhere (e.g. :func:`govopt.analysis.over_regulation.over_regulates`)
    #: where the margin alone cannot decide it; None: from the margin.
    verdict: bool | None = None
    #: what the check belongs to (:data:`GROUPS`), e.g. ``"spring"`` for the spring tables
    group: str = ""

    @property
    def margin(self) -> float:
        """Relative margin: positive when satisfied, ``(limit - value)/|limit|`` for ``<=``
        (divided by ``scale`` instead where the limit is zero)."""
        scale = self.scale or (abs(self.limit) if self.limit != 0 else 1.0)
        diff = self.limit - self.value if self.sense == "<=" else self.value - self.limit
        return diff / scale

    @property
    def passed(self) -> bool:
        return self.margin >= PASS_TOL if self.verdict is None else self.verdict

    @property
    def active(self) -> bool:
        return self.passed and self.margin < ACTIVE_TOL

    def to_dict(self) -> dict:
        """JSON-ready; ``value`` and ``limit`` in ``unit`` (the checks differ in units, so the
        unit is a field), infinities as null with a flag (:func:`govopt.jsonable.jsonable`)."""
        return jsonable({"name": self.name, "value": self.value, "limit": self.limit,
                         "sense": self.sense, "unit": self.unit, "margin": self.margin,
                         "passed": self.passed, "active": self.active, "source": self.source,
                         "group": self.group})


@dataclass(frozen=True)
class Figure:
    """One reported number of a design: ``value`` in the SI ``unit`` (``""`` dimensionless; a
    word where the figure is a verdict, e.g. a stability class), with what it means.

    >>> Figure("wire diameter", 0.004, "m", group="design", symbol="d").key
    'wire_diameter_m'
    """

    name: str
    value: Any
    unit: str = ""
    group: str = ""
    source: str = ""
    symbol: str = ""
    note: str = ""
    #: the JSON key, where govopt's JSON names it otherwise than :func:`json_key` would
    json: str | None = None

    @property
    def key(self) -> str:
        """The figure's JSON key (``json``, else :func:`json_key` of its name and unit)."""
        return self.json or json_key(self.name, self.unit)


#: How a unit is spelt at the end of a JSON key (govopt's JSON rule: each key names its unit).
_KEY_SUFFIX = {"N*m*s/rad": "N_m_s_per_rad", "N*s/m": "N_s_per_m", "rad^2/s^2": "rad2_s2",
               "N/m": "N_per_m", "kg*m^2": "kg_m2", "rad/s": "rad_s", "1/s": "per_s",
               "N*m": "N_m", "%": "percent", "rpm": "rpm"}


def json_key(name: str, unit: str) -> str:
    """The JSON key of a figure: its name in snake case with its unit's suffix.

    >>> json_key("dashpot", "N*m*s/rad"), json_key("active turns", ""), json_key("mass", "kg")
    ('dashpot_N_m_s_per_rad', 'active_turns', 'mass_kg')
    """
    stem = name.strip().replace(" ", "_").replace("-", "_")
    if not unit:
        return stem
    return f"{stem}_{_KEY_SUFFIX.get(unit, unit.replace('*', '_').replace('/', '_per_'))}"
