"""The specification an engineer sends to a spring maker (after EN 13906 / DIN 2099 sheets).

A :class:`SpringSheet` holds SI numbers for one helical spring - material, wire and coil
diameters, coils, ends or hooks, free length, rate, two working points (force and length), the
EN 15800 tolerance grade with the tolerances it implies, surface treatment - and renders itself
as a dict (SI keys with units) or as text in the spring maker's units (mm, N, N/mm).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np

from ..verdict import Figure
from . import compression as hc
from . import extension as he
from . import helical as hx
from . import tolerances as tol
from .materials import Material


class _Section:
    def __repr__(self) -> str:
        return "<SECTION>"


#: The value of a section's title row among :func:`record_rows`.
SECTION = _Section()


def record_json(record: Mapping) -> dict:
    """The JSON of a record: a nested dict whose values are :class:`~govopt.verdict.Figure`
    (written under its :attr:`~govopt.verdict.Figure.key`, which names its unit), a record (a
    section, under its key) or plain data (words, counts, lists: under its key, as it is).

    Parameters
    ----------
    record : Mapping [SI]
        Figures (each carrying its SI unit), records and plain data by key.

    Returns
    -------
    dict [SI]
        The same nesting, each figure's key naming its unit (``rate_N_per_m``).

    Examples
    --------
    >>> record_json({"rate": Figure("rate", 2e4, "N/m"), "grade": "SH", "x": {"n": 3}})
    {'rate_N_per_m': 20000.0, 'grade': 'SH', 'x': {'n': 3}}
    """
    out = {}
    for key, value in record.items():
        if isinstance(value, Figure):
            out[value.key] = value.value
        elif isinstance(value, Mapping):
            out[key] = record_json(value)
        else:
            out[key] = value
    return out


def record_rows(record: Mapping, depth: int = 0) -> Iterator[tuple[int, str, Any, str]]:
    """``(depth, label, SI value, SI unit)`` rows of a record, depth first: a figure's name and
    unit from its fields, a section's title (value :data:`SECTION`) and a plain entry's key in
    words (no unit).

    Parameters
    ----------
    record : Mapping [SI]
        Figures (each carrying its SI unit), records and plain data by key.
    depth : int [-]
        Nesting depth of ``record`` (dimensionless count).

    Yields
    ------
    tuple [SI]
        ``(depth, label, value, unit)``, the value in the figure's SI unit.

    Examples
    --------
    >>> list(record_rows({"rate": Figure("rate", 2e4, "N/m"), "loads": {"life_cycles": 7}}))[1:]
    [(0, 'loads', <SECTION>, ''), (1, 'life cycles', 7, '')]
    """
    for key, value in record.items():
        if isinstance(value, Figure):
            yield depth, value.name, value.value, value.unit
        elif isinstance(value, Mapping):
            yield depth, key.replace("_", " "), SECTION, ""
            yield from record_rows(value, depth + 1)
        else:
            yield depth, key.replace("_", " "), value, ""


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

    def figures(self) -> dict:
        """The sheet as a record (:func:`record_json`, :func:`record_rows`): each number a
        :class:`~govopt.verdict.Figure` with its SI unit as a field, the words as they are,
        the tolerances a section of figures (``A_d`` ... of EN 15800, in m or N)."""
        mm = ("m", "d", "D", "L0", "L1", "L2", "solid_length")
        names = {"d": "wire diameter", "D": "mean coil diameter", "n": "active coils",
                 "L0": "free length", "R": "rate", "F1": "force 1", "L1": "length 1",
                 "F2": "force 2", "L2": "length 2", "F0": "initial tension", "mass": "mass",
                 "surge_frequency": "surge frequency", "solid_length": "solid length"}
        units = {"R": "N/m", "F1": "N", "F2": "N", "F0": "N", "mass": "kg",
                 "surge_frequency": "Hz", "n": ""}
        out: dict = {}
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name == "tolerances":
                value = {k: Figure(k.replace("_", " "), v, "m" if k.startswith(
                    ("A_d", "A_D", "A_L0")) else "N", group="tolerance")
                    for k, v in value.items()}
            elif f.name in names:
                value = Figure(names[f.name], value, units.get(f.name, "m" if f.name in mm
                                                               else ""), symbol=f.name)
            out[f.name] = value
        out["outside diameter"] = Figure("outside diameter", self.D + self.d, "m")
        out["inside diameter"] = Figure("inside diameter", self.D - self.d, "m")
        return out

    def to_dict(self) -> dict:
        """SI values, each key naming its unit (:meth:`figures` by :func:`record_json`)."""
        return record_json(self.figures())

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
    """The wire standard whose diameter tolerances apply to the grade (EN 10270-1 or -2, ASTM
    A228, A227 or A229), or None (:func:`govopt.springs.tolerances.wire_standard`).

    Parameters
    ----------
    mat : Material [-]
        The wire grade (:func:`govopt.springs.materials.material`).

    Returns
    -------
    str or None [-]
        A key of :data:`govopt.springs.tolerances.WIRE_TOLERANCE`, or None.

    References
    ----------
    [en10270-1], [en10270-2]; ASTM A228, A227, A229 (as their wire makers quote them).

    Examples
    --------
    >>> from govopt.springs.materials import material
    >>> wire_standard(material("EN10270-1 DH")), wire_standard(material("Shigley A228"))
    ('EN10270-1', 'ASTM A228')
    >>> wire_standard(material("Shigley A401")) is None
    True
    """
    return tol.wire_standard(mat.grade)


def compression_sheet(mat: Material, d, D, n, n_t, L0, F1, F2, *, ends: str = "closed_ground",
                      grade: int = 2, surface: str = "none") -> SpringSheet:
    """The sheet of a compression spring; working lengths follow from the rate.

    ``L_i = L0 - F_i / R`` with ``R = G d^4 / (8 D^3 n)``; the solid length with the largest
    wire diameter within tolerance; EN 15800 tolerances of grade ``grade``.

    Parameters
    ----------
    mat : Material [-]
        The wire grade (:func:`govopt.springs.materials.material`).
    d : float [m]
        Wire diameter.
    D : float [m]
        Mean coil diameter.
    n : float [-]
        Active coils.
    n_t : float [-]
        Total coils.
    L0 : float [m]
        Free length.
    F1, F2 : float [N]
        The two working forces.
    ends : str [-]
        End form, a key of :data:`~govopt.springs.compression.END_FORMS`.
    grade : int [-]
        EN 15800 quality grade 1, 2 or 3.
    surface : str [-]
        Surface treatment, as written on the sheet (dimensionless text).

    Returns
    -------
    SpringSheet [SI]
        The sheet, SI (m, N, N/m, kg, Hz).

    References
    ----------
    [en13906-1] rate and solid length; [en15800] tolerances; [shigley] 9th ed. Example 10-4.

    Examples
    --------
    Shigley (9th ed.) Example 10-4: music wire d = 0.092 in, OD = 9/16 in, free length 4 3/8 in,
    21 active and 23 total coils, squared and ground, 5 and 35 lbf. The book prints
    k = 48.1 lbf/in; by hand, ``L2 = 111.125 - 155.69 / 8.4233 = 92.64`` mm and the solid length
    with EN 13906-1's largest wire, ``n_t d_max = 23 * 0.093 = 2.139`` in (ASTM A228 holds 0.092
    in wire to +-0.001 in; the book's ``L_s = d N_t = 2.116`` in takes the nominal wire).

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> s = compression_sheet(material("Shigley A228"), 0.092 * inch, (9 / 16 - 0.092) * inch,
    ...                       21, 23, 4.375 * inch, 5 * lbf, 35 * lbf)
    >>> round(s.R / (lbf / inch), 1), round(s.L2 * 1e3, 2), round(s.solid_length / inch, 3)
    (48.1, 92.64, 2.139)
    """
    G = _f(mat.shear_modulus(d))
    R = _f(hx.stiffness(d, D, n, G))
    d_max = tol.max_wire_diameter(d, mat.grade)
    tols = {"A_D": _f(tol.coil_diameter_tolerance(D, D / d, grade)),
            "A_L0": _f(tol.free_length_tolerance(d, D, n, R, grade)),
            "A_F1": _f(tol.force_tolerance(F1, d, D, n, grade)),
            "A_F2": _f(tol.force_tolerance(F2, d, D, n, grade))}
    std = wire_standard(mat)
    if std:
        tols["A_d"] = _f(tol.wire_diameter_tolerance(d, std))
    notes = ("tolerances on F1, F2 (with L0 free) after EN 15800; A_L0 applies if no force "
             "is toleranced",)
    Lc = _f(hc.solid_length(d_max, n_t, ends))
    F_c = R * (_f(L0) - Lc)

    def length(F):  # a force past solid: no length (the spring never gets there)
        return _f(L0) - _f(F) / R if _f(F) <= F_c else float("nan")
    if _f(F2) > F_c:
        notes += (f"solid at {F_c:.5g} N, below the working force: no length given past it",)
    return SpringSheet(
        kind="compression", grade=mat.grade, material_standard=mat.standard, d=_f(d), D=_f(D),
        n=_f(n), coils=_f(n_t), ends=ends.replace("_", " "), L0=_f(L0), R=R, F1=_f(F1),
        L1=length(F1), F2=_f(F2), L2=length(F2), tolerance_grade=grade,
        surface=surface,
        mass=_f(hx.helix_mass(d, D, n, hc.pitch(L0, d, n, n_t, ends, d_max), _f(n_t) - _f(n),
                              mat.density)),
        surge_frequency=_f(hx.surge_frequency(d, D, n, G, mat.density)),
        solid_length=Lc, tolerances=tols, notes=notes)


def extension_sheet(mat: Material, d, D, n_body, F0, F1, F2, *,
                    hooks: str = "full loops (German loops) in line, both ends",
                    grade: int = 2, surface: str = "none") -> SpringSheet:
    """The sheet of an extension spring with two full loops; lengths inside the loops.

    Active coils ``n = n_b + G/E``, ``L0 = 2 (D - d) + (n_b + 1) d`` and
    ``L_i = L0 + (F_i - F0) / R``; EN 15800's coil diameter tolerance only (the standard covers
    compression springs).

    Parameters
    ----------
    mat : Material [-]
        The wire grade (:func:`govopt.springs.materials.material`).
    d : float [m]
        Wire diameter.
    D : float [m]
        Mean coil diameter.
    n_body : float [-]
        Body coils ``n_b``.
    F0 : float [N]
        Initial tension.
    F1, F2 : float [N]
        The two working forces.
    hooks : str [-]
        The loops, as written on the sheet (dimensionless text).
    grade : int [-]
        EN 15800 quality grade 1, 2 or 3.
    surface : str [-]
        Surface treatment, as written on the sheet (dimensionless text).

    Returns
    -------
    SpringSheet [SI]
        The sheet, SI (m, N, N/m, kg, Hz).

    References
    ----------
    [en13906-2] free length and loops; [shigley] 9th ed. §10-11, Example 10-6.

    Examples
    --------
    Shigley (9th ed.) Example 10-6: hard-drawn wire d = 0.035 in, OD = 0.248 in, initial tension
    1.19 lbf, 12.17 body coils. The book prints N_a = 12.57, k = 17.91 lbf/in, L0 = 0.817 in.

    >>> from govopt.springs.materials import material
    >>> inch, lbf = 0.0254, 4.4482216152605
    >>> s = extension_sheet(material("Shigley A227"), 0.035 * inch, (0.248 - 0.035) * inch,
    ...                     12.17, 1.19 * lbf, 1.19 * lbf, 5.25 * lbf)
    >>> round(s.n, 2), round(s.R / (lbf / inch), 2), round(s.L0 / inch, 3)
    (12.57, 17.91, 0.817)
    """
    G, E = _f(mat.shear_modulus(d)), _f(mat.elastic_modulus(d))
    n = _f(he.extension_active_coils(n_body, G, E))
    R = _f(hx.stiffness(d, D, n, G))
    L0 = _f(he.extension_free_length(d, D, n_body))
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
        # the body's coils touching (pitch d), the two loops counted as two more coils
        mass=_f(hx.helix_mass(d, D, 0.0, 0.0, _f(n_body) + 2.0, mat.density)),
        surge_frequency=_f(hx.surge_frequency(d, D, n, G, mat.density)),
        tolerances=tols, notes=notes)
