"""Every governor requirement declared once, as a row, and the one evaluator of rows over arrays.

A :class:`Row` (the shape of :class:`govopt.springs.checks.Row`, extended) is ``value(ev) sense
limit(ev)`` with ``ev`` a mapping of SI figures, each a float or an array over N designs; its
group (``"statics"``, ``"spring"``, ``"bounds"``, ``"dynamics"``), its unit, its source, the
scale of its margin where the limit is zero, a verdict where the margin alone cannot decide it,
and where one exists its form in the spring's geometric programme (:class:`GPForm`).

The same rows are read by the one evaluator (:func:`govopt.evaluator.core`: N designs for
the bulk evaluation, one for :func:`govopt.evaluate`), the design search's catalogue screen
(:func:`govopt.optimize.design.spring_checks`) and the spring GP's constraint table
(:mod:`govopt.optimize.gp_table`); :class:`CheckTable` turns rows into values, margins and
verdicts over N designs, and into :class:`govopt.result.Check` objects for one.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from .springs import helical as hx
from .springs.checks import Row as SpringRow
from .units import SI_UNITS
from .verdict import PASS_TOL, Check


@dataclass(frozen=True)
class GPForm:
    """A row in the spring GP (:mod:`govopt.optimize.gp_table`'s table is made of them, the
    requirements' and the GP's own stiffness and stress rows): ``g(d, r, n, t, P) sense
    P[limit]`` with ``sense`` "upper" (``<=``), "lower" (``>=``) or "equal"; ``g_exps`` the
    exponents of the parameters in ``g`` (a monomial in them), for the duals' sensitivities;
    ``name``: the constraint's name in the GP's solution."""

    name: str
    limit: str
    sense: str  # "upper": g <= limit, "lower": g >= limit, "equal": g == limit
    g: Callable[..., Any]
    g_exps: tuple[tuple[str, float], ...] = ()
    source: str = ""

    def log_exponents(self) -> dict[str, float]:
        """Parameter exponents in cvxpy's ``log(args[0]) - log(args[1])`` for this row (the
        duals' sensitivities)."""
        sign = -1.0 if self.sense == "lower" else 1.0  # cvxpy stores g >= c as c <= g
        out = {k: sign * e for k, e in self.g_exps}
        out[self.limit] = out.get(self.limit, 0.0) - sign
        return out


@dataclass(frozen=True)
class Row(SpringRow):
    """One requirement: ``value(ev) sense limit(ev)`` over arrays (see the module's text).

    ``scale(ev)``: the margin's scale where the limit is zero (None: ``|limit|``);
    ``verdict(ev)``: pass/fail decided elsewhere (None: from the margin); ``gp``: the row's GP
    form, where one exists."""

    group: str = ""
    scale: Callable | None = None
    verdict: Callable | None = None
    gp: GPForm | None = None


def _const(v):
    return lambda ev: v


# ---------------------------------------------------------------------------------------------
# The spring GP's forms of the requirements (Hamabe Example 1; Wahl 1944)
# ---------------------------------------------------------------------------------------------

def surge_g(d, r, n, P):
    """Surge frequency ``d / (8 pi r^2 n) sqrt(G / (2 rho))`` (Hz; Wahl 1944 ch. 25, both ends
    fixed) as a monomial in ``d, r, n`` and the parameters ``G`` (Pa), ``density`` (kg/m^3)."""
    return d / (8.0 * np.pi) * r**-2 / n * P["G"] ** 0.5 * (2.0 * P["density"]) ** -0.5


def _index_g(d, r, n, t, P):
    return 2.0 * r / d


GP_BOUNDS = {
    "d_min": GPForm("minimum wire diameter", "d_min", "lower", lambda d, r, n, t, P: d),
    "d_max": GPForm("maximum wire diameter", "d_max", "upper", lambda d, r, n, t, P: d),
    "r_min": GPForm("minimum coil radius", "r_min", "lower", lambda d, r, n, t, P: r),
    "r_max": GPForm("maximum coil radius", "r_max", "upper", lambda d, r, n, t, P: r),
    "n_min": GPForm("minimum active turns", "n_min", "lower", lambda d, r, n, t, P: n),
    "n_max": GPForm("maximum active turns", "n_max", "upper", lambda d, r, n, t, P: n),
    "C_min": GPForm("minimum spring index", "C_min", "lower", _index_g,
                    source="Wahl 1944 ch. 2"),
    "C_max": GPForm("maximum spring index", "C_max", "upper", _index_g,
                    source="Wahl 1944 ch. 2"),
    "D_out_max": GPForm("outer diameter", "D_out_max", "upper",
                        lambda d, r, n, t, P: 2.0 * r + d),
    "L_body_max": GPForm("body length", "L_body_max", "upper",
                         lambda d, r, n, t, P: (n + 1.0) * d),
    "f_surge_min": GPForm("surge frequency", "f_surge_min", "lower",
                          lambda d, r, n, t, P: surge_g(d, r, n, P),
                          (("G", 0.5), ("density", -0.5)), "Wahl 1944 ch. 25"),
}
"""The GP forms of the spring's requirements and search bounds, by the GP parameter that is
their limit (:mod:`govopt.optimize.gp_table` appends them to its stiffness and stress rows)."""


