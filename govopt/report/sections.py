"""The sections of a result that every writer renders alike: declared tables with named columns
and units, built once here from a :class:`~govopt.result.Result` (formats only, no physics).

A writer never guesses layout from a dict's keys: the dynamics (load changes, their roots and
responses, the forced vibration, friction) and the optimiser's record are declared below as
:class:`Table` objects, and the text report and the Excel sheets lay them out the same way.

Units are shown as people read them (:data:`SHOWN`: degrees for angles, millimetres for lengths,
MPa for stresses); a cell is a finite number in the column's (or row's) unit, a word, or blank:

* booleans are ``"yes"`` / ``"no"``;
* infinities are words that say what they mean: a time that never comes is ``"never"``, an
  over-regulation that grows without bound (unstable) is ``"unbounded"``;
* NaN (not defined) is blank.

A *properties* table has the columns ``quantity``, ``unit`` and one value column per item (one
per load change, say): each row carries its own unit. A *series* table is a long data series
(a response over time) that a chart draws; the text report leaves it out.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..verdict import SHOWN, json_key, shown

__all__ = ["SHOWN", "Chart", "Table", "cell", "dynamics", "optimisation", "recorded_units",
           "restoring", "shown", "unflag"]

def cell(value: Any, inf: str = "unbounded") -> Any:
    """A value as a table shows it: a finite number (float or int), a word, or None (blank).
    Booleans are ``"yes"``/``"no"``; ``+-inf`` is ``inf`` (``-inf`` with a minus sign in
    front); NaN and None are blank.

    >>> cell(True), cell(float("inf"), "never"), cell(float("nan")), cell(2)
    ('yes', 'never', None, 2)
    """
    if value is None:
        return None
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "no"
    if isinstance(value, int | np.integer):
        return int(value)
    try:
        x = float(value)
    except (TypeError, ValueError):
        return str(value)
    if math.isnan(x):
        return None
    if math.isinf(x):
        return inf if x > 0 else f"-{inf}"
    return x


@dataclass(frozen=True)
class Chart:
    """A scatter chart of columns ``ys`` against column ``x`` of its table (0-based); the axis
    titles are the columns' headers (name and unit)."""

    title: str
    x: int
    ys: tuple[int, ...]
    y_title: str = ""


@dataclass
class Table:
    """One declared table: a title, headers with units, rows of cells (:func:`cell`), notes."""

    title: str
    headers: list[str]
    rows: list[list[Any]]
    notes: list[str] = field(default_factory=list)
    chart: Chart | None = None
    #: a long data series (a response) drawn by ``chart``: the sheets write it, the text skips it
    series: bool = False
    #: a properties table (quantity, unit, values...): each row has its own unit
    properties: bool = False


def header(name: str, unit: str) -> str:
    """A column header with its unit: ``"settling time (s)"``; no brackets when dimensionless."""
    return f"{name} ({unit})" if unit else name


# --------------------------------------------------------------------------------------------
# dynamics


def _coordinate(res) -> tuple[str, str]:
    """The configuration's SI unit (``rad`` or ``m``) and its shown unit (``deg`` or ``mm``)."""
    si = res.spec.governor.key_unit("x")
    return si, SHOWN[si][0]


def _roots_text(roots: Sequence) -> str:
    """Roots ``[re, im]`` (1/s) as one line: ``-64.29, -2.36 +- 2.00i``; a conjugate pair once."""
    out, seen = [], set()
    for re_, im in roots:
        if abs(im) < 1e-12 * max(1.0, abs(re_)):
            out.append(f"{re_:.4g}")
        elif (round(re_, 12), round(abs(im), 12)) not in seen:
            seen.add((round(re_, 12), round(abs(im), 12)))
            out.append(f"{re_:.4g} +- {abs(im):.4g}i")
    return ", ".join(out)


