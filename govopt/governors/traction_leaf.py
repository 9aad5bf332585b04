"""The flat-spring (leaf-spring) traction-engine governor (the spring-balance governor article,
``/work/shared/seeds/003_*``, Fig. 2) on the seam.

Each fly weight is carried at the middle of its own flat spring of length ``L``, whose ends are
attached to two collars on the spindle at radius ``r_h`` from its centreline (one collar fixed,
the other moving the throttle-valve rod). The centrifugal force bows the spring: its middle stands
``x`` off the line of its ends (the article's ``x``; its deflection ``Delta`` when the spring has no
set), the distance between the end attachments shortens to the chord ``l``, and the rod travels
``s = l_1 - l`` from the throttle fully open (``l_1``). The weight's radius is ``r = r_h + x``
(article, design step 5).

The coordinate is the fly-weight radius ``r``, as for :mod:`.traction_coil` and the textbook
governors; the range is given by the valve's positions (``chord_open``/``chord_closed``, the
article's ``l_1``, ``l_2``, or ``travel_open``/``travel_closed``, the rod's travel from rest) or by
measured bows (``bow_open``/``bow_closed``) and converted with the governor's chord-bow relation,
so the throttle positions stay fixed whatever the fidelity.

Per fly weight, the spring's force at the middle balances the centrifugal force (virtual work:
the bow's rate in ``r`` is 1; the collars slide freely, the article's assumption)::

    omega^2 m r = F(x),   F = kappa (f(x) - l0)

with ``kappa = c E I / L^3`` (:func:`govopt.springs.leaf.stiffness`, ``c`` = 48 hinged or 192
clamped: eq. 5) and ``l0`` the spring's *set*: the bow of the unloaded leaf at its middle, from
the line of its end attachments, outward (away from the spindle) positive - the article's Fig. 2
"shows the spring with a set in it", its bow ``x`` = set + deflection ``Delta`` (note to eq. 8),
and its design takes no set (step 2). A negative ``l0`` is a leaf bent the other way, towards the
spindle: at rest the weights would swing in to ``r_h + l0`` (the old optimum of
``traction-leaf-design.toml``, ``l0 = -19.36 mm``: 12.4 mm from the axis, three 0.25 kg weights
on a 31.75 mm hinge radius meet each other and the rod), so it is buildable only pre-loaded
against a stop that neither the article's governor nor this model has. The set is therefore
kept within ``leaf_set_min`` .. ``leaf_set_max`` (default 0 .. ``L/5``, the article's range of
``x`` for eq. 8); a spec with such a stop states a negative ``leaf_set_min``. Fidelity
``leaf_model``
(:data:`govopt.springs.leaf.CHORD_MODELS`):

* ``"straight"``: the article's method: ``f = x`` (eq. 5, small deflection, span ``L``) and the
  straight-line chord of eq. 8;
* ``"arc"``: ``f = x`` with the circular-arc chord (the article's formula, corrected);
* ``"elastica"`` (default): the exact large-deflection force and chord for a spring without set
  (:func:`govopt.springs.leaf.force_per_stiffness`). A set ``l0`` enters as ``kappa (f(x) - l0)``:
  exact in the linear theory, a first-order approximation in the elastica.

The rod's travel per unit radius ``ds/dr = -dl/dx`` drives the throttle (the engine's torque) and
scales rod friction; the weight moves along the spindle by half of it.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..keys import Key
from ..springs import leaf
from ..verdict import Check
from .base import Equation, Setting, Terms
from .drawing import Drawing, Part, ball_radius, mirrored
from .traction_coil import HINGE_RADIUS, N_WEIGHTS, ROD_FRICTION, FlyWeights, centrifugal_force

#: the ways a spec gives the range: chords ``l`` (the valve's positions), bows ``x`` (measured
#: at the weights) or rod travels from rest (the article's design from the valve travel ``Z``:
#: ``travel_open = Z``, ``travel_closed = 2 Z``, eq. 9)
RANGE_KINDS = ("chord", "bow", "travel")
ENDS = ("open", "closed", "normal")

_RANGE_WORDS = {
    "chord": ("the leaf's chord (its end attachments' distance)", "(0, leaf_length)",
              "article 003, l_1 and l_2"),
    "bow": ("the leaf's bow at its middle from the line of its ends (measured)",
            "(0, leaf_length/2)", "article 003, x"),
    "travel": ("the throttle rod's travel from rest", "(0, leaf_length)",
               "article 003, Z and 2 Z (eq. 9)"),
}
_END_WORDS = {"open": "with the throttle just fully open (the lowest speed)",
              "closed": "with the throttle just closed (the highest speed)",
              "normal": "at the normal configuration"}


def _range_key(kind: str, end: str) -> Key:
    what, text, source = _RANGE_WORDS[kind]
    top = 0.5 if kind == "bow" else 1.0
    return Key(f"{kind}_{end}", "length", f"{what} {_END_WORDS[end]}", default=None,
               default_text="the fly weights at the mid radius" if end == "normal" else "",
               high=lambda v, top=top: top * v["leaf_length"], range_text=text, source=source,
               when="one way: chords, bows or travels; open and closed are required, normal "
                    "is optional")


def _set_key(end: str, meaning: str, default, default_text: str) -> Key:
    return Key(f"leaf_set_{end}", "length", meaning, default=default, default_text=default_text,
               positive=False, low=lambda v: -0.5 * v["leaf_length"],
               high=lambda v: 0.5 * v["leaf_length"],
               range_text="[-leaf_length/2, leaf_length/2]")


#: ``[governor]`` of the flat-spring traction governor (article 003, Fig. 2)
KEYS = (
    N_WEIGHTS,
    Key("leaf_length", "length", "each flat spring's length L (the fly weight at its middle)",
        source="article 003, eq. 5"),
    Key("leaf_ends", "choice", "how the leaf's ends are held: \"hinged\" or \"clamped\" "
                               "(48 or 192 E I / L^3)", default="hinged",
        choices=tuple(leaf.ENDS), source="article 003, eq. 5"),
    HINGE_RADIUS,
    Key("leaf_model", "choice", "the leaf's force and chord: \"straight\" (the article's eqs. "
                                "5 and 8), \"arc\" (circular-arc chord) or \"elastica\" (exact "
                                "large deflection)", default="elastica",
        choices=tuple(leaf.CHORD_MODELS), source="article 003, eqs. 5, 8"),
    *(_range_key(kind, end) for kind in RANGE_KINDS for end in ENDS),
    _set_key("min", "the least set of the leaf (its unloaded bow, outward +): below 0 only "
                    "against a stop", 0.0, "0"),
    _set_key("max", "the largest set of the leaf", lambda v: 0.2 * v["leaf_length"],
             "leaf_length / 5 (the article's range of the bow for eq. 8)"),
    ROD_FRICTION,
)


def fly_mass_from_deflection(delta, r, omega, w, t, L, E, ends="hinged"):
    """The fly weight's mass [kg] for a flat spring from its measured deflection (the article's
    first procedure, eqs. 5-7).

    The force of eq. 5 at the measured deflection ``delta`` (throttle just closed),
    ``F = c E I delta / L^3`` with ``I`` from eq. 7, then eq. 6 solved for the mass at radius ``r``
    and speed ``omega`` -- with ``F = m r omega^2``, not the article's ``W r N^2 / 2933`` (12 times
    too large with ``r`` in inches: :func:`govopt.governors.traction_coil.centrifugal_force`).

    Parameters
    ----------
    delta : float [m]
        The leaf's deflection at its middle, throttle just closed.
    r : float [m]
        The fly weight's radius there.
    omega : float [rad/s]
        The speed at which the throttle just closes.
    w : float [m]
        Leaf width.
    t : float [m]
        Leaf thickness.
    L : float [m]
        Leaf length.
    E : float [Pa]
        Young's modulus.
    ends : str [-]
        "hinged" (48 E I / L^3) or "clamped" (192 E I / L^3).

    Returns
    -------
    float [kg]
        Mass of one fly weight.

    References
    ----------
    [traction-article] eqs. 5-7 (the first flat-spring procedure).

    Examples
    --------
    The article gives no worked numbers; the bundled case ``traction-leaf-weights``: a 1 x 0.025
    x 8 in hinged leaf (E = 28.5e6 psi) deflected 1.2 in at 2.45 in and 250 rpm: ``F = 4.1748``
    lbf and a 0.95989 lbf weight (the article's constant 2933 would give 12 times less):

    >>> import math
    >>> LBF, IN, LB = 4.4482216152605, 0.0254, 0.45359237  # lbf [N], in [m], lb [kg]
    >>> RPM, PSI = 2 * math.pi / 60, 4.4482216152605 / 0.0254**2  # [rad/s], [Pa]
    >>> m = fly_mass_from_deflection(1.2 * IN, 2.45 * IN, 250 * RPM, 1.0 * IN, 0.025 * IN,
    ...                              8.0 * IN, 28.5e6 * PSI)
    >>> round(m / LB, 5)  # the weight in lbf
    0.95989
    """
    return leaf.stiffness(w, t, L, E, ends) * delta / centrifugal_force(1.0, r, omega)


def assembly_from_valve_travel(L, Z, hinge_radius, omega_idle, w, t, E, ends="hinged",
                               model="straight"):
    """The article's complete flat-spring assembly from the valve's travel ``Z`` (its second
    procedure, eqs. 5-9): a dict of SI quantities.

    No set; the rod travels ``Z`` from rest to fully open and ``Z`` more to closed, so
    ``l_1 = L - Z`` and ``l_2 = L - 2 Z`` (eq. 9); the bows from the chords (eq. 8 with
    ``model="straight"``, the article's), ``r = r_h + x``; the fly-weight mass that holds the
    throttle just closed at ``omega_idle`` on the leaf (eqs. 5-7), and the speed at which the
    throttle is just fully open, the lower end of the speed range.

    Parameters
    ----------
    L : float [m]
        Leaf length.
    Z : float [m]
        The valve's travel from rest to fully open.
    hinge_radius : float [m]
        The end attachments' radius from the spindle's centreline.
    omega_idle : float [rad/s]
        The speed at which the throttle just closes.
    w : float [m]
        Leaf width.
    t : float [m]
        Leaf thickness.
    E : float [Pa]
        Young's modulus.
    ends : str [-]
        "hinged" or "clamped".
    model : str [-]
        Chord-bow relation: "straight" (the article's eq. 8), "arc" or "elastica".

    Returns
    -------
    dict [-]
        ``chord_open``, ``chord_closed``, ``bow_open``, ``bow_closed``, ``radius_open``,
        ``radius_closed`` [m]; ``force_open``, ``force_closed`` [N]; ``fly_mass`` [kg];
        ``omega_open`` [rad/s].

    References
    ----------
    [traction-article] eqs. 5-9 (the second flat-spring procedure).

    Examples
    --------
    The article gives no worked numbers; the bundled case ``traction-leaf-assembly``: an 8 in
    hinged leaf 1 x 0.025 in (E = 28.5e6 psi), Z = 3/16 in, hinges at 1.25 in, closed at 250 rpm:
    bows 0.8609 and 1.2103 in, a 0.9641 lbf weight, throttle fully open at 227.63 rpm:

    >>> import math
    >>> LBF, IN, LB = 4.4482216152605, 0.0254, 0.45359237  # lbf [N], in [m], lb [kg]
    >>> RPM, PSI = 2 * math.pi / 60, 4.4482216152605 / 0.0254**2  # [rad/s], [Pa]
    >>> a = assembly_from_valve_travel(8 * IN, 0.1875 * IN, 1.25 * IN, 250 * RPM, 1.0 * IN,
    ...                                0.025 * IN, 28.5e6 * PSI)
    >>> round(float(a["bow_open"]) / IN, 4), round(float(a["bow_closed"]) / IN, 4)
    (0.8609, 1.2103)
    >>> round(float(a["fly_mass"]) / LB, 4), round(a["omega_open"] / RPM, 2)
    (0.9641, 227.63)
    """
    chords = np.array([L - Z, L - 2.0 * Z])
    bows = leaf.bow(chords, L, model)
    radii = hinge_radius + bows
    forces = leaf.stiffness(w, t, L, E, ends) * leaf.force_per_stiffness(bows, L, model)[0]
    m = forces[1] / centrifugal_force(1.0, radii[1], omega_idle)
    return dict(chord_open=chords[0], chord_closed=chords[1], bow_open=bows[0],
                bow_closed=bows[1], radius_open=radii[0], radius_closed=radii[1],
                force_open=forces[0], force_closed=forces[1], fly_mass=m,
                omega_open=float(np.sqrt(forces[0] / (m * radii[0]))))


@functools.lru_cache(maxsize=256)
def _bow(l: float, L: float, model: str) -> float:
    """:func:`govopt.springs.leaf.bow` of one chord, remembered: a nested bisection (~0.1 s),
    the same for every spec giving the same range (each study point, each variant)."""
    return float(leaf.bow(l, L, model))


@dataclass(frozen=True)
class TractionLeafGovernor(FlyWeights):
    """Flat-spring traction-engine governor (article 003, Fig. 2), SI; per fly weight."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("traction-leaf-weights", {}, "governor.leaf_model",
                               ("elastica", "arc", "straight"))

    type_name: ClassVar[str] = "traction_leaf"
    title: ClassVar[str] = "Flat-spring traction-engine governor (article 003, Fig. 2)"
    coordinate: ClassVar[str] = "length"
    coordinate_name: ClassVar[str] = "fly-weight radius"
    travel: ClassVar[str] = "length"
    spring: ClassVar[str | None] = "leaf"
    mass_key: ClassVar[str] = "fly"
    mass_name: ClassVar[str] = "fly weight"
    #: the valve's positions one way: chords, bows or travels (open and closed; normal optional)
    key_alternatives: ClassVar[tuple] = (tuple(
        (f"{way}_open", f"{way}_closed", f"{way}_normal?") for way in ("chord", "bow", "travel")),)
    free_length_key: ClassVar[str] = "leaf_set"
    free_length_positive: ClassVar[bool] = False  # the set may bow either way
    free_length_meaning: ClassVar[str] = ("the leaf's set l0: its unloaded bow at the middle, "
                                          "from the line of its ends, outward +")
    keys: ClassVar[tuple[Key, ...]] = KEYS
    example: ClassVar[str] = "traction-leaf-design"

    n_weights: int
    leaf_length: float
    leaf_ends: str
    hinge_radius: float
    leaf_model: str
    chord_open: float
    x_inner: float
    x_outer: float
    x_normal: float
    rod_friction: float = 0.0
    set_min: float = 0.0
    set_max: float = np.inf

    @classmethod
    def parse(cls, reader) -> TractionLeafGovernor:
        """Keys ``n_weights``, ``leaf_length``, ``leaf_ends`` ("hinged" or "clamped", default
        hinged), ``hinge_radius`` (of the spring's end attachments), ``leaf_model`` (default
        "elastica"), the range as ``chord_open``/``chord_closed`` (the article's ``l_1``,
        ``l_2``), ``bow_open``/``bow_closed`` (measured ``x``) or ``travel_open``/
        ``travel_closed`` (the rod's travel from rest, ``Z`` and ``2 Z`` in the article's design),
        an optional ``*_normal`` of the same kind (default: the mid radius), ``rod_friction``
        (default 0), ``leaf_set_min`` and ``leaf_set_max``: the bounds of the leaf's set ``l0``
        (default 0 and ``leaf_length / 5``; see the module's docstring).

        >>> from govopt.reader import Reader
        >>> gov = TractionLeafGovernor.parse(Reader("ex", {"n_weights": 3,
        ...     "leaf_length": "8 in", "hinge_radius": "1.25 in", "leaf_model": "straight",
        ...     "chord_open": "7.8125 in", "chord_closed": "7.625 in"}, "governor", []))
        >>> round((gov.x_outer - gov.hinge_radius) / 0.0254, 6)  # eq. 8: sqrt(8^2 - 7.625^2)/2
        1.210307
        """
        v = reader.read_all(KEYS[:5])
        n, L, ends, r_h, model = v.values()
        kinds = [k for k in RANGE_KINDS if any(reader.has(f"{k}_{e}") for e in ENDS)]
        if len(kinds) > 1:
            key = next(f"{kinds[1]}_{e}" for e in ENDS if reader.has(f"{kinds[1]}_{e}"))
            reader.fail(key, f"give the range one way, not as {kinds[0]}s and {kinds[1]}s")
        kind = kinds[0] if kinds else "chord"
        given = {e: reader.read(KEYS[5 + 3 * RANGE_KINDS.index(kind) + i], v,
                                required=e != "normal") for i, e in enumerate(ENDS)}
        chords = {}
        if kind == "bow":
            bows = given
        else:  # a travel from rest shortens the chord by as much
            chords = {e: None if v is None else (L - v if kind == "travel" else v)
                      for e, v in given.items()}
            bows = {e: None if v is None else _bow(v, L, model) for e, v in chords.items()}
        if not bows["open"] < bows["closed"]:
            reader.fail(f"{kind}_closed", f"expected the {kind} with the throttle closed "
                                          f"{'shorter' if kind == 'chord' else 'longer'} than open")
        chord_open = float(leaf.chord(bows["open"], L, model)[0])
        for end, b in bows.items():
            back = None if b is None else leaf.chord(b, L, model)[0]
            if back is not None and (not np.isfinite(back) or kind != "bow"
                                     and abs(back - chords[end]) > 1e-9 * L):
                reader.fail(f"{kind}_{end}", f"beyond the reach of the {model!r} chord model")
        normal = r_h + (bows["normal"] if bows["normal"] is not None
                        else 0.5 * (bows["open"] + bows["closed"]))
        set_min, set_max = reader.read_all(KEYS[-3:-1], v).values()
        if not set_min <= set_max:
            reader.fail("leaf_set_max", "expected at least leaf_set_min")
        gov = cls(n_weights=n, leaf_length=L, leaf_ends=ends, hinge_radius=r_h,
                  leaf_model=model, chord_open=chord_open, x_inner=r_h + bows["open"],
                  x_outer=r_h + bows["closed"], x_normal=float(normal),
                  rod_friction=reader.read(ROD_FRICTION), set_min=set_min, set_max=set_max)
        if not gov.x_inner <= gov.x_normal <= gov.x_outer:
            reader.fail(f"{kind}_normal", "expected between the open and closed positions")
        reader.finish()
        return gov

    # -- the leaf -------------------------------------------------------------------------------

    def spring_mass(self, sd, material):
        """The strip's mass ``density w t L`` (kg; :func:`govopt.springs.leaf.mass`, the
        article's Fig. 2 strip)."""
        return leaf.mass(sd.width, sd.thickness, self.leaf_length, material.density)

    def leaf_stiffness(self, w, t, E):
        """``kappa = c E I / L^3`` (N/m) of a leaf ``w x t`` (m) of this length and ends."""
        return leaf.stiffness(w, t, self.leaf_length, E, self.leaf_ends)

    # -- the spring plug: the leaf instead of a helical spring --------------------------------

    spring_loaded_check = "leaf loaded over the range"

    def spring_rate(self, design, material) -> float:
        """``kappa = c E w t^3 / (12 L^3)`` of the design's leaf (:mod:`govopt.springs.leaf`)."""
        return float(self.leaf_stiffness(design.leaf_width, design.leaf_thickness,
                                         material.elastic_modulus))

    def spring_stress(self, x, F, sd, material):
        """The leaf's bending stress ``6 M / (w t^2)`` at its largest moment (Roark Table 8.1)."""
        return leaf.bending_stress(F, sd.width, sd.thickness, self.span(x), self.leaf_ends)

    def spring_checks(self, spec, sd, char, vib=None) -> list:
        """The leaf's constraint table (:data:`govopt.springs.leaf.CONSTRAINTS`): bending stress
        against the material's allowable, bow/length within the chord models' stated range; and
        the set ``l0`` within ``leaf_set_min`` .. ``leaf_set_max`` (:meth:`set_ok`)."""
        mat, req = spec.material, spec.requirements
        allowable = mat.allowable_bending_stress if mat is not None else None
        rows = leaf.checks(F=np.max(np.abs(char.spring_force)),
                           x=self.x_outer - self.hinge_radius, w=sd.width, t=sd.thickness,
                           L=self.leaf_length, span=self.span(char.alpha), ends=self.leaf_ends,
                           allowable=allowable if allowable is not None else np.inf,
                           max_bow_ratio=getattr(req, "max_bow_ratio", 0.2) or 0.2)
        source = "a buildable leaf: its set (unloaded bow, outward +) within [governor] bounds"
        return [c for c in rows if np.isfinite(c.limit)] + [
            Check("leaf set >= min", sd.l0, self.set_min, ">=", "m", source,
                  scale=None if self.set_min else self.leaf_length, group="spring"),
            Check("leaf set <= max", sd.l0, self.set_max, "<=", "m", source, group="spring")]

    def spring_checks_over(self, spec, sd, F, x) -> list:
        """:meth:`spring_checks` of N designs at once (arrays of N: the leaf's rows are
        elementwise, each design's largest over its configurations)."""
        mat, req = spec.material, spec.requirements
        allowable = mat.allowable_bending_stress if mat is not None else None
        N = np.shape(F)[0]

        def col(v):
            return np.broadcast_to(np.asarray(v, dtype=float), (N, 1))

        kw = dict(F=np.max(np.abs(F), axis=1, keepdims=True), x=self.x_outer - self.hinge_radius,
                  w=col(sd.width), t=col(sd.thickness), L=self.leaf_length,
                  span=self.span(x), ends=self.leaf_ends,
                  allowable=allowable if allowable is not None else np.inf,
                  max_bow_ratio=getattr(req, "max_bow_ratio", 0.2) or 0.2)
        l0 = col(sd.l0)[:, 0]
        source = "a buildable leaf: its set (unloaded bow, outward +) within [governor] bounds"
        rows = [Check(c.name, np.broadcast_to(c.value(**kw), (N, np.size(kw["span"]))).max(axis=1),
                      np.full(N, float(c.limit(**kw))), c.sense, c.unit, c.source, group="spring")
                for c in leaf.CONSTRAINTS if np.isfinite(c.limit(**kw))]
        return rows + [
            Check("leaf set >= min", l0, np.full(N, self.set_min), ">=", "m", source,
                  scale=None if self.set_min else np.full(N, self.leaf_length), group="spring"),
            Check("leaf set <= max", l0, np.full(N, self.set_max), "<=", "m", source,
                  group="spring")]

    def free_length_limits(self) -> dict:
        """The set's bounds as the design search's statics rows (the names of the checks of
        :meth:`spring_checks`)."""
        return {name: (sense, limit) for name, sense, limit in (
            ("leaf set >= min", ">=", self.set_min), ("leaf set <= max", "<=", self.set_max))
            if np.isfinite(limit)}

    def set_ok(self, l0):
        """True where the leaf's set ``l0`` (m) lies within ``set_min`` .. ``set_max``."""
        return (l0 >= self.set_min) & (l0 <= self.set_max)

    def geometry(self, x) -> dict:
        """At fly-weight radii ``x`` (m): the bow, the chord ``l`` and the rod travel ``s`` from
        the throttle fully open (m), with ``s1 = ds/dr``."""
        b = np.asarray(x, dtype=float) - self.hinge_radius
        l, dl = leaf.chord(b, self.leaf_length, self.leaf_model)
        return dict(bow=b, l=l, s=self.chord_open - l, s1=-dl)

    def span(self, x):
        """The span of the leaf's largest moment (:func:`govopt.springs.leaf.moment_arm`): ``L``
        in the linear theory, the chord ``l`` in the elastica."""
        if self.leaf_model == "elastica":
            return self.geometry(x)["l"]
        return self.leaf_length + 0.0 * np.asarray(x, dtype=float)

    def columns(self, x) -> dict:
        g = self.geometry(x)
        return {"leaf bow": (g["bow"], "m"), "leaf chord": (g["l"], "m"),
                "rod travel": (g["s"], "m")}

    # -- the seam -------------------------------------------------------------------------------

    def terms(self, x, m, analysis=None, central=None) -> Terms:
        """Per fly weight: ``jp = m r``; the leaf ``kappa (f(x) - l0)`` at the middle (``A = f``,
        ``B = 1``); no dead loads."""
        x = np.asarray(x, dtype=float)
        f, f_x = leaf.force_per_stiffness(x - self.hinge_radius, self.leaf_length,
                                          self.leaf_model)
        zero = 0.0 * x
        return Terms(jp=m * x, jpp=m + zero, cf=zero, cf_x=zero, ci=zero, ci_x=zero,
                     A=f + zero, B=1.0 + zero, A_x=f_x + zero, B_x=zero)

    def spring_force_coefficients(self, x):
        """The leaf's middle load ``F = kappa (f - l0)``: ``(A_F, B_F) = (f, 1)``."""
        f = leaf.force_per_stiffness(np.asarray(x, dtype=float) - self.hinge_radius,
                                     self.leaf_length, self.leaf_model)[0]
        return f, 1.0 + 0.0 * f

    # -- the type's method and drawing: what a reader is told (the article, Fig. 2) -----------

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """The article's eqs. 5, 6 and 8 on the leaf of Fig. 2."""
        chord = {"straight": ("x = sqrt(L^2 - l^2) / 2 (two straight halves)",
                              "traction-article", "eq. 8"),
                 "arc": ("a circular arc of length L: L = 2 R arcsin(l / 2R), R = (l^2 + 4 x^2) "
                         "/ (8 x)", "traction-article", "eq. 8, note (corrected)"),
                 "elastica": ("the exact large-deflection shape (each half a cantilever with "
                              "its tip load)", "bisshopp-drucker", "")}[self.leaf_model]
        return (self.centrifugal(),
                Equation("statics", "the leaf's force at its middle balances the centrifugal "
                         "force (the collars slide freely): the characteristic",
                         "omega^2 m r = F(x), F = kappa (f(x) - l0), r = r_h + x",
                         "traction-article", "eqs. 5-6", ("governor.leaf_model",),
                         name="characteristic"),
                Equation("statics", "the leaf's bow x and chord l (the rod's travel s = l_1 - "
                         "l)", chord[0], chord[1], chord[2], ("governor.leaf_model",)),
                Equation("statics", "the leaf's force at its middle and its set l0",
                         "F = kappa (f(x) - l0): f = x in the linear theory, the elastica's "
                         "force otherwise", "traction-article", "eq. 5, note to eq. 8",
                         name="spring force"))

    def spring_method(self, spec) -> tuple[Equation, ...]:
        """The leaf: its stiffness, section and bending stress."""
        c = 48 if self.leaf_ends == "hinged" else 192
        return (Equation("spring", f"the leaf's stiffness ({self.leaf_ends} ends)",
                         f"kappa = {c} E I / L^3", "roark", "Table 8.1",
                         ("governor.leaf_ends",), name="rate"),
                Equation("spring", "the leaf's section", "I = w t^3 / 12", "traction-article",
                         "eq. 7"),
                Equation("spring", "bending stress at the leaf's largest moment",
                         "sigma = 6 M / (w t^2)", "roark", "Table 8.1", name="stress"),
                Equation("spring", "the chord models' stated range", "x / L <= 0.2",
                         "traction-article", "eq. 8"))

    def settings(self, spec) -> list[Setting]:
        """The seam's settings and the leaf's: its chord model and ends."""
        return [Setting("governor.leaf_model", self.leaf_model, "the leaf's chord and force: "
                        "straight (the article's eq. 8), arc, or elastica (exact)"),
                Setting("governor.leaf_ends", self.leaf_ends, "the leaf's ends: hinged (48) or "
                        "clamped (192)")] + super().settings(spec)

    def free_length_words(self) -> str:
        """The leaf's set: its unloaded bow (its length is the governor's ``leaf_length``)."""
        return ("leaf set l0: the unloaded leaf's bow at its middle from the line of its end "
                "attachments, outward positive (its length is governor.leaf_length)")

    def drawing(self, x, sd) -> Drawing:
        """One leaf each side in the meridian plane (Fig. 2): its ends on the collars at
        ``hinge_radius``, the fixed one at height 0 and the moving one the chord ``l`` above
        it, the fly weight at its middle ``x`` out; the leaf drawn through its ends and middle
        (two straight halves for the article's straight model, else the circular arc through
        them: the chord and bow are the model's own)."""
        g = self.geometry(float(x))
        bow, l = float(g["bow"]), float(g["l"])
        rh = self.hinge_radius
        if self.leaf_model == "straight" or bow <= 0.0:
            leaf_line = ((rh, 0.0), (rh + bow, 0.5 * l), (rh, l))
        else:
            R = (0.25 * l * l + bow * bow) / (2.0 * bow)
            half = np.arcsin(min(1.0, 0.5 * l / R))
            t = np.linspace(-half, half, 25)
            leaf_line = tuple((float(rh + bow - R + R * np.cos(a)), float(0.5 * l + R * np.sin(a)))
                              for a in t)
        parts = [Part("link", leaf_line), Part("pivot", ((rh, 0.0),)),
                 Part("pivot", ((rh, l),)), Part("mass", ((rh + bow, 0.5 * l),),
                                                  ball_radius(sd.m))]
        parts = list(mirrored(parts))
        tall = 0.05 * self.leaf_length
        for y, kind in ((0.0, "frame"), (l, "sleeve")):
            parts.append(Part(kind, ((-rh, y - tall / 2), (rh, y - tall / 2), (rh, y + tall / 2),
                                     (-rh, y + tall / 2), (-rh, y - tall / 2))))
        parts.append(Part("frame", ((0.0, -0.15 * self.leaf_length),
                                    (0.0, self.chord_open + 0.15 * self.leaf_length))))
        return Drawing(tuple(parts))
