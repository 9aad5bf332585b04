"""One helical spring assessed: every figure and check a spring maker signs off, from the
spring as drawn (``govopt spring`` reports a designed spring and ``govopt spring check`` a
given one through this one function, :func:`assess`).

The spring (:class:`Spring`, SI) is its wire ``d``, mean coil diameter ``D``, coils, end form
(a compression spring: :data:`~govopt.springs.compression.END_FORMS`) or loops (an extension
spring: :data:`~govopt.springs.extension.HOOKS`) and free length; the material a wire grade
(:mod:`govopt.springs.materials`) or a stand-in carrying the shear modulus and density only
(:func:`govopt.springs.materials.given`, then the static allowable is given); the loads its
two working forces and, for fatigue, a load cycle (:class:`Loads`); the rules the standard's
choices (:class:`Rules`). The checks are the spring kind's table
(:mod:`govopt.springs.checks`); the figures, EN 13906-1's (compression) and EN 13906-2's
(extension) with Shigley's where they say nothing:

- rate ``R = G d^4 / (8 D^3 n)``; the solid length ``L_c`` with the largest wire diameter
  ``d_max`` and the least working length ``L_n = L_c + S_a`` (EN 13906-1);
- the working points: free length, ``L1``/``F1``, ``L2``/``F2``, ``L_n`` and ``L_c`` with the
  deflection, force, shear stress ``tau = 8 F D / (pi d^3)`` and corrected stress ``tau_k = k
  tau`` (Bergstraesser's ``k``) at each;
- the deflection used, ``s2 / (L0 - L_c)`` (per cent of the deflection available to solid),
  the energy stored from free to ``L2`` and between the working points;
- the pitch, helix angle, wire length and mass with the helix rise
  (:func:`~govopt.springs.helical.helix_mass`), surge frequency, buckling deflection and the
  increase of the outside diameter at solid length;
- a load cycle's corrected stresses, fatigue safety and estimated life
  (:func:`govopt.springs.fatigue.finite_life`: infinite where the cycle passes at the data's
  life);
- EN 15800 grade tolerances (coil diameter, forces, free length; the wire's after EN 10270)
  and what they do: the rate's worst-case range (:func:`~govopt.springs.tolerances.rate_spread`)
  and the force at ``L2`` with its tolerance.

Every figure is a :class:`govopt.verdict.Figure` in SI with its unit as a field; sections
(:data:`SECTIONS`) hold the same keys whatever the spring (nan where a figure does not apply:
a compression spring's solid length for an extension spring, R_m without a grade).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from ..verdict import Check, Figure
from . import checks as ck
from . import compression as hc
from . import extension as he
from . import fatigue as ft
from . import helical as hx
from . import tolerances as tl
from .materials import Material

KINDS = ("compression", "extension")
#: the report's sections of figures, in order (each a dict of :class:`Figure` by name)
SECTIONS = ("spring", "material", "lengths and energy", "dynamics", "fatigue", "tolerances")
#: the working points' names, in order (compression; an extension spring has the first three)
POINTS = ("free", "1", "2", "n", "c")


@dataclass(frozen=True)
class Spring:
    """One helical spring as drawn (SI). ``coils``: a compression spring's active coils ``n``,
    an extension spring's body coils ``n_b`` (its active coils are ``n_b + G/E``, Shigley
    section 10-11); ``end_coils``: a compression spring's inactive coils ``n_t - n`` (closed
    ends: 2); ``form``: the end form or the loops; ``L0``: the free length (an extension
    spring's inside its loops); ``F0``: an extension spring's initial tension."""

    kind: str
    d: float
    D: float
    coils: float
    end_coils: float
    L0: float
    form: str
    F0: float = 0.0

    @property
    def total_coils(self) -> float:
        """``n_t = n + end_coils`` (compression); the body coils (extension)."""
        return self.coils + self.end_coils if self.kind == "compression" else self.coils


def extension_free_length(d, D, body_coils, loops: str):
    """Free length inside the loops ``L0 = L_K + 2 L_H`` (m), the body ``L_K = (n_b + 1) d``
    (EN 13906-2; Shigley section 10-11) and each loop ``L_H`` the multiple of the inside
    diameter ``D - d`` that :data:`~govopt.springs.extension.HOOKS` gives.

    Parameters
    ----------
    d : float [m]
        Wire diameter.
    D : float [m]
        Mean coil diameter.
    body_coils : float [-]
        Body coils ``n_b``.
    loops : str [-]
        A key of :data:`~govopt.springs.extension.HOOKS` (e.g. ``"full_loop"``).

    Returns
    -------
    float [m]
        Free length inside the loops.

    References
    ----------
    [en13906-2] body length and loop lengths; [shigley] 9th ed. §10-11.

    Examples
    --------
    Checked by hand: d = 2 mm, D = 16 mm, 10 body coils, full loops (``L_H = D - d``): body
    ``11 * 2 = 22`` mm and two loops of 14 mm.

    >>> round(float(extension_free_length(2e-3, 16e-3, 10, "full_loop")) * 1e3, 6)  # 22 + 28
    50.0
    """
    return he.extension_body_length(d, body_coils) + 2.0 * he.HOOKS[loops].length * (D - d)


@dataclass(frozen=True)
class Loads:
    """The working forces ``F1 <= F2`` (N; ``F1`` 0 when only the largest is given) and a
    fatigue load cycle ``(least, largest)`` (N) or None."""

    F1: float
    F2: float
    cycle: tuple[float, float] | None = None


@dataclass(frozen=True)
class Rules:
    """The standard's choices (:mod:`govopt.springs.checks`' keywords): the allowable rule
    ``method``, an explicit static ``allowable`` (Pa) and ``correction``, shot peening, the
    seating for buckling, the index range, the required fatigue safety and life, dynamic
    loading (``S_a`` x1.5) and the EN 15800 tolerance grade."""

    method: str = "EN13906"
    allowable: float | None = None
    correction: str | None = None
    peened: bool = False
    seating: str = "fixed-fixed"
    index: tuple[float, float] = (4.0, 20.0)
    fatigue_safety: float = 1.0
    cycles: float = 1e7
    dynamic: bool = True
    tolerance_grade: int = 2


@dataclass
class Assessment:
    """:func:`assess`'s answer: the sections of figures (:data:`SECTIONS`), the working
    points (each a dict of figures), the checks, the load cycle's life (cycles; inf: it passes
    at the data's life; nan: below 1e3; None: no cycle) and notes."""

    spring: Spring
    mat: Material
    loads: Loads
    rules: Rules
    sections: dict[str, dict[str, Figure]]
    points: list[dict[str, Figure]]
    checks: list[Check]
    life: float | None = None
    notes: list[str] = field(default_factory=list)

    @property
    def failed(self) -> list[str]:
        return [c.name for c in self.checks if not c.passed]

    def figure(self, name: str) -> Figure:
        """The figure ``name`` of any section."""
        for section in self.sections.values():
            if name in section:
                return section[name]
        raise KeyError(name)

    def value(self, name: str) -> float:
        return self.figure(name).value


