"""Spring engineering of a governor's helical spring on the mechanism's own loads.

The rules live in :mod:`govopt.springs` (materials, helical geometry, fatigue, EN 15800
tolerances, the constraint tables); this module feeds them a governor's loads and geometry, for
one design (:func:`checks`, :func:`report`) and over arrays of catalogue springs (the optimiser's
screen: :func:`feasible`, :func:`fatigue_safety`). It runs for a spec whose ``[material]``
names a wire ``grade``; the spring maker's sheet and the tolerance spread are reported for every
helical design.

How the governor's numbers become the library's (SI; ``d`` wire, ``D = 2 r`` mean coil
diameter, ``n`` active coils, ``kappa`` rate, ``l0`` the type's free length):

* **static range**: the least and largest spring force over the configuration range,
  ``F1 <= F2`` (the characteristic's ``F = kappa (A_F - B_F l0)``);
* **compression spring** (Hartnell, spring-and-gravity, traction coil, a Porter's auxiliary
  spring): free length ``L0 = spring_length_factor l0``, total coils ``n_t = n +
  inactive_turns`` (closed ends: 2, EN 13906-1), largest deflection ``s_max = (F2 + overtravel
  (F2 - F1)) / kappa``: full lift plus the overspeed margin as a fraction of the working stroke;
* **extension spring** (the shaft governor's, the spring-loaded governor's): body coils
  ``n_b = n - G/E`` (the two loops add ``G/E`` coil, Shigley 9th ed. §10-11); initial tension
  ``F0`` as given, else the middle of Shigley's preferred range (eq. (10-40)) but at most
  ``F1`` (the spring must open over the whole range); and the spring with two full loops, closed,
  must fit between its attachments: ``2 (D - d) + (n_b + 1) d <= L_v + F0 / kappa`` with
  ``L_v = spring_length_factor l0`` the attachments' distance where the linear law
  ``F = kappa (L - L_v)`` gives no force;
* **fatigue** from the type's own periodic forcing (:meth:`Governor.vibration`: the shaft
  governor's valve gear, Hamabe Part II, with the dash-pot): the spring force at
  ``x_normal -+ peak_to_peak / 2`` (the mean offset of the swing, Hamabe's ``L``, is neglected:
  ~1e-16 rad for the bundled design) gives the least and largest force of the load cycle; a
  type without a modelled forcing says "no periodic forcing modelled: fatigue not checked";
* **surge**: the spring's surge frequency kept ``requirements.surge_detuning`` (relative) clear
  of each harmonic ``k omega0`` of that forcing whose moment is present (above
  :data:`PRESENT_RTOL` of the largest; for the vertical engine the odd orders above 1 vanish).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from ..springs import checks as ck
from ..springs import extension as he
from ..springs import fatigue as ft
from ..springs import helical as hx
from ..springs import materials as mt
from ..springs import sheet as sh
from ..verdict import Check, Figure
from . import statics

#: ``Governor.spring`` -> the library's spring kind.
KINDS = {"tension": "extension", "compression": "compression"}
#: A forcing harmonic whose moment is below this fraction of the largest is rounding: absent.
PRESENT_RTOL = 1e-9
NO_FORCING = "no periodic forcing modelled: fatigue not checked"
FITS = "extension spring fits between its attachments"


def wire(material) -> mt.Material:
    """The spec's ``[material]`` as a wire grade (a :class:`~govopt.springs.materials.Material`).

    The grade with the spec's explicit G, density and R_m; without a grade a stand-in carrying G
    and density only (no R_m).

    Parameters
    ----------
    material : Material [-]
        The spec's ``[material]`` (moduli in Pa, density in kg/m^3).

    Returns
    -------
    Material [-]
        R_m(d) in Pa for ``d`` in m, the moduli in Pa.

    References
    ----------
    [en10270-1] (grade DH: R_m = 2220 - 820 lg(d/mm) MPa, the data file's fit).

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    By hand ``2220 - 820 lg 17 = 1211.0 MPa``; G is Hamabe's 850000 kgf/cm^2 = 83.36 GPa.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> mat = wire(spec.material)
    >>> mat.grade, round(float(mat.tensile_strength(0.017)) / 1e6, 1)
    ('EN10270-1 DH', 1211.0)
    >>> round(float(mat.shear_modulus(0.017)) / 1e9, 2)
    83.36
    """
    if material.grade is None:
        return replace(mt.given(material.shear_modulus, material.density),
                       grade="as specified (no wire grade)",
                       standard="shear modulus and allowable stress given in the spec")
    return mt.material(material.grade, tensile_strength=material.tensile_strength,
                       G=material.shear_modulus, density=material.density)


def harmonics_hz(vib) -> tuple[float, ...]:
    """Frequencies ``k omega0 / 2 pi``, Hz, of the forcing harmonics present in ``vib``.

    Orders up to ``analysis.harmonics``; a harmonic whose moment is below :data:`PRESENT_RTOL` of
    the largest is absent (Hamabe Part II: for the vertical engine the odd orders above the first
    vanish).

    Parameters
    ----------
    vib : VibrationResult [-]
        The forced vibration (its ``omega0`` in rad/s, harmonic moments in N m); None: none.

    Returns
    -------
    tuple of float [Hz]
        The present harmonics' frequencies.

    References
    ----------
    [hamabe] Part II, eq. (14).

    Examples
    --------
    Hamabe's valve gear on the vertical engine at 240 rpm (4 Hz): orders 1, 2, 4, ..., 12.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> fat = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> vib = screen_vibration(fat, fat.requirements)
    >>> [round(f, 9) for f in harmonics_hz(vib)]
    [4.0, 8.0, 16.0, 24.0, 32.0, 40.0, 48.0]
    """
    if vib is None:
        return ()
    moments = np.array([math.hypot(h["moment_cos_N_m"], h["moment_sin_N_m"])
                        for h in vib.harmonics])
    if moments.size == 0 or not np.max(moments) > 0:
        return ()
    keep = moments > PRESENT_RTOL * np.max(moments)
    return tuple(h["order"] * vib.omega0 / (2.0 * math.pi)
                 for h, k in zip(vib.harmonics, keep, strict=True) if k)


def fatigue_forces(spec, sd, swing: float):
    """Least and largest spring force, N, of the load cycle: ``F(x_normal -+ swing / 2)``.

    The forced vibration about the normal configuration (Hamabe Part II) swings the spring
    between these (the swing's mean offset, Hamabe's ``L``, neglected).

    Parameters
    ----------
    spec : Spec [-]
        The governor.
    sd : SpringDesign [-]
        The design (stiffness in N/m, free length in m).
    swing : float [rad] or [m]
        Peak-to-peak vibration, in the coordinate's unit.

    Returns
    -------
    tuple of float [N]
        ``(F_lo, F_hi)``.

    References
    ----------
    [hamabe] Part I, eq. (2); Part II (the forced vibration).

    Examples
    --------
    Hamabe's Example 1 (a): with no swing both are F_n (the paper prints 508 kgf; 509 with
    omega0 = 240 rpm exactly); a 0.02 rad swing moves them by about
    ``2 kappa h_n x 0.01 = 2 x 62952 x 0.02882 x 0.01 = 36.3 N`` either side.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> [round(f / KGF) for f in fatigue_forces(spec, sd, 0.0)]
    [509, 509]
    >>> [round(f, 1) for f in fatigue_forces(spec, sd, 0.02)]
    [4958.9, 5031.4]
    """
    x = spec.governor.x_normal + np.array([-0.5, 0.5]) * swing
    F = statics.spring_force(spec, x, sd.kappa, sd.l0)
    return float(np.min(F)), float(np.max(F))


def initial_tension(spec, d, D, F1):
    """An extension spring's initial tension, N.

    ``[spring] initial_tension`` where the spec gives it, else the middle of Shigley's preferred
    range (eq. (10-40), uncorrected stress) at the index ``D/d``, at most the least working force
    ``F1`` (the spring must open over the whole range).

    Parameters
    ----------
    spec : Spec [-]
        Its ``[spring]`` form.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    F1 : float or array [N]
        Least working force.

    Returns
    -------
    float or array [N]
        The initial tension ``F0``.

    References
    ----------
    [shigley] 9th ed. section 10-11, eq. (10-40).

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    At the index 12/1.7 = 7.06 the preferred range is 86.8 to 133.3 MPa; by hand its middle,
    110.07 MPa, is ``110.07e6 x pi 0.017^3 / (8 x 0.12) = 1770 N``, below F1 = 4114 N.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> round(float(initial_tension(spec, 0.017, 0.12, 4114.0)))
    1770
    """
    if spec.spring_form.initial_tension is not None:
        return spec.spring_form.initial_tension + 0.0 * np.asarray(F1, dtype=float)
    lo, hi = he.initial_tension_range(hx.spring_index(d, D))
    return np.minimum(hx.force_at_stress(0.5 * (lo + hi), d, D), F1)


def _kw(spec, d, D, n, kappa, l0, F1, F2, harmonics=()) -> dict:
    """The library's keywords (:mod:`govopt.springs.checks`) for the spec's spring."""
    m, form, req = spec.material, spec.spring_form, spec.requirements
    mat = wire(m)
    kw = dict(mat=mat, d=d, D=D, F1=F1, F2=F2, method=m.rules, allowable=m.allowable_shear_stress,
              correction=m.stress_correction, peened=m.surface == "shot peened",
              cycles=m.life_cycles, harmonics_hz=tuple(harmonics))
    if req is not None:
        kw.update(index_min=req.spring_index[0], index_max=req.spring_index[1],
                  detuning=req.surge_detuning,
                  fatigue_safety=1.0 if req.min_fatigue_safety is None
                  else req.min_fatigue_safety)
    L = spec.governor.spring_length_factor * np.asarray(l0, dtype=float)
    if KINDS[spec.governor.spring] == "compression":
        s_max = (F2 + form.overtravel * (F2 - F1)) / kappa
        kw.update(n=n, n_t=n + form.inactive_turns, L0=L, ends=form.ends, seating=form.seating,
                  s_max=s_max)
    else:
        kw.update(n_body=n - mat.shear_modulus(d) / mat.elastic_modulus(d),
                  F0=initial_tension(spec, d, D, F1), r2=form.hook_bend_radius,
                  L_v=L, kappa=kappa)
    return kw


def _static(name: str, spec) -> bool:
    """Rows of the static table (fatigue comes from the vibration; the spring index rows from
    the requirements, when the spec has them)."""
    if "fatigue" in name:
        return False
    return spec.requirements is None or not name.startswith("spring index")


def _fits(kw):
    """``(value, limit)`` of :data:`FITS`: the closed spring with its loops, and the
    attachments' distance at the initial tension."""
    return (he.extension_free_length(kw["d"], kw["D"], kw["n_body"]),
            kw["L_v"] + kw["F0"] / kw["kappa"])


