"""Plots an engineer reads (matplotlib, PNG and SVG): one function per plot, data from the Result.

Every plot draws numbers a :class:`~govopt.result.Result` carries (its statics, k^2, classic
measures and dynamics); nothing here recomputes physics. Configurations are shown as people read
them through the seam (``spec.governor.shown``: degrees or millimetres), speeds in rpm with rad/s
on the right-hand axis. The plots, each named by its *kind*:

* ``characteristic``: equilibrium speed against configuration, the required speed band
  (``[speed]``), the friction band where the design has friction, the normal configuration;
  the title cites the type's statics (its method, :meth:`Governor.method`);
* ``linkage``: the governor drawn to scale at its innermost, normal and outermost
  configurations, from the geometry its statics use (:meth:`Governor.drawing`);
* ``controlling-force`` (ball and fly-weight governors, coordinate = the ball's radius): the
  controlling force ``F_c(r)`` per ball with lines of constant speed ``F = m omega^2 r`` through
  the origin (textbook 3.3, the controlling-force diagram); each line joins the origin to a point
  of the curve, so it is drawn from the curve alone;
* ``k2``: ``k^2`` over the range against ``omega0^2`` with the stable band ``0 < k^2 < omega0^2``
  (Hamabe Part II, cases 1-3);
* ``load-change-N``: the N-th load change's response (Hamabe Part III, eq. 28) with the new
  equilibrium, the over-regulation, the settling band and the settling time;
* ``vyshnegradsky``: every load change's point ``(A, B)`` on Vyshnegradsky's diagram
  (:mod:`govopt.analysis.vyshnegradsky`);
* ``vibration-spectrum`` and ``vibration-trace``: the harmonic amplitudes of the forced vibration
  and the steady response over one revolution (Hamabe Part II, eqs. 18-22), where the type has a
  periodic forcing;
* ``fatigue``: the spring's fatigue diagram with its load cycle under that vibration (EN 13906-1
  Annex A or Shigley §10-9), where the spec names a wire grade (the spring report).
* ``speed-band``: a robust design's equilibrium speed at nominal values and its least and largest
  over the tolerance box (:mod:`govopt.optimize.robust`);
* ``yield``: governors made to the spec's tolerances (:mod:`govopt.made`): the worst-case speeds
  over the tolerance box as made, the sampled governors' speeds and the yield in the title.

matplotlib is imported only when a plot is drawn (``govopt --help`` never loads it); figures are
:class:`matplotlib.figure.Figure` objects on the Agg canvas, so no GUI backend or pyplot state is
touched. :mod:`govopt.report.plot_files` writes them to files (through
:func:`govopt.report.files.atomic_write` and its no-clobber policy); this module only draws, so
:meth:`govopt.result.Result.plot` imports it without importing the evaluator back.
"""

from __future__ import annotations

import math

import numpy as np

from ..units import SI_UNITS
from ..verdict import shown

FORMATS = ("png", "svg")
#: inches and dots per inch of a single plot: 1050 x 675 px, text readable at 100 % zoom
SIZE, DPI = (7.0, 4.5), 150
#: the kinds in the order they are drawn; ``load-change`` stands for ``load-change-1``, ...
KINDS = ("characteristic", "linkage", "controlling-force", "k2", "load-change", "vyshnegradsky",
         "vibration-spectrum", "vibration-trace", "fatigue", "speed-band", "yield")
STYLE = {"font.size": 10, "axes.titlesize": 11, "axes.labelsize": 10, "legend.fontsize": 9,
         "axes.grid": True, "grid.alpha": 0.35, "svg.hashsalt": "govopt"}
RPM = 30.0 / math.pi  # rpm per rad/s


def kinds(res) -> list[str]:
    """The plots ``res`` has data for, in order (see the module docstring)."""
    dyn = res.dynamics or {}
    changes = dyn.get("load_changes") or []
    vib = dyn.get("vibration")
    return [k for k, present in (
        ("characteristic", True),
        ("linkage", res.spec.governor.drawing(res.spec.governor.x_normal, res.spring)
         is not None),
        ("controlling-force", res.spec.governor.coordinate == "length"),
        ("k2", res.k2 is not None),
        *((f"load-change-{i}", True) for i in range(1, len(changes) + 1)),
        ("vyshnegradsky", bool(changes)),
        ("vibration-spectrum", bool(vib)),
        ("vibration-trace", bool(vib) and "response" in vib),
        ("fatigue", "diagram" in (_fatigue_loads(res) or {})),
        ("speed-band", "speed_band" in ((res.optimisation or {}).get("robust") or {})),
        ("yield", bool(res.made)),
    ) if present]