def load_changes(res) -> list[Table]:
    """The load changes (the type's load-change model, :meth:`Governor.load_change_method`):
    one properties table with a column per load change (friction rows where the design has
    friction), the roots of the load-change cubic with real and imaginary parts in columns, and
    each response as a series with its chart; headings and labels cite the type's method."""
    changes = [unflag(lc) if isinstance(lc, Mapping) else lc
               for lc in res.dynamics.get("load_changes") or []]
    if not changes:
        return []
    gov, method = res.spec.governor, res.method
    cubic, hurwitz = method.named("cubic"), method.named("hurwitz")
    strokes = method.named("strokes")
    si, xu = _coordinate(res)
    stem = gov.coordinate_name.split()[-1]
    fric = [unflag(f) if isinstance(f, Mapping) else f
            for f in res.dynamics.get("friction") or []]
    band = changes[0].get("settling_band")

    def x(lc, end):  # a configuration as its JSON key names it (the seam's json_coordinate)
        key, _ = gov.json_coordinate(f"{stem}_{end}", 0.0)
        value = lc.get(key)
        if value is None:
            return None
        # json_coordinate writes an angle in degrees already, a length in SI (m)
        return value if gov.coordinate == "angle" else shown(value, si)[0]

    def get(lc, key, default=None):
        return lc.get(key, default) if isinstance(lc, Mapping) else default

    rows: list[list[Any]] = [
        [f"{gov.coordinate_name} before (old equilibrium)", xu, *(x(lc, "from") for lc in changes)],
        [f"{gov.coordinate_name} after (new equilibrium)", xu, *(x(lc, "to") for lc in changes)],
        ["k^2 at the new equilibrium", "1/s^2", *(get(lc, "k2_rad2_s2") for lc in changes)],
        ["roots of the load-change cubic (table below)", "1/s",
         *(_roots_text(get(lc, "roots_per_s", [])) for lc in changes)],
        ["response", "", *(get(lc, "kind") for lc in changes)],
        [f"Hurwitz margin 9 a1 a2 / (a0 a3) - 1 ({hurwitz.cite})", "",
         *(get(lc, "hurwitz_margin") for lc in changes)],
        ["stable", "", *(get(lc, "stable") for lc in changes)],
        ["Vyshnegradsky A", "", *(get(lc, "vyshnegradsky", {}).get("A") for lc in changes)],
        ["Vyshnegradsky B", "", *(get(lc, "vyshnegradsky", {}).get("B") for lc in changes)],
        ["Vyshnegradsky region", "",
         *(get(lc, "vyshnegradsky", {}).get("region") for lc in changes)],
        ["over-regulation (past the new equilibrium)", xu,
         *(shown(get(lc, f"over_regulation_{si}"), si)[0] for lc in changes)],
        ["over-regulates (any t >= 0)", "", *(get(lc, "over_regulates") for lc in changes)],
        ["first arrival at the new equilibrium", "s",
         *(cell(get(lc, "first_arrival_time_s"), "never") for lc in changes)],
        [f"settling time ({100 * band:g} % band)" if band else "settling time", "s",
         *(cell(get(lc, "settling_time_s"),
                "not decided" if get(lc, "settling_not_decided") else "never")
           for lc in changes)],
    ]
    notes = []
    if any(_is_inf(get(lc, "first_arrival_time_s")) for lc in changes):
        notes.append("first arrival 'never': the response approaches the new equilibrium "
                     "without reaching it (no crossing, so no over-regulation).")
    if any(_is_inf(get(lc, "settling_time_s")) and not get(lc, "settling_not_decided")
           for lc in changes):
        notes.append("settling time 'never': the response does not stay within the band "
                     "(unstable).")
    if any(get(lc, "settling_not_decided") for lc in changes):
        notes.append("settling time 'not decided': a stable response whose settling lies "
                     "beyond what the time grid (govopt.limits.MAX_TRANSIENT_POINTS) resolves.")
    if any(_is_inf(get(lc, f"over_regulation_{si}")) for lc in changes):
        notes.append("over-regulation 'unbounded': the load change is unstable and the "
                     "excursion grows without bound.")
    if fric:
        rows += [
            [f"with friction ({strokes.cite if strokes else 'strokes'}): outcome", "",
             *(get(f, "outcome") for f in fric)],
            ["with friction: strokes", "", *(get(f, "n_strokes") for f in fric)],
            ["with friction: the first stroke ends from the new equilibrium", xu,
             *(shown(get(f, f"first_stroke_end_{si}"), si)[0] for f in fric)],
            ["with friction: hunting", "", *(get(f, "hunting") for f in fric)],
        ]
        notes += [f"with friction, {lc.get('name')}: {get(f, 'note')}"
                  for lc, f in zip(changes, fric, strict=False) if get(f, "note")]
    names = [str(get(lc, "name", f"load change {i + 1}")) for i, lc in enumerate(changes)]
    out = [Table(method.heading("load change", "Load changes"),
                 ["quantity", "unit", *names],
                 [[r[0], r[1], *(cell(v) for v in r[2:])] for r in rows], notes,
                 properties=True)]
    roots = [[name, k + 1, cell(re_), cell(im),
              cell(-1.0 / re_ if re_ != 0 else math.inf, "never"),
              cell(2 * math.pi / abs(im)) if abs(im) > 0 else None]
             for name, lc in zip(names, changes, strict=True)
             for k, (re_, im) in enumerate(get(lc, "roots_per_s", []))]
    out.append(Table(f"Roots of the load-change cubic ({cubic.cite}): xi ~ exp(s t)",
                     ["load change", "root", "real part (1/s)",
                     "imaginary part (1/s)", "time constant -1/Re (s)",
                     "period 2 pi / |Im| (s)"], roots,
                     ["period blank: a real root (no oscillation); a negative time constant "
                      "is a growing mode."]))
    for name, lc in zip(names, changes, strict=True):
        resp = get(lc, "response") or {}
        t, xi = resp.get("t_s"), resp.get(f"xi_{si}")
        if t is None or xi is None:
            continue
        xi_shown = shown(list(xi), si)[0]
        out.append(Table(
            f"Load change '{name}': response", ["t (s)", f"deviation xi ({xu})"],
            [[cell(a), cell(b)] for a, b in zip(t, xi_shown, strict=True)],
            [f"xi: {gov.coordinate_name} minus its new equilibrium"],
            Chart(f"Load change '{name}': deviation from the new equilibrium", 0, (1,)),
            series=True))
    return out


