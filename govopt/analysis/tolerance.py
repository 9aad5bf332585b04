"""The tolerance model of a made governor: what a governor built to its drawing may be.

One declaration, read by every tolerance answer govopt gives: the spring sheet's worst-case
spread (:func:`govopt.analysis.spring_record.spread`), the yield beside the verdict
(:mod:`govopt.made`), a tolerance study's samples (``govopt study run --tolerance grade=N``,
:func:`govopt.study.tolerances.grade_tolerances`) and robust design's box
(:mod:`govopt.optimize.robust`). So the worst case bounds every sample, and the three agree.

What is toleranced, each design's quantity +- a half-width (SI):

- a helical spring made to EN 15800 quality grade ``N`` (1 finest, 2, 3): the wire diameter
  ``+-A_d`` after its wire standard (EN 10270-1 or -2, by the wire grade's name; a wire without
  tabulated tolerances is taken exact), the mean coil diameter ``+-A_D`` (EN 15800 Table 1; on
  the radius ``+-A_D / 2``) and, for a compression spring ordered by its free length (no force
  toleranced), the free length ``+-A_L0 = alpha_F k_F Q / R`` (EN 15800; over the type's
  ``spring_length_factor`` in the type's form), :mod:`govopt.springs.tolerances`. The rate
  ``R = G d^4 / (8 D^3 n)`` follows from the wire and the coil (the coils ``n`` are counted as
  coiled). An extension spring's free length and initial tension are by agreement with the
  maker (EN 15800 covers compression springs): not toleranced, and a note says so;
- the flying and central masses ``+-robust_masses`` (a fraction), the dash-pot setting
  ``+-robust_dashpot`` and the engine's torque slope ``+-robust_torque_slope``, as the spec's
  ``[requirements]`` state them.

The spring's grade (:func:`spring_grade`): ``requirements.robust_spring_grade``, else, where the
spec names a wire grade (``material.grade``: a spring made to a standard), its
``material.tolerance_grade``.

The scatter: each quantity independent, normal with its band read as +-3 standard deviations
and truncated at the band (:func:`govopt.stats.truncated_normal`: a part outside its tolerance
is rejected, so every made governor lies in the box).

The worst case of the speeds (:func:`speed_band`) is found at the box's corners, exactly: the
equilibrium speed (virtual work, :func:`govopt.analysis.statics.omega_squared`),
``omega^2(x) = (kappa A(x) - kappa l0 B(x) + C_f(x) -+ F(x)) / (J'(x)/2 - C_i(x))`` (with the
friction band ``F`` where it opens or closes), is, each other quantity held, affine in the free
length ``l0``, affine in the rate ``kappa`` and so monotone in the wire and the coil diameter
(``kappa ~ d^4 / D^3``), and a ratio of affine functions of a mass (monotone wherever it has no
pole, and a pole is a governor without equilibrium). A function monotone in each coordinate
reaches its least and largest over a box at corners (move one coordinate at a time to its
better face). The dash-pot and the torque slope do not enter the statics.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np

from ..inputs import Design
from ..springs import helical as hx
from ..springs import tolerances as tl
from . import statics

#: the design's toleranced quantities (:class:`govopt.inputs.Design` fields), in the order a
#: sample draws them (the study's grade tolerances keep it: the same points)
FIELDS = ("wire_diameter", "coil_radius", "free_half_length", "dashpot", "flying_mass",
          "central_mass")
#: the scatter within the box (:func:`govopt.stats.truncated_normal`)
DISTRIBUTION = ("normal, each tolerance read as +-3 standard deviations and truncated at it "
                "(a part outside its tolerance is rejected)")
#: where each quantity's tolerance comes from
SOURCES = {"wire_diameter": "the wire's standard (EN 10270-1 or -2)",
           "coil_radius": "EN 15800 Table 1 (mean coil diameter +-A_D; the radius +-A_D / 2)",
           "free_half_length": "EN 15800 free length +-A_L0 = alpha_F k_F Q / R (spring "
                               "ordered by its free length), over spring_length_factor",
           "flying_mass": "requirements.robust_masses",
           "central_mass": "requirements.robust_masses",
           "dashpot": "requirements.robust_dashpot"}
NO_WIRE_STANDARD = ("no wire standard with tolerances for this material: wire diameter taken "
                    "exact")
UNKNOWN = {"coil_radius": "coil diameter or index outside EN 15800 Table 1: coil diameter "
                           "taken exact",
           "wire_diameter": "wire diameter outside its standard's table: taken exact",
           "free_half_length": "free length tolerance not defined there: taken exact"}
EXTENSION_FREE_LENGTH = ("free length (or initial tension) tolerance of an extension spring by "
                         "agreement with the maker (EN 15800 covers compression springs): not "
                         "included")


def kind(spec) -> str | None:
    """The spring kind of the spec's governor for the spring library: ``"compression"``,
    ``"extension"``, or None (no spring, or one that is not helical)."""
    sk = spec.governor.spring_kind
    if spec.governor.spring is None or sk is None or not sk.helical:
        return None
    return "compression" if spec.governor.spring == "compression" else "extension"


def spring_grade(spec, req=None) -> int | None:
    """The EN 15800 quality grade the spring of ``spec`` is made to: ``robust_spring_grade`` of
    ``req`` (default the spec's requirements), else the wire grade's ``material.tolerance_grade``
    where the spec names a wire grade and the spring is helical; None where it names none."""
    req = spec.requirements if req is None else req
    if req is not None and req.robust_spring_grade is not None:
        return int(req.robust_spring_grade)
    mat = spec.material
    if kind(spec) is not None and mat is not None and mat.grade is not None:
        return int(mat.tolerance_grade)
    return None


def wire_standard(spec) -> str | None:
    """The standard whose wire diameter tolerances apply (EN 10270-1 or -2), or None."""
    mat = spec.material
    return None if mat is None or mat.grade is None else tl.wire_standard(mat.grade)


def spring_tolerances(spec, grade: int, d, r, n):
    """The spring maker's tolerances of helical springs ``(d, r, n)`` (m, m, -; arrays) made to
    EN 15800 grade ``grade``: ``(d_tol, r_tol, l0_tol)``, +- m, on the wire diameter (its
    standard's, :func:`wire_standard`; 0 without one), the mean coil radius (``A_D / 2``, EN
    15800 Table 1; NaN outside the table) and the free length in the type's form (``A_L0`` of a
    compression spring over ``spring_length_factor``, with the rate from the spec's shear
    modulus; 0 for an extension spring).

    >>> from govopt.spec import load_spec
    >>> from govopt.examples import SPECS
    >>> spec = load_spec(SPECS / "hartnell-tolerances.toml")
    >>> [round(float(t) * 1e3, 3) for t in spring_tolerances(spec, 2, 4e-3, 18e-3, 9.0)]  # mm
    [0.03, 0.3, 2.968]
    """
    d, r, n = (np.asarray(v, dtype=float) for v in (d, r, n))
    D = 2.0 * r
    with np.errstate(invalid="ignore", divide="ignore"):
        r_tol = tl.coil_diameter_tolerance(D, D / d, grade) / 2.0
    std = wire_standard(spec)
    d_tol = tl.wire_diameter_tolerance(d, std) if std else np.zeros_like(d)
    if kind(spec) == "compression":
        rate = hx.stiffness(d, D, n, spec.material.shear_modulus)
        l0_tol = tl.free_length_tolerance(d, D, n, rate, grade) \
            / spec.governor.spring_length_factor
    else:
        l0_tol = np.zeros_like(d)
    zero = 0.0 * d
    return d_tol + zero, r_tol + zero, l0_tol + zero


def notes(spec, grade: int | None) -> list[str]:
    """What the box leaves out, in words."""
    out = []
    if grade is not None and kind(spec) is not None:
        if wire_standard(spec) is None:
            out.append(NO_WIRE_STANDARD)
        if kind(spec) != "compression":
            out.append(EXTENSION_FREE_LENGTH)
    return out


@dataclass
class Box:
    """Tolerance half-widths of designs (arrays, SI): ``fields`` maps a design field
    (:data:`FIELDS`) to its absolute half-width per design; ``torque`` is the engine's torque
    slope's relative half-width; ``grade`` the spring's EN 15800 grade (None: the spring
    exact); ``notes`` what the box leaves out."""

    fields: dict
    torque: float = 0.0
    grade: int | None = None
    notes: tuple[str, ...] = field(default_factory=tuple)

    def active(self) -> list[str]:
        """The toleranced design fields, in :data:`FIELDS` order."""
        return [k for k in FIELDS if k in self.fields and np.any(self.fields[k] > 0)]

    def dims(self) -> list[str]:
        """The box's toleranced quantities: :meth:`active`, then ``torque_slope``."""
        return self.active() + (["torque_slope"] if self.torque > 0 else [])

    def take(self, rows) -> Box:
        """The box of some of the designs (an index or a mask)."""
        return Box({k: np.asarray(v)[rows] for k, v in self.fields.items()}, self.torque,
                   self.grade, self.notes)

    def finite(self) -> np.ndarray:
        """Per design: every half-width is a number (inside the standards' tables)."""
        n = len(next(iter(self.fields.values()))) if self.fields else 0
        return np.all([np.isfinite(v) for v in self.fields.values()], axis=0) \
            if self.fields else np.ones(n, bool)

    def known(self) -> Box:
        """This box with a half-width outside the standards' tables (NaN: the coil or the index
        beyond EN 15800 Table 1) taken as exact, and a note saying so."""
        bad = [k for k, v in self.fields.items() if not np.all(np.isfinite(v))]
        if not bad:
            return self
        return Box({k: np.nan_to_num(v, nan=0.0) for k, v in self.fields.items()},
                   self.torque, self.grade, (*self.notes, *(UNKNOWN[k] for k in bad)))

    def half_widths(self, spec) -> dict:
        """The first design's half-widths as a JSON record, each key naming its SI unit."""
        gov = spec.governor
        damping = gov.key_unit("damping")
        names = {"wire_diameter": "wire_diameter_m", "coil_radius": "coil_radius_m",
                 "free_half_length": f"{gov.free_length_key}_m",
                 "flying_mass": f"{gov.mass_key}_mass_kg", "central_mass": "central_mass_kg",
                 "dashpot": f"dashpot_{damping}"}
        return {names[k]: float(self.fields[k][0]) for k in self.active()}


