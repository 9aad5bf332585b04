"""The leaf (flat) spring: a strip of width ``w``, thickness ``t`` and length ``L`` loaded at its
middle by a force ``F`` across it, its ends on two collars that may slide together (no axial
load), as in a flat-spring traction-engine governor (the spring-balance governor article,
``/work/shared/seeds/003_*``, Fig. 2). SI throughout; vectorised over numpy arrays.

Stiffness (small deflection, Euler-Bernoulli; Roark's *Formulas for Stress and Strain*, 7th ed.,
Table 8.1, cases 1a and 1e; the article's eq. 5 and its note):

* ``"hinged"`` (pinned ends, free to turn): each half is a cantilever of length ``L/2`` from the
  middle (where the slope is zero by symmetry) with ``F/2`` at its tip, so the middle moves
  ``(F/2)(L/2)^3 / (3 E I) = F L^3 / (48 E I)``: ``kappa = 48 E I / L^3``;
* ``"clamped"`` (both ends built in, the collars free to slide): inflexion points at the quarter
  points, each quarter a cantilever of length ``L/4`` with ``F/2``, the middle moving
  ``2 (F/2)(L/4)^3 / (3 E I) = F L^3 / (192 E I)``: ``kappa = 192 E I / L^3``.

The article's Fig. 2 shows a centre-loaded leaf (the fly weight at the middle, the ends on the
collars) and its 48 is the pinned case above; its 192 is the clamped one. Both need the collars to
slide freely: an axial load on the valve rod would add a beam-column term the article leaves out.

The chord-bow relation (the distance ``l`` between the end attachments when the middle stands
``x`` off the line of the ends), three ways (:data:`CHORD_MODELS`):

* ``"straight"``: the article's eq. 8, two straight halves, ``x = sqrt(L^2 - l^2) / 2``;
* ``"arc"``: a circular arc of length ``L``, sagitta ``x``: radius ``R = (l^2 + 4 x^2)/(8 x)``
  and ``L = 2 R arccos(1 - x/R) = 2 R arcsin(l / 2R)`` (the article prints ``arcsin(1 - 8x^2 /
  (l^2 + 4x^2))``, which is ``arcsin(1 - x/R)``: the complement of the half-angle, wrong; with
  ``arccos`` it is right);
* ``"elastica"``: the exact large-deflection shape (Euler's elastica; Bisshopp & Drucker, *Quart.
  Appl. Math.* 3 (1945) 272, the cantilever with a tip load across it). Each half (hinged) or
  quarter (clamped) is that cantilever; with tip angle ``theta0``, ``k^2 = (1 + sin theta0)/2``,
  ``sin phi1 = 1/(sqrt(2) k)`` and ``F(.|m)``, ``E(.|m)`` the incomplete elliptic integrals
  (``m = k^2``)::

      alpha = sqrt(P l_c^2 / (E I)) = K(k) - F(phi1, k)
      delta / l_c = 1 - 2 (E(k) - E(phi1, k)) / alpha          (tip deflection across)
      a / l_c = sqrt(2 sin theta0) / alpha                      (tip distance along)

  for a cantilever of length ``l_c`` with tip load ``P``. Hinged: ``l_c = L/2``, ``P = F/2``,
  ``x = delta``, ``l = 2a``; clamped: ``l_c = L/4``, ``x = 2 delta``, ``l = 4a``. Both give
  ``x/L = u/2`` and ``l/L = c`` with ``u = delta/l_c``, ``c = a/l_c``: the chord-bow relation is
  the same for either end, and the force is ``F = kappa L alpha^2 / 6`` for either stiffness
  (``8 alpha^2 E I / L^2`` hinged, ``32 alpha^2 E I / L^2`` clamped), tending to ``kappa x``.
  ``K - F(phi1)`` and ``E - E(phi1)`` are evaluated as ``F(psi)`` and ``E(psi) - m sin(phi1)
  sin(psi)`` with ``tan(psi) = sqrt(2 sin theta0 / (1 - sin theta0))`` (the complementary
  arguments, ``tan phi1 tan psi = 1/k'``; Byrd & Friedman 116.01), free of cancellation.

Against the elastica, the straight line overstates ``l`` (by 0.42 % at ``x/L = 0.1``, 2.05 % at
0.2, 3.8 % at 0.25) and the arc understates it (0.29 %, 1.59 %, 3.3 %); the linear force (eq. 5)
falls short of the exact one by 4.1 % at ``x/L = 0.1`` and 16.8 % at 0.2 (the exact force is
4.3 % and 20 % above it; the table in docs/theory/traction_leaf.md).
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from importlib import resources

import numpy as np

from ..verdict import Check

#: end fixity -> ``c`` in ``kappa = c E I / L^3`` (Roark Table 8.1 cases 1a, 1e; article eq. 5)
ENDS = {"hinged": 48.0, "clamped": 192.0}
#: the chord-bow relations: the article's eq. 8, the circular arc, the exact elastica
CHORD_MODELS = ("straight", "arc", "elastica")
#: below this ``x/L`` the elastica is replaced by its series in ``X = x/L`` (error below 1e-16;
#: above it the elliptic forms lose at most 4e-11 to cancellation): ``l/L = 1 - (12/5) X^2 -
#: (576/175) X^4``, ``f/x = 1 + (144/35) X^2 + (257904/13475) X^4`` (coefficients identified from
#: mpmath at 80 digits; the X^2 ones follow from the linear shape, ``(3/5) delta^2 / l_c``)
_SMALL = 1e-3
_L2, _L4, _F2, _F4 = -12.0 / 5.0, -576.0 / 175.0, 144.0 / 35.0, 257904.0 / 13475.0
_SQRT2 = np.sqrt(2.0)


def second_moment(w, t):
    """Second moment of area of the strip about its neutral axis, ``I = w t^3 / 12`` (m^4) for
    width ``w`` and thickness ``t`` (m); the article's eq. 7.

    Parameters
    ----------
    w : float or array [m]
        Width of the strip.
    t : float or array [m]
        Thickness of the strip.

    References
    ----------
    [traction-article] eq. 7; a 1 in x 1/32 in strip (rounded to 0.0001 mm^4).

    >>> round(float(second_moment(0.0254, 0.0254 / 32)) * 1e12, 4)  # 1 in x 1/32 in, mm^4
    1.0585
    """
    return w * t**3 / 12.0


def stiffness(w, t, L, E, ends="hinged"):
    """Small-deflection stiffness at the middle, ``kappa = c E I / L^3`` (N/m), ``c`` = 48 hinged
    or 192 clamped (:data:`ENDS`; article eq. 5); ``w``, ``t``, ``L`` in m, ``E`` in Pa.

    Parameters
    ----------
    w : float or array [m]
        Width of the leaf.
    t : float or array [m]
        Thickness of the leaf.
    L : float or array [m]
        Length (span) of the leaf.
    E : float [Pa]
        Young's modulus.
    ends : str [-]
        ``"hinged"`` or ``"clamped"`` (:data:`ENDS`).

    References
    ----------
    [traction-article] eq. 5; a 1 in x 0.025 in steel leaf over 8 in, a hand calculation in the
    article's units (rounded to 0.0001 lbf/in).

    >>> from govopt.units import parse_quantity as q
    >>> k = stiffness(q("1 in", "length"), q("0.025 in", "length"), q("8 in", "length"),
    ...               q("28.5e6 psi", "stress"))
    >>> round(k / q("1 lbf/in", "stiffness"), 4)  # 48 x 28.5e6 x (1 x 0.025^3/12) / 8^3
    3.479
    """
    return ENDS[ends] * E * second_moment(w, t) / L**3


def moment_arm(span, ends="hinged"):
    """Largest bending moment per unit middle load, ``M/F`` (m): ``span/4`` hinged (at the
    middle), ``span/8`` clamped (at the middle and the ends). ``span``: the leaf's length ``L``
    in the small-deflection theory; the chord ``l`` in the elastica, where each half (quarter)
    carries ``F/2`` at a lever ``l/2`` (``l/4``) from its root.

    Parameters
    ----------
    span : float or array [m]
        The leaf's length ``L`` or its chord ``l`` (see above).
    ends : str [-]
        ``"hinged"`` or ``"clamped"`` (:data:`ENDS`).

    Returns
    -------
    float or array [m]
        The largest moment per unit load.

    References
    ----------
    [roark] Table 8.1, cases 1a (centre load, simply supported) and 1e (both ends fixed).

    Examples
    --------
    Roark's ``M_max = W l/4`` and ``W l/8`` for a 200 mm leaf:

    >>> float(moment_arm(0.2)), float(moment_arm(0.2, "clamped"))
    (0.05, 0.025)
    """
    return span / (4.0 if ends == "hinged" else 8.0)


def bending_stress(F, w, t, span, ends="hinged"):
    """Largest bending stress ``sigma = M (t/2) / I = 6 M / (w t^2)`` (Pa) under the middle load
    ``F`` (N), ``M = F`` :func:`moment_arm` (Roark Table 8.1 cases 1a, 1e).

    Parameters
    ----------
    F : float or array [N]
        Load at the middle, across the leaf (its magnitude is used).
    w : float or array [m]
        Width of the leaf.
    t : float or array [m]
        Thickness of the leaf.
    span : float or array [m]
        Span of the moment (:func:`moment_arm`).
    ends : str [-]
        ``"hinged"`` or ``"clamped"`` (:data:`ENDS`).

    Returns
    -------
    float or array [Pa]
        The largest bending stress.

    References
    ----------
    [roark] Table 8.1, cases 1a and 1e; [traction-article] eq. 7 (I = w t^3/12).

    Examples
    --------
    Hand checks: unit moment on a unit section, ``6 x 1/(1 x 1) = 6``; 10 N on a 20 x 1 mm leaf
    over 200 mm, hinged: ``M = 10 x 0.05 = 0.5 N m``, ``6 x 0.5/(0.02 x 1e-6) = 150 MPa``.

    >>> round(float(bending_stress(1.0, 1.0, 1.0, 4.0)), 12)  # M = 1
    6.0
    >>> round(float(bending_stress(10.0, 0.02, 0.001, 0.2)) / 1e6, 6)  # MPa
    150.0
    """
    return 6.0 * np.abs(F) * moment_arm(span, ends) / (w * t**2)


def mass(w, t, L, density):
    """Mass of the strip, ``density w t L`` (kg).

    Parameters
    ----------
    w : float or array [m]
        Width of the strip.
    t : float or array [m]
        Thickness of the strip.
    L : float or array [m]
        Length of the strip.
    density : float or array [kg/m^3]
        Density of the material.

    Returns
    -------
    float or array [kg]
        The strip's mass (its volume times the density; no source needed beyond the strip).

    References
    ----------
    [traction-article] Fig. 2 (the strip w x t x L).

    Examples
    --------
    A hand check: a 1 in x 1/32 in x 8 in steel strip is 0.25 in^3 = 4.097 cm^3, 32.16 g at
    7850 kg/m^3.

    >>> inch = 0.0254
    >>> round(float(mass(inch, inch / 32, 8 * inch, 7850)) * 1e3, 2)  # g
    32.16
    """
    return density * w * t * L


# -- the chord-bow relation ------------------------------------------------------------------


def _elliptic(theta0):
    """The elliptic integrals of the cantilever elastica with tip angle ``theta0`` (rad):
    ``(sin theta0, m = k^2, alpha = K - F(phi1), G = E - E(phi1))`` (the module's
    elastica, Bisshopp & Drucker)."""
    from scipy.special import ellipeinc, ellipkinc  # imported when used (docs/decisions.md)

    s0 = np.sin(theta0)
    m = 0.5 * (1.0 + s0)
    psi = np.arctan(np.sqrt(2.0 * s0 / (1.0 - s0)))
    alpha = ellipkinc(psi, m)  # K - F(phi1)
    G = ellipeinc(psi, m) - 0.5 * np.sqrt(1.0 + s0) * np.sin(psi)  # E - E(phi1)
    return s0, m, alpha, G


def _elastica_u(theta0):
    """``u = delta / l_c`` of :func:`_elastica` alone (the bisection's function: the same
    numbers, without the derivatives)."""
    _, _, alpha, G = _elliptic(theta0)
    return 1.0 - 2.0 * G / alpha


def _elastica(theta0):
    """The cantilever elastica with tip angle ``theta0`` (rad, in (0, pi/2)): ``u = delta/l_c``,
    ``c = a/l_c``, ``alpha`` and their derivatives in ``k`` (suffix ``_k``)."""
    s0, m, alpha, G = _elliptic(theta0)
    k, kc2, q = np.sqrt(m), 0.5 * (1.0 - s0), np.sqrt(s0)  # k, k'^2, q = sqrt(2 k^2 - 1)
    # d/dk by DLMF 19.4.1-19.4.4 with dphi1/dk = -1/(k q): a closed, linear system in (G, alpha)
    G_k = (G - alpha) / k + 1.0 / (_SQRT2 * k * q)
    alpha_k = G / (k * kc2) - alpha / k + q / (_SQRT2 * k * kc2) + _SQRT2 / (k * q)
    u = 1.0 - 2.0 * G / alpha
    u_k = -2.0 * (G_k * alpha - G * alpha_k) / alpha**2
    c = _SQRT2 * q / alpha
    c_k = _SQRT2 * (2.0 * k / q * alpha - q * alpha_k) / alpha**2
    return dict(u=u, c=c, alpha=alpha, u_k=u_k, c_k=c_k, alpha_k=alpha_k)


def _bisect(fun, target, lo, hi, steps=60):
    """Root of the increasing ``fun(p) = target`` in ``(lo, hi)``, elementwise (bisection)."""
    target = np.asarray(target, dtype=float)
    lo, hi = np.full_like(target, lo), np.full_like(target, hi)
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        below = fun(mid) < target
        lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
    return 0.5 * (lo + hi)


def _elastica_at(x, L):
    """The elastica at bow ``x`` (m) of a leaf of length ``L`` (m); ``None`` where all are
    small (the linear limit applies)."""
    X = np.clip(np.asarray(x, dtype=float) / L, _SMALL, 0.5 - 1e-12)
    theta0 = _bisect(_elastica_u, 2.0 * X, 0.0, 0.5 * np.pi)
    return _elastica(theta0)


def chord(x, L, model="elastica"):
    """Chord ``l`` (m, the distance between the leaf's end attachments) and ``dl/dx`` when its
    middle stands ``x`` (m) off the line of the ends, for a leaf of length ``L`` (m) and no set;
    ``model`` one of :data:`CHORD_MODELS`. Bows the model cannot reach give NaN (``"straight"``:
    ``x >= L/2``; ``"arc"``: beyond a semicircle, ``x/L > 1/pi``; ``"elastica"``: ``x/L >=
    1/2``).

    Parameters
    ----------
    x : float or array [m]
        Bow of the middle off the line of the ends.
    L : float [m]
        Length of the leaf.
    model : str [-]
        ``"straight"`` (the article's eq. 8), ``"arc"`` (its circular arc, corrected) or
        ``"elastica"`` (exact).

    Returns
    -------
    tuple of float or array [m] and float or array [-]
        The chord ``l`` and its slope ``dl/dx``.

    References
    ----------
    [traction-article] eq. 8 and its circular-arc equation; [bisshopp-drucker] (the elastica).

    Examples
    --------
    At x = 0.2 L: the straight line by hand ``sqrt(1 - 0.4^2) = 0.916515``; the elastica's
    0.89812 is the table's in docs/theory/traction_leaf.md (checked against mpmath); the arc
    lies 1.59 % below it.

    >>> [round(float(chord(0.2, 1.0, m)[0]), 6) for m in CHORD_MODELS]  # x = 0.2 L
    [0.916515, 0.883872, 0.898117]
    """
    x = np.asarray(x, dtype=float)
    X = x / L
    if model == "straight":  # eq. 8: (l/2)^2 + x^2 = (L/2)^2
        with np.errstate(invalid="ignore", divide="ignore"):
            l = np.sqrt(L**2 - 4.0 * x**2)
            return l, np.where(x == 0.0, 0.0, -4.0 * x / l)
    if model == "arc":  # half-angle th: L = 2 R th, x = R (1 - cos th), l = 2 R sin th
        bad = (X < 0.0) | (X > 1.0 / np.pi)
        th = _bisect(lambda t: (1.0 - np.cos(t)) / (2.0 * t), np.clip(X, 1e-300, 1.0 / np.pi),
                     0.0, 0.5 * np.pi)
        l = L * np.sin(th) / th
        h = 0.5 * th  # dl/dx = 2 (th cos th - sin th) / (th sin th - 1 + cos th)
        dl = (th * np.cos(th) - np.sin(th)) / (np.sin(h) * (th * np.cos(h) - np.sin(h)))
        return np.where(bad, np.nan, l), np.where(bad, np.nan, dl)
    if model != "elastica":
        raise ValueError(f"chord model must be one of {CHORD_MODELS}, got {model!r}")
    e = _elastica_at(x, L)
    small, bad = X < _SMALL, (X < 0.0) | (X >= 0.5)
    l = np.where(small, L * (1.0 + _L2 * X**2 + _L4 * X**4), L * e["c"])
    dl = np.where(small, 2.0 * _L2 * X + 4.0 * _L4 * X**3, 2.0 * e["c_k"] / e["u_k"])
    return np.where(bad, np.nan, l), np.where(bad, np.nan, dl)


def bow(l, L, model="elastica"):
    """The inverse of :func:`chord`: bow ``x`` (m) at chord ``l`` (m), ``0 < l <= L``.

    Parameters
    ----------
    l : float or array [m]
        Chord, the distance between the end attachments.
    L : float [m]
        Length of the leaf.
    model : str [-]
        One of :data:`CHORD_MODELS`.

    Returns
    -------
    float or array [m]
        The bow ``x``.

    References
    ----------
    [traction-article] eq. 8 (``x = sqrt(L^2 - l^2)/2``); [bisshopp-drucker] (the elastica).

    Examples
    --------
    Eq. 8 by hand, ``sqrt(1 - 0.8^2)/2 = 0.3``; the arc's inverse returns the bow it was
    given.

    >>> round(float(bow(0.8, 1.0, "straight")), 12)
    0.3
    >>> round(float(bow(chord(0.15, 1.0, "arc")[0], 1.0, "arc")), 12)
    0.15
    """
    l = np.asarray(l, dtype=float)
    if model == "straight":
        return 0.5 * np.sqrt(L**2 - l**2)
    top = 1.0 / np.pi if model == "arc" else 0.5 - 1e-12
    return L * _bisect(lambda X: -chord(X * L, L, model)[0] / L, -l / L, 0.0, top)


def force_per_stiffness(x, L, model="elastica"):
    """``f = F / kappa`` (m) and ``df/dx`` for the middle load ``F`` holding a bow ``x`` (m),
    ``kappa`` the small-deflection :func:`stiffness`: ``f = x`` in the article's linear theory
    (eq. 5; models ``"straight"`` and ``"arc"``), ``f = L alpha^2 / 6`` in the elastica (exact,
    hinged or clamped alike; it stiffens as the lever arms shorten).

    Parameters
    ----------
    x : float or array [m]
        Bow of the middle off the line of the ends.
    L : float [m]
        Length of the leaf.
    model : str [-]
        One of :data:`CHORD_MODELS`.

    Returns
    -------
    tuple of float or array [m] and float or array [-]
        ``f = F/kappa`` and its slope ``df/dx``.

    References
    ----------
    [traction-article] eq. 5 (linear); [bisshopp-drucker] (the elastica).

    Examples
    --------
    At x = 0.2 L the exact force is 1.2025 times eq. 5's (eq. 5 falls 16.8 % short, the table
    in docs/theory/traction_leaf.md); in the linear models ``f = x``.

    >>> round(float(force_per_stiffness(0.2, 1.0)[0]) / 0.2, 6)  # exact / eq. 5 at x = 0.2 L
    1.202536
    >>> float(force_per_stiffness(0.2, 1.0, "straight")[0])
    0.2
    """
    x = np.asarray(x, dtype=float)
    if model in ("straight", "arc"):
        return x + 0.0, 1.0 + 0.0 * x
    if model != "elastica":
        raise ValueError(f"chord model must be one of {CHORD_MODELS}, got {model!r}")
    e = _elastica_at(x, L)
    X = x / L
    small = X < _SMALL
    f = np.where(small, x * (1.0 + _F2 * X**2 + _F4 * X**4), L * e["alpha"] ** 2 / 6.0)
    f_x = np.where(small, 1.0 + 3.0 * _F2 * X**2 + 5.0 * _F4 * X**4,
                   2.0 * e["alpha"] * e["alpha_k"] / (3.0 * e["u_k"]))
    return f, f_x


def article_arc_length(l, x):
    """The article's "more accurate" circular-arc formula *as printed*, in radians (m):
    ``L = (4 pi / 360) ((l^2 + 4x^2)/(8x)) arcsin_deg(1 - 8x^2/(l^2 + 4x^2))``, i.e.
    ``2 R arcsin(1 - x/R)``. It is wrong: ``1 - x/R = cos(half-angle)``, so it needs ``arccos``
    (:func:`chord` with ``model="arc"`` is the corrected relation). Kept to show the slip.

    Parameters
    ----------
    l : float or array [m]
        Chord, the distance between the end attachments.
    x : float or array [m]
        Bow of the middle.

    Returns
    -------
    float or array [m]
        The length the printed formula gives.

    References
    ----------
    [traction-article] the circular-arc equation after eq. 9.

    Examples
    --------
    The arc through l = 0.9, x = 0.1 has R = 1.0625 and length ``2 R arcsin(0.45/R)`` =
    0.9293 by hand; the printed formula gives 2.4086:

    >>> round(float(article_arc_length(0.9, 0.1)), 4)
    2.4086
    """
    R = (l**2 + 4.0 * x**2) / (8.0 * x)
    return 2.0 * R * np.arcsin(1.0 - x / R)


# -- stock sections and checks ----------------------------------------------------------------


def stock_sections():
    """Stock flat sections ``(widths, thicknesses)`` (m, paired arrays: every width with every
    thickness below a quarter of it) from ``govopt/data/leaf_stock.csv`` (sources in its
    header).

    Returns
    -------
    tuple of array [m] and array [m]
        Widths and thicknesses, paired element by element.

    Examples
    --------
    Every pair keeps ``t <= w/4``, the strip bending about its weak axis:

    >>> w, t = stock_sections()
    >>> bool(len(w) == len(t) > 0 and (t <= 0.25 * w).all())
    True
    """
    text = resources.files("govopt").joinpath("data/leaf_stock.csv").read_text(encoding="utf-8")
    rows = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    series = {"width": [], "thickness": []}
    for row in rows:
        series[row["dimension"]].append(float(row["inches"]) * 0.0254)
    w, t = np.meshgrid(series["width"], series["thickness"], indexing="ij")
    keep = t <= 0.25 * w
    return w[keep], t[keep]


@dataclass(frozen=True)
class Constraint:
    """One row of the leaf's constraint table: ``value(**kw) sense limit(**kw)`` (SI)."""

    name: str
    sense: str
    unit: str
    source: str
    value: object
    limit: object


#: the leaf's constraint table; keywords: F (largest middle load, N), x (largest bow, m), w, t,
#: L (m), span (m, the moment's span: L or the chord), ends, allowable (bending stress, Pa),
#: max_bow_ratio (x/L allowed; the article's approximations are stated for 0-0.2)
CONSTRAINTS = (
    Constraint("leaf bending stress", "<=", "Pa", "Roark Table 8.1 cases 1a/1e: 6 M/(w t^2)",
               lambda F, w, t, span, ends, **_: bending_stress(F, w, t, span, ends),
               lambda allowable, **_: allowable),
    Constraint("leaf bow / length", "<=", "", "article (003): eq. 8 stated for x = 0-20 % of L",
               lambda x, L, **_: x / L, lambda max_bow_ratio=0.2, **_: max_bow_ratio),
    Constraint("leaf thickness / width", "<=", "", "a strip bending about its weak axis "
               "(the stock catalogue's t <= w/4)", lambda w, t, **_: t / w, lambda **_: 0.25),
)


def checks(**kw):
    """The constraint table evaluated: a list of :class:`govopt.verdict.Check` (keywords as in
    :data:`CONSTRAINTS`).

    Parameters
    ----------
    **kw : float [N, m, Pa] or str [-]
        ``F`` (N), ``x``, ``w``, ``t``, ``L``, ``span`` (m), ``ends`` (str), ``allowable`` (Pa),
        ``max_bow_ratio`` (dimensionless, default 0.2).

    Returns
    -------
    list of Check [-]
        One check per row of :data:`CONSTRAINTS`.

    References
    ----------
    [roark] Table 8.1 (the stress); [traction-article] eq. 8 (stated for x = 0-20 % of L).

    Examples
    --------
    A hand check: 1 N on a 20 x 1 mm leaf over 200 mm, hinged, is 15 MPa (:func:`bending_stress`),
    well under 1 GPa; the bow 10/200 = 0.05 under 0.2; t/w = 0.05 under 0.25.

    >>> [c.passed for c in checks(F=1.0, x=0.01, w=0.02, t=0.001, L=0.2, span=0.2,
    ...                           ends="hinged", allowable=1e9)]
    [True, True, True]
    """
    return [Check(c.name, float(np.max(c.value(**kw))), float(c.limit(**kw)), c.sense, c.unit,
                  c.source, group="spring") for c in CONSTRAINTS]