FITS_SOURCE = ("Shigley 9th ed. §10-11: free length inside two full loops 2 (D - d) + "
               "(N_b + 1) d, at most the attachments' distance where the spring opens, "
               "L_v + F0 / kappa (the linear law F = kappa (L - L_v))")


def evaluate_rows(spec, d, D, n, kappa, l0, F1, F2, harmonics=()) -> dict:
    """Every static row over arrays (the optimiser's screen): ``{name: (value, limit, sense)}``.

    The spring kind's static table (:mod:`govopt.springs.checks`: stresses, initial tension,
    index) and, for an extension spring, the fit between its attachments (Shigley 9th ed.
    section 10-11: ``2 (D - d) + (n_b + 1) d <= L_v + F0 / kappa``).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]``, ``[spring]`` and requirements.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter (``2 r``).
    n : float or array [-]
        Active coils (dimensionless).
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form (the shaft governor: half the spring's length).
    F1 : float or array [N]
        Least working force of the static range.
    F2 : float or array [N]
        Largest working force.
    harmonics : tuple of float [Hz], optional
        The forcing's harmonics present (for the surge row).

    Returns
    -------
    dict [-]
        Row name -> ``(value, limit, sense)`` in the row's SI unit (Pa, N, m).

    References
    ----------
    [shigley] 9th ed. sections 10-9, 10-11; [en13906-1].

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    Closed with two full loops it would be ``2 (0.12 - 0.017) + (8 - G/E + 1) 0.017 = 0.352 m``
    long, more than the attachments' ``2 l0 + F0 / kappa = 0.2594 + 0.0281 = 0.2875 m``: as a
    close-coiled extension spring with loops, Hamabe's spring does not fit.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> F1, F2 = static_range(spec, sd.kappa, sd.l0)
    >>> rows = evaluate_rows(spec, sd.d, 2 * sd.r, sd.n, sd.kappa, sd.l0, F1, F2)
    >>> value, limit, sense = rows[FITS]
    >>> round(float(value), 4), round(float(limit), 4), sense
    (0.3521, 0.2875, '<=')
    """
    kind = KINDS[spec.governor.spring]
    kw = _kw(spec, d, D, n, kappa, l0, F1, F2, harmonics)
    senses = {r.name: r.sense for r in ck.TABLES[kind]}
    rows = {k: (v, lim, senses[k]) for k, (v, lim) in ck.evaluate(kind, **kw).items()
            if _static(k, spec)}
    if kind == "extension":
        full = ck.prepare(kind, **kw)
        rows[FITS] = (*_fits(full), "<=")
    return rows