# ---------------------------------------------------------------------------------------------
# The governor's rows
# ---------------------------------------------------------------------------------------------

def statics_rows(spec) -> list[Row]:
    """The statics requirements (group ``"statics"``); ``ev``: ``irregularity``; ``band_low``,
    ``band_high`` (the operating band's lowest and highest speed over the range, with
    friction, :func:`statics.band_extremes`);
    ``rise`` (the least slope of the characteristic,
    :func:`~govopt.analysis.characteristic.rising_slopes`); ``w0sq`` (the reference
    ``omega0^2``); ``F_min``, ``F_top`` (the least and the largest absolute spring force);
    ``k2_min``, ``k2_max``."""
    # here: the spring designer's rows need no governor's statics
    from .analysis import characteristic as chs
    from .analysis import statics
    gov, sp, req = spec.governor, spec.speed, spec.requirements
    margin = req.k2_margin if req else 0.0
    unit = SI_UNITS[gov.coordinate]
    method = gov.method(spec)  # the type's own sources (governors.base.Method)
    rows = []
    if sp is not None:
        rows.append(Row("irregularity", "<=", "", lambda ev: ev["irregularity"],
                        _const(sp.irregularity), method.text("irregularity"), group="statics"))
        if sp.band:
            friction = method.named("band")
            band = statics.BAND_SOURCE + (f" ({friction.cite})" if friction else "")
            rows += [Row(statics.BAND_INNER, ">=", "rad/s", lambda ev: ev["band_low"],
                         _const(sp.omega_inner), band, group="statics"),
                     Row(statics.BAND_OUTER, "<=", "rad/s", lambda ev: ev["band_high"],
                         _const(sp.omega_outer), band, group="statics")]
    rows.append(Row("characteristic rises (stable)", ">=", f"rad/s/{unit}", lambda ev: ev["rise"],
                    _const(0.0),
                    "d omega/dx > 0 over the range: the characteristic "
                    f"({method.named('characteristic').cite}) differentiated, stable by the "
                    f"characteristic curve ({method.named('stable').cite}); margin on omega0 / "
                    "(x_outer - x_inner) (characteristic.stability)", group="statics",
                    scale=lambda ev: chs.slope_scale(spec, np.sqrt(ev["w0sq"]))))
    if gov.spring is not None:
        rows.append(Row(gov.spring_loaded_check, ">=", "N", lambda ev: ev["F_min"], _const(0.0),
                        "the spring stays loaded over the range: its force > 0 ("
                        f"{method.named('spring force').cite})", group="statics",
                        scale=lambda ev: ev["F_top"]))
    rows.append(Row("k^2 > 0 (stability)", ">=", "rad^2/s^2", lambda ev: ev["k2_min"],
                    lambda ev: margin * ev["w0sq"], method.text("stable"), group="statics",
                    scale=lambda ev: ev["w0sq"]))
    if gov.resonance_ceiling:
        rows.append(Row("k^2 < omega0^2 (no resonance)", "<=", "rad^2/s^2",
                        lambda ev: ev["k2_max"], lambda ev: (1.0 - margin) * ev["w0sq"],
                        method.text("resonance"), group="statics"))
    return rows


def statics_figures(irregularity, band_low, band_high, rise, w0sq, spring_force, k2) -> dict:
    """The ``ev`` of :func:`statics_rows` from the figures of one design (1-D arrays over the
    configurations) or many (2-D, a row per design): the spring force's least value and
    largest magnitude and ``k^2``'s extremes over the configurations (last axis)."""
    return {"irregularity": irregularity, "band_low": band_low, "band_high": band_high,
            "rise": rise, "w0sq": w0sq, "F_min": np.min(spring_force, axis=-1),
            "F_top": np.max(np.abs(spring_force), axis=-1), "k2_min": np.min(k2, axis=-1),
            "k2_max": np.max(k2, axis=-1)}