def _finite_abs(value) -> float:
    """``|value|`` when it is a finite number, else 0."""
    try:
        x = abs(float(value))
    except (TypeError, ValueError):
        return 0.0
    return x if math.isfinite(x) else 0.0


def _is_inf(value) -> bool:
    try:
        return math.isinf(float(value))
    except (TypeError, ValueError):
        return False


def unflag(data: Mapping) -> dict:
    """A JSON-ready dict with its infinities back: ``null`` beside ``"<key>_infinite"`` (the
    rule of :func:`govopt.jsonable.jsonable`) is ``+-inf`` again, in nested dicts too.

    >>> unflag({"t_s": None, "t_s_infinite": "+inf", "h": [{"a": None, "a_infinite": "-inf"}]})
    {'t_s': inf, 'h': [{'a': -inf}]}
    """
    out = {}
    for key, value in data.items():
        flag = data.get(f"{key}_infinite")
        if isinstance(key, str) and key.endswith("_infinite") and key[:-9] in data:
            continue
        if value is None and isinstance(flag, str):
            value = math.inf if flag == "+inf" else -math.inf
        elif isinstance(value, list) and isinstance(flag, list):
            value = [(math.inf if f == "+inf" else -math.inf) if v is None and f else v
                     for v, f in zip(value, flag, strict=False)]
        if isinstance(value, Mapping):
            value = unflag(value)
        elif isinstance(value, list):
            value = [unflag(v) if isinstance(v, Mapping) else v for v in value]
        out[key] = value
    return out


