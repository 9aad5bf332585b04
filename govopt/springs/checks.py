"""The helical spring's checks as one constraint table per spring type.

Each :class:`Row` is ``value(kw) sense limit(kw)`` with a source; the same rows evaluate over
numpy arrays (an optimiser's screen: :func:`evaluate`) and, for one design, become
:class:`govopt.verdict.Check` objects with value, limit, margin and source (:func:`checks`).

Keywords (SI): ``mat`` (:class:`~govopt.springs.materials.Material`), ``d``, ``D`` (m), ``n``
(active coils; for an extension spring the *body* coils ``n_body``), ``F1 <= F2`` the least and
largest working forces (N). Compression springs also take ``n_t`` (total coils), ``L0`` (free
length, m), ``ends`` (:data:`~govopt.springs.compression.END_FORMS`), ``seating``
(:data:`~govopt.springs.compression.SEATING`) and ``s_max`` - the largest deflection including the
overspeed margin (default ``F2 / R``; the static stress is checked at the larger of ``F2`` and
``R s_max``). Extension springs take ``F0`` (initial tension, N),
``r1`` (hook radius, default ``D/2``, a full loop) and ``r2`` (bend radius where the hook leaves
the body, default ``2 d``, Shigley's least advisable ``C2 = 4``). Common options: ``method``
("EN13906" or "Shigley", the allowable-stress and fatigue rules), ``allowable`` (an explicit
allowable static shear stress, Pa, overriding the rule), ``correction`` (the stress correction
of the static body stresses, overriding the rule's: "none", "wahl" or "bergstrasser"),
``peened``, ``criterion`` (fatigue line
where Zimmerli's data apply), ``fatigue_safety`` (required, default 1), ``cycles`` (required
life, default 1e7), ``harmonics_hz`` (excitation harmonics actually present), ``detuning``
(required relative distance of the surge frequency from each of them, default 0.2),
``index_min``/``index_max`` (default 4 and 20: EN 13906-1's range for cold-coiled springs),
``L0_max`` (space for the free length).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..verdict import Check, holds
from . import compression as hc
from . import extension as he
from . import fatigue as fat
from . import helical as hx
from . import tolerances as tol
from .materials import allowable_static_stress, static_rule

DEFAULTS = dict(method="EN13906", allowable=None, correction=None, peened=False,
                criterion="goodman",
                fatigue_safety=1.0, cycles=1e7, harmonics_hz=(), detuning=0.2, index_min=4.0,
                index_max=20.0, L0_max=None)
COMPRESSION_DEFAULTS = dict(DEFAULTS, ends="closed_ground", seating="hinged-hinged", s_max=None,
                            dynamic=True)
EXTENSION_DEFAULTS = dict(DEFAULTS, F0=0.0, r1=None, r2=None)


@dataclass(frozen=True)
class Row:
    """One constraint: ``value(kw) sense limit(kw)``; ``source`` is text or ``source(kw)``."""

    name: str
    sense: str
    unit: str
    value: Callable
    limit: Callable
    source: str | Callable


class _Prepared(dict):
    """:func:`prepare`'s keywords: each derived quantity (moduli, R_m, index, rate, largest
    force, surge frequency) computed when a row first reads it, so that a subset of the rows
    (``only=GEOMETRY``: the design screen's millions of springs) pays for what it reads only;
    the same numbers as computing them all up front (each is elementwise)."""

    def __missing__(self, key):
        derive = _DERIVED[self["kind"]].get(key)
        if derive is None:
            raise KeyError(key)
        self[key] = value = derive(self)
        return value


def _surge(kw):
    return hx.surge_frequency(kw["d"], kw["D"], kw["n_active"], kw["G"], kw["mat"].density)


_COMMON_DERIVED = {
    "G": lambda kw: kw["mat"].shear_modulus(kw["d"]),
    "E": lambda kw: kw["mat"].elastic_modulus(kw["d"]),
    "Rm": lambda kw: kw["mat"].tensile_strength(kw["d"]),
    "C": lambda kw: hx.spring_index(kw["d"], kw["D"]),
    "f_e": _surge,
    # the largest wire diameter within tolerance, of the solid length (EN 13906-1)
    "d_max": lambda kw: tol.max_wire_diameter(kw["d"], kw["mat"].grade),
}
_DERIVED = {
    "compression": {
        **_COMMON_DERIVED,
        "R": lambda kw: hx.stiffness(kw["d"], kw["D"], kw["n"], kw["G"]),
        # the static stress at the overspeed deflection
        "F_max": lambda kw: np.maximum(kw["F2"], kw["R"] * kw["s_max"]),
        # the force that closes the spring solid (none beyond it follows the rate), and the
        # largest force the spring's wire feels: no more than that
        "F_c": lambda kw: kw["R"] * np.maximum(
            kw["L0"] - hc.solid_length(kw["d_max"], kw["n_t"], kw["ends"]), 0.0),
        "F_reached": lambda kw: np.minimum(kw["F_max"], kw["F_c"]),
    },
    "extension": {
        **_COMMON_DERIVED,
        "n_active": lambda kw: he.extension_active_coils(kw["n_body"], kw["G"], kw["E"]),
        "R": lambda kw: hx.stiffness(kw["d"], kw["D"], kw["n_active"], kw["G"]),
    },
}


def prepare(kind: str, **kw) -> dict:
    """Fill defaults and the derived quantities every row needs (moduli, R_m, rate, ...; each
    computed when first read: :class:`_Prepared`).

    Parameters
    ----------
    kind : str [-]
        ``"compression"`` or ``"extension"`` (:data:`TABLES`).
    **kw : dict [SI: m, N, Pa]
        The design's keywords, SI (see the module): ``mat``, ``d``, ``D`` [m], ``n`` or
        ``n_body`` [-], ``F1``, ``F2`` [N], ... and the options.

    Returns
    -------
    dict [SI]
        The keywords with defaults and derived quantities: ``G``, ``E``, ``Rm`` [Pa], ``C``
        [-], ``R`` [N/m], ``f_e`` [Hz], ...

    References
    ----------
    [shigley] 9th ed. ch. 10; [en13906-1] (each row names its own clause as its source).

    Examples
    --------
    The spring of Shigley's Example 10-4 (its data and what the book prints: :func:`checks`);
    the book prints C = 5.11 and k = 48.1 lbf/in:

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> kw = dict(mat=material("Shigley A228"), d=0.092 * inch, D=(9 / 16 - 0.092) * inch, n=21,
    ...           n_t=23, L0=4.375 * inch, F1=5 * lbf, F2=35 * lbf, method="Shigley",
    ...           criterion="gerber")
    >>> p = prepare("compression", **kw)
    >>> round(float(p["C"]), 3), round(float(p["R"]) / (lbf / inch), 1)
    (5.114, 48.1)
    """
    kw = _Prepared(COMPRESSION_DEFAULTS if kind == "compression" else EXTENSION_DEFAULTS,
                   **kw, kind=kind)
    d, D = np.asarray(kw["d"], dtype=float), np.asarray(kw["D"], dtype=float)
    kw.update(d=d, D=D)
    if kind == "compression":
        kw["n_active"] = np.asarray(kw["n"], dtype=float)
        if kw["s_max"] is None:
            kw["s_max"] = kw["F2"] / kw["R"]
    else:
        kw["L0"] = he.extension_free_length(d, D, kw["n_body"])
        kw["r1"] = D / 2.0 if kw["r1"] is None else kw["r1"]
        kw["r2"] = 2.0 * d if kw["r2"] is None else kw["r2"]
        kw["F_max"] = kw["F2"]
    return kw


def _static(place):
    def value(kw):
        rule = static_rule(kw["mat"], place, kw["method"])
        F = {"solid": "F_c", "compression": "F_reached"}.get(place, "F_max")
        return hx.shear_stress(kw[F], kw["d"], kw["D"], kw["correction"] or rule.correction)

    def limit(kw):
        override = kw["allowable"] if place in ("compression", "extension") else None
        return allowable_static_stress(kw["mat"], kw["d"], place, kw["method"], override)

    def source(kw):
        rule = static_rule(kw["mat"], place, kw["method"])
        text = rule.source
        if place in ("compression", "extension") and kw["allowable"] is not None:
            text = "allowable shear stress given in the spec"
        if kw["correction"] not in (None, rule.correction):
            text += f"; stress with the {kw['correction']} factor (chosen in place of the rule's)"
        return text
    return value, limit, source


#: Life of the fatigue data (EN 13906-1 Goodman diagrams and Zimmerli's data: 1e7 cycles)
DATA_CYCLES = 1e7


def _life_note(kw, cycles_of_data, body: bool = False):
    if kw["cycles"] > cycles_of_data:
        return (f"; required life {kw['cycles']:.3g} cycles exceeds the data's "
                f"{cycles_of_data:.3g} (fatigue strength assumed constant beyond)")
    if kw["cycles"] < cycles_of_data and body:
        return (f"; at the required life {kw['cycles']:.3g} cycles: the strength on Basquin's "
                f"line from 0.9 S_su at 1e3 to the data's {cycles_of_data:.3g} cycles (Shigley "
                "9th ed. section 6-7)")
    if kw["cycles"] < cycles_of_data:
        return (f"; at the data's {cycles_of_data:.3g} cycles (a required life of "
                f"{kw['cycles']:.3g} is shorter: on the safe side)")
    return ""


def _body_fatigue(kw):
    """The body's fatigue safety at the required life: at the data's life (the grade's EN
    13906-1 diagram, else Zimmerli's), times the S-N line's strength ratio where the required
    life is shorter (:func:`govopt.springs.fatigue.life_factor`)."""
    diagram = kw["mat"].fatigue_diagram(kw["peened"]) if kw["method"] == "EN13906" else None
    if diagram is not None:
        safety = fat.en13906_fatigue_safety(kw["F1"], kw["F2"], kw["d"], kw["D"], diagram)
    else:
        Fa, Fm = np.abs(kw["F2"] - kw["F1"]) / 2.0, (kw["F2"] + kw["F1"]) / 2.0
        tau_a = hx.shear_stress(Fa, kw["d"], kw["D"], "bergstrasser")
        tau_m = hx.shear_stress(Fm, kw["d"], kw["D"], "bergstrasser")
        safety = fat.shigley_fatigue_safety(tau_a, tau_m, kw["Rm"], kw["peened"],
                                            kw["criterion"])
    if np.all(np.asarray(kw["cycles"]) >= DATA_CYCLES):
        return safety
    Sse, Ssu = fat.reversed_endurance(kw["mat"], kw["d"], kw["method"], kw["peened"],
                                      kw["criterion"])
    return safety * fat.life_factor(kw["cycles"], Sse, Ssu, DATA_CYCLES)


def _body_fatigue_source(kw):
    diagram = kw["mat"].fatigue_diagram(kw["peened"]) if kw["method"] == "EN13906" else None
    note = _life_note(kw, DATA_CYCLES, body=True)
    if diagram is not None:
        return diagram.source + ", Bergstraesser-corrected stresses" + note
    return (f"{fat.ZIMMERLI_SOURCE}; {kw['criterion'].capitalize()} line through "
            f"S_su = 0.67 S_ut (Shigley §10-9), K_B-corrected stresses" + note)


def _hook_fatigue(point):
    def value(kw):
        F1, F2 = kw["F1"], kw["F2"]
        if point == "A":
            sa = he.hook_bending_stress(np.abs(F2 - F1) / 2.0, kw["d"], kw["D"], kw["r1"])
            sm = he.hook_bending_stress((F2 + F1) / 2.0, kw["d"], kw["D"], kw["r1"])
            return fat.shigley_bending_fatigue_safety(sa, sm, kw["Rm"], False, kw["criterion"])
        ta = he.hook_torsion_stress(np.abs(F2 - F1) / 2.0, kw["d"], kw["D"], kw["r2"])
        tm = he.hook_torsion_stress((F2 + F1) / 2.0, kw["d"], kw["D"], kw["r2"])
        return fat.shigley_fatigue_safety(ta, tm, kw["Rm"], False, kw["criterion"])

    def source(kw):
        how = ("bending: S_e = S_se/0.577 (Shigley Example 10-7)" if point == "A"
               else "torsion with (K)_B")
        return (f"hook point {point}, {how}; {fat.ZIMMERLI_SOURCE} (hooks taken unpeened); "
                f"{kw['criterion'].capitalize()} line" + _life_note(kw, DATA_CYCLES))
    return value, source


def _over(a, b):
    """``a / b``, infinite where ``b`` is zero (a buckling deflection lost to rounding on a
    spring far longer than it is wide: it buckles at once)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.asarray(a, dtype=float) / b


def _surge_source(kw):
    return ("EN 13906-1 surge frequency (both ends fixed) kept at least the required relative "
            f"distance from each excitation harmonic present ({len(kw['harmonics_hz'])} given)")


#: the largest free pitch: the simple rate and stress formulas assume a small helix angle
PITCH_MAX = "free pitch <= 0.7 inside diameter (helix angle)"

_static_c, _static_s, _static_e = _static("compression"), _static("solid"), _static("extension")
_hook_A, _hook_B = _hook_fatigue("A"), _hook_fatigue("B")

COMMON = (
    Row("spring index >= min", ">=", "", lambda kw: kw["C"], lambda kw: kw["index_min"],
        "EN 13906-1 scope, cold coiled: 4 <= w <= 20 (Shigley prefers 4 <= C <= 12)"),
    Row("spring index <= max", "<=", "", lambda kw: kw["C"], lambda kw: kw["index_max"],
        "EN 13906-1 scope, cold coiled: 4 <= w <= 20 (Shigley prefers 4 <= C <= 12)"),
    Row("body fatigue safety factor", ">=", "", _body_fatigue, lambda kw: kw["fatigue_safety"],
        _body_fatigue_source),
    Row("surge frequency detuning from harmonics", ">=", "",
        lambda kw: hx.surge_detuning(kw["f_e"], kw["harmonics_hz"]), lambda kw: kw["detuning"],
        _surge_source),
)

#: the row that says where a compression spring goes solid (its force there)
SOLID = "largest force <= force at solid length"

COMPRESSION = (
    Row(SOLID, "<=", "N", lambda kw: kw["F_max"], lambda kw: kw["F_c"],
        "EN 13906-1: the spring is solid at L_c (with d_max), at the force R (L0 - L_c); a "
        "larger force does not compress it further, and the static stress is taken at the "
        "smaller of the two"),
    Row("static shear stress", "<=", "Pa", _static_c[0], _static_c[1], _static_c[2]),
    Row("shear stress at solid length", "<=", "Pa", _static_s[0], _static_s[1], _static_s[2]),
    Row("working length >= least length (coil clash)", ">=", "m",
        lambda kw: kw["L0"] - kw["s_max"],
        lambda kw: hc.min_working_length(kw["d"], kw["D"], kw["n"], kw["n_t"], kw["ends"],
                                         kw["dynamic"], kw["ends"].startswith("hot"),
                                         kw["d_max"]),
        lambda kw: "EN 13906-1: L_n = L_c + S_a, L_c with the largest wire diameter d_max, "
                   "S_a = n (0.0015 D^2/d + 0.1 d) "
                   + ("x1.5 (dynamic load)" if kw["dynamic"] else "(static load; x1.5 dynamic)")
                   + ", at the largest deflection including the overspeed margin"),
    Row("deflection / buckling deflection", "<=", "",
        lambda kw: _over(kw["s_max"], hc.buckling_deflection(kw["L0"], kw["D"], kw["G"], kw["E"],
                                                             hc.SEATING[kw["seating"]])),
        lambda kw: 1.0,
        lambda kw: f"EN 13906-1, 9.14: buckling deflection s_K, seating {kw['seating']} "
                   f"(nu = {hc.SEATING[kw['seating']]})"),
    Row("free pitch > wire diameter", ">=", "m",
        lambda kw: hc.pitch(kw["L0"], kw["d"], kw["n"], kw["n_t"], kw["ends"], kw["d_max"]),
        lambda kw: kw["d"], "geometry: the free spring must have gaps between active coils"),
    Row(PITCH_MAX, "<=", "m",
        lambda kw: hc.pitch(kw["L0"], kw["d"], kw["n"], kw["n_t"], kw["ends"], kw["d_max"]),
        lambda kw: hc.max_pitch(kw["d"], kw["D"]),
        "Gutekunst Federn ('Spring pitch'): m <= 0.7 D_i, a helix angle atan(m / (pi D)) of at "
        "most 9.5-12.6 deg, where the rate G d^4 / (8 D^3 n) is within 1.5 % of the "
        "open-coiled spring's (6 % at 25 deg)"),
    Row("active coils >= 2", ">=", "", lambda kw: kw["n_active"], lambda kw: 2.0,
        "EN 13906-1 scope: n >= 2"),
) + COMMON

EXTENSION = (
    Row("body static shear stress", "<=", "Pa", _static_e[0], _static_e[1], _static_e[2]),
    Row("hook bending stress (point A)", "<=", "Pa",
        lambda kw: he.hook_bending_stress(kw["F2"], kw["d"], kw["D"], kw["r1"]),
        lambda kw: allowable_static_stress(kw["mat"], kw["d"], "hook_bending", "Shigley"),
        lambda kw: "Shigley §10-11 hook point A; " + static_rule(kw["mat"], "hook_bending",
                                                                 "Shigley").source),
    Row("hook torsion stress (point B)", "<=", "Pa",
        lambda kw: he.hook_torsion_stress(kw["F2"], kw["d"], kw["D"], kw["r2"]),
        lambda kw: allowable_static_stress(kw["mat"], kw["d"], "hook_torsion", "Shigley"),
        lambda kw: "Shigley §10-11 hook point B; " + static_rule(kw["mat"], "hook_torsion",
                                                                 "Shigley").source),
    Row("initial tension stress >= preferred min", ">=", "Pa",
        lambda kw: hx.shear_stress(kw["F0"], kw["d"], kw["D"]),
        lambda kw: he.initial_tension_range(kw["C"])[0],
        "Shigley eq. (10-40): preferred uncorrected initial-tension stress"),
    Row("initial tension stress <= preferred max", "<=", "Pa",
        lambda kw: hx.shear_stress(kw["F0"], kw["d"], kw["D"]),
        lambda kw: he.initial_tension_range(kw["C"])[1],
        "Shigley eq. (10-40): preferred uncorrected initial-tension stress"),
    Row("least force >= initial tension", ">=", "N", lambda kw: kw["F1"], lambda kw: kw["F0"],
        "an extension spring below its initial tension is closed: the force no longer follows "
        "the rate"),
    Row("hook A fatigue safety factor", ">=", "", _hook_A[0], lambda kw: kw["fatigue_safety"],
        _hook_A[1]),
    Row("hook B fatigue safety factor", ">=", "", _hook_B[0], lambda kw: kw["fatigue_safety"],
        _hook_B[1]),
) + COMMON

#: the compression rows that need the spring's geometry and moduli only, not the wire's strength:
#: they hold for a spring whose ``[material]`` gives an allowable stress and no wire grade too
#: (``only=GEOMETRY``). A free length far beyond the installed length (the article's "longer
#: spring" for a narrow speed range, 003) buckles long before it is compressed into place.
GEOMETRY = (SOLID, "working length >= least length (coil clash)",
            "deflection / buckling deflection", "free pitch > wire diameter", PITCH_MAX)

_SPACE = Row("free length <= space", "<=", "m", lambda kw: kw["L0"], lambda kw: kw["L0_max"],
             "installation space given in the spec")

TABLES = {"compression": COMPRESSION, "extension": EXTENSION}


def _rows(kind, kw, only=None):
    rows = TABLES[kind] + ((_SPACE,) if kw.get("L0_max") is not None else ())
    if only is not None:  # a subset by name (e.g. GEOMETRY; an extension spring has none of it)
        rows = tuple(r for r in rows if r.name in only)
    if len(kw.get("harmonics_hz", ())) == 0:  # nothing to resonate with: no surge row
        rows = tuple(r for r in rows if not r.name.startswith("surge"))
    return rows


def rows_over(kind: str, only=None, **kw) -> list[tuple[Row, np.ndarray, np.ndarray, str]]:
    """Every row of the ``kind`` table (or the rows named in ``only``) over arrays, in order:
    ``(row, value, limit, source)`` (value and limit broadcast; the source's text).

    Parameters
    ----------
    kind : str [-]
        ``"compression"`` or ``"extension"`` (:data:`TABLES`).
    only : tuple of str or None [-]
        Names of the rows to take (e.g. :data:`GEOMETRY`); None for all.
    **kw : dict [SI: m, N, Pa]
        The design's keywords, SI (see the module): ``mat``, ``d``, ``D`` [m], ``n`` or
        ``n_body`` [-], ``F1``, ``F2`` [N], ... and the options.

    Returns
    -------
    list of tuple [-]
        ``(Row, value, limit, source)``, value and limit in the row's ``unit``.

    References
    ----------
    [shigley] 9th ed. ch. 10; [en13906-1] (each row names its own clause as its source).

    Examples
    --------
    The spring of Shigley's Example 10-4 (its data and what the book prints: :func:`checks`):

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> kw = dict(mat=material("Shigley A228"), d=0.092 * inch, D=(9 / 16 - 0.092) * inch, n=21,
    ...           n_t=23, L0=4.375 * inch, F1=5 * lbf, F2=35 * lbf, method="Shigley",
    ...           criterion="gerber")
    >>> row, value, limit, source = rows_over("compression", **kw)[-1]
    >>> row.name, round(float(value), 2), source[:20]
    ('body fatigue safety factor', 1.2, "Zimmerli's endurance")
    """
    kw = prepare(kind, **kw)
    return [(r, *np.broadcast_arrays(np.asarray(r.value(kw), dtype=float),
                                     np.asarray(r.limit(kw), dtype=float)),
             r.source(kw) if callable(r.source) else r.source) for r in _rows(kind, kw, only)]


def evaluate(kind: str, only=None, **kw) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Every row of the ``kind`` table (or the rows named in ``only``) over arrays:
    ``{name: (value, limit)}`` (broadcast).

    Parameters
    ----------
    kind : str [-]
        ``"compression"`` or ``"extension"`` (:data:`TABLES`).
    only : tuple of str or None [-]
        Names of the rows to take (e.g. :data:`GEOMETRY`); None for all.
    **kw : dict [SI: m, N, Pa]
        The design's keywords, SI (see the module): ``mat``, ``d``, ``D`` [m], ``n`` or
        ``n_body`` [-], ``F1``, ``F2`` [N], ... and the options.

    Returns
    -------
    dict of str to tuple of array [-]
        ``(value, limit)`` per row name, in the row's ``unit``.

    References
    ----------
    [shigley] 9th ed. ch. 10; [en13906-1] (each row names its own clause as its source).

    Examples
    --------
    The spring of Shigley's Example 10-4 (its data and what the book prints: :func:`checks`):

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> kw = dict(mat=material("Shigley A228"), d=0.092 * inch, D=(9 / 16 - 0.092) * inch, n=21,
    ...           n_t=23, L0=4.375 * inch, F1=5 * lbf, F2=35 * lbf, method="Shigley",
    ...           criterion="gerber")
    >>> value, limit = evaluate("compression", **kw)["body fatigue safety factor"]
    >>> round(float(value), 2), float(limit)
    (1.2, 1.0)
    """
    return {r.name: (value, limit) for r, value, limit, _ in rows_over(kind, only, **kw)}


def feasible(kind: str, only=None, **kw) -> np.ndarray:
    """True where every row (of ``only``, if given) holds (NaN, e.g. a wire outside its grade's
    range, fails).

    Parameters
    ----------
    kind : str [-]
        ``"compression"`` or ``"extension"`` (:data:`TABLES`).
    only : tuple of str or None [-]
        Names of the rows to take (e.g. :data:`GEOMETRY`); None for all.
    **kw : dict [SI: m, N, Pa]
        The design's keywords, SI (see the module): ``mat``, ``d``, ``D`` [m], ``n`` or
        ``n_body`` [-], ``F1``, ``F2`` [N], ... and the options.

    Returns
    -------
    array of bool [-]
        Feasible designs (broadcast over the keywords' arrays).

    References
    ----------
    [shigley] 9th ed. ch. 10; [en13906-1] (each row names its own clause as its source).

    Examples
    --------
    The spring of Shigley's Example 10-4 (its data and what the book prints: :func:`checks`):

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> kw = dict(mat=material("Shigley A228"), d=0.092 * inch, D=(9 / 16 - 0.092) * inch, n=21,
    ...           n_t=23, L0=4.375 * inch, F1=5 * lbf, F2=35 * lbf, method="Shigley",
    ...           criterion="gerber")

    The book checks no buckling: under EN 13906-1 with hinged ends the unguided spring
    (free length 9.3 coil diameters) would buckle, so it is infeasible whatever its wire.

    >>> bool(feasible("compression", **kw))
    False
    >>> round(float(evaluate("compression", **kw)["deflection / buckling deflection"][0]), 2)
    5.22
    """
    kw = prepare(kind, **kw)
    ok = True
    for r in _rows(kind, kw, only):
        value, limit = r.value(kw), r.limit(kw)
        ok = ok & holds(value, limit, r.sense)  # as each Check passes
    return np.asarray(ok)


def checks(kind: str, only=None, **kw):
    """The ``kind`` table (or the rows named in ``only``) for one design as
    :class:`govopt.verdict.Check` objects.

    Arrays (e.g. forces over the governor's range) are reduced to the worst case: the largest
    value of a ``<=`` row, the smallest of a ``>=`` row (with its own limit).

    Parameters
    ----------
    kind : str [-]
        ``"compression"`` or ``"extension"`` (:data:`TABLES`).
    only : tuple of str or None [-]
        Names of the rows to take (e.g. :data:`GEOMETRY`); None for all.
    **kw : dict [SI: m, N, Pa]
        The design's keywords, SI (see the module): ``mat``, ``d``, ``D`` [m], ``n`` or
        ``n_body`` [-], ``F1``, ``F2`` [N], ... and the options.

    Returns
    -------
    list of Check [-]
        One per row: value and limit in the row's ``unit``, margin and source.

    References
    ----------
    [shigley] 9th ed. ch. 10; [en13906-1] (each row names its own clause as its source).

    Examples
    --------
    Shigley (9th ed.) Example 10-4: music wire d = 0.092 in, OD = 9/16 in, free length 4 3/8 in,
    21 active coils, squared and ground, cycled between 5 and 35 lbf. The book prints
    C = 5.11, k = 48.1 lbf/in and (Gerber) n_f = 1.21; the wire's Zimmerli data are held in SI
    (241 / 379 MPa, 0.13 % / 0.06 % below 35 / 55 kpsi) and its tensile strength from the SI
    constant of Table 10-4 (0.19 % below the US one), which gives 1.20.

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> kw = dict(mat=material("Shigley A228"), d=0.092 * inch, D=(9 / 16 - 0.092) * inch, n=21,
    ...           n_t=23, L0=4.375 * inch, F1=5 * lbf, F2=35 * lbf, method="Shigley",
    ...           criterion="gerber")
    >>> got = {c.name: c for c in checks("compression", **kw)}
    >>> c = got["body fatigue safety factor"]
    >>> round(c.value, 2), c.sense, c.limit
    (1.2, '>=', 1.0)
    """
    kw = prepare(kind, **kw)
    out = []
    for r in _rows(kind, kw, only):
        value, limit = np.broadcast_arrays(np.asarray(r.value(kw), dtype=float),
                                           np.asarray(r.limit(kw), dtype=float))
        slack = limit - value if r.sense == "<=" else value - limit
        i = int(np.argmin(np.where(np.isnan(slack), -np.inf, slack))) if slack.size else 0
        source = r.source(kw) if callable(r.source) else r.source
        out.append(Check(r.name, float(value.flat[i]), float(limit.flat[i]), r.sense, r.unit,
                         source, group="spring"))
    return out