#: where the spring index limits come from (the requirements; the standard's scope for reference)
INDEX_SOURCE = ("requirements.spring_index (EN 13906-1 scope, cold coiled: 4 <= w <= 20; "
                "Shigley prefers 4 <= C <= 12)")


def requirement_rows(spec, req) -> list[Row]:
    """The spring's design requirements (group ``"spring"``) of `govopt design`, what a made
    spring is checked against; ``ev``: ``d``, ``r``, ``n`` (wire diameter, coil radius, active
    turns), ``l0`` (the type's free length), ``C`` (spring index), ``body`` (close-wound body
    length ``(n + 1) d``), ``surge`` (Hz)."""
    factor = spec.governor.spring_length_factor
    rows = [
        Row("spring index >= min", ">=", "", lambda ev: ev["C"], _const(req.spring_index[0]),
            INDEX_SOURCE, group="spring", gp=GP_BOUNDS["C_min"]),
        Row("spring index <= max", "<=", "", lambda ev: ev["C"], _const(req.spring_index[1]),
            INDEX_SOURCE, group="spring", gp=GP_BOUNDS["C_max"]),
        Row("body length within free length", "<=", "m", lambda ev: ev["body"],
            lambda ev: factor * ev["l0"], "close-wound body (n + 1) d within 2 l0",
            group="spring", gp=GP_BOUNDS["L_body_max"]),
    ]
    if req.max_outer_diameter is not None:
        rows.append(Row("outer diameter", "<=", "m", lambda ev: 2.0 * ev["r"] + ev["d"],
                        _const(req.max_outer_diameter), "", group="spring",
                        gp=GP_BOUNDS["D_out_max"]))
    if req.min_surge_frequency is not None:
        rows.append(Row("surge frequency", ">=", "Hz", lambda ev: ev["surge"],
                        _const(req.min_surge_frequency), "Wahl 1944 ch. 25", group="spring",
                        gp=GP_BOUNDS["f_surge_min"]))
    return rows


def search_bound_rows(req) -> list[Row]:
    """The helical spring's search bounds (group ``"bounds"``): the limits of the spring GP's
    continuous bound (:func:`govopt.optimize.design.gp_values`), not requirements of a made
    spring, which is never checked against them; ``ev``: ``d``, ``r``, ``n``."""
    rows = []
    for name, key, bounds, unit in (("wire diameter", "d", req.wire_diameter, "m"),
                                    ("coil radius", "r", req.coil_radius, "m"),
                                    ("active turns", "n", req.active_turns, "")):
        rows += [Row(f"{name} >= min", ">=", unit, lambda ev, k=key: ev[k], _const(bounds[0]), "",
                     group="bounds", gp=GP_BOUNDS[f"{key}_min"]),
                 Row(f"{name} <= max", "<=", unit, lambda ev, k=key: ev[k], _const(bounds[1]), "",
                     group="bounds", gp=GP_BOUNDS[f"{key}_max"])]
    return rows


#: the helical spring's static stress against the spec's allowable (no wire grade)
STRESS_SOURCE = "Hamabe Ex. 1: 16 F r / (pi d^3) <= k_s"


def stress_row(material, spec=None) -> Row:
    """The largest shear stress of a helical spring (``ev["stress"]``, Pa) within the spec's
    allowable ``material.allowable_shear_stress`` (group ``"spring"``; without a wire grade,
    whose table has its own stress rows: :meth:`Governor.spring_checks`); its source the
    type's stress equation (its method) where ``spec`` is given."""
    source = STRESS_SOURCE if spec is None else \
        spec.governor.method(spec).text("stress", STRESS_SOURCE) + " <= k_s"
    return Row("shear stress", "<=", "Pa", lambda ev: ev["stress"],
               _const(material.allowable_shear_stress), source, group="spring")


class SpringFigures(dict):
    """The ``ev`` of :func:`requirement_rows` for helical springs (floats or arrays), each
    figure computed when a row first reads it: ``C = 2 r / d``, ``body = (n + 1) d`` and the
    surge frequency (:func:`govopt.springs.helical.surge_frequency_r`, Hz) of the ``material``."""

    def __init__(self, d, r, n, l0, material, m=None):
        super().__init__(d=d, r=r, n=n, l0=l0, m=m)
        self.material = material

    def __missing__(self, key):
        d, r, n = self["d"], self["r"], self["n"]
        if key == "C":
            value = hx.spring_index_r(d, r)
        elif key == "body":
            value = (n + 1.0) * d
        elif key == "surge":
            value = hx.surge_frequency_r(d, r, n, self.material.shear_modulus,
                                           self.material.density)
        else:
            raise KeyError(key)
        self[key] = value
        return value


