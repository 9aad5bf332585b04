"""The one evaluator: every figure and check of N designs of a spec, over arrays, and one
design's evaluation as a :class:`~govopt.result.Result`.

:func:`core` computes, for designs given as arrays (:func:`govopt.bulk.design_arrays`), the statics
(Hamabe eqs. 1, 2, 11, 12), ``k^2`` (eqs. 18-20), the load-change model (eqs. 24-32,
:func:`govopt.analysis.transient_events.analyse_many`) and the classic measures (textbook ch. 3) in
a few numpy operations, and evaluates every requirement row of :mod:`govopt.requirements` on them in
one :class:`~govopt.requirements.CheckTable`, with a type's periodic forcing (Hamabe Part II) for
all the designs at once (:meth:`Governor.vibrations`). The parts that have no vectorised form run
inside it design by design, into the same table: Hamabe's friction transient (eqs. 42-46, a
sequence of strokes), and the spring's own checks where the type or a wire grade supplies them
(:meth:`Governor.spring_checks`). A design no
spring can realise gets the one-line diagnosis :func:`diagnose` (the ``DesignError``
:func:`govopt.evaluate` raises for it) instead of figures.

:func:`evaluate` (``govopt.evaluate``) is this core with one design, plus what only a report
needs (the characteristic table, the load changes' responses, the spring maker's sheet);
:func:`govopt.bulk.evaluate_many` is it over chunks, as a pandas frame. There is no other
computation of a check. Only what the spec asks for is modelled: dynamics run when the spec has
engine data, friction only when the design has a friction moment.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

import numpy as np

from .analysis import characteristic as chs
from .analysis import loadchange, statics
from .analysis.classic import CLASSIC_FIGURES, classic_measures
from .analysis.classic import report as classic_report
from .analysis.over_regulation import over_regulates
from .analysis.transient_cubic import hamabe_initial_conditions
from .analysis.transient_events import TransientSummary, analyse_many
from .errors import DesignError, located
from .governors import Governor
from .governors.base import Terms
from .requirements import (
    CheckTable,
    friction_rows,
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


# ---------------------------------------------------------------------------------------------
# Diagnoses of impossible designs (the DesignError evaluate raises)
# ---------------------------------------------------------------------------------------------

def possible(spec: Spec, sd: statics.SpringDesign) -> None:
    """Reject a design no spring can realise, with a diagnosis (:class:`DesignError`): a
    non-finite figure, or a spring's free length ``l0 <= 0`` (where the type's free length is a
    length, :attr:`Governor.free_length_positive`). On the seam
    ``l0 = (A_n - Q_n / kappa) / B_n`` (Hamabe, Example 1: ``l0 = l_n - F_n / (2 kappa)``) rises
    with ``kappa`` towards ``l_inf = A_n / B_n``, so ``l0 > 0`` needs
    ``kappa > kappa (1 - l0 / l_inf)``: the spring is too soft to hold the normal configuration
    at the mean speed even stretched from zero length."""
    gov = spec.governor
    name = gov.free_length_key.replace("_", " ")
    finite(spec, {f"{gov.mass_name} mass": sd.m, "inertia": sd.inertia,
                  "spring stiffness": sd.kappa, name: sd.l0})
    if gov.spring is not None and gov.free_length_positive and sd.l0 <= 0:
        l_inf = float(statics.free_half_length(spec, sd.m, np.inf, sd.central))
        need = (f"; it needs kappa > {sd.kappa * (1.0 - sd.l0 / l_inf):.6g} N/m (or a lighter "
                "flying mass)" if l_inf > 0 else "")
        raise DesignError(
            f"{spec.path}: design: impossible design: the {name} l0 = {sd.l0:.6g} m is not "
            f"positive: the spring (kappa = {sd.kappa:.6g} N/m) is too soft to hold the normal "
            f"configuration at the mean speed even stretched from zero length{need}")


def finite(spec: Spec, figures: dict) -> None:
    """:class:`DesignError` naming the first figure that is infinite or not a number."""
    for name, value in figures.items():
        bad = ~np.isfinite(np.asarray(value, dtype=float))
        if np.any(bad):
            shown = np.asarray(value, dtype=float)[bad].flat[0]
            raise DesignError(f"{spec.path}: design: impossible design: the {name} is {shown} "
                              "(not finite); the design's inputs are outside any physical range")


def overflow_message(spec: Spec) -> str:
    return (f"{spec.path}: design: impossible design: a figure overflows the floating-point "
            "range; the design's inputs are far outside any physical range")


def invalid(spec: Spec, design: Design) -> str | None:
    """What the spec parser would say of a design given as numbers (a mass that is not a
    number, a wire thicker than its coil), or None."""
    if design.flying_mass is None or not math.isfinite(design.flying_mass):
        return (f"{spec.path}: {chs.design_key(spec, 'flying_mass') or 'design'}: the "
                f"{spec.governor.mass_key} mass is missing or not a finite number")
    if design.wire_diameter is not None and design.coil_radius is not None and \
            design.wire_diameter >= 2.0 * design.coil_radius:
        key = chs.design_key(spec, "wire_diameter")
        return (f"{spec.path}: {key}: expected a wire thinner than the coil diameter 2 r" if key
                else f"{spec.path}: design: impossible design: the wire "
                f"({design.wire_diameter:.4g} m) is not thinner than the coil diameter 2 r "
                f"({2.0 * design.coil_radius:.4g} m)")
    return None


def diagnose(spec: Spec, design: Design) -> str:
    """The one-line diagnosis of a design :func:`core` finds impossible: the parser's word on
    its numbers (:func:`invalid`), else the first of the statics' own (its spring, a free
    length <= 0, no equilibrium speed, a figure that is not finite), else an overflow."""
    bad = invalid(spec, design)
    if bad:
        return bad
    spec = spec.with_design(design)
    try:
        sd = statics.spring_design(spec, design)
        possible(spec, sd)
        char = chs.characteristic(spec, sd)
        k2 = statics.restoring_k2(spec, char.alpha, sd, char.omega**2)
        finite(spec, {"equilibrium speed": char.omega, "spring force (generalised)": char.M_f,
                      "centrifugal force (generalised)": char.M_z,
                      "spring force": char.spring_force, "k^2": k2,
                      **({"shear stress": char.stress} if spec.material is not None
                         and np.isfinite(sd.d) else {})})
    except DesignError as exc:
        return located(spec.path, str(exc))
    except OverflowError:
        pass
    return overflow_message(spec)


# ---------------------------------------------------------------------------------------------
# Small helpers on arrays of designs
# ---------------------------------------------------------------------------------------------

def overridden(gov: Governor, method: str) -> bool:
    """Whether the governor type supplies its own ``method`` (not the seam's default)."""
    own = getattr(type(gov), method, None)
    return own is not None and own is not getattr(Governor, method, None)


def design_of(cols: dict, i: int) -> Design:
    """Row ``i`` of a dict of design arrays as a :class:`Design`."""
    return Design(**{f: (None if np.isnan(cols[f][i]) else float(cols[f][i]))
                     for f in DESIGN_FIELDS})


def dashpot_column(gov: Governor) -> str:
    """The dash-pot's figure (SI, the type's damping unit: ``dashpot_N_m_s_per_rad`` ...)."""
    return f"dashpot_{gov.key_unit('damping')}"


def design_columns(designs) -> dict[str, np.ndarray]:
    """A sequence of :class:`Design` as one float array per field (SI, NaN for "not given")."""
    return {f: np.array([np.nan if getattr(d, f) is None else getattr(d, f) for d in designs],
                        dtype=float) for f in DESIGN_FIELDS}


def flat(v, n: int) -> np.ndarray:
    """A per-design quantity of shape ``(N, 1)`` (or broadcasting to it) as ``(N,)``."""
    return np.broadcast_to(np.asarray(v, dtype=float), (n, 1))[:, 0]


def friction_at(gov: Governor, cols: dict, x) -> np.ndarray:
    """The friction band :meth:`Governor.friction` of every design at configurations ``x``,
    shape ``(N, K)`` (evaluated once per distinct friction moment)."""
    fm = cols["friction_moment"]
    band = np.zeros((fm.size, np.size(x)))
    for value in np.unique(fm):
        rows = (fm == value) | (np.isnan(fm) & np.isnan(value))
        probe = Design(flying_mass=1.0, friction_moment=None if np.isnan(value) else value)
        band[rows] = gov.friction(x, probe)
    return band


def spring_design_of(sd: statics.SpringDesign, i: int, given: bool) -> statics.SpringDesign:
    """Design ``i`` of a vectorised :class:`SpringDesign` as scalars (``given``: the inertia is
    the design's own, as :func:`statics.spring_design` marks it)."""
    vals = {f.name: getattr(sd, f.name) for f in fields(sd)}
    for k, v in vals.items():
        if isinstance(v, np.ndarray):
            vals[k] = float(np.broadcast_to(v, (v.shape[0], 1))[i, 0]) if v.ndim else float(v)
    return statics.SpringDesign(**{**vals, "inertia_given": given})


def _pick(s: TransientSummary, j: int) -> TransientSummary:
    """Design ``j`` of a :class:`TransientSummary` of many."""
    return replace(s, **{f.name: np.asarray(getattr(s, f.name))[j] for f in fields(s)})


# ---------------------------------------------------------------------------------------------
# The core
# ---------------------------------------------------------------------------------------------

@dataclass
class Evaluation:
    """What :func:`core` gives for N designs (SI).

    ``spec``: the spec evaluated (with its use case's settings, :func:`govopt.fidelity.plan`);
    ``figures``: the per-design figures (name -> array of N; the columns of a bulk row before
    its checks); ``table``: every check; ``error``: the diagnosis of each impossible design,
    None for the others (an impossible design's figures and checks mean nothing). With
    ``report=True`` (one design, for :func:`govopt.evaluate`) also the report's content of
    design 0: ``spring`` (its :class:`SpringDesign`), ``char`` (its :class:`Characteristic`),
    ``k2`` over the configurations, ``vib`` (the forced vibration) and ``dynamics`` (the load
    changes', the forcing's and the friction runs' dicts)."""

    n: int
    spec: Spec
    figures: dict
    table: CheckTable
    error: np.ndarray
    spring: statics.SpringDesign | None = None
    char: chs.Characteristic | None = None
    k2: np.ndarray | None = None
    vib: object = None
    dynamics: dict = field(default_factory=dict)
    #: the spec's ``[analysis] use_case`` plan (:func:`govopt.fidelity.plan`), None without
    plan: object = None
    #: the classic measures' report of design 0 (:func:`govopt.analysis.classic.report`)
    classic: dict = field(default_factory=dict)

    @property
    def impossible(self) -> np.ndarray:
        return np.array([e is not None for e in self.error], dtype=bool)


def core(spec: Spec, cols: dict, *, dynamics: bool = True, vibration: bool = True,
         classic: bool = True, report: bool = False) -> Evaluation:
    """Evaluate the designs ``cols`` (one float array per :data:`DESIGN_FIELDS`, NaN for "not
    given") of ``spec``: see the module's text. ``dynamics``: the load-change transients and
    friction runs (Hamabe Part III); ``vibration``: the type's periodic forcing (Part II);
    ``classic``: range, sensitiveness, stability, effort and power (textbook ch. 3). A spec's
    ``[analysis] use_case`` is honoured (:func:`govopt.fidelity.plan`: its settings, only its
    analyses)."""
    from .fidelity import plan as use_case_plan

    plan = use_case_plan(spec)
    friction_on = dynamics
    if plan is not None:
        spec = plan.apply(spec)
        dynamics = dynamics and plan.runs("load_change")
        vibration = vibration and plan.runs("vibration")
        friction_on = friction_on and plan.runs("friction")
    s = _statics(spec, cols)
    out = _figures(spec, cols, s)
    per_design = _PerDesign(spec, s.impossible)
    own = _own_spring_checks(spec)
    vibs = _vibrations(spec, s, per_design, vibration or own)
    # the checks, in this order: the spring's, statics, load changes, vibration, friction, the
    # design requirements
    checks = CheckTable(s.n)
    _spring_checks(spec, cols, s, per_design, vibs, checks, own)
    _statics_checks(spec, cols, s, out["irregularity"], checks)
    dyn: dict = {}
    if dynamics and spec.engine is not None and spec.load_changes:
        reports = _load_changes(spec, s, out, checks, report)
        if reports:
            dyn["load_changes"] = reports
    if vibration:
        _vibration_checks(spec, s, vibs, out, checks)
    if friction_on and spec.engine is not None and spec.load_changes:
        runs_of = _friction(spec, cols, s, per_design, checks)
        if report and 0 in runs_of:
            dyn["friction"] = [run.to_dict() for run in runs_of[0]]
    _requirement_checks(spec, cols, s, out, checks)
    measures = None
    if classic:  # the textbook's measures (ch. 3) over the range, the friction band included
        measures = classic_measures(spec, s.sd, s.x, s.omega, s.t,
                                    friction_at(spec.governor, cols, s.x), ~s.impossible)
        out.update({k: measures[k] for k in CLASSIC_FIGURES})
    error = np.full(s.n, None, dtype=object)
    for i in np.nonzero(s.impossible)[0]:
        error[i] = per_design.said.get(int(i)) or diagnose(spec, design_of(cols, i))
    ev = Evaluation(s.n, spec, out, checks, error, plan=plan)
    if report and not s.impossible[0]:
        _report(ev, s, vibs[0], vibration, measures, dyn)
    return ev


@dataclass
class _Statics:
    """The statics of N designs (:func:`_statics`): arrays of shape ``(N, K)`` over the
    configurations ``x`` (``(N, 1)`` per design), SI, and ``impossible``, the designs found
    impossible so far (every later step that finds one marks it here)."""

    x: np.ndarray
    i_n: int  # the normal configuration's index in x
    t: Terms  # the statics' terms at x
    m: np.ndarray
    central: np.ndarray
    I_given: np.ndarray  # the designs' own inertia, NaN where the type's
    dashpot: np.ndarray  # (N,), NaN for none
    kappa: np.ndarray
    l0: np.ndarray
    w2: np.ndarray  # omega^2 of the characteristic
    omega: np.ndarray
    k2: np.ndarray
    F: np.ndarray  # spring force
    M_f: np.ndarray
    M_z: np.ndarray
    stress: np.ndarray
    rise: np.ndarray  # (N,): the least slope of the characteristic
    sd: statics.SpringDesign
    helical: np.ndarray  # (N,): a wire spring of a known material
    impossible: np.ndarray  # (N,)

    @property
    def n(self) -> int:
        return self.impossible.size

    def spring_of(self, i: int) -> statics.SpringDesign:
        """Design ``i``'s :class:`SpringDesign` (scalars; as :func:`statics.spring_design`)."""
        return spring_design_of(self.sd, i, bool(np.isfinite(self.I_given[i, 0])))

    def char_of(self, spec: Spec, i: int) -> chs.Characteristic:
        """Design ``i``'s characteristic
        (:func:`~govopt.analysis.characteristic.characteristic`, from the arrays)."""
        t, K = self.t, self.x.size
        return chs.Characteristic(
            alpha=self.x, omega=self.omega[i], M_z=self.M_z[i], M_f=self.M_f[i],
            M_r0=np.broadcast_to(t.cf + self.w2 * t.ci, (self.n, K))[i],
            spring_force=self.F[i], stress=self.stress[i], extra=spec.governor.columns(self.x),
            omega_mean=_omega_mean(spec))


def _omega_mean(spec: Spec) -> float:
    return spec.speed.omega_mean if spec.speed is not None else math.nan


def _statics(spec: Spec, cols: dict) -> _Statics:
    """The statics of every design over the configurations, vectorised: the spring (rate and
    free length), the characteristic (Hamabe eqs. 1, 2, 11, 12), ``k^2`` (eqs. 18-20), the
    spring's force and stress, the characteristic's least slope; and the designs they show
    impossible (no spring, a free length <= 0, no equilibrium speed, a figure not finite)."""
    gov = spec.governor
    n = len(cols["flying_mass"])
    col = {k: v[:, None] for k, v in cols.items()}  # (N, 1) against configurations (K,)
    m = col["flying_mass"]
    central = np.where(np.isnan(col["central_mass"]), 0.0, col["central_mass"])
    d, r, nt = col["wire_diameter"], col["coil_radius"], col["active_turns"]
    mat = spec.material
    impossible = ~np.isfinite(cols["flying_mass"])
    impossible |= np.isfinite(cols["wire_diameter"]) & (
        cols["wire_diameter"] >= 2.0 * cols["coil_radius"])
    with np.errstate(all="ignore"):
        kappa, l0 = _spring(spec, cols, col, central)
        if gov.spring is not None and gov.free_length_positive:
            impossible |= ~(l0[:, 0] > 0)
        I_given = col["flying_inertia"]
        I_n = np.where(np.isnan(I_given), gov.inertia(np.asarray(gov.x_normal), m, central),
                       I_given)
        impossible |= ~np.isfinite(kappa[:, 0]) | ~np.isfinite(l0[:, 0]) | ~np.isfinite(
            flat(I_n, n))
        x = statics.configurations(spec)
        K = x.size
        i_n = int(np.searchsorted(x, gov.x_normal))
        t = statics.terms(spec, x, m, central)
        w2 = np.broadcast_to(t.omega_squared(kappa, l0), (n, K))
        impossible |= ~(w2 > 0).all(axis=1)
        omega = np.sqrt(w2)
        w2c = omega**2  # as the characteristic: k^2 at its omega^2
        I_x = np.where(np.isnan(I_given), gov.inertia(x, m, central), I_given)
        stiff = t.stiffness(kappa, l0, w2c)
        k2 = np.broadcast_to(stiff / I_x, (n, K))
        A_F, B_F = gov.spring_force_coefficients(x)
        F = np.broadcast_to(kappa * (A_F - B_F * l0), (n, K))
        M_f = np.broadcast_to(kappa * (t.A - t.B * l0), (n, K))
        M_z = np.broadcast_to(w2 * t.jp, (n, K))
        helical = (mat is not None) & np.isfinite(cols["wire_diameter"])
        sd = statics.SpringDesign(m, I_n, kappa, l0, d, r, nt, central, False,
                                  col["leaf_width"], col["leaf_thickness"])
        stress = np.full((n, K), np.nan)
        if gov.spring is not None and mat is not None:
            stress = np.broadcast_to(gov.spring_stress(x, F, sd, mat), (n, K))
        finite_rows = [omega, M_f, M_z, F, k2]
        impossible |= ~np.all([np.isfinite(v).all(axis=1) for v in finite_rows], axis=0)
        impossible |= helical & ~np.isfinite(stress).all(axis=1)
        if spec.analysis.reaction_slope:  # chs.characteristic_slope on the terms in hand
            slope = stiff / (2.0 * omega * t.lever)
        else:
            slope = chs.characteristic_slope(spec, sd, x, omega)
        slope = np.broadcast_to(slope, (n, K))
        secant = np.diff(omega, axis=1) / np.diff(x)
        rise = np.minimum(slope.min(axis=1), secant.min(axis=1, initial=np.inf))
    return _Statics(x=x, i_n=i_n, t=t, m=m, central=central, I_given=I_given,
                    dashpot=cols["dashpot"], kappa=kappa, l0=l0, w2=w2, omega=omega, k2=k2,
                    F=F, M_f=M_f, M_z=M_z, stress=stress, rise=rise, sd=sd, helical=helical,
                    impossible=impossible)


def _figures(spec: Spec, cols: dict, s: _Statics) -> dict:
    """The per-design figures of the statics and the spring (name -> array of N, SI): the
    columns of a bulk row before its checks."""
    gov, mat, n = spec.governor, spec.material, s.n
    omega_mean = _omega_mean(spec)
    wi, wa, wn = s.omega[:, 0], s.omega[:, -1], s.omega[:, s.i_n]
    helical = s.helical
    out = {f"{gov.mass_key}_mass_kg": cols["flying_mass"], "central_mass_kg": s.central[:, 0]}
    if gov.spring is not None:
        out.update({"wire_diameter_m": cols["wire_diameter"],
                    "coil_radius_m": cols["coil_radius"], "active_turns": cols["active_turns"],
                    "stiffness_N_per_m": s.kappa[:, 0], f"{gov.free_length_key}_m": s.l0[:, 0]})
    out[dashpot_column(gov)] = cols["dashpot"]
    out.update({"irregularity": (wa - wi) / omega_mean, "omega_inner_rad_s": wi,
                "omega_outer_rad_s": wa, "omega_normal_rad_s": wn})
    if gov.spring is not None:
        out.update({"min_spring_force_N": s.F.min(axis=1), "max_spring_force_N": s.F.max(axis=1),
                    "max_stress_Pa": s.stress.max(axis=1)})
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
    out["moving_mass_kg"] = cols["flying_mass"] + s.central[:, 0] + np.where(helical, smass, 0.0)
    out.update({"k2_min_rad2_s2": s.k2.min(axis=1), "k2_max_rad2_s2": s.k2.max(axis=1),
                "k2_normal_rad2_s2": s.k2[:, s.i_n]})
    return out


class _PerDesign:
    """Runs a part that has no vectorised form for one design (``self(i, part)``): its
    DesignError (or an overflow) makes design ``i`` impossible with that diagnosis (``said``:
    what evaluate raises for it)."""

    def __init__(self, spec: Spec, impossible: np.ndarray):
        self.spec, self.impossible, self.said = spec, impossible, {}

    def __call__(self, i: int, part):
        try:
            return part()
        except DesignError as exc:
            self.said[i] = located(self.spec.path, str(exc))
        except OverflowError:
            self.said[i] = overflow_message(self.spec)
        self.impossible[i] = True
        return None


def _own_spring_checks(spec: Spec) -> bool:
    """Whether the spring brings checks of its own (:meth:`Governor.spring_checks`): the type's
    own spring (a leaf), or a wire of a grade."""
    gov, mat = spec.governor, spec.material
    return gov.spring is not None and (overridden(gov, "spring_checks") or (
        mat is not None and getattr(mat, "grade", None) is not None))


def _engine_or_dashpot(spec: Spec, s: _Statics) -> np.ndarray:
    """The designs that are possible so far and have a dash-pot, or an engine to drive them."""
    return ~s.impossible & (np.isfinite(s.dashpot) | (spec.engine is not None))


def _vibrations(spec: Spec, s: _Statics, per_design: _PerDesign, wanted: bool) -> list:
    """The type's forced vibration (Hamabe Part II) of each design with a dash-pot or an engine
    (also the spring's load cycle), all at once (:meth:`Governor.vibrations`; design by design
    only to name the design whose vibration raises a :class:`DesignError`); None where not
    ``wanted`` or the type has none."""
    gov = spec.governor
    vibs = _Vibrations(s.n)
    if wanted and overridden(gov, "vibration"):
        at = np.nonzero(_engine_or_dashpot(spec, s))[0]
        dashpot = np.where(np.isfinite(s.dashpot), s.dashpot, 0.0)
        try:  # every design at once (:meth:`Governor.vibrations`)
            with np.errstate(all="ignore"):
                vibs.put(at, gov.vibrations(spec, _spring_rows(s.sd, at, s.n),
                                            s.k2[at, s.i_n], dashpot[at]))
        except (DesignError, OverflowError):  # one design's: each alone, to say which
            for i in at:
                vibs.put([i], [per_design(i, lambda i=i: gov.vibration(
                    spec, s.spring_of(i), float(s.k2[i, s.i_n]), float(dashpot[i])))])
    return vibs


class _Vibrations:
    """Each design's forced vibration (None where there is none): ``vibs[i]``, made on demand
    from what :meth:`Governor.vibrations` computed for many; ``peak_to_peak()`` over all."""

    def __init__(self, n: int):
        self.n, self.parts = n, []

    def put(self, at, many) -> None:
        if many is not None:
            self.parts.append((np.asarray(at, dtype=np.int64), many))

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, i: int):
        for at, many in self.parts:
            j = np.searchsorted(at, i)
            if j < at.size and at[j] == i:
                return many[int(j)]
        return None

    def __iter__(self):
        return (self[i] for i in range(self.n))

    def peak_to_peak(self) -> np.ndarray:
        """Each design's peak-to-peak (NaN where it has no vibration)."""
        out = np.full(self.n, np.nan)
        for at, many in self.parts:
            p2p = getattr(many, "peak_to_peak_rad", None)
            out[at] = (np.asarray(p2p, dtype=float) if p2p is not None else
                       [np.nan if v is None else float(v.peak_to_peak_rad) for v in many])
        return out