def _tidy(values: Sequence, scale: float, rel: float = 1e-9) -> list:
    """``values`` with round-off below ``rel * scale`` shown as 0 (a harmonic the forcing does
    not contain comes out as 1e-15 of the largest, say)."""
    out = []
    for v in values:
        try:
            out.append(0.0 if abs(float(v)) < rel * scale else v)
        except (TypeError, ValueError):
            out.append(v)
    return out


def vibration(res) -> list[Table]:
    """The forced vibration under the type's periodic forcing (the shaft governor's valve gear,
    Hamabe Part II): the figures, the harmonics and one revolution of the steady response; the
    headings cite the type's method (:meth:`Governor.vibration_method`)."""
    vib = res.dynamics.get("vibration")
    if not isinstance(vib, Mapping):
        return []
    vib = unflag(vib)  # an undamped resonance's infinite swing: "unbounded", not blank
    g = vib.get

    def deg(v):
        return shown(v, "rad")[0]

    rows = [
        ["configuration alpha0", "deg", deg(g("alpha0_rad"))],
        ["peak-to-peak swing", "deg", deg(g("peak_to_peak_rad"))],
        ["truncation error (harmonics left out)", "deg", deg(g("truncation_error_rad"))],
        ["harmonics kept", "", g("n_harmonics")],
        ["eccentric travel", "mm", shown(g("eccentric_travel_m"), "m")[0]],
        ["mean offset", "deg",
         deg(_tidy([g("mean_offset_rad")], _finite_abs(g("peak_to_peak_rad")))[0])],
        ["k^2 at alpha0", "1/s^2", g("k2_rad2_s2")],
        ["mean speed omega0", "rad/s", g("omega0_rad_s")],
        ["dash-pot", "N m s/rad", g("dashpot_N_m_s_per_rad")],
        ["tangential inertia ratio", "", g("tangential_inertia_ratio")],
        ["resonance", "", g("resonance")],
        ["resonant orders", "", ", ".join(str(o) for o in g("resonant_orders") or []) or "none"],
        ["stable", "", g("stable")],
        ["Hamabe's case (Part II)", "", g("hamabe_case")],
    ]
    out = [Table(res.method.heading("vibration", "Forced vibration"),
                 ["quantity", "unit", "value"], [[a, b, cell(v)] for a, b, v in rows],
                 properties=True)]
    harmonics = [h for h in g("harmonics") or [] if isinstance(h, Mapping)]
    if harmonics:
        moments = [h.get(k) for h in harmonics for k in ("moment_cos_N_m", "moment_sin_N_m")]
        amplitudes = [h.get("amplitude_rad") for h in harmonics]
        m_scale, a_scale = (max(map(_finite_abs, v), default=0.0) for v in (moments, amplitudes))
        harmonics = [{**h, **dict(zip(("moment_cos_N_m", "moment_sin_N_m", "amplitude_rad"),
                                      _tidy([h.get("moment_cos_N_m"), h.get("moment_sin_N_m")],
                                            m_scale)
                                      + _tidy([h.get("amplitude_rad")], a_scale), strict=True))}
                     for h in harmonics]
        out.append(Table("Harmonics of the forced vibration",
                         ["order", "moment cos (N m)", "moment sin (N m)", "amplitude (deg)",
                          "phase (deg)", "detuning", "resonant"],
                         [[cell(h.get("order")), cell(h.get("moment_cos_N_m")),
                           cell(h.get("moment_sin_N_m")), cell(deg(h.get("amplitude_rad"))),
                           cell(deg(h.get("phase_rad")) if h.get("amplitude_rad") else None),
                           cell(h.get("detuning")), cell(h.get("resonant"))]
                          for h in harmonics],
                         ["0: below 1e-9 of the largest (round-off; the forcing has no such "
                          "harmonic), its phase blank."]))
    resp = g("response") or {}
    tau, xi = resp.get("crank_angle_rad"), resp.get("xi_rad")
    if tau is not None and xi is not None:
        out.append(Table("Forced vibration: one revolution of the steady response",
                         ["crank angle (deg)", "swing xi (deg)"],
                         [[cell(deg(a)), cell(deg(b))] for a, b in zip(tau, xi, strict=True)],
                         ["xi: the pendulum's angle minus alpha0"],
                         Chart("Forced vibration over one revolution", 0, (1,)), series=True))
    return out


