"""Manufacturing tolerances of cold-coiled compression springs (EN 15800) and their effect.

EN 15800:2008 (successor of DIN 2095) defines quality grades 1 (finest), 2 (default) and 3 for
the coil diameter, the spring forces at given lengths and the free length; the wire diameter
tolerance comes from the wire standard (EN 10270). The stored sources hold the standard's
coil-diameter table only as transcribed by spring makers and spring software (Gutekunst
"Toleranzen Druckfedern" up to D = 16 mm; SpringONE ``EN15800.pas`` for all rows - they agree
where both exist) and its force formula as coded by SpringONE; the clause text itself is not in
the stored sources.

All functions are vectorised and SI (m, N, N/m); the standard's formulas are in mm and N and are
converted here.
"""

from __future__ import annotations

import numpy as np

from .tables import row_index, within

#: Quality grades and their factor Q on force and free-length tolerances (EN 15800).
GRADES = (1, 2, 3)
Q_FACTOR = {1: 0.63, 2: 1.0, 3: 1.6}

# EN 15800 Table 1: +- tolerance of the mean coil diameter (mm) by D (upper bound of each row, mm)
# and, per grade 1/2/3, index w in 4-8, 8-14, 14-20.
_AD_D = np.array([1.0, 1.6, 2.5, 4.0, 6.3, 10.0, 16.0, 25.0, 31.5, 40.0, 50.0, 63.0, 80.0,
                  100.0, 125.0, 160.0, 200.0])
_AD = np.array([
    [0.05, 0.07, 0.10, 0.07, 0.10, 0.15, 0.10, 0.15, 0.20],
    [0.05, 0.07, 0.10, 0.08, 0.10, 0.15, 0.15, 0.20, 0.30],
    [0.07, 0.10, 0.15, 0.10, 0.15, 0.20, 0.20, 0.30, 0.40],
    [0.10, 0.10, 0.15, 0.15, 0.20, 0.25, 0.30, 0.40, 0.50],
    [0.10, 0.15, 0.20, 0.20, 0.25, 0.30, 0.40, 0.50, 0.60],
    [0.15, 0.15, 0.20, 0.25, 0.30, 0.35, 0.50, 0.60, 0.70],
    [0.15, 0.20, 0.25, 0.30, 0.35, 0.40, 0.60, 0.70, 0.80],
    [0.20, 0.25, 0.30, 0.35, 0.45, 0.50, 0.70, 0.90, 1.00],
    [0.25, 0.30, 0.35, 0.40, 0.50, 0.60, 0.80, 1.00, 1.20],
    [0.25, 0.30, 0.35, 0.50, 0.60, 0.70, 1.00, 1.20, 1.50],
    [0.30, 0.40, 0.50, 0.60, 0.80, 0.90, 1.20, 1.50, 1.80],
    [0.40, 0.50, 0.60, 0.80, 1.00, 1.10, 1.50, 2.00, 2.30],
    [0.50, 0.70, 0.80, 1.00, 1.20, 1.40, 1.80, 2.40, 2.80],
    [0.60, 0.80, 0.90, 1.20, 1.50, 1.70, 2.30, 3.00, 3.50],
    [0.70, 1.00, 1.10, 1.40, 1.90, 2.20, 2.80, 3.70, 4.40],
    [0.90, 1.20, 1.40, 1.80, 2.30, 2.70, 3.50, 4.60, 5.40],
    [1.20, 1.50, 1.70, 2.10, 2.90, 3.30, 4.20, 5.70, 6.60],
])

_IN = 25.4  # mm per inch: the ASTM tables are in inches

