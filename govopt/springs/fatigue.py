"""Fatigue of helical springs: pure, vectorised functions (SI, stresses in Pa).

Two criteria, each from its source:

- **Shigley** (R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 9th ed.,
  §10-9): Zimmerli's endurance data for spring steels under 10 mm - the strength amplitude
  ``S_sa`` at the midrange ``S_sm`` for infinite life, independent of material and size - set
  the fatigue locus through the torsional ultimate ``S_su = 0.67 S_ut`` with a Goodman, Gerber
  or Sines line; the safety factor is taken along the radial load line ``tau_a / tau_m``.
- **EN 13906-1:2013**, Annex A: the Goodman diagram of the corrected upper stress
  ``tau_kO`` against the corrected lower stress ``tau_kU`` at 1e7 cycles for the wire grade,
  shot-peened or not (:class:`govopt.springs.materials.FatigueDiagram`); the safety factor is
  the admissible stroke ``tau_kH`` at the actual lower stress over the actual stroke.
"""

from __future__ import annotations

import numpy as np

from ..verdict import Figure
from .helical import shear_stress

#: Zimmerli's data as tabulated by Shigley (§10-9): (S_sa, S_sm) in Pa for infinite life of
#: spring steels under 10 mm: unpeened 35 / 55 kpsi (241 / 379 MPa), peened 57.5 / 77.5 kpsi
#: (396.4 / 534 MPa; Shigley prints 398 MPa for 57.5 kpsi, a slip: 57.5 x 6.894757 = 396.4).
#: The book's MPa are kept where they are the kpsi rounded (241, 379, 534).
ZIMMERLI = {False: (241e6, 379e6), True: (57.5 * 6.894757e6, 534e6)}
ZIMMERLI_SOURCE = ("Zimmerli's endurance data, Shigley 9th ed. §10-9: S_sa = 241 / 396.4 MPa "
                   "(35 / 57.5 kpsi) at S_sm = 379 / 534 MPa (unpeened / peened), infinite "
                   "life, d < 10 mm")
#: Fatigue loci through the midrange axis at the ultimate (Shigley Table 6-7; Sines ignores the
#: midrange stress).
CRITERIA = ("goodman", "gerber", "sines")
#: Ratio of the torsional to the tensile endurance limit (distortion energy), used by Shigley
#: Example 10-7 for bending at an extension spring's hook: ``S_e = S_se / 0.577``.
SHEAR_TO_NORMAL = 0.577


def torsional_ultimate(Sut):
    """Torsional ultimate strength of spring wire ``S_su = 0.67 S_ut`` (Pa) (Shigley eq. (10-30)).

    Parameters
    ----------
    Sut : float or array [Pa]
        Tensile ultimate strength of the wire (any stress unit: the result is in the same).

    Returns
    -------
    float or array [Pa]
        Torsional ultimate ``S_su``.

    References
    ----------
    [shigley] 9th ed. eq. (10-30).

    Examples
    --------
    Shigley Example 10-4: music wire with ``S_ut = 284.1`` kpsi; the book prints
    ``S_su = 190.3`` kpsi.

    >>> round(float(torsional_ultimate(284.1)), 1)
    190.3
    """
    return 0.67 * np.asarray(Sut, dtype=float)


