"""Helical compression and extension springs of round wire: pure, vectorised functions (SI).

Arguments are numpy arrays (or floats) that broadcast together: wire diameter ``d`` (m), mean
coil diameter ``D`` (m; Hamabe's coil radius is ``r = D/2``), active coils ``n``, total coils
``n_t``, forces (N), moduli (Pa), density (kg/m^3). Sources: EN 13906-1:2013 (compression) and
EN 13906-2:2013 (extension); R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering
Design*, 9th ed. (2011), ch. 10 ("Shigley"); A. M. Wahl, *Mechanical Springs* (1963).

Here: the spring index and stress corrections, the rate, the stresses, the wire's length and
mass, the surge frequency, and Hamabe's forms in the coil radius ``r``. A compression spring's
lengths, pitch and buckling are in :mod:`govopt.springs.compression`; an extension spring's body
and hooks in :mod:`govopt.springs.extension`.
"""

from __future__ import annotations

import numpy as np

#: Stress-correction factors for :func:`correction_factor`.
CORRECTIONS = ("none", "wahl", "bergstrasser")
#: each correction factor by name, as a report names it beside a corrected stress
CORRECTION_TEXT = {"none": "none (uncorrected)", "wahl": "Wahl's (4w - 1)/(4w - 4) + 0.615/w",
                   "bergstrasser": "Bergstraesser's (w + 0.5)/(w - 0.75)"}

#: The default correction per use: EN 13906-1/-2 use the uncorrected stress for static and
#: quasi-static checks and k (Bergstraesser) for fatigue; Shigley uses K_B for both.
DEFAULT_CORRECTION = {("EN13906", "static"): "none", ("EN13906", "fatigue"): "bergstrasser",
                      ("Shigley", "static"): "bergstrasser",
                      ("Shigley", "fatigue"): "bergstrasser"}


def spring_index(d, D):
    """Spring index ``w = C = D/d`` (EN 13906-1 symbol w; Shigley eq. (10-1) C).

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.

    References
    ----------
    [en13906-1] symbol w; [shigley] eq. (10-1). Example: Shigley Problem 10-3 (d = 2.5 mm,
    D = 28.5 mm).

    >>> float(spring_index(2.5e-3, 28.5e-3))
    11.4
    """
    return np.asarray(D, dtype=float) / d


def bergstrasser_factor(C):
    """Bergstraesser's stress-correction factor ``k = (w + 0.5)/(w - 0.75) = (4C + 2)/(4C - 3)``.

    EN 13906-1:2013 eq. for k; Shigley eq. (10-5) K_B. Differs from Wahl's by under 1.4 % for
    4 <= C <= 12 (10th ed. solutions manual, Problem 10-1).

    Parameters
    ----------
    C : float or array [-]
        Spring index ``D/d``, dimensionless.

    References
    ----------
    [en13906-1] factor k; [shigley] eq. (10-5). Example: Shigley Problem 10-3 (rounded to
    three places as printed).

    >>> round(float(bergstrasser_factor(11.4)), 3)  # 10th ed. Problem 10-3
    1.117
    """
    C = np.asarray(C, dtype=float)
    return (C + 0.5) / (C - 0.75)


def correction_factor(C, correction: str):
    """Stress-correction factor K (-): ``"none"`` (1), ``"wahl"`` or ``"bergstrasser"``.

    Parameters
    ----------
    C : float or array [-]
        Spring index ``D/d``, dimensionless.
    correction : str [-]
        ``"none"``, ``"wahl"`` (:func:`wahl_factor`) or ``"bergstrasser"``
        (:func:`bergstrasser_factor`); anything else is a ValueError.

    Returns
    -------
    float or array [-]
        The factor K, shaped like ``C``.

    References
    ----------
    [en13906-1] factor k; [shigley] eq. (10-5); [wahl] eq. (2-12).

    Examples
    --------
    Shigley Problem 10-3 (10th ed. solutions manual) prints K_B = 1.117 at C = 11.4; Wahl's
    factor at C = 4 by hand is 15/12 + 0.615/4 = 1.40375.

    >>> round(float(correction_factor(11.4, "bergstrasser")), 3)
    1.117
    >>> float(correction_factor(4.0, "none")), round(float(correction_factor(4.0, "wahl")), 5)
    (1.0, 1.40375)
    """
    if correction == "none":
        return np.ones_like(np.asarray(C, dtype=float))
    if correction == "wahl":
        return wahl_factor(C)
    if correction == "bergstrasser":
        return bergstrasser_factor(C)
    raise ValueError(f"stress correction must be one of {CORRECTIONS}, got {correction!r}")


