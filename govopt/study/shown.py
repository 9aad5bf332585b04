"""The units a person reads a study in: the spec's own.

The database holds figures in SI and inputs as written; ``study show``, the exports and the
plots give each column in the unit the spec itself uses for that quantity (a spec that writes
its speeds in rpm, lengths in cm and loads in kgf reads its study in rpm, cm and kgf), else in
the drawing office's usual unit (mm, rpm, MPa, N/mm, deg), else in SI. The factor of each unit
is the spec's own reading of it (the SI value the parser gave a key over the number written),
so a unit is shown as govopt read it, never guessed again.
"""

from __future__ import annotations

import math
import re
from collections import Counter

_WRITTEN = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s+([^\s+][^+]*?)\s*")

#: where the spec writes no quantity of a kind: SI unit -> (unit shown, SI per unit shown)
USUAL = {"m": ("mm", 1e-3), "rad/s": ("rpm", math.pi / 30.0), "Pa": ("MPa", 1e6),
         "rad": ("deg", math.pi / 180.0), "N/m": ("N/mm", 1e3)}


def spec_units(entries) -> dict[str, tuple[str, float]]:
    """SI unit -> ``(unit, SI per unit)`` the spec writes that kind of quantity in (the most
    used, the first of equals), read from its entries (``Spec.entries``: each input as written
    and in SI).

    >>> from govopt.reader import Entry
    >>> spec_units([Entry("speed.mean", "240 rpm", 25.132741228718345, "rad/s")])
    {'rad/s': ('rpm', 0.10471975511965977)}
    """
    found: dict[str, Counter] = {}
    factor: dict[tuple[str, str], float] = {}
    for e in entries:
        m = _WRITTEN.fullmatch(e.written) if isinstance(e.written, str) else None
        if m is None or not isinstance(e.si, float) or not e.unit:
            continue
        x = float(m[1])
        if x == 0 or not math.isfinite(x) or not math.isfinite(e.si) or e.si == 0:
            continue
        found.setdefault(e.unit, Counter())[m[2]] += 1
        factor.setdefault((e.unit, m[2]), e.si / x)
    return {si: (u, factor[si, u]) for si, counts in found.items()
            for u in [counts.most_common(1)[0][0]]}


class Shown:
    """The unit each column of a study is read in: ``shown(si_unit)`` is ``(unit, SI per
    unit)``."""

    def __init__(self, entries=()):
        self.own = spec_units(entries)

    def __call__(self, si: str) -> tuple[str, float]:
        if si in self.own:
            return self.own[si]
        force, length = self.own.get("N"), self.own.get("m")
        if si == "N/m" and force and length:  # a rate in the spec's force and length
            return f"{force[0]}/{length[0]}", force[1] / length[1]
        if si in ("N*m", "J") and force and length:
            return f"{force[0]}*{length[0]}", force[1] * length[1]
        return USUAL.get(si, (si, 1.0))
