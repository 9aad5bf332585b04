"""Bulk evaluation: many designs of one spec at once, vectorised, as one table.

:func:`evaluate_many` gives, for every design, the figures and the checks that
:func:`govopt.evaluate` gives for it (the same names, values and margins, to rounding), as one
row of a pandas frame; :func:`result_row` flattens one :class:`~govopt.result.Result` to the
same row. Studies (:mod:`govopt.study`) are tables of these rows.

Everything is written on the seam (:mod:`govopt.governors.base`), so it holds for every governor
type: the designs' masses, springs and dash-pots are arrays of shape ``(N, 1)`` against the
configurations ``x`` of shape ``(K,)``; the statics (Hamabe eqs. 1, 2, 11, 12), ``k^2``
(eqs. 18-20), the load-change model (eqs. 24-32) through
:func:`govopt.analysis.transient.analyse_many`, and the classic measures (textbook ch. 3) are
evaluated for all ``N`` designs in a few numpy operations, in chunks that bound the memory.
Where a type has no vectorised form of a part (the spring's own checks of a non-helical
spring, a periodic forcing, Hamabe's friction transient), that part is evaluated design by
design with the very functions :func:`govopt.evaluate` calls.
"""

from __future__ import annotations

import math
from dataclasses import fields

import numpy as np
import pandas as pd

from .analysis import loadchange, statics
from .analysis import transient as tr
from .governors import Governor
from .requirements import (
    CheckTable,
    load_change_rows,
    requirement_rows,
    statics_figures,
    statics_rows,
    stress_row,
    vibration_rows,
)
from .result import Result
from .spec import Design, Spec
from .springs import helical as hx

#: the fields of :class:`govopt.spec.Design`: the columns a frame of designs may have (SI)
DESIGN_FIELDS = tuple(f.name for f in fields(Design))

#: designs evaluated at once (bounds the memory: ~ CHUNK x configurations x 30 arrays)
CHUNK = 4096

STATUS_PASS, STATUS_FAIL, STATUS_ERROR = "pass", "fail", "error"


# ---------------------------------------------------------------------------------------------
# Columns
# ---------------------------------------------------------------------------------------------

def value_column(check: str) -> str:
    """Column of a check's value (SI) in a row."""
    return f"value: {check}"


def margin_column(check: str) -> str:
    """Column of a check's relative margin (positive when satisfied; ``Check.margin``)."""
    return f"margin: {check}"


def passed_column(check: str) -> str:
    return f"passed: {check}"


def check_names(columns) -> list[str]:
    """The checks present in a table's ``columns``, in order."""
    return [c[len("margin: "):] for c in columns if c.startswith("margin: ")]


def _dashpot_column(gov: Governor) -> str:
    return f"dashpot_{gov.key_unit('damping')}"


def _objective_name(spec: Spec) -> str:
    return spec.requirements.objective if spec.requirements is not None else "moving_mass"


# ---------------------------------------------------------------------------------------------
# One Result -> one row
# ---------------------------------------------------------------------------------------------