def _spring_rows(sd: statics.SpringDesign, rows: np.ndarray, n: int) -> statics.SpringDesign:
    """The designs ``rows`` of a vectorised :class:`SpringDesign` of ``n`` (fields ``(rows,)``)."""
    return replace(sd, **{f.name: np.broadcast_to(np.asarray(v, dtype=float), (n, 1))[rows, 0]
                          for f in fields(sd) if isinstance(v := getattr(sd, f.name), np.ndarray)})


def _spread(n: int, at: list, by_design: dict, field: str) -> np.ndarray:
    """A check's ``field`` over ``n`` designs: its value at the designs ``at`` (NaN, or False
    for a verdict, elsewhere)."""
    out = np.zeros(n, bool) if field == "verdict" else np.full(n, np.nan)
    out[at] = [getattr(by_design[i], field) for i in at]
    return out


def _spring_checks(spec: Spec, cols: dict, s: _Statics, per_design: _PerDesign, vibs: list,
                   checks: CheckTable, own: bool) -> None:
    """The spring's checks: its own (``own``: a leaf's, a graded wire's), design by design, or
    a helical spring's stress and geometry (coil clash, buckling, pitch), which need no wire
    grade."""
    gov, mat, n = spec.governor, spec.material, s.n
    if own:  # each row added once over the designs that have it (the last of a name wins)
        rows: dict[str, dict] = {}
        todo = ~s.impossible
        unforced = todo & np.array([v is None for v in vibs], dtype=bool)
        table = gov.spring_checks_over(spec, s.sd, s.F, s.x) if unforced.any() else None
        if table is not None:  # the designs without a forcing at once, the rest one by one
            for c in table:
                checks.add(c.name, c.value, c.limit, c.sense, scale=c.scale, where=unforced,
                           unit=c.unit, source=c.source, group=c.group)
            todo = todo & ~unforced
        for i in np.nonzero(todo)[0]:
            found = per_design(i, lambda i=i: gov.spring_checks(spec, s.spring_of(i),
                                                                s.char_of(spec, i), vibs[i]))
            for c in found or []:
                rows.setdefault(c.name, {})[int(i)] = c
        for name, by_design in rows.items():
            kinds: dict[tuple, list] = {}  # designs with a scale, a verdict of their own or not
            for i, c in by_design.items():
                kinds.setdefault((c.scale is None, c.verdict is None), []).append(i)
            for (no_scale, no_verdict), at in kinds.items():
                on = np.zeros(n, bool)
                on[at] = True
                first = by_design[at[0]]
                checks.add(name, _spread(n, at, by_design, "value"),
                           _spread(n, at, by_design, "limit"), first.sense,
                           scale=None if no_scale else _spread(n, at, by_design, "scale"),
                           verdict=None if no_verdict else _spread(n, at, by_design, "verdict"),
                           where=on, unit=first.unit, source=first.source, group=first.group)
    elif gov.spring is not None and mat is not None and s.helical.any():
        from .analysis import spring_engineering

        checks.add_row(stress_row(mat, spec), {"stress": s.stress.max(axis=1)}, where=s.helical)
        for row, value, limit, source in spring_engineering.geometry_table(
                spec, cols["wire_diameter"], 2.0 * cols["coil_radius"],
                cols["active_turns"], s.kappa[:, 0], s.l0[:, 0], s.F.min(axis=1),
                s.F.max(axis=1)):
            checks.add(row.name, value, limit, row.sense, where=s.helical, unit=row.unit,
                       source=source, group="spring")


