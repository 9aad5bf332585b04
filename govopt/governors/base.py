"""The seam every governor type plugs into (Lagrange form, one configuration coordinate ``x``).

A governor type is one module in :mod:`govopt.governors` with a subclass of :class:`Governor`:
its spec schema (:meth:`Governor.parse`) and, as vectorised SI functions of ``x``, the
generalised forces of the mechanism turning at ``omega``. Every analysis (statics, k^2, the
load-change model, friction, the optimiser's screen, the reports) is written once against these.

Sign convention: ``x`` increases as the governor opens (balls or pendulum move out, speed rises).
Generalised forces are counted positive when they *resist* opening. Virtual work on the flying
masses (Hamabe eqs. 1, 2, 11, 12; the textbook's controlling-force and instantaneous-centre
methods are the same principle) gives the equilibrium::

    omega^2 (jp(x) - ci(x)) = kappa (A(x) - B(x) l0) + cf(x)          (the characteristic)

* ``jp = J'(x)/2``: the centrifugal generalised force per unit ``omega^2``; ``J(x)`` is the
  moment of inertia of the flying masses about the spindle (``J = m r^2`` for a ball at radius
  ``r``; ``J = m (a^2 + rho^2 - 2 a rho cos x)`` for Hamabe's pendulum, so ``jp = m a rho sin x``);
* ``kappa (A - B l0)``: the spring's generalised force, affine in its stiffness ``kappa`` and in
  ``kappa l0`` (``l0`` the spring's free length, in whatever form the type states it);
* ``cf + omega^2 ci``: the dead loads (weights, central load, the regulating gear's mean reaction)
  split into a speed-independent part and a part growing with ``omega^2``.

The restoring stiffness about an equilibrium at ``(x, omega)`` is (Hamabe eqs. 18-20)::

    k^2 = (kappa (A_x - B_x l0) + cf_x - omega^2 (jpp - ci_x)) / I(x)

with ``_x`` the derivatives in ``x`` and ``I(x)`` the generalised inertia; the speed lever of the
load-change model is ``d/domega`` of the net generalised force, ``2 omega (jp - ci)``; the engine's
torque follows the regulating member's travel ``s(x)``, so ``dT/dx = (dT/ds) s'(x)``.

Any consistent normalisation is allowed (per pendulum, per ball, or the whole mechanism): the
load-change model and k^2 are invariant under scaling every generalised force and ``I`` together.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field, fields, replace
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from ..keys import Key, Table
from ..references import REFERENCES, cite, found_in
from ..springs.kinds import KINDS, SpringKind

if TYPE_CHECKING:
    from .drawing import Drawing

#: The SI units of the quantities measured at the coordinate ``x``, as JSON keys write them
#: (govopt's rule: every key's unit in its name), by the coordinate's dimension: ``x`` itself
#: and its rate; the generalised force ``Q`` (N m about an angle, N along a length) and inertia
#: ``I`` (:meth:`Governor.inertia`); the dash-pot ``f = dQ/dx'`` and the speed lever
#: ``C = dQ/domega`` (omega in rad/s) of the load-change model; the engine's ``R = -(dT/dx) /
#: I_fw`` (rad/s^2 per unit x: 1/s^2 for an angle) of Hamabe's eqs. (24)-(27), (42). The one
#: place these names are decided (:meth:`Governor.key_unit`).
KEY_UNITS = {
    "angle": {"x": "rad", "rate": "rad_per_s", "force": "N_m", "inertia": "kg_m2",
              "damping": "N_m_s_per_rad", "lever": "N_m_s", "engine": "per_s2"},
    "length": {"x": "m", "rate": "m_per_s", "force": "N", "inertia": "kg",
               "damping": "N_s_per_m", "lever": "N_s", "engine": "rad_per_m_s2"},
}


#: the least share of the spec's band ``[speed] inner .. outer`` the governor's range of speed
#: covers by default where its spring sets that range (:meth:`Governor.range_rule`); the other
#: half is left to the friction band and the made governor's spread: a spring rate made to EN
#: 15800 grade 2 spreads the range by about +-10 %, so a design that must span 3/4 of the band
#: and stay inside it has too little room to be made (the Hartnell and traction-coil templates
#: find no design whose made-and-set yield reaches 95 % at 3/4, and do at 1/2)
MIN_RANGE = 0.5

#: Hamabe's margin on ``k^2`` within ``(0, omega0^2)`` where a forcing is modelled (the shaft
#: governor's default ``requirements.k2_margin``; Hamabe Part II, Example 1's band of k^2)
K2_MARGIN = 0.05


@dataclass(frozen=True)
class Terms:
    """Generalised forces at configurations ``x`` for flying mass ``m`` (SI, broadcasting arrays).

    Units, for a coordinate of dimension ``[x]`` (rad or m): generalised forces ``Q`` are N m for
    an angle, N for a length; ``jp``, ``ci`` are Q per (rad/s)^2; ``A`` is Q per (N/m); ``B`` is Q
    per (N/m) per m; the ``_x`` variants are per ``[x]``.
    """

    jp: np.ndarray  # J'(x)/2
    jpp: np.ndarray  # d(jp)/dx = J''(x)/2
    cf: np.ndarray  # speed-independent restoring generalised force (dead loads)
    cf_x: np.ndarray
    ci: np.ndarray  # restoring generalised force per omega^2 (regulating gear's inertia)
    ci_x: np.ndarray
    A: np.ndarray  # spring: Q_s = kappa (A - B l0)
    B: np.ndarray
    A_x: np.ndarray
    B_x: np.ndarray

    @property
    def lever(self):
        """``jp - ci``: the net centrifugal generalised force per unit ``omega^2``."""
        return self.jp - self.ci

    def restoring(self, kappa=0.0, l0=0.0):
        """Speed-independent restoring generalised force ``kappa (A - B l0) + cf``."""
        return kappa * (self.A - self.B * l0) + self.cf

    def omega_squared(self, kappa=0.0, l0=0.0, friction=0.0):
        """Equilibrium speed squared (the characteristic): ``(kappa (A - B l0) + cf + friction)
        / (jp - ci)``; ``friction`` > 0 gives the speed with the governor opening against a
        friction band, < 0 closing (the textbook's sleeve friction, section 3.4)."""
        return (self.restoring(kappa, l0) + friction) / self.lever

    def stiffness(self, kappa, l0, omega2):
        """``I k^2 = kappa (A_x - B_x l0) + cf_x - omega^2 (jpp - ci_x)`` at ``omega^2``
        (Hamabe eqs. 18-20 in general form); divide by :meth:`Governor.inertia` for k^2."""
        return kappa * (self.A_x - self.B_x * l0) + self.cf_x - omega2 * (self.jpp - self.ci_x)


# -- what a reader is told: a type's method and its drawing, declared beside its physics ------

#: The topics of a method in the order a reader meets them, and their headings.
TOPICS = {"statics": "Statics", "speed": "Speed band", "spring": "Spring",
          "stability": "Stability", "friction": "Friction", "vibration": "Forced vibration",
          "load change": "Load change", "classic": "Classic measures"}


@dataclass(frozen=True)
class Equation:
    """One equation a type uses: ``what`` it gives (in words), its ``formula`` (symbols as the
    source writes them, plain text), the ``source`` (a key of :data:`govopt.references.
    REFERENCES`) and ``where`` in it (an equation, a section, a clause), and the fidelity
    settings that choose its form (``settings``: ``"analysis.geometry"``, ``"governor.k"``).
    ``name``: the handle a writer or a check asks for (``"irregularity"``, ``"hurwitz"``).
    ``borrowed``: a criterion or solution of another type's source applied to this type
    (:meth:`Governor.borrows`); its citation says so."""

    topic: str
    what: str
    formula: str
    source: str
    where: str = ""
    settings: tuple[str, ...] = ()
    name: str = ""
    borrowed: bool = False

    @property
    def cite(self) -> str:
        """The citation in running text: ``"Hamabe eq. 12"``, or for a borrowed criterion
        ``"borrowed from Hamabe Part II, case 2"``."""
        return ("borrowed from " if self.borrowed else "") + cite(self.source, self.where)

    @property
    def text(self) -> str:
        """``"<citation>: <formula>"``, as a check's source reads it."""
        return f"{self.cite}: {self.formula}"


@dataclass(frozen=True)
class Setting:
    """A fidelity setting that applies to the type: its key as the spec writes it
    (``"analysis.geometry"``), its value in this spec and what it chooses."""

    key: str
    value: Any
    meaning: str


@dataclass(frozen=True)
class Method:
    """What a governor type computes and from which sources, for one spec: its equations by
    topic (:data:`TOPICS`), the fidelity settings that apply to it, and what the spring's free
    length ``l0`` is in this type (``free_length``, words; empty without a spring). Every writer
    reads it: the workbook's Method sheet, the text report's headings, the plots' titles, the
    JSON's ``method``; the checks read their sources from it (:meth:`text`)."""

    title: str
    equations: tuple[Equation, ...]
    settings: tuple[Setting, ...] = ()
    free_length: str = ""
    notes: tuple[str, ...] = field(default=())

    def of(self, topic: str) -> tuple[Equation, ...]:
        """The equations of ``topic``, in order."""
        return tuple(e for e in self.equations if e.topic == topic)

    def named(self, name: str) -> Equation | None:
        """The equation called ``name`` (:attr:`Equation.name`), or None."""
        return next((e for e in self.equations if e.name == name), None)

    def cite(self, topic: str) -> str:
        """The citations of a topic's equations, one per source with its places in order,
        ``"; "``-joined (``""`` for none): what a heading puts in brackets.

        >>> Method("t", (Equation("statics", "", "", "hamabe", "eq. 1"),
        ...              Equation("statics", "", "", "hamabe", "eq. 12"),
        ...              Equation("statics", "", "", "rattan"))).cite("statics")
        'Hamabe eq. 1, eq. 12; Rattan'
        """
        places: dict[str, list[str]] = {}
        for e in self.of(topic):
            where = places.setdefault(e.source, [])
            if e.where and e.where not in where:
                where.append(e.where)
        return "; ".join(cite(key, ", ".join(where)) for key, where in places.items())

    def heading(self, topic: str, text: str) -> str:
        """``text`` with the topic's citations in brackets (none: ``text`` alone)."""
        sources = self.cite(topic)
        return f"{text} ({sources})" if sources else text

    def text(self, name: str, default: str = "") -> str:
        """A check's source from the equation ``name`` (:attr:`Equation.text`), else
        ``default``."""
        eq = self.named(name)
        return default if eq is None else eq.text

    def sources(self, also: tuple[str, ...] = ()) -> list[str]:
        """The bibliography keys the method cites, in order of first use, then those the texts
        ``also`` (the checks' own sources) name (:func:`govopt.references.found_in`)."""
        keys = [e.source for e in self.equations]
        keys += [k for text in also for k in found_in(text)]
        return list(dict.fromkeys(keys))

    def uses(self, checks: tuple[tuple[str, str], ...] = ()) -> dict[str, str]:
        """What this method uses each of its sources for (:meth:`sources`' keys, in order),
        in words: the topics whose equations cite it, each with the places cited, then the
        ``checks`` (``(name, source text)`` pairs) whose sources name it. A source cited by
        another type's method is listed for what this one takes from it, not for its whole
        content.

        >>> Method("t", (Equation("statics", "", "", "hamabe", "eq. 1"),
        ...              Equation("stability", "", "", "hamabe", "Part II, case 2"),
        ...              Equation("statics", "", "", "rattan"))).uses(
        ...     (("shear stress", "Wahl 1944: tau"), ("irregularity", "Hamabe Part I")))
        {'hamabe': 'statics (eq. 1); stability (Part II, case 2); the check irregularity', \
'rattan': 'statics', 'wahl': 'the check shear stress'}
        """
        out: dict[str, dict[str, list[str]]] = {}
        for e in self.equations:
            places = out.setdefault(e.source, {}).setdefault(TOPICS.get(e.topic, e.topic).lower(),
                                                             [])
            if e.where and e.where not in places:
                places.append(e.where)
        named: dict[str, list[str]] = {}
        for name, text in checks:
            for key in found_in(text):
                out.setdefault(key, {})
                if name not in named.setdefault(key, []):
                    named[key].append(name)
        words = {}
        for key, topics in out.items():
            parts = [f"{t} ({', '.join(w)})" if w else t for t, w in topics.items()]
            names = named.get(key, [])
            if names:
                shown = ", ".join(names[:4]) + (f" and {len(names) - 4} more" if len(names) > 4
                                                else "")
                parts.append(f"the check{'s' if len(names) > 1 else ''} {shown}")
            words[key] = "; ".join(parts)
        return words

    def to_dict(self) -> dict:
        """The method as JSON: equations (topic, what, formula, source key, citation,
        settings), the fidelity settings with values and the free length's meaning."""
        return {"title": self.title,
                "equations": [{"topic": e.topic, "what": e.what, "formula": e.formula,
                               "source": e.source, "cite": e.cite,
                               **({"borrowed": True} if e.borrowed else {}),
                               **({"settings": list(e.settings)} if e.settings else {})}
                              for e in self.equations],
                "settings": {s.key: s.value for s in self.settings},
                **({"free_length": self.free_length} if self.free_length else {}),
                **({"notes": list(self.notes)} if self.notes else {})}


@dataclass(frozen=True)
class Coordinate:
    """One way the books give a governor's configuration (the ball's radius, the arm's angle to
    the axis, the height, the joint's radius, the sleeve's lift): its ``name`` as a spec key's
    stem and a query point write it (``angle`` -> ``angle_inner``, ``--at "angle=30 deg"``),
    its ``dimension`` (``"angle"`` or ``"length"``), one line of ``meaning`` with its source,
    and ``value``: the coordinate at configurations ``x`` (SI, vectorised). Every type declares
    its own (:meth:`Governor.coordinates`); :func:`govopt.analysis.points.configuration`
    inverts ``value`` by bracketed root-finding over :meth:`Governor.x_domain`."""

    name: str
    dimension: str
    meaning: str
    value: Any


def solve_monotone(f, value: float, lo: float, hi: float, samples: int = 257) -> float:
    """The ``u`` in ``(lo, hi)`` where ``f(u) = value``: ``f`` sampled at ``samples`` points
    (its non-finite values skipped), the first sign change bracketed and closed by Brent's
    method to rounding; NaN where ``f`` does not cross ``value`` (no root in the domain).

    Brent's method (R. P. Brent, *Algorithms for Minimization without Derivatives*, 1973, ch.
    4; ``scipy.optimize.brentq``): a root of a continuous function, bracketed, never lost.

    Parameters
    ----------
    f : callable [-]
        Vectorised function of ``u`` (SI).
    value : float [-]
        The value sought, in ``f``'s unit.
    lo, hi : float [-]
        The domain of ``u`` (the ends themselves are not sampled).
    samples : int [-]
        Points sampled to find a bracket.

    Returns
    -------
    float [-]
        The root, or NaN.

    Examples
    --------
    ``u^2 = 2`` on (0, 3): by hand sqrt(2) = 1.41421356...

    >>> round(solve_monotone(lambda u: u**2, 2.0, 0.0, 3.0), 12)
    1.414213562373
    """
    from scipy.optimize import brentq

    u = np.linspace(lo, hi, samples + 2)[1:-1]
    with np.errstate(all="ignore"):
        g = np.asarray(f(u), dtype=float) - value
    ok = np.isfinite(g)
    u, g = u[ok], g[ok]
    hit = np.flatnonzero(g == 0.0)
    if hit.size:
        return float(u[hit[0]])
    cross = np.flatnonzero(np.sign(g[:-1]) * np.sign(g[1:]) < 0)
    if not cross.size:
        return float("nan")
    i = int(cross[0])
    return float(brentq(lambda v: float(f(v)) - value, u[i], u[i + 1], xtol=1e-15 * max(
        abs(hi), abs(lo), 1e-300), rtol=4 * np.finfo(float).eps))


@dataclass(frozen=True)
class Adjustment:
    """A setting the fitter makes on each governor as it is built: ``what`` is set (in words),
    the :class:`~govopt.inputs.Design` ``field`` it changes, the ``end`` of the range
    (``"inner"`` or ``"outer"``) whose equilibrium speed it brings to the design's, and the
    ``source`` (a key of :data:`govopt.references.REFERENCES`) with ``where`` in it. Applied by
    :func:`govopt.made.set_by_the_fitter` (the speed is affine in the setting: a closed form)."""

    what: str
    field: str
    end: str
    source: str
    where: str = ""

    @property
    def cite(self) -> str:
        return cite(self.source, self.where)


#: the spring's initial compression (its free length) set by the nut so that the sleeve begins
#: to rise at the design's speed: how the textbook's examples fix a spring governor's spring
#: ("find the initial compression ... in order that the sleeve shall begin to rise at 240 rpm")
SPRING_PRELOAD = Adjustment("the spring's preload (its free length, by the adjusting nut)",
                            "free_half_length", "inner", "textbook-ch3",
                            "section 3.5, Examples 5 and 8 (initial compression)")


class Governor(ABC):
    """One governor type with its parsed geometry (SI); subclasses supply the seam.

    Class attributes describe the type for the spec schema and reports:

    * ``type_name``: the ``governor.type`` string; ``title``: a human name with its source;
    * ``coordinate``: the dimension of ``x`` (``"angle"`` or ``"length"``) and ``coordinate_name``
      (``"alpha"``, ``"sleeve lift"`` ...) for reports;
    * ``travel``: the dimension of the regulating member's travel ``s`` (the engine's torque slope
      is given per unit of it);
    * ``spring``: ``None`` (dead-weight governor), ``"tension"``, ``"compression"`` or ``"leaf"``;
    * ``mass_key``: stem of the flying mass's spec key (``"pendulum"`` -> ``pendulum_weight``);
    * ``mass_name``: the type's own word for one flying mass in reports and check names
      (``"pendulum"``, ``"ball"``, ``"fly weight"``);
    * ``free_length_key``: the ``[design]`` key of the spring's free length ``l0``;
    * ``keys``: its ``[governor]`` keys beyond ``type`` (:class:`govopt.keys.Key`, in reading
      order), which :meth:`parse` reads; ``tables``: top-level tables of its own (the shaft
      governor's ``[valve_gear]``); ``example``: the bundled design spec of the type (the
      values of its ``govopt init --type`` template); ``key_alternatives``: the choices
      between groups of its keys (:attr:`govopt.keys.Table.alternatives`).
    """

    type_name: ClassVar[str]
    key_alternatives: ClassVar[tuple] = ()
    title: ClassVar[str]
    coordinate: ClassVar[str] = "angle"
    coordinate_name: ClassVar[str] = "x"
    travel: ClassVar[str] = "length"
    spring: ClassVar[str | None] = None
    mass_key: ClassVar[str] = "ball"
    mass_name: ClassVar[str] = "ball"
    free_length_key: ClassVar[str] = "free_length"
    #: flying masses (balls, pendulums) acting on the regulating member: effort and power, and
    #: the moving mass (:meth:`moving_mass`)
    flying_masses: ClassVar[int] = 2
    #: ``l0`` is a length that must be positive (a coil spring's free length; a leaf's set is not)
    free_length_positive: ClassVar[bool] = True
    #: the flying masses are forced at the running speed's harmonics (Hamabe Part II: the valve
    #: gear), so ``k^2 < omega0^2`` keeps them clear of resonance (case 2) by default, with
    #: :data:`K2_MARGIN`; False (the default) for a type whose mechanism has no such forcing
    #: modelled (the textbook's and the article's governors): only ``k^2 > 0`` (stability, case
    #: 3) is required, and Hamabe's band only where the spec asks for it
    #: (``requirements.k2_margin``, :meth:`k2_rule`)
    resonance_ceiling: ClassVar[bool] = False
    #: the spec's band ``[speed] inner/outer`` is the governor's range of speed from the
    #: sleeve's lowest to its highest position (the textbook's and the article's reading:
    #: :meth:`range_rule`); False where it is only an envelope the speeds stay within (Hamabe's
    #: irregularity "at most")
    band_is_range: ClassVar[bool] = True
    #: where the ceiling ``0 < k^2 < omega0^2`` comes from, for a plot's legend ('' for none)
    resonance_source: ClassVar[str] = ""
    #: the spec key of the type's friction (its dotted path) and its dimension: what a
    #: diagnosis lowers where friction makes a design infeasible ("" where the type has none)
    friction_key: ClassVar[str] = ""
    friction_dimension: ClassVar[str] = "force"
    #: the spec keys of the range's ends (innermost, outermost configuration) and their
    #: dimension: a narrower range narrows the speed band, what a diagnosis may propose
    range_keys: ClassVar[tuple[str, str] | None] = None
    range_dimension: ClassVar[str] = "length"
    #: the type's own source (a key of :data:`govopt.references.REFERENCES`): a spec key or a
    #: criterion citing another type's source is borrowed, and its text says so
    source: ClassVar[str] = ""
    #: the spring's whole free length per unit of ``l0`` (the shaft's l0 is a half length: 2)
    spring_length_factor: ClassVar[float] = 1.0
    #: names of the three generalised forces in reports: centrifugal, spring, dead loads
    force_names: ClassVar[tuple[str, str, str]] = ("F_c", "F_s", "F_d")
    keys: ClassVar[tuple[Key, ...]] = ()
    tables: ClassVar[tuple[Table, ...]] = ()
    #: the type's own ``[analysis]`` settings, beside the shared ones
    #: (:func:`govopt.spec_keys.analysis_table`)
    analysis_keys: ClassVar[tuple[Key, ...]] = ()
    example: ClassVar[str] = ""
    #: a spring the type may have, where ``spring`` is decided by its spec (a Porter's
    #: auxiliary spring): the kind whose keys its spec may hold (:meth:`declared_spring_kind`)
    optional_spring: ClassVar[str | None] = None
    #: what the ``[design]`` key :attr:`free_length_key` holds
    free_length_meaning: ClassVar[str] = "the spring's free length l0"
    #: the type carries a central (sleeve) load, which ``[design] central_weight`` gives and
    #: the design search varies within ``[bounds] central_weight``
    central_load: ClassVar[bool] = False
    #: the generalised forces and the inertia are affine in the central load, and the lever
    #: ``jp - ci`` free of it (a sleeve's weight acting through the linkage, as a Porter's): each
    #: statics requirement is then an interval of central loads, found in closed form
    #: (:func:`govopt.optimize.windows.central_load_intervals`)
    central_load_affine: ClassVar[bool] = False

    #: innermost, outermost and normal configurations (SI), set by :meth:`parse`
    x_inner: float
    x_outer: float
    x_normal: float

    @classmethod
    @abstractmethod
    def parse(cls, reader) -> Governor:
        """Read the type's ``[governor]`` table (a :class:`govopt.reader.Reader`; keys beyond
        ``type``) and return an instance; errors name the file and key."""

    @abstractmethod
    def terms(self, x, m, analysis, central=None) -> Terms:
        """The generalised forces at ``x`` for flying mass ``m`` (each ball's or pendulum's mass,
        kg; arrays broadcasting with ``x``). ``analysis`` is the spec's fidelity settings
        (:class:`govopt.spec.Analysis`: the type reads the settings it has, e.g. ``geometry``).
        ``central``: the central (sleeve) load's mass, kg, where the type has one and the
        optimiser varies it; ``None`` means the spec's own value."""

    @abstractmethod
    def inertia(self, x, m, central=None):
        """Generalised inertia ``I(x)`` of the moving parts about ``x`` (kg m^2 for an angle,
        kg for a length), in the same normalisation as :meth:`terms`."""

    def travel_slope(self, x):
        """``s'(x)``: travel of the regulating member per unit ``x`` (default: ``x`` itself)."""
        return np.ones_like(np.asarray(x, dtype=float))

    def friction(self, x, design=None):
        """Magnitude of the friction band as a generalised force at ``x`` (sleeve friction
        ``R |s'(x)|``; Hamabe's fulcrum moment ``M_0``); default none."""
        return np.zeros_like(np.asarray(x, dtype=float))

    def excel_design(self, s, res) -> bool:
        """Write the type's own live formulas on the workbook's Design sheet (``s``: the sheet
        writer of :mod:`govopt.report.excel`) and return True; default False: the generic sheet
        on the seam's constants is written instead."""
        return False

    def vibration(self, spec, sd, k2_normal: float, dashpot: float):
        """The forced vibration at the normal configuration where the type has a periodic
        forcing (a result with ``to_dict()`` and ``peak_to_peak_rad``), else ``None`` (default:
        no forcing modelled). A type with a forcing overrides this, and :meth:`vibrations`
        where it can compute many designs at once."""
        return None

    def vibrations(self, spec, sd, k2_normal, dashpot):
        """:meth:`vibration` of N designs (``sd``'s fields of shape ``(N,)`` or ``(N, 1)``,
        ``k2_normal`` and ``dashpot`` of shape ``(N,)``): a sequence of N results, or None
        where the type has no forcing. Default: :meth:`vibration` design by design; a type
        overrides it with one computation over the designs."""
        rows = []
        for i in range(np.size(k2_normal)):
            one = replace(sd, **{f.name: float(np.ravel(getattr(sd, f.name))[i])
                                 for f in fields(sd) if np.ndim(getattr(sd, f.name))})
            rows.append(self.vibration(spec, one, float(k2_normal[i]), float(dashpot[i])))
        return None if rows and rows[0] is None else rows

    @classmethod
    def key_unit(cls, quantity: str) -> str:
        """The SI unit of ``quantity`` (a key of :data:`KEY_UNITS`: ``"x"``, ``"rate"``,
        ``"force"``, ``"inertia"``, ``"damping"``, ``"lever"``, ``"engine"``) at this type's
        coordinate, as JSON keys write it.

        >>> from govopt.governors.porter import PorterGovernor
        >>> from govopt.governors.shaft import ShaftGovernor
        >>> PorterGovernor.key_unit("damping"), ShaftGovernor.key_unit("damping")
        ('N_s_per_m', 'N_m_s_per_rad')
        """
        return KEY_UNITS[cls.coordinate][quantity]

    @classmethod
    def key_units(cls) -> dict[str, str]:
        """Every :meth:`key_unit` of this type's coordinate (a copy of its :data:`KEY_UNITS`)."""
        return dict(KEY_UNITS[cls.coordinate])

    def shown(self, x):
        """``(value, unit)`` of a configuration as people read it: degrees or millimetres."""
        x = np.asarray(x, dtype=float)
        return (np.degrees(x), "deg") if self.coordinate == "angle" else (1e3 * x, "mm")

    def json_coordinate(self, stem: str, x) -> tuple[str, float]:
        """JSON key and value of a configuration: ``<stem>_deg`` for an angle, ``<stem>_m``."""
        if self.coordinate == "angle":
            return f"{stem}_deg", float(np.degrees(x))
        return f"{stem}_m", float(x)

    # -- the spring plug: a helical spring by default (a type with another spring overrides) --

    @classmethod
    def declared_spring_kind(cls) -> SpringKind | None:
        """The spring kind whose keys a spec of this type may hold (its spring, or the one it
        may have), None for a dead-weight type."""
        name = cls.spring or cls.optional_spring
        return None if name is None else KINDS[name]

    @property
    def spring_kind(self) -> SpringKind | None:
        """The spring's kind (:data:`govopt.springs.kinds.KINDS`: its spec keys and catalogue
        limits), None for a dead-weight governor."""
        return None if self.spring is None else KINDS[self.spring]

    @property
    def spring_loaded_check(self) -> str:
        """Name of the check that the spring stays loaded in its working sense over the range."""
        return f"spring in {self.spring}"

    @property
    def moving_springs(self) -> int:
        """How many design springs the governor carries (each of the design's size): one by
        default, none for a dead-weight governor."""
        return 0 if self.spring is None else 1

    def moving_mass(self, m, central, spring_mass):
        """Every moving mass (kg): the flying masses (:attr:`flying_masses` of ``m`` each), the
        central (sleeve) load and the design springs (:attr:`moving_springs` of
        ``spring_mass`` each): the objective ``moving_mass``.

        A definition of govopt's (the sources size the parts, not their sum); what it counts
        is :meth:`moving_mass_words`.

        Parameters
        ----------
        m : float or array [kg]
            Each flying mass.
        central : float or array [kg]
            The central load (0 without one).
        spring_mass : float or array [kg]
            One design spring's mass.

        Returns
        -------
        float or array [kg]
            The moving mass.

        Examples
        --------
        A Hartnell with two 2.5 kg balls and a 0.17 kg spring:

        >>> from govopt.governors.hartnell import HartnellGovernor
        >>> HartnellGovernor.__new__(HartnellGovernor).moving_mass(2.5, 0.0, 0.17)
        5.17
        """
        return self.flying_masses * m + central + self.moving_springs * spring_mass

    def moving_mass_words(self) -> str:
        """What :meth:`moving_mass` counts, in words: ``"2 balls, the central load and the
        spring"``."""
        parts = [f"{self.flying_masses} {self.mass_name}s"]
        if self.central_load:
            parts.append("the central load")
        springs = self.moving_springs
        if springs:
            parts.append("the spring" if springs == 1 else f"{springs} springs")
        return parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]

    def k2_rule(self, k2_margin: float | None) -> tuple[float, bool]:
        """Hamabe's band ``margin omega0^2 <= k^2 <= (1 - margin) omega0^2`` as this type
        applies it: ``(margin, ceiling)``, the ceiling kept or not. Where a forcing is modelled
        (:attr:`resonance_ceiling`, the shaft governor's valve gear: Hamabe Part II, case 2) the
        band applies by default with :data:`K2_MARGIN`; elsewhere only ``k^2 > 0`` (stability,
        the characteristic rising: the textbook's criterion) unless the spec asks for the band
        (``k2_margin`` given: then margin and ceiling both apply).

        Parameters
        ----------
        k2_margin : float or None [-]
            The spec's ``requirements.k2_margin``; None where it gives none.

        Returns
        -------
        tuple of (float [-], bool)
            The margin on ``k^2 / omega0^2`` and whether the ceiling applies.

        References
        ----------
        [hamabe] Part II, cases 1-3.

        Examples
        --------
        >>> from govopt.governors.porter import PorterGovernor
        >>> from govopt.governors.shaft import ShaftGovernor
        >>> Governor.k2_rule(PorterGovernor, None), Governor.k2_rule(ShaftGovernor, None)
        ((0.0, False), (0.05, True))
        >>> Governor.k2_rule(PorterGovernor, 0.1)
        (0.1, True)
        """
        if k2_margin is None:
            return (K2_MARGIN, True) if self.resonance_ceiling else (0.0, False)
        return float(k2_margin), True

    def range_rule(self, min_range: float | str | None) -> float:
        """The least range of speed, a share of the spec's band, this type requires:
        ``requirements.min_range`` as given (``"envelope"``: 0, the speeds anywhere inside the
        band), else :data:`MIN_RANGE` where the band is the governor's range of speed
        (:attr:`band_is_range`) and a spring sets it, else 0.

        The textbook states a governor's speeds at the sleeve's lowest and highest positions
        and its range of speed between them (ch. 3, Problems 2; Examples 5-8 design the spring
        through both); the traction article takes N1 and N2 at the throttle's two ends and
        warns that a narrow range hunts. A dead-weight governor's range is set by its linkage
        (textbook 3.4(b) eq. (ii): the Porter's speed ratio between two heights does not depend
        on its weights), which the spec gives, so it is not required by default.

        Parameters
        ----------
        min_range : float, "envelope" or None [-]
            The spec's ``requirements.min_range``; None where it gives none.

        Returns
        -------
        float [-]
            The share of the band (0: no range required).

        References
        ----------
        [textbook-ch3] Problems 2 (the range of speed); [traction-article] (hunting).

        Examples
        --------
        >>> from govopt.governors.hartnell import HartnellGovernor
        >>> from govopt.governors.porter import PorterGovernor
        >>> from govopt.governors.shaft import ShaftGovernor
        >>> [Governor.range_rule(g, None) for g in (HartnellGovernor, PorterGovernor,
        ...                                         ShaftGovernor)]
        [0.5, 0.0, 0.0]
        >>> Governor.range_rule(HartnellGovernor, "envelope")
        0.0
        """
        if min_range == "envelope":
            return 0.0
        if min_range is None:
            return MIN_RANGE if self.band_is_range and self.spring is not None else 0.0
        return float(min_range)

    def spring_rate(self, design, material) -> float:
        """The spring's stiffness ``kappa`` (N/m) from the design's section: a helical spring,
        ``G d^4 / (64 r^3 n)`` (Wahl 1944; Hamabe Ex. 1)."""
        from ..springs import helical as hx

        return hx.stiffness_r(design.wire_diameter, design.coil_radius, design.active_turns,
                              material.shear_modulus)

    def spring_mass(self, sd, material):
        """One design spring's mass (kg) for the design(s) ``sd``: here a leaf's or another
        spring of the type's own (a helical spring's is the evaluator's, Wahl 1944 ch. 25);
        NaN where the type does not say."""
        return np.full(np.shape(sd.m), np.nan)

    def spring_stress(self, x, F, sd, material):
        """The spring's stress (Pa) under force ``F`` at ``x``: helical shear ``16 F r/(pi d^3)``
        with the material's correction (Wahl 1944; Bergstraesser's k, EN 13906-1)."""
        from ..springs import helical as hx

        if material.stress_correction == "bergstrasser":
            return hx.shear_stress(F, sd.d, 2.0 * sd.r, "bergstrasser")
        return hx.shear_stress_r(F, sd.d, sd.r, material.stress_correction)

    def spring_checks(self, spec, sd, char, vib=None) -> list:
        """The spring's own checks (:class:`govopt.verdict.Check`) beyond the evaluator's rows
        (:mod:`govopt.evaluator`: a helical spring's shear stress against the allowable,
        :func:`govopt.requirements.stress_row`, and its geometry, which needs no wire grade):
        with a wire grade (``material.grade``) the spring engineering table instead - static
        stresses against the grade's allowables at ``d``, the spring kind's geometry, and
        fatigue and surge under ``vib``, the type's forced vibration
        (:mod:`govopt.analysis.spring_engineering`); none without a grade. A type with another
        spring (a leaf) gives its whole table here."""
        if spec.material is None or spec.material.grade is None or not np.isfinite(sd.d):
            return []
        from ..analysis import spring_engineering

        return spring_engineering.checks(spec, sd, char, vib)

    def adjustments(self) -> tuple[Adjustment, ...]:
        """What the fitter sets on each governor as built (:class:`Adjustment`): a spring's
        preload where the type has a spring (:data:`SPRING_PRELOAD`), nothing for a dead-weight
        governor. A type whose source says otherwise overrides this."""
        return () if self.spring is None else (SPRING_PRELOAD,)

    def spring_checks_over(self, spec, sd, F, x) -> list | None:
        """:meth:`spring_checks` of N designs at once, without a forcing (no fatigue rows):
        ``sd`` a :class:`~govopt.analysis.statics.SpringDesign` of arrays (``(N, 1)``), ``F``
        the spring forces over the configurations ``x`` (N, ``(N, K)``; ``x`` in the
        coordinate's unit, ``(K,)``). Each
        :class:`govopt.verdict.Check` holds arrays of N (value, limit, in its SI unit); None
        where some design has no array form (a spring given by its rate alone: then
        :meth:`spring_checks` design by design). The same numbers as :meth:`spring_checks`
        (each row is elementwise over the designs: :func:`govopt.springs.checks.rows_over`)."""
        if spec.material is None or spec.material.grade is None:
            return []
        if not np.all(np.isfinite(sd.d)):
            return None
        from ..analysis import spring_engineering

        return spring_engineering.checks_over(spec, sd, F)

    def spring_report(self, spec, sd, char, vib=None):
        """The spring maker's sheet, the fatigue loads under ``vib`` and the manufacturing
        spread of a helical spring (:func:`govopt.analysis.spring_record.report`); None
        without a wire spring."""
        if spec.material is None or not np.isfinite(sd.d):
            return None
        from ..analysis import spring_record as sr

        return sr.report(spec, sd, char, vib)

    #: the name of the type's own coordinate ``x`` as a query point writes it
    coordinate_key: ClassVar[str] = "x"

    def coordinates(self) -> tuple[Coordinate, ...]:
        """The coordinates a configuration may be given by (:class:`Coordinate`): the type's
        own ``x`` (default); a type adds the ones its books use."""
        return (Coordinate(self.coordinate_key, self.coordinate,
                           f"the {self.coordinate_name} (the type's own coordinate)",
                           lambda x: np.asarray(x, dtype=float)),)

    def x_domain(self) -> tuple[float, float]:
        """The configurations ``x`` the mechanism can take (SI): a query point is sought
        within it; default the spec's range."""
        return self.x_inner, self.x_outer

    #: the type's hard case for ``govopt bench`` (:func:`govopt.bench.suites.types_suite`): a
    #: bundled spec's name (or a spec's data), the values that make it hard ({dotted key:
    #: value}), the fidelity key of its shortcuts ("" for none) and their settings (the exact
    #: model first), and optionally the input its solve rows find (default the flying mass)
    bench_case: ClassVar[tuple] = ()

    def bench_reference(self, spec, x):
        """The equilibrium speeds (rad/s) at ``x`` of the bench case ``spec`` by the source's
        own closed form in high precision, where the type has one; default None (the bench
        measures the shortcuts against the exact model)."""
        return None

    def link_forces(self, x, m, central, omega2, restoring) -> dict:
        """The forces in the type's arms, links and pivots (N) at configurations ``x`` in
        equilibrium at ``omega2`` (rad/s)^2 with the restoring generalised force ``restoring``
        (:meth:`Terms.restoring`, a friction band added where the governor is moving):
        name -> array. Default: none (the type does not resolve its linkage's forces)."""
        return {}

    def columns(self, x) -> dict:
        """The type's own geometry over ``x`` for the characteristic table: name -> (values, SI
        unit); default none."""
        return {}

    def free_length_limits(self) -> dict:
        """``{requirement name: (sense, limit)}``: the bounds on the spring's free length ``l0``
        (m, the type's form) that the design search keeps among the statics (affine in
        ``kappa`` with ``kappa l0``); a positive free length where it is a length."""
        return {"free length > 0": (">=", 0.0)} if self.free_length_positive else {}

    def spring_force_coefficients(self, x):
        """``(A_F, B_F)`` with the spring force ``F = kappa (A_F - B_F l0)`` (N per N/m), for
        stresses; types without a spring return zeros."""
        z = np.zeros_like(np.asarray(x, dtype=float))
        return z, z

    # -- the type's method: what a reader is told (each type states its own) ------------------

    def method(self, spec) -> Method:
        """What this type computes for ``spec`` and from which sources (:class:`Method`): its
        statics (:meth:`statics_method`, each type's own), the speed band, its spring, the
        stability, friction, forced vibration and load change where they apply, and the
        classic measures; the fidelity settings that apply (:meth:`settings`)."""
        parts = (self.statics_method(spec), self.speed_method(spec),
                 self.spring_method(spec) if self.spring is not None else (),
                 self.stability_method(spec), self.friction_method(spec),
                 self.vibration_method(spec),
                 self.load_change_method(spec) if spec.engine is not None else (),
                 self.classic_method(spec))
        return Method(self.title, tuple(e for p in parts for e in p), tuple(self.settings(spec)),
                      self.free_length_words() if self.spring is not None else "")

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """The type's statics (each type states its own): here the seam's equilibrium by
        virtual work, the form every type's equations take."""
        return (Equation("statics", "equilibrium speed over the range (the characteristic), "
                                    "by virtual work on the one coordinate x",
                         "omega^2 (J'(x)/2 - C_i(x)) = kappa (A(x) - B(x) l0) + C_f(x)",
                         "lagrange", name="characteristic"),)

    def speed_method(self, spec) -> tuple[Equation, ...]:
        """The spec's speed band: the irregularity against the spec's mean speed (the
        textbook's ratio of the range of speed to the mean speed)."""
        if spec.speed is None:
            return ()
        out = (Equation("speed", "irregularity: the range of speed over the mean speed",
                        "delta = (omega_a - omega_i) / omega0, omega0 the spec's mean speed",
                        "textbook-ch3", "Problems, 2", name="irregularity"),)
        least = self.range_rule(spec.requirements.min_range if spec.requirements else None)
        if spec.speed.band and least > 0:
            out += (Equation("speed", "the band is the range of speed from the sleeve's lowest "
                             "to its highest position: the design spans at least min_range "
                             "of it (a narrow range is sensitive and hunts)",
                             f"omega_a - omega_i >= {least:g} (outer - inner)",
                             "traction-article", "coil-spring governor, step 3",
                             ("requirements.min_range",), name="range"),)
        return out

    def spring_method(self, spec) -> tuple[Equation, ...]:
        """A helical spring's rate, stress (with the material's correction), mass, surge
        frequency, and the standards its checks and the maker's sheet follow (a type with
        another spring overrides this)."""
        mat = spec.material
        correction = getattr(mat, "stress_correction", "none")
        stress = {"wahl": ("x K, K = (4C - 1)/(4C - 4) + 0.615/C", "wahl", "eq. 2-12"),
                  "bergstrasser": ("x k, k = (C + 0.5)/(C - 0.75)", "en13906-1", "")}.get(
            correction, ("(uncorrected)", "wahl", "ch. 2"))
        standard = "en13906-2" if self.spring == "tension" else "en13906-1"
        return (
            Equation("spring", "rate of the helical spring", "kappa = G d^4 / (64 r^3 n)",
                     "wahl", "ch. 2", name="rate"),
            Equation("spring", "index", "C = 2 r / d", "wahl", "ch. 2"),
            Equation("spring", "shear stress at the force F", f"tau = 16 F r / (pi d^3) "
                     f"{stress[0]}", stress[1], stress[2], ("material.stress_correction",),
                     name="stress"),
            Equation("spring", "mass of the active coils and surge frequency (both ends fixed)",
                     "m_s = rho_w (pi d^2/4)(2 pi r n), f_s = d/(8 pi r^2 n) sqrt(G/(2 rho_w))",
                     "wahl", "ch. 25"),
            Equation("spring", f"the maker's sheet: {self.spring} spring's lengths and "
                     "stresses", "EN 13906 (solid and least working length; extension: "
                     "initial tension, loops)", standard),
            Equation("spring", "manufacturing tolerances and the speeds they spread",
                     "A_d, A_D, A_L0, A_F (grade 1-3) at the four corners of (kappa, l0)",
                     "en15800", "", ("material.tolerance_grade",)),
        )

    def stability_method(self, spec) -> tuple[Equation, ...]:
        """The restoring stiffness about an equilibrium on the seam, stability by its sign and,
        where the type keeps it (:attr:`resonance_ceiling`), the ceiling ``omega0^2``."""
        out = (Equation("stability", "restoring stiffness: the equation of motion linearised "
                                     "about an equilibrium",
                        "I k^2 = kappa (A' - B' l0) + C_f' - omega^2 (J''/2 - C_i')",
                        "lagrange", name="k2"),
               Equation("stability", "stable where k^2 > 0, i.e. where the characteristic "
                                     "rises (d omega/dx > 0)",
                        "I k^2 = 2 omega (J'/2 - C_i) d omega/dx", "rattan",
                        name="stable"))
        if self.k2_rule(spec.requirements.k2_margin if spec.requirements else None)[1]:
            out += (Equation("stability", "the flying masses' natural frequency kept below the "
                                          "running speed (clear of resonance)",
                             "k^2 < omega0^2", "hamabe", "Part II, case 2", name="resonance",
                             borrowed=self.borrows("hamabe")),)
        return out

    @classmethod
    def borrows(cls, source: str) -> bool:
        """Whether an equation citing ``source`` (a bibliography key) is borrowed by this type:
        the source is not the type's own (:attr:`source`) nor a general one (a standard,
        Lagrange, Rattan) but another governor type's (:attr:`Reference.governor`)."""
        return bool(cls.source) and source != cls.source and REFERENCES[source].governor

    def friction_method(self, spec) -> tuple[Equation, ...]:
        """The type's friction band (default none) and, with an engine, the load change
        against it."""
        return ()

    def friction_strokes(self, spec) -> tuple[Equation, ...]:
        """With an engine and friction: the load change moves in strokes against the friction
        band (Hamabe's stick-slip solution, which govopt applies to every type on the seam)."""
        if spec.engine is None:
            return ()
        return (Equation("friction", "load change against the friction band: strokes and "
                                     "rests (stick-slip), each stroke solved exactly",
                         "I xi'' + f xi' + I k^2 xi + F_r sign(xi') = C eta, "
                         "eta' = -R xi", "hamabe", "eqs. 42-46", name="strokes",
                         borrowed=self.borrows("hamabe")),)

    def vibration_method(self, spec) -> tuple[Equation, ...]:
        """The forced vibration under a periodic forcing (default: none modelled)."""
        return ()

    def load_change_method(self, spec) -> tuple[Equation, ...]:
        """A load change of the governed engine: the third-order model on the seam, its
        stability (Hurwitz), its response (with the spec's engine data)."""
        return (Equation("load change", "governor and engine after a load change: the "
                                        "third-order equation of the governed engine",
                         "a0 xi''' + 3 a1 xi'' + 3 a2 xi' + a3 xi = 0, a0 = I, a1 = f/3, "
                         "a2 = I k^2/3, a3 = C R", "vyshnegradsky", name="cubic"),
                Equation("load change", "stable where the cubic's roots have negative real "
                                        "parts", "9 a1 a2 > a0 a3, margin 9 a1 a2 / (a0 a3) - 1",
                         "hurwitz", name="hurwitz"),
                Equation("load change", "Vyshnegradsky's diagram: the normal form and its "
                                        "regions", "lambda^3 + A lambda^2 + B lambda + 1 = 0, "
                                                   "stable for A B > 1", "vyshnegradsky"))

    def classic_method(self, spec) -> tuple[Equation, ...]:
        """The classic measures every type reports from its characteristic (and, for a flying
        mass on a radius, the controlling-force diagram)."""
        diagram = (Equation("classic", "controlling-force diagram: the controlling force per "
                            "flying mass against its radius, lines of constant speed through "
                            "the origin", "F_c(r) = m omega^2 r at equilibrium", "textbook-ch3",
                            "3.3"),) if self.coordinate == "length" else ()
        return diagram + (Equation("classic", "sensitiveness, stability, effort and power of the "
                                    "governor", "sensitiveness = 2 (omega_a - omega_i) / "
                                                "(omega_a + omega_i); effort P = n ((1 + c)^2 "
                                                "- 1) omega^2 (J'/2 - C_i) / (2 s')", "rattan",
                         settings=("analysis.speed_change",)),)

    def settings(self, spec) -> list[Setting]:
        """The fidelity settings that apply to this type (the seam's; a type adds its own)."""
        an = spec.analysis
        out = [Setting("analysis.points", an.points,
                       "configurations over the range: the characteristic's resolution"),
               Setting("analysis.speed_change", an.speed_change,
                       "the speed change of the classic effort and power")]
        if spec.engine is not None and spec.load_changes:
            out.append(Setting("analysis.settling_band", an.settling_band,
                               "the band a load change's response settles in"))
        if an.use_case is not None:
            out += [Setting("analysis.use_case", an.use_case, "the analyses run"),
                    Setting("analysis.tolerance", an.tolerance,
                            "the error each analysis stays within")]
        if self.spring_kind is not None and self.spring_kind.helical and spec.material is not None:
            out.append(Setting("material.stress_correction", spec.material.stress_correction,
                               "the factor on the spring's shear stress"))
        return out

    def free_length_words(self) -> str:
        """What the spring's free length ``l0`` is in this type, in words (the design's
        ``free_length_key``; a type whose ``l0`` is not the spring's own length says so)."""
        return (f"{self.free_length_key.replace('_', ' ')} l0: the spring's own free length, "
                "unloaded")

    # -- the type's drawing (each type draws its own linkage) ---------------------------------

    def drawing(self, x, sd) -> Drawing | None:
        """The governor drawn to scale at configuration ``x`` (SI) for the design ``sd`` (a
        :class:`govopt.analysis.statics.SpringDesign`: the flying masses drawn as steel balls
        of their mass, :func:`~govopt.governors.drawing.ball_radius`; the coil spring at its
        mean diameter ``2 r``): a :class:`~govopt.governors.drawing.Drawing` from the same
        geometry the type's statics use. Default: None (the type draws nothing)."""
        return None