#: The dynamics keys the tables above declare; any other key is listed as recorded.
_DYNAMICS_KEYS = {"load_changes", "friction", "vibration", "k2_normal_rad2_s2"}


def restoring(res) -> list[Table]:
    """k^2 at the normal configuration (the type's restoring stiffness, its method's ``k2``),
    and any dynamics result no table declares (as JSON text, so nothing is silently
    dropped)."""
    dyn = res.dynamics or {}
    out = []
    k2n = dyn.get("k2_normal_rad2_s2")
    if k2n is not None:
        w0sq = res.omega_reference ** 2
        k2, ceiling = res.method.named("k2"), res.method.named("resonance")
        out.append(Table(f"Restoring stiffness at the normal configuration ({k2.cite})",
                         ["quantity", "unit", "value"],
                         [["k^2", "1/s^2", cell(k2n)], ["k^2 / omega0^2", "", cell(k2n / w0sq)]],
                         ["stable and clear of resonance for 0 < k^2 / omega0^2 < 1"
                          + (f" (the ceiling {ceiling.cite})" if ceiling.borrowed else "")
                          if ceiling is not None else
                          "stable for k^2 > 0; this type keeps no ceiling on k^2 / omega0^2 "
                          "(nothing forces its flying masses at the running speed's "
                          "harmonics)"],
                         properties=True))
    other = {k: v for k, v in dyn.items() if k not in _DYNAMICS_KEYS}
    if other:
        out.append(_recorded("Other dynamics results (as recorded)", other))
    return out


def dynamics(res) -> list[Table]:
    """Every dynamics table of ``res`` in order: load changes (with friction), roots and
    responses, the forced vibration, k^2 at the normal configuration, and anything else the
    result records (:func:`restoring`)."""
    return load_changes(res) + vibration(res) + restoring(res)


def _recorded(title: str, data: Mapping) -> Table:
    """Keys no table declares, each as recorded (its key, which names its unit, as the label)
    with its value as JSON text."""
    import json

    from ..jsonable import jsonable

    rows = []
    for key, value in data.items():
        label, unit = str(key).replace("_", " "), ""
        v = jsonable(value) if not callable(getattr(value, "to_dict", None)) else value.to_dict()
        try:
            text = v if isinstance(v, int | float | str) else json.dumps(jsonable(v))
        except TypeError:
            text = repr(value)
        if isinstance(text, str) and len(text) > 200:
            text = text[:197] + "..."
        rows.append([label, unit, cell(text)])
    return Table(title, ["quantity", "unit", "value"], rows, properties=True)


# --------------------------------------------------------------------------------------------
# optimisation

_SEARCH = {"springs": "springs on the catalogue grid", "masses": "flying masses on the grid",
           "combinations": "combinations searched", "statics_feasible": "pass the statics",
           "spring_feasible": "pass the spring checks",
           "dynamics_checked": "dynamics checked (best first)"}


def recorded_units(res) -> dict[str, tuple[str, str]]:
    """The optimiser's records (``optimisation["design"]``, the continuous bound, a robust
    design's tolerances, nut, valve and cost): JSON key -> (label, SI unit), declared here once.
    Each key is made from its label and unit (:func:`govopt.verdict.json_key`, the rule the
    records follow), never the unit read back from a key."""
    gov = res.spec.governor
    damping = "N*m*s/rad" if gov.coordinate == "angle" else "N*s/m"
    objective = ((res.optimisation or {}).get("objective") or {}).get("unit", "")
    declared = [
        (f"{gov.mass_key} weight", "N"), (f"{gov.mass_key} mass", "kg"), ("central mass", "kg"),
        ("wire diameter", "m"), ("coil radius", "m"), ("active turns", ""),
        (gov.free_length_key.replace("_", " "), "m"), ("free half length", "m"),
        ("dashpot", damping), ("dashpot feasible range", damping),
        ("dashpot margin to lower end", "%"), ("dashpot margin to upper end", "%"),
        ("spring mass", "kg"), ("stiffness", "N/m"), ("shear stress", "Pa"),
        ("range", "m"), ("needed range", "m"), ("nominal setting", "m"),
        ("range", damping), ("needed range", damping), ("nominal setting", damping),
        ("nominal objective", objective), ("robust objective", objective), ("increase", "%")]
    return {json_key(name, unit): (name, unit) for name, unit in declared}