def _mpa(figure):
    """A stress figure's value in MPa (a number or a list of numbers), converted from its unit
    (:func:`govopt.verdict.shown`; a figure in MPa as it is)."""
    value, unit = shown(figure.value, figure.unit)
    if unit != "MPa":
        raise ValueError(f"{figure.name}: a stress in Pa or MPa expected, got {figure.unit!r}")
    return value


def _fatigue_loads(res) -> dict | None:
    """The spring's fatigue load cycle from the Result's spring report, where it has one."""
    rep = getattr(res, "spring_report", None)
    return None if rep is None else rep.loads.get("fatigue")


# --------------------------------------------------------------------------------------------
# helpers


def _shown(res, x):
    """Configuration values as people read them and the unit (``"deg"`` or ``"mm"``)."""
    values, unit = res.spec.governor.shown(x)
    return np.asarray(values, dtype=float), unit


def _config_label(res) -> str:
    gov = res.spec.governor
    return f"{gov.coordinate_name} ({_shown(res, 0.0)[1]})"


def _rad_s_axis(ax) -> None:
    """A right-hand axis in rad/s beside a speed axis in rpm."""
    ax.secondary_yaxis("right", functions=(lambda v: v / RPM, lambda v: v * RPM)).set_ylabel(
        "speed (rad/s)")


def _mark_normal(res, ax) -> None:
    gov = res.spec.governor
    xn, unit = _shown(res, gov.x_normal)
    ax.axvline(float(xn), color="0.4", ls=":", lw=1.2,
               label=f"normal configuration {float(xn):.4g} {unit}")


def _finite(value) -> float | None:
    """A JSON number as a float; None where the Result has none (an infinity is ``null``)."""
    v = float("nan") if value is None else float(value)
    return v if math.isfinite(v) else None


def _title(res, ax, what: str) -> None:
    ax.set_title(f"{res.spec.name}: {what}")


def new_axes():
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=SIZE, dpi=DPI, layout="constrained")
    FigureCanvasAgg(fig)
    return fig.add_subplot()


# --------------------------------------------------------------------------------------------
# one function per plot


def characteristic(res, ax) -> None:
    """Equilibrium speed against configuration with the required band (Hamabe Part I: the
    irregularity; textbook 3.4(b): the friction band of speeds opening and closing)."""
    st, spec, cl = res.statics, res.spec, res.classic or {}
    x, _ = _shown(res, st.alpha)
    ax.plot(x, st.omega * RPM, color="tab:blue", lw=2, label="equilibrium speed")
    if spec.speed is not None:
        lo, hi = spec.speed.omega_inner * RPM, spec.speed.omega_outer * RPM
        ax.axhspan(lo, hi, color="tab:green", alpha=0.15,
                   label=f"required band {lo:.4g}-{hi:.4g} rpm "
                         f"(irregularity {spec.speed.irregularity:.3g})")
    rise, fall = (np.asarray(cl.get(k, []), dtype=float)
                  for k in ("omega_rise_rad_s", "omega_fall_rad_s"))
    friction = rise.size == x.size and np.any(rise > fall)
    if friction:
        ax.plot(x, rise * RPM, color="tab:red", ls="--", lw=1, label="opening against friction")
        ax.plot(x, fall * RPM, color="tab:purple", ls="--", lw=1,
                label="closing against friction")
    for i, off in ((0, (8, -8)), (-1, (-8, 8))):  # the ends decide the irregularity; their
        ax.plot(x[i], st.omega[i] * RPM, "o", color="tab:blue")  # labels off the curve's side
        ax.annotate(f"{st.omega[i] * RPM:.4g} rpm", (x[i], st.omega[i] * RPM), xytext=off,
                    textcoords="offset points", ha="left" if i == 0 else "right",
                    va="top" if i == 0 else "bottom")
    _mark_normal(res, ax)
    ax.margins(x=0.04, y=0.1)
    ax.set_xlabel(_config_label(res))
    ax.set_ylabel("speed (rpm)")
    _rad_s_axis(ax)
    delta = _finite(res.irregularity)  # against the spec's mean speed, where it has one
    _title(res, ax, f"characteristic, {res.method.named('characteristic').cite} (" + (
        f"irregularity {delta:.4g})" if delta is not None else
        f"sensitiveness {cl.get('sensitiveness', 0.0):.4g})"))
    if friction:  # three curves across the axes: the legend below them, covering none
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=8.5)
    else:
        ax.legend(loc="upper left")