def _f(x) -> float:
    return float(np.asarray(x, dtype=float))


def _point(name: str, length: float, force: float, deflection: float, d: float, D: float,
           correction: str = "bergstrasser", wire_force: float | None = None
           ) -> dict[str, Figure]:
    """One working point: its length, deflection, force and stresses (uncorrected and with
    the chosen correction factor, Bergstraesser's by default, EN 13906-1); ``wire_force`` the
    force the wire carries where it differs from the force applied (an extension spring held
    closed by its initial tension). A point the spring never reaches (beyond solid) has its
    force only: its length, deflection and stresses are nan."""
    wire = force if wire_force is None else wire_force
    factor = hx.CORRECTION_TEXT[correction]
    return {"point": Figure("point", name), "length": Figure("length", length, "m"),
            "deflection": Figure("deflection", deflection, "m"),
            "force": Figure("force", force, "N"),
            "stress": Figure("stress", math.nan if math.isnan(length) else
                             _f(hx.shear_stress(wire, d, D)), "Pa",
                             source="EN 13906-1: tau = 8 F D / (pi d^3)"),
            "corrected stress": Figure("corrected stress", math.nan if math.isnan(length) else
                                       _f(hx.shear_stress(wire, d, D, correction)), "Pa",
                                       source=f"tau_k = k tau, k {factor}")}


