"""Manufacturing tolerances of a tolerance study: each sampled input's scatter around the
spec's nominal value, and the spring maker's tolerances of a quality grade.

The interface the study reads: :class:`Tolerance` (a key, its band and distribution) with
:meth:`Tolerance.draw` (values at uniform fractions), :func:`grade_tolerances` (a spec's
helical spring under EN 15800 / EN 10270-1) and :func:`nominal` (the spec's value of each
toleranced key, in SI). A study samples the unit cube (:mod:`govopt.study.sampling`) and
draws each key's column from it; nothing else in the study knows how a tolerance is read.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import StudyError
from .quantities import quantity

#: a tolerance band ``+-X`` is read as +-3 standard deviations of a normal scatter (the usual
#: reading of a manufacturing tolerance: 99.73 % of the parts within it), unless ``uniform``
TOLERANCE_SIGMAS = 3.0
DISTRIBUTIONS = ("normal", "uniform")


@dataclass(frozen=True)
class Tolerance:
    """Manufacturing scatter of one input around the spec's nominal value: a band ``+-half``
    (relative when ``relative``; else in ``unit``), read as +-3 sigma of a normal scatter or
    as uniform."""

    key: str
    half: float
    relative: bool
    unit: str = ""
    distribution: str = "normal"

    @classmethod
    def parse(cls, key: str, text: str) -> Tolerance:
        """``+-X%``, ``±X%``, ``±X unit`` with an optional ``normal`` (default) or ``uniform``
        before it: ``design.wire_diameter=±1%``, ``design.coil_radius=uniform ±0.2 mm``."""
        where = f"tolerance {key}"
        t = str(text).strip()
        dist = "normal"
        for word in DISTRIBUTIONS:
            if t.lower().startswith(word):
                dist, t = word, t[len(word):].strip()
        for sign in ("±", "+/-", "+-"):
            if t.startswith(sign):
                t = t[len(sign):].strip()
                break
        else:
            raise StudyError("expected ±X% or ±X unit (optionally after 'normal' or "
                             f"'uniform'), got {text!r}", where=where)
        if t.endswith("%"):
            try:
                half = float(t[:-1]) / 100.0
            except ValueError:
                raise StudyError(f"cannot read {text!r}", where=where) from None
            out = cls(key, half, True, "", dist)
        else:
            q = quantity(t, where)
            out = cls(key, float(q.magnitude), False, f"{q.units:~}" if not q.unitless else "",
                      dist)
        if not (math.isfinite(out.half) and out.half > 0):
            raise StudyError(f"expected a positive band, got {text!r}", where=where)
        return out

    def half_si(self, nominal_si: float, si_unit: str) -> float:
        """The band's half width in SI (``si_unit``: the key's SI unit)."""
        if self.relative:
            return self.half * abs(nominal_si)
        if not self.unit:
            return self.half
        from ..units import UnitError, convert  # by the spec's rule for units (an angle)

        try:
            return convert(self.half, self.unit, si_unit)
        except UnitError as exc:
            raise StudyError(str(exc), where=f"tolerance {self.key}") from None
        except Exception:  # pint's dimensionality error: a band in the wrong unit
            raise StudyError(f"±{self.half:g} {self.unit} is not a quantity of the key's "
                             f"unit ({si_unit or 'a number'})",
                             where=f"tolerance {self.key}") from None

    def draw(self, nominal_si: float, si_unit: str, u: np.ndarray) -> np.ndarray:
        """Values (SI) at uniform fractions ``u``: ``nominal + band * z`` with ``z`` normal with
        sigma 1/3 (by the inverse normal CDF) or uniform in [-1, 1]."""
        from scipy.special import ndtri

        z = (ndtri(np.clip(u, 1e-12, 1 - 1e-12)) / TOLERANCE_SIGMAS
             if self.distribution == "normal" else 2.0 * np.asarray(u) - 1.0)
        return nominal_si + self.half_si(nominal_si, si_unit) * z


def nominal(spec, tolerances) -> dict[str, tuple[float, str]]:
    """Each toleranced key's nominal value in the spec and its SI unit: ``key -> (si,
    unit)``; a key the spec has no number for is refused (one line naming it)."""
    entries = {e.key: e for e in spec.entries}
    out = {}
    for t in tolerances:
        e = entries.get(t.key)
        if e is None or not isinstance(e.si, float):
            raise StudyError("the spec has no numeric value there (give the key as it is "
                             "written in the spec)", where=f"tolerance {t.key}")
        out[t.key] = (e.si, e.unit)
    return out


def grade_tolerances(spec, grade: int) -> list[Tolerance]:
    """The spring maker's tolerances of the spec's helical spring for EN 15800 quality grade
    ``grade``: the mean coil diameter ``+-A_D`` (Table 1; on the radius ``+-A_D/2``) and the
    wire diameter after EN 10270-1 (:mod:`govopt.springs.tolerances`)."""
    from ..springs import tolerances as tol

    ds = spec.design
    if ds is None or ds.wire_diameter is None or ds.coil_radius is None:
        raise StudyError("needs a helical spring in [design] (wire_diameter, coil_radius)",
                         where="tolerance grade")
    D = 2.0 * ds.coil_radius
    a_d = float(tol.coil_diameter_tolerance(D, D / ds.wire_diameter, grade))
    a_w = float(tol.wire_diameter_tolerance(ds.wire_diameter))
    if not (math.isfinite(a_d) and math.isfinite(a_w)):
        raise StudyError(f"the spring (d = {ds.wire_diameter:.4g} m, D = {D:.4g} m) is "
                         "outside the EN 15800 / EN 10270-1 tables",
                         where=f"tolerance grade {grade}")
    return [Tolerance("design.coil_radius", a_d / 2.0, False, "m"),
            Tolerance("design.wire_diameter", a_w, False, "m")]
