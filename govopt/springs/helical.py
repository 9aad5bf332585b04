"""Helical compression and extension springs of round wire: pure, vectorised functions (SI).

Arguments are numpy arrays (or floats) that broadcast together: wire diameter ``d`` (m), mean
coil diameter ``D`` (m; Hamabe's coil radius is ``r = D/2``), active coils ``n``, total coils
``n_t``, forces (N), moduli (Pa), density (kg/m^3). Sources: EN 13906-1:2013 (compression) and
EN 13906-2:2013 (extension); R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering
Design*, 9th ed. (2011), ch. 10 ("Shigley"); A. M. Wahl, *Mechanical Springs* (1963).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

#: Stress-correction factors for :func:`correction_factor`.
CORRECTIONS = ("none", "wahl", "bergstrasser")

#: The default correction per use: EN 13906-1/-2 use the uncorrected stress for static and
#: quasi-static checks and k (Bergstraesser) for fatigue; Shigley uses K_B for both.
DEFAULT_CORRECTION = {("EN13906", "static"): "none", ("EN13906", "fatigue"): "bergstrasser",
                      ("Shigley", "static"): "bergstrasser",
                      ("Shigley", "fatigue"): "bergstrasser"}

class EndForm(NamedTuple):
    """A compression spring's end form: its solid length ``L_c = (n_t + extra) d_max``, the
    inactive coils ``n_t - n`` it takes, and where both come from."""

    extra: float
    source: str
    end_coils: float = 2.0


#: End forms of compression springs (:class:`EndForm`). EN 13906-1:2013 gives the solid length
#: of cold-coiled springs with closed ends, ground or not, and of hot-coiled ones, always with
#: the largest wire diameter ``d_max`` (the nominal one plus its tolerance,
#: :func:`govopt.springs.tolerances.max_wire_diameter`); open ends are Shigley's (Table 10-1:
#: plain ends ``N_t = N_a``, ``L_s = d (N_t + 1)``; plain and ground ``N_t = N_a + 1``,
#: ``L_s = d N_t``). ``plain``, ``plain_ground`` and ``squared`` are the same forms by
#: Shigley's names (``squared``: his closed-end solid length ``d (N_t + 1)``).
END_FORMS = {
    "closed_ground": EndForm(0.0, "EN 13906-1:2013 (solid length): cold coiled, ends closed and "
                                  "ground, L_c <= n_t d_max, n_t = n + 2; Shigley Table 10-1 "
                                  "squared and ground L_s = d N_t"),
    "closed": EndForm(1.5, "EN 13906-1:2013 (solid length): cold coiled, ends closed, not ground, "
                           "L_c <= (n_t + 1.5) d_max, n_t = n + 2"),
    "open_ground": EndForm(0.0, "Shigley 9th ed. Table 10-1: plain and ground ends, N_t = N_a + "
                                "1, L_s = d N_t (EN 13906-1 gives closed ends only)", 1.0),
    "open": EndForm(1.0, "Shigley 9th ed. Table 10-1: plain ends, N_t = N_a, L_s = d (N_t + 1) "
                         "(EN 13906-1 gives closed ends only)", 0.0),
    "hot_closed_ground": EndForm(-0.3, "EN 13906-1:2013 (solid length): hot coiled, ends closed "
                                       "and ground, L_c <= (n_t - 0.3) d_max"),
    "hot_open": EndForm(1.1, "EN 13906-1:2013 (solid length): hot coiled, ends open, not ground, "
                             "L_c <= (n_t + 1.1) d_max"),
    "squared": EndForm(1.0, "Shigley 9th ed. Table 10-1: squared or closed ends, N_t = N_a + 2, "
                            "L_s = d (N_t + 1)"),
    "plain": EndForm(1.0, "Shigley 9th ed. Table 10-1: plain ends, N_t = N_a, L_s = d (N_t + 1)",
                     0.0),
    "plain_ground": EndForm(0.0, "Shigley 9th ed. Table 10-1: plain and ground ends, N_t = N_a + "
                                 "1, L_s = d N_t", 1.0),
}


class HookForm(NamedTuple):
    """An extension spring's loop: its length ``L_H`` from the body's end to the inside of the
    loop as a multiple of the inside diameter ``D_i = D - d``, the coils of wire it takes, and
    where the figures come from."""

    length: float
    coils: float
    source: str


#: Loops of extension springs after EN 13906-2:2013 (as Gutekunst Federn lists them, "Eyelet
#: shapes extension springs", blog.federnshop.com): the free length inside the loops is
#: ``L0 = L_K + 2 L_H`` with the body ``L_K = (n_b + 1) d``. Where EN 13906-2 gives a range, the
#: value used is named in the source; the loops' added flexibility ``G/E`` coil (Shigley 9th
#: ed. section 10-11, for full loops) is taken for every form.
HOOKS = {
    "full_loop": HookForm(1.0, 1.0, "full (German) loop, L_H = 0.8-1.1 D_i (EN 13906-2): "
                                    "L_H = D_i, Shigley's L0 = 2 (D - d) + (N_b + 1) d"),
    "half_loop": HookForm(0.675, 0.5, "half (German) loop, L_H = 0.55-0.8 D_i (EN 13906-2): the "
                                      "middle, 0.675 D_i"),
    "side_loop": HookForm(1.0, 1.0, "full loop raised at the side, L_H ~ D_i (EN 13906-2)"),
    "english_loop": HookForm(1.1, 1.0, "English loop, L_H ~ 1.1 D_i (EN 13906-2)"),
}


#: End conditions for buckling: EN 13906-1 seating coefficient nu (= Shigley's alpha, Table 10-2).
SEATING = {
    "fixed-free": 2.0,      # one end clamped, the other free
    "hinged-hinged": 1.0,   # both ends pivoted (guided, free to tilt)
    "fixed-hinged": 0.7,    # one end clamped, the other pivoted (0.707 in Shigley)
    "fixed-fixed": 0.5,     # both ends clamped between flat parallel plates
}


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

def solid_length(d_max, n_t, ends: str = "closed_ground"):
    """Solid (block) length ``L_c = (n_t + extra) d_max`` for the end form ``ends`` (m).

    See :data:`END_FORMS` for the forms and their clauses. EN 13906-1 writes it with the
    largest wire diameter within tolerance ``d_max`` (nominal ``d`` plus its tolerance,
    :func:`govopt.springs.tolerances.max_wire_diameter`): pass that, the nominal ``d`` only
    where the wire's tolerance is unknown. A hand calculation: 10 total coils of 2.8 mm
    EN 10270-1 wire (+-0.030 mm) with closed and ground ends, ``L_c = 10 x 2.830 = 28.30 mm``
    (rounded to 0.01 mm as written by hand).

    Parameters
    ----------
    d_max : float or array [m]
        Largest wire diameter within tolerance (nominal where the tolerance is unknown).
    n_t : float or array [-]
        Total number of coils.
    ends : str [-]
        End form, a key of :data:`END_FORMS`.

    References
    ----------
    [en13906-1] solid length L_c; [en10270-1] wire tolerance of the example.


    >>> round(float(solid_length(2.8e-3 + 0.030e-3, 10, "closed_ground")) * 1e3, 2)
    28.3
    >>> round(float(solid_length(2.83e-3, 10, "closed")) * 1e3, 3)  # (n_t + 1.5) d_max
    32.545
    """
    try:
        extra = END_FORMS[ends].extra
    except KeyError:
        raise ValueError(f"end form must be one of {tuple(END_FORMS)}, got {ends!r}") from None
    return (np.asarray(n_t, dtype=float) + extra) * d_max


def end_coils(ends: str) -> float:
    """Inactive coils ``n_t - n`` of the end form ``ends`` (:data:`END_FORMS`): 2 for closed
    ends (EN 13906-1, cold coiled), 1 for open and ground, 0 for open ends (Shigley Table
    10-1).

    Parameters
    ----------
    ends : str [-]
        End form, a key of :data:`END_FORMS`; anything else is a ValueError.

    Returns
    -------
    float [-]
        Inactive coils, ``n_t - n``.

    References
    ----------
    [en13906-1] solid length (cold coiled, closed ends: n_t = n + 2); [shigley] Table 10-1.

    Examples
    --------
    Shigley Table 10-1: squared ends N_t = N_a + 2, plain and ground N_t = N_a + 1, plain
    ends N_t = N_a.

    >>> [end_coils(e) for e in ("squared", "plain_ground", "plain")]
    [2.0, 1.0, 0.0]
    """
    try:
        return END_FORMS[ends].end_coils
    except KeyError:
        raise ValueError(f"end form must be one of {tuple(END_FORMS)}, got {ends!r}") from None


def sum_of_min_gaps(d, D, n, dynamic: bool = False, hot: bool = False):
    """Minimum sum of gaps between active coils at the least working length, ``S_a`` (m).

    EN 13906-1:2013 (least working length): cold coiled ``S_a = n (0.0015 D^2/d + 0.1 d)``,
    hot coiled ``S_a = 0.02 n (D + d)``; under dynamic load multiplied by 1.5 (cold) or 2 (hot). The
    constants are dimensionless (``D^2/d`` is a length), so the formula holds in any unit.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    dynamic : bool [-]
        The spring works under dynamic load.
    hot : bool [-]
        The spring is hot coiled.

    Returns
    -------
    float or array [m]
        The least sum of the gaps, ``S_a``.

    References
    ----------
    [en13906-1] least working length, S_a.

    Examples
    --------
    A hand calculation: 10 coils of 2 mm wire on a 20 mm coil, cold coiled, static:
    ``10 (0.0015 x 400/2 + 0.1 x 2) = 10 (0.3 + 0.2) = 5.0 mm``; dynamic 1.5 times that.

    >>> round(float(sum_of_min_gaps(2e-3, 20e-3, 10)) * 1e3, 3)  # mm
    5.0
    >>> round(float(sum_of_min_gaps(2e-3, 20e-3, 10, dynamic=True)) * 1e3, 3)  # mm
    7.5
    """
    d = np.asarray(d, dtype=float)
    if hot:
        return 0.02 * n * (D + d) * (2.0 if dynamic else 1.0)
    return n * (0.0015 * D**2 / d + 0.1 * d) * (1.5 if dynamic else 1.0)


def min_working_length(d, D, n, n_t, ends: str = "closed_ground", dynamic: bool = False,
                       hot: bool = False, d_max=None):
    """Least admissible working length ``L_n = L_c + S_a`` (EN 13906-1:2013), m: the solid
    length with the largest wire diameter ``d_max`` (default: ``d``, where its tolerance is
    unknown) and the gaps :func:`sum_of_min_gaps` with the nominal ``d``.

    Parameters
    ----------
    d : float or array [m]
        Nominal wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    n_t : float or array [-]
        Total number of coils.
    ends : str [-]
        End form, a key of :data:`END_FORMS`.
    dynamic : bool [-]
        The spring works under dynamic load.
    hot : bool [-]
        The spring is hot coiled.
    d_max : float or array or None [m]
        Largest wire diameter within tolerance (``None``: ``d``).

    Returns
    -------
    float or array [m]
        The least working length ``L_n``.

    References
    ----------
    [en13906-1] least working length L_n = L_c + S_a.

    Examples
    --------
    A hand calculation: 12 coils (10 active) of 2 mm wire, closed and ground, on a 20 mm coil:
    ``L_c = 12 x 2 = 24 mm`` and ``S_a = 5 mm`` (:func:`sum_of_min_gaps`), 29 mm.

    >>> round(float(min_working_length(2e-3, 20e-3, 10, 12)) * 1e3, 3)  # mm
    29.0
    """
    return (solid_length(d if d_max is None else d_max, n_t, ends)
            + sum_of_min_gaps(d, D, n, dynamic, hot))


def pitch(L0, d, n, n_t, ends: str = "closed_ground", d_max=None):
    """Pitch of the active coils ``m = (L0 - L_c)/n + d = s_c/n + d`` (m): the free gap shared
    by n coils, with EN 13906-1's solid length ``L_c`` (:func:`solid_length` with the largest
    wire diameter ``d_max``, default ``d``), as SpringONE's EN 13906-1 solver computes it
    (``SpringLIB/src/EN13906.pas``: pitch ``S_c / n + d``, ``S_c = L0 - L_c``).

    Equals Shigley Table 10-1's ``(L0 - 3d)/N_a`` for squared ends and ``(L0 - 2d)/N_a`` for
    squared and ground ends (with N_t = N_a + 2 and ``d_max = d``).

    Parameters
    ----------
    L0 : float or array [m]
        Free length.
    d : float or array [m]
        Nominal wire diameter.
    n : float or array [-]
        Number of active coils.
    n_t : float or array [-]
        Total number of coils.
    ends : str [-]
        End form, a key of :data:`END_FORMS`.
    d_max : float or array or None [m]
        Largest wire diameter within tolerance (``None``: ``d``).

    Returns
    -------
    float or array [m]
        Pitch of the active coils.

    References
    ----------
    [en13906-1] solid length L_c and s_c = L0 - L_c; [shigley] Table 10-1.

    Examples
    --------
    A hand calculation: 50 mm free, 12 coils (10 active) of 2 mm wire, closed and ground:
    ``(50 - 24)/10 + 2 = 4.6 mm``; with squared ends (unground) Shigley's ``(L0 - 3d)/N_a``
    gives 4.4 mm.

    >>> round(float(pitch(50e-3, 2e-3, 10, 12)) * 1e3, 3)  # mm
    4.6
    >>> round(float(pitch(50e-3, 2e-3, 10, 12, "squared")) * 1e3, 3)  # mm, (50 - 6)/10
    4.4
    """
    return (L0 - solid_length(d if d_max is None else d_max, n_t, ends)) / n + d


def helix_angle(m, D):
    """Pitch (helix) angle of the coils ``alpha = atan(m / (pi D))`` (rad): one turn of mean
    diameter ``D`` (m) advances the pitch ``m`` (m) along the axis.

    The geometry of the helix (one coil unrolled is a right triangle of legs ``pi D`` and
    ``m``); the pitch angle whose effect on the rate :func:`open_coil_stiffness` takes.

    Parameters
    ----------
    m : float or array [m]
        Pitch of the coils.
    D : float or array [m]
        Mean coil diameter.

    Returns
    -------
    float or array [rad]
        The helix angle.

    References
    ----------
    [wahl] the effect of the pitch angle (the angle's definition).

    Examples
    --------
    A hand check: ``atan(35/(24 pi)) = atan(0.4642) = 24.9 deg`` for a 35 mm pitch on a
    24 mm coil.

    >>> round(float(np.degrees(helix_angle(35e-3, 24e-3))), 1)
    24.9
    """
    return np.arctan(np.asarray(m, dtype=float) / (np.pi * np.asarray(D, dtype=float)))


def max_pitch(d, D):
    """Largest pitch of a compression spring ``m_max = 0.7 D_i = 0.7 (D - d)`` (m).

    Gutekunst Federn, "Spring pitch" (blog.federnshop.com, 2024): the largest pitch 0.7 D_i,
    exceeded "in rare exceptional cases" only. The helix angle there, ``atan(0.7 (1 - 1/w)/pi)``,
    is 9.5 deg at the index w = 4, 11.9 deg at w = 20 and below 12.6 deg at any index: the simple
    rate :func:`stiffness` is then within 1.5 % of :func:`open_coil_stiffness` (steel), against
    6 % at the 25 deg of a 35 mm pitch on a 24 mm coil.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.

    Returns
    -------
    float or array [m]
        The largest pitch, 0.7 times the inside diameter.

    Examples
    --------
    A hand check at the index w = 4: ``atan(0.7 x 3/(4 pi)) = atan(0.1671) = 9.49 deg``.

    >>> round(float(np.degrees(helix_angle(max_pitch(1.0, 4.0), 4.0))), 2)  # w = 4
    9.49
    """
    return 0.7 * (np.asarray(D, dtype=float) - d)


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


def critical_free_length(D, G, E, nu):
    """Longest free length that cannot buckle: ``L0_cr = pi D / nu sqrt((1 - G/E)/(0.5 + G/E))``.

    The root of EN 13906-1's buckling formula (:func:`buckling_deflection`): for ``L0 < L0_cr``
    the root is imaginary and the spring is stable at any deflection. For steel
    (G/E = 11.5/30) this is Shigley eq. (10-13), ``L0 < 2.63 D / alpha``.

    Parameters
    ----------
    D : float or array [m]
        Mean coil diameter.
    G : float or array [Pa]
        Shear modulus of the wire (only ``G/E`` matters: any common unit).
    E : float or array [Pa]
        Young's modulus of the wire.
    nu : float or array [-]
        Seating coefficient of the ends (:data:`SEATING`; Shigley's alpha).

    Returns
    -------
    float or array [m]
        The critical free length.

    References
    ----------
    [en13906-1] 9.14 (buckling); [shigley] eq. (10-13).

    Examples
    --------
    Shigley Problem 10-3 (10th ed. solutions manual): music wire, D = 31 - 2.5 = 28.5 mm,
    ends between flat plates (alpha = 0.5), prints (L0)_cr = 149.9 mm from 2.63 D/alpha; the
    root itself is 2.6249 D/alpha (Shigley rounds it up), so 149.6 mm:

    >>> round(float(critical_free_length(1.0, 11.5, 30.0, 1.0)), 4)  # Shigley's 2.63
    2.6249
    >>> round(float(critical_free_length(28.5e-3, 11.5, 30.0, 0.5)) * 1e3, 1)  # mm
    149.6
    """
    ratio = np.asarray(G, dtype=float) / E
    return np.pi * D / nu * np.sqrt((1.0 - ratio) / (0.5 + ratio))


def buckling_deflection(L0, D, G, E, nu):
    """Deflection at which a compression spring buckles, ``s_K`` (m); ``inf`` if it cannot.

    EN 13906-1:2013, 9.14:
    ``s_K = L0 0.5/(1 - G/E) [1 - sqrt(1 - (1 - G/E)/(0.5 + G/E) (pi D/(nu L0))^2)]``,
    with ``nu`` from :data:`SEATING`. The spring is safe when ``s / s_K < 1``.

    Parameters
    ----------
    L0 : float or array [m]
        Free length.
    D : float or array [m]
        Mean coil diameter.
    G : float or array [Pa]
        Shear modulus of the wire (only ``G/E`` matters).
    E : float or array [Pa]
        Young's modulus of the wire.
    nu : float or array [-]
        Seating coefficient of the ends (:data:`SEATING`).

    Returns
    -------
    float or array [m]
        The buckling deflection ``s_K``; ``inf`` below :func:`critical_free_length`.

    References
    ----------
    [en13906-1] 9.14 (buckling); [shigley] eq. (10-10), the same formula.

    Examples
    --------
    Two hand checks, steel (G = 81.5, E = 206 GPa), a 30 mm coil with both ends pivoted
    (nu = 1): 50 mm free is below the critical 77.4 mm and cannot buckle; 200 mm free buckles
    after ``0.2 x 0.5/0.6044 x (1 - sqrt(1 - 0.6748 x 0.2221)) = 12.9 mm``.

    >>> float(buckling_deflection(0.05, 0.03, 81.5e9, 206e9, 1.0))
    inf
    >>> round(float(buckling_deflection(0.2, 0.03, 81.5e9, 206e9, 1.0)) * 1e3, 1)  # mm
    12.9
    """
    L0 = np.asarray(L0, dtype=float)
    ratio = np.asarray(G, dtype=float) / E
    radicand = 1.0 - (1.0 - ratio) / (0.5 + ratio) * (np.pi * D / (nu * L0)) ** 2
    with np.errstate(invalid="ignore"):
        sK = L0 * 0.5 / (1.0 - ratio) * (1.0 - np.sqrt(radicand))
    return np.where(radicand < 0.0, np.inf, sK)


def diameter_increase(d, D, n, L0, n_t, ends: str = "closed_ground", d_max=None):
    """Increase of the outside diameter at solid length, ``Delta D_e`` (m), EN 13906-1:2013:
    ``0.1 (m^2 - 0.8 m d - 0.2 d^2)/D`` with the pitch ``m`` of :func:`pitch` (ends free to turn).

    Parameters
    ----------
    d : float or array [m]
        Nominal wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    L0 : float or array [m]
        Free length.
    n_t : float or array [-]
        Total number of coils.
    ends : str [-]
        End form, a key of :data:`END_FORMS`.
    d_max : float or array or None [m]
        Largest wire diameter within tolerance (``None``: ``d``).

    Returns
    -------
    float or array [m]
        The increase of the outside diameter.

    References
    ----------
    [en13906-1] increase of the coil diameter on compression.

    Examples
    --------
    A hand calculation in mm, the spring of :func:`pitch` (m = 4.6 mm, d = 2 mm, D = 20 mm):
    ``0.1 (21.16 - 7.36 - 0.8)/20 = 0.065 mm``.

    >>> round(float(diameter_increase(2e-3, 20e-3, 10, 50e-3, 12)) * 1e3, 4)  # mm
    0.065
    """
    m = pitch(L0, d, n, n_t, ends, d_max)
    return 0.1 * (m**2 - 0.8 * m * d - 0.2 * np.asarray(d, dtype=float) ** 2) / D


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


# ---------------------------------------------------------------- extension springs

def extension_active_coils(n_body, G, E):
    """Active coils of an extension spring with hooks, ``N_a = N_b + G/E`` (Shigley §10-11):
    the two end loops add the flexibility of G/E coil.

    Parameters
    ----------
    n_body : float or array [-]
        Body coils ``N_b``.
    G : float or array [Pa]
        Shear modulus of the wire.
    E : float or array [Pa]
        Young's modulus of the wire.

    Returns
    -------
    float or array [-]
        Active coils ``N_a``.

    References
    ----------
    [shigley] section 10-11 (the loops' added G/E coil).

    Examples
    --------
    Shigley Example 10-6 (9th ed.): N_b = 12.17, G = 11.6 and E = 28.7 Mpsi, prints
    N_a = 12.57.

    >>> round(float(extension_active_coils(12.17, 11.6e6, 28.7e6)), 2)
    12.57
    """
    return n_body + np.asarray(G, dtype=float) / E


def extension_body_length(d, n_body):
    """Body length of a close-wound extension spring ``L_b = d (N_b + 1)`` (Shigley §10-11), m.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    n_body : float or array [-]
        Body coils ``N_b``.

    Returns
    -------
    float or array [m]
        Body length ``L_b``.

    References
    ----------
    [shigley] section 10-11.

    Examples
    --------
    Shigley Example 10-6 (9th ed.): d = 0.035 in, N_b = 12.17; by hand 0.035 x 13.17 =
    0.461 in.

    >>> round(float(extension_body_length(0.035 * 0.0254, 12.17)) / 0.0254, 3)  # in
    0.461
    """
    return np.asarray(d, dtype=float) * (n_body + 1.0)


def extension_free_length(d, D, n_body):
    """Free length inside two full loops ``L0 = 2 (D - d) + (N_b + 1) d`` (Shigley §10-11), m:
    each loop adds its inside diameter ``D - d`` to the body length.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n_body : float or array [-]
        Body coils ``N_b``.

    Returns
    -------
    float or array [m]
        Free length inside the loops.

    References
    ----------
    [shigley] section 10-11.

    Examples
    --------
    Shigley Example 10-6 (9th ed.): d = 0.035 in, OD = 0.248 in, N_b = 12.17, prints
    L0 = 0.817 in.

    >>> inch = 0.0254
    >>> round(float(extension_free_length(0.035 * inch, 0.213 * inch, 12.17)) / inch, 3)
    0.817
    """
    return 2.0 * (D - d) + extension_body_length(d, n_body)


def initial_tension_range(C):
    """Preferred range of the *uncorrected* initial-tension stress (Pa) at index ``C``.

    Shigley 9th ed. eq. (10-40), fitted by Shigley to the SMI chart in psi:
    ``tau_i = 33500 / exp(0.105 C) +- 1000 (4 - (C - 3)/6.5)`` psi. Returns ``(low, high)``.

    Parameters
    ----------
    C : float or array [-]
        Spring index ``D/d``, dimensionless.

    References
    ----------
    [shigley] eq. (10-40); Shigley Example 10-6 (printed in kpsi, rounded to 0.1 kpsi).

    >>> lo, hi = initial_tension_range(6.086)  # Shigley Example 10-6: 14.2 to 21.2 kpsi
    >>> round(float(lo) / 6894.757e3, 1), round(float(hi) / 6894.757e3, 1)
    (14.2, 21.2)
    """
    C = np.asarray(C, dtype=float)
    psi = 6894.757293168361  # Pa (lbf/in^2)
    mid = 33500.0 / np.exp(0.105 * C)
    half = 1000.0 * (4.0 - (C - 3.0) / 6.5)
    return (mid - half) * psi, (mid + half) * psi


def hook_bending_factor(C1):
    """Curvature factor for bending at the hook's inner fibre (point A, Shigley Fig. 10-7a):
    ``(K)_A = (4 C1^2 - C1 - 1) / (4 C1 (C1 - 1))`` with ``C1 = 2 r1 / d`` (Shigley §10-11).

    Parameters
    ----------
    C1 : float or array [-]
        Index of the hook's bend, ``2 r1 / d``, dimensionless.

    Returns
    -------
    float or array [-]
        The factor ``(K)_A``.

    References
    ----------
    [shigley] section 10-11, Fig. 10-7a (point A).

    Examples
    --------
    Shigley Example 10-6 (9th ed.): r1 = 0.106 in, d = 0.035 in, prints (K)_A = 1.140.

    >>> round(float(hook_bending_factor(2 * 0.106 / 0.035)), 3)
    1.14
    """
    C1 = np.asarray(C1, dtype=float)
    return (4.0 * C1**2 - C1 - 1.0) / (4.0 * C1 * (C1 - 1.0))


def hook_torsion_factor(C2):
    """Curvature factor for torsion at the hook's side bend (point B, Shigley Fig. 10-7b):
    ``(K)_B = (4 C2 - 1) / (4 C2 - 4)`` with ``C2 = 2 r2 / d`` (Shigley §10-11).

    Parameters
    ----------
    C2 : float or array [-]
        Index of the side bend, ``2 r2 / d``, dimensionless.

    Returns
    -------
    float or array [-]
        The factor ``(K)_B``.

    References
    ----------
    [shigley] section 10-11, Fig. 10-7b (point B).

    Examples
    --------
    Shigley Example 10-6 (9th ed.): r2 = 0.089 in, d = 0.035 in (C2 = 5.086), prints
    (K)_B = 1.184.

    >>> round(float(hook_torsion_factor(2 * 0.089 / 0.035)), 3)
    1.184
    """
    C2 = np.asarray(C2, dtype=float)
    return (4.0 * C2 - 1.0) / (4.0 * C2 - 4.0)


def hook_bending_stress(F, d, D, r1):
    """Normal stress at the hook's point A: bending plus direct tension (Pa), Shigley §10-11:
    ``sigma_A = F [(K)_A 16 D / (pi d^3) + 4 / (pi d^2)]`` with ``r1`` the hook's mean radius.

    Parameters
    ----------
    F : float or array [N]
        Axial force on the spring (its magnitude is used).
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    r1 : float or array [m]
        Mean radius of the hook (Shigley Fig. 10-7a).

    Returns
    -------
    float or array [Pa]
        The normal stress at A.

    References
    ----------
    [shigley] section 10-11, Fig. 10-7a (point A).

    Examples
    --------
    Shigley Example 10-6 (9th ed.): 5.25 lbf, d = 0.035 in, D = 0.213 in, r1 = 0.106 in,
    prints sigma_A = 156.9 kpsi.

    >>> inch, lbf, ksi = 0.0254, 4.4482216152605, 6894757.293168361
    >>> F, d, D = 5.25 * lbf, 0.035 * inch, 0.213 * inch
    >>> round(float(hook_bending_stress(F, d, D, 0.106 * inch)) / ksi, 1)  # kpsi
    156.9
    """
    d = np.asarray(d, dtype=float)
    KA = hook_bending_factor(2.0 * r1 / d)
    return np.abs(F) * (KA * 16.0 * D / (np.pi * d**3) + 4.0 / (np.pi * d**2))


def hook_torsion_stress(F, d, D, r2):
    """Shear stress at the hook's point B (Pa), Shigley §10-11:
    ``tau_B = (K)_B 8 F D / (pi d^3)`` with ``r2`` the bend radius where the hook leaves the
    body.

    Parameters
    ----------
    F : float or array [N]
        Axial force on the spring (its magnitude is used).
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    r2 : float or array [m]
        Radius of the side bend (Shigley Fig. 10-7b).

    Returns
    -------
    float or array [Pa]
        The shear stress at B.

    References
    ----------
    [shigley] section 10-11, Fig. 10-7b (point B).

    Examples
    --------
    Shigley Example 10-6 (9th ed.): 5.25 lbf, d = 0.035 in, D = 0.213 in, r2 = 0.089 in,
    prints tau_B = 78.6 kpsi.

    >>> inch, lbf, ksi = 0.0254, 4.4482216152605, 6894757.293168361
    >>> F, d, D = 5.25 * lbf, 0.035 * inch, 0.213 * inch
    >>> round(float(hook_torsion_stress(F, d, D, 0.089 * inch)) / ksi, 1)  # kpsi
    78.6
    """
    d = np.asarray(d, dtype=float)
    return hook_torsion_factor(2.0 * r2 / d) * 8.0 * np.abs(F) * D / (np.pi * d**3)


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