def _statics_checks(spec: Spec, cols: dict, s: _Statics, irregularity: np.ndarray,
                    checks: CheckTable) -> None:
    """The statics' rows (:func:`govopt.requirements.statics_rows`): the speed range over the
    whole operating band (with friction) where the spec asks for it, the characteristic's
    rise, the spring force and ``k^2``."""
    gov, n = spec.governor, s.n
    band = (None, None)
    if spec.speed is not None and spec.speed.band:  # the whole operating band, with friction,
        friction_x = friction_at(gov, cols, s.x)  # over the whole range
        with np.errstate(all="ignore"):
            band = statics.band_extremes(*(np.broadcast_to(b2, (n, s.x.size)) for b2 in
                                           statics.band_speeds_squared(s.t, s.kappa, s.l0,
                                                                       friction_x)))
    w0sq = (np.full(n, _omega_mean(spec)**2) if spec.speed is not None
            else s.omega[:, s.i_n]**2)
    checks.add_rows(statics_rows(spec), statics_figures(irregularity, *band, s.rise, w0sq,
                                                        s.F, s.k2))


def _load_changes(spec: Spec, s: _Statics, out: dict, checks: CheckTable,
                  report: bool) -> list:
    """Every load change of the designs with a dash-pot (Hamabe Part III): their figures into
    ``out``, their rows into ``checks``; design 0's summaries with ``report``."""
    n = s.n
    settle = np.full(n, -np.inf)
    run = ~s.impossible & np.isfinite(s.dashpot)
    reports = []
    for lc in spec.load_changes:
        hur, over, overs, st_time, xi0, good, detail = _load_change_many(
            spec, lc, s.m, s.kappa, s.l0, s.central, s.I_given, s.dashpot, run)
        s.impossible |= run & ~good
        on = run & good
        out[f"hurwitz_margin: {lc.name}"] = np.where(on, hur, np.nan)
        out[f"over_regulation: {lc.name}"] = np.where(on, over, np.nan)
        out[f"settling_time_s: {lc.name}"] = np.where(on, st_time, np.nan)
        settle = np.where(on, np.maximum(settle, st_time), settle)
        checks.add_rows(load_change_rows(spec, lc.name), {
            "hurwitz": hur, "over": over, "over_regulates": overs, "xi0": xi0,
            "settling": st_time}, where=on)
        if report and on[0]:
            a, xs, k2_0, summary = detail
            reports.append(loadchange.summary(spec, lc, tuple(float(v[0]) for v in a),
                                              tuple(float(v[0]) for v in xs),
                                              float(k2_0[0]), _pick(summary, 0)))
    out["settling_time_s"] = np.where(settle > -np.inf, settle, np.nan)
    return reports