def _quantities(res, data: Mapping, skip: Sequence[str] = ()) -> list[list[Any]]:
    """``[label, shown unit, value]`` rows of an optimiser's record, each key's label and unit
    as :func:`recorded_units` declares them (a key it does not declare: as recorded, no
    unit)."""
    units = recorded_units(res)
    rows = []
    for key, value in data.items():
        if key in skip or value is None:  # unset (no dash-pot without an engine): no row
            continue
        label, unit = units.get(str(key), (str(key).replace("_", " "), ""))
        v, u = shown(value, unit)
        u = u.replace("*", " ")  # as people write it: N m s/rad
        if isinstance(v, list | tuple):
            for end, x in zip(("from", "to"), v, strict=False):
                rows.append([f"{label} {end}", u, cell(x, "no upper end found")])
        else:
            rows.append([label, u, cell(v)])
    return rows


def optimisation(res) -> list[Table]:
    """The optimiser's record (``govopt design``): status and objective with its unit, the
    continuous bound and gap, the search, the chosen design, the bound's design and the
    sensitivities. Empty for an evaluation."""
    opt = res.optimisation or {}
    if not opt:
        return []
    obj = opt.get("objective") or {}
    unit = obj.get("unit", "")
    v, u = shown(opt.get("value"), unit)
    rows = [["status", "", cell(opt.get("status"))],
            [f"objective: {str(obj.get('name', '')).replace('_', ' ')}"
             + (f" ({obj['counts']})" if obj.get("counts") else ""), u, cell(v)]]
    if opt.get("bound") is not None:
        rows.append(["continuous bound (GP relaxation)", u,
                     cell(shown(opt["bound"], unit)[0])])
    if opt.get("gap") is not None:
        rows.append(["gap to the bound", "%", cell(100.0 * opt["gap"])])
    rows += [[_SEARCH.get(k, k.replace("_", " ")), "", cell(n)]
             for k, n in (opt.get("search") or {}).items()]
    out = [Table("Optimisation (govopt design)", ["quantity", "unit", "value"], rows,
                 [str(n) for n in opt.get("notes") or []], properties=True)]
    if opt.get("design"):
        out.append(Table("Chosen design", ["quantity", "unit", "value"],
                         _quantities(res, opt["design"]), properties=True))
    if opt.get("bound_design"):
        out.append(Table("Continuous bound's design (not buildable: a lower bound)",
                         ["quantity", "unit", "value"],
                         _quantities(res, opt["bound_design"]), properties=True))
    out += robustness(res, opt.get("robust"))
    sens = opt.get("sensitivities") or {}  # elasticities: % of the objective per +1 %
    if sens:
        out.append(Table("Sensitivities: +1 % on a requirement",
                         ["requirement", "change (%)", "objective change (%)"],
                         [[name, cell(1.0), cell(e)] for name, e in sens.items()]))
    return out