def feasible(spec, d, D, n, kappa, l0, F1, F2, harmonics=()):
    """True where every static row of :func:`evaluate_rows` holds (arrays broadcast; NaN fails).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]``, ``[spring]`` and requirements.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter (``2 r``).
    n : float or array [-]
        Active coils (dimensionless).
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form (the shaft governor: half the spring's length).
    F1 : float or array [N]
        Least working force of the static range.
    F2 : float or array [N]
        Largest working force.
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
    It fails on the fit between its attachments alone (:func:`evaluate_rows`).

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> F1, F2 = static_range(spec, sd.kappa, sd.l0)
    >>> bool(feasible(spec, sd.d, 2 * sd.r, sd.n, sd.kappa, sd.l0, F1, F2))
    False
    """
    ok = True
    for value, limit, sense in evaluate_rows(spec, d, D, n, kappa, l0, F1, F2,
                                             harmonics).values():
        ok = ok & (value <= limit if sense == "<=" else value >= limit)
    return np.asarray(ok)


def fatigue_safety(spec, d, D, n, kappa, l0, F1, F2, F_lo, F_hi):
    """The least fatigue safety factor, dimensionless, for the load cycle ``F_lo .. F_hi``.

    Over the body and, for an extension spring, the hooks (the library's fatigue rows:
    EN 13906-1's Goodman diagram of the grade, Shigley's hook points A and B), over arrays.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]``, ``[spring]`` and requirements.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter (``2 r``).
    n : float or array [-]
        Active coils (dimensionless).
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form (the shaft governor: half the spring's length).
    F1 : float or array [N]
        Least working force of the static range.
    F2 : float or array [N]
        Largest working force.
    F_lo : float or array [N]
        Least force of the load cycle.
    F_hi : float or array [N]
        Largest force of the load cycle.

    Returns
    -------
    array [-]
        The least safety factor (dimensionless).

    References
    ----------
    [en13906-1] (fatigue diagram); [shigley] 9th ed. sections 10-9, 10-11.

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    A wider cycle about the same mean force is less safe:

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> F1, F2 = static_range(spec, sd.kappa, sd.l0)
    >>> def safety(lo, hi):
    ...     return float(fatigue_safety(spec, sd.d, 2 * sd.r, sd.n, sd.kappa, sd.l0, F1, F2,
    ...                                 lo, hi))
    >>> safety(4900.0, 5100.0) < safety(4950.0, 5050.0)
    True
    """
    kind = KINDS[spec.governor.spring]
    kw = _kw(spec, d, D, n, kappa, l0, F1, F2)
    kw.update(F1=F_lo, F2=F_hi)
    values = [v for k, (v, _) in ck.evaluate(kind, **kw).items() if "fatigue" in k]
    return np.minimum.reduce(np.broadcast_arrays(*values))


