"""Plain-text report of a :class:`~govopt.result.Result` for the terminal (formats only)."""

from __future__ import annotations

import math

from ..result import Result
from ..units import to_unit


def _table(headers: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(headers)]
    line = "  ".join(h.rjust(w) for h, w in zip(headers, widths, strict=True))
    body = ["  ".join(c.rjust(w) for c, w in zip(r, widths, strict=True)) for r in rows]
    return "\n".join([line, "-" * len(line), *body])


def format_result(res: Result) -> str:
    """The characteristic table, spring, checks and (when present) dynamics, in SI with rpm."""
    st, sd, sp = res.statics, res.spring, res.spring_properties
    out = [f"govopt {res.kind}: {res.spec.name}  ({res.spec.path})",
           f"fidelity: geometry={res.spec.analysis.geometry}, "
           f"reaction_speed={res.spec.analysis.reaction_speed}, "
           f"stress_correction={res.spec.material.stress_correction}", ""]
    headers = ["alpha deg", "omega rad/s", "rpm", "M_z N m", "M_f N m", "M_r0 N m",
               "F_spring N", "tau MPa"]
    if res.k2 is not None:
        headers.append("k^2 1/s^2")
    rows = []
    for i, a in enumerate(st.alpha):
        row = [f"{math.degrees(a):.3f}", f"{st.omega[i]:.4f}", f"{st.omega[i] * 30 / math.pi:.2f}",
               f"{st.M_z[i]:.3f}", f"{st.M_f[i]:.3f}", f"{st.M_r0[i]:.3f}",
               f"{st.spring_force[i]:.1f}", f"{st.stress[i] / 1e6:.1f}"]
        if res.k2 is not None:
            row.append(f"{res.k2[i]:.1f}")
        rows.append(row)
    out += ["Characteristic (Hamabe eq. 12)", _table(headers, rows), ""]
    out += [
        f"irregularity          {res.irregularity:.5f}  "
        f"(required <= {res.spec.speed.irregularity:g})",
        f"speed range           {st.omega[0]:.4f} .. {st.omega[-1]:.4f} rad/s  "
        f"({st.omega[0] * 30 / math.pi:.2f} .. {st.omega[-1] * 30 / math.pi:.2f} rpm)",
        f"pendulum              {sd.m:.4g} kg ({to_unit(sd.m * 9.80665, 'force', 'kgf'):.4g} kgf),"
        f" I = {sd.inertia:.5g} kg m^2",
        f"spring                d = {sd.d * 1e3:.4g} mm, r = {sd.r * 1e3:.4g} mm, n = {sd.n:g}, "
        f"kappa = {sd.kappa:.6g} N/m, free half length l0 = {sd.l0 * 1e3:.4f} mm",
        f"                      index C = {sp['spring_index']:.3f}, Wahl K = "
        f"{sp['wahl_factor']:.4f}, mass = {sp['mass_kg']:.4g} kg, surge = "
        f"{sp['surge_frequency_Hz']:.4g} Hz",
        f"max shear stress      {res.max_stress / 1e6:.2f} MPa  "
        f"(allowable {res.spec.material.allowable_shear_stress / 1e6:.2f} MPa)",
        "",
    ]
    out += format_dynamics(res)
    out.append("Checks")
    out.append(_table(["check", "value", "limit", "margin", ""],
                      [[c.name, f"{c.value:.6g}", f"{c.sense} {c.limit:.6g}",
                        f"{100 * c.margin:+.2f} %",
                        ("PASS" if c.passed else "FAIL") + (" (active)" if c.active else "")]
                       for c in res.checks]))
    return "\n".join(out)


def format_dynamics(res: Result) -> list[str]:
    """Lines for the dynamics sections present in the result (none for statics only)."""
    out = []
    vib = res.dynamics.get("vibration")
    if vib:
        out += ["Vibration under the valve gear (Hamabe Part II, normal configuration)",
                f"  k^2 = {vib['k2_rad2_s2']:.1f} 1/s^2, peak-to-peak "
                f"{math.degrees(vib['peak_to_peak_rad']):.3f} deg "
                f"(+- {math.degrees(vib['truncation_error_rad']):.2g} deg truncation, "
                f"{vib['n_harmonics']} harmonics), eccentric travel "
                f"{vib['eccentric_travel_m'] * 1e3:.3f} mm", ""]
    for lc in res.dynamics.get("load_changes", []):
        roots = ", ".join(f"{r:.4g}" if abs(i) < 1e-12 else f"{r:.4g}{i:+.4g}i"
                          for r, i in lc["roots_per_s"])
        out += [f"Load change '{lc['name']}' {lc['alpha_from_deg']:.3f} -> "
                f"{lc['alpha_to_deg']:.3f} deg (Hamabe Part III, eq. 28)",
                f"  roots {roots} 1/s ({lc['kind']}); Hurwitz margin (eq. 32) "
                f"{lc['hurwitz_margin']:.4g}; stable: {lc['stable']}",
                f"  over-regulation {math.degrees(lc['over_regulation_rad']):.4g} deg; settling "
                f"({100 * lc['settling_band']:g} % band) {lc['settling_time_s']:.4g} s; first "
                f"arrival {lc['first_arrival_time_s']:.4g} s", ""]
    opt = res.optimisation
    if opt:
        d, b = opt["design"], opt.get("continuous_bound")
        out += [f"Design ({opt['status']}): objective {opt['objective']['name']} = "
                f"{opt['objective']['value']:.5g}"
                + (f", continuous bound {b['objective']:.5g} (gap {100 * opt['gap']:.2f} %)"
                   if b else ""),
                f"  dash-pot f = {d['dashpot_N_m_s_per_rad']:.5g} N m s/rad (feasible "
                f"{d['dashpot_feasible_range_N_m_s_per_rad'][0]:.4g} .. "
                f"{d['dashpot_feasible_range_N_m_s_per_rad'][1]:.4g} on the search grid)",
                f"  searched {opt['search']['combinations']} combinations, "
                f"{opt['search']['statics_feasible']} pass the statics, "
                f"{opt['search']['spring_feasible']} the spring checks",
                *[f"  {s['text']}" for s in opt.get("sensitivities", [])], ""]
    return out