#: Wire diameter tolerances (+- mm) by diameter (upper bound of each row, mm): EN 10270-1 and
#: EN 10270-2, as tabulated in SpringONE ``WIRETOL.csv``; ASTM A228 (music wire: 0.004 to 0.250
#: in) and ASTM A227 and A229 (hard-drawn and oil-tempered: 0.020 to 0.625 in), the
#: "permissible variations in wire diameter" of the standards as Insteel Wire / Interwire Group
#: quote them on their product pages (tinned music wire to A228; bright hard-drawn MB to A227;
#: oil-tempered MB class I and II to A229: the same table for both). The other grades' standards
#: (ASTM A232 and A401, EN 10270-3) have no table here: their nominal d is taken, and named so.
WIRE_TOLERANCE = {
    "EN10270-1": (np.array([0.09, 0.16, 0.25, 0.63, 0.75, 1.0, 1.2, 1.7, 2.6, 4.0, 5.3, 7.0, 9.0,
                            10.0, 11.0, 14.0, 18.0, 20.0]),
                  np.array([0.003, 0.004, 0.005, 0.008, 0.010, 0.015, 0.020, 0.020, 0.025, 0.030,
                            0.035, 0.040, 0.045, 0.050, 0.070, 0.080, 0.090, 0.100])),
    "EN10270-2": (np.array([0.85, 1.05, 1.7, 3.0, 4.2, 6.0, 7.5, 9.0, 11.0, 13.0, 16.0, 17.0]),
                  np.array([0.010, 0.015, 0.020, 0.025, 0.030, 0.035, 0.040, 0.045, 0.050, 0.070,
                            0.080, 0.090])),
    "ASTM A228": (np.array([0.010, 0.028, 0.063, 0.080, 0.250]) * _IN,
                  np.array([0.0002, 0.0003, 0.0004, 0.0005, 0.001]) * _IN),
    "ASTM A227": (np.array([0.028, 0.075, 0.375, 0.625]) * _IN,
                  np.array([0.0008, 0.001, 0.002, 0.003]) * _IN),
    "ASTM A229": (np.array([0.028, 0.075, 0.375, 0.625]) * _IN,
                  np.array([0.0008, 0.001, 0.002, 0.003]) * _IN),
}


def _check_grade(grade):
    if grade not in GRADES:
        raise ValueError(f"EN 15800 quality grade must be one of {GRADES}, got {grade!r}")


def coil_diameter_tolerance(D, w, grade: int = 2):
    """+- tolerance of the mean coil diameter ``A_D`` (m), EN 15800 Table 1.

    ``D`` in m (0.63-200 mm), ``w = D/d`` (4-20); NaN outside the table.

    Parameters
    ----------
    D : float or array [m]
        Mean coil diameter.
    w : float or array [-]
        Spring index ``D/d``, dimensionless.
    grade : int [-]
        EN 15800 quality grade 1, 2 or 3 (dimensionless).

    Returns
    -------
    float or array [m]
        The +- tolerance ``A_D``.

    References
    ----------
    [en15800] Table 1 (as transcribed by Gutekunst and SpringONE; see the module).

    Examples
    --------
    The spring of Shigley Problem 10-3 (d = 2.5 mm, D = 28.5 mm, 13 active coils); the standard's
    own examples are not in the stored sources, so the value is checked by hand.
    D = 28.5 mm lies in the row 25-31.5 mm, w = 11.4 in the column 8-14 of grade 2: 0.50 mm.

    >>> round(float(coil_diameter_tolerance(28.5e-3, 11.4, 2)) * 1e3, 2)  # mm
    0.5
    """
    _check_grade(grade)
    Dmm = np.asarray(D, dtype=float) * 1e3
    w = np.asarray(w, dtype=float)
    row = row_index(_AD_D, Dmm)
    col = np.minimum(row_index((8.0, 14.0), w), 2) + 3 * (grade - 1)
    ok = within(Dmm, 0.63, 200.0) & within(w, 4.0, 20.0)
    return np.where(ok, _AD[np.minimum(row, len(_AD_D) - 1), col] * 1e-3, np.nan)


def alpha_F(d, D):
    """EN 15800 force-tolerance base ``alpha_F`` (N):
    ``65.92 d^3.3 / D^1.6 (-0.84 (w/10)^3 + 3.781 (w/10)^2 - 4.244 (w/10) + 2.274)`` with d, D
    in mm and ``w = D/d``.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.

    Returns
    -------
    float or array [N]
        The force-tolerance base ``alpha_F``.

    References
    ----------
    [en15800] force tolerance (the formula as coded by SpringONE; see the module).

    Examples
    --------
    The spring of Shigley Problem 10-3 (d = 2.5 mm, D = 28.5 mm, 13 active coils); the standard's
    own examples are not in the stored sources, so the value is checked by hand.
    ``65.92 * 2.5^3.3 / 28.5^1.6 * (-0.84 * 1.14^3 + 3.781 * 1.14^2 - 4.244 * 1.14 + 2.274)
    = 7.045`` N.

    >>> round(float(alpha_F(2.5e-3, 28.5e-3)), 3)
    7.045
    """
    dmm = np.asarray(d, dtype=float) * 1e3
    Dmm = np.asarray(D, dtype=float) * 1e3
    x = Dmm / dmm / 10.0
    return 65.92 * dmm**3.3 / Dmm**1.6 * (-0.84 * x**3 + 3.781 * x**2 - 4.244 * x + 2.274)