def stiffness(d, D, n, G):
    """Spring rate ``R = G d^4 / (8 D^3 n)`` (N/m), EN 13906-1 eq. for R; Shigley eq. (10-9).

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    G : float [Pa]
        Shear modulus of the wire.

    References
    ----------
    [en13906-1] rate R; [shigley] eq. (10-9). Example: Shigley Problem 10-3 (printed in N/mm,
    rounded to three places).

    >>> round(float(stiffness(2.5e-3, 28.5e-3, 13, 81e9)) / 1e3, 3)  # N/mm, Problem 10-3
    1.314
    """
    return G * np.asarray(d, dtype=float) ** 4 / (8.0 * np.asarray(D, dtype=float) ** 3 * n)


def shear_stress(F, d, D, correction: str = "none"):
    """Torsional shear stress ``tau = K 8 F D / (pi d^3)`` (Pa); K by ``correction``.

    EN 13906-1 eq. for tau (uncorrected) and tau_k = k tau; Shigley eq. (10-7) with K_B.

    Parameters
    ----------
    F : float or array [N]
        Axial spring force (its magnitude is used).
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    correction : str [-]
        ``"none"``, ``"wahl"`` or ``"bergstrasser"`` (the factor K).

    References
    ----------
    [en13906-1] stresses tau and tau_k; [shigley] eq. (10-7). Example: Shigley Problem 10-3
    backwards, the force :func:`force_at_stress` gives back the stress (MPa, rounded to 0.1).

    >>> F = force_at_stress(871.2e6, 2.5e-3, 28.5e-3, "bergstrasser")
    >>> round(float(shear_stress(F, 2.5e-3, 28.5e-3, "bergstrasser")) / 1e6, 1)
    871.2
    """
    d = np.asarray(d, dtype=float)
    K = correction_factor(spring_index(d, D), correction)
    return K * 8.0 * np.abs(F) * D / (np.pi * d**3)


def force_at_stress(tau, d, D, correction: str = "none"):
    """Force that raises the stress to ``tau``: ``F = pi d^3 tau / (8 K D)`` (Shigley (10-7)).

    Parameters
    ----------
    tau : float or array [Pa]
        Shear stress to reach.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    correction : str [-]
        ``"none"``, ``"wahl"`` or ``"bergstrasser"`` (the factor K).

    References
    ----------
    [shigley] eq. (10-7) with K_B. Example: Shigley Problem 10-3 (force rounded to 0.1 N).

    >>> round(float(force_at_stress(871.2e6, 2.5e-3, 28.5e-3, "bergstrasser")), 1)  # N
    167.9
    """
    d = np.asarray(d, dtype=float)
    K = correction_factor(spring_index(d, D), correction)
    return np.pi * d**3 * tau / (8.0 * K * D)


# ---------------------------------------------------------------- compression-spring geometry


