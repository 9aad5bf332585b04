"""Spring wire materials: tensile strength as a function of wire diameter, moduli, allowables.

The grades and every number's source are in ``govopt/data/spring_materials.toml``; this module
only reads them and evaluates them vectorised in SI (d in m, stresses in Pa).

>>> dh = material("EN10270-1 DH")
>>> round(float(dh.tensile_strength(2e-3)) / 1e6)  # MPa at d = 2 mm: 2220 - 820 lg 2
1973
>>> round(float(material("Shigley A228").tensile_strength(2.5e-3)) / 1e6)  # 10th ed. Prob. 10-3
1936
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field, replace
from functools import cache
from importlib import resources

import numpy as np

from .tables import row_index

MPA = 1e6
GPA = 1e9
MM = 1e-3
#: kilopound per square inch in Pa (exact: 1 lbf = 4.4482216152605 N, 1 in = 0.0254 m).
KSI = 4.4482216152605e3 / 0.0254**2
INCH = 0.0254

#: Methods for allowable static stresses (see :func:`allowable_static_stress`).
METHODS = ("EN13906", "Shigley")
#: Where a static stress acts (keys of the rules in the data file).
STRESS_PLACES = ("compression", "solid", "extension", "hook_torsion", "hook_bending")


@dataclass(frozen=True)
class FatigueDiagram:
    """EN 13906-1 Goodman diagram at ``cycles``: three lines ``a - b lg(d / 1 mm)`` in Pa.

    ``tau_O`` is the upper corrected stress for a lower stress of zero, ``tau_max`` the diagram's
    horizontal cut-off and ``tau_U`` the lower stress where the Goodman line meets the cut-off.
    """

    tau_O: tuple[float, float]
    tau_max: tuple[float, float]
    tau_U: tuple[float, float]
    cycles: float
    source: str

    @staticmethod
    def _line(ab, d):
        return ab[0] - ab[1] * np.log10(np.asarray(d, dtype=float) / MM)

    def upper_at_zero(self, d):
        return self._line(self.tau_O, d)

    def cutoff(self, d):
        return self._line(self.tau_max, d)

    def knee(self, d):
        return self._line(self.tau_U, d)


@dataclass(frozen=True)
class Material:
    """One wire grade; all values SI. ``rm`` is the tensile-strength curve spec from the file."""

    grade: str
    standard: str
    family: str
    d_min: float
    d_max: float
    G: float | tuple[tuple[float, float], ...]
    E: float | tuple[tuple[float, float], ...]
    density: float
    rm: dict = field(repr=False)
    moduli_source: str = ""
    fatigue: dict[str, FatigueDiagram] = field(default_factory=dict, repr=False)

    @property
    def rm_source(self) -> str:
        return self.rm["source"]

    def in_range(self, d):
        """True where ``d`` (m) lies in the grade's diameter range."""
        d = np.asarray(d, dtype=float)
        return (d >= self.d_min * (1 - 1e-9)) & (d <= self.d_max * (1 + 1e-9))

    def tensile_strength(self, d):
        """Minimum tensile strength R_m (Pa) at wire diameter ``d`` (m); NaN outside the range.

        Table grades interpolate the standard's table linearly in lg d; step grades take the
        minimum of the standard's row holding ``d`` (rows by inclusive upper diameter, robust to
        the rounding of unit conversion: :func:`govopt.springs.tables.row_index`); fitted grades
        evaluate their published fit (the data file names which, and its source).

        >>> ss = material("EN10270-3 1.4310")  # EN 10270-3 NS: 0.80 < d <= 1.00 mm -> 1900
        >>> [round(float(ss.tensile_strength(x)) / 1e6) for x in (1e-3, 0.001000001, 0.009)]
        [1900, 1850, 1250]
        """
        d = np.asarray(d, dtype=float)
        rm, kind = self.rm, self.rm["kind"]
        dmm = d / MM
        if kind == "table":
            out = np.interp(np.log(dmm), np.log(rm["d_mm"]), rm["Pa"])
        elif kind == "steps":
            rows = np.asarray(rm["Pa"], dtype=float)
            out = rows[np.minimum(row_index(rm["d_upper_mm"], dmm), len(rows) - 1)]
        elif kind == "power":
            out = np.full(np.shape(d), np.nan)
            for p in rm["pieces"]:  # later pieces win at a shared boundary (both agree there)
                inside = (dmm >= p["d_min_mm"]) & (dmm <= p["d_max_mm"])
                out = np.where(inside, p["A_MPa"] * MPA / dmm ** p["m"], out)
        elif kind == "log10":
            out = np.minimum(rm["cap_MPa"], rm["a_MPa"] - rm["b_MPa"] * np.log10(dmm)) * MPA
        elif kind == "constant":
            out = np.full(np.shape(d), rm["MPa"] * MPA)
        else:  # pragma: no cover - the loader rejects other kinds
            raise ValueError(kind)
        return np.where(self.in_range(d), out, np.nan)

    @property
    def rm_nodes(self):
        """Wire diameters (m) of a table's nodes or a step table's rows' upper ends (where
        ``R_m d^m`` is largest in a row, for ``m > 0``); empty for the fits."""
        rm = self.rm
        mm = {"table": rm.get("d_mm"), "steps": rm.get("d_upper_mm")}.get(rm["kind"]) or []
        return np.asarray(mm, dtype=float) * MM

    def strength_exponent(self, d) -> float:
        """``-d ln R_m / d ln d`` at wire diameter ``d`` (m): the exponent ``m`` of the local
        power law ``R_m ~ d^-m`` (Shigley Table 10-4's form). A step table's derivative is zero
        or infinite, so there it is the slope in lg-lg between the neighbouring rows' centres
        (geometric mean of each row's diameters), the table's trend."""
        rm = self.rm
        if rm["kind"] == "steps":
            up = np.asarray(rm["d_upper_mm"], dtype=float) * MM
            lower = np.concatenate([[self.d_min], up[:-1]])
            centre = np.sqrt(np.maximum(lower, up[0] * 0.5) * up)
            lg_c, lg_r = np.log(centre), np.log(np.asarray(rm["Pa"], dtype=float))
            i = int(np.clip(np.searchsorted(lg_c, np.log(d)), 1, len(lg_c) - 1))
            return float(-(lg_r[i] - lg_r[i - 1]) / (lg_c[i] - lg_c[i - 1]))
        h = 1e-4
        r = self.tensile_strength(d * np.exp([-h, h]))
        return float(-np.log(r[1] / r[0]) / (2.0 * h))

    def shear_modulus(self, d):
        """Shear modulus G (Pa) at wire diameter ``d`` (m) (stepwise in d for some grades)."""
        return _stepped(self.G, d)

    def elastic_modulus(self, d):
        """Young's modulus E (Pa) at wire diameter ``d`` (m)."""
        return _stepped(self.E, d)

    def fatigue_diagram(self, peened: bool) -> FatigueDiagram | None:
        """The EN 13906-1 Goodman diagram for this grade, if the data file has one."""
        return self.fatigue.get("peened" if peened else "unpeened")