def _speed_axes(res, ax) -> None:
    """A speed band plot's required band (dashed green), axis labels and rad/s axis."""
    spec = res.spec
    if spec.speed is not None:
        a, b = spec.speed.omega_inner * RPM, spec.speed.omega_outer * RPM
        ax.axhline(a, color="tab:green", ls="--", lw=1)
        ax.axhline(b, color="tab:green", ls="--", lw=1,
                   label=f"spec's speed range {a:.4g}-{b:.4g} rpm")
    ax.set_xlabel(_config_label(res))
    ax.set_ylabel("speed (rpm)")
    _rad_s_axis(ax)


def _band_and_nominal(res, ax, band: dict, label: str) -> np.ndarray:
    """Fill ``band``'s least and largest equilibrium speed against the configuration
    (``label``) and draw the nominal characteristic over it; returns the band's shown
    configurations."""
    xs = np.asarray(next(v for k, v in band.items() if k.startswith("configuration_")))
    x, _ = _shown(res, xs)
    lo, hi = (np.asarray(band[k], dtype=float) * RPM for k in ("lowest_rad_s", "highest_rad_s"))
    ax.fill_between(x, lo, hi, color="tab:orange", alpha=0.3, label=label)
    xn, _ = _shown(res, res.statics.alpha)
    ax.plot(xn, res.statics.omega * RPM, color="tab:blue", lw=2, label="nominal")
    return x


def speed_band(res, ax) -> None:
    """A robust design's speed band under its tolerances: the equilibrium speed at
    nominal values, and the least and largest over the points of the tolerance box evaluated
    (each at the fitter's setting), against the configuration, with the required band; the
    title gives what robustness cost in the objective."""
    _band_and_nominal(res, ax, res.optimisation["robust"]["speed_band"],
                      "over the tolerance box (after the fitter's setting)")
    _speed_axes(res, ax)
    cost = res.optimisation["robust"].get("cost") or {}
    more = cost.get("increase_percent")
    _title(res, ax, "speed band under the tolerances" + (
        "" if more is None else f" (robustness cost {more:+.3g} %)"))
    ax.legend(loc="upper left")


def made_yield(res, ax) -> None:
    """Governors made to the spec's tolerances (``Result.made``, :mod:`govopt.made`): the
    equilibrium speed at nominal values, its least and largest over the tolerance box as made
    (exact, at the box's corners), the sampled governors' speeds at both ends of the range, and
    the required band; the title gives the yield in the reports' words
    (:func:`govopt.made.yield_words`)."""
    from ..made_words import yield_words

    made, spec = res.made, res.spec
    y = made["yield"]
    x = _band_and_nominal(res, ax, made["speed_band"],
                          "worst case over the tolerance box (as made)")
    ends = [(x[0], y.get("sampled_inner_rad_s")), (x[-1], y.get("sampled_outer_rad_s"))]
    how = "as made and set" if made["tolerances"].get("set_by_the_fitter") else "as made"
    for i, (at, w) in enumerate(e for e in ends if e[1]):
        ax.plot([at, at], [w[0] * RPM, w[1] * RPM], color="k", lw=3, solid_capstyle="butt",
                label=f"{y['samples']} sampled governors ({how})" if i == 0 else None)
    _speed_axes(res, ax)
    words = yield_words(made)
    ax.set_title(f"{spec.name}: made to its tolerances\n{_wrapped(words, 90)}", fontsize=9)
    ax.legend(loc="upper left", fontsize=8)


def _wrapped(text: str, width: int) -> str:
    """``text`` broken into lines of at most ``width`` characters."""
    import textwrap

    return "\n".join(textwrap.wrap(text, width))


def controlling_force(res, ax) -> None:
    """The controlling-force diagram (textbook 3.3): ``F_c(r)`` per ball (at equilibrium the
    centrifugal force ``m omega^2 r``, the characteristic's ``M_z``, N) against the ball's radius,
    with lines of constant speed through the origin at the inner, normal and outer radii."""
    st, gov = res.statics, res.spec.governor
    r, unit = _shown(res, st.alpha)
    ax.plot(r, st.M_z, color="tab:blue", lw=2.2, label="controlling force $F_c(r)$")
    i_n = int(np.argmin(np.abs(st.alpha - gov.x_normal)))
    r_end = 1.08 * float(r[-1])
    for i, color in ((0, "tab:green"), (i_n, "0.4"), (-1, "tab:red")):
        slope = float(st.M_z[i]) / float(r[i])
        ax.plot(r[i], st.M_z[i], "o", color=color, mec="k", zorder=5)
        ax.plot([0.0, r_end], [0.0, slope * r_end], color=color, ls="--", lw=1,
                label=f"constant speed {float(st.omega[i]) * RPM:.4g} rpm "
                      f"(r = {float(r[i]):.4g} {unit})")
    ax.set_xlim(0.0, r_end)
    ax.set_ylim(0.0, 1.08 * float(np.max(st.M_z)))
    ax.set_xlabel(_config_label(res))
    ax.set_ylabel(f"controlling force per {gov.mass_name} (N)")
    _title(res, ax, "controlling-force diagram")
    ax.legend(loc="upper left")