def endurance_intercept(Ssa, Ssm, Ssu, criterion: str = "gerber"):
    """Amplitude at zero midrange ``S_se`` of the line through Zimmerli's point ``(S_sm, S_sa)``
    and the ultimate ``S_su`` (Shigley §10-9): Goodman ``S_sa / (1 - S_sm/S_su)``, Gerber
    ``S_sa / (1 - (S_sm/S_su)^2)``, Sines ``S_sa``.

    Parameters
    ----------
    Ssa, Ssm : float or array [Pa]
        Zimmerli's strength amplitude and midrange (:data:`ZIMMERLI`).
    Ssu : float or array [Pa]
        Torsional ultimate strength (:func:`torsional_ultimate`).
    criterion : str [-]
        ``"goodman"``, ``"gerber"`` or ``"sines"``.

    Returns
    -------
    float or array [Pa]
        Fully reversed shear endurance ``S_se`` (same unit as the inputs).

    References
    ----------
    [shigley] 9th ed. §10-9, Example 10-4.

    Examples
    --------
    Shigley Example 10-4 in kpsi (any one stress unit will do): the book prints
    ``S_se = 38.2`` (Gerber) and ``49.2`` (Goodman).

    >>> round(float(endurance_intercept(35.0, 55.0, 190.3, "gerber")), 1)
    38.2
    >>> round(float(endurance_intercept(35.0, 55.0, 190.3, "goodman")), 1)
    49.2
    """
    Ssa, Ssm, Ssu = (np.asarray(x, dtype=float) for x in (Ssa, Ssm, Ssu))
    if criterion == "goodman":
        return Ssa / (1.0 - Ssm / Ssu)
    if criterion == "gerber":
        return Ssa / (1.0 - (Ssm / Ssu) ** 2)
    if criterion == "sines":
        return Ssa + 0.0 * Ssu
    raise ValueError(f"fatigue criterion must be one of {CRITERIA}, got {criterion!r}")


def amplitude_strength(r, Sse, Su, criterion: str = "gerber"):
    """Strength amplitude on the radial load line ``amplitude = r * midrange`` (Shigley Table
    6-7): Goodman ``r S_se S_u / (r S_u + S_se)``, Gerber
    ``r^2 S_u^2 / (2 S_se) [-1 + sqrt(1 + (2 S_se / (r S_u))^2)]``, Sines ``S_se``.

    ``r = inf`` (fully reversed) gives ``S_se``.

    Parameters
    ----------
    r : float or array [-]
        Load-line slope, amplitude over midrange stress (``inf`` for fully reversed).
    Sse : float or array [Pa]
        Endurance intercept at zero midrange (:func:`endurance_intercept`).
    Su : float or array [Pa]
        Ultimate strength where the locus meets the midrange axis.
    criterion : str [-]
        ``"goodman"``, ``"gerber"`` or ``"sines"``.

    Returns
    -------
    float or array [Pa]
        Strength amplitude on the load line (same unit as the inputs).

    References
    ----------
    [shigley] 9th ed. Table 6-7, Example 10-4.

    Examples
    --------
    Shigley Example 10-4 in kpsi, ``r = 29.7 / 39.6 = 0.75``: the book prints
    ``S_sa = 36.6`` (Goodman) and ``35.8`` (Gerber).

    >>> round(float(amplitude_strength(0.75, 49.2, 190.3, "goodman")), 1)
    36.6
    >>> round(float(amplitude_strength(0.75, 38.2, 190.3, "gerber")), 1)
    35.8
    """
    r, Sse, Su = (np.asarray(x, dtype=float) for x in (r, Sse, Su))
    if criterion == "sines":
        return Sse + 0.0 * r
    with np.errstate(divide="ignore", invalid="ignore"):
        if criterion == "goodman":
            out = r * Sse * Su / (r * Su + Sse)
        elif criterion == "gerber":
            x = 2.0 * Sse / (r * Su)
            # -1 + sqrt(1 + x^2) written as x^2 / (1 + sqrt(1 + x^2)): no cancellation
            out = r**2 * Su**2 / (2.0 * Sse) * x**2 / (1.0 + np.sqrt(1.0 + x**2))
        else:
            raise ValueError(f"fatigue criterion must be one of {CRITERIA}, got {criterion!r}")
    return np.where(np.isinf(r), Sse, out)