def robustness(res, rob) -> list[Table]:
    """A robust design's record (:mod:`govopt.optimize.robust`): the tolerance box,
    the worst case of each check over it beside the nominal value, the adjusting nut,
    the Monte-Carlo verification and what robustness cost."""
    if not isinstance(rob, Mapping):
        return []
    tol = rob.get("tolerances") or {}
    rows = [["EN 15800 spring grade", "", cell(tol.get("spring_grade"))],
            ["dash-pot setting +-", "%", cell(100.0 * (tol.get("dashpot_fraction") or 0.0))],
            ["flying and central masses +-", "%",
             cell(100.0 * (tol.get("masses_fraction") or 0.0))],
            ["engine torque slope +-", "%",
             cell(100.0 * (tol.get("torque_slope_fraction") or 0.0))]]
    rows += [[f"{r[0]} +-", r[1], r[2]] for r in _quantities(res, tol.get("half_widths") or {})]
    for key, label in (("adjusting_nut", "adjusting nut"), ("dashpot_valve", "dash-pot valve")):
        item = rob.get(key)
        if isinstance(item, Mapping):
            rows += [[f"{label}: {r[0]}", r[1], r[2]] for r in _quantities(res, item)]
        else:
            rows.append([label, "", "not adjusted by the fitter"])
    rows.append(["corners of the box evaluated", "", cell(rob.get("corners"))])
    if rob.get("points_evaluated") is not None:  # corners, edges and inner maximisations
        rows.append(["points of the box evaluated", "", cell(rob.get("points_evaluated"))])
    bent = [f"{c['check']} ({', '.join(c['not_monotone_in'])})"
            for c in rob.get("checks") or [] if c.get("not_monotone_in")]
    rows.append(["checks not monotone in a tolerance", "", "; ".join(bent) or "none"])
    band = rob.get("speed_band") or {}
    if band.get("lowest_rad_s"):
        rpm = 30.0 / math.pi
        for end, i in (("inner", 0), ("outer", -1)):
            rows.append([f"speed at the {end} end over the box", "rpm",
                         f"{band['lowest_rad_s'][i] * rpm:.5g} .. "
                         f"{band['highest_rad_s'][i] * rpm:.5g}"])
    mc = rob.get("monte_carlo") or {}
    if mc:
        lo, hi = (mc.get("ci95") or [None, None])[:2]
        rows += [["Monte-Carlo samples (seed)", "", f"{mc.get('samples')} ({mc.get('seed')}), "
                  f"{mc.get('distribution')}"],
                 ["probability every check holds", "%", cell(100.0 * mc["probability"])],
                 ["  95 % Wilson interval", "%", f"{100.0 * lo:.4g} .. {100.0 * hi:.4g}"]]
        rows += [[f"  samples failing '{name}'", "", cell(count)]
                 for name, count in (mc.get("failing_checks") or {}).items()]
    cost = {k: v for k, v in (rob.get("cost") or {}).items() if isinstance(v, int | float)}
    rows += [[f"robustness cost: {r[0]}", r[1], r[2]] for r in _quantities(res, cost)]
    notes = [str(n) for n in tol.get("notes") or []]
    out = [Table("Robust design: the tolerance box", ["quantity", "unit", "value"],
                 rows, notes, properties=True)]
    checks = [c for c in rob.get("checks") or [] if isinstance(c, Mapping)]
    if checks:
        body = []
        for c in checks:
            nominal, u = shown(c.get("nominal"), c.get("unit", ""))
            worst, _ = shown(c.get("worst_case"), c.get("unit", ""))
            limit, _ = shown(c.get("limit"), c.get("unit", ""))
            # where, in half-widths of each tolerance: a face as its sign, inside as a number
            at = " ".join(f"{k}{'+' if v == 1 else '-' if v == -1 else f'{v:+.2g}'}"
                          for k, v in (c.get("worst_at") or {}).items())
            body.append([c.get("check"), cell(nominal), cell(worst), c.get("sense", ""),
                         cell(limit), u,
                         cell(100.0 * c.get("worst_margin", float("nan"))), at,
                         c.get("found_by", ""), "PASS" if c.get("holds") else "FAIL"])
        out.append(Table("Worst case over the tolerance box (after adjustment)",
                         ["check", "nominal", "worst case", "sense", "limit", "unit",
                          "worst margin (%)", "worst at", "found by", "result"], body,
                         ["worst at: in half-widths of each tolerance (+, -: a face of the box); "
                          "found by: a corner or an edge of the box, or the inner maximisation "
                          "of a check not monotone in a tolerance"]))
    return out
