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
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..keys import Key, Table
from ..springs.kinds import KINDS, SpringKind

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
      values of its ``govopt init --type`` template).
    """

    type_name: ClassVar[str]
    title: ClassVar[str]
    coordinate: ClassVar[str] = "angle"
    coordinate_name: ClassVar[str] = "x"
    travel: ClassVar[str] = "length"
    spring: ClassVar[str | None] = None
    mass_key: ClassVar[str] = "ball"
    mass_name: ClassVar[str] = "ball"
    free_length_key: ClassVar[str] = "free_length"
    #: flying masses (balls, pendulums) acting on the regulating member: effort and power
    flying_masses: ClassVar[int] = 2
    #: ``l0`` is a length that must be positive (a coil spring's free length; a leaf's set is not)
    free_length_positive: ClassVar[bool] = True
    #: the flying masses are forced at the running speed's harmonics (Hamabe Part II: the valve
    #: gear), so ``k^2 < omega0^2`` keeps them clear of resonance (case 2); False for a type
    #: whose mechanism has no such forcing: only ``k^2 > 0`` (stability, case 3) is required
    resonance_ceiling: ClassVar[bool] = True
    #: where the ceiling ``0 < k^2 < omega0^2`` comes from, for a plot's legend ('' for none)
    resonance_source: ClassVar[str] = ""
    #: the spring's whole free length per unit of ``l0`` (the shaft's l0 is a half length: 2)
    spring_length_factor: ClassVar[float] = 1.0
    #: names of the three generalised forces in reports: centrifugal, spring, dead loads
    force_names: ClassVar[tuple[str, str, str]] = ("F_c", "F_s", "F_d")
    keys: ClassVar[tuple[Key, ...]] = ()
    tables: ClassVar[tuple[Table, ...]] = ()
    example: ClassVar[str] = ""
    #: a spring the type may have, where ``spring`` is decided by its spec (a Porter's
    #: auxiliary spring): the kind whose keys its spec may hold (:meth:`declared_spring_kind`)
    optional_spring: ClassVar[str | None] = None
    #: what the ``[design]`` key :attr:`free_length_key` holds
    free_length_meaning: ClassVar[str] = "the spring's free length l0"
    #: the type carries a central (sleeve) load, which ``[design] central_weight`` gives and
    #: the design search varies within ``[bounds] central_weight``
    central_load: ClassVar[bool] = False

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
        forcing (a result with ``to_dict()``), else ``None`` (default: no forcing modelled)."""
        return None

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

    def spring_rate(self, design, material) -> float:
        """The spring's stiffness ``kappa`` (N/m) from the design's section: a helical spring,
        ``G d^4 / (64 r^3 n)`` (Wahl 1944; Hamabe Ex. 1)."""
        from ..springs import helical as hx

        return hx.stiffness_r(design.wire_diameter, design.coil_radius, design.active_turns,
                              material.shear_modulus)

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

    def spring_report(self, spec, sd, char, vib=None):
        """The spring maker's sheet, the fatigue loads under ``vib`` and the manufacturing
        spread of a helical spring (:func:`govopt.analysis.spring_engineering.report`); None
        without a wire spring."""
        if spec.material is None or not np.isfinite(sd.d):
            return None
        from ..analysis import spring_engineering

        return spring_engineering.report(spec, sd, char, vib)

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