def corrected(rules: Rules) -> str:
    """The correction factor of the report's corrected stresses: the one chosen
    (``rules.correction``, Wahl's or Bergstraesser's), else EN 13906-1's k (Bergstraesser's).

    Parameters
    ----------
    rules : Rules [-]
        The standard's choices.

    Returns
    -------
    str [-]
        ``"wahl"`` or ``"bergstrasser"`` (:data:`govopt.springs.helical.CORRECTION_TEXT`).

    References
    ----------
    [en13906-1] factor k; [wahl] eq. (2-12).

    Examples
    --------
    >>> corrected(Rules(correction="wahl")), corrected(Rules(correction="none"))
    ('wahl', 'bergstrasser')
    """
    return rules.correction if rules.correction in ("wahl", "bergstrasser") else "bergstrasser"


def table_keywords(spring: Spring, mat: Material, loads: Loads, rules: Rules) -> dict:
    """The table's keywords (:mod:`govopt.springs.checks`) for the spring and its working
    forces.

    Parameters
    ----------
    spring : Spring [m, N]
        The spring as drawn, SI (lengths in m, initial tension in N).
    mat : Material [-]
        The wire grade (:func:`govopt.springs.materials.material`) or a stand-in.
    loads : Loads [N]
        The working forces and the load cycle.
    rules : Rules [-]
        The standard's choices.

    Returns
    -------
    dict [SI: m, N, Pa]
        The keywords of :func:`govopt.springs.checks.checks`.

    References
    ----------
    [en13906-1], [en13906-2] (the figures and checks, each with its own clause as its source);
    [shigley] 9th ed. ch. 10 where the standards say nothing; [en15800] the tolerances.

    Examples
    --------
    Shigley (9th ed.) Example 10-4: music wire d = 0.092 in, OD = 9/16 in, free length 4 3/8 in,
    21 active coils, squared and ground (2 end coils), cycled between 5 and 35 lbf.

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> spring = Spring("compression", 0.092 * inch, (9 / 16 - 0.092) * inch, 21, 2,
    ...                 4.375 * inch, "closed_ground")
    >>> loads = Loads(5 * lbf, 35 * lbf, cycle=(5 * lbf, 35 * lbf))

    The total coils are the active ones and the end coils, 21 + 2:

    >>> kw = table_keywords(spring, material("Shigley A228"), loads, Rules(method="Shigley"))
    >>> kw["n_t"], round(kw["F2"] / lbf, 6), kw["ends"]
    (23, 35.0, 'closed_ground')
    """
    kw = dict(mat=mat, d=spring.d, D=spring.D, F1=loads.F1, F2=loads.F2, method=rules.method,
              allowable=rules.allowable, correction=rules.correction, peened=rules.peened,
              cycles=rules.cycles, index_min=rules.index[0], index_max=rules.index[1],
              fatigue_safety=rules.fatigue_safety)
    if spring.kind == "compression":
        kw.update(n=spring.coils, n_t=spring.total_coils, L0=spring.L0, ends=spring.form,
                  seating=rules.seating, dynamic=rules.dynamic)
    else:
        kw.update(n_body=spring.coils, F0=spring.F0)
    return kw


def table(spring: Spring, mat: Material, loads: Loads, rules: Rules
           ) -> tuple[list[Check], list[str]]:
    """The spring kind's checks at the working forces, the fatigue rows at the load cycle;
    rows whose value or limit the material cannot give (no R_m without a grade) left out and
    named.

    Parameters
    ----------
    spring : Spring [m, N]
        The spring as drawn, SI (lengths in m, initial tension in N).
    mat : Material [-]
        The wire grade (:func:`govopt.springs.materials.material`) or a stand-in.
    loads : Loads [N]
        The working forces and the load cycle.
    rules : Rules [-]
        The standard's choices.

    Returns
    -------
    tuple of (list of Check, list of str) [-]
        The checks (each in its row's unit) and the names of the rows left out.

    References
    ----------
    [en13906-1], [en13906-2] (the figures and checks, each with its own clause as its source);
    [shigley] 9th ed. ch. 10 where the standards say nothing; [en15800] the tolerances.

    Examples
    --------
    Shigley (9th ed.) Example 10-4: music wire d = 0.092 in, OD = 9/16 in, free length 4 3/8 in,
    21 active coils, squared and ground (2 end coils), cycled between 5 and 35 lbf.

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> spring = Spring("compression", 0.092 * inch, (9 / 16 - 0.092) * inch, 21, 2,
    ...                 4.375 * inch, "closed_ground")
    >>> loads = Loads(5 * lbf, 35 * lbf, cycle=(5 * lbf, 35 * lbf))

    The book checks neither the solid length nor buckling; EN 13906-1's rules find the spring
    overstressed when closed solid and, unguided with fixed ends, buckling before its
    working deflection:

    >>> rows, left_out = table(spring, material("Shigley A228"), loads, Rules(method="Shigley"))
    >>> [c.name for c in rows if not c.passed], left_out
    (['shear stress at solid length', 'deflection / buckling deflection'], [])
    """
    kw = table_keywords(spring, mat, loads, rules)
    if loads.cycle is not None:  # the static rows at every force the spring sees
        static = dict(kw, F1=min(loads.F1, *loads.cycle), F2=max(loads.F2, *loads.cycle))
    rows = [c for c in ck.checks(spring.kind, **(kw if loads.cycle is None else static))
            if "fatigue" not in c.name]
    if loads.cycle is not None:
        kw.update(F1=min(loads.cycle), F2=max(loads.cycle))
        rows += [c for c in ck.checks(spring.kind, **kw) if "fatigue" in c.name]
    kept = [c for c in rows if not (math.isnan(c.value) or math.isnan(c.limit))]
    return kept, [c.name for c in rows if c not in kept]