#: The k^2 plot shows the ceiling omega0^2 on its axis only where k^2 reaches this share of it
#: (below, the data would sit squashed in the axis's bottom quarter).
FAR_CEILING = 0.25


def k2(res, ax) -> None:
    """``k^2`` over the range (Hamabe Part II): where the type is forced at the running speed's
    harmonics (``resonance_ceiling``), against the band ``0 < k^2 < omega0^2`` (case 1;
    resonance risk above, case 2; unstable below 0, case 3); otherwise only ``k^2 > 0``
    (stability) is required and the axis is scaled to ``k^2`` itself. The required margin (the
    check ``k^2 > 0``'s limit, where positive) is drawn as a line, its spare named."""
    x, _ = _shown(res, res.statics.alpha)
    w0sq = res.omega_reference**2
    k2v = np.asarray(res.k2, dtype=float)
    ceiling = res.spec.governor.resonance_ceiling
    low = next((c for c in res.checks if c.name == "k^2 > 0 (stability)"), None)
    floor = low.limit if low is not None and low.limit > 0 else None
    top = float(np.max(k2v))
    if ceiling:
        source = res.spec.governor.resonance_source
        case = f" ({source})" if source else ""
        ax.axhspan(0.0, w0sq, color="tab:green", alpha=0.15,
                   label=r"stable, clear of resonance: $0 < k^2 < \omega_0^2$" + case)
        lo = min(0.0, float(np.min(k2v)))
        if top >= FAR_CEILING * w0sq:
            ax.axhline(w0sq, color="tab:red", ls="--", lw=1.2,
                       label=rf"$\omega_0^2$ = {w0sq:.4g} 1/s$^2$ "
                             f"({res.omega_reference * RPM:.4g} rpm)")
            hi = max(w0sq, top)
        else:  # the ceiling far above: the axis is the data's, the ceiling named
            ax.plot([], [], " ", label=rf"$\omega_0^2$ = {w0sq:.4g} 1/s$^2$, above the axis: "
                                       f"{100 * (1 - top / w0sq):.0f} % spare")
            hi = top
    else:  # no ceiling: the axis is the data's and the limit 0 (or the margin's line)
        lo = min(0.0, float(np.min(k2v)))
        hi = max(float(np.max(k2v)), floor or 0.0)
        ax.axhspan(0.0, hi + (hi - lo), color="tab:green", alpha=0.15,
                   label="stable: $k^2 > 0$ (no forcing at the running speed's harmonics, "
                         "so no ceiling)")
    ax.axhline(0.0, color="k", lw=0.8)
    if floor is not None:
        ax.axhline(floor, color="tab:orange", ls="--", lw=1.2,
                   label=f"required $k^2 \\geq$ {floor:.4g} 1/s$^2$ "
                         f"({floor / w0sq:.3g} $\\omega_0^2$)")
    ax.plot(x, k2v, color="tab:blue", lw=2,
            label=f"$k^2$: {float(np.min(k2v)):.4g} .. {float(np.max(k2v)):.4g} 1/s$^2$")
    _mark_normal(res, ax)
    ax.set_ylim(lo - 0.06 * (hi - lo), hi + 0.3 * (hi - lo))
    ax.set_xlabel(_config_label(res))
    ax.set_ylabel("$k^2$ (1/s$^2$)")
    _title(res, ax, "restoring stiffness $k^2$ over the range")
    ax.legend(loc="upper left", ncol=1)