def _vibration_checks(spec: Spec, s: _Statics, vibs: list, out: dict,
                      checks: CheckTable) -> None:
    """The forced vibration's figure and rows (:func:`govopt.requirements.vibration_rows`),
    where the type has a forcing and some design is driven."""
    p2p = vibs.peak_to_peak()
    if overridden(spec.governor, "vibration") and _engine_or_dashpot(spec, s).any():
        out["vibration_p2p_rad"] = p2p
        checks.add_rows(vibration_rows(spec), {"p2p": p2p}, where=~np.isnan(p2p))


def _friction(spec: Spec, cols: dict, s: _Statics, per_design: _PerDesign,
              checks: CheckTable) -> dict:
    """Hamabe's friction strokes (eqs. 42-46) of the designs whose friction band moves at a
    load change's end, design by design, and their rows; returns each design's runs."""
    gov, n = spec.governor, s.n
    moves = np.zeros(n, bool)
    for lc in spec.load_changes:
        moves |= friction_at(gov, cols, np.array([lc.alpha_to]))[:, 0] > 0
    runs_of = {}
    for i in np.nonzero(moves & ~s.impossible)[0]:
        runs = per_design(i, lambda i=i: _friction_runs(spec, design_of(cols, i),
                                                        s.spring_of(i)))
        if runs is not None:
            runs_of[i] = runs
    for j, lc in enumerate(spec.load_changes):
        rows = friction_rows(spec, lc.name)
        for i, runs in runs_of.items():
            row, figures = _friction_figures(lc, runs[j])
            on = np.zeros(n, bool)
            on[i] = True
            checks.add_row(rows[row], figures, where=on)
    return runs_of