def shigley_fatigue_safety(tau_a, tau_m, Sut, peened: bool = False, criterion: str = "gerber"):
    """Fatigue safety factor in torsion ``n_f = S_sa / tau_a`` along the load line (Shigley
    §10-9, Example 10-4): Zimmerli's point, ``S_su = 0.67 S_ut`` and ``criterion``.

    Parameters
    ----------
    tau_a, tau_m : float or array [Pa]
        Corrected (Bergstraesser K_B) amplitude and midrange shear stresses.
    Sut : float or array [Pa]
        Tensile ultimate strength of the wire.
    peened : bool [-]
        Shot-peened wire: Zimmerli's peened data.
    criterion : str [-]
        ``"goodman"``, ``"gerber"`` or ``"sines"``.

    Returns
    -------
    float or array [-]
        Fatigue safety factor ``n_f``.

    References
    ----------
    [shigley] 9th ed. §10-9, Example 10-4.

    Examples
    --------
    Shigley Example 10-4: ``tau_a = 29.7``, ``tau_m = 39.6``, ``S_ut = 284.1`` kpsi. The book
    prints ``n_f = 1.21`` (Gerber) and ``1.23`` (Goodman); Zimmerli's data are held in SI
    (241 / 379 MPa, 0.13 % / 0.06 % below 35 / 55 kpsi), which takes the Gerber factor to 1.20.

    >>> ksi = 6.894757e6
    >>> round(float(shigley_fatigue_safety(29.7 * ksi, 39.6 * ksi, 284.1 * ksi)), 2)
    1.2
    >>> round(float(shigley_fatigue_safety(29.7 * ksi, 39.6 * ksi, 284.1 * ksi,
    ...                                    criterion="goodman")), 2)
    1.23
    """
    tau_a = np.asarray(tau_a, dtype=float)
    Ssa, Ssm = ZIMMERLI[bool(peened)]
    Ssu = torsional_ultimate(Sut)
    Sse = endurance_intercept(Ssa, Ssm, Ssu, criterion)
    with np.errstate(divide="ignore"):
        r = tau_a / np.asarray(tau_m, dtype=float)
    return amplitude_strength(r, Sse, Ssu, criterion) / tau_a


def shigley_bending_fatigue_safety(sigma_a, sigma_m, Sut, peened: bool = False,
                                   criterion: str = "gerber"):
    """Fatigue safety factor in bending at an extension spring's hook (Shigley Example 10-7):
    Zimmerli's torsional endurance intercept turned into a tensile one, ``S_e = S_se / 0.577``,
    with the tensile ultimate ``S_ut`` on the same kind of line.

    Parameters
    ----------
    sigma_a, sigma_m : float or array [Pa]
        Amplitude and midrange bending stresses at the hook (with its curvature factor).
    Sut : float or array [Pa]
        Tensile ultimate strength of the wire.
    peened : bool [-]
        Shot-peened wire: Zimmerli's peened data.
    criterion : str [-]
        ``"goodman"``, ``"gerber"`` or ``"sines"``.

    Returns
    -------
    float or array [-]
        Fatigue safety factor in bending.

    References
    ----------
    [shigley] 9th ed. §10-9, Example 10-7.

    Examples
    --------
    The printed factors of Example 10-7 are not in the stored sources; a case checked by hand
    instead: fully reversed bending (zero midrange) of 400 MPa on wire of ``S_ut = 2000`` MPa
    gives ``S_e / sigma_a`` with the Gerber intercept
    ``S_se = 241 / (1 - (379/1340)^2) = 261.96`` MPa, ``S_e = 261.96 / 0.577 = 454.0`` MPa.

    >>> round(float(shigley_bending_fatigue_safety(400e6, 0.0, 2000e6)), 4)
    1.135
    """
    sigma_a = np.asarray(sigma_a, dtype=float)
    Ssa, Ssm = ZIMMERLI[bool(peened)]
    Se = endurance_intercept(Ssa, Ssm, torsional_ultimate(Sut), criterion) / SHEAR_TO_NORMAL
    with np.errstate(divide="ignore"):
        r = sigma_a / np.asarray(sigma_m, dtype=float)
    return amplitude_strength(r, Se, np.asarray(Sut, dtype=float), criterion) / sigma_a