def load_change(res, ax, index: int = 0) -> None:
    """A load change's response (the type's load-change cubic, its method's ``cubic``: Hamabe
    eq. 28 for the shaft governor): the configuration against time, the
    new equilibrium, the over-regulation (the largest swing past it) and the settling band
    ``+- band |xi0|`` with the settling time."""
    lc = res.dynamics["load_changes"][index]
    target = res.spec.load_changes[index]  # the Result's dynamics follow the spec's order
    u = SI_UNITS[res.spec.governor.coordinate]  # the keys name the coordinate's SI unit
    t = np.asarray(lc["response"]["t_s"], dtype=float)
    xi = np.asarray(lc["response"][f"xi_{u}"], dtype=float)  # null (unbounded) -> nan
    xi0 = float(lc["initial_state"][f"xi_{u}"])
    (x0, x1), unit = _shown(res, [target.alpha_from, target.alpha_to])
    band = float(lc["settling_band"]) * abs(xi0)
    lo, hi = _shown(res, [target.alpha_to - band, target.alpha_to + band])[0]
    ax.axhspan(lo, hi, color="tab:green", alpha=0.2,
               label=f"settling band \u00b1{100 * lc['settling_band']:g} % of the change")
    ax.axhline(x1, color="k", ls="--", lw=1, label=f"new equilibrium {x1:.4g} {unit}")
    ax.plot(t, _shown(res, target.alpha_to + xi)[0], color="tab:blue", lw=2,
            label=res.spec.governor.coordinate_name)
    ts = _finite(lc["settling_time_s"])
    if ts is not None:
        ax.axvline(ts, color="tab:green", ls=":", lw=1.5, label=f"settled at {ts:.3g} s")
    else:
        ax.plot([], [], " ", label="does not settle")
    over = _finite(lc[f"over_regulation_{u}"])
    if over is None:
        ax.plot([], [], " ", label="over-regulation without bound (unstable)")
    elif over > 0:
        past = _shown(res, target.alpha_to - math.copysign(over, xi0))[0]
        amount = float(_shown(res, over)[0])
        ax.axhline(float(past), color="tab:red", ls="-.", lw=1,
                   label=f"over-regulation {amount:.3g} {unit}")
    else:
        ax.plot([], [], " ", label="no over-regulation")
    ax.set_xlim(0.0, float(t[-1]))
    ax.margins(y=0.08)
    ax.set_xlabel("time after the load change (s)")
    ax.set_ylabel(_config_label(res))
    _title(res, ax, f"load change '{lc['name']}' {x0:.4g} \u2192 {x1:.4g} {unit} "
                    f"({res.method.named('cubic').cite})")
    ax.legend(loc="best")


def vyshnegradsky(res, ax) -> None:
    """Vyshnegradsky's diagram (the load-change cubic in normal form): the regions and the
    stability,
    discriminant and monotonic boundaries of :func:`govopt.analysis.vyshnegradsky.boundaries`,
    with each load change's point ``(A, B)``."""
    from ..analysis import vyshnegradsky as vy

    changes = res.dynamics["load_changes"]
    pts = [(float(c["vyshnegradsky"]["A"]), float(c["vyshnegradsky"]["B"])) for c in changes]
    top = max([6.0] + [1.25 * v for p in pts for v in p])
    grid = np.linspace(top / 300, top, 300)
    index = {name: i for i, name in enumerate(vy.REGIONS)}
    zone = vy.regions(grid[None, :], grid[:, None])  # rows along B, columns along A
    colors = ("#dbe9f6", "#e2f0d9", "#fff2cc", "#f4cccc")  # in the order of vy.REGIONS
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch
    from scipy.ndimage import distance_transform_edt

    ax.pcolormesh(grid, grid, zone, cmap=ListedColormap(colors), vmin=-0.5,
                  vmax=len(colors) - 0.5, shading="nearest", rasterized=True)
    # each region's name where it is widest, away from the frame and the points
    aa, bb = np.meshgrid(grid, grid)
    clear = np.ones_like(zone, dtype=bool)
    for a, b in pts:
        clear &= np.hypot(aa - a, bb - b) > 0.1 * top
    for name, i in index.items():
        room = distance_transform_edt(np.pad((zone == i) & clear, 1))[1:-1, 1:-1]
        if room.max() > 0.05 * len(grid):
            b, a = np.unravel_index(np.argmax(room), room.shape)
            ax.text(grid[a], grid[b], name, ha="center", va="center", fontsize=10,
                    style="italic", color="0.25")
    handles = [Patch(color=c, label=name) for name, c in zip(vy.REGIONS, colors, strict=True)]
    curves = vy.boundaries(top)
    for key, style, label in (("stability", "k-", "stability boundary $AB = 1$"),
                              ("aperiodic", "b-", "three real roots (discriminant = 0)"),
                              ("monotonic", "g--", "$2A^3 - 9AB + 27 = 0$")):
        handles += ax.plot(*curves[key], style, lw=1.4, label=label)
    for k, (c, (a, b)) in enumerate(zip(changes, pts, strict=True)):  # named in the legend
        handles += ax.plot(a, b, "osD^v"[k % 5], ms=9, color="k", mfc="white", mew=2, ls="none",
                           zorder=5, label=f"{c['name']}: A = {a:.3g}, B = {b:.3g} "
                                           f"({c['vyshnegradsky']['region']})")
    ax.set_xlim(0.0, top)
    ax.set_ylim(0.0, top)
    ax.set_xlabel("A (dimensionless)")
    ax.set_ylabel("B (dimensionless)")
    _title(res, ax, r"Vyshnegradsky's diagram ($\lambda^3 + A\lambda^2 + B\lambda + 1 = 0$)")
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3,
              fontsize=8.5)