def k_F(n):
    """EN 15800 factor for the number of active coils ``k_F = 1/(3 n^2) + 8/(5 n) + 0.803``
    (as coded in SpringONE; one other public transcription writes the first term with a minus
    sign and n - 1.75 for n; with the same n the two differ by 2/(3 n^2), under 1 % for n >= 10).

    Parameters
    ----------
    n : float or array [-]
        Number of active coils.

    Returns
    -------
    float or array [-]
        The factor ``k_F``.

    References
    ----------
    [en15800] force tolerance (as coded by SpringONE; see the module).

    Examples
    --------
    Checked by hand: ``n = 10`` gives ``1/300 + 0.16 + 0.803 = 0.96633``.

    >>> round(float(k_F(10)), 5)
    0.96633
    """
    n = np.asarray(n, dtype=float)
    return 1.0 / (3.0 * n**2) + 8.0 / (5.0 * n) + 0.803


def force_tolerance(F, d, D, n, grade: int = 2):
    """+- tolerance of a spring force ``A_F = (alpha_F k_F + 1.5 F / 100) Q`` (N), EN 15800.

    Parameters
    ----------
    F : float or array [N]
        The toleranced spring force.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    grade : int [-]
        EN 15800 quality grade 1, 2 or 3 (dimensionless).

    Returns
    -------
    float or array [N]
        The +- tolerance ``A_F``.

    References
    ----------
    [en15800] force tolerance (as coded by SpringONE; see the module).

    Examples
    --------
    The spring of Shigley Problem 10-3 (d = 2.5 mm, D = 28.5 mm, 13 active coils); the standard's
    own examples are not in the stored sources, so the value is checked by hand.
    ``alpha_F = 7.045`` N (:func:`alpha_F`), ``k_F(13) = 0.928``, Q = 1 for grade 2: at 100 N,
    ``7.045 * 0.928 + 1.5 = 8.04`` N.

    >>> round(float(force_tolerance(100.0, 2.5e-3, 28.5e-3, 13, 2)), 2)  # N: 7.05 x 0.928 + 1.5
    8.04
    """
    _check_grade(grade)
    return (alpha_F(d, D) * k_F(n) + 0.015 * np.asarray(F, dtype=float)) * Q_FACTOR[grade]


def free_length_tolerance(d, D, n, R, grade: int = 2):
    """+- tolerance of the free length ``A_L0 = alpha_F k_F Q / R`` (m) when no force is
    toleranced (EN 15800); ``R`` in N/m.

    Parameters
    ----------
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    n : float or array [-]
        Number of active coils.
    R : float or array [N/m]
        Spring rate.
    grade : int [-]
        EN 15800 quality grade 1, 2 or 3 (dimensionless).

    Returns
    -------
    float or array [m]
        The +- tolerance ``A_L0``.

    References
    ----------
    [en15800] free-length tolerance (as coded by SpringONE; see the module).

    Examples
    --------
    The spring of Shigley Problem 10-3 (d = 2.5 mm, D = 28.5 mm, 13 active coils); the standard's
    own examples are not in the stored sources, so the value is checked by hand.
    With a rate of 1000 N/m (round for the hand check): ``7.045 * 0.928 / 1000`` m = 6.538 mm.

    >>> round(float(free_length_tolerance(2.5e-3, 28.5e-3, 13, 1000.0)) * 1e3, 3)
    6.538
    """
    _check_grade(grade)
    return alpha_F(d, D) * k_F(n) * Q_FACTOR[grade] / np.asarray(R, dtype=float)