def _requirement_checks(spec: Spec, cols: dict, s: _Statics, out: dict,
                        checks: CheckTable) -> None:
    """The design requirements' rows (:func:`govopt.requirements.requirement_rows`) of the
    wire springs."""
    req = spec.requirements
    if req is not None and s.helical.any():
        checks.add_rows(requirement_rows(spec, req), {
            "d": cols["wire_diameter"], "r": cols["coil_radius"], "n": cols["active_turns"],
            "m": cols["flying_mass"], "l0": s.l0[:, 0], "C": out["spring_index"],
            "body": out["body_length_m"], "surge": out["surge_frequency_Hz"]}, where=s.helical)


def _report(ev: Evaluation, s: _Statics, vib, vibration: bool, measures, dyn: dict) -> None:
    """What only a report of design 0 needs (:func:`evaluate`): its spring, characteristic,
    ``k^2``, forced vibration (``vib``; its dict where ``vibration`` was asked for), classic
    measures and the dynamics' dicts."""
    spec = ev.spec
    ev.spring = s.spring_of(0)
    ev.char = s.char_of(spec, 0)
    ev.k2 = np.array(s.k2[0])
    ev.vib = vib
    if measures is not None:
        ev.classic = classic_report(spec, measures, 0)
    if vibration and vib is not None:
        dyn["vibration"] = vib.to_dict()
    ev.dynamics = dyn