def vibration_spectrum(res, ax) -> None:
    """The harmonic amplitudes of the steady forced vibration at the normal configuration
    (Hamabe Part II, eq. 22 with the dash-pot; order ``n`` = n times per revolution)."""
    vib = res.dynamics["vibration"]
    orders = np.array([h["order"] for h in vib["harmonics"]])
    amp, unit = _shown(res, [h["amplitude_rad"] for h in vib["harmonics"]])
    ax.bar(orders, amp, color=np.where([h["resonant"] for h in vib["harmonics"]],
                                       "tab:red", "tab:blue"), width=0.6)
    largest = float(np.max(amp[np.isfinite(amp)], initial=0.0))
    noise = 1e-9 * largest  # below: rounding, not an excited order
    for n, v in zip(orders, amp, strict=True):
        ax.annotate("inf" if not np.isfinite(v) else f"{v:.3g}" if v > noise else "0", (n, v),
                    xytext=(0, 2), textcoords="offset points", ha="center", fontsize=8)
    if largest > 0:
        ax.set_ylim(0.0, 1.1 * largest)  # room for the largest bar's label
    p2p = float(_shown(res, vib["peak_to_peak_rad"])[0])
    ax.plot([], [], " ", label=f"peak-to-peak {p2p:.3g} {unit}; k$^2$ = "
                               f"{vib['k2_rad2_s2']:.4g} 1/s$^2$")
    ax.set_xticks(orders)
    ax.set_xlabel("harmonic order n (per revolution)")
    ax.set_ylabel(f"amplitude ({unit})")
    a0, a_unit = _shown(res, vib["alpha0_rad"])
    _title(res, ax, f"forced vibration at {float(a0):.4g} {a_unit}: harmonic amplitudes")
    ax.legend(loc="upper right")


def vibration_trace(res, ax) -> None:
    """The steady forced vibration over one revolution, ``xi`` about the normal configuration
    against the crank angle (Hamabe Part II, eqs. 18-22: the sum of the kept harmonics)."""
    vib = res.dynamics["vibration"]
    tau = np.degrees(np.asarray(vib["response"]["crank_angle_rad"], dtype=float))
    xi, unit = _shown(res, vib["response"]["xi_rad"])
    ax.plot(tau, xi, color="tab:blue", lw=2, label=r"$\xi$")
    p2p = float(_shown(res, vib["peak_to_peak_rad"])[0])
    for v in (np.max(xi), np.min(xi)):
        ax.axhline(float(v), color="tab:red", ls="--", lw=1)
    ax.plot([], [], "--", color="tab:red", lw=1,
            label=f"peak-to-peak {p2p:.3g} {unit} ({vib['n_harmonics']} harmonics)")
    a0, a_unit = _shown(res, vib["alpha0_rad"])
    ax.set_xlim(0.0, 360.0)
    ax.set_xticks(np.arange(0, 361, 45))
    ax.set_xlabel("crank angle (deg)")
    ax.margins(y=0.25)  # room for the legend above or below the swing
    ax.set_ylabel(f"swing $\\xi$ ({unit})")
    _title(res, ax, f"forced vibration about {float(a0):.4g} {a_unit}, one revolution")
    ax.legend(loc="best")