def box(spec, cols: dict, grade: int | None = None, masses: float = 0.0, dashpot: float = 0.0,
        torque: float = 0.0) -> Box:
    """The tolerance box of designs given as design columns ``cols`` (arrays, SI; each
    :class:`~govopt.inputs.Design` field): the spring made to EN 15800 grade ``grade``
    (:func:`spring_tolerances`; None: exact), the masses ``+-masses`` and the dash-pot
    ``+-dashpot`` (fractions), the torque slope ``+-torque``."""
    n = len(cols["flying_mass"])
    out = {}
    if grade is not None and kind(spec) is not None:
        d_tol, r_tol, l0_tol = spring_tolerances(spec, grade, cols["wire_diameter"],
                                                 cols["coil_radius"], cols["active_turns"])
        out.update(wire_diameter=d_tol, coil_radius=r_tol, free_half_length=l0_tol)
    if dashpot > 0:
        out["dashpot"] = dashpot * np.nan_to_num(cols["dashpot"])
    if masses > 0:
        out["flying_mass"] = masses * cols["flying_mass"]
        out["central_mass"] = masses * np.nan_to_num(cols["central_mass"])
    return Box({k: np.broadcast_to(v, (n,)).astype(float) for k, v in out.items()}, torque,
               grade if kind(spec) is not None else None, tuple(notes(spec, grade)))