def assess(spring: Spring, mat: Material, loads: Loads, rules: Rules = Rules()) -> Assessment:
    """Every figure and check of ``spring`` (module docstring).

    Parameters
    ----------
    spring : Spring [m, N]
        The spring as drawn, SI (lengths in m, initial tension in N).
    mat : Material [-]
        The wire grade (:func:`govopt.springs.materials.material`) or a stand-in.
    loads : Loads [N]
        The working forces and the load cycle.
    rules : Rules [-]
        The standard's choices.

    Returns
    -------
    Assessment [SI]
        The sections of figures (each a :class:`~govopt.verdict.Figure` with its SI unit), the
        working points, the checks and the load cycle's life (cycles).

    References
    ----------
    [en13906-1], [en13906-2] (the figures and checks, each with its own clause as its source);
    [shigley] 9th ed. ch. 10 where the standards say nothing; [en15800] the tolerances.

    Examples
    --------
    Shigley (9th ed.) Example 10-4: music wire d = 0.092 in, OD = 9/16 in, free length 4 3/8 in,
    21 active coils, squared and ground (2 end coils), cycled between 5 and 35 lbf.

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> spring = Spring("compression", 0.092 * inch, (9 / 16 - 0.092) * inch, 21, 2,
    ...                 4.375 * inch, "closed_ground")
    >>> loads = Loads(5 * lbf, 35 * lbf, cycle=(5 * lbf, 35 * lbf))

    The book prints k = 48.1 lbf/in, f_n = 281 Hz (from k and W rounded; unrounded 281.5) and
    (Goodman, the default line here) n_f = 1.23:

    >>> a = assess(spring, material("Shigley A228"), loads, Rules(method="Shigley"))
    >>> round(a.value("rate") / (lbf / inch), 1), round(a.value("surge frequency"), 1)
    (48.1, 281.5)
    >>> round(a.sections["fatigue"]["safety factor"].value, 2), a.life
    (1.23, inf)
    """
    if spring.kind not in KINDS:
        raise ValueError(f"spring kind must be one of {KINDS}, got {spring.kind!r}")
    d, D, rho = spring.d, spring.D, mat.density
    G, E = _f(mat.shear_modulus(d)), _f(mat.elastic_modulus(d))
    Rm = _f(mat.tensile_strength(d))
    grade_known = math.isfinite(Rm)
    d_max = _f(tl.max_wire_diameter(d, mat.grade)) if grade_known else d
    compression = spring.kind == "compression"
    n = spring.coils if compression else _f(he.extension_active_coils(spring.coils, G, E))
    R = _f(hx.stiffness(d, D, n, G))
    L0, F1, F2 = spring.L0, loads.F1, loads.F2
    nan = math.nan
    notes: list[str] = []
    k = corrected(rules)
    if compression:
        n_t, form = spring.total_coils, hc.END_FORMS[spring.form]
        hot = spring.form.startswith("hot")
        Lc = _f(hc.solid_length(d_max, n_t, spring.form))
        Sa = _f(hc.sum_of_min_gaps(d, D, n, rules.dynamic, hot))
        Ln = Lc + Sa
        m = _f(hc.pitch(L0, d, n, n_t, spring.form, d_max))
        Fc = R * max(L0 - Lc, 0.0)  # the force that closes it solid
        s1, s2 = F1 / R, F2 / R

        def point(name, F):  # a force beyond solid: no length (nor stress) it never reaches
            s = F / R if F <= Fc else nan
            return _point(name, L0 - s, F, s, d, D, k)

        points = [_point("free length L0", L0, 0.0, 0.0, d, D, k)]
        if F1 > 0.0:  # a least force given: the spring works there
            points.append(point("L1", F1))
        points.append(point("L2", F2))
        if Ln < L0:  # (a free length at or below L_n: the spring never works there)
            points.append(_point("least working length L_n", Ln, R * (L0 - Ln), L0 - Ln, d, D,
                                 k))
        points.append(_point("solid length L_c", Lc, Fc, L0 - Lc, d, D, k))
        beyond = [name for name, F in (("L1", F1), ("L2", F2)) if F > Fc]
        if beyond:
            notes.append(f"{' and '.join(beyond)} beyond the solid length: the spring is solid "
                         f"at {Fc:.5g} N, below the force there (no length, stress or energy "
                         "reported where it never gets)")
        wire = _f(hx.helix_wire_length(D, n, m, spring.end_coils, d))
        nu = hc.SEATING[rules.seating]
        sK = _f(hc.buckling_deflection(L0, D, G, E, nu))
        energy_2 = 0.5 * F2 * s2 if F2 <= Fc else nan
        energy_12 = (F1 + F2) / 2.0 * (s2 - s1) if F2 <= Fc else nan
        used = s2 / (L0 - Lc)
        end_source = form.source
    else:
        Lc = Sa = Ln = nan
        hook = he.HOOKS[spring.form]
        m = d
        F0 = spring.F0
        # below its initial tension the spring stays closed: no deflection, the wire holding F0
        s1, s2 = (max(F - F0, 0.0) / R for F in (F1, F2))
        points = [_point("free length L0", L0, 0.0, 0.0, d, D, k, wire_force=F0)]
        if F1 > 0.0:
            points.append(_point("L1", L0 + s1, F1, s1, d, D, k, wire_force=max(F1, F0)))
        points.append(_point("L2", L0 + s2, F2, s2, d, D, k, wire_force=max(F2, F0)))
        wire = _f(hx.helix_wire_length(D, 0.0, 0.0, spring.coils + 2.0 * hook.coils, d))
        sK = nan

        def work(s):  # from the free length: F0 s + R s^2 / 2
            return F0 * s + 0.5 * R * s**2

        energy_2, energy_12 = work(s2), work(s2) - work(s1)
        used = nan
        end_source = hook.source
    index = D / d
    spring_fig = {
        "kind": Figure("kind", spring.kind),
        "ends": Figure("ends" if compression else "loops", spring.form, source=end_source,
                       json="ends"),
        "wire diameter": Figure("wire diameter", d, "m", symbol="d"),
        "largest wire diameter": Figure(
            "largest wire diameter", d_max, "m", symbol="d_max",
            source="d + its tolerance after " + (tl.wire_standard(mat.grade) or ""),
            json="largest_wire_diameter_m") if d_max > d else Figure(
            "solid length's wire diameter", d, "m", symbol="d",
            source="the nominal d", json="largest_wire_diameter_m",
            note="no diameter tolerance of " + (mat.standard or "the wire") + " in govopt's "
                 "data: the nominal d, not d_max"),
        "mean coil diameter": Figure("mean coil diameter", D, "m", symbol="D"),
        "outside diameter": Figure("outside diameter", D + d, "m", symbol="D_e"),
        "inside diameter": Figure("inside diameter", D - d, "m", symbol="D_i"),
        "spring index": Figure("spring index", index, symbol="w"),
        "active coils": Figure("active coils", n, symbol="n"),
        "total coils": Figure("total coils" if compression else "body coils",
                              spring.total_coils, symbol="n_t" if compression else "n_b",
                              json="total_coils"),
        "free length": Figure("free length", L0, "m", symbol="L0"),
        "initial tension": Figure("initial tension", spring.F0 if not compression else nan,
                                  "N", symbol="F0"),
        "pitch": Figure("pitch", m, "m", symbol="m",
                        source="EN 13906-1: m = s_c / n + d" if compression
                        else "coils touching: m = d"),
        "helix angle": Figure("helix angle", _f(hc.helix_angle(m, D)), "rad"),
        "wire length": Figure("wire length", wire, "m", source="Developed wire length of a "
                              "helical spring including the helix rise (m)"),
        "mass": Figure("mass", rho * math.pi * d**2 / 4.0 * wire, "kg"),
    }
    material_fig = {
        "grade": Figure("grade", mat.grade), "standard": Figure("standard", mat.standard),
        "shear modulus": Figure("shear modulus", G, "Pa", symbol="G"),
        "elastic modulus": Figure("elastic modulus", E, "Pa", symbol="E"),
        "density": Figure("density", rho, "kg/m^3", json="density_kg_per_m3"),
        "tensile strength": Figure("tensile strength", Rm, "Pa", symbol="R_m"),
    }
    lengths = {
        "rate": Figure("rate", R, "N/m", symbol="R", source="EN 13906-1: R = G d^4 / (8 D^3 n)"),
        "solid length": Figure("solid length", Lc, "m", symbol="L_c",
                               source=end_source if compression else ""),
        "sum of least gaps": Figure("sum of least gaps", Sa, "m", symbol="S_a",
                                    source="EN 13906-1: S_a = n (0.0015 D^2/d + 0.1 d), "
                                           + ("x1.5 dynamic load" if rules.dynamic else
                                              "static load (x1.5 under dynamic load)")
                                           if compression else ""),
        "least working length": Figure("least working length", Ln, "m", symbol="L_n"),
        "deflection used": Figure("deflection used", 100.0 * used, "%",
                                  symbol="s2 / (L0 - L_c)",
                                  source="the deflection at L2 over the deflection to solid"),
        "energy to L2": Figure("energy to L2", energy_2, "J", symbol="W2",
                               source="the work from the free length to L2"),
        "energy between the working points": Figure(
            "energy between the working points", energy_12, "J", symbol="W12",
            source="EN 13906-1: W = (F1 + F2)/2 (s2 - s1)" if compression else
            "W = F0 (s2 - s1) + R (s2^2 - s1^2) / 2, s from the initial tension"),
    }
    dynamics = {
        "surge frequency": Figure("surge frequency", _f(hx.surge_frequency(d, D, n, G, rho)),
                                  "Hz", symbol="f_e",
                                  source="``f_e = d / (2 pi n D^2) sqrt(G / (2 rho))`` - "
                                         "EN 13906-1:2013 (natural frequency)"),
        "buckling deflection": Figure("buckling deflection", sK, "m", symbol="s_K",
                                      source=f"EN 13906-1, 9.14, seating {rules.seating}"
                                      if compression else "",
                                      note="cannot buckle at any deflection" if math.isinf(sK)
                                      else ""),
        "diameter increase at solid": Figure(
            "diameter increase at solid",
            _f(hc.diameter_increase(d, D, n, L0, spring.total_coils, spring.form, d_max))
            if compression else nan, "m", symbol="Delta D_e", source="EN 13906-1"),
    }
    table_rows, dropped = table(spring, mat, loads, rules)
    if dropped:
        notes.append("not checked without a wire grade (they need its tensile strength): "
                     + ", ".join(dropped))
    fatigue, life = _fatigue(spring, mat, loads, rules, table_rows)
    sections = {"spring": spring_fig, "material": material_fig, "lengths and energy": lengths,
                "dynamics": dynamics, "fatigue": fatigue,
                "tolerances": _tolerances(spring, mat, loads, rules, n, R, G, s2)}
    return Assessment(spring, mat, loads, rules, sections, points, table_rows, life, notes)