def _stepped(value, d):
    d = np.asarray(d, dtype=float)
    if isinstance(value, float):
        return np.full(np.shape(d), value)
    uppers = np.array([u for u, _ in value])
    values = np.array([v for _, v in value])
    return values[np.minimum(row_index(uppers, d), len(values) - 1)]


def _moduli(raw, key):
    v = raw[key]
    if isinstance(v, list):
        return tuple((float(u) * MM, float(x) * GPA) for u, x in v)
    return float(v) * GPA


def _rm_spec(raw: dict) -> dict:
    rm = dict(raw)
    kind = rm.get("kind")
    if kind == "table":
        if "ksi" in rm:
            rm["d_mm"] = [x * INCH / MM for x in rm.pop("d_in")]
            rm["Pa"] = [x * KSI for x in rm.pop("ksi")]
        else:
            rm["Pa"] = [x * MPA for x in rm.pop("MPa")]
        if np.any(np.diff(rm["d_mm"]) <= 0) or np.any(np.diff(rm["Pa"]) > 0):
            raise ValueError("R_m table must have rising d and non-rising R_m")
    elif kind == "steps":
        rm["Pa"] = [x * MPA for x in rm.pop("MPa")]
        if (len(rm["Pa"]) != len(rm["d_upper_mm"]) or np.any(np.diff(rm["d_upper_mm"]) <= 0)
                or np.any(np.diff(rm["Pa"]) > 0)):
            raise ValueError("R_m rows must have rising upper diameters and non-rising R_m")
    elif kind not in ("power", "log10", "constant"):
        raise ValueError(f"unknown R_m kind {kind!r}")
    return rm


@cache
def _data() -> dict:
    text = resources.files("govopt").joinpath("data/spring_materials.toml").read_text("utf-8")
    return tomllib.loads(text)