def result_row(res: Result) -> dict:
    """One flat record of a result (SI): the design, the figures, every check's value, margin
    and verdict, the objective, status and message -- the row :func:`evaluate_many` gives for
    the same design."""
    spec, sd, st, gov, ds = res.spec, res.spring, res.statics, res.spec.governor, res.design
    i_n = int(np.searchsorted(st.alpha, gov.x_normal))
    row = {f"{gov.mass_key}_mass_kg": float(sd.m), "central_mass_kg": float(sd.central)}
    if gov.spring is not None:
        row.update({"wire_diameter_m": float(sd.d), "coil_radius_m": float(sd.r),
                    "active_turns": float(sd.n), "stiffness_N_per_m": float(sd.kappa),
                    f"{gov.free_length_key}_m": float(sd.l0)})
    row[_dashpot_column(gov)] = math.nan if ds.dashpot is None else float(ds.dashpot)
    row.update({"irregularity": st.irregularity, "omega_inner_rad_s": float(st.omega[0]),
                "omega_outer_rad_s": float(st.omega[-1]),
                "omega_normal_rad_s": float(st.omega[i_n])})
    if gov.spring is not None:
        row["min_spring_force_N"] = float(np.min(st.spring_force))
        row["max_spring_force_N"] = float(np.max(st.spring_force))
        row["max_stress_Pa"] = float(np.max(st.stress))
    props = res.spring_properties
    spring_mass = props.get("mass_kg", 0.0)
    for key in ("spring_index", "wahl_factor", "surge_frequency_Hz", "body_length_m"):
        if key in props:
            row[key] = float(props[key])
    row["spring_mass_kg"] = float(spring_mass) if props else math.nan
    row["moving_mass_kg"] = float(sd.m + sd.central + spring_mass)
    if res.k2 is not None:
        row.update({"k2_min_rad2_s2": float(np.min(res.k2)),
                    "k2_max_rad2_s2": float(np.max(res.k2)),
                    "k2_normal_rad2_s2": float(res.k2[i_n])})
    cl = res.classic
    if cl:
        row.update({k: cl[k] for k in ("range_rad_s", "sensitiveness", "stability", "effort",
                                       "power", "friction_band", "insensitiveness")})
    changes = res.dynamics.get("load_changes", [])
    for lc in changes:
        row[f"hurwitz_margin: {lc['name']}"] = float(lc["hurwitz_margin"])
        over = next(k for k in lc if k.startswith("over_regulation_")
                    and not k.startswith("over_regulation_scaled"))
        row[f"over_regulation: {lc['name']}"] = float(lc[over])
        row[f"settling_time_s: {lc['name']}"] = float(lc["settling_time_s"])
    if changes:
        row["settling_time_s"] = max(float(lc["settling_time_s"]) for lc in changes)
    vib = res.dynamics.get("vibration")
    if vib is not None:
        row["vibration_p2p_rad"] = float(vib["peak_to_peak_rad"])
    for c in res.checks:
        row[value_column(c.name)] = float(c.value)
        row[margin_column(c.name)] = float(c.margin)
        row[passed_column(c.name)] = bool(c.passed)
    name = _objective_name(spec)
    row["objective"] = name
    row["objective_value"] = _objective(name, row)
    failed = [c.name for c in res.checks if not c.passed]
    row["status"] = STATUS_FAIL if failed else STATUS_PASS
    row["message"] = ("fails: " + ", ".join(failed)) if failed else ""
    return row


#: the objectives of `govopt design` (:func:`govopt.optimize.design.objective_values`) as columns:
#: moving mass ``m + M + spring mass``, spring mass, the longest settling time, the vibration's
#: peak-to-peak
OBJECTIVE_COLUMN = {"moving_mass": "moving_mass_kg", "spring_mass": "spring_mass_kg",
                     "settling_time": "settling_time_s", "vibration": "vibration_p2p_rad"}


def _objective(name: str, row: dict) -> float:
    return float(row.get(OBJECTIVE_COLUMN[name], math.nan))


# ---------------------------------------------------------------------------------------------
# Designs as arrays
# ---------------------------------------------------------------------------------------------

def design_arrays(spec: Spec, designs) -> dict[str, np.ndarray]:
    """The designs as one float array per :class:`~govopt.spec.Design` field (SI, NaN for
    "not given"). ``designs``: a pandas frame or a dict of arrays (columns named as the fields;
    a missing column takes the spec's own ``[design]`` value), or a sequence of
    :class:`Design`."""
    if isinstance(designs, list | tuple) and designs and isinstance(designs[0], Design):
        cols = {f: np.array([np.nan if getattr(d, f) is None else getattr(d, f)
                             for d in designs], dtype=float) for f in DESIGN_FIELDS}
        return cols
    if isinstance(designs, pd.DataFrame):
        given = {c: designs[c].to_numpy(dtype=float) for c in designs.columns}
    else:
        given = {c: np.asarray(v, dtype=float) for c, v in dict(designs).items()}
    unknown = sorted(set(given) - set(DESIGN_FIELDS))
    if unknown:
        raise ValueError(f"unknown design columns {unknown}; expected some of {DESIGN_FIELDS}")
    n = max((np.size(v) for v in given.values()), default=0)
    base = spec.design
    out = {}
    for f in DESIGN_FIELDS:
        if f in given:
            out[f] = np.broadcast_to(given[f], (n,)).astype(float)
        else:
            v = None if base is None else getattr(base, f)
            out[f] = np.full(n, np.nan if v is None else float(v))
    return out


def _design_of(cols: dict, i: int) -> Design:
    """Row ``i`` of :func:`design_arrays` as a :class:`Design`."""
    return Design(**{f: (None if np.isnan(cols[f][i]) else float(cols[f][i]))
                     for f in DESIGN_FIELDS})


