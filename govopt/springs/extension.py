"""A helical extension spring's body and hooks (Shigley section 10-11, EN 13906-2).

The active coils of a close-wound body (a hook adds to the body's rate), its length and free
length, the initial tension coiling practice allows, and the bending and torsion stresses in the
hooks with their stress factors. All SI; functions broadcast over numpy arrays. The rate, the
stresses, the mass and the surge frequency of any helical spring are in
:mod:`govopt.springs.helical`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


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