def fatigue(res, ax) -> None:
    """The spring's fatigue diagram with its load cycle under the forced vibration (the body's
    diagram of :func:`govopt.springs.fatigue.body_locus`; corrected stresses, MPa): EN 13906-1's
    Goodman diagram (upper against lower stress, the cycle a vertical stroke) or Shigley's
    amplitude against midrange (Zimmerli's point, the load line through the cycle). The legend
    lists the fatigue safety factors of the Result's checks (the body and any hooks)."""
    fat = _fatigue_loads(res)
    dia = fat["diagram"]
    lo, hi = (_mpa(fat[k]) for k in ("corrected stress min", "corrected stress max"))
    if dia["method"] == "EN13906":
        x, y = (np.asarray(_mpa(dia["locus"][k])) for k in ("lower stress", "upper stress"))
        cycles = f"{dia['cycles']:.0e}".replace("e+0", "e").replace("e+", "e")
        ax.plot(x, y, color="tab:red", lw=2, label=f"admissible upper stress ({cycles} cycles)")
        ax.plot([0.0, x[-1]], [0.0, x[-1]], color="0.4", ls="--", lw=1,
                label="upper = lower (no stroke)")
        ax.plot([lo, lo], [lo, hi], color="tab:blue", lw=3, solid_capstyle="butt",
                label=f"load cycle {lo:.4g} \u2192 {hi:.4g} MPa")
        ax.plot(lo, hi, "o", color="tab:blue", mec="k")
        top = float(np.interp(lo, x, y))  # the diagram read at the cycle's lower stress
        ax.plot([lo, lo], [hi, top], color="tab:blue", ls=":", lw=1.5,
                label=f"admissible stroke at {lo:.4g} MPa: {top - lo:.4g} MPa")
        corner = "lower right"
        ax.set_xlabel("corrected lower stress $\\tau_{k1}$ (MPa)")
        ax.set_ylabel("corrected upper stress $\\tau_{k2}$ (MPa)")
        what = "EN 13906-1 Goodman diagram"
    else:
        x, y = (np.asarray(_mpa(dia["locus"][k])) for k in ("midrange stress",
                                                            "amplitude stress"))
        ax.plot(x, y, color="tab:red", lw=2, label=f"{dia['criterion'].capitalize()} line")
        zm, za = _mpa(dia["zimmerli"])
        ax.plot(zm, za, "s", color="tab:red", mec="k", label="Zimmerli's endurance point")
        tm, ta = (_mpa(fat[k]) for k in ("mean stress", "alternating stress"))
        ax.plot([0.0, x[-1]], [0.0, ta / tm * x[-1]], color="0.4", ls="--", lw=1,
                label="load line")
        ax.plot(tm, ta, "o", color="tab:blue", mec="k",
                label=f"load cycle {tm:.4g} \u00b1 {ta:.4g} MPa")
        ax.set_ylim(0.0, 1.1 * float(np.max(y)))
        corner = "upper right"
        ax.set_xlabel("corrected midrange stress $\\tau_m$ (MPa)")
        ax.set_ylabel("corrected stress amplitude $\\tau_a$ (MPa)")
        what = "Shigley's fatigue diagram"
    factors = [c for c in res.checks if c.name.endswith("fatigue safety factor")]
    governs = min(factors, key=lambda c: c.margin, default=None)
    for c in factors:  # the verdicts, as the Result's checks give them; the least governs
        note = "" if c is not governs or len(factors) == 1 else ", governs"
        ax.plot([], [], " ", label=f"{c.name.replace(' factor', '')}: {c.value:.3g} "
                                   f"(need {c.limit:.3g}){note}")
    ax.set_xlim(0.0, float(x[-1]) * 1.05)
    ax.set_ylim(bottom=0.0)
    if fat.get("hooks"):  # room above the body's diagram for the hooks' own
        ax.set_ylim(0.0, 1.7 * ax.get_ylim()[1])
        _hooks(fat["hooks"], {c.name.split()[1]: c for c in factors
                              if c.name.startswith("hook ")}, ax, governs)
    _title(res, ax, f"spring fatigue: {what}")
    ax.legend(loc=corner, fontsize=8 if len(factors) > 1 else 8.5)


def _hooks(hooks: dict, checks: dict, ax, governs) -> None:
    """The hooks' fatigue diagram in an inset of ``ax`` (Shigley §10-11, Example 10-7): each
    point's amplitude over its line's endurance intercept against its midrange over the
    ultimate, so that one line (Goodman ``x + y = 1``, Gerber ``y = 1 - x^2``) serves bending at
    A and torsion at B; the load line through each cycle meets it at the safety factor times
    the cycle (marked x; the amplitude axis zoomed to show it). The governing hook is red."""
    ins = ax.inset_axes([0.07, 0.6, 0.36, 0.33])
    u = np.linspace(0.0, 1.0, 201)
    line = {"goodman": 1.0 - u, "gerber": 1.0 - u**2}.get(hooks["criterion"], 0.0 * u + 1.0)
    ins.plot(u, line, color="tab:red", lw=1.5)
    top = 0.0
    for point, offset in (("A", (5, -11)), ("B", (-12, 5))):
        h, check = hooks[point], checks.get(point)
        xm = h["midrange"].value / h["ultimate"].value  # ratios of stresses: any one unit
        ya = h["amplitude"].value / h["endurance"].value
        colour = "tab:red" if check is not None and check is governs else "tab:blue"
        n = None if check is None else check.value
        reach = n if n is not None and np.isfinite(n) else 1.0
        ins.plot([0.0, reach * xm], [0.0, reach * ya], color=colour, ls=":", lw=1)
        ins.plot(reach * xm, reach * ya, "x", color=colour, ms=5)  # the cycle times n: on the line
        ins.plot(xm, ya, "o", color=colour, mec="k", ms=5)
        ins.annotate(point + ("" if n is None else f" {n:.3g}"), (xm, ya), xytext=offset,
                     textcoords="offset points", fontsize=7, color=colour)
        top = max(top, reach * ya)
    ins.set_xlim(0.0, 1.0)
    ins.set_ylim(0.0, min(1.05, 2.0 * top) if top > 0 else 1.05)
    ins.set_xlabel("midrange / ultimate", fontsize=7)
    ins.set_ylabel("amplitude / endurance", fontsize=7)
    ins.tick_params(labelsize=6)
    ins.set_title(f"hooks: A bending, B torsion ({hooks['criterion'].capitalize()}, Shigley "
                  "10-11)", fontsize=7)