# ---------------------------------------------------------------------------------------------
# Vectorised checks
# ---------------------------------------------------------------------------------------------

def _check_columns(table: CheckTable) -> dict:
    """``value: ``, ``margin: `` and ``passed: `` columns (nullable booleans) of each check."""
    out = {}
    for name in table.names:
        v, _, m, _, p, applies = table.cols[name]
        out[value_column(name)] = v
        out[margin_column(name)] = m
        out[passed_column(name)] = pd.arrays.BooleanArray(p, ~applies)
    return out


def _status(table: CheckTable):
    """``(status, message)`` arrays: "fail" and "fails: <names>" where a check failed."""
    names = table.names
    bits = np.zeros(table.n, dtype=object if len(names) > 62 else np.int64)
    for j, name in enumerate(names):
        *_, p, applies = table.cols[name]
        bits = bits + np.where(applies & ~p, 1 << j, 0)
    patterns, inverse = np.unique(bits, return_inverse=True)
    texts = np.array([", ".join(nm for j, nm in enumerate(names) if int(b) >> j & 1)
                      for b in patterns], dtype=object)
    failed = bits != 0
    message = np.where(failed, "fails: " + texts[inverse.reshape(-1)], "")
    return np.where(failed, STATUS_FAIL, STATUS_PASS), message


def _overridden(gov: Governor, method: str) -> bool:
    """Whether the governor type supplies its own ``method`` (not the seam's default)."""
    own = getattr(type(gov), method, None)
    return own is not None and own is not getattr(Governor, method, None)


# ---------------------------------------------------------------------------------------------
# evaluate_many
# ---------------------------------------------------------------------------------------------

def evaluate_many(spec: Spec, designs, *, dynamics: bool = True, vibration: bool = True,
                  classic: bool = True, chunk: int = CHUNK) -> pd.DataFrame:
    """Evaluate many designs of ``spec`` at once: one row per design, the columns of
    :func:`result_row` (the figures and checks :func:`govopt.evaluate` gives, to rounding).

    ``designs``: see :func:`design_arrays`. ``dynamics``: the load-change transients (Hamabe
    Part III, eqs. 28-32); ``vibration``: the type's periodic forcing (Hamabe Part II);
    ``classic``: range, sensitiveness, stability, effort and power (textbook ch. 3). With all
    three off only the statics, the spring and ``k^2`` are evaluated: the fast path. Designs
    the vectorised path cannot decide alone are evaluated by :func:`govopt.evaluate` itself
    (so that their row is its row): a design with friction in a spec with load changes
    (Hamabe's friction transient, eqs. 42-46, is a sequence of strokes), a type whose spring is
    not the helical one (its own rate, stress and checks), and any design the vectorised path
    finds impossible (no equilibrium speed, a non-finite figure, a free length <= 0: the row
    then carries evaluate's own message). A design that cannot be evaluated is a row with
    ``status = "error"`` and the reason in ``message``, never an exception.
    """
    cols = design_arrays(spec, designs)
    n = len(cols["pendulum_mass"])
    parts = [_evaluate_block(spec, {k: v[s:s + chunk] for k, v in cols.items()}, dynamics,
                             vibration, classic) for s in range(0, n, chunk)]
    return pd.concat(parts, ignore_index=True) if parts else pd.DataFrame()


def _scalar_row(spec: Spec, design: Design, dynamics: bool, vibration: bool,
                classic: bool) -> dict:
    """The row of one design by :func:`govopt.evaluate` (an error row on a user's error)."""
    from .errors import GovoptError
    from .evaluation import evaluate

    try:
        res = evaluate(spec.with_design(design))
    except GovoptError as exc:
        return _error_row(spec, design, str(exc))
    row = result_row(res)
    if not (dynamics and vibration and classic):  # the same columns as the vectorised path
        drop = ({"range_rad_s", "sensitiveness", "stability", "effort", "power",
                 "friction_band", "insensitiveness"} if not classic else set())
        for k in list(row):
            if (k in drop or (not vibration and (k == "vibration_p2p_rad"
                                                 or k.endswith("vibration peak-to-peak")))
                    or (not dynamics and _dynamic_column(k))):
                del row[k]
    return row


def _dynamic_column(k: str) -> bool:
    return any(k.startswith(p) or f": {p}" in k for p in (
        "hurwitz_margin:", "over_regulation:", "settling_time_s", "Hurwitz margin",
        "no over-regulation:", "settling time:", "friction:"))