def _static_range(char):
    F = np.asarray(char.spring_force, dtype=float)
    return float(np.min(F)), float(np.max(F))


def checks(spec, sd, char, vib=None) -> list:
    """The spring engineering checks of one design (:class:`govopt.verdict.Check`, SI).

    The static table, an extension spring's fit, and the fatigue rows under the forcing's load
    cycle ``F(x_normal -+ peak-to-peak / 2)`` (Hamabe Part II, with the dash-pot) where ``vib``
    is given.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]``, ``[spring]`` and requirements.
    sd : SpringDesign [-]
        The design (wire and coil in m, turns dimensionless, rate in N/m).
    char : Characteristic [-]
        Its statics (:func:`statics.characteristic`; spring force in N).
    vib : VibrationResult [-], optional
        The forced vibration (peak-to-peak in rad or m); None: no fatigue rows.

    Returns
    -------
    list of Check [-]
        Value and limit in each row's SI unit.

    References
    ----------
    [shigley] 9th ed. sections 10-9, 10-11; [en13906-1]; [hamabe] Part II.

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    The body's uncorrected stress ``8 F2 D / (pi d^3) = 8 x 5992.5 x 0.12 / (pi 0.017^3) =
    372.7 MPa`` is within k_s = 392.3 MPa; only the fit fails.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> cs = checks(spec, sd, statics.characteristic(spec, sd))
    >>> round(cs[0].value / 1e6, 1), round(cs[0].limit / 1e6, 1), cs[0].name
    (372.7, 392.3, 'body static shear stress')
    >>> [c.name for c in cs if not c.passed]
    ['extension spring fits between its attachments']
    """
    kind = KINDS[spec.governor.spring]
    d, D, n = sd.d, 2.0 * sd.r, sd.n
    F1, F2 = _static_range(char)
    kw = _kw(spec, d, D, n, sd.kappa, sd.l0, F1, F2, harmonics_hz(vib))
    out = [c for c in ck.checks(kind, **kw) if _static(c.name, spec)]
    if kind == "extension":
        value, limit = _fits(ck.prepare(kind, **kw))
        out.append(Check(FITS, float(value), float(limit), "<=", "m", FITS_SOURCE, group="spring"))
    if vib is None:
        return out
    swing = float(vib.peak_to_peak_rad)
    if math.isfinite(swing):
        kw.update(zip(("F1", "F2"), fatigue_forces(spec, sd, swing), strict=True))
        rows = [c for c in ck.checks(kind, **kw) if "fatigue" in c.name]
    else:  # an undamped resonance: the swing and the stresses are unbounded
        rows = [replace(c, value=0.0, source=c.source + "; infinite swing (undamped resonance)")
                for c in ck.checks(kind, **kw) if "fatigue" in c.name]
    tail = ("; load cycle F(x_normal -+ peak-to-peak / 2) from the forced vibration "
            "(Hamabe Part II, with the dash-pot)")
    return out + [replace(c, source=c.source + tail) for c in rows]


# ---------------------------------------------------------------- tolerances

@dataclass(frozen=True)
class Spread:
    """Manufacturing spread of a helical spring in a governor (SI): wire and coil diameter
    tolerances ``d_tol``, ``D_tol`` (+-), the rate's worst-case range, the free length's
    tolerance ``l0_tol`` in the type's form, and the governed speed range's spread."""

    d_tol: float
    D_tol: float
    kappa: tuple[float, float]
    l0_tol: float
    omega_inner: tuple[float, float]
    omega_outer: tuple[float, float]
    notes: tuple[str, ...] = ()

    def sample(self, sd, rng, size: int):
        """Monte-Carlo draws ``(kappa, l0)`` (arrays of ``size``): wire and coil diameter
        uniform within their tolerances (the rate ``~ d^4 / D^3`` follows) and the free length
        uniform within its tolerance - for the studies."""
        d = sd.d + self.d_tol * rng.uniform(-1.0, 1.0, size)
        D = 2.0 * sd.r + self.D_tol * rng.uniform(-1.0, 1.0, size)
        kappa = sd.kappa * (d / sd.d) ** 4 * (2.0 * sd.r / D) ** 3
        return kappa, sd.l0 + self.l0_tol * rng.uniform(-1.0, 1.0, size)

    def figures(self) -> dict:
        """The spread as a record of figures (:func:`govopt.springs.sheet.record_json`)."""
        return {f.name: f for f in (
            Figure("wire diameter tolerance", self.d_tol, "m"),
            Figure("coil diameter tolerance", self.D_tol, "m"),
            Figure("stiffness range", list(self.kappa), "N/m"),
            Figure("free length tolerance", self.l0_tol, "m"),
            Figure("omega inner range", list(self.omega_inner), "rad/s"),
            Figure("omega outer range", list(self.omega_outer), "rad/s"))} | {
            "notes": list(self.notes)}

    def to_dict(self) -> dict:
        return sh.record_json(self.figures())