def en13906_stroke_limit(tau_k_lower, d, diagram):
    """Admissible corrected stroke ``tau_kH`` (Pa) at the corrected lower stress ``tau_kU``,
    read off the EN 13906-1 Goodman diagram of wire diameter ``d`` (m): the upper stress rises
    linearly from ``tau_O`` at ``tau_kU = 0`` to the cut-off ``tau_max`` at ``tau_kU = tau_U``,
    and stays at the cut-off beyond.

    Parameters
    ----------
    tau_k_lower : float or array [Pa]
        Corrected lower stress ``tau_kU``.
    d : float or array [m]
        Wire diameter.
    diagram : FatigueDiagram [Pa]
        The grade's diagram (:meth:`govopt.springs.materials.Material.fatigue_diagram`),
        whose lines give stresses in Pa.

    Returns
    -------
    float or array [Pa]
        Admissible corrected stroke ``tau_kH``.

    References
    ----------
    [en13906-1] Annex A (Goodman diagrams at 1e7 cycles).

    Examples
    --------
    Grade DH, not shot peened, d = 3 mm, on the standard's diagram as digitised in SpringONE
    (the diagram's ``source``): ``tau_O = 422.5``, ``tau_max = 922.4`` MPa, the knee at
    ``tau_U = 678.4`` MPa. At zero lower stress the stroke is ``tau_O``; at 300 MPa it is
    ``422.5 + (922.4 - 422.5) / 678.4 * 300 - 300 = 343.6``; beyond the knee, at 900 MPa,
    ``922.4 - 900 = 22.4`` (checked by hand).

    >>> from govopt.springs.materials import material
    >>> dh = material("EN10270-1 DH").fatigue_diagram(False)
    >>> [round(float(x) / 1e6, 1) for x in en13906_stroke_limit([0.0, 300e6, 900e6], 3e-3, dh)]
    [422.5, 343.6, 22.4]
    """
    lower = np.asarray(tau_k_lower, dtype=float)
    tO, tmax, tU = diagram.upper_at_zero(d), diagram.cutoff(d), diagram.knee(d)
    upper = np.where(lower < tU, tO + (tmax - tO) / tU * lower, tmax)
    return upper - lower


def en13906_fatigue_safety(F_min, F_max, d, D, diagram):
    """Fatigue safety factor after EN 13906-1: admissible over actual corrected stroke,
    ``tau_kH,adm(tau_kU) / (tau_k2 - tau_k1)``, with ``tau_k = k tau`` (Bergstraesser's k).

    Parameters
    ----------
    F_min, F_max : float or array [N]
        The two spring forces of the load cycle.
    d : float or array [m]
        Wire diameter.
    D : float or array [m]
        Mean coil diameter.
    diagram : FatigueDiagram [Pa]
        The grade's diagram (:meth:`govopt.springs.materials.Material.fatigue_diagram`).

    Returns
    -------
    float or array [-]
        Fatigue safety factor (below 1: the stroke exceeds the admissible one).

    References
    ----------
    [en13906-1] Annex A (the Goodman diagram; the stroke it admits over the actual one).

    Examples
    --------
    Grade DH, d = 3 mm, D = 24 mm (w = 8, k = 34/29 = 1.1724) between 100 and 300 N, checked by
    hand: ``tau_k1 = k 8 F D / (pi d^3) = 265.4`` MPa, ``tau_k2 = 796.1`` MPa; the diagram
    admits ``422.5 + 0.7369 * 265.4 - 265.4 = 352.7`` MPa of stroke against 530.8 MPa.

    >>> from govopt.springs.materials import material
    >>> dh = material("EN10270-1 DH").fatigue_diagram(False)
    >>> round(float(en13906_fatigue_safety(100.0, 300.0, 3e-3, 24e-3, dh)), 4)
    0.6645
    """
    t1 = shear_stress(F_min, d, D, "bergstrasser")
    t2 = shear_stress(F_max, d, D, "bergstrasser")
    lower, stroke = np.minimum(t1, t2), np.abs(t2 - t1)
    with np.errstate(divide="ignore"):
        return en13906_stroke_limit(lower, d, diagram) / stroke


#: Cycles where the S-N line of :func:`finite_life` starts: a strength amplitude ``f S_su``
#: at 1e3 cycles (Shigley 9th ed. §6-7, the fatigue strength fraction ``f`` at 10^3 cycles,
#: 0.9 where Figure 6-18 gives nothing better, here in shear with the torsional ultimate)
LOW_CYCLES, LOW_CYCLE_FRACTION = 1e3, 0.9