def _error_row(spec: Spec, design: Design, message: str) -> dict:
    gov = spec.governor
    row = {f"{gov.mass_key}_mass_kg": math.nan if design.pendulum_mass is None
           else design.pendulum_mass,
           "central_mass_kg": design.central_mass or 0.0}
    if gov.spring is not None:
        row.update({k: math.nan if v is None else v for k, v in (
            ("wire_diameter_m", design.wire_diameter), ("coil_radius_m", design.coil_radius),
            ("active_turns", design.active_turns))})
    row[_dashpot_column(gov)] = math.nan if design.dashpot is None else design.dashpot
    row.update({"objective": _objective_name(spec), "objective_value": math.nan,
                "status": STATUS_ERROR, "message": message})
    return row


def _invalid(spec: Spec, design: Design) -> str | None:
    """What the spec parser would say of a design given as numbers (a mass that is not a
    number, a wire thicker than its coil), or None."""
    if design.pendulum_mass is None or not math.isfinite(design.pendulum_mass):
        return (f"{spec.path}: design: the {spec.governor.mass_key} mass is missing or not a "
                "finite number")
    if design.wire_diameter is not None and design.coil_radius is not None and \
            design.wire_diameter >= 2.0 * design.coil_radius:
        return (f"{spec.path}: design.wire_diameter: expected a wire thinner than the coil "
                "diameter 2 r")
    return None


def _evaluate_block(spec: Spec, cols: dict, dynamics: bool, vibration: bool,
                    classic: bool) -> pd.DataFrame:
    """One chunk: the vectorised path, and :func:`govopt.evaluate` for the designs it cannot
    decide alone (see :func:`evaluate_many`). A spec's ``[analysis] use_case`` is honoured as
    evaluate honours it (:func:`govopt.fidelity.plan`: its settings, only its analyses)."""
    from .fidelity import plan as use_case_plan

    own = spec  # evaluate applies the plan itself
    plan = use_case_plan(spec)
    if plan is not None:
        spec = plan.apply(spec)
        dynamics = dynamics and plan.runs("load_change")
        vibration = vibration and plan.runs("vibration")
    gov = spec.governor
    n = len(cols["pendulum_mass"])
    mat = spec.material
    own_spring = gov.spring is not None and (any(
        _overridden(gov, f) for f in ("spring_rate", "spring_stress", "spring_checks"))
        or (mat is not None and getattr(mat, "grade", None) is not None))
    scalar = np.full(n, own_spring)
    if dynamics and spec.engine is not None and spec.load_changes:
        for value in np.unique(cols["friction_moment"]):
            probe = Design(pendulum_mass=1.0,
                           friction_moment=None if np.isnan(value) else float(value))
            if any(float(gov.friction(lc.alpha_to, probe)) > 0 for lc in spec.load_changes):
                scalar |= (cols["friction_moment"] == value) | (
                    np.isnan(cols["friction_moment"]) & np.isnan(value))
    frame = None
    if not scalar.all():
        frame, impossible = _vectorised(spec, cols, dynamics, vibration, classic)
        scalar |= impossible
    if not scalar.any():
        return frame
    rows = {}
    for i in np.nonzero(scalar)[0]:
        design = _design_of(cols, i)
        invalid = _invalid(spec, design)
        rows[int(i)] = (_error_row(spec, design, invalid) if invalid else
                        _scalar_row(own, design, dynamics, vibration, classic))
    extra = pd.DataFrame(list(rows.values()), index=list(rows))
    if frame is None:
        return extra.sort_index().reset_index(drop=True)
    frame = frame.loc[~scalar]
    return pd.concat([frame, extra]).sort_index().reset_index(drop=True)