def spread(spec, sd, sheet: sh.SpringSheet) -> Spread:
    """The spring's spread under the tolerance model of a made governor (a :class:`Spread`, SI).

    At the sheet's EN 15800 grade (:mod:`govopt.analysis.tolerance`): the wire (EN 10270), coil
    diameter (EN 15800 Table 1) and free length (EN 15800 ``A_L0`` of a compression spring)
    tolerances, the rate's range over them, and the equilibrium speeds' worst case at both ends
    of the range (at the box's corners, exact: :func:`govopt.analysis.tolerance.speed_band`): the
    spread of the governed speed range.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds and ``[material]``.
    sd : SpringDesign [-]
        The design (m, kg, N/m).
    sheet : SpringSheet [-]
        The spring maker's sheet (its tolerance grade).

    Returns
    -------
    Spread [-]
        Tolerances in m, rates in N/m, speeds in rad/s.

    References
    ----------
    [en15800] Table 1; [en10270-1]; [hamabe] Part I, eqs. (2), (12).

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    EN 10270-1: d = 17 mm +- 0.090 mm (row to 18 mm); EN 15800 grade 2, D = 120 mm (row to
    125 mm), w = 7.06 (4-8): +- 1.40 mm, so the rate lies in ``kappa (d -+ A_d)^4 / d^4 x
    D^3 / (D +- A_D)^3`` = 59.5 to 66.6 kN/m about its 62.95 kN/m.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> rep = report(spec, sd, statics.characteristic(spec, sd))
    >>> sp = spread(spec, sd, rep.sheet)
    >>> round(sp.d_tol * 1e3, 3), round(sp.D_tol * 1e3, 2)
    (0.09, 1.4)
    >>> [round(k / 1e3, 1) for k in sp.kappa]
    [59.5, 66.6]
    """
    from . import tolerance as tm

    cols = {"flying_mass": np.array([sd.m]), "wire_diameter": np.array([sd.d]),
            "coil_radius": np.array([sd.r]), "active_turns": np.array([sd.n]),
            "free_half_length": np.array([sd.l0]), "central_mass": np.array([sd.central]),
            "flying_inertia": np.array([sd.inertia if sd.inertia_given else np.nan])}
    bx = tm.box(spec, cols, sheet.tolerance_grade).known()
    half = {k: float(bx.fields[k][0]) for k in ("wire_diameter", "coil_radius",
                                                  "free_half_length")}
    d = sd.d + np.array([-1.0, 1.0]) * half["wire_diameter"]
    r = sd.r - np.array([-1.0, 1.0]) * half["coil_radius"]
    kappa = hx.stiffness_r(d, r, sd.n, spec.material.shear_modulus)
    band = tm.speed_band(spec, cols, bx)
    return Spread(half["wire_diameter"], 2.0 * half["coil_radius"],
                  (float(kappa[0]), float(kappa[1])), half["free_half_length"],
                  tuple(band["inner_rad_s"]), tuple(band["outer_rad_s"]), bx.notes)


# ---------------------------------------------------------------- the report

@dataclass
class SpringReport:
    """The spring maker's sheet and the engineering figures of one governor spring (SI):
    ``material`` and ``loads`` are records (:func:`govopt.springs.sheet.record_json`) whose
    numbers are :class:`~govopt.verdict.Figure` keyed by name (``loads["force min"]``,
    ``loads["fatigue"]["corrected stress max"]``, each with its unit as a field)."""

    kind: str
    sheet: sh.SpringSheet
    material: dict
    loads: dict
    spread: Spread
    notes: list[str] = field(default_factory=list)

    def record(self) -> dict:
        """The whole report as one record: what the Spring sheet lists, row by row
        (:func:`govopt.springs.sheet.record_rows`), and the JSON writes (:meth:`to_dict`)."""
        return {"kind": self.kind, "sheet": self.sheet.figures(), "material": self.material,
                "loads": self.loads, "tolerance_spread": self.spread.figures(),
                "notes": list(self.notes)}

    def to_dict(self) -> dict:
        return sh.record_json(self.record())