def open_coil_stiffness(d, D, n, G, E, alpha):
    """Rate of an open-coiled spring with the helix angle ``alpha`` (rad), N/m (d, D in m; G, E
    in Pa): ``R = G d^4 / (8 D^3 n) cos(alpha) / (cos^2(alpha) + 2 (G/E) sin^2(alpha))``.

    The axial force F at the coil radius ``D/2`` twists the wire with ``T = F D/2 cos(alpha)``
    and bends it with ``M = F D/2 sin(alpha)`` over its length ``pi D n / cos(alpha)``;
    Castigliano with ``J = pi d^4/32`` and ``I = pi d^4/64`` gives the deflection
    ``8 F D^3 n / (G d^4) (cos^2 + 2 (G/E) sin^2) / cos``: the open-coiled helical spring of
    strength of materials (Timoshenko; Wahl, *Mechanical Springs*, the effect of the pitch angle).
    At ``alpha = 0`` it is :func:`stiffness`; like it, it neglects direct shear and the wire's
    curvature, and takes ``alpha`` constant (small deflections).

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    G : float or array [Pa]
        Shear modulus of the wire.
    E : float or array [Pa]
        Young's modulus of the wire.
    alpha : float or array [rad]
        Helix angle of the coils (:func:`helix_angle`).

    Returns
    -------
    float or array [N/m]
        The axial rate.

    References
    ----------
    [wahl] the effect of the pitch angle on the rate; [en13906-1] rate R at ``alpha = 0``.

    Examples
    --------
    A textbook problem (expertsmind.com, "Open coiled helical spring": alpha = 38 deg,
    E = 200 GPa, G = 80 GPa) prints the extension under-estimated by 14.96 % when alpha is
    neglected, from rounded figures (and cos 38 deg printed as 0.866, which is cos 30 deg);
    the formula gives 14.7 %:

    >>> a = np.radians(38.0)
    >>> round(float(1 - open_coil_stiffness(1, 1, 1, 80e9, 200e9, a) / stiffness(1, 1, 1, 80e9)
    ...             ) * 100, 2)
    14.74
    """
    c, s = np.cos(alpha), np.sin(alpha)
    return stiffness(d, D, n, G) * c / (c**2 + 2.0 * np.asarray(G, dtype=float) / E * s**2)


# ---------------------------------------------------------------- dynamics

def surge_frequency(d, D, n, G, density):
    """First natural (surge) frequency, both ends fixed, excited at one end (Hz).

    ``f_e = d / (2 pi n D^2) sqrt(G / (2 rho))`` - EN 13906-1:2013 (natural frequency)
    (``f_e = 3.56e5 d/(n D^2)`` in mm for steel) and Shigley eq. (10-25) ``f = 1/2 sqrt(k g/W)``
    with the active-coil weight ``W = pi^2 d^2 D N_a gamma / 4``: the same formula.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    G : float [Pa]
        Shear modulus of the wire.
    density : float [kg/m^3]
        Density of the wire.

    References
    ----------
    [en13906-1] natural frequency f_e; [shigley] eq. (10-25). Example: Shigley Example 10-4,
    which prints 281 Hz from k and W rounded (here rounded to 0.1 Hz).

    >>> inch, psi = 0.0254, 6894.757  # Shigley Example 10-4 prints 281 Hz (from k and W rounded)
    >>> round(float(surge_frequency(0.092 * inch, 0.4705 * inch, 21, 11.75e6 * psi, 7861)), 1)
    281.5
    """
    d = np.asarray(d, dtype=float)
    return d / (2.0 * np.pi * n * np.asarray(D, dtype=float) ** 2) * np.sqrt(G / (2.0 * density))


def surge_detuning(f_e, harmonics_hz):
    """Relative distance of the surge frequency from the nearest excitation harmonic.

    ``min_i |f_e / f_i - 1|`` over the harmonic frequencies actually present in the excitation
    (last axis of ``harmonics_hz``; a 1-D list of frequencies broadcasts against ``f_e``). A check
    against a band, e.g. ``>= 0.2``, keeps every present harmonic out of +-20 % of ``f_e``.
    Returns ``inf`` for an empty list (nothing to resonate with). govopt's own measure (no source
    gives it); the frequency it guards is EN 13906-1's natural frequency (:func:`surge_frequency`).

    Parameters
    ----------
    f_e : float or array [Hz]
        Surge frequency of the spring.
    harmonics_hz : array [Hz]
        Frequencies of the excitation's harmonics present (last axis).

    Returns
    -------
    float or array [-]
        The smallest relative detuning, dimensionless.

    References
    ----------
    [en13906-1] natural frequency f_e (the frequency compared).

    Examples
    --------
    A hand check: the 281 Hz of Shigley Example 10-4 against harmonics at 4, 8 and 250 Hz is
    nearest to 250 Hz: ``281/250 - 1 = 0.124``.

    >>> round(float(surge_detuning(281.0, [4.0, 8.0, 250.0])), 3)
    0.124
    >>> float(surge_detuning(281.0, []))
    inf
    """
    f_e = np.asarray(f_e, dtype=float)
    h = np.asarray(harmonics_hz, dtype=float)
    if h.size == 0:
        return np.full(f_e.shape, np.inf)
    return np.min(np.abs(f_e[..., None] / h - 1.0), axis=-1)