def reversed_endurance(mat, d, method: str = "EN13906", peened: bool = False,
                       criterion: str = "goodman"):
    """The fully reversed shear endurance ``S_se`` (Pa) at the data's life of the diagram the
    body's check reads (:func:`body_locus`) for wire ``d`` (m), and the torsional ultimate
    ``S_su = 0.67 S_ut`` (Shigley eq. (10-30)): Zimmerli's line's intercept (Shigley §10-9,
    :func:`endurance_intercept`), or for an EN 13906-1 diagram its point at zero lower stress
    (amplitude and midrange ``tau_O / 2``) taken to zero midrange on a Goodman line,
    ``S_se = (tau_O/2) / (1 - tau_O / (2 S_su))`` (Shigley §6-12, the equivalent fully
    reversed stress of Example 6-12).

    Parameters
    ----------
    mat : Material [-]
        The wire grade (:func:`govopt.springs.materials.material`).
    d : float [m]
        Wire diameter.
    method : str [-]
        ``"EN13906"`` (the grade's diagram where it has one) or ``"Shigley"`` (Zimmerli).
    peened : bool [-]
        Shot-peened wire.
    criterion : str [-]
        Zimmerli's line: ``"goodman"``, ``"gerber"`` or ``"sines"``.

    Returns
    -------
    tuple of float [Pa]
        ``(S_se, S_su)``.

    References
    ----------
    [shigley] 9th ed. eq. (10-30), §10-9, §6-12; [en13906-1] Annex A.

    Examples
    --------
    Music wire (A228) of 2 mm, Zimmerli's Goodman line, checked by hand:

    >>> from govopt.springs.materials import material
    >>> Sse, Ssu = reversed_endurance(material("Shigley A228"), 2e-3, method="Shigley")
    >>> # S_ut = 2211 MPa mm^0.145 / 2^0.145 = 2000 MPa, S_su 1340 MPa, 241 / (1 - 379/1340)
    >>> round(float(Sse / 1e6), 1), round(float(Ssu / 1e6), 1)
    (336.1, 1339.7)
    """
    Ssu = torsional_ultimate(mat.tensile_strength(d))
    diagram = mat.fatigue_diagram(peened) if method == "EN13906" else None
    if diagram is not None:
        half = np.asarray(diagram.upper_at_zero(d), dtype=float) / 2.0
        return half / (1.0 - half / Ssu), Ssu
    Ssa, Ssm = ZIMMERLI[bool(peened)]
    return endurance_intercept(Ssa, Ssm, Ssu, criterion), Ssu


def finite_life(safety, Sse, Ssu, data_cycles: float = 1e7):
    """Estimated life (cycles) of a spring whose fatigue safety at the data's life
    ``data_cycles`` is ``safety`` (< 1: the stress exceeds the endurance by ``1/safety``
    along its load line): Basquin's S-N line ``S_f = a N^b`` through ``f S_su`` at
    :data:`LOW_CYCLES` and ``S_se`` at ``data_cycles`` (Shigley 9th ed. §6-7, eqs. (6-13)-(6-16),
    with the data's life in place of 10^6 and shear strengths), read at ``S_se / safety``:
    ``N = data_cycles * safety^(-1/b)``, ``b = log10(S_se / (f S_su)) / log10(data_cycles /
    1e3)``. ``inf`` where ``safety >= 1`` (beyond the data: no estimate, the strength is held
    constant), ``nan`` below :data:`LOW_CYCLES` (quasi-static: the line does not reach).

    Parameters
    ----------
    safety : float or array [-]
        Fatigue safety factor at ``data_cycles``.
    Sse : float or array [Pa]
        Fully reversed shear endurance at ``data_cycles`` (:func:`reversed_endurance`).
    Ssu : float or array [Pa]
        Torsional ultimate strength.
    data_cycles : float [-]
        Cycles at which the endurance data hold (number of cycles).

    Returns
    -------
    float or array [-]
        Estimated life in cycles.

    References
    ----------
    [shigley] 9th ed. §6-7, eqs. (6-13)-(6-16).

    Examples
    --------
    A hand-checkable case: ``S_se = 300``, ``S_su = 1200`` MPa, safety 0.8; the life read back
    on the line gives the stress ``300 / 0.8 = 375`` MPa.

    >>> N = float(finite_life(0.8, 300e6, 1200e6))  # b = lg(300/1080)/4 = -0.139
    >>> round(N / 1e6, 3), round(float(300e6 * (N / 1e7) ** (np.log10(300 / 1080) / 4)) / 1e6, 6)
    (2.01, 375.0)
    """
    safety, Sse, Ssu = (np.asarray(x, dtype=float) for x in (safety, Sse, Ssu))
    b = np.log10(Sse / (LOW_CYCLE_FRACTION * Ssu)) / np.log10(data_cycles / LOW_CYCLES)
    with np.errstate(divide="ignore", over="ignore"):
        life = data_cycles * safety ** (-1.0 / b)
    low = LOW_CYCLES * (1.0 - 1e-9)  # the line's end itself, whatever the rounding
    return np.where(safety >= 1.0, np.inf, np.where(life >= low, life, np.nan))


