"""Manufacturing tolerances of a tolerance study: each sampled input's scatter around the
spec's nominal value, and the tolerances of a governor made to a quality grade.

The interface the study reads: :class:`Tolerance` (a key, its band and distribution) with
:meth:`Tolerance.draw` (values at uniform fractions), :func:`grade_tolerances` (the tolerance
model of a made governor, :mod:`govopt.analysis.tolerance`, on the spec's keys) and
:func:`nominal` (the spec's value of each toleranced key, in SI). A study samples the unit cube
(:mod:`govopt.study.sampling`) and draws each key's column from it; nothing else in the study
knows how a tolerance is read.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import StudyError
from .quantities import quantity

#: a tolerance band ``+-X`` is read as +-3 standard deviations of a normal scatter truncated at
#: the band (the usual reading of a manufacturing tolerance, a part outside it rejected:
#: :func:`govopt.stats.truncated_normal`), unless ``uniform``
DISTRIBUTIONS = ("normal", "uniform")


@dataclass(frozen=True)
class Tolerance:
    """Manufacturing scatter of one input around the spec's nominal value: a band ``+-half``
    (relative when ``relative``; else in ``unit``), read as +-3 sigma of a normal scatter
    truncated at the band (a part outside its tolerance is rejected) or as uniform."""

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
        sigma 1/3 truncated at +-1 (:func:`govopt.stats.truncated_normal`, by the inverse of its
        distribution function) or uniform in [-1, 1]."""
        from ..stats import truncated_normal

        z = (truncated_normal(u) if self.distribution == "normal"
             else 2.0 * np.asarray(u) - 1.0)
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


def check_bands(spec, tolerances, toml) -> None:
    """Refuse (one line naming the key) a band whose end the spec itself refuses: a part that
    cannot be made (``±200 %`` of a weight or a wire's diameter reaches below zero), read by
    the spec's parser at each end of the band (``toml(key, si)``: the value as the spec
    writes it), so that no sample of the study is an impossible part."""
    from ..errors import GovoptError
    from ..spec import with_values

    for t in tolerances:
        si, unit = nominal(spec, [t])[t.key]
        half = t.half_si(si, unit)
        for end in (si - half, si + half):
            try:
                with_values(spec, {t.key: toml(t.key, end)})
            except GovoptError as exc:
                said = str(exc).removeprefix(f"{spec.path}: ").removeprefix(f"{t.key}: ")
                band = f"±{t.half * 100:g}%" if t.relative else f"±{t.half:g} {t.unit}".strip()
                raise StudyError(f"the band {band} reaches a value the spec refuses ({said}): "
                                 "a part that cannot be made; give a narrower band",
                                 where=f"tolerance {t.key}") from None


def grade_tolerances(spec, grade: int) -> list[Tolerance]:
    """The tolerances of a governor made to EN 15800 quality grade ``grade``, as the tolerance
    model of a made governor states them (:mod:`govopt.analysis.tolerance`: the wire diameter
    after its wire's EN 10270 standard, the mean coil radius ``+-A_D / 2``, a compression
    spring's free length ``+-A_L0``; the masses and the dash-pot where ``[requirements]``
    spreads them), each on the spec's ``[design]`` key, in the model's order: the same points
    as the yield beside the verdict (:mod:`govopt.made`) draws. The spec's design must give its
    free length (:func:`fixed_free_length` writes it where it does not)."""
    from ..analysis import characteristic as chs
    from ..analysis import tolerance as tm
    from ..bulk import design_arrays

    ds = spec.design
    if ds is None or tm.kind(spec) is None or ds.wire_diameter is None or \
            ds.coil_radius is None or ds.active_turns is None:
        designed = "" if ds is not None or tm.kind(spec) is None else (
            "; a spec to design: design it first (govopt design SPEC -o designed.toml) and "
            "study the design")
        raise StudyError("needs a helical spring in [design], given by its section "
                         "(wire_diameter, coil_radius, active_turns): EN 15800's tolerances "
                         "follow from it" + designed, where="tolerance grade")
    req = spec.requirements
    cols = design_arrays(spec, [ds])
    bx = tm.box(spec, cols, grade, 0.0 if req is None else req.robust_masses,
                0.0 if req is None else req.robust_dashpot)
    if not np.all(bx.finite()):
        D = 2.0 * ds.coil_radius
        raise StudyError(f"the spring (d = {ds.wire_diameter:.4g} m, D = {D:.4g} m) is "
                         "outside the EN 15800 / EN 10270 tables", where=f"tolerance grade {grade}")
    out = []
    for name in bx.active():
        key = chs.design_key(spec, name)
        if key is None:
            raise StudyError(f"the spec's [design] does not give its {name.replace('_', ' ')}",
                             where=f"tolerance grade {grade}")
        if name in ("flying_mass", "central_mass", "dashpot"):  # a spread: relative
            frac = req.robust_masses if name != "dashpot" else req.robust_dashpot
            out.append(Tolerance(key, frac, True))
        else:
            out.append(Tolerance(key, float(bx.fields[name][0]), False, "m"))
    return out


def fixed_free_length(data: dict, spec):
    """``(data, spec)`` with the design's free length written where its ``[design]`` leaves it
    out (the one that holds the normal configuration at the mean speed, as evaluated): a made
    spring's free length is a number, the same in every sample of a tolerance study."""
    from ..analysis import statics
    from ..errors import GovoptError
    from ..spec import parse_spec

    gov = spec.governor
    design = data.get("design")
    if gov.spring is None or spec.design is None or not isinstance(design, dict) or \
            gov.free_length_key in design or spec.design.free_half_length is not None:
        return data, spec
    try:
        l0 = float(statics.spring_design(spec, spec.design).l0)
    except GovoptError:
        return data, spec
    data = {**data, "design": {**design, gov.free_length_key: f"{l0!r} m"}}
    return data, parse_spec(data, spec.path)