def stated(spec, cols: dict, req=None) -> Box:
    """The box the spec states (``req``: its requirements, default the spec's): the spring's
    grade (:func:`spring_grade`) and the ``robust_*`` spreads."""
    req = spec.requirements if req is None else req
    return box(spec, cols, spring_grade(spec, req),
               0.0 if req is None else req.robust_masses,
               0.0 if req is None else req.robust_dashpot,
               0.0 if req is None else req.robust_torque_slope)


def states_tolerances(spec, req=None) -> bool:
    """Whether the spec states any tolerance of a made governor (a spring grade, or a spread of
    the masses, the dash-pot or the torque slope)."""
    req = spec.requirements if req is None else req
    return spring_grade(spec, req) is not None or (req is not None and (
        req.robust_masses > 0 or req.robust_dashpot > 0 or req.robust_torque_slope > 0))


def fitter_settings(nut: float, valve: float, count: int = 9):
    """The fitter's settings on assembly, tried least change first: ``(nut, valve)`` arrays over
    the grid of an adjusting nut's range ``+-nut`` (m, added to the free length) and the
    dash-pot valve's ``+-valve`` (a factor on the dash-pot, on a log scale), ``count`` settings
    of each (odd: the nominal setting, 0 and 1, first).

    >>> [round(float(v), 4) for v in fitter_settings(0.002, 0.0, 5)[0]]
    [0.0, -0.001, 0.001, -0.002, 0.002]
    """
    a = np.linspace(-nut, nut, count) if nut > 0 else np.zeros(1)
    half = count // 2 + 1  # each side of the nominal 1, on a log scale
    v = np.concatenate([np.geomspace(1.0 - valve, 1.0, half),
                        np.geomspace(1.0, 1.0 + valve, half)[1:]]) if valve > 0 else np.ones(1)
    a, v = (x.ravel() for x in np.meshgrid(a, v, indexing="ij"))
    change = (np.abs(a) / max(nut, 1e-300) + np.abs(np.log(v)) / max(math.log1p(valve), 1e-300))
    o = np.argsort(np.round(change, 12), kind="stable")
    return a[o], v[o]