@cache
def materials() -> dict[str, Material]:
    """All grades in the data file, by grade name."""
    out = {}
    for raw in _data()["material"]:
        fatigue = {k: FatigueDiagram(tau_O=tuple(v * MPA for v in f["tau_O"]),
                                     tau_max=tuple(v * MPA for v in f["tau_max"]),
                                     tau_U=tuple(v * MPA for v in f["tau_U"]),
                                     cycles=float(f["cycles"]), source=f["source"])
                   for k, f in raw.get("fatigue", {}).items()}
        out[raw["grade"]] = Material(
            grade=raw["grade"], standard=raw["standard"], family=raw["family"],
            d_min=raw["d_min_mm"] * MM, d_max=raw["d_max_mm"] * MM,
            G=_moduli(raw, "G_GPa"), E=_moduli(raw, "E_GPa"),
            density=float(raw["density_kg_m3"]), rm=_rm_spec(raw["rm"]),
            moduli_source=raw.get("moduli_source", ""), fatigue=fatigue)
    return out


def __getattr__(name: str):
    """``GRADES``, the grade names of the data file, read when first asked for (a spring
    sized from an allowable stress and a modulus reads no grade)."""
    if name == "GRADES":
        return tuple(materials())
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def material(grade: str, *, tensile_strength: float | None = None, G: float | None = None,
             E: float | None = None, density: float | None = None) -> Material:
    """The grade named ``grade`` (e.g. ``"EN10270-1 DH"``), with optional overrides in SI.

    ``tensile_strength`` (Pa) replaces the grade's R_m(d) by a constant (required for
    ``"custom"``, which otherwise carries a placeholder). The grades and each number's source are
    in ``govopt/data/spring_materials.toml``.

    Parameters
    ----------
    grade : str [-]
        A grade of the data file (:data:`GRADES`); an unknown one is a ValueError.
    tensile_strength : float or None [Pa]
        Constant tensile strength R_m replacing the grade's curve.
    G : float or None [Pa]
        Shear modulus replacing the grade's.
    E : float or None [Pa]
        Young's modulus replacing the grade's.
    density : float or None [kg/m^3]
        Density replacing the grade's.

    Returns
    -------
    Material [-]
        The grade, all values SI.

    References
    ----------
    [en10270-1] grades SM, SH, DM, DH; [en10270-2]; [astm-a228] and [shigley] Table 10-4 (the
    Shigley grades).

    Examples
    --------
    Shigley Problem 10-3 (10th ed. solutions manual) prints S_ut = 1936 MPa for music wire of
    2.5 mm; EN 10270-1 DH at 2 mm is ``2220 - 820 lg 2 = 1973 MPa``; a custom wire carries the
    strength given.

    >>> round(float(material("Shigley A228").tensile_strength(2.5e-3)) / 1e6)  # MPa
    1936
    >>> round(float(material("EN10270-1 DH").tensile_strength(2e-3)) / 1e6)  # MPa
    1973
    >>> float(material("custom", tensile_strength=1.6e9).tensile_strength(0.017)) / 1e6
    1600.0
    """
    try:
        mat = materials()[grade]
    except KeyError:
        raise ValueError(f"unknown spring material {grade!r}; "
                         f"known: {', '.join(materials())}") from None
    changes = {k: float(v) for k, v in (("G", G), ("E", E), ("density", density)) if v is not None}
    if tensile_strength is not None:
        changes["rm"] = {"kind": "constant", "MPa": tensile_strength / MPA,
                         "source": "given in the spec"}
    elif grade == "custom":
        raise ValueError("material 'custom' needs its tensile_strength")
    return replace(mat, **changes) if changes else mat


#: where the sizes of a grade no table covers come from (:func:`wire_sizes`)
R20_SOURCE = ("ISO 3 R20 preferred numbers, 1 to 25 mm (the catalogue govopt design uses): no "
              "table of the grade's standard's diameters in govopt/data/wire_sizes.toml")


@cache
def _sizes() -> list[dict]:
    text = resources.files("govopt").joinpath("data/wire_sizes.toml").read_text("utf-8")
    return tomllib.loads(text)["standard"]