def statics_of(spec: Spec, cols: dict):
    """The statics of the designs ``cols`` as :func:`core` evaluates them (arrays over the
    designs and configurations: ``x``, ``F``, ``sd``, ``impossible`` ...)."""
    return _statics(spec, cols)


def springs_of(spec: Spec, cols: dict) -> tuple[np.ndarray, np.ndarray]:
    """The springs' rate ``kappa`` (N/m) and free length ``l0`` (the type's form, m) of the
    designs ``cols`` (one float array per :data:`DESIGN_FIELDS`), shape ``(N,)``: as
    :func:`core` evaluates them."""
    n = len(cols["flying_mass"])
    cols = {f: np.asarray(cols[f], dtype=float) if f in cols else np.full(n, np.nan)
            for f in DESIGN_FIELDS}
    col = {k: v[:, None] for k, v in cols.items()}
    central = np.where(np.isnan(col["central_mass"]), 0.0, col["central_mass"])
    with np.errstate(all="ignore"):
        kappa, l0 = _spring(spec, cols, col, central)
    return kappa[:, 0], l0[:, 0]


def _spring(spec: Spec, cols: dict, col: dict, central) -> tuple[np.ndarray, np.ndarray]:
    """The springs' rate ``kappa`` (N/m) and free length ``l0`` (the type's form, m), shape
    ``(N, 1)``: a given stiffness, else the type's rate of the section (a helical spring's
    ``G d^4 / (64 r^3 n)``, Wahl 1944, Hamabe Ex. 1, vectorised; a type's own spring, a leaf,
    design by design); a given free length, else the one that holds the normal configuration at
    the mean speed (:func:`statics.free_half_length`, Hamabe Ex. 1). Zeros without a spring."""
    gov, mat, n = spec.governor, spec.material, len(cols["flying_mass"])
    m = col["flying_mass"]
    if gov.spring is None:
        return np.zeros_like(m), np.zeros_like(m)
    if overridden(gov, "spring_rate"):  # the type's own spring (a leaf): design by design
        rate = np.array([gov.spring_rate(design_of(cols, i), mat)
                         if np.isnan(cols["spring_stiffness"][i]) else np.nan
                         for i in range(n)], dtype=float).reshape(n, 1)
    elif mat is not None and mat.shear_modulus is not None:
        rate = hx.stiffness_r(col["wire_diameter"], col["coil_radius"], col["active_turns"],
                              mat.shear_modulus)
    else:
        rate = np.full_like(m, np.nan)
    kappa = np.where(np.isfinite(col["spring_stiffness"]), col["spring_stiffness"], rate)
    l0 = col["free_half_length"]
    if np.isnan(l0).any():
        try:
            l0 = np.where(np.isnan(l0), statics.free_half_length(spec, m, kappa, central), l0)
        except DesignError as exc:  # the spec has no speed to set it from
            raise DesignError(located(spec.path, str(exc))) from None
    return kappa, l0