def hook_cycles(mat, d, D, F_lo, F_hi, r2=None, r1=None,
                criterion: str = ck.DEFAULTS["criterion"]) -> dict:
    """The fatigue cycle of an extension spring's hooks between the forces ``F_lo`` and ``F_hi``.

    As the hook checks read it (:mod:`govopt.springs.checks`: Shigley section 10-11, hooks taken
    unpeened; ``r1`` default ``D/2``, ``r2`` default ``2 d``): for point A (bending, Shigley
    Example 10-7: ``S_e = S_se / 0.577`` with the tensile ``S_ut``) and point B (torsion,
    ``S_se`` with ``S_su = 0.67 S_ut``) the midrange and amplitude stresses and the line's
    intercepts (``endurance`` on the amplitude axis, ``ultimate`` on the midrange axis), Pa; the
    safety factor is where the load line through the cycle meets the line.

    Parameters
    ----------
    mat : Material [-]
        The wire (R_m in Pa).
    d : float [m]
        Wire diameter.
    D : float [m]
        Mean coil diameter.
    F_lo : float [N]
        Least force of the cycle.
    F_hi : float [N]
        Largest force of the cycle.
    r2 : float [m], optional
        Bend radius where the hook leaves the body.
    r1 : float [m], optional
        The hook's mean radius.
    criterion : str [-], optional
        The fatigue line (dimensionless name: ``"goodman"`` ...).

    Returns
    -------
    dict [-]
        ``criterion``, ``source`` and points ``A`` and ``B`` of :class:`Figure` in Pa.

    References
    ----------
    [shigley] 9th ed. section 10-11 and Example 10-7.

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    The stresses are linear in the force, so amplitude over midrange is
    ``(F_hi - F_lo) / (F_hi + F_lo) = 200 / 10000``:

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> A = hook_cycles(wire(spec.material), 0.017, 0.12, 4900.0, 5100.0)["A"]
    >>> round(A["amplitude"].value / A["midrange"].value, 6), A["stress"]
    (0.02, 'bending')
    """
    r1 = D / 2.0 if r1 is None else r1
    r2 = 2.0 * d if r2 is None else r2
    Sut = float(mat.tensile_strength(d))
    Ssu = float(ft.torsional_ultimate(Sut))
    Ssa, Ssm = ft.ZIMMERLI[False]
    Sse = float(ft.endurance_intercept(Ssa, Ssm, Ssu, criterion))
    half, mid = abs(F_hi - F_lo) / 2.0, (F_hi + F_lo) / 2.0
    def point(stress: str, midrange, amplitude, endurance, ultimate) -> dict:
        return {"stress": stress} | {f.name: f for f in (
            Figure("midrange", float(midrange), "Pa"), Figure("amplitude", float(amplitude), "Pa"),
            Figure("endurance", float(endurance), "Pa"), Figure("ultimate", float(ultimate), "Pa"))}

    return {"criterion": criterion, "source": ft.ZIMMERLI_SOURCE,
            "A": point("bending", he.hook_bending_stress(mid, d, D, r1),
                       he.hook_bending_stress(half, d, D, r1), Sse / ft.SHEAR_TO_NORMAL, Sut),
            "B": point("torsion", he.hook_torsion_stress(mid, d, D, r2),
                       he.hook_torsion_stress(half, d, D, r2), Sse, Ssu)}


def report(spec, sd, char, vib=None) -> SpringReport:
    """The spring maker's sheet and the engineering figures of one helical governor spring.

    The sheet (material, d, D, n, ends or hooks, free length, rate, the loads at the range's two
    ends, tolerance grade, surface), the material's figures at ``d``, the static and fatigue
    loads (the cycle of the type's forcing, Hamabe Part II, where ``vib`` is given), and the
    tolerance spread (:func:`spread`).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]`` and ``[spring]``.
    sd : SpringDesign [-]
        The design (m, kg, N/m).
    char : Characteristic [-]
        Its statics (spring force in N).
    vib : VibrationResult [-], optional
        The forced vibration; None: no fatigue (and a note saying so).

    Returns
    -------
    SpringReport [-]
        Figures in SI, each with its unit.

    References
    ----------
    [en13906-1] (surge frequency, sheet); [shigley] 9th ed. section 10-11; [en15800];
    [hamabe] Part II.

    Examples
    --------
    Hamabe's Example 1 (a) spring (d 1.7 cm, D 12 cm, 8 turns) drawn from EN 10270-1 DH wire
    (the bundled ``hamabe-design-fatigue`` spec, Hamabe's k_s = 4000 kgf/cm^2 as the allowable).
    Its surge frequency with both ends fixed, by hand
    ``d / (2 pi n D^2) sqrt(G / (2 rho)) = 0.017 / (2 pi 8 0.0144) x sqrt(83.36e9 / 15700)``
    ``= 54.1 Hz``; no forcing given, so no fatigue.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> rep = report(spec, sd, statics.characteristic(spec, sd))
    >>> rep.kind, round(rep.loads["surge frequency"].value, 1), rep.notes == [NO_FORCING]
    ('extension', 54.1, True)
    """
    m, form = spec.material, spec.spring_form
    kind = KINDS[spec.governor.spring]
    mat = wire(m)
    d, D, n = sd.d, 2.0 * sd.r, sd.n
    F = np.asarray(char.spring_force, dtype=float)
    F1, F2 = sorted((float(F[0]), float(F[-1])))
    graded = m.grade is not None
    surface = m.surface if graded else "not stated (no wire grade: no fatigue check)"
    L = spec.governor.spring_length_factor * sd.l0
    if kind == "compression":
        sheet = sh.compression_sheet(mat, d, D, n, n + form.inactive_turns, L, F1, F2,
                                     ends=form.ends, grade=m.tolerance_grade, surface=surface)
    else:
        F0 = float(initial_tension(spec, d, D, float(np.min(F))))
        sheet = sh.extension_sheet(mat, d, D, n - float(mat.shear_modulus(d))
                                   / float(mat.elastic_modulus(d)), F0, F1, F2,
                                   grade=m.tolerance_grade, surface=surface)
    notes = []
    material = {"grade": mat.grade, "standard": mat.standard,
                "shear modulus": Figure("shear modulus", float(mat.shear_modulus(d)), "Pa"),
                "elastic modulus": Figure("elastic modulus", float(mat.elastic_modulus(d)), "Pa"),
                "density": Figure("density", mat.density, "kg/m^3", json="density_kg_m3"),
                "moduli_source": mat.moduli_source, "surface": surface}
    if graded:
        place = "compression" if kind == "compression" else "extension"
        rule = mt.static_rule(mat, place, m.rules)
        material.update({
            "tensile strength": Figure("tensile strength", float(mat.tensile_strength(d)), "Pa"),
            "rm_source": mat.rm_source,
            "rules": m.rules, "static_correction": m.stress_correction,
            "fatigue_correction": hx.DEFAULT_CORRECTION[(m.rules, "fatigue")],
            "allowable static stress": Figure("allowable static stress", float(
                mt.allowable_static_stress(mat, d, place, m.rules, m.allowable_shear_stress)),
                "Pa"),
            "allowable_source": "material.allowable_shear_stress (given in the spec)"
            if m.allowable_shear_stress is not None else rule.source,
            "life_cycles": m.life_cycles})
    loads = {f.name: f for f in (
        Figure("force min", float(np.min(F)), "N"), Figure("force max", float(np.max(F)), "N"),
        Figure("surge frequency", sheet.surge_frequency, "Hz"),
        Figure("excitation harmonics", list(harmonics_hz(vib)), "Hz"))}
    if vib is None:
        loads["fatigue"] = None
        notes.append(NO_FORCING)
    else:
        swing = float(vib.peak_to_peak_rad)
        unit = "rad" if spec.governor.coordinate == "angle" else "m"
        fat = {"forcing": "the valve gear's fluctuating reaction (Hamabe Part II, with the "
                          "dash-pot)", "peak to peak": Figure("peak to peak", swing, unit)}
        if math.isfinite(swing):
            lo, hi = fatigue_forces(spec, sd, swing)
            K = hx.bergstrasser_factor(hx.spring_index(d, D))
            fat.update(ft.cycle_figures(lo, hi, *(float(K * hx.shear_stress(f, d, D))
                                                  for f in (lo, hi))))
            if graded:  # the diagram the body's fatigue check reads (for the plot)
                fat["diagram"] = ft.body_locus(mat, d, m.rules, m.surface == "shot peened",
                                               ck.DEFAULTS["criterion"])
                if kind == "extension":  # and the hooks' (the check's own line and cycle)
                    fat["hooks"] = hook_cycles(mat, d, D, lo, hi, form.hook_bend_radius)
        loads["fatigue"] = fat
        if not graded:
            notes.append("no material.grade: the fatigue and spring engineering checks need "
                         "a wire grade")
    return SpringReport(kind, sheet, material, loads, spread(spec, sd, sheet), notes)


