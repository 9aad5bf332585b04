"""The design search's screens of candidate governor springs on the mechanism's own loads (SI).

Over arrays of catalogue springs, before a design is evaluated: the allowable stress as a
monomial in the wire diameter for the spring GP (:func:`allowable_monomial`), the spring
engineering checks (:func:`screen`), the compression spring's geometry (:func:`geometry_screen`),
fatigue (:func:`screen_fatigue`) and the surge frequency against the forcing
(:func:`screen_vibration`). The rules are those of :mod:`govopt.analysis.spring_engineering`,
which checks and reports one design.
"""

from __future__ import annotations

import math

import numpy as np

from ..springs import materials as mt
from . import statics
from .spring_engineering import (
    KINDS,
    fatigue_safety,
    feasible,
    geometry_rows,
    static_range,
    wire,
)


def allowable_monomial(spec, d_lo: float, d_hi: float) -> tuple[float, float]:
    """``(k, m)``: the static allowable is at most ``k d^-m`` (Pa, ``d`` in m) on the wires.

    The spec's explicit allowable (``m = 0``), else the grade's rule ``fraction R_m(d)`` fitted
    by least squares in ``lg R_m`` against ``lg d`` (R_m falls with ``d`` as a near power law:
    Shigley Table 10-4's ``A / d^m``), then raised until it lies above the rule at 513
    log-spaced wires and the table's nodes (a step table's row ends). A monomial keeps the
    spring GP a GP; lying above makes it a relaxation (its optimum a lower bound). govopt's own
    construction on Shigley's law.

    Parameters
    ----------
    spec : Spec [-]
        Its ``[material]`` and governor (the spring kind).
    d_lo : float [m]
        Thinnest wire.
    d_hi : float [m]
        Thickest wire.

    Returns
    -------
    tuple of float
        ``(k [Pa m^m], m [-])``.

    References
    ----------
    [shigley] 9th ed. Table 10-4; [en13906-1] (the allowable as a fraction of R_m).

    Examples
    --------
    Hamabe's spec gives k_s = 4000 kgf/cm^2 explicitly: by hand ``4000 x 9.80665e4 =
    392.266 MPa``, independent of ``d``.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> allowable_monomial(spec, 0.005, 0.02)
    (392266000.0, 0.0)
    """
    m_, kind = spec.material, KINDS[spec.governor.spring]
    if m_.allowable_shear_stress is not None:
        return float(m_.allowable_shear_stress), 0.0
    mat = wire(m_)
    d = np.geomspace(d_lo, d_hi, 513)
    nodes = mat.rm_nodes  # a table's nodes, a step table's row ends: where R_m d^m peaks
    d = np.union1d(d, nodes[(nodes > d_lo) & (nodes < d_hi)])
    allow = mt.allowable_static_stress(mat, d, kind, m_.rules)
    ok = np.isfinite(allow) & (allow > 0)
    if not np.any(ok):
        return math.nan, 0.0
    d, allow = d[ok], allow[ok]
    m = -np.polyfit(np.log(d), np.log(allow), 1)[0] if d.size > 1 else 0.0
    return float(np.max(allow * d**m) * (1.0 + 1e-9)), float(m)


def screen_vibration(spec, req):
    """The type's forced vibration for a representative flying mass, or None.

    The middle of the flying mass's bounds, when the spec has an engine (as
    :func:`govopt.evaluate` computes it); None without. Only the harmonics' presence is read from
    it (the forcing does not involve the spring).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speed, engine and forcing.
    req : Requirements [-]
        The design bounds (``flying_mass`` in kg).

    Returns
    -------
    VibrationResult or None [-]
        Harmonic moments in N m, ``omega0`` in rad/s.

    References
    ----------
    [hamabe] Part II, eq. (14).

    Examples
    --------
    Hamabe's valve gear (the pendulum bounded to 4-16 kg), 12 harmonics at omega0 = 240 rpm:

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> fat = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> vib = screen_vibration(fat, fat.requirements)
    >>> round(vib.omega0, 4), len(vib.harmonics)
    (25.1327, 12)
    """
    if spec.engine is None or spec.speed is None:
        return None
    gov = spec.governor
    m = 0.5 * (req.flying_mass[0] + req.flying_mass[1])
    sd = statics.SpringDesign(m, float(gov.inertia(gov.x_normal, m)), 0.0, 0.0)
    return gov.vibration(spec, sd, 0.5 * spec.speed.omega_mean**2, 0.0)