def _friction_runs(spec: Spec, design: Design, sd: statics.SpringDesign) -> list:
    """Hamabe's friction transient (eqs. 42-46) of every load change of one design."""
    from .analysis import friction  # only where a design has friction (model what is asked)

    spec = spec.with_design(design)  # its dash-pot and friction moment
    return [friction.friction_load_change(spec, sd, lc) for lc in spec.load_changes]


def _friction_figures(lc, run) -> tuple[str, dict]:
    """Which friction row of :func:`govopt.requirements.friction_rows` a run of load change
    ``lc`` is judged by, and its figures: "stuck" (the governor does not follow the load
    change: the offset it rests at) or "moves" (how far its first stroke ends past the new
    equilibrium)."""
    xi0 = lc.alpha_from - lc.alpha_to
    first = run.first_stroke_end
    stuck = run.outcome == "stuck"
    return ("stuck" if stuck else "moves"), {
        "xi0": xi0, "rest": abs(run.final_state[0]),
        "past": 0.0 if stuck or first is None else max(0.0, -float(np.sign(xi0)) * first)}


def _load_change_many(spec, lc, m, kappa, l0, central, I_given, dashpot, run):
    """:func:`govopt.analysis.loadchange.analyse` for many designs: Hamabe eqs. (24)-(32) with
    the coefficients of :func:`loadchange.load_change_model`, events by
    :func:`~govopt.analysis.transient_events.analyse_many`. Returns (Hurwitz margin,
    over-regulation, over-regulates, settling time, xi0, finite, (coefficients, initial state, k^2,
    summary of the designs run))."""
    gov = spec.governor
    n = m.shape[0]
    a0x, a1x = lc.alpha_to, lc.alpha_from
    with np.errstate(all="ignore"):
        t0 = statics.terms(spec, a0x, m, central)
        t1 = statics.terms(spec, a1x, m, central)
        w0 = np.sqrt(flat(t0.omega_squared(kappa, l0), n))
        w1 = np.sqrt(flat(t1.omega_squared(kappa, l0), n))
        own = flat(gov.inertia(np.asarray(a0x, dtype=float), m, central), n)
        I = np.where(np.isnan(I_given[:, 0]), own, I_given[:, 0])
        k2 = flat(t0.stiffness(kappa, l0, (w0**2)[:, None]), n) / I
        C = 2.0 * w0 * flat(t0.lever, n)
        R = loadchange.torque_ratio(spec, a0x)
        xi0 = np.full(n, a1x - a0x)
        eta0 = w1 * (1.0 + spec.engine.insensibility) - w0
        a = (I, np.where(np.isfinite(dashpot), dashpot, 0.0) / 3.0, I * k2 / 3.0, C * R)
        x = hamabe_initial_conditions(a[0], a[2], a[3], R, xi0, eta0)
    good = np.all([np.isfinite(v) for v in (*a, *x)], axis=0) & (a[0] != 0)
    hur, over, overs, st = (np.full(n, np.nan) for _ in range(4))
    overs = np.zeros(n, bool)
    sel = np.nonzero(run & good)[0]
    s = None
    if sel.size:
        s = analyse_many(*(v[sel] for v in a), *(v[sel] for v in x),
                         band=spec.analysis.settling_band)
        hur[sel] = s.hurwitz_margin
        over[sel] = np.where(s.stable, s.over_regulation, np.inf)
        overs[sel] = ~s.stable | over_regulates(s.over_regulation_scaled, x[0][sel])
        st[sel] = s.settling_time
    return hur, over, overs, st, x[0], good, (a, x, k2, s)