def _vectorised(spec: Spec, cols: dict, dynamics: bool, vibration: bool, classic: bool):
    """The vectorised evaluation of a chunk: ``(frame, impossible)``, ``impossible`` marking the
    designs to hand to :func:`govopt.evaluate` (their rows in ``frame`` are placeholders)."""
    gov = spec.governor
    n = len(cols["pendulum_mass"])
    col = {k: v[:, None] for k, v in cols.items()}  # (N, 1) against configurations (K,)
    m = col["pendulum_mass"]
    central = np.where(np.isnan(col["central_mass"]), 0.0, col["central_mass"])
    d, r, nt = col["wire_diameter"], col["coil_radius"], col["active_turns"]
    mat = spec.material
    impossible = ~np.isfinite(cols["pendulum_mass"])
    impossible |= np.isfinite(cols["wire_diameter"]) & (
        cols["wire_diameter"] >= 2.0 * cols["coil_radius"])
    with np.errstate(all="ignore"):
        if gov.spring is None:
            kappa, l0 = np.zeros_like(m), np.zeros_like(m)
        else:
            rate = (hx.stiffness_r(d, r, nt, mat.shear_modulus) if mat is not None
                    and mat.shear_modulus is not None else np.full_like(m, np.nan))
            kappa = np.where(np.isfinite(col["spring_stiffness"]), col["spring_stiffness"], rate)
            l0 = col["free_half_length"]
            if np.isnan(l0).any():
                l0 = np.where(np.isnan(l0), statics.free_half_length(spec, m, kappa, central),
                              l0)
            if gov.free_length_positive:
                impossible |= ~(l0[:, 0] > 0)
        I_given = col["pendulum_inertia"]
        I_n = np.where(np.isnan(I_given), gov.inertia(np.asarray(gov.x_normal), m, central),
                       I_given)
        impossible |= ~np.isfinite(kappa[:, 0]) | ~np.isfinite(l0[:, 0]) | ~np.isfinite(
            _flat(I_n, n))
        x = statics.configurations(spec)
        K = x.size
        i_n = int(np.searchsorted(x, gov.x_normal))
        t = statics.terms(spec, x, m, central)
        w2 = np.broadcast_to(t.omega_squared(kappa, l0), (n, K))
        impossible |= ~(w2 > 0).all(axis=1)
        omega = np.sqrt(w2)
        w2c = omega**2  # as evaluate: k^2 at the characteristic's omega^2
        wi, wa, wn = omega[:, 0], omega[:, -1], omega[:, i_n]
        I_x = np.where(np.isnan(I_given), gov.inertia(x, m, central), I_given)
        stiff = t.stiffness(kappa, l0, w2c)
        k2 = np.broadcast_to(stiff / I_x, (n, K))
        A_F, B_F = gov.spring_force_coefficients(x)
        F = np.broadcast_to(kappa * (A_F - B_F * l0), (n, K))
        M_f = np.broadcast_to(kappa * (t.A - t.B * l0), (n, K))
        M_z = np.broadcast_to(w2 * t.jp, (n, K))
        helical = (mat is not None) & np.isfinite(cols["wire_diameter"])
        stress = np.full((n, K), np.nan)
        if gov.spring is not None and mat is not None:
            stress = np.broadcast_to(hx.shear_stress_r(F, d, r, mat.stress_correction), (n, K))
        finite = [omega, M_f, M_z, F, k2]
        impossible |= ~np.all([np.isfinite(v).all(axis=1) for v in finite], axis=0)
        impossible |= helical & ~np.isfinite(stress).all(axis=1)
        sd = statics.SpringDesign(m, I_n, kappa, l0, d, r, nt, central, False)
        if spec.analysis.reaction_slope:  # statics.characteristic_slope on the terms in hand
            slope = stiff / (2.0 * omega * t.lever)
        else:
            slope = statics.characteristic_slope(spec, sd, x, omega)
        slope = np.broadcast_to(slope, (n, K))
        secant = np.diff(omega, axis=1) / np.diff(x)
        rise = np.minimum(slope.min(axis=1), secant.min(axis=1, initial=np.inf))
    ok = ~impossible
    omega_mean = spec.speed.omega_mean if spec.speed is not None else math.nan
    out = {f"{gov.mass_key}_mass_kg": cols["pendulum_mass"], "central_mass_kg": central[:, 0]}
    if gov.spring is not None:
        out.update({"wire_diameter_m": cols["wire_diameter"],
                    "coil_radius_m": cols["coil_radius"], "active_turns": cols["active_turns"],
                    "stiffness_N_per_m": kappa[:, 0], f"{gov.free_length_key}_m": l0[:, 0]})
    out[_dashpot_column(gov)] = cols["dashpot"]
    out.update({"irregularity": (wa - wi) / omega_mean, "omega_inner_rad_s": wi,
                "omega_outer_rad_s": wa, "omega_normal_rad_s": wn})
    if gov.spring is not None:
        out.update({"min_spring_force_N": F.min(axis=1), "max_spring_force_N": F.max(axis=1),
                    "max_stress_Pa": stress.max(axis=1)})
    smass = np.zeros(n)
    if mat is not None and mat.shear_modulus is not None:
        dd, rr, nn = cols["wire_diameter"], cols["coil_radius"], cols["active_turns"]
        with np.errstate(all="ignore"):
            C = hx.spring_index_r(dd, rr)
            props = {"spring_index": C, "wahl_factor": hx.wahl_factor(C),
                     "surge_frequency_Hz": hx.surge_frequency_r(dd, rr, nn, mat.shear_modulus,
                                                                  mat.density),
                     "body_length_m": (nn + 1.0) * dd}
            smass = hx.wire_mass(dd, rr, nn, mat.density)
        for k, v in props.items():
            out[k] = np.where(helical, v, np.nan)
    out["spring_mass_kg"] = np.where(helical, smass, np.nan)
    out["moving_mass_kg"] = cols["pendulum_mass"] + central[:, 0] + np.where(helical, smass, 0.0)
    out.update({"k2_min_rad2_s2": k2.min(axis=1), "k2_max_rad2_s2": k2.max(axis=1),
                "k2_normal_rad2_s2": k2[:, i_n]})

    # -- checks, in evaluate's order --
    checks = CheckTable(n)
    req = spec.requirements
    w0sq = np.full(n, omega_mean**2) if spec.speed is not None else wn**2
    if gov.spring is not None and mat is not None:
        checks.add_row(stress_row(mat), {"stress": stress.max(axis=1)},
                       where=np.isfinite(cols["wire_diameter"]))
        if helical.any():  # Governor.spring_checks' geometric rows: no grade needed
            from .analysis import spring_engineering

            for name, (value, limit, sense) in spring_engineering.geometry_rows(
                    spec, cols["wire_diameter"], 2.0 * cols["coil_radius"],
                    cols["active_turns"], kappa[:, 0], l0[:, 0], F.min(axis=1),
                    F.max(axis=1)).items():
                checks.add(name, value, limit, sense, where=helical)
    band = (None, None)
    if spec.speed is not None and spec.speed.band:  # evaluate's band rows (statics)
        fr = _friction_at(gov, cols, np.array([gov.x_inner, gov.x_outer]))
        with np.errstate(all="ignore"):
            band = tuple(np.sqrt(np.maximum(_flat(w2, n), 0.0)) for w2 in
                         statics.band_speeds_squared(spec, m, kappa, l0, central,
                                                     (fr[:, :1], fr[:, 1:])))
    checks.add_rows(statics_rows(spec), statics_figures(out["irregularity"], *band, rise, w0sq,
                                                        F, k2))
    dashpot = cols["dashpot"]
    has_dashpot = np.isfinite(dashpot)
    if dynamics and spec.engine is not None and spec.load_changes:
        settle = np.full(n, -np.inf)
        run = ok & has_dashpot
        for lc in spec.load_changes:
            hur, over, overs, st_time, xi0, good = _load_change_many(
                spec, lc, m, kappa, l0, central, I_given, dashpot, run)
            impossible |= run & ~good
            on = run & good
            out[f"hurwitz_margin: {lc.name}"] = np.where(on, hur, np.nan)
            out[f"over_regulation: {lc.name}"] = np.where(on, over, np.nan)
            out[f"settling_time_s: {lc.name}"] = np.where(on, st_time, np.nan)
            settle = np.where(on, np.maximum(settle, st_time), settle)
            checks.add_rows(load_change_rows(spec, lc.name), {
                "hurwitz": {lc.name: hur}, "over": {lc.name: over},
                "over_regulates": {lc.name: overs}, "xi0": {lc.name: xi0},
                "settling": {lc.name: st_time}}, where=on)
        out["settling_time_s"] = np.where(settle > -np.inf, settle, np.nan)
    if vibration and _overridden(gov, "vibration"):
        want = ok & (has_dashpot | (spec.engine is not None))
        p2p = np.full(n, np.nan)
        for i in np.nonzero(want)[0]:
            sdi = _row_design(sd, i, bool(np.isfinite(I_given[i, 0])))
            vib = gov.vibration(spec, sdi, float(k2[i, i_n]),
                                float(dashpot[i]) if has_dashpot[i] else 0.0)
            if vib is not None:
                p2p[i] = vib.to_dict()["peak_to_peak_rad"]
        if want.any():
            out["vibration_p2p_rad"] = p2p
            checks.add_rows(vibration_rows(spec), {"p2p": p2p}, where=~np.isnan(p2p))
    if req is not None and helical.any():
        checks.add_rows(requirement_rows(spec, req), {
            "d": cols["wire_diameter"], "r": cols["coil_radius"], "n": cols["active_turns"],
            "m": cols["pendulum_mass"], "l0": l0[:, 0], "C": out["spring_index"],
            "body": out["body_length_m"], "surge": out["surge_frequency_Hz"]}, where=helical)
    if classic:
        out.update(_classic(spec, cols, t, sd, w2c, x, omega, ok))

    # -- assemble --
    out.update(_check_columns(checks))
    frame = pd.DataFrame(out)
    obj = _objective_name(spec)
    frame["objective"] = obj
    key = OBJECTIVE_COLUMN[obj]
    frame["objective_value"] = frame[key] if key in frame else np.nan
    frame["status"], frame["message"] = _status(checks)
    return frame, impossible