def holds(rows, ev) -> np.ndarray:
    """True where every row holds on ``ev`` (NaN fails), without margins: the screens' test."""
    ok = True
    for row in rows:
        value, limit = row.value(ev), row.limit(ev)
        ok = ok & (value <= limit if row.sense == "<=" else value >= limit)
    return np.asarray(ok)


def load_change_rows(spec, name: str) -> list[Row]:
    """The load change ``name``'s requirements (Hamabe Part III; group ``"dynamics"``);
    ``ev``: ``hurwitz``, ``over`` (over-regulation, the coordinate's unit), ``over_regulates``,
    ``xi0`` (the initial offset), ``settling`` (s), each of the load change ``name``."""
    req = spec.requirements
    unit = SI_UNITS[spec.governor.coordinate]
    cubic = spec.governor.method(spec).named("cubic")  # the type's own load-change model
    rows = [Row(f"Hurwitz margin: {name}", ">=", "", lambda ev: ev["hurwitz"],
                _const(req.hurwitz_margin if req else 0.0),
                spec.governor.method(spec).text("hurwitz"), group="dynamics",
                scale=_const(1.0)),
            Row(f"no over-regulation: {name}", "<=", unit, lambda ev: ev["over"],
                _const(0.0), f"{cubic.cite}; all t >= 0 (over_regulation.over_regulates)",
                group="dynamics", scale=lambda ev: np.abs(ev["xi0"]),
                verdict=lambda ev: ~np.asarray(ev["over_regulates"], dtype=bool))]
    if req is not None and req.max_settling_time is not None:
        rows.append(Row(f"settling time: {name}", "<=", "s", lambda ev: ev["settling"],
                        _const(req.max_settling_time), cubic.cite, group="dynamics"))
    return rows


def friction_rows(spec, name: str) -> dict[str, Row]:
    """Hamabe's friction transient of load change ``name`` (eqs. 42-46; group ``"dynamics"``),
    by outcome: ``"stuck"`` (the governor does not follow the load change: ``ev["rest"]``, the
    offset it rests at) and ``"moves"`` (``ev["past"]``, how far the first stroke ends past the
    new equilibrium); ``ev["xi0"]`` the initial offset (the coordinate's unit)."""
    unit = SI_UNITS[spec.governor.coordinate]
    eq = spec.governor.method(spec).named("strokes")  # the type's words (borrowed?)
    strokes = eq.cite if eq is not None else "Hamabe eqs. 42-46"
    return {
        "stuck": Row(f"friction: the governor follows the load change: {name}", "<=", unit,
                     lambda ev: ev["rest"], _const(0.0),
                     f"{strokes}: stuck while |C eta - I k^2 xi| <= M0",
                     group="dynamics", scale=lambda ev: abs(ev["xi0"])),
        "moves": Row(f"friction: no over-regulation after the first stroke: {name}", "<=", unit,
                     lambda ev: ev["past"], _const(0.0), strokes,
                     group="dynamics", scale=lambda ev: abs(ev["xi0"]) or 1.0),
    }


def vibration_rows(spec) -> list[Row]:
    """The forced vibration's requirement (Hamabe Part II); ``ev``: ``p2p`` (peak to peak, the
    coordinate's unit)."""
    req = spec.requirements
    if req is None or req.max_vibration is None:
        return []
    return [Row("vibration peak-to-peak", "<=", SI_UNITS[spec.governor.coordinate],
                lambda ev: ev["p2p"], _const(req.max_vibration),
                "Hamabe Part II, eqs. (18)-(22)", group="dynamics")]


# ---------------------------------------------------------------------------------------------
# The evaluator of rows
# ---------------------------------------------------------------------------------------------

class Column(NamedTuple):
    """One row of a :class:`CheckTable` over its N designs: value, limit, margin, the margin's
    scale (NaN: ``|limit|``), verdict, and whether the row applies to each design."""

    value: np.ndarray
    limit: np.ndarray
    margin: np.ndarray
    scale: np.ndarray
    passed: np.ndarray
    applies: np.ndarray


def _over(v, n: int, dtype=float) -> np.ndarray:
    """``v`` as an array over ``n`` designs (broadcast where it is one number)."""
    a = np.asarray(v, dtype=dtype)
    if a.shape == (n,):
        return a
    return np.full(n, a, dtype) if a.ndim == 0 else np.broadcast_to(a, (n,))