def wire_sizes(grade: str | None) -> tuple[tuple[float, ...], str]:
    """The wire diameters (m, rising) a grade is drawn to by its standard, and their source
    (``govopt/data/wire_sizes.toml``); for a grade no table covers (or none), the ISO 3 R20
    preferred numbers of :data:`govopt.inputs.PREFERRED_WIRE` and :data:`R20_SOURCE`.

    Parameters
    ----------
    grade : str or None [-]
        A grade name (matched by the prefixes of the data file's tables), or ``None``.

    Returns
    -------
    tuple of float [m], str [-]
        The diameters and the text naming their source.

    References
    ----------
    [en10270-1] nominal diameters of the example.

    Examples
    --------
    EN 10270-1's diameters between 2.5 and 3.2 mm:

    >>> sizes, source = wire_sizes("EN10270-1 SH")
    >>> [round(x * 1e3, 2) for x in sizes if 2.5e-3 <= x <= 3.2e-3], source[:10]
    ([2.5, 2.6, 2.8, 3.0, 3.2], 'EN 10270-1')
    """
    for std in _sizes():
        if grade is not None and grade.startswith(tuple(std["grades"])):
            sizes = ([x * MM for x in std["d_mm"]] if "d_mm" in std
                     else [x * INCH for x in std["d_in"]])
            return tuple(sorted(sizes)), std["source"]
    from ..inputs import PREFERRED_WIRE

    return tuple(PREFERRED_WIRE), R20_SOURCE


def given(G: float, density: float, E: float | None = None) -> Material:
    """A wire without a grade: a stand-in carrying the shear modulus ``G`` and ``density``
    given (SI) and no tensile strength (R_m nan: the rules that read it cannot be applied);
    its elastic modulus, for buckling and an extension spring's loops, is ``E`` or that of
    ``custom`` (EN 10270-1 steel's 206 GPa).

    govopt's own stand-in (no source defines it); the default E is EN 10270-1 wire's reference
    value as EN 13906-1 lists it.

    Parameters
    ----------
    G : float [Pa]
        Shear modulus of the wire.
    density : float [kg/m^3]
        Density of the wire.
    E : float or None [Pa]
        Young's modulus (``None``: 206 GPa).

    Returns
    -------
    Material [-]
        The stand-in, its tensile strength NaN.

    References
    ----------
    [en13906-1] reference values of EN 10270-1 wire (E = 206 GPa); [en10270-1].

    Examples
    --------
    Hamabe's G = 850000 kg/cm^2 (83.36 GPa) with steel's density, no grade:

    >>> w = given(83.356525e9, 7850.0)
    >>> float(w.E) / 1e9, bool(np.isnan(w.tensile_strength(0.017)))
    (206.0, True)
    """
    custom = materials()["custom"]
    return replace(custom, grade="as given (no wire grade)",
                   standard="shear modulus and allowable stress given",
                   G=float(G), density=float(density), E=custom.E if E is None else float(E),
                   rm={"kind": "constant", "MPa": math.nan, "source": "no wire grade"})


@dataclass(frozen=True)
class Allowable:
    """An allowable static stress rule: ``fraction * R_m``, compared with the stress corrected
    by ``correction`` ("none" or "bergstrasser"), and where the rule comes from."""

    fraction: float
    correction: str
    source: str


def static_rule(mat: Material, place: str, method: str = "EN13906") -> Allowable:
    """The allowable-stress rule for a stress at ``place`` (one of :data:`STRESS_PLACES`).

    EN 13906 rules depend only on R_m (compression 0.5, solid 0.56, extension 0.45 R_m, against
    the uncorrected stress; hooks are not covered there, so they fall back to Shigley's Table
    10-7); Shigley's depend on the material family (Tables 10-6 and 10-7, against K_B tau).

    Parameters
    ----------
    mat : Material [-]
        The wire (its ``family`` chooses Shigley's row).
    place : str [-]
        Where the stress acts, one of :data:`STRESS_PLACES`.
    method : str [-]
        ``"EN13906"`` or ``"Shigley"`` (:data:`METHODS`); anything else is a ValueError.

    Returns
    -------
    Allowable [-]
        The fraction of R_m, the stress correction it is compared with, and the rule's source.

    References
    ----------
    [en13906-1] static stress (0.5 and 0.56 R_m); [en13906-2] (0.45 R_m); [shigley] Tables 10-6
    and 10-7.

    Examples
    --------
    Shigley Problem 10-3 takes 45 % of S_ut for music wire against K_B tau; EN 13906-1 takes
    half of R_m against the uncorrected stress:

    >>> mw = material("Shigley A228")
    >>> r = static_rule(mw, "compression", "Shigley")
    >>> r.fraction, r.correction
    (0.45, 'bergstrasser')
    >>> r = static_rule(mw, "compression")
    >>> r.fraction, r.correction
    (0.5, 'none')
    """
    if method not in METHODS:
        raise ValueError(f"method must be one of {METHODS}, got {method!r}")
    rules = _data()["rules"]
    if method == "EN13906" and place in rules["EN13906"]:
        r = rules["EN13906"][place]
    else:
        family = rules["Shigley"].get(mat.family, rules["Shigley"]["cold_drawn"])
        key = "compression" if place == "solid" else place
        r = family[key]
    return Allowable(float(r["fraction"]), r["correction"], r["source"])