def _row_design(sd: statics.SpringDesign, i: int, given: bool) -> statics.SpringDesign:
    """Design ``i`` of a vectorised :class:`SpringDesign` as scalars (``given``: the inertia is
    the design's own, as :func:`statics.spring_design` marks it)."""
    vals = {f.name: getattr(sd, f.name) for f in fields(sd)}
    for k, v in vals.items():
        if isinstance(v, np.ndarray):
            vals[k] = float(np.broadcast_to(v, (v.shape[0], 1))[i, 0]) if v.ndim else float(v)
    return statics.SpringDesign(**{**vals, "inertia_given": given})


def _load_change_many(spec, lc, m, kappa, l0, central, I_given, dashpot, run):
    """:func:`govopt.analysis.loadchange.analyse` for many designs: Hamabe eqs. (24)-(32) with
    the coefficients of :func:`loadchange.load_change_model`, events by
    :func:`transient.analyse_many`. Returns (Hurwitz margin, over-regulation, over-regulates,
    settling time, xi0, finite)."""
    gov = spec.governor
    n = m.shape[0]
    a0x, a1x = lc.alpha_to, lc.alpha_from
    with np.errstate(all="ignore"):
        t0 = statics.terms(spec, a0x, m, central)
        t1 = statics.terms(spec, a1x, m, central)
        w0 = np.sqrt(_flat(t0.omega_squared(kappa, l0), n))
        w1 = np.sqrt(_flat(t1.omega_squared(kappa, l0), n))
        own = _flat(gov.inertia(np.asarray(a0x, dtype=float), m, central), n)
        I = np.where(np.isnan(I_given[:, 0]), own, I_given[:, 0])
        k2 = _flat(t0.stiffness(kappa, l0, (w0**2)[:, None]), n) / I
        C = 2.0 * w0 * _flat(t0.lever, n)
        R = loadchange.torque_ratio(spec, a0x)
        xi0 = np.full(n, a1x - a0x)
        eta0 = w1 * (1.0 + spec.engine.insensibility) - w0
        a = (I, np.where(np.isfinite(dashpot), dashpot, 0.0) / 3.0, I * k2 / 3.0, C * R)
        x = tr.hamabe_initial_conditions(a[0], a[2], a[3], R, xi0, eta0)
    good = np.all([np.isfinite(v) for v in (*a, *x)], axis=0) & (a[0] != 0)
    hur, over, overs, st = (np.full(n, np.nan) for _ in range(4))
    overs = np.zeros(n, bool)
    sel = np.nonzero(run & good)[0]
    if sel.size:
        s = tr.analyse_many(*(v[sel] for v in a), *(v[sel] for v in x),
                            band=spec.analysis.settling_band)
        hur[sel] = s.hurwitz_margin
        over[sel] = np.where(s.stable, s.over_regulation, np.inf)
        overs[sel] = ~s.stable | tr.over_regulates(s.over_regulation_scaled, x[0][sel])
        st[sel] = s.settling_time
    return hur, over, overs, st, x[0], good