def life_factor(cycles, Sse, Ssu, data_cycles: float = 1e7):
    """The fatigue strength at a required life ``cycles`` over the strength at the data's life
    ``data_cycles``, on the S-N line :func:`finite_life` reads (Basquin's ``S_f = a N^b``
    through ``f S_su`` at :data:`LOW_CYCLES` and ``S_se`` at ``data_cycles``): ``(N /
    data_cycles)^b`` with ``N`` held within ``[LOW_CYCLES, data_cycles]`` (1 at and beyond the
    data's life, where the strength is held constant; the line's end below 1e3 cycles). A
    safety factor at the data's life times this factor is the safety at the required life: at
    least 1 exactly where :func:`finite_life` estimates at least ``cycles``.

    Parameters
    ----------
    cycles : float or array [-]
        Required life (number of load cycles).
    Sse : float or array [Pa]
        Fully reversed shear endurance at ``data_cycles`` (:func:`reversed_endurance`).
    Ssu : float or array [Pa]
        Torsional ultimate strength.
    data_cycles : float [-]
        Cycles at which the endurance data hold (number of cycles).

    Returns
    -------
    float or array [-]
        The strength ratio, at least 1.

    References
    ----------
    [shigley] 9th ed. §6-7, eqs. (6-13)-(6-16).

    Examples
    --------
    The case of :func:`finite_life` (``S_se = 300``, ``S_su = 1200`` MPa): a safety of 0.8 at
    1e7 cycles lasts 2.01e6 cycles, where the factor is 1/0.8:

    >>> N = float(finite_life(0.8, 300e6, 1200e6))
    >>> round(float(life_factor(N, 300e6, 1200e6)) * 0.8, 12), float(life_factor(1e8, 1, 2))
    (1.0, 1.0)
    """
    Sse, Ssu = np.asarray(Sse, dtype=float), np.asarray(Ssu, dtype=float)
    b = np.log10(Sse / (LOW_CYCLE_FRACTION * Ssu)) / np.log10(data_cycles / LOW_CYCLES)
    N = np.clip(np.asarray(cycles, dtype=float), LOW_CYCLES, data_cycles)
    return (N / data_cycles) ** b


