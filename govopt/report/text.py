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
        f"irregularity          {res.irregularity:.5f}  (required <= {res.spec.speed.irregularity:g})",
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
    return []
