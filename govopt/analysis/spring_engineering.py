"""Spring engineering of a governor's helical spring on the mechanism's own loads.

The rules live in :mod:`govopt.springs` (materials, helical geometry, fatigue, EN 15800
tolerances, the constraint tables); this module feeds them a governor's loads and geometry, for
one design (:func:`checks`; the spring's record, :func:`govopt.analysis.spring_record.report`)
and over arrays of catalogue springs (:func:`feasible`, :func:`fatigue_safety`; the design
search's screens are :mod:`govopt.analysis.spring_screens`). It runs for a spec whose ``[material]``
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
from dataclasses import replace

import numpy as np

from ..springs import checks as ck
from ..springs import extension as he
from ..springs import helical as hx
from ..springs import materials as mt
from ..verdict import Check
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
    >>> from govopt.analysis import characteristic as chs
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
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> fat = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> from govopt.analysis.spring_screens import screen_vibration
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
    >>> from govopt.analysis import characteristic as chs
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
    >>> from govopt.analysis import characteristic as chs
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
    >>> from govopt.analysis import characteristic as chs
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
    >>> from govopt.analysis import characteristic as chs
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
    >>> from govopt.analysis import characteristic as chs
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
        Its statics (:func:`~govopt.analysis.characteristic.characteristic`; spring force in N).
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
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> KGF = 9.80665
    >>> cs = checks(spec, sd, chs.characteristic(spec, sd))
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


def checks_over(spec, sd, F) -> list:
    """The static checks of :func:`checks` (no forcing: no fatigue rows) for N designs at once.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its ``[material]``, ``[spring]`` and requirements.
    sd : SpringDesign [-]
        N designs as arrays of shape ``(N, 1)`` (wire and coil in m, rate in N/m, free length
        in m in the type's form).
    F : array [N]
        The spring force of each design over the configurations, ``(N, K)``.

    Returns
    -------
    list of Check [-]
        One per row, ``value`` and ``limit`` arrays of N in the row's SI unit: design ``i``'s
        numbers are those :func:`checks` gives for it (every row is elementwise).

    References
    ----------
    [shigley] 9th ed. sections 10-9, 10-11; [en13906-1].

    Examples
    --------
    Hamabe's Example 1 (a) spring (the bundled ``hamabe-design-fatigue`` spec) and a copy of it
    with a thinner wire, at once: the first row is the body's uncorrected stress, 372.7 MPa
    against k_s = 392.3 MPa for Hamabe's wire (as :func:`checks` prints), and by hand
    ``x (17/16)^3`` = 447 MPa for the 16 mm wire at the same forces.

    >>> import govopt
    >>> from dataclasses import replace
    >>> from govopt.examples import example
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.load_spec(example("hamabe-design-fatigue"))
    >>> spec = spec.with_design(govopt.load_spec(example("hamabe-a")).design)
    >>> sd = statics.spring_design(spec)
    >>> two = replace(sd, d=np.array([[sd.d], [0.016]]), r=np.full((2, 1), sd.r),
    ...               n=np.full((2, 1), sd.n), kappa=np.full((2, 1), sd.kappa),
    ...               l0=np.full((2, 1), sd.l0))
    >>> F = np.tile(chs.characteristic(spec, sd).spring_force, (2, 1))
    >>> c = checks_over(spec, two, F)[0]
    >>> c.name, [round(float(v) / 1e6, 1) for v in c.value], round(float(c.limit[0]) / 1e6, 1)
    ('body static shear stress', [372.7, 447.1], 392.3)
    """
    kind = KINDS[spec.governor.spring]
    N = np.shape(F)[0]

    def flat(v):
        return np.broadcast_to(np.asarray(v, dtype=float), (N, 1))[:, 0]

    F = np.asarray(F, dtype=float)
    kw = _kw(spec, flat(sd.d), 2.0 * flat(sd.r), flat(sd.n), flat(sd.kappa), flat(sd.l0),
             F.min(axis=1), F.max(axis=1))
    out = [Check(r.name, value, limit, r.sense, r.unit, source, group="spring")
           for r, value, limit, source in ck.rows_over(kind, **kw) if _static(r.name, spec)]
    if kind == "extension":
        value, limit = np.broadcast_arrays(*_fits(ck.prepare(kind, **kw)))
        out.append(Check(FITS, value, limit, "<=", "m", FITS_SOURCE, group="spring"))
    return out


# ---------------------------------------------------------------- the optimiser's screen


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
    >>> from govopt.analysis import characteristic as chs
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
    >>> from govopt.analysis import characteristic as chs
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
    The buckling row cites its clause (the spring buckles: 1.06 of the buckling deflection);
    it is the third row, after the force at solid (a geometry row since every material checks
    it, graded or not) and the coil clash.

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
    >>> F1, F2 = static_range(spec, sd.kappa, sd.l0)
    >>> table = geometry_table(spec, sd.d, 2 * sd.r, sd.n, sd.kappa, sd.l0, F1, F2)
    >>> row, value, limit, source = table[2]
    >>> row.name, round(float(value), 2), source.split(":")[0]
    ('deflection / buckling deflection', 1.06, 'EN 13906-1, 9.14')
    """
    kind = KINDS[spec.governor.spring]
    if not any(r.name in ck.GEOMETRY for r in ck.TABLES[kind]):
        return []
    return ck.rows_over(kind, ck.GEOMETRY, **_kw(spec, d, D, n, kappa, l0, F1, F2))


__all__ = ["KINDS", "NO_FORCING", "checks", "evaluate_rows", "fatigue_forces", "fatigue_safety",
           "feasible", "geometry_rows", "geometry_table", "harmonics_hz", "initial_tension",
           "static_range", "wire"]