def perpendicularity(L0, grade: int = 2):
    """Permissible deviation of the outer generatrix from the perpendicular, ``e1`` (m):
    0.030, 0.050, 0.080 times L0 for grades 1, 2, 3 (EN 15800, as coded in SpringONE).

    Parameters
    ----------
    L0 : float or array [m]
        Free length.
    grade : int [-]
        EN 15800 quality grade 1, 2 or 3 (dimensionless).

    Returns
    -------
    float or array [m]
        The deviation ``e1``.

    References
    ----------
    [en15800] perpendicularity (as coded by SpringONE; see the module).

    Examples
    --------
    Checked by hand: 50 mm free length, grade 2: ``0.05 * 50 = 2.5`` mm.

    >>> round(float(perpendicularity(50e-3)) * 1e3, 6)
    2.5
    """
    _check_grade(grade)
    return {1: 0.030, 2: 0.050, 3: 0.080}[grade] * np.asarray(L0, dtype=float)


def parallelism(De, grade: int = 2):
    """Permissible deviation of the ground end faces from parallel, ``e2`` (m): 0.015, 0.030,
    0.060 times the outside diameter for grades 1, 2, 3 (EN 15800, as coded in SpringONE).

    Parameters
    ----------
    De : float or array [m]
        Outside coil diameter.
    grade : int [-]
        EN 15800 quality grade 1, 2 or 3 (dimensionless).

    Returns
    -------
    float or array [m]
        The deviation ``e2``.

    References
    ----------
    [en15800] parallelism (as coded by SpringONE; see the module).

    Examples
    --------
    Checked by hand: 20 mm outside diameter, grade 1: ``0.015 * 20 = 0.3`` mm.

    >>> round(float(parallelism(20e-3, 1)) * 1e3, 6)
    0.3
    """
    _check_grade(grade)
    return {1: 0.015, 2: 0.030, 3: 0.060}[grade] * np.asarray(De, dtype=float)


def wire_diameter_tolerance(d, standard: str = "EN10270-1"):
    """+- tolerance of the wire diameter (m) after the wire standard (EN 10270-1 or -2, ASTM
    A228, A227 or A229: :data:`WIRE_TOLERANCE`).

    NaN beyond the table.

    Parameters
    ----------
    d : float or array [m]
        Nominal wire diameter.
    standard : str [-]
        ``"EN10270-1"`` or ``"EN10270-2"`` (:data:`WIRE_TOLERANCE`).

    Returns
    -------
    float or array [m]
        The +- tolerance.

    References
    ----------
    [en10270-1], [en10270-2] diameter tolerances (as tabulated by SpringONE ``WIRETOL.csv``).

    Examples
    --------
    2.8 mm wire lies in the rows 2.6-4.0 mm (EN 10270-1: +-0.030 mm) and 1.7-3.0 mm
    (EN 10270-2: +-0.025 mm) of :data:`WIRE_TOLERANCE`.

    >>> round(float(wire_diameter_tolerance(2.8e-3)) * 1e3, 6)
    0.03
    >>> round(float(wire_diameter_tolerance(2.8e-3, "EN10270-2")) * 1e3, 6)
    0.025
    """
    try:
        upper, tol = WIRE_TOLERANCE[standard]
    except KeyError:
        raise ValueError(f"wire standard must be one of {tuple(WIRE_TOLERANCE)}") from None
    dmm = np.asarray(d, dtype=float) * 1e3
    row = row_index(upper, dmm)
    return np.where(row < len(tol), tol[np.minimum(row, len(tol) - 1)] * 1e-3, np.nan)


def wire_standard(grade: str) -> str | None:
    """The wire standard whose diameter tolerances apply to a grade named ``grade`` (EN
    10270-1 or -2, ASTM A228, A227 or A229, Shigley's fits of them too:
    :data:`WIRE_TOLERANCE`), or None (a grade without tabulated tolerances).

    Parameters
    ----------
    grade : str [-]
        A wire grade's name, as :func:`govopt.springs.materials.material` knows it
        (dimensionless text).

    Returns
    -------
    str or None [-]
        A key of :data:`WIRE_TOLERANCE` (``"EN10270-1"``, ``"ASTM A228"`` ...) or None.

    References
    ----------
    [en10270-1], [en10270-2].

    Examples
    --------
    >>> wire_standard("EN10270-1 SH"), wire_standard("Shigley A229"), wire_standard("ASTM A401")
    ('EN10270-1', 'ASTM A229', None)
    """
    for std in WIRE_TOLERANCE:
        if str(grade).startswith(std):
            return std
    words = str(grade).split()  # "Shigley A228": the ASTM grade of Shigley's fit
    if len(words) == 2 and f"ASTM {words[1]}" in WIRE_TOLERANCE:
        return f"ASTM {words[1]}"
    return None