def _flat(v, n: int) -> np.ndarray:
    """A per-design quantity of shape ``(N, 1)`` (or broadcasting to it) as ``(N,)``."""
    return np.broadcast_to(np.asarray(v, dtype=float), (n, 1))[:, 0]


def _friction_at(gov: Governor, cols: dict, x) -> np.ndarray:
    """The friction band :meth:`Governor.friction` of every design at configurations ``x``,
    shape ``(N, K)`` (evaluated once per distinct friction moment)."""
    fm = cols["friction_moment"]
    band = np.zeros((fm.size, np.size(x)))
    for value in np.unique(fm):
        rows = (fm == value) | (np.isnan(fm) & np.isnan(value))
        probe = Design(pendulum_mass=1.0, friction_moment=None if np.isnan(value) else value)
        band[rows] = gov.friction(x, probe)
    return band


def _classic(spec, cols, t, sd, w2, x, omega, ok):
    """:func:`govopt.analysis.classic.classic_measures` (its scalar figures), vectorised."""
    from .analysis.classic import speed_change, travel_between

    gov = spec.governor
    n = omega.shape[0]
    band = _friction_at(gov, cols, x)
    with np.errstate(all="ignore"):
        rise = np.sqrt(np.maximum(t.omega_squared(sd.kappa, sd.l0, band), 0.0))
        fall = np.sqrt(np.maximum(t.omega_squared(sd.kappa, sd.l0, -band), 0.0))
        i_c = int(np.searchsorted(x, gov.x_normal))
        w0 = spec.speed.omega_mean if spec.speed is not None else omega[:, i_c]
        stability = statics.stability(statics.rising_slopes(spec, sd, x, omega),
                                      np.broadcast_to(statics.slope_scale(spec, w0), (n,)))
        wi, wa = omega[:, 0], omega[:, -1]
        c, over_range = speed_change(spec, wi, wa)
        grow = (1.0 + c[:, None]) ** 2 - 1.0
        lever = np.broadcast_to(t.lever, (n, x.size))
        effort = gov.flying_masses * grow * w2 * lever / (2.0 * gov.travel_slope(x))
        ic = int(np.argmin(np.abs(x - gov.x_normal)))
        at = 0 if over_range else ic
        if over_range:
            travel = np.full(n, travel_between(spec, float(x[0]), float(x[-1])))
        else:
            target = (1.0 + c) ** 2 * w2[:, ic]
            travel = _travel_many(spec, sd, float(x[ic]), float(x[-1]), target, ok)
        return {"range_rad_s": wa - wi, "sensitiveness": 2.0 * (wa - wi) / (wa + wi),
                "stability": np.where(ok, stability, None), "effort": effort[:, at],
                "power": effort[:, at] * travel, "friction_band": band[:, ic],
                "insensitiveness": ((rise - fall) / omega).max(axis=1)}


