"""Vyshnegradsky's diagram: where a governed engine's third-order model sits (Hamabe eq. 28).

The load-change model ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3 = 0`` (Hamabe eq. 29; Vyshnegradsky
1877 for the ball governors) is brought to Vyshnegradsky's normal form by ``s = q lambda`` with
``q = (a3/a0)^(1/3)``::

    lambda^3 + A lambda^2 + B lambda + 1 = 0,   A = 3 a1 / (a0 q),   B = 3 a2 / (a0 q^2).

Stable iff ``A B > 1`` (Hurwitz; Hamabe eq. 32: ``9 a1 a2 > a0 a3``). In the stable region the
roots are three real ones (*aperiodic*, below the discriminant curve), or a complex pair with a
real root; the pair decays faster than the real root (*monotonic*: the real root dominates the
late response) or slower (*oscillatory*). The boundary between the last two is the curve
``2 A^3 - 9 A B + 27 = 0`` (pair and real root with equal real parts).
"""

from __future__ import annotations

import numpy as np

REGIONS = ("oscillatory", "monotonic", "aperiodic", "unstable")


def coordinates(a0, a1, a2, a3):
    """``(A, B)`` of Vyshnegradsky's normal form, dimensionless, from the coefficients of eq. (28).

    ``q = (a3/a0)^(1/3)``, ``A = 3 a1 / (a0 q)``, ``B = 3 a2 / (a0 q^2)`` (module docstring).

    Parameters
    ----------
    a0 : float or array [kg m^2]
        ``I``, the flying masses' inertia (any consistent units: ``A`` and ``B`` are ratios).
    a1 : float or array [N m s]
        A third of the dash-pot coefficient ``f``.
    a2 : float or array [N m]
        A third of ``I k^2``.
    a3 : float or array [N m/s]
        ``2 R omega0 a m rho sin(alpha0)`` (the engine's torque slope over the flywheel).

    Returns
    -------
    tuple of float or array [-]
        ``(A, B)``, dimensionless.

    References
    ----------
    [hamabe] Part III, eqs. (28), (29); [vyshnegradsky].

    Examples
    --------
    >>> A, B = coordinates(1.0, 1.0, 1.0, 1.0)   # (s + 1)^3: the triple root
    >>> float(A), float(B)
    (3.0, 3.0)

    Hamabe's Example 3 (a) in the paper's kgf-cm-s units (a0 = 1.76, a1 = 24, k^2 = 360 so
    a2 = a0 k^2 / 3 = 211.2, a3 = 840):

    >>> A, B = coordinates(1.76, 24.0, 211.2, 840.0)
    >>> round(float(A), 3), round(float(B), 3)
    (5.235, 5.895)
    """
    q = np.cbrt(np.asarray(a3, dtype=float) / np.asarray(a0, dtype=float))
    return 3.0 * a1 / (a0 * q), 3.0 * a2 / (a0 * q**2)


def region(A: float, B: float, rtol: float = 1e-12) -> str:
    """Vyshnegradsky's region of the point ``(A, B)``: one of :data:`REGIONS`.

    ``"unstable"`` (``A B <= 1``), ``"aperiodic"`` (three real roots: discriminant
    ``18 A B - 4 A^3 + A^2 B^2 - 4 B^3 - 27 >= 0``), ``"oscillatory"`` (complex pair decaying
    slower than the real root: ``2 A^3 - 9 A B + 27 > 0``) or ``"monotonic"``. Decided from the
    coefficients, so exact at the triple root ``A = B = 3`` where computed roots scatter.

    Parameters
    ----------
    A : float [-]
        Normal-form coefficient (dimensionless, :func:`coordinates`).
    B : float [-]
        Normal-form coefficient (dimensionless).
    rtol : float [-], optional
        Relative tolerance of the discriminant's sign (dimensionless).

    Returns
    -------
    str [-]
        The region's name.

    References
    ----------
    [vyshnegradsky]; [hurwitz] (``A B > 1``); [hamabe] Part III, eqs. (32), (37).

    Examples
    --------
    >>> region(3.0, 3.0), region(1.0, 0.5), region(0.5, 4.0), region(4.0, 1.0)
    ('aperiodic', 'unstable', 'oscillatory', 'oscillatory')
    >>> q = 2.5 ** (1 / 3)   # roots -0.5 and -2 +- 1i (scaled): the pair decays faster
    >>> region(4.5 / q, 7.0 / q**2)
    'monotonic'
    """
    return REGIONS[int(regions(A, B, rtol))]