#: How :func:`linkage` draws the three configurations: (label, colour, line style).
CONFIGURATIONS = (("innermost", "tab:blue", "--"), ("normal", "k", "-"),
                  ("outermost", "tab:red", "--"))


def linkage(res, ax) -> None:
    """The governor drawn to scale (:meth:`Governor.drawing`, the geometry its statics use) at
    its innermost, normal and outermost configurations, one colour each: links and arms as
    lines, the flying masses as steel balls of their mass, fulcrums and hinges as triangles,
    the sleeve and the spring; mm on equal axes."""
    from matplotlib.patches import Circle

    gov, sd = res.spec.governor, res.spring
    drawing = None
    for (label, colour, style), x in zip(CONFIGURATIONS, (gov.x_inner, gov.x_normal,
                                                          gov.x_outer), strict=True):
        drawing = gov.drawing(x, sd)
        xs, unit = _shown(res, x)
        first = True
        for part in drawing.parts:
            pts = np.asarray(part.points, dtype=float) * 1e3
            if part.kind == "frame":
                if len(pts) == 1:
                    ax.add_patch(Circle(tuple(pts[0]), part.size * 1e3, color="0.55"))
                else:
                    ax.plot(*pts.T, color="0.55", lw=2.5, zorder=1)
            elif part.kind == "mass":
                ax.add_patch(Circle(tuple(pts[0]), part.size * 1e3, fill=False, ec=colour,
                                    ls=style, lw=1.5, zorder=3))
            elif part.kind == "pivot":
                ax.plot(*pts.T, "^", color=colour, ms=6, zorder=4)
            else:
                ax.plot(*pts.T, color=colour, ls=":" if part.kind == "spring" else style,
                        lw=1.0 if part.kind == "spring" else 1.6, zorder=2,
                        label=f"{label}: {gov.coordinate_name} {float(xs):.4g} {unit}"
                        if first else None)
                first = False
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.set_xlabel(drawing.axes[0])
    ax.set_ylabel(drawing.axes[1])
    _title(res, ax, "the governor drawn to scale (balls: steel of their mass)")
    ax.legend(loc="best", fontsize=8)


DRAW = {"characteristic": characteristic, "linkage": linkage,
        "controlling-force": controlling_force, "k2": k2,
        "vyshnegradsky": vyshnegradsky, "vibration-spectrum": vibration_spectrum,
        "vibration-trace": vibration_trace, "fatigue": fatigue, "speed-band": speed_band,
        "yield": made_yield}


# --------------------------------------------------------------------------------------------
# entry points


def draw(res, kind: str, ax=None):
    """Draw plot ``kind`` of ``res`` on ``ax`` (a new figure's axes if None); return the axes.
    Raises ValueError naming the plots ``res`` has if it has no data for ``kind``."""
    import matplotlib as mpl

    available = kinds(res)
    if kind not in available:
        raise ValueError(f"no {kind!r} plot for {res.spec.name}; it has: {', '.join(available)}")
    with mpl.rc_context(STYLE):
        ax = new_axes() if ax is None else ax
        if kind.startswith("load-change-"):
            load_change(res, ax, int(kind.rsplit("-", 1)[1]) - 1)
        else:
            DRAW[kind](res, ax)
    return ax


def overview(res):
    """A figure with every plot of ``res`` (two columns); returns the figure."""
    import matplotlib as mpl
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    names = kinds(res)
    rows = (len(names) + 1) // 2
    with mpl.rc_context(STYLE):
        fig = Figure(figsize=(2 * SIZE[0], rows * SIZE[1]), dpi=DPI, layout="constrained")
        FigureCanvasAgg(fig)
        for i, name in enumerate(names, start=1):
            draw(res, name, fig.add_subplot(rows, 2, i))
    return fig


def plot(res, kind: str | None = None, ax=None):
    """``Result.plot``: one plot on ``ax`` (returns the axes), or with ``kind=None`` every plot
    in one new figure (returns the figure)."""
    if kind is None:
        if ax is not None:
            raise ValueError("plot(kind=None) draws every plot in a new figure; name a kind to "
                             "draw on ax")
        return overview(res)
    return draw(res, kind, ax)