def _fatigue(spring, mat, loads, rules, rows) -> tuple[dict[str, Figure], float | None]:
    """The load cycle's figures (:func:`govopt.springs.fatigue.cycle_figures`), the body's
    safety and its estimated life; nan without a cycle."""
    nan = math.nan
    if loads.cycle is None:
        out = ft.cycle_figures(nan, nan, nan, nan)
        out["safety factor"] = Figure("safety factor", nan)
        out["life"] = Figure("life", nan, "cycles", note="no load cycle given")
        return out, None
    lo, hi = min(loads.cycle), max(loads.cycle)
    d, D = spring.d, spring.D
    out = ft.cycle_figures(lo, hi, *(_f(hx.shear_stress(F, d, D, "bergstrasser"))
                                     for F in (lo, hi)))
    for key in ("corrected stress min", "corrected stress max"):  # the fatigue data's factor
        out[key] = replace(out[key], note="k " + hx.CORRECTION_TEXT["bergstrasser"]
                           + ", as the fatigue check")
    row = next((c for c in rows if c.name == "body fatigue safety factor"), None)
    safety = nan if row is None else row.value  # at the required life
    life = nan
    if row is not None:  # the row's safety at the required life, read back to the data's
        Sse, Ssu = ft.reversed_endurance(mat, d, rules.method, rules.peened)
        at_data = safety / _f(ft.life_factor(rules.cycles, Sse, Ssu, ck.DATA_CYCLES))
        life = _f(ft.finite_life(at_data, Sse, Ssu, ck.DATA_CYCLES))
    out["safety factor"] = Figure("safety factor", safety, source=row.source if row else "")
    out["life"] = Figure(
        "life", life, "cycles", source="Basquin's line from 0.9 S_su at 1e3 cycles to the "
                                       "endurance at the data's 1e7 (Shigley 9th ed. "
                                       "section 6-7)",
        note="the cycle passes at the data's 1e7 cycles" if math.isinf(life) else
        "below 1e3 cycles: quasi-static, no S-N estimate" if math.isnan(life) else "")
    return out, life