# ---------------------------------------------------------------- mass

def wire_length(D, n_t):
    """Developed wire length ``pi D n_t`` (m) - EN 13906-1 (ends and hooks as coils), the
    coils' helix rise left out (:func:`helix_wire_length` includes it).

    Parameters
    ----------
    D : float or array [m]
        Mean coil diameter.
    n_t : float or array [-]
        Coils counted (total coils; hooks as coils).

    Returns
    -------
    float or array [m]
        The wire's length.

    References
    ----------
    [en13906-1] developed length of the wire (mass of the spring).

    Examples
    --------
    A hand check: 10 coils on a 20 mm coil take ``pi x 20 x 10 = 628.3 mm``.

    >>> round(float(wire_length(20e-3, 10)) * 1e3, 1)  # mm
    628.3
    """
    return np.pi * np.asarray(D, dtype=float) * n_t


def helix_wire_length(D, n, m, end_coils, d):
    """Developed wire length of a helical spring including the helix rise (m): ``n`` active
    coils of pitch ``m`` and ``end_coils`` inactive ones wound at the pitch ``d`` (closed ends,
    coils touching; an extension spring's body), each coil a turn of the helix of mean
    diameter ``D``: ``n sqrt((pi D)^2 + m^2) + end_coils sqrt((pi D)^2 + d^2)``. The active
    part is Starrett's ``pi D n / cos(alpha)`` (spring catalogue terminology: ``L_d = pi D (2
    + n_m + n / cos alpha)``, ``alpha`` the helix angle of :func:`helix_angle`), which counts
    the inactive coils as flat circles; they rise by ``d`` per turn here. Lengths in m.

    govopt's own refinement of EN 13906-1's developed length ``pi D n_t`` (:func:`wire_length`).

    Parameters
    ----------
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    m : float or array [m]
        Pitch of the active coils (:func:`pitch`).
    end_coils : float or array [-]
        Inactive coils, wound at the pitch ``d``.
    d : float or array [m]
        Wire diameter.

    Returns
    -------
    float or array [m]
        The wire's length along the helix.

    References
    ----------
    [en13906-1] developed length ``pi D n_t`` (the flat-coil limit).

    Examples
    --------
    A hand check: one coil of 10 mm pitch on a 30 mm coil is ``sqrt(1 + (10/(30 pi))^2)`` =
    1.00561 times ``pi D``:

    >>> D, m = 30e-3, 10e-3
    >>> round(float(helix_wire_length(D, 1.0, m, 0.0, 3e-3) / wire_length(D, 1.0)), 5)
    1.00561
    """
    D = np.asarray(D, dtype=float)
    circle = np.pi * D
    return n * np.hypot(circle, m) + end_coils * np.hypot(circle, d)


def mass(d, D, n_t, density):
    """Wire mass ``rho (pi d^2/4) pi D n_t`` (kg) over ``n_t`` coils (pass the active coils
    for the vibrating mass of :func:`surge_frequency`); the helix rise left out
    (:func:`helix_mass` includes it).

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n_t : float or array [-]
        Coils counted.
    density : float or array [kg/m^3]
        Density of the wire.

    Returns
    -------
    float or array [kg]
        The wire's mass.

    References
    ----------
    [en13906-1] mass of the spring; [shigley] eq. (10-25) and Example 10-4 (the active coils'
    weight W).

    Examples
    --------
    Shigley Example 10-4 (9th ed.): 21 active coils of 0.092 in music wire, OD = 9/16 in,
    prints W = 0.0586 lbf (0.284 lbf/in^3 there, 7861 kg/m^3 here).

    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> W = mass(0.092 * inch, (9 / 16 - 0.092) * inch, 21, 7861) * 9.80665 / lbf
    >>> round(float(W), 4)  # lbf
    0.0586
    """
    return density * np.pi * np.asarray(d, dtype=float) ** 2 / 4.0 * wire_length(D, n_t)


