"""The spring as a plug: each kind of governor spring declares, in one place, what a spec gives
for it and what the design search may choose - its ``[design]`` section, its ``[bounds]``, its
own ``[requirements]`` and ``[catalogue]`` keys and its catalogue's size limits. The spec parser,
the size limits and the robust search read these declarations, so no code outside the spring's
own asks which kind of spring it has.

Kinds (:data:`KINDS`, keyed by :attr:`govopt.governors.base.Governor.spring`):

* ``"compression"``, ``"tension"``: a helical spring of round wire, given by ``wire_diameter``
  ``d``, mean ``coil_radius`` ``r`` and ``active_turns`` ``n`` (Hamabe Ex. 1; EN 13906-1/-2),
  of a ``[material]`` with a shear modulus (or a wire grade);
* ``"leaf"``: a flat strip of ``leaf_width`` x ``leaf_thickness`` whose length and ends are the
  governor's (the traction engine's leaf, :mod:`govopt.springs.leaf`), of a ``[material]`` with
  an elastic modulus.

Defaults of the bounds are the fields of :class:`govopt.inputs.Requirements` of the same names.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..limits import MAX_COMBINATIONS, MAX_SPRINGS, count_error, steps


@dataclass(frozen=True)
class SpringKind:
    """One kind of governor spring: its spec keys and the search's catalogue limits."""

    name: str
    #: a helical spring of round wire (shear stress, wire grades, EN 15800 tolerances)
    helical: bool
    #: the ``[design]`` keys of its section, in reading order: (key, dimension); ``None`` for a
    #: bare number (a count)
    section: tuple[tuple[str, str | None], ...]
    #: the section's key an error names when ``[material]`` is missing, and why it is needed
    needs_material: tuple[str, str]
    #: ``[bounds]`` of the section: (key, dimension; "dimensionless" for a bare pair)
    bounds: tuple[tuple[str, str], ...]
    #: the kind's own ``[requirements]`` numbers: (key, upper limit, exclusive)
    requirement_numbers: tuple[tuple[str, float], ...] = ()
    #: the kind's own ``[catalogue]`` choices: (key, choices, default)
    catalogue_choices: tuple[tuple[str, tuple[str, ...], str], ...] = ()

    def section_error(self, values: dict) -> tuple[str, str] | None:
        """``(key, message)`` when the section read from ``[design]`` cannot be built, else
        None: a wire at least as thick as the coil's diameter ``2 r``; a strip at least as
        thick as it is wide."""
        if self.helical:
            if values["wire_diameter"] >= 2.0 * values["coil_radius"]:
                return "wire_diameter", "expected a wire thinner than the coil diameter 2 r"
        elif values["leaf_thickness"] >= values["leaf_width"]:
            return "leaf_thickness", "expected a strip thinner than it is wide"
        return None

    def size_errors(self, req, weight_pairs: float) -> list[tuple[str, str | None]]:
        """The kind's catalogue sizes against govopt's limits, as ``(key, message or None)``,
        counted from ``req``'s bounds and steps (:class:`govopt.inputs.Requirements`) before a
        grid is built; ``weight_pairs``: the flying x central weight grid's size. A leaf's
        catalogue is the stock list (``govopt/data/leaf_stock.csv``): nothing to count."""
        if not self.helical:
            return []
        wires = sum(req.wire_diameter[0] - 1e-12 <= w <= req.wire_diameter[1] + 1e-12
                    for w in req.wire_diameters)
        radii = steps(*req.coil_radius, req.coil_radius_step)
        turns = steps(*req.active_turns, req.turn_step)
        springs = wires * radii * turns
        return [
            ("catalogue.coil_radius_step", count_error(radii, MAX_SPRINGS,
                                                        "coil radii within bounds.coil_radius")),
            ("catalogue.turn_step", count_error(turns, MAX_SPRINGS,
                                                 "turns within bounds.active_turns")),
            ("catalogue", count_error(springs, MAX_SPRINGS, "springs (wire diameters x coil "
                                                            "radii x turns within the bounds)")),
            ("catalogue", count_error(springs * weight_pairs, MAX_COMBINATIONS,
                                      "weight pairs x springs")),
        ]


def _helical(name: str) -> SpringKind:
    return SpringKind(
        name=name, helical=True,
        section=(("wire_diameter", "length"), ("coil_radius", "length"), ("active_turns", None)),
        needs_material=("wire_diameter", "a spring given by its wire needs a [material] table "
                                         "(or give spring_stiffness)"),
        bounds=(("wire_diameter", "length"), ("coil_radius", "length"),
                ("active_turns", "dimensionless")))


#: a leaf's bow over its length within the article's stated range of its chord models (eq. 8)
LEAF = SpringKind(
    name="leaf", helical=False,
    section=(("leaf_width", "length"), ("leaf_thickness", "length")),
    needs_material=("leaf_width", "a leaf given by its section needs a [material] table "
                                  "(or give spring_stiffness)"),
    bounds=(("leaf_width", "length"), ("leaf_thickness", "length")),
    requirement_numbers=(("max_bow_ratio", 0.5),),
    catalogue_choices=(("leaf_sections", ("standard",), "standard"),))

#: every spring kind by the name a governor type gives it (``Governor.spring``)
KINDS: dict[str, SpringKind] = {
    "compression": _helical("compression"), "tension": _helical("tension"), "leaf": LEAF}