def allowable_static_stress(mat: Material, d, place: str, method: str = "EN13906",
                            override: float | None = None):
    """Allowable static stress (Pa) at wire diameter ``d`` (m): ``fraction * R_m(d)``.

    ``override`` (Pa, e.g. the spec's explicit ``allowable_shear_stress``) wins when given.

    Parameters
    ----------
    mat : Material [-]
        The wire.
    d : float or array [m]
        Wire diameter.
    place : str [-]
        Where the stress acts, one of :data:`STRESS_PLACES`.
    method : str [-]
        ``"EN13906"`` or ``"Shigley"`` (:func:`static_rule`).
    override : float or None [Pa]
        An allowable stress given outright.

    Returns
    -------
    float or array [Pa]
        The allowable stress, shaped like ``d``.

    References
    ----------
    [en13906-1] static stress; [shigley] Table 10-6 and Problem 10-3.

    Examples
    --------
    Shigley Problem 10-3 (10th ed. solutions manual): music wire of 2.5 mm, S_sy = 0.45 x 1936
    = 871.2 MPa as printed; EN 13906-1 for EN 10270-1 DH at 2 mm, 0.5 x 1973.2 MPa.

    >>> mw = material("Shigley A228")
    >>> round(float(allowable_static_stress(mw, 2.5e-3, "compression", "Shigley")) / 1e6, 1)
    871.2
    >>> dh = material("EN10270-1 DH")
    >>> round(float(allowable_static_stress(dh, 2e-3, "compression")) / 1e6, 1)  # 0.5 R_m
    986.6
    """
    if override is not None:
        return np.full(np.shape(d), float(override))
    return static_rule(mat, place, method).fraction * mat.tensile_strength(d)


def ksi_to_pa(x):
    """kpsi to Pa (for worked examples in US units).

    The factor is exact (1 lbf = 4.4482216152605 N, 1 in = 0.0254 m): 6.894757 MPa per kpsi.

    Parameters
    ----------
    x : float or array [kpsi]
        Stress in kpsi.

    Returns
    -------
    float or array [Pa]
        The same stress in Pa.

    References
    ----------
    [shigley] Table 10-5 (its moduli in Mpsi and GPa).

    Examples
    --------
    Shigley Table 10-5 lists hard-drawn wire's G = 11.6 Mpsi as 80.0 GPa and E = 28.7 Mpsi as
    197.9 GPa:

    >>> round(float(ksi_to_pa(11.6e3)) / 1e9, 1), round(float(ksi_to_pa(28.7e3)) / 1e9, 1)
    (80.0, 197.9)
    """
    return np.asarray(x, dtype=float) * KSI


def shigley_A_si(A_kpsi: float, m: float) -> float:
    """Shigley's constant A in MPa mm^m from kpsi in^m: ``A_SI = 6.894757 * 25.4^m * A_US``.

    10th ed. solutions manual, Problem 10-2 (music wire: 2215 MPa mm^m).

    Parameters
    ----------
    A_kpsi : float [kpsi in^m]
        Table 10-4's constant A in US units.
    m : float [-]
        Table 10-4's exponent m, dimensionless.

    Returns
    -------
    float [MPa mm^m]
        The constant in SI units.

    References
    ----------
    [shigley] Table 10-4 (S_ut = A / d^m); 10th ed. solutions manual, Problem 10-2.

    Examples
    --------
    Music wire, A = 201 kpsi in^m, m = 0.145: Problem 10-2 answers 2215 (Table 10-4 prints 2211).

    >>> round(shigley_A_si(201.0, 0.145))
    2215
    """
    return KSI / MPA * (INCH / MM) ** m * A_kpsi


__all__ = ["FatigueDiagram", "Material", "Allowable", "METHODS", "given", "material",
           "wire_sizes",
           "materials", "static_rule", "allowable_static_stress", "ksi_to_pa", "shigley_A_si"]