def helix_mass(d, D, n, m, end_coils, density):
    """Wire mass ``rho (pi d^2/4) L`` (kg) with the wire length ``L`` of
    :func:`helix_wire_length` (the helix rise included); m, kg/m^3.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    m : float or array [m]
        Pitch of the active coils.
    end_coils : float or array [-]
        Inactive coils, wound at the pitch ``d``.
    density : float or array [kg/m^3]
        Density of the wire.

    Returns
    -------
    float or array [kg]
        The wire's mass.

    References
    ----------
    [en13906-1] mass of the spring (the flat-coil limit, :func:`mass`).

    Examples
    --------
    A hand check: 10 active coils of 4.6 mm pitch and 2 closed end coils of 2 mm steel wire on
    a 20 mm coil weigh 0.23 % more than the 12 flat coils of :func:`mass` (18.59 g):

    >>> rho = 7850
    >>> round(float(helix_mass(2e-3, 20e-3, 10, 4.6e-3, 2, rho) / mass(2e-3, 20e-3, 12, rho)), 4)
    1.0023
    """
    d = np.asarray(d, dtype=float)
    return density * np.pi * d**2 / 4.0 * helix_wire_length(D, n, m, end_coils, d)


# ---------------------------------------------------------------- Hamabe's coil-radius forms
# Hamabe's Example 1 writes the spring with its mean coil *radius* r (not the diameter D = 2 r);
# the optimiser, the bulk evaluator and the shaft governor's sheet keep his form, whose
# arithmetic (and so every printed digit) differs from the D forms above in the last place.


def stiffness_r(d, r, n, G):
    """Axial stiffness of a close-coiled helical spring, force per unit extension.

    ``kappa = G d^4 / (64 r^3 n)`` — Hamabe, Example 1 (``n = G d^4 / (64 r^3 kappa)``); the
    same as the textbook ``G d^4 / (8 D^3 n)`` with ``D = 2 r``. Torsion of the wire only
    (shear and curvature corrections to stiffness are below 1 % for index C > 4).

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius, ``D/2``.
    n : float or array [-]
        Number of active turns.
    G : float or array [Pa]
        Shear modulus of the wire.

    Returns
    -------
    float or array [N/m]
        The axial stiffness ``kappa``.

    References
    ----------
    [hamabe] Example 1, case (a); [en13906-1] rate R with ``D = 2 r``.

    Examples
    --------
    Hamabe's Example 1, case (a): d = 1.7 cm, r = 6 cm, n = 8, G = 850000 kg/cm^2 prints
    64.2 kg per cm; in SI (1 kg = 9.80665 N) G = 83.356525 GPa and kappa = 62952 N/m =
    64.19 kg/cm.

    >>> kgf = 9.80665
    >>> k = stiffness_r(0.017, 0.06, 8, 850000 * kgf * 1e4)
    >>> round(float(k), 1), round(float(k) / (kgf * 100), 1)  # N/m, kg/cm
    (62952.3, 64.2)
    """
    return G * d**4 / (64.0 * r**3 * n)


def spring_index_r(d, r):
    """Spring index ``C = D / d = 2 r / d`` (Wahl, *Mechanical Springs*, 1944, ch. 2).

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius, ``D/2``.

    Returns
    -------
    float or array [-]
        The spring index, dimensionless.

    References
    ----------
    [wahl] ch. 2; [shigley] eq. (10-1) with ``D = 2 r``.

    Examples
    --------
    Hamabe's Example 1 spring (d = 1.7 cm, r = 6 cm): by hand 12/1.7 = 7.059.

    >>> round(float(spring_index_r(0.017, 0.06)), 3)
    7.059
    """
    return 2.0 * r / d


