"""Load change with Coulomb friction at the fulcrum: an exact hybrid (stick-slip) model.

Hamabe, *Disturbing Actions of a Shaft Governor*, Part III, eqs. (42)-(46). With a constant
friction moment ``M0`` about the fulcrum, eq. (24) becomes eq. (42)::

    I xi'' + f xi' + I k^2 xi + M0 sign(xi') = C eta,      C = dM/domega at (alpha0, omega0),
    I_fw eta' = (dT/dalpha) xi = -I_fw R xi,                R = -(dT/dalpha) / I_fw > 0 (27),

on the state ``(xi, xi', eta)``: ``xi = alpha - alpha0`` the pendulum's deviation from its new
equilibrium, ``eta = omega - omega0`` the engine's speed error. Hamabe has no dash-pot here
(``f = 0``); eliminating ``eta`` gives his eq. (43) ``a0 xi''' + 3 a2 xi' + a3 xi = 0`` for each
stroke, solved as eq. (44), with the constants of each stroke from its initial point (45) and the
end of the stroke where ``xi' = 0`` (46). A dash-pot is allowed as well (``f > 0``).

The hybrid model, phase by phase:

* **Slide** (a stroke) in direction ``s = sign(xi')``: the linear ODE with the constant input
  ``-s M0``. It is solved exactly as ``z(t) = expm(M t) z0`` (:func:`expm`: scaling and
  squaring, as :func:`scipy.linalg.expm` but in numpy only) with the augmented state
  ``z = (xi, xi', eta, 1)``, so the constant input needs no particular solution and repeated or
  nearly repeated roots of the cubic are no trouble. The stroke ends at the first ``t > 0`` where
  ``xi' = 0`` (eq. 46): bracketed on a grid of step ``0.1 / max|lambda|`` (the fastest
  eigenvalue's time scale), including local minima of ``s xi'`` (zeros of ``xi''``) so a dip of
  ``xi'`` through zero between grid points is not missed, and refined with ``brentq`` on the
  analytic solution.
* **Stick**: at rest, the pendulum stays put while the net moment of the other forces,
  ``N = C eta - I k^2 xi``, is within the friction band ``|N| <= M0`` (static friction taken
  equal to kinetic friction). The engine does not stop meanwhile: ``eta' = -R xi`` is constant,
  so ``N`` is linear in time and the break-away time is closed form,
  ``t_b = t_s + (N_s - N_b) / (C R xi_s)`` with ``N_b = -sign(xi_s) M0``; the next stroke starts
  in the direction of ``N_b``, i.e. always towards ``xi = 0``.
* At the end of a stroke, if ``|N| > M0`` the pendulum reverses at once (direction
  ``sign(N)``), otherwise it sticks.

Consequences, which the model reports rather than hides:

* The pendulum can only stay at rest for good at ``xi = 0`` exactly: stuck anywhere else, the
  speed keeps drifting (``eta' = -R xi != 0``) until the friction breaks. So it never truly
  "rests at an offset".
* Every phase is linear and homogeneous about the friction-shifted equilibrium
  ``(xi, xi', eta) = (0, 0, s M0 / C)``, and the break-away condition is linear too, so once the
  pendulum creeps towards ``xi = 0`` from one side (stick, slide, stick, ... all in one
  direction) the cycle is self-similar: each stick-slip cycle takes the same time and shrinks
  the offset by the same ratio (:attr:`FrictionResult.creep_ratio`). The pendulum reaches
  ``xi = 0`` only as ``t -> oo``, and the speed settles at ``omega0 +- M0 / C``: the dead band
  (insensibility) that the friction causes. The run stops when the offset has shrunk below
  ``settle_tol * |xi0|`` ("settled"), or at the time horizon or the stroke budget.
* A stroke that starts from rest at a break-away is the frictionless response (eq. 28) from a
  balanced rest, scaled by the offset: its ``xi_end / xi_start`` is :func:`stroke_ratio`,
  independent of ``M0``. If the pendulum was in equilibrium before the load change (consistent
  statics: ``C eta0 - I k^2 xi0`` is only second order), friction holds it until the speed error
  reaches ``M0 / C`` and then the first stroke is the same whatever ``M0`` (above that small
  imbalance): friction delays the first stroke but does not shape it, nor decide
  over-regulation.
* Hamabe's criteria (Part III): **over-regulation** when ``xi`` at the end of the first stroke
  has the opposite sign to ``xi0`` (the pendulum passed its new equilibrium; "xi > 0 at the end
  of the first stroke" for unloading); **hunting** when a stroke ends farther from the new
  equilibrium than the pendulum started (``|xi_end| >= |xi0|``: "the pendulum never comes to
  rest") or the stroke amplitudes keep growing.

Hamabe's own treatment starts the first stroke at ``t = 0`` with the upper sign of ``M0``
whatever the net moment (his eq. 45). If the initial net moment is inside the friction band the
pendulum cannot move yet; here it first sticks until the speed has changed enough. SI units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from ..governors.base import KEY_UNITS
from ..inputs import LoadChange, Spec
from . import statics
from .loadchange import LoadChangeModel, load_change_model  # noqa: F401 (re-exported)

__all__ = [
    "FrictionResult",
    "LoadChangeModel",
    "Phase",
    "friction_load_change",
    "friction_transient",
    "linear_response",
    "load_change_model",
    "slide_matrix",
    "stroke_ratio",
]

_XTOL = 1e-15
_RTOL = 1e-15
_RESYNC = 32  # grid steps between exact re-evaluations of expm(M t) z0


# --------------------------------------------------------------------------------------------
# exact linear pieces


def expm(A) -> np.ndarray:
    """Matrix exponential of small matrices (any leading batch shape), in numpy only.

    Scaling and squaring with a degree-18 Taylor polynomial: ``A / 2^s`` has 1-norm at most 1,
    where the truncation error is below ``1 / 19! < 1e-17``; agrees with
    :func:`scipy.linalg.expm` to about 1e-14 relative (checked in the tests). Written out
    because scipy's ``expm`` calls its own LAPACK, whose threading costs milliseconds per 4x4
    matrix on a busy machine, and the stroke search evaluates thousands of them.

    Parameters
    ----------
    A : array [-]
        Square matrix or stack of them, shape (..., n, n), in the reciprocal unit of the time
        it is scaled by (``M t`` is dimensionless).

    Returns
    -------
    ndarray [-]
        ``exp(A)``, the same shape.

    References
    ----------
    Scaling and squaring (as :func:`scipy.linalg.expm`), the solution of the strokes of
    [hamabe] eqs. (42)-(44); govopt's own code.

    Examples
    --------
    A quarter turn: ``exp([[0, -pi/2], [pi/2, 0]])`` is the rotation by 90 degrees, by hand.

    >>> E = expm(np.array([[0.0, -math.pi / 2], [math.pi / 2, 0.0]]))
    >>> [[round(float(v), 12) + 0.0 for v in row] for row in E]
    [[0.0, -1.0], [1.0, 0.0]]
    """
    A = np.asarray(A, dtype=float)
    eye = np.eye(A.shape[-1])
    if A.ndim == 2:  # the common case, without the batch bookkeeping
        norm = float(np.max(np.sum(np.abs(A), axis=0)))
        s = max(0, math.ceil(math.log2(norm))) if norm > 1.0 else 0
        B = A * (0.5**s)
        E = eye + B / 18.0
        for k in range(17, 0, -1):
            E = eye + (B @ E) * (1.0 / k)
        for _ in range(s):
            E = E @ E
        return E
    norm = np.max(np.sum(np.abs(A), axis=-2), axis=-1)
    with np.errstate(divide="ignore"):
        s = np.where(norm > 1.0, np.ceil(np.log2(norm)), 0.0).astype(int)
    B = A / np.ldexp(1.0, s)[..., None, None]
    E = eye + B / 18.0
    for k in range(17, 0, -1):
        E = eye + (B @ E) / k
    for j in range(1, int(np.max(s, initial=0)) + 1):
        E = np.where((j <= s)[..., None, None], E @ E, E)
    return E


def slide_matrix(I, f, k2, C, R, M0=0.0, direction=0) -> np.ndarray:
    """4x4 matrix ``M`` of one stroke on the augmented state ``z = (xi, xi', eta, 1)``.

    ``xi'' = (C eta - I k^2 xi - f xi' - direction M0) / I``, ``eta' = -R xi`` (eqs. 26, 42),
    so that ``z(t) = expm(M t) z(0)`` exactly.

    Parameters
    ----------
    I : float [kg m^2]
        Moment of inertia of the pendulum about its fulcrum (kg for a length coordinate).
    f : float [N m s/rad]
        Dash-pot coefficient (N s/m for a length coordinate); 0 is Hamabe's friction case.
    k2 : float [1/s^2]
        ``k^2`` at the new equilibrium.
    C : float [N m s]
        ``dM/domega`` at ``(alpha0, omega0)`` (N s for a length coordinate).
    R : float [1/s^2]
        ``-(dT/dalpha) / I_fw`` (eq. 27; 1/(m s^2) for a length coordinate).
    M0 : float [N m]
        Friction moment at the fulcrum (N for a length coordinate).
    direction : int [-]
        ``sign(xi')`` of the stroke: +1, -1 (0: no friction term).

    Returns
    -------
    ndarray [1/s]
        The 4x4 matrix.

    References
    ----------
    [hamabe] eqs. (26), (42).

    Examples
    --------
    By hand, ``I = 2, f = 4, k^2 = 9, C = 6, R = 0.5, M0 = 1`` on a rising stroke: the second
    row is ``(-k^2, -f/I, C/I, -M0/I)``, the third ``(-R, 0, 0, 0)``.

    >>> slide_matrix(2.0, 4.0, 9.0, 6.0, 0.5, 1.0, 1)[1:3].tolist()
    [[-9.0, -2.0, 3.0, -0.5], [-0.5, 0.0, 0.0, 0.0]]
    """
    M = np.zeros((4, 4))
    M[0, 1] = 1.0
    M[1, 0] = -k2
    M[1, 1] = -f / I
    M[1, 2] = C / I
    M[1, 3] = -direction * M0 / I
    M[2, 0] = -R
    return M


def linear_response(I, f, k2, C, R, xi0, eta0, t, xi_dot0=0.0) -> np.ndarray:
    """Frictionless response (eq. 28) on the state: array ``(len(t), 3)`` of ``(xi, xi', eta)``.

    Exact: ``expm(A t) x0`` for every ``t`` (no closed forms dividing by root differences).

    Parameters
    ----------
    I : float [kg m^2]
        Moment of inertia of the pendulum about its fulcrum (kg for a length coordinate).
    f : float [N m s/rad]
        Dash-pot coefficient (N s/m for a length coordinate); 0 is Hamabe's friction case.
    k2 : float [1/s^2]
        ``k^2`` at the new equilibrium.
    C : float [N m s]
        ``dM/domega`` at ``(alpha0, omega0)`` (N s for a length coordinate).
    R : float [1/s^2]
        ``-(dT/dalpha) / I_fw`` (eq. 27; 1/(m s^2) for a length coordinate).
    xi0 : float [rad]
        Initial deviation (m for a length coordinate).
    eta0 : float [rad/s]
        Initial speed error.
    t : array [s]
        Times.
    xi_dot0 : float [rad/s]
        Initial velocity of the pendulum.

    Returns
    -------
    ndarray [rad, rad/s, rad/s]
        Shape ``(len(t), 3)``: ``(xi, xi', eta)``.

    References
    ----------
    [hamabe] Part III, eqs. (24), (26)-(28).

    Examples
    --------
    Example 3, case a, with the paper's model and dash-pot (``f = 72 kgf cm s``): the same
    ``xi`` as the cubic's response
    (:func:`govopt.analysis.transient.transient`), the two methods agreeing to rounding.

    >>> from govopt.analysis.transient import transient
    >>> from govopt.analysis.transient_cubic import hamabe_initial_conditions
    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> m = load_change_model(spec, dashpot=72 * 0.0980665)
    >>> y = linear_response(m.I, m.f, m.k2, m.C, m.R, m.xi0, m.eta0, [0.5, 1.0])
    >>> a0, a1, a2, a3 = m.cubic
    >>> x = hamabe_initial_conditions(a0, a2, a3, m.R, m.xi0, m.eta0)
    >>> bool(np.allclose(y[:, 0], transient(a0, a1, a2, a3, *x, [0.5, 1.0]), rtol=1e-12))
    True
    >>> [round(float(v), 4) for v in y[:, 0]]
    [-0.0594, -0.0269]
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    A = slide_matrix(I, f, k2, C, R)[:3, :3]
    x0 = np.array([xi0, xi_dot0, eta0], dtype=float)
    return expm(t[:, None, None] * A) @ x0


# --------------------------------------------------------------------------------------------
# hybrid solution


@dataclass(frozen=True)
class Phase:
    """One phase of the motion: a stroke (``"slide"``) or a rest in the friction band
    (``"stick"``). ``net`` is ``C eta - I k^2 xi`` (N m), the moment friction has to hold."""

    kind: str
    t_start: float
    t_end: float  # math.inf: stuck for good
    xi_start: float
    xi_end: float
    eta_start: float
    eta_end: float
    direction: int  # +1 outward (xi increasing), -1 inward, 0 stuck
    net_start: float
    net_end: float
    xi_dot_end: float = 0.0  # residual xi' at the computed end of a stroke (about 1e-16)
    complete: bool = True  # False: cut by the time horizon

    @property
    def duration(self) -> float:
        return self.t_end - self.t_start

    @property
    def amplitude(self) -> float:
        """Hamabe's amplitude of a stroke: the distance from the new equilibrium at its end."""
        return abs(self.xi_end)

    @property
    def travel(self) -> float:
        return abs(self.xi_end - self.xi_start)

    @property
    def crosses_equilibrium(self) -> bool:
        """The stroke passes ``xi = 0`` (xi is monotonic within a stroke)."""
        return self.xi_start * self.xi_end < 0.0 or (self.xi_start != 0 and self.xi_end == 0)

    def to_dict(self, units: dict | None = None) -> dict:
        """JSON-ready; ``units``: the keys' units at the coordinate
        (:meth:`govopt.governors.base.Governor.key_units`; default the shaft's angle)."""
        units = units or KEY_UNITS["angle"]
        x, q = units["x"], units["force"]
        return {"kind": self.kind, "t_start_s": self.t_start, "t_end_s": _num(self.t_end),
                "duration_s": _num(self.duration), f"xi_start_{x}": self.xi_start,
                f"xi_end_{x}": self.xi_end, "eta_start_rad_per_s": self.eta_start,
                "eta_end_rad_per_s": self.eta_end, "direction": self.direction,
                f"net_start_{q}": self.net_start, f"net_end_{q}": self.net_end,
                f"amplitude_{x}": self.amplitude, f"travel_{x}": self.travel,
                f"xi_dot_end_{units['rate']}": self.xi_dot_end, "complete": self.complete}


@dataclass(frozen=True)
class FrictionResult:
    """Hybrid stick-slip solution of a load change with fulcrum friction (Hamabe, eqs. 42-46).

    ``outcome``: ``"settled"`` (the offset from the new equilibrium shrank below
    ``settle_tol |xi0|``; the model would go on creeping with ever smaller stick-slip cycles),
    ``"at rest"`` (stuck exactly at ``xi = 0`` with the speed error inside the friction band),
    ``"horizon"`` (time ``t_end`` reached), ``"max_strokes"`` (stroke budget used up) or
    ``"stuck"``: the governor does not move at all before the horizon (the friction moment holds
    it while the speed error grows; the governor does not follow the load change, and the
    residual offset is the whole ``xi0``).
    """

    I: float
    f: float
    k2: float
    C: float
    R: float
    M0: float
    xi0: float
    eta0: float
    xi_dot0: float
    phases: tuple[Phase, ...]
    outcome: str
    t_simulated: float
    t_horizon: float
    settle_tol: float
    grid_step: float = field(repr=False, default=math.nan)
    #: the JSON keys' units at the governor's coordinate (:meth:`Governor.key_units`): the
    #: shaft's (kg m^2, N m s/rad, N m s, 1/s^2, N m, rad) unless a spec's governor says
    units: dict = field(default_factory=lambda: dict(KEY_UNITS["angle"]), repr=False,
                        compare=False)

    # ---- derived quantities ------------------------------------------------------------------
    @property
    def strokes(self) -> tuple[Phase, ...]:
        return tuple(p for p in self.phases if p.kind == "slide")

    @property
    def sticks(self) -> tuple[Phase, ...]:
        return tuple(p for p in self.phases if p.kind == "stick")

    @property
    def amplitudes(self) -> tuple[float, ...]:
        return tuple(p.amplitude for p in self.strokes)

    @property
    def moved(self) -> bool:
        """The pendulum made at least one stroke."""
        return bool(self.strokes)

    @property
    def first_stroke_end(self) -> float | None:
        """``xi`` at the end of the first stroke (at the horizon if it has not ended)."""
        s = self.strokes
        return s[0].xi_end if s else None

    @property
    def over_regulation(self) -> bool:
        """Hamabe's criterion: ``xi`` at the end of the first stroke on the other side of the new
        equilibrium from ``xi0`` (positive after unloading)."""
        x = self.first_stroke_end
        return x is not None and x * self.xi0 < 0.0

    @property
    def equilibrium_crossings(self) -> int:
        """How many times the pendulum passes its new equilibrium."""
        return sum(p.crosses_equilibrium for p in self.strokes)

    @property
    def amplitude_growing(self) -> bool:
        """The last three stroke amplitudes strictly increase."""
        a = self.amplitudes
        return len(a) >= 3 and a[-3] < a[-2] < a[-1]

    @property
    def hunting(self) -> bool:
        """A stroke ends at least as far from the new equilibrium as the pendulum started
        (Hamabe: "the pendulum never comes to rest"), or the amplitudes keep growing."""
        x0 = abs(self.xi0)
        return any(a >= x0 for a in self.amplitudes if x0 > 0) or self.amplitude_growing

    @property
    def final_state(self) -> tuple[float, float, float]:
        """``(xi, xi', eta)`` at the end of the simulated time."""
        if not self.phases:
            return self.xi0, self.xi_dot0, self.eta0
        p = self.phases[-1]
        if p.kind == "slide" and not p.complete:
            return tuple(float(x) for x in self.state_at(self.t_simulated)[0])
        return float(p.xi_end), 0.0, float(p.eta_end)

    @property
    def resting_offset(self) -> float | None:
        """``xi`` where the pendulum is at rest at the end of the run (None if it is moving).
        Not a permanent rest unless it is 0: stuck at ``xi != 0`` the speed drifts on and the
        friction breaks again ("settled" means it is within ``settle_tol |xi0|`` of 0)."""
        p = self.phases[-1] if self.phases else None
        if p is None or (p.kind == "slide" and not p.complete):
            return None
        return p.xi_end

    @property
    def speed_offset(self) -> float:
        """Speed error ``eta`` at the end of the run; tends to ``+-M0/C`` when the pendulum creeps
        in (the friction's dead band)."""
        return self.final_state[2]

    @property
    def creep_ratio(self) -> float | None:
        """Ratio of successive stuck offsets ``xi_(n+1) / xi_n`` over the last two sticks, when
        they are on the same side (the self-similar creep's contraction per cycle)."""
        st = [p.xi_start for p in self.sticks if p.xi_start != 0.0 and p.t_start > 0.0]
        if len(st) < 2 or st[-1] * st[-2] <= 0:
            return None
        return st[-1] / st[-2]

    @property
    def note(self) -> str:
        """One sentence on what the run shows, for reports."""
        if self.outcome == "stuck":
            return (f"the governor does not move: the friction (M0 = {self.M0:.4g}, SI) holds "
                    f"it for the whole {self.t_simulated:.4g} s simulated, so it does "
                    f"not follow the load change (residual offset {self.final_state[0]:.4g}, SI, "
                    f"from the new equilibrium: all of xi0; the speed error drifts to "
                    f"{self.final_state[2]:.4g} rad/s)")
        return {"settled": "the offset from the new equilibrium shrank below the tolerance",
                "at rest": "at rest at the new equilibrium, inside the friction band",
                "horizon": "still moving (or creeping) at the time horizon",
                "max_strokes": "stroke budget used up"}[self.outcome]

    def state_at(self, t) -> np.ndarray:
        """``(xi, xi', eta)`` at times ``t`` (array ``(len(t), 3)``), exactly, from the phases."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        out = np.full((t.size, 3), np.nan)
        if not self.phases:
            return out
        starts = np.array([p.t_start for p in self.phases])
        idx = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, len(self.phases) - 1)
        first = t < self.phases[0].t_start
        for k in np.unique(idx):
            sel = (idx == k) & ~first & (t <= self.t_simulated)
            if not sel.any():
                continue
            p = self.phases[k]
            tau = t[sel] - p.t_start
            if p.kind == "stick":
                out[sel, 0] = p.xi_start
                out[sel, 1] = 0.0
                out[sel, 2] = p.eta_start - self.R * p.xi_start * tau
            else:
                M = slide_matrix(self.I, self.f, self.k2, self.C, self.R, self.M0, p.direction)
                v0 = self.xi_dot0 if (k == 0 and p.t_start == 0.0) else 0.0
                z0 = np.array([p.xi_start, v0, p.eta_start, 1.0])
                out[sel] = (expm(tau[:, None, None] * M) @ z0)[:, :3]
        return out

    def to_dict(self) -> dict:
        """JSON-ready, each key's unit in its name at the governor's coordinate (``units``)."""
        u = self.units
        x = u["x"]
        return {
            # the source is the method's (its "strokes" equation: the type's own or borrowed)
            "model": "hybrid stick-slip strokes, static = kinetic friction",
            f"I_{u['inertia']}": self.I, f"f_{u['damping']}": self.f, "k2_per_s2": self.k2,
            f"C_{u['lever']}": self.C, f"R_{u['engine']}": self.R, f"M0_{u['force']}": self.M0,
            f"xi0_{x}": self.xi0, "eta0_rad_per_s": self.eta0,
            f"xi_dot0_{u['rate']}": self.xi_dot0,
            "outcome": self.outcome, "moved": self.moved, "note": self.note,
            "t_simulated_s": self.t_simulated,
            "t_horizon_s": self.t_horizon, "settle_tol": self.settle_tol,
            "n_strokes": len(self.strokes), f"first_stroke_end_{x}": self.first_stroke_end,
            "over_regulation": self.over_regulation, "hunting": self.hunting,
            "equilibrium_crossings": self.equilibrium_crossings,
            f"final_xi_{x}": self.final_state[0],
            f"resting_offset_{x}": self.resting_offset,
            "speed_offset_rad_per_s": self.speed_offset,
            "friction_speed_band_rad_per_s": self.M0 / self.C if self.C else None,
            "creep_ratio": self.creep_ratio,
            "phases": [p.to_dict(u) for p in self.phases],
        }


def _num(x):
    return None if x is None or not math.isfinite(x) else float(x)


def _slide(M, z0, s, t_max, h):
    """Integrate one stroke from ``z0`` in direction ``s`` until ``xi' = 0`` or ``t_max``.

    Returns ``(tau, z)``: the stroke's duration (None if it reaches ``t_max``) and the state at
    its end.
    """
    from scipy.optimize import brentq  # where a stroke's end is refined

    def at(tau):
        return expm(M * tau) @ z0

    def v(tau):
        return at(tau)[1]

    def acc(tau):
        return M[1] @ at(tau)

    E = expm(M * h)
    t, z = 0.0, z0
    started = s * z0[1] > 0.0  # s xi' has been seen positive
    steps = 0
    while t < t_max:
        t1 = t + h
        if t1 >= t_max:
            t1 = t_max
            z1 = at(t1)
        else:
            steps += 1
            z1 = at(t1) if steps % _RESYNC == 0 else E @ z
        if s * z1[1] <= 0.0:
            lo = t
            if not started:
                # The stroke starts from rest with zero or tiny acceleration (a break-away):
                # s xi' ~ c tau^2 > 0 at first; find a point where it is positive.
                lo, tau = None, t1
                for _ in range(80):
                    tau *= 0.5
                    if s * v(tau) > 0.0:
                        lo = tau
                        break
                if lo is None:
                    return 0.0, z0.copy()
            # the stepped state E^k z0 and the exact expm(M t) z0 differ by rounding: where the
            # exact velocity has not changed sign over (lo, t1) the stroke goes on (or, past
            # zero already at lo, it ended there)
            if s * v(lo) <= 0.0:
                return lo, at(lo)
            if s * v(t1) > 0.0:
                started = True
                t, z = t1, at(t1)
                continue
            tr = brentq(v, lo, t1, xtol=_XTOL, rtol=_RTOL)
            return tr, at(tr)
        if started and s * (M[1] @ z) < 0.0 < s * (M[1] @ z1) \
                and s * acc(t) < 0.0 < s * acc(t1):
            # s xi' has a local minimum inside (t, t1): does it dip through zero? (The bracket
            # is taken on acc itself: the stepped state E^k z0 and expm(M t) z0 differ by
            # rounding, and where xi'' is ~0 at a step's end the two can disagree in sign;
            # the minimum is then at that end, where s xi' > 0 was just seen.)
            tm = brentq(acc, t, t1, xtol=_XTOL, rtol=_RTOL)
            if s * v(tm) <= 0.0:
                tr = brentq(v, t, tm, xtol=_XTOL, rtol=_RTOL) if s * v(t) > 0.0 else t
                return tr, at(tr)
        started = True
        t, z = t1, z1
    return None, z


def friction_transient(I, f, k2, C, R, M0, xi0, eta0, t_end=None, max_strokes=50, *,
                       xi_dot0=0.0, settle_tol=1e-6) -> FrictionResult:
    """Load change with a constant friction moment ``M0`` at the fulcrum (Hamabe, eqs. 42-46).

    ``I xi'' + f xi' + I k^2 xi + M0 sign(xi') = C eta``, ``eta' = -R xi``, from
    ``(xi0, xi_dot0, eta0)``. Solved phase by phase (see the module docstring): strokes exactly
    by ``expm``, their ends (``xi' = 0``, eq. 46) by ``brentq``, the friction law at every stop
    (stick while ``|C eta - I k^2 xi| <= M0``) and break-away times in closed form.

    Stops at ``t_end`` (default ``30 / min|lambda|`` over the frictionless system's
    eigenvalues), after ``max_strokes`` strokes, when the pendulum is stuck exactly at
    ``xi = 0``, or once a stuck offset or a stroke's travel is below ``settle_tol * |xi0|``.
    ``f = 0`` is Hamabe's case (no dash-pot); ``M0 = 0`` gives the linear solution of eq. (28).

    Parameters
    ----------
    I : float [kg m^2]
        Moment of inertia of the pendulum about its fulcrum (kg for a length coordinate).
    f : float [N m s/rad]
        Dash-pot coefficient (N s/m for a length coordinate); 0 is Hamabe's friction case.
    k2 : float [1/s^2]
        ``k^2`` at the new equilibrium.
    C : float [N m s]
        ``dM/domega`` at ``(alpha0, omega0)`` (N s for a length coordinate).
    R : float [1/s^2]
        ``-(dT/dalpha) / I_fw`` (eq. 27; 1/(m s^2) for a length coordinate).
    M0 : float [N m]
        Friction moment at the fulcrum (N for a length coordinate).
    xi0 : float [rad]
        Initial deviation (m for a length coordinate).
    eta0 : float [rad/s]
        Initial speed error.
    t_end : float [s], optional
        Time horizon.
    max_strokes : int [-]
        Stroke budget (dimensionless count).
    xi_dot0 : float [rad/s]
        Initial velocity of the pendulum.
    settle_tol : float [-]
        Offset, relative to ``|xi0|``, below which the run counts as settled.

    Returns
    -------
    FrictionResult [-]
        The phases (stick, slide) and the criteria (over-regulation, hunting).

    References
    ----------
    [hamabe] Part III, eqs. (42)-(46).

    Examples
    --------
    Hamabe's friction example, case d, with the paper's model and no dash-pot: with
    ``M0 = 22.6 kgf cm`` the first stroke ends at -0.0286 rad, no over-regulation, as the
    paper says; with 3 kgf cm (below the threshold of about 5.15 kgf cm found by bisection) it
    overshoots to +0.018 rad.

    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-d.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> for M0 in (22.6, 3.0):  # kgf cm
    ...     m = load_change_model(spec, dashpot=0.0, friction_moment=M0 * 0.0980665)
    ...     r = friction_transient(m.I, m.f, m.k2, m.C, m.R, m.M0, m.xi0, m.eta0)
    ...     print(round(r.first_stroke_end, 4), r.over_regulation)
    -0.0286 False
    0.0182 True
    """
    I, f, k2, C, R, M0 = (float(x) for x in (I, f, k2, C, R, M0))
    xi, v, eta = float(xi0), float(xi_dot0), float(eta0)
    if I <= 0 or C <= 0 or R <= 0 or M0 < 0 or f < 0:
        raise ValueError("need I, C, R > 0 and f, M0 >= 0")
    lam = np.linalg.eigvals(slide_matrix(I, f, k2, C, R)[:3, :3])
    h = 0.1 / float(np.max(np.abs(lam)))
    if t_end is None:
        t_end = 30.0 / float(np.min(np.abs(lam)))
    t_end = float(t_end)
    tol = settle_tol * abs(xi0)

    def net(x, e):
        return C * e - I * k2 * x

    phases: list[Phase] = []
    t, outcome = 0.0, "horizon"
    while True:
        if t >= t_end:
            outcome = "horizon"
            break
        if len(phases) and sum(p.kind == "slide" for p in phases) >= max_strokes:
            outcome = "max_strokes"
            break
        n = net(xi, eta)
        # at rest within the band, or on its edge to rounding (then the drift decides)
        if v == 0.0 and abs(n) <= M0 + 1e-12 * max(abs(C * eta), abs(I * k2 * xi), M0):
            # stick: eta' = -R xi, so n(t) = n - C R xi (t - t_s) until |n| = M0
            if xi == 0.0:
                phases.append(Phase("stick", t, math.inf, xi, xi, eta, eta, 0, n, n))
                outcome = "at rest"
                break
            if phases and abs(xi) <= tol:
                phases.append(Phase("stick", t, t, xi, xi, eta, eta, 0, n, n, complete=False))
                outcome = "settled"
                break
            n_b = -math.copysign(M0, xi)
            tb = t + max(0.0, (n - n_b) / (C * R * xi))
            if tb >= t_end:
                e_end = eta - R * xi * (t_end - t)
                phases.append(Phase("stick", t, t_end, xi, xi, eta, e_end, 0, n,
                                    net(xi, e_end), complete=False))
                moved = any(p.kind == "slide" for p in phases)
                t, outcome = t_end, "horizon" if moved else "stuck"
                break
            eta_b = (n_b + I * k2 * xi) / C
            phases.append(Phase("stick", t, tb, xi, xi, eta, eta_b, 0, n, net(xi, eta_b)))
            t, eta = tb, eta_b
            s = -1 if xi > 0 else 1
        else:
            s = (1 if v > 0 else -1) if v != 0.0 else (1 if n > 0 else -1)
        M = slide_matrix(I, f, k2, C, R, M0, s)
        z0 = np.array([xi, v, eta, 1.0])
        n0 = net(xi, eta)
        tau, z = _slide(M, z0, s, t_end - t, h)
        if tau is None:
            phases.append(Phase("slide", t, t_end, xi, float(z[0]), eta, float(z[2]), s, n0,
                                net(z[0], z[2]), float(z[1]), complete=False))
            t, outcome = t_end, "horizon"
            break
        xi_e, eta_e = float(z[0]), float(z[2])
        phases.append(Phase("slide", t, t + tau, xi, xi_e, eta, eta_e, s, n0, net(xi_e, eta_e),
                            float(z[1])))
        travel = abs(xi_e - xi)
        t, xi, v, eta = t + tau, xi_e, 0.0, eta_e
        if travel <= tol and abs(xi) <= tol:
            outcome = "settled"
            break
    t_sim = min(t, t_end)
    return FrictionResult(I, f, k2, C, R, M0, float(xi0), float(eta0), float(xi_dot0),
                          tuple(phases), outcome, t_sim, t_end, settle_tol, h)


def stroke_ratio(I, f, k2, C, R) -> float:
    """``xi_end / xi_start`` of a stroke that starts from rest at a break-away (or, with
    consistent statics, from the old equilibrium), whatever ``M0``.

    Relative to the friction-shifted equilibrium ``(0, 0, s M0 / C)`` the break-away state is
    ``(xi_s, 0, I k^2 xi_s / C)`` -- the pendulum balanced, with the speed error of a static
    equilibrium -- so the stroke is the frictionless load-change response (eq. 28) from that
    state up to its first stop, scaled by ``xi_s``. Negative: every such stroke over-regulates;
    between 0 and 1: the pendulum creeps in from one side by this ratio per stick-slip cycle
    (:attr:`FrictionResult.creep_ratio`). ``nan`` if the stroke never stops (monotonic
    approach within ``30 / min|lambda|``).

    Parameters
    ----------
    I : float [kg m^2]
        Moment of inertia of the pendulum about its fulcrum (kg for a length coordinate).
    f : float [N m s/rad]
        Dash-pot coefficient (N s/m for a length coordinate); 0 is Hamabe's friction case.
    k2 : float [1/s^2]
        ``k^2`` at the new equilibrium.
    C : float [N m s]
        ``dM/domega`` at ``(alpha0, omega0)`` (N s for a length coordinate).
    R : float [1/s^2]
        ``-(dT/dalpha) / I_fw`` (eq. 27; 1/(m s^2) for a length coordinate).

    Returns
    -------
    float [-]
        ``xi_end / xi_start``.

    References
    ----------
    [hamabe] Part III, eqs. (42)-(46); the self-similar creep is govopt's own finding on them.

    Examples
    --------
    Hamabe's friction example, case a: ``M0 = 22.6 kgf cm`` (2.216 N m), no dash-pot,
    Example 3's unloading, with the paper's model. The paper finds no over-regulation; the
    first stroke ends at -0.0803 rad, still short of the new equilibrium. The pendulum then
    creeps in by a fixed ratio per stick-slip cycle, which does not depend on ``M0``: the
    stroke ratio equals the creep ratio of the full run.

    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> m = load_change_model(spec, dashpot=0.0, friction_moment=22.6 * 0.0980665)
    >>> r = friction_load_change(spec, dashpot=0.0, friction_moment=22.6 * 0.0980665)
    >>> round(stroke_ratio(m.I, m.f, m.k2, m.C, m.R), 4), round(r.creep_ratio, 4)
    (0.6276, 0.6276)
    """
    r = friction_transient(I, f, k2, C, R, 0.0, 1.0, I * k2 / C, max_strokes=1,
                           settle_tol=0.0)
    s = r.strokes
    return s[0].xi_end if s and s[0].complete else math.nan


def friction_load_change(spec: Spec, sd: statics.SpringDesign | None = None,
                         load_change: LoadChange | None = None, *, dashpot: float | None = None,
                         friction_moment: float | None = None, **kwargs) -> FrictionResult:
    """:func:`friction_transient` for a load change of a spec's design (Hamabe, eqs. 42-46).

    Coefficients from :func:`load_change_model`; ``M0`` is the design's ``friction_moment`` and
    ``f`` its dash-pot (0 when absent) unless given. ``kwargs`` go to
    :func:`friction_transient` (``t_end``, ``max_strokes``, ``settle_tol``).

    Parameters
    ----------
    spec : Spec [-]
        The governor's spec, with its engine and load change(s).
    sd : SpringDesign [-]
        The spring and flying masses; default: the spec's design.
    load_change : LoadChange [-]
        The load change; default: the spec's first.
    dashpot : float [N m s/rad]
        Dash-pot coefficient (N s/m for a length coordinate).
    friction_moment : float [N m]
        Friction moment ``M0`` at the fulcrum (N for a length coordinate).
    **kwargs : dict [-]
        Passed to :func:`friction_transient`.

    Returns
    -------
    FrictionResult [-]
        As :func:`friction_transient`, with the type's units for its JSON.

    References
    ----------
    [hamabe] Part III, eqs. (42)-(46).

    Examples
    --------
    Hamabe's friction example, case a: ``M0 = 22.6 kgf cm`` (2.216 N m), no dash-pot,
    Example 3's unloading, with the paper's model. The paper finds no over-regulation; the
    first stroke ends at -0.0803 rad, still short of the new equilibrium.

    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> r = friction_load_change(spec, dashpot=0.0, friction_moment=22.6 * 0.0980665)
    >>> round(r.first_stroke_end, 4), r.over_regulation, r.hunting
    (-0.0803, False, False)
    """
    m = load_change_model(spec, sd, load_change, dashpot=dashpot,
                          friction_moment=friction_moment)
    return replace(friction_transient(m.I, m.f, m.k2, m.C, m.R, m.M0, m.xi0, m.eta0, **kwargs),
                   units=m.units)