class CheckTable:
    """Rows evaluated over N designs, in the order added: arrays of values, limits, margins and
    verdicts (``applies`` False where a row does not apply to a design). ``checks(i)`` gives
    design ``i``'s :class:`~govopt.result.Check` objects; ``columns()`` the arrays (the bulk
    evaluation's columns), ``failed()`` which rows fail for which design."""

    def __init__(self, n: int):
        self.n = n
        self._cols: dict[str, Column] = {}
        self._meta: dict[str, tuple] = {}
        self.names: list[str] = []

    def add_row(self, row: Row, ev, where=None) -> None:
        """Evaluate ``row`` on ``ev`` for the designs ``where`` (all if None)."""
        self.add(row.name, row.value(ev), row.limit(ev), row.sense,
                 scale=None if row.scale is None else row.scale(ev),
                 verdict=None if row.verdict is None else row.verdict(ev), where=where,
                 unit=row.unit, source=row.source, group=row.group)

    def add_rows(self, rows, ev, where=None) -> None:
        for row in rows:
            self.add_row(row, ev, where)

    def add(self, name, value, limit, sense, scale=None, verdict=None, where=None, unit="",
            source="", group=""):
        """``Check.margin`` vectorised: ``(limit - value)/s`` for ``<=``, ``(value - limit)/s``
        for ``>=``, ``s = scale or (|limit| if limit != 0 else 1)``; ``Check.passed``."""
        n = self.n
        value, limit = _over(value, n), _over(limit, n)
        fallback = np.where(limit != 0, np.abs(limit), 1.0)
        if scale is None:
            s = fallback
            sc = np.full(n, np.nan)
        else:
            sc = _over(scale, n)
            s = np.where(sc != 0, sc, fallback)
        diff = limit - value if sense == "<=" else value - limit
        with np.errstate(invalid="ignore", divide="ignore"):
            margin = diff / s
        given = verdict is not None
        passed = margin >= PASS_TOL if not given else _over(verdict, n, bool)
        on = slice(None) if where is None else _over(where, n, bool)
        if name not in self._cols:
            self.names.append(name)
            self._cols[name] = Column(*(np.full(n, np.nan) for _ in range(4)),
                                      np.zeros(n, bool), np.zeros(n, bool))
            self._meta[name] = (sense, unit, source, given, group)
        v, lim, m, scl, p, applies = self._cols[name]
        v[on], lim[on], m[on], scl[on] = value[on], limit[on], margin[on], sc[on]
        p[on] = passed[on]
        applies[on] = True

    def drop(self, designs) -> None:
        """No row applies to the ``designs`` (a mask): designs that cannot be evaluated."""
        for c in self._cols.values():
            for a in c[:4]:
                a[designs] = np.nan
            c.passed[designs] = False
            c.applies[designs] = False

    def checks(self, i: int = 0, source_of=None) -> list[Check]:
        """Design ``i``'s checks (the rows that apply to it), in order; ``source_of(text)``
        resolves a callable source."""
        out = []
        for name in self.names:
            v, lim, _, scl, p, applies = self._cols[name]
            if not applies[i]:
                continue
            sense, unit, source, given, group = self._meta[name]
            if callable(source):
                source = source_of(source) if source_of else source()
            out.append(Check(name, float(v[i]), float(lim[i]), sense, unit, source,
                             scale=None if np.isnan(scl[i]) else float(scl[i]),
                             verdict=bool(p[i]) if given else None, group=group))
        return out

    def units(self) -> dict[str, str]:
        """Every row's SI unit (``""`` dimensionless), by name, in order."""
        return {name: self._meta[name][1] for name in self.names}

    def columns(self) -> dict[str, Column]:
        """Every row's arrays (:class:`Column`), by name, in order."""
        return {name: self._cols[name] for name in self.names}

    def failed(self) -> np.ndarray:
        """``(N, rows)`` booleans: True where a row applies to a design and fails (NaN fails);
        the rows in :attr:`names` order."""
        out = np.zeros((self.n, len(self.names)), bool)
        for j, name in enumerate(self.names):
            c = self._cols[name]
            out[:, j] = c.applies & ~c.passed
        return out

    def feasible(self) -> np.ndarray:
        """True where every row that applies holds (NaN fails)."""
        return ~self.failed().any(axis=1)


__all__ = ["GP_BOUNDS", "PASS_TOL", "CheckTable", "Column", "GPForm", "Row", "SpringFigures",
           "friction_rows", "holds", "load_change_rows", "requirement_rows",
           "search_bound_rows", "statics_rows",
           "statics_figures", "stress_row", "vibration_rows"]