def regions(A, B, rtol: float = 1e-12) -> np.ndarray:
    """:func:`region` of every point of the arrays ``A``, ``B``, as indices into :data:`REGIONS`.

    The arrays broadcast together; the same tests in the same order, on a whole grid at once (the
    diagram's map of the regions).

    Parameters
    ----------
    A : array [-]
        Normal-form coefficients (dimensionless, :func:`coordinates`).
    B : array [-]
        Normal-form coefficients (dimensionless).
    rtol : float [-], optional
        Relative tolerance of the discriminant's sign (dimensionless).

    Returns
    -------
    array of int [-]
        Indices into :data:`REGIONS`.

    References
    ----------
    [vyshnegradsky]; [hurwitz].

    Examples
    --------
    >>> [REGIONS[i] for i in regions([3.0, 1.0, 0.5, 4.0], [3.0, 0.5, 4.0, 1.0])]
    ['aperiodic', 'unstable', 'oscillatory', 'oscillatory']
    """
    A, B = np.broadcast_arrays(np.asarray(A, dtype=float), np.asarray(B, dtype=float))
    scale = np.maximum(np.maximum(1.0, A), B) ** 4
    disc = 18.0 * A * B - 4.0 * A**3 + A**2 * B**2 - 4.0 * B**3 - 27.0
    stable = np.where(disc >= -rtol * scale, REGIONS.index("aperiodic"),
                      np.where(2.0 * A**3 - 9.0 * A * B + 27.0 > 0,
                               REGIONS.index("oscillatory"), REGIONS.index("monotonic")))
    return np.where(A * B > 1.0, stable, REGIONS.index("unstable"))


def point(a0, a1, a2, a3) -> dict:
    """``{"A", "B", "region"}`` of one design's load-change model (JSON-ready).

    Parameters
    ----------
    a0 : float or array [kg m^2]
        ``I``, the flying masses' inertia (any consistent units: ``A`` and ``B`` are ratios).
    a1 : float or array [N m s]
        A third of the dash-pot coefficient ``f``.
    a2 : float or array [N m]
        A third of ``I k^2``.
    a3 : float or array [N m/s]
        ``2 R omega0 a m rho sin(alpha0)`` (the engine's torque slope over the flywheel).

    Returns
    -------
    dict [-]
        ``A`` and ``B`` (dimensionless floats) and the region's name.

    References
    ----------
    [hamabe] Part III, eqs. (28), (37); [vyshnegradsky].

    Examples
    --------
    Hamabe's Example 3 (a), kgf-cm-s units: with a1 = 24 the paper prints three real roots
    (-29.1, -10, -1.7; the cubic's own are -29.10, -10.20, -1.61), with a1 = 15 the root -1.5 and
    the pair -12.043 +- 13.35i decaying faster (the cubic's: -1.47, -12.05 +- 13.39i).

    >>> point(1.76, 24.0, 211.2, 840.0)["region"], point(1.76, 15.0, 211.2, 840.0)["region"]
    ('aperiodic', 'monotonic')
    """
    A, B = (float(v) for v in coordinates(a0, a1, a2, a3))
    return {"A": A, "B": B, "region": region(A, B)}


def boundaries(A_max: float, samples: int = 400) -> dict:
    """The curves of Vyshnegradsky's diagram for ``0 < A <= A_max``: ``name -> (A, B)`` arrays.

    * ``"stability"``: ``A B = 1`` (Hurwitz; Hamabe eq. 32);
    * ``"aperiodic"``: the discriminant curve, the normal forms with a double root,
      ``(lambda + p)^2 (lambda + 1/p^2)``: ``A = 2 p + 1/p^2``, ``B = p^2 + 2/p`` for ``p > 0``
      (both branches meet in the cusp ``A = B = 3`` at ``p = 1``); three real roots between them;
    * ``"monotonic"``: ``2 A^3 - 9 A B + 27 = 0``, i.e. ``B = 2 A^2/9 + 3/A``, for ``A <= 3``
      (the pair ``-r +- i w`` and the real root ``-r``: ``A = 3 r``, ``r (r^2 + w^2) = 1``);
      beyond the cusp it runs inside the aperiodic region and separates nothing.

    Parameters
    ----------
    A_max : float [-]
        Largest ``A`` drawn (dimensionless).
    samples : int [-], optional
        Points per curve (dimensionless).

    Returns
    -------
    dict [-]
        Curve name -> ``(A, B)``, dimensionless arrays.

    References
    ----------
    [vyshnegradsky]; [hurwitz]; [hamabe] Part III, eqs. (32), (37).

    Examples
    --------
    >>> c = boundaries(6.0)
    >>> A, B = c["aperiodic"]
    >>> i = int(np.argmin(A)); round(float(A[i]), 6), round(float(B[i]), 6)   # the cusp
    (3.0, 3.0)
    >>> A, B = c["monotonic"]; round(float(A[-1]), 12), round(float(B[-1]), 12)
    (3.0, 3.0)
    """
    A = np.linspace(A_max / samples, A_max, samples)
    # 2 p + 1/p^2 <= A_max holds for p in [1/sqrt(A_max), A_max/2] (a little wider, then cut)
    p = np.concatenate([np.geomspace(0.5 / np.sqrt(A_max), 1.0, samples),
                        np.geomspace(1.0, A_max, samples)[1:]])
    Ad, Bd = 2.0 * p + 1.0 / p**2, p**2 + 2.0 / p
    keep = Ad <= A_max
    Am = np.linspace(A_max / samples, min(3.0, A_max), samples)
    return {"stability": (A, 1.0 / A), "aperiodic": (Ad[keep], Bd[keep]),
            "monotonic": (Am, 2.0 * Am**2 / 9.0 + 3.0 / Am)}