# ---------------------------------------------------------------------------------------------
# One design, as a Result
# ---------------------------------------------------------------------------------------------

#: the spring's report figures (:attr:`Result.spring_properties`, SI) and the evaluator's names
SPRING_PROPERTIES = (("spring_index", "spring_index"), ("wahl_factor", "wahl_factor"),
                     ("mass_kg", "spring_mass_kg"), ("surge_frequency_Hz", "surge_frequency_Hz"),
                     ("body_length_m", "body_length_m"))


def evaluate(spec: Spec, design: Design | None = None) -> Result:
    """Evaluate ``design`` (default: the spec's own ``[design]``) against the spec: :func:`core`
    with one design, and what a :class:`~govopt.result.Result` reports beside its checks and
    figures (the characteristic table, ``k^2`` over the range, the load changes' responses, the
    spring maker's sheet, the classic measures).

    Statics always; the load-change transient (Hamabe Part III) when the spec has engine data,
    load changes and the design a dash-pot; friction only when the design has a friction moment;
    design-requirement checks (margins, spring index, envelope, surge, bounds) when the spec has
    ``[requirements]`` or ``[bounds]``.
    """
    design = design or spec.design
    if design is not spec.design:  # every analysis reads the design evaluated, never the spec's
        spec = spec.with_design(design)
    try:
        return _evaluate(spec, design)
    except OverflowError:  # Python floats raise where numpy gives inf
        raise DesignError(overflow_message(spec)) from None


def _evaluate(spec: Spec, design: Design) -> Result:
    if design is None:  # the parser's diagnosis: no design to evaluate
        try:
            statics.spring_design(spec, design)
        except DesignError as exc:
            raise DesignError(located(spec.path, str(exc))) from None
    ev = core(spec, design_columns([design]), report=True)
    if ev.error[0] is not None:
        raise DesignError(ev.error[0])
    spec, sd, char, k2 = ev.spec, ev.spring, ev.char, ev.k2  # spec: with the use case's plan
    gov = spec.governor
    helical = spec.material is not None and np.isfinite(sd.d)  # a wire spring
    i_n = int(np.searchsorted(char.alpha, gov.x_normal))  # the normal configuration is on the grid
    dynamics = dict(ev.dynamics)
    if design.dashpot is not None or spec.engine is not None:
        dynamics["k2_normal_rad2_s2"] = float(k2[i_n])
    for key in ("vibration", "friction"):  # the report's order: the forcing, then friction
        if key in dynamics:
            dynamics[key] = dynamics.pop(key)
    if ev.plan is not None:
        dynamics["use_case"] = ev.plan.to_dict()
    return Result(spec=spec, design=design, spring=sd, statics=char,
                  spring_properties={k: float(ev.figures[f][0]) for k, f in SPRING_PROPERTIES}
                  if helical else {},
                  checks=ev.table.checks(), k2=k2, dynamics=dynamics,
                  classic=ev.classic,
                  spring_report=gov.spring_report(spec, sd, char, ev.vib)
                  if gov.spring is not None else None, evaluation=ev)


__all__ = ["DESIGN_FIELDS", "Evaluation", "core", "dashpot_column", "design_columns", "diagnose",
           "evaluate", "finite", "invalid", "possible"]