def wahl_factor(C):
    """Wahl's stress-correction factor ``K = (4C - 1)/(4C - 4) + 0.615 / C``.

    A. M. Wahl, *Mechanical Springs* (1944), eq. (2-12): curvature and direct shear at the inner
    fibre of the coil. ``K -> 1`` as ``C -> inf``; undefined for ``C <= 1``.

    Parameters
    ----------
    C : float or array [-]
        Spring index ``D/d``, dimensionless.

    References
    ----------
    [wahl] eq. (2-12); value at C = 7 rounded to four places.

    >>> round(float(wahl_factor(7.0)), 4)
    1.2129
    """
    C = np.asarray(C, dtype=float)
    return (4.0 * C - 1.0) / (4.0 * C - 4.0) + 0.615 / C


def shear_stress_r(F, d, r, correction: str = "none"):
    """Maximum torsional shear stress in the wire under axial force ``F``.

    Uncorrected: ``tau = 16 F r / (pi d^3)`` — Hamabe, Example 1
    (``d = (16 F_a r / (pi k_s))^(1/3)``), i.e. torque ``F r`` on a round bar of diameter ``d``.
    ``correction="wahl"`` multiplies by :func:`wahl_factor` of the index ``2 r / d``,
    ``"bergstrasser"`` by Bergstraesser's ``(C + 0.5)/(C - 0.75)`` (EN 13906-1; Shigley eq.
    (10-5); :func:`bergstrasser_factor`).

    Parameters
    ----------
    F : float or array [N]
        Axial force on the spring (its magnitude is used).
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius, ``D/2``.
    correction : str [-]
        ``"none"``, ``"wahl"`` or ``"bergstrasser"``; anything else is a ValueError.

    Returns
    -------
    float or array [Pa]
        The shear stress.

    References
    ----------
    [hamabe] Example 1; [wahl] eq. (2-12); [en13906-1] factor k; [shigley] eq. (10-5).

    Examples
    --------
    Hamabe's Example 1, case (a): F_a = 606 kg on the spring he chose, d = 1.7 cm, r = 6 cm;
    the paper prints no stress, only that 1.7 cm keeps it under k_s = 4000 kg/cm^2: by hand
    ``16 x 606 x 6/(pi 1.7^3) = 3769 kg/cm^2`` (1 kg/cm^2 = 98066.5 Pa).

    >>> kgf = 9.80665
    >>> round(float(shear_stress_r(606 * kgf, 0.017, 0.06)) / 98066.5)  # kg/cm^2
    3769
    """
    tau = 16.0 * np.abs(F) * r / (np.pi * d**3)
    if correction == "wahl":
        return tau * wahl_factor(spring_index_r(d, r))
    if correction == "bergstrasser":
        return tau * bergstrasser_factor(spring_index_r(d, r))
    if correction != "none":
        raise ValueError(f"stress correction must be one of {CORRECTIONS}, got {correction!r}")
    return tau


def wire_diameter_for_stress(F, r, allowable):
    """Least wire diameter that keeps the uncorrected stress at ``allowable``.

    ``d = (16 F r / (pi k_s))^(1/3)`` — Hamabe, Example 1.

    Parameters
    ----------
    F : float or array [N]
        Largest axial force on the spring (its magnitude is used).
    r : float or array [m]
        Mean coil radius, ``D/2``.
    allowable : float or array [Pa]
        Allowable shear stress ``k_s``.

    Returns
    -------
    float or array [m]
        The least wire diameter.

    References
    ----------
    [hamabe] Example 1, case (a).

    Examples
    --------
    Hamabe's Example 1, case (a): F_a = 606 kg, r = 6 cm, k_s = 4000 kg/cm^2; the paper
    rounds the result to the 1.7 cm it takes, the formula gives 1.667 cm.

    >>> kgf = 9.80665
    >>> round(float(wire_diameter_for_stress(606 * kgf, 0.06, 4000 * kgf * 1e4)) * 100, 3)  # cm
    1.667
    """
    return np.cbrt(16.0 * np.abs(F) * r / (np.pi * allowable))