def offsets(u: np.ndarray) -> np.ndarray:
    """Offsets in half-widths (-1 .. 1) at uniform fractions ``u`` of the unit cube: the
    model's scatter, :data:`DISTRIBUTION`."""
    from ..stats import truncated_normal

    return truncated_normal(u)


def corners(k: int) -> np.ndarray:
    """The ``2^k`` corners of a box of ``k`` quantities, in half-widths (``2^k x k``)."""
    return np.array(list(itertools.product((-1.0, 1.0), repeat=k)), dtype=float).reshape(
        2**k, k)


def at(cols: dict, bx: Box, points, i: int = 0) -> dict:
    """Design ``i`` of ``cols`` made at ``points`` of its box (``P x len(bx.active())``, in
    half-widths): design columns of ``P`` rows."""
    points = np.atleast_2d(np.asarray(points, dtype=float))
    rows = {f: np.repeat(np.asarray(v, dtype=float)[i:i + 1], len(points))
            for f, v in cols.items()}
    for j, name in enumerate(bx.active()):
        rows[name] = rows[name] + points[:, j] * bx.fields[name][i]
    return rows


def made_spring(spec, design: Design) -> tuple[float, float, float, float]:
    """A made governor's flying and central masses and its spring's rate and free length
    ``(m, central, kappa, l0)`` (SI): the rate from its section (the type's
    :meth:`~govopt.governors.base.Governor.spring_rate`) or as the design states it, the free
    length as made (a number: the design gives it)."""
    gov = spec.governor
    if gov.spring is None:
        return design.flying_mass, design.central_mass or 0.0, 0.0, 0.0
    kappa = design.spring_stiffness if design.spring_stiffness is not None else \
        gov.spring_rate(design, spec.material)
    return design.flying_mass, design.central_mass or 0.0, kappa, design.free_half_length


def speed_band(spec, cols: dict, bx: Box) -> dict:
    """The worst case of design 0's equilibrium speeds over its box, exact (at the corners: see
    the module's text), SI: per configuration its least and largest speed (``lowest_rad_s``,
    ``highest_rad_s``; the configurations ``x`` in the type's unit), their extremes at the
    inner and outer ends, and the governor's band with its friction (the lowest closing and
    highest opening speed over the range, :func:`govopt.analysis.statics.band_extremes`):
    ``band_rad_s``. The design's free length must be given (a made spring's is a number)."""
    x = statics.configurations(spec)
    pts = at(cols, bx, corners(len(bx.active())))
    gov = spec.governor
    lo = hi = fall = rise = None
    for i in range(len(pts["flying_mass"])):
        design = Design(**{f: (None if not np.isfinite(v[i]) else float(v[i]))
                           for f, v in pts.items()})
        m, central, kappa, l0 = made_spring(spec, design)
        t = statics.terms(spec, x, m, central)
        with np.errstate(invalid="ignore"):
            w = np.sqrt(t.omega_squared(kappa, l0))
            f2, r2 = statics.band_speeds_squared(t, kappa, l0, gov.friction(x, design))
            f1, r1 = statics.band_extremes(f2, r2)
        lo = w if lo is None else np.fmin(lo, w)
        hi = w if hi is None else np.fmax(hi, w)
        fall = f1 if fall is None else np.fmin(fall, f1)
        rise = r1 if rise is None else np.fmax(rise, r1)
    unit = "rad" if gov.coordinate == "angle" else "m"
    return {f"configuration_{unit}": x.tolist(), "lowest_rad_s": lo.tolist(),
            "highest_rad_s": hi.tolist(),
            "inner_rad_s": [float(lo[0]), float(hi[0])],
            "outer_rad_s": [float(lo[-1]), float(hi[-1])],
            "band_rad_s": [float(fall), float(rise)]}


def speed_band_each(spec, cols: dict, bx: Box) -> dict[str, list[float]]:
    """Per toleranced quantity of design 0, the worst case of its speed band (with friction,
    ``band_rad_s`` of :func:`speed_band`) over that quantity's tolerance alone: which
    tolerance spreads the speeds most."""
    out = {}
    for name in bx.active():
        one = Box({k: (v if k == name else np.zeros_like(v)) for k, v in bx.fields.items()})
        out[name] = speed_band(spec, cols, one)["band_rad_s"]
    return out


__all__ = ["DISTRIBUTION", "FIELDS", "SOURCES", "Box", "at", "box", "corners",
           "fitter_settings", "kind", "made_spring", "notes", "offsets", "speed_band",
           "speed_band_each", "spring_grade", "spring_tolerances", "states_tolerances", "stated",
           "wire_standard"]