# ---------------------------------------------------------------- the optimiser's screen

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


def static_range(spec, kappa, l0):
    """Least and largest spring force, N, over the characteristic's configurations.

    ``F = kappa (A_F - B_F l0)`` (:func:`statics.spring_force`; the shaft governor's
    ``2 kappa (l - l0)``, Hamabe eq. 2) at :func:`statics.configurations`, for arrays of springs.

    Parameters
    ----------
    spec : Spec [-]
        The governor.
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form.

    Returns
    -------
    tuple of float or array [N]
        ``(F1, F2)``.

    References
    ----------
    [hamabe] Part I, eq. (2) and Example 1.

    Examples
    --------
    Hamabe's Example 1 (a), the paper's spring (64.2 kgf/cm): the paper prints F_a = 606 kgf for
    the spring the range needs (63.3 kgf/cm with exact arms); its rounded, stiffer spring pulls
    611 kgf at the outermost configuration, and F_i = 419.2 kgf with the exact arm.

    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> F1, F2 = static_range(spec, sd.kappa, sd.l0)
    >>> round(float(F1) / KGF, 1), round(float(F2) / KGF, 1)
    (419.5, 611.1)
    """
    A_F, B_F = spec.governor.spring_force_coefficients(statics.configurations(spec))
    A_F, B_F = np.ravel(A_F), np.ravel(B_F)
    if B_F.size and np.all(B_F == B_F[0]) and np.all(np.asarray(kappa) >= 0):
        # F = kappa (A_F - B l0) is monotone in A_F: its extremes at A_F's, the same numbers
        # as the loop below (rounding is monotone), without a pass per configuration
        b = B_F[0]
        return kappa * (np.min(A_F) - b * l0), kappa * (np.max(A_F) - b * l0)
    lo = hi = None
    for a, b in zip(np.ravel(A_F), np.ravel(B_F), strict=True):
        F = kappa * (a - b * l0)
        lo, hi = (F, F) if lo is None else (np.minimum(lo, F), np.maximum(hi, F))
    return lo, hi


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