def turns_for_stiffness(kappa, d, r, G):
    """Active turns for stiffness ``kappa``: ``n = G d^4 / (64 r^3 kappa)`` (Hamabe, Ex. 1).

    Parameters
    ----------
    kappa : float or array [N/m]
        Axial stiffness required.
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius, ``D/2``.
    G : float or array [Pa]
        Shear modulus of the wire.

    Returns
    -------
    float or array [-]
        Number of active turns.

    References
    ----------
    [hamabe] Example 1, case (a).

    Examples
    --------
    Hamabe's Example 1, case (a): kappa = 59.7 kg per cm, d = 1.7 cm, r = 6 cm,
    G = 850000 kg/cm^2 (the scan's printed result is garbled by the OCR; by hand
    ``850000 x 1.7^4/(64 x 6^3 x 59.7) = 8.60``), after which he takes n = 8.

    >>> kgf = 9.80665
    >>> round(float(turns_for_stiffness(59.7 * kgf * 100, 0.017, 0.06, 850000 * kgf * 1e4)), 2)
    8.6
    """
    return G * d**4 / (64.0 * r**3 * kappa)


def wire_mass(d, r, n, density):
    """Mass of the active coils: wire cross-section ``pi d^2 / 4`` times length ``2 pi r n``.

    Ends and hooks are not included (they depend on the end form, which the sources leave open).

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius, ``D/2``.
    n : float or array [-]
        Number of active turns.
    density : float or array [kg/m^3]
        Density of the wire.

    Returns
    -------
    float or array [kg]
        Mass of the active coils.

    References
    ----------
    [en13906-1] mass of the spring (``D = 2 r``); [hamabe] Example 1 (the spring weighed).

    Examples
    --------
    Hamabe's Example 1, case (a) spring (d = 1.7 cm, r = 6 cm, n = 8) in steel of
    7850 kg/m^3; the paper prints no mass: by hand
    ``7850 x pi 0.017^2/4 x 2 pi 0.06 x 8 = 5.37 kg``, the same as :func:`mass` with D = 2 r.

    >>> round(float(wire_mass(0.017, 0.06, 8, 7850)), 2)  # kg
    5.37
    >>> round(float(mass(0.017, 0.12, 8, 7850)), 2)
    5.37
    """
    return density * (np.pi * d**2 / 4.0) * (2.0 * np.pi * r * n)


def surge_frequency_r(d, r, n, G, density):
    """Lowest surge (longitudinal natural) frequency in Hz, both ends fixed.

    ``f = (1/2) sqrt(kappa / m)`` with ``m`` the active-coil mass (Wahl 1944, ch. 25; Shigley,
    *Mechanical Engineering Design*, eq. 10-25), which with ``D = 2 r`` is
    ``f = d / (8 pi r^2 n) * sqrt(G / (2 rho))``.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    r : float or array [m]
        Mean coil radius, ``D/2``.
    n : float or array [-]
        Number of active turns.
    G : float or array [Pa]
        Shear modulus of the wire.
    density : float or array [kg/m^3]
        Density of the wire.

    Returns
    -------
    float or array [Hz]
        The first surge frequency.

    References
    ----------
    [wahl] ch. 25; [shigley] eq. (10-25); [en13906-1] natural frequency f_e.

    Examples
    --------
    Shigley Example 10-4 (9th ed.) prints 281 Hz from k and W rounded; the same spring in the
    radius form (r = D/2) gives what :func:`surge_frequency` gives, 281.5 Hz.

    >>> inch, psi = 0.0254, 6894.757
    >>> round(float(surge_frequency_r(0.092 * inch, 0.4705 * inch / 2, 21, 11.75e6 * psi, 7861)), 1)
    281.5
    """
    return d / (8.0 * np.pi * r**2 * n) * np.sqrt(G / (2.0 * density))