def body_locus(mat, d, method: str = "EN13906", peened: bool = False,
               criterion: str = "goodman", points: int = 41) -> dict:
    """The fatigue diagram the body's check reads (:mod:`govopt.springs.checks`: the grade's
    EN 13906-1 Goodman diagram under ``method="EN13906"`` where the grade has one, else
    Zimmerli's data with ``criterion``), for wire ``d`` (m); a record whose stresses are
    :class:`~govopt.verdict.Figure` in Pa (:func:`govopt.springs.sheet.record_json` writes it):

    * EN 13906-1 Annex A: ``{"method": "EN13906", "cycles", "source", "locus":
      {"lower stress", "upper stress"}}``, the admissible corrected upper stress against
      the corrected lower stress: ``tau_O`` at zero, linear to the cut-off ``tau_max`` at
      ``tau_U``, level until the diagonal ``upper = lower`` (:func:`en13906_stroke_limit`);
    * Shigley §10-9: ``{"method": "Shigley", "criterion", "source", "zimmerli": [S_sm, S_sa],
      "locus": {"midrange stress", "amplitude stress"}}``, the strength amplitude against
      the midrange from 0 to ``S_su = 0.67 S_ut`` (Shigley Table 6-7's lines through Zimmerli's
      point, :func:`endurance_intercept`).

    Parameters
    ----------
    mat : Material [-]
        The wire grade (:func:`govopt.springs.materials.material`).
    d : float [m]
        Wire diameter.
    method : str [-]
        ``"EN13906"`` or ``"Shigley"``.
    peened : bool [-]
        Shot-peened wire.
    criterion : str [-]
        Zimmerli's line: ``"goodman"``, ``"gerber"`` or ``"sines"``.
    points : int [-]
        Points of the Shigley locus (dimensionless count).

    Returns
    -------
    dict [Pa]
        The record above, its stresses as figures in Pa.

    References
    ----------
    [en13906-1] Annex A; [shigley] 9th ed. §10-9, Table 6-7.

    Examples
    --------
    Music wire (A228) of 2 mm, Zimmerli's Goodman line: it passes through Zimmerli's point
    (379, 241) MPa by construction.

    >>> from govopt.springs.materials import material
    >>> loc = body_locus(material("Shigley A228"), 2e-3, method="Shigley")
    >>> m, a = (loc["locus"][k].value for k in ("midrange stress", "amplitude stress"))
    >>> round(float(np.interp(379e6, m, a)) / 1e6, 6)   # the Goodman line meets Zimmerli's point
    241.0
    """
    diagram = mat.fatigue_diagram(peened) if method == "EN13906" else None
    if diagram is not None:
        tO, tmax, tU = (float(f(d)) for f in (diagram.upper_at_zero, diagram.cutoff,
                                              diagram.knee))
        return {"method": "EN13906", "cycles": diagram.cycles, "source": diagram.source,
                "locus": _figures(Figure("lower stress", [0.0, tU, tmax], "Pa"),
                                  Figure("upper stress", [tO, tmax, tmax], "Pa"))}
    Ssa, Ssm = ZIMMERLI[bool(peened)]
    Ssu = float(torsional_ultimate(mat.tensile_strength(d)))
    Sse = float(endurance_intercept(Ssa, Ssm, Ssu, criterion))
    m = np.linspace(0.0, Ssu, points)
    if criterion == "goodman":
        a = Sse * (1.0 - m / Ssu)
    elif criterion == "gerber":
        a = Sse * (1.0 - (m / Ssu) ** 2)
    else:
        a = Sse + 0.0 * m
    return {"method": "Shigley", "criterion": criterion, "source": ZIMMERLI_SOURCE,
            "zimmerli": Figure("zimmerli", [Ssm, Ssa], "Pa"),
            "locus": _figures(Figure("midrange stress", m.tolist(), "Pa"),
                              Figure("amplitude stress", a.tolist(), "Pa"))}


def _figures(*figures: Figure) -> dict[str, Figure]:
    """A record of figures keyed by their names."""
    return {f.name: f for f in figures}


def cycle_figures(force_min: float, force_max: float, stress_min: float,
                  stress_max: float) -> dict[str, Figure]:
    """The figures of a spring body's fatigue load cycle between two forces (N) and their
    corrected shear stresses (Pa): the forces, the stresses, the mean stress ``(min + max)/2``
    and the alternating stress ``(max - min)/2`` (Shigley §10-9's midrange and amplitude;
    EN 13906-1's lower and upper stress are the two ends).

    Parameters
    ----------
    force_min, force_max : float [N]
        The two forces of the cycle.
    stress_min, stress_max : float [Pa]
        Their corrected shear stresses.

    Returns
    -------
    dict of str to Figure [N, Pa]
        The six figures keyed by name.

    References
    ----------
    [shigley] 9th ed. §10-9; [en13906-1] Annex A.

    Examples
    --------
    The mean of 200 and 600 MPa is 400 MPa (by hand):

    >>> {k: f.value for k, f in cycle_figures(100.0, 300.0, 2e8, 6e8).items()}["mean stress"]
    400000000.0
    """
    return _figures(Figure("force min", force_min, "N"), Figure("force max", force_max, "N"),
                    Figure("corrected stress min", stress_min, "Pa"),
                    Figure("corrected stress max", stress_max, "Pa"),
                    Figure("mean stress", 0.5 * (stress_min + stress_max), "Pa"),
                    Figure("alternating stress", 0.5 * (stress_max - stress_min), "Pa"))