def geometry_rows(spec, d, D, n, kappa, l0, F1=None, F2=None) -> dict:
    """The rows of :data:`govopt.springs.checks.GEOMETRY` over arrays: ``{name: (value, ...)}``.

    A compression spring's coil clash, buckling (EN 13906-1, the seating ``[spring] seating``,
    default both ends on flat parallel seats, ``nu = 0.5``) and free pitch (gaps between the
    coils; at most 0.7 D_i, a helix angle small enough for the rate G d^4 / (8 D^3 n)), which need
    no wire strength, for a spring without a wire grade (with one, :func:`screen` and
    :func:`checks` hold them already); none for an extension spring. The static range
    ``F1 <= F2`` defaults to :func:`static_range`; E is the grade's or, without one, the
    EN 10270-1 steel default of :func:`wire`.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]`` and ``[spring]``.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter (``2 r``).
    n : float or array [-]
        Active coils (dimensionless).
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form.
    F1 : float or array [N], optional
        Least working force.
    F2 : float or array [N], optional
        Largest working force.

    Returns
    -------
    dict [-]
        Row name -> ``(value, limit, sense)`` in the row's SI unit (m, or dimensionless).

    References
    ----------
    [en13906-1] clause 9.14 (buckling), the least working length ``L_c + S_a``.

    Examples
    --------
    A Hartnell governor's compression spring (the bundled ``hartnell-design`` spec, no wire
    grade) of 3 mm wire, D 40 mm, 8 active coils, closed ends (10 in all), free length 209.7 mm,
    working between 180.9 and 230.3 N at 1648 N/m.
    By hand: the free pitch ``(L0 - 2 d) / n = (209.7 - 6) / 8 = 25.47 mm`` against
    ``0.7 D_i = 0.7 x 37 = 25.9 mm``; the working length at full lift plus the 10 % overtravel,
    ``L0 - (F2 + 0.1 (F2 - F1)) / kappa = 209.7 - 142.7 = 67.0 mm``.

    >>> import tomllib
    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> data = tomllib.loads(example("hartnell-design").read_text(encoding="utf-8"))
    >>> data["design"] = {"ball_weight": "2 kgf", "wire_diameter": "3 mm", "coil_radius": "2 cm",
    ...                   "active_turns": 8}
    >>> spec = govopt.parse_spec(data, "hartnell")
    >>> sd = statics.spring_design(spec)
    >>> rows = geometry_rows(spec, sd.d, 2 * sd.r, sd.n, sd.kappa, sd.l0)
    >>> v, lim, sense = rows["free pitch <= 0.7 inside diameter (helix angle)"]
    >>> round(float(v) * 1e3, 2), round(float(lim) * 1e3, 2), sense
    (25.47, 25.9, '<=')
    >>> round(float(rows["working length >= least length (coil clash)"][0]) * 1e3, 1)
    67.0
    """
    kind = KINDS[spec.governor.spring]
    senses = {r.name: r.sense for r in ck.TABLES[kind] if r.name in ck.GEOMETRY}
    if not senses:  # no geometric row for this kind (an extension spring): nothing to compute
        return {}
    if F1 is None:
        F1, F2 = static_range(spec, kappa, l0)
    kw = _kw(spec, d, D, n, kappa, l0, F1, F2)
    return {k: (v, lim, senses[k]) for k, (v, lim) in ck.evaluate(kind, ck.GEOMETRY, **kw).items()}


def geometry_table(spec, d, D, n, kappa, l0, F1, F2) -> list:
    """The rows of :func:`geometry_rows` with what a check shows of them, in order.

    ``(row, value, limit, source)`` (:func:`govopt.springs.checks.rows_over`; the row's name,
    sense and unit); none for a spring kind without geometric rows.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]`` and ``[spring]``.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter (``2 r``).
    n : float or array [-]
        Active coils (dimensionless).
    kappa : float or array [N/m]
        Rate of the whole spring.
    l0 : float or array [m]
        Free length in the type's form.
    F1 : float or array [N]
        Least working force.
    F2 : float or array [N]
        Largest working force.

    Returns
    -------
    list of tuple [-]
        ``(Row, value, limit, source)``, values in the row's SI unit.

    References
    ----------
    [en13906-1] clause 9.14 (buckling), the least working length.

    Examples
    --------
    A Hartnell governor's compression spring (the bundled ``hartnell-design`` spec, no wire
    grade) of 3 mm wire, D 40 mm, 8 active coils, closed ends (10 in all), free length 209.7 mm,
    working between 180.9 and 230.3 N at 1648 N/m.
    The buckling row cites its clause (the spring buckles: 1.06 of the buckling deflection).

    >>> import tomllib
    >>> import govopt
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> data = tomllib.loads(example("hartnell-design").read_text(encoding="utf-8"))
    >>> data["design"] = {"ball_weight": "2 kgf", "wire_diameter": "3 mm", "coil_radius": "2 cm",
    ...                   "active_turns": 8}
    >>> spec = govopt.parse_spec(data, "hartnell")
    >>> sd = statics.spring_design(spec)
    >>> F1, F2 = static_range(spec, sd.kappa, sd.l0)
    >>> table = geometry_table(spec, sd.d, 2 * sd.r, sd.n, sd.kappa, sd.l0, F1, F2)
    >>> row, value, limit, source = table[1]
    >>> row.name, round(float(value), 2), source.split(":")[0]
    ('deflection / buckling deflection', 1.06, 'EN 13906-1, 9.14')
    """
    kind = KINDS[spec.governor.spring]
    if not any(r.name in ck.GEOMETRY for r in ck.TABLES[kind]):
        return []
    return ck.rows_over(kind, ck.GEOMETRY, **_kw(spec, d, D, n, kappa, l0, F1, F2))


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
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> one = screen_fatigue(spec, np.array([sd.d]), np.array([sd.r]), np.array([sd.n]),
    ...                      np.array([sd.kappa]), np.array([sd.l0]), np.array([[0.02]]))
    >>> F1, F2 = static_range(spec, sd.kappa, sd.l0)
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


__all__ = ["KINDS", "NO_FORCING", "Spread", "SpringReport", "allowable_monomial", "checks",
           "evaluate_rows", "fatigue_forces", "fatigue_safety", "feasible",
           "geometry_rows", "geometry_screen", "geometry_table", "harmonics_hz",
           "initial_tension", "report", "screen", "screen_fatigue",
           "screen_vibration", "spread", "static_range", "wire"]
