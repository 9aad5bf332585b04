"""A helical compression spring's lengths, pitch and buckling (EN 13906-1).

The end forms and their inactive coils, the solid length and the sum of the least gaps between
active coils, the least working length, the pitch and helix angle of the coils, the largest pitch
that coiling allows, the critical free length and the buckling deflection, and the coil
diameter's increase under load. All SI; functions broadcast over numpy arrays. The rate, the
stresses, the mass and the surge frequency of any helical spring are in
:mod:`govopt.springs.helical`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


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


#: End conditions for buckling: EN 13906-1 seating coefficient nu (= Shigley's alpha, Table 10-2).
SEATING = {
    "fixed-free": 2.0,      # one end clamped, the other free
    "hinged-hinged": 1.0,   # both ends pivoted (guided, free to tilt)
    "fixed-hinged": 0.7,    # one end clamped, the other pivoted (0.707 in Shigley)
    "fixed-fixed": 0.5,     # both ends clamped between flat parallel plates
}


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