def max_wire_diameter(d, grade: str | None):
    """The largest wire diameter within tolerance ``d_max = d + A_d`` (m) of the wire grade
    named ``grade`` (:func:`wire_diameter_tolerance` of its standard), which EN 13906-1 takes
    for the solid length; ``d`` itself for a grade without tabulated tolerances (and beyond
    the table).

    Parameters
    ----------
    d : float or array [m]
        Nominal wire diameter.
    grade : str or None [-]
        The wire grade's name (dimensionless text), or None.

    Returns
    -------
    float or array [m]
        ``d + A_d``, or ``d``.

    References
    ----------
    [en13906-1] solid length with the maximum wire diameter; [en10270-1] tolerances.

    Examples
    --------
    2.8 mm EN 10270-1 wire is held to +-0.030 mm (:func:`wire_diameter_tolerance`); 0.092 in
    music wire (ASTM A228, over 0.080 to 0.250 in) to +-0.001 in; ASTM A401 has no table here.

    >>> round(float(max_wire_diameter(2.8e-3, "EN10270-1 SH")) * 1e3, 3)  # +-0.030 mm
    2.83
    >>> round(float(max_wire_diameter(0.092 * 0.0254, "ASTM A228")) / 0.0254, 6)
    0.093
    >>> float(max_wire_diameter(2.8e-3, "Shigley A401")) * 1e3
    2.8
    """
    d = np.asarray(d, dtype=float)
    std = None if grade is None else wire_standard(grade)
    if std is None:
        return d
    tol = wire_diameter_tolerance(d, std)
    return np.where(np.isfinite(tol), d + tol, d)


def rate_spread(d, D, n, G, d_tol, D_tol):
    """Worst-case range of the rate ``R = G d^4 / (8 D^3 n)`` from the wire and coil diameter
    tolerances (exact, not linearised): ``(R(d - d_tol, D + D_tol), R(d + d_tol, D - D_tol))``.
    To first order the relative spread is ``4 d_tol/d + 3 D_tol/D``.

    Parameters
    ----------
    d : float or array [m]
        Nominal wire diameter.
    D : float or array [m]
        Nominal mean coil diameter.
    n : float or array [-]
        Number of active coils.
    G : float [Pa]
        Shear modulus of the wire.
    d_tol, D_tol : float or array [m]
        +- tolerances of the wire and coil diameters.

    Returns
    -------
    tuple of float or array [N/m]
        The lowest and the highest rate.

    References
    ----------
    [en13906-1] rate R (the formula); [en15800] the tolerances it is fed. The worst-case
    corners are govopt's own construction.

    Examples
    --------
    The spring of Shigley Problem 10-3 (d = 2.5 mm, D = 28.5 mm, 13 coils, G = 79.3 GPa:
    R = 1286.7 N/m) with +-0.025 mm wire and +-0.5 mm coil: the full width,
    0.1856 of R, is near the first-order ``2 (4 * 0.025/2.5 + 3 * 0.5/28.5) = 0.1853``.

    >>> lo, hi = rate_spread(2.5e-3, 28.5e-3, 13, 79.3e9, 0.025e-3, 0.5e-3)
    >>> round(float(lo), 1), round(float(hi), 1), round(float((hi - lo) / 1286.66), 4)
    (1173.1, 1411.9, 0.1856)
    """
    d, D = np.asarray(d, dtype=float), np.asarray(D, dtype=float)
    lo = G * (d - d_tol) ** 4 / (8.0 * (D + D_tol) ** 3 * n)
    hi = G * (d + d_tol) ** 4 / (8.0 * (D - D_tol) ** 3 * n)
    return lo, hi
