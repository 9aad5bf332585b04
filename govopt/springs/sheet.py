"""The specification an engineer sends to a spring maker (after EN 13906 / DIN 2099 sheets).

A :class:`SpringSheet` holds SI numbers for one helical spring - material, wire and coil
diameters, coils, ends or hooks, free length, rate, two working points (force and length), the
EN 15800 tolerance grade with the tolerances it implies, surface treatment - and renders itself
as a dict (SI keys with units) or as text in the spring maker's units (mm, N, N/mm).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

import numpy as np

from . import helical as hx
from . import tolerances as tol
from .materials import Material


@dataclass(frozen=True)
class SpringSheet:
    """One spring, SI. ``coils`` is the total coils (compression) or body coils (extension)."""

    kind: str
    grade: str
    material_standard: str
    d: float
    D: float
    n: float
    coils: float
    ends: str
    L0: float
    R: float
    F1: float
    L1: float
    F2: float
    L2: float
    tolerance_grade: int
    surface: str
    F0: float = 0.0
    mass: float = 0.0
    surge_frequency: float = 0.0
    solid_length: float | None = None
    tolerances: dict[str, float] = field(default_factory=dict)
    notes: tuple[str, ...] = ()

    def to_dict(self) -> dict:
        """SI values; key suffixes give the unit."""
        out = asdict(self)
        renamed = {"d": "wire_diameter_m", "D": "mean_coil_diameter_m", "n": "active_coils",
                   "L0": "free_length_m", "R": "rate_N_per_m", "F1": "force_1_N",
                   "L1": "length_1_m", "F2": "force_2_N", "L2": "length_2_m",
                   "F0": "initial_tension_N", "mass": "mass_kg",
                   "surge_frequency": "surge_frequency_Hz", "solid_length": "solid_length_m"}
        out = {renamed.get(k, k): v for k, v in out.items()}
        out["outside_diameter_m"] = self.D + self.d
        out["inside_diameter_m"] = self.D - self.d
        out["tolerances"] = {f"{k}_m" if k.startswith(("A_d", "A_D", "A_L0")) else f"{k}_N": v
                             for k, v in self.tolerances.items()}
        return out

    def to_text(self) -> str:
        """The sheet in mm, N and N/mm."""
        mm, t = 1e3, self.tolerances
        coils = "total coils n_t" if self.kind == "compression" else "body coils n_b"

        def pm(key, scale=mm, unit="mm"):
            return f" +- {t[key] * scale:.3g} {unit}" if key in t else ""
        lines = [
            f"Helical {self.kind} spring (cold coiled, round wire) - specification",
            f"  material            {self.grade}  ({self.material_standard})",
            f"  wire diameter d     {self.d * mm:.3f} mm" + pm("A_d"),
            f"  mean diameter D     {self.D * mm:.2f} mm" + pm("A_D")
            + f"   (outside {(self.D + self.d) * mm:.2f}, inside {(self.D - self.d) * mm:.2f} mm)",
            f"  active coils n      {self.n:.2f}",
            f"  {coils:<19} {self.coils:.2f}",
            f"  ends / hooks        {self.ends}",
            f"  free length L0      {self.L0 * mm:.2f} mm" + pm("A_L0"),
            f"  rate R              {self.R / 1e3:.4g} N/mm",
        ]
        if self.kind == "extension":
            lines.append(f"  initial tension F0  {self.F0:.4g} N")
        lines += [
            f"  working point 1     F1 = {self.F1:.4g} N" + pm("A_F1", 1.0, "N")
            + f" at L1 = {self.L1 * mm:.2f} mm",
            f"  working point 2     F2 = {self.F2:.4g} N" + pm("A_F2", 1.0, "N")
            + f" at L2 = {self.L2 * mm:.2f} mm",
        ]
        if self.solid_length is not None:
            lines.append(f"  solid length Lc     {self.solid_length * mm:.2f} mm (max)")
        lines += [
            f"  tolerances          EN 15800 grade {self.tolerance_grade}",
            f"  surface treatment   {self.surface}",
            "  coiling direction   right hand (unless stated)",
            f"  mass                {self.mass * 1e3:.4g} g;  surge frequency "
            f"{self.surge_frequency:.4g} Hz",
        ]
        lines += [f"  note: {n}" for n in self.notes]
        return "\n".join(lines)


def _f(x) -> float:
    return float(np.asarray(x, dtype=float))


def wire_standard(mat: Material) -> str | None:
    """The wire standard whose diameter tolerances apply to the grade (EN 10270-1 or -2), or
    None."""
    for std in tol.WIRE_TOLERANCE:
        if mat.grade.startswith(std):
            return std
    return None


def compression_sheet(mat: Material, d, D, n, n_t, L0, F1, F2, *, ends: str = "closed_ground",
                      grade: int = 2, surface: str = "none") -> SpringSheet:
    """The sheet of a compression spring; working lengths follow from the rate."""
    G = _f(mat.shear_modulus(d))
    R = _f(hx.stiffness(d, D, n, G))
    tols = {"A_D": _f(tol.coil_diameter_tolerance(D, D / d, grade)),
            "A_L0": _f(tol.free_length_tolerance(d, D, n, R, grade)),
            "A_F1": _f(tol.force_tolerance(F1, d, D, n, grade)),
            "A_F2": _f(tol.force_tolerance(F2, d, D, n, grade))}
    std = wire_standard(mat)
    if std:
        tols["A_d"] = _f(tol.wire_diameter_tolerance(d, std))
    notes = ("tolerances on F1, F2 (with L0 free) after EN 15800; A_L0 applies if no force "
             "is toleranced",)
    return SpringSheet(
        kind="compression", grade=mat.grade, material_standard=mat.standard, d=_f(d), D=_f(D),
        n=_f(n), coils=_f(n_t), ends=ends.replace("_", " "), L0=_f(L0), R=R, F1=_f(F1),
        L1=_f(L0) - _f(F1) / R, F2=_f(F2), L2=_f(L0) - _f(F2) / R, tolerance_grade=grade,
        surface=surface, mass=_f(hx.mass(d, D, n_t, mat.density)),
        surge_frequency=_f(hx.surge_frequency(d, D, n, G, mat.density)),
        solid_length=_f(hx.solid_length(d, n_t, ends)), tolerances=tols, notes=notes)


def extension_sheet(mat: Material, d, D, n_body, F0, F1, F2, *,
                    hooks: str = "full loops (German loops) in line, both ends",
                    grade: int = 2, surface: str = "none") -> SpringSheet:
    """The sheet of an extension spring with two full loops; lengths inside the loops."""
    G, E = _f(mat.shear_modulus(d)), _f(mat.elastic_modulus(d))
    n = _f(hx.extension_active_coils(n_body, G, E))
    R = _f(hx.stiffness(d, D, n, G))
    L0 = _f(hx.extension_free_length(d, D, n_body))
    tols = {"A_D": _f(tol.coil_diameter_tolerance(D, D / d, grade))}
    std = wire_standard(mat)
    if std:
        tols["A_d"] = _f(tol.wire_diameter_tolerance(d, std))
    notes = ("EN 15800 covers compression springs: force and length tolerances of this "
             "extension spring by agreement with the maker (coil diameter per EN 15800 Table 1)",
             f"active coils n = n_b + G/E = {n:.3f} (the loops' flexibility, Shigley §10-11)")
    return SpringSheet(
        kind="extension", grade=mat.grade, material_standard=mat.standard, d=_f(d), D=_f(D),
        n=n, coils=_f(n_body), ends=hooks, L0=L0, R=R, F1=_f(F1), L1=L0 + (_f(F1) - F0) / R,
        F2=_f(F2), L2=L0 + (_f(F2) - F0) / R, tolerance_grade=grade, surface=surface, F0=_f(F0),
        mass=_f(hx.mass(d, D, _f(n_body) + 2.0, mat.density)),
        surge_frequency=_f(hx.surge_frequency(d, D, n, G, mat.density)),
        tolerances=tols, notes=notes)
