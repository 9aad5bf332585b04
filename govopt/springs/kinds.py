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

Each key is a :class:`govopt.keys.Key` (what the parser reads, the reference and the schema
show); the defaults of the bounds are the fields of :class:`govopt.inputs.Requirements` of the
same names. :data:`FORM` declares the governor spec's ``[spring]`` table, the helical spring's
form for the spring engineering checks (:class:`govopt.inputs.SpringForm`).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..inputs import PREFERRED_WIRE, Requirements, SpringForm
from ..keys import Key, Table
from ..limits import MAX_COMBINATIONS, MAX_SPRINGS, count_error, steps

_REQ, _FORM = Requirements(), SpringForm()


@dataclass(frozen=True)
class SpringKind:
    """One kind of governor spring: its spec keys (:class:`govopt.keys.Key`) and the search's
    catalogue limits."""

    name: str
    #: a helical spring of round wire (shear stress, wire grades, EN 15800 tolerances)
    helical: bool
    #: the ``[design]`` keys of its section, in reading order
    section: tuple[Key, ...]
    #: the section's key an error names when ``[material]`` is missing, and why it is needed
    needs_material: tuple[str, str]
    #: ``[bounds]`` of the section (pairs; defaults: :class:`govopt.inputs.Requirements`)
    bounds: tuple[Key, ...]
    #: the kind's own ``[requirements]`` keys
    requirements: tuple[Key, ...] = ()
    #: the kind's own ``[catalogue]`` keys
    catalogue: tuple[Key, ...] = ()

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


#: a helical spring's section: wire, mean coil radius, active turns (EN 13906-1)
HELICAL_SECTION = (
    Key("wire_diameter", "length", "the wire's diameter d", source="EN 13906-1", example="4 mm"),
    Key("coil_radius", "length", "the coil's mean radius r (half the mean coil diameter)",
        source="EN 13906-1", example="2.4 cm"),
    Key("active_turns", "number", "the active turns n", source="EN 13906-1", example=8.5),
)
HELICAL_BOUNDS = (
    Key("wire_diameter", "length", "the wire diameters searched", shape="pair",
        default=_REQ.wire_diameter),
    Key("coil_radius", "length", "the mean coil radii searched", shape="pair",
        default=_REQ.coil_radius),
    Key("active_turns", "dimensionless", "the active turns searched", shape="pair",
        default=_REQ.active_turns),
)
HELICAL_CATALOGUE = (
    Key("wire_diameters", "length", "the wire diameters the search may use (within "
                                    "bounds.wire_diameter), or \"preferred\": ISO 3 R20 sizes "
                                    "1-25 mm", shape="list", choices=("preferred",),
        default=PREFERRED_WIRE, default_text="\"preferred\" (ISO 3 R20, 1 mm to 25 mm)"),
    Key("turn_step", "number", "the step of the active turns", default=_REQ.turn_step),
    Key("coil_radius_step", "length", "the step of the mean coil radius",
        default=_REQ.coil_radius_step),
)


def _helical(name: str) -> SpringKind:
    return SpringKind(
        name=name, helical=True, section=HELICAL_SECTION,
        needs_material=("wire_diameter", "a spring given by its wire needs a [material] table "
                                         "(or give spring_stiffness)"),
        bounds=HELICAL_BOUNDS, catalogue=HELICAL_CATALOGUE)


#: a leaf's bow over its length within the article's stated range of its chord models (eq. 8)
LEAF = SpringKind(
    name="leaf", helical=False,
    section=(Key("leaf_width", "length", "the leaf's width w", source="article 003, eq. 7"),
             Key("leaf_thickness", "length", "the leaf's thickness t, less than its width",
                 source="article 003, eq. 7")),
    needs_material=("leaf_width", "a leaf given by its section needs a [material] table "
                                  "(or give spring_stiffness)"),
    bounds=(Key("leaf_width", "length", "the leaf widths searched (stock sections within them)",
                shape="pair", default=_REQ.leaf_width),
            Key("leaf_thickness", "length", "the leaf thicknesses searched", shape="pair",
                default=_REQ.leaf_thickness)),
    requirements=(Key("max_bow_ratio", "number", "the largest bow of the leaf over its length "
                                                 "(the article's stated range of its eq. 8)",
                      default=_REQ.max_bow_ratio, high=0.5, source="article 003, eq. 8"),),
    catalogue=(Key("leaf_sections", "choice", "the leaf sections the search may use: "
                                              "\"standard\", the stock list "
                                              "(govopt/data/leaf_stock.csv)",
                   default="standard", choices=("standard",)),))

#: every spring kind by the name a governor type gives it (``Governor.spring``)
KINDS: dict[str, SpringKind] = {
    "compression": _helical("compression"), "tension": _helical("tension"), "leaf": LEAF}


def _end_forms() -> tuple:
    from . import compression as hc

    return tuple(hc.END_FORMS)


def _seatings() -> tuple:
    from . import compression as hc

    return tuple(hc.SEATING)


#: ``[spring]``: the helical spring's form, for the spring engineering checks
#: (:class:`govopt.inputs.SpringForm`)
FORM = Table("spring", "the helical spring's form, for the spring engineering checks (coil "
                       "clash, buckling, hooks)", (
    Key("ends", "choice", "a compression spring's end form (its solid length)",
        default=_FORM.ends, choices=_end_forms, source="EN 13906-1 (solid length)"),
    Key("seating", "choice", "how a compression spring's ends are held (its buckling length)",
        default=_FORM.seating, choices=_seatings, source="EN 13906-1 (buckling)"),
    Key("inactive_turns", "number", "the turns beyond the active ones (n_t = n + this)",
        default=_FORM.inactive_turns, nonnegative=True, source="EN 13906-1"),
    Key("overtravel", "number", "the deflection beyond full lift (an overspeed margin), as a "
                                "fraction of the working stroke", default=_FORM.overtravel,
        nonnegative=True),
    Key("initial_tension", "force", "an extension spring's initial tension", default=None,
        nonnegative=True, default_text="the middle of Shigley's preferred range, at most the "
                                       "least working force"),
    Key("hook_bend_radius", "length", "an extension spring's hook bend radius", default=None,
        default_text="2 d"),
))