def screen(spec, d, r, n, kappa, l0, harmonics=()):
    """The static table over catalogue springs (arrays): True where every row holds.

    :func:`feasible` at the static range :func:`static_range` of each spring.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]`` and ``[spring]``.
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius.
    n : float or array [-]
        Active coils (dimensionless).
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form.
    harmonics : tuple of float [Hz], optional
        The forcing's harmonics present.

    Returns
    -------
    array of bool [-]
        One per spring.

    References
    ----------
    [shigley] 9th ed. sections 10-9, 10-11; [en13906-1].

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    As :func:`feasible`: it does not fit between its attachments with loops.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> screen(spec, np.array([sd.d]), np.array([sd.r]), np.array([sd.n]), np.array([sd.kappa]),
    ...        np.array([sd.l0])).tolist()
    [False]
    """
    F1, F2 = static_range(spec, kappa, l0)
    return feasible(spec, d, 2.0 * r, n, kappa, l0, F1, F2, harmonics)


def geometry_screen(spec, d, r, n, kappa, l0):
    """True where every row of :func:`geometry_rows` holds (catalogue springs, arrays).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]`` and ``[spring]``.
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius.
    n : float or array [-]
        Active coils (dimensionless).
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form.

    Returns
    -------
    array of bool [-]
        One per spring.

    References
    ----------
    [en13906-1] clause 9.14 (buckling), the least working length.

    Examples
    --------
    A Hartnell governor's compression spring (the bundled ``hartnell-design`` spec, no wire
    grade) of 3 mm wire, D 40 mm, 8 active coils, closed ends (10 in all), free length 209.7 mm,
    working between 180.9 and 230.3 N at 1648 N/m.
    It buckles (:func:`geometry_table`), so it fails the screen:

    >>> import tomllib
    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> data = tomllib.loads(example("hartnell-design").read_text(encoding="utf-8"))
    >>> data["design"] = {"ball_weight": "2 kgf", "wire_diameter": "3 mm", "coil_radius": "2 cm",
    ...                   "active_turns": 8}
    >>> spec = govopt.parse_spec(data, "hartnell")
    >>> sd = statics.spring_design(spec)
    >>> bool(geometry_screen(spec, sd.d, sd.r, sd.n, sd.kappa, sd.l0))
    False
    """
    ok = True
    for value, limit, sense in geometry_rows(spec, d, 2.0 * r, n, kappa, l0).values():
        ok = ok & (value <= limit if sense == "<=" else value >= limit)
    return np.asarray(ok)


def screen_fatigue(spec, d, r, n, kappa, l0, swing):
    """The least fatigue safety factor, dimensionless, of candidate springs under swings ``swing``.

    The load cycle ``F(x_normal -+ swing / 2)`` (:func:`fatigue_forces`) for every candidate and
    dash-pot, then :func:`fatigue_safety`.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]`` and ``[spring]``.
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius.
    n : float or array [-]
        Active coils (dimensionless).
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form.
    swing : array [rad] or [m]
        Peak-to-peak vibration, candidates x dash-pots.

    Returns
    -------
    array [-]
        Candidates x dash-pots (dimensionless).

    References
    ----------
    [hamabe] Part II; [en13906-1]; [shigley] 9th ed. sections 10-9, 10-11.

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    The same number as :func:`fatigue_safety` on the cycle of a 0.02 rad swing:

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> one = screen_fatigue(spec, np.array([sd.d]), np.array([sd.r]), np.array([sd.n]),
    ...                      np.array([sd.kappa]), np.array([sd.l0]), np.array([[0.02]]))
    >>> F1, F2 = static_range(spec, sd.kappa, sd.l0)
    >>> from govopt.analysis.spring_engineering import fatigue_forces
    >>> lo, hi = fatigue_forces(spec, sd, 0.02)
    >>> two = fatigue_safety(spec, sd.d, 2 * sd.r, sd.n, sd.kappa, sd.l0, F1, F2, lo, hi)
    >>> bool(np.isclose(one[0, 0], two, rtol=1e-9))
    True
    """
    def col(v):
        return np.asarray(v, dtype=float)[:, None]

    F1, F2 = static_range(spec, kappa, l0)
    x = spec.governor.x_normal + 0.5 * np.stack([-swing, swing])
    F = statics.spring_force(spec, x, col(kappa), col(l0))
    return fatigue_safety(spec, col(d), 2.0 * col(r), col(n), col(kappa), col(l0), col(F1),
                          col(F2), np.min(F, axis=0), np.max(F, axis=0))