def _tolerances(spring, mat, loads, rules, n, R, G, s2) -> dict[str, Figure]:
    """EN 15800 (grade ``rules.tolerance_grade``) and the wire's tolerance after EN 10270, and
    what they do: the rate's worst-case range and the force at L2 with its tolerance."""
    d, D, grade = spring.d, spring.D, rules.tolerance_grade
    std = tl.wire_standard(mat.grade)
    A_d = _f(tl.wire_diameter_tolerance(d, std)) if std else math.nan
    A_D = _f(tl.coil_diameter_tolerance(D, D / d, grade))
    compression = spring.kind == "compression"
    A_F2 = _f(tl.force_tolerance(loads.F2, d, D, n, grade)) if compression else math.nan
    A_F1 = (_f(tl.force_tolerance(loads.F1, d, D, n, grade))
            if compression and loads.F1 > 0 else math.nan)
    lo, hi = tl.rate_spread(d, D, n, G, 0.0 if math.isnan(A_d) else A_d,
                            0.0 if math.isnan(A_D) else A_D)
    src = f"EN 15800 grade {grade}"
    return {
        "quality grade": Figure("quality grade", grade, source="EN 15800"),
        "wire diameter tolerance": Figure("wire diameter tolerance", A_d, "m", symbol="A_d",
                                          source=std or "no wire standard known"),
        "coil diameter tolerance": Figure("coil diameter tolerance", A_D, "m", symbol="A_D",
                                          source=src + " Table 1"),
        "free length tolerance": Figure(
            "free length tolerance",
            _f(tl.free_length_tolerance(d, D, n, R, grade)) if compression else math.nan, "m",
            symbol="A_L0", source=src + ", when no force is toleranced"),
        "force 1 tolerance": Figure("force 1 tolerance", A_F1, "N", symbol="A_F1", source=src),
        "force 2 tolerance": Figure("force 2 tolerance", A_F2, "N", symbol="A_F2", source=src),
        "rate least": Figure("rate least", _f(lo), "N/m",
                             source="R(d - A_d, D + A_D): the wire's and coil's tolerances"),
        "rate largest": Figure("rate largest", _f(hi), "N/m",
                               source="R(d + A_d, D - A_D)"),
        "force 2 least": Figure("force 2 least", max(loads.F2 - A_F2, 0.0), "N",
                                source="F2 - A_F2 at L2 (at least 0)"),
        "force 2 largest": Figure("force 2 largest", loads.F2 + A_F2, "N",
                                  source="F2 + A_F2 at L2"),
        "stress at force 2 largest": Figure(
            "stress at force 2 largest", _f(hx.shear_stress(loads.F2 + A_F2, d, D)), "Pa",
            source="tau at F2 + A_F2"),
        "perpendicularity": Figure("perpendicularity",
                                   _f(tl.perpendicularity(spring.L0, grade))
                                   if compression else math.nan, "m", symbol="e1", source=src),
        "parallelism": Figure("parallelism", _f(tl.parallelism(D + d, grade))
                              if compression else math.nan, "m", symbol="e2", source=src),
    }


__all__ = ["KINDS", "POINTS", "SECTIONS", "Assessment", "Loads", "Rules", "Spring", "assess",
           "corrected", "extension_free_length", "table", "table_keywords"]