def _travel_many(spec, sd, x0, x_end, target, ok):
    """:func:`govopt.analysis.classic._travel` for many designs: the configuration ``x1`` in
    equilibrium at speed^2 ``target`` (``brentq`` to 1e-15 in the scalar version) by a
    safeguarded Newton iteration on the characteristic, whose slope is exact on the seam
    (``d omega^2/dx = I k^2 / (jp - ci)`` with the dead loads' slope included), then the
    member's travel ``int s'(u) du`` from ``x0`` by 8-point Gauss-Legendre."""
    from .analysis.classic import travel_between

    exact = spec.with_analysis(reaction_slope=True)
    n = target.shape[0]

    def excess(u):
        t = statics.terms(exact, u[:, None], sd.m, sd.central)
        w2 = _flat(t.omega_squared(sd.kappa, sd.l0), n)
        return w2 - target, _flat(t.stiffness(sd.kappa, sd.l0, w2[:, None]) / t.lever, n)

    out = np.full(n, np.inf)
    top, _ = excess(np.full(n, x_end))
    go = ok & (top > 0)
    if not go.any():
        return out
    lo, hi = np.full(n, x0), np.full(n, x_end)
    u = np.full(n, 0.5 * (x0 + x_end))
    for _ in range(100):
        f, df = excess(u)
        lo, hi = np.where(f > 0, lo, u), np.where(f > 0, u, hi)
        step = f / df
        new = u - step
        new = np.where((new > lo) & (new < hi) & np.isfinite(new), new, 0.5 * (lo + hi))
        done = (np.abs(new - u) <= 1e-15 * np.abs(u)) | (f == 0) | (hi - lo <= 4e-16 * np.abs(u))
        u = np.where(done, u, new)
        if done[go].all():
            break
    out[go] = travel_between(spec, x0, u)[go]
    return out


__all__ = ["DESIGN_FIELDS", "design_arrays", "evaluate_many", "result_row"]
