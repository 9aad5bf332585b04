"""Spec files (TOML with units) -> validated, typed, SI-valued spec objects.

Every error is a :class:`SpecError` naming the file, the key path and what was expected; the CLI
prints it on one line and exits with code 2. Unknown keys are errors, so a typo cannot pass
silently. ``Spec.entries`` keeps every input as written and in SI, for reports.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

from . import limits
from .errors import DesignError
from .governors import REGISTRY, Governor, governor_class
from .inputs import (
    OBJECTIVES,
    PREFERRED_WIRE,
    Analysis,
    Design,
    Engine,
    LoadChange,
    Material,
    Requirements,
    Spec,
    Speed,
    SpringForm,
)
from .reader import Entry, Reader, SpecError, read_spec_data
from .units import G_STANDARD, SI_UNITS

ANGLE_RANGE = dict(low=0.0, high=math.pi, range_text="(0 deg, 180 deg)")



def load_spec(path: str | Path, *, max_bytes: int = 1 << 20, max_depth: int = 32) -> Spec:
    """Read and validate a spec file; raises :class:`SpecError` naming file and key.

    The file must be a regular file (a FIFO, device or folder is refused without being read) of
    at most ``max_bytes`` (1 MiB; a spec is a few KiB), UTF-8 text (a leading BOM is allowed)
    and TOML nested at most ``max_depth`` tables/arrays deep (:func:`read_spec_data`).
    """
    return parse_spec(read_spec_data(path, max_bytes=max_bytes, max_depth=max_depth),
                      str(path))


def with_values(spec: Spec, values: dict) -> Spec:
    """The spec re-validated with some inputs replaced: ``values`` maps dotted key paths of
    the TOML (``"speed.irregularity"``, ``"design.pendulum_weight"``, ``"bounds.wire_diameter
    [1]"``, ``"load_change[0].to"``) to values as they would be written in the file
    (``"10 kgf"``, ``0.1``). Missing tables and keys are created; the result is
    :func:`parse_spec` of a copy of :attr:`Spec.data`, so a bad value raises
    :class:`SpecError` naming the key. Changes made with :meth:`Spec.with_design` or
    :meth:`Spec.with_analysis` are not in :attr:`Spec.data` and so not in the result.

    >>> s = parse_spec({"governor": {"type": "watt", "suspension": "axis", "arm": "30 cm",
    ...     "radius_inner": "10 cm", "radius_outer": "20 cm"}, "speed": {"inner": "55 rpm",
    ...     "outer": "64 rpm"}})
    >>> round(with_values(s, {"speed.outer": "66 rpm"}).speed.omega_outer, 4)
    6.9115
    """
    import copy

    if spec.data is None:
        raise SpecError(f"{spec.path}: the spec was not read from TOML: no values to replace")
    data = copy.deepcopy(spec.data)
    for key, value in values.items():
        _set_value(data, key, value, spec.path)
    return parse_spec(data, spec.path)


def _set_value(data: dict, key: str, value, file: str) -> None:
    """Set the dotted path ``key`` (parts ``name`` or ``name[i]``) in ``data``."""
    import re

    parts = key.split(".")
    node = data
    for depth, part in enumerate(parts):
        m = re.fullmatch(r"([^\[\]]+)((?:\[\d+\])*)", part)
        if m is None:
            raise SpecError(f"{file}: {key}: expected a dotted key path like "
                            "'speed.irregularity' or 'load_change[0].to'")
        steps: list = [m[1]] + [int(i) for i in re.findall(r"\[(\d+)\]", m[2])]
        if depth < len(parts) - 1:
            steps.append(None)  # descend into a table
        for i, step in enumerate(steps):
            if step is None:  # the path goes on: this must be a table
                if not isinstance(node, dict):
                    raise SpecError(f"{file}: {key}: {'.'.join(parts[:depth + 1])} is not "
                                    "a table")
                continue
            if not isinstance(node, list if isinstance(step, int) else dict) or (
                    isinstance(step, int) and step >= len(node)):
                raise SpecError(f"{file}: {key}: no {step!r} to replace in the spec")
            if i == len(steps) - 1:
                node[step] = value
            else:
                if isinstance(step, str) and step not in node:
                    node[step] = {}
                node = node[step]


def parse_spec(data: dict, file: str = "<spec>") -> Spec:
    """Validate a spec already read into a dict (keys as in the TOML file)."""
    entries: list[Entry] = []
    top = Reader(file, data, "", entries)
    name = top.text("name", default=Path(file).stem)
    top.text("description")

    gov = top.sub("governor")
    gtype = gov.raw("type", True)
    if not isinstance(gtype, str) or gtype not in REGISTRY:
        gov.fail("type", f"expected one of {', '.join(map(repr, REGISTRY))}, got {gtype!r}")
    entries.append(Entry("governor.type", gtype, gtype, ""))
    gov.top = top  # a type may read top-level tables of its own (the shaft's [valve_gear])
    governor = governor_class(gtype).parse(gov)
    # the speed range to meet: optional where a design is only evaluated (the textbook's "find
    # the equilibrium speeds"); whatever needs it says so
    speed = _speed(top.sub("speed")) if top.has("speed") or not top.has("design") else None

    mat = top.sub("material", required=False)
    material = None
    if mat is not None:
        kind = governor.spring_kind
        helical = kind is None or kind.helical  # shear values for a wire, E for a leaf
        grade = _grade(mat, helical)
        material = Material(
            allowable_shear_stress=mat.quantity("allowable_shear_stress", "stress",
                                                required=helical and grade is None),
            shear_modulus=mat.quantity("shear_modulus", "stress",
                                       required=helical and not (grade and grade["G"]),
                                       default=grade and grade["G"]),
            density=mat.quantity("density", "density", required=False,
                                 default=grade["density"] if grade else 7850.0),
            stress_correction=mat.choice("stress_correction", ("none", "wahl", "bergstrasser"),
                                         grade["correction"] if grade else "none"),
            elastic_modulus=mat.quantity("elastic_modulus", "stress", required=not helical),
            allowable_bending_stress=mat.quantity("allowable_bending_stress", "stress",
                                                  required=False),
            **({k: v for k, v in grade.items() if k not in ("G", "density", "correction")}
               if grade else {}),
        )
        mat.finish()

    design = _design(top.sub("design", required=False), governor, material,
                     band=speed is not None and speed.band)
    eng = top.sub("engine", required=False)
    engine = None
    if eng is not None:
        per = "angle" if governor.travel == "angle" else "length"
        engine = Engine(
            flywheel_inertia=eng.quantity("flywheel_inertia", "inertia"),
            torque_slope=eng.quantity("torque_slope", f"torque_per_{per}", positive=False),
            insensibility=eng.number("insensibility", required=False, default=0.0,
                                     nonnegative=True, high=1.0),
            speed_fluctuation_cos=eng.quantity("speed_fluctuation_E2", "angular_velocity",
                                               required=False, default=0.0, positive=False),
            speed_fluctuation_sin=eng.quantity("speed_fluctuation_F2", "angular_velocity",
                                               required=False, default=0.0, positive=False),
        )
        if engine.torque_slope >= 0:
            s_name = governor.coordinate_name if per == "angle" else "s"
            eng.fail("torque_slope", f"expected dT/d{s_name} < 0 (torque falls as the governor "
                                     "moves out)")
        eng.finish()

    load_changes = []
    changes = top.tables("load_change")
    if len(changes) > limits.MAX_LOAD_CHANGES:
        top.fail("load_change", limits.count_error(len(changes), limits.MAX_LOAD_CHANGES,
                                                   "load changes"))
    for i, lc in enumerate(changes):
        load_changes.append(LoadChange(
            name=lc.text("name", default=f"load change {i + 1}"),
            alpha_from=_configuration(lc, "from", governor),
            alpha_to=_configuration(lc, "to", governor),
        ))
        lc.finish()

    analysis = _analysis(top.sub("analysis", required=False))
    if speed is not None:
        analysis = replace(analysis, omega_mean=speed.omega_mean)
    requirements = _requirements(top, governor)
    too_big = requirements and limits.design_size_error(requirements, analysis.points,
                                                        governor.spring_kind, governor.mass_key)
    if too_big:  # counted before anything is allocated
        top.fail(*too_big)
    form = _spring_form(top.sub("spring", required=False))
    top.raw("study", False)  # a trade study's own table (govopt.study reads it)
    top.finish()
    spec = Spec(file, name, gtype, governor, speed, material, design, engine,
                tuple(load_changes), analysis, requirements, tuple(entries), data=data,
                spring_form=form)
    if design is not None and governor.spring is not None and design.spring_stiffness is None \
            and design.wire_diameter is None and design.leaf_width is None:
        spec = band_spring(spec)
    return spec


def band_spring(spec: Spec) -> Spec:
    """The spec with the spring that makes its governor float between the band's two speeds:
    at the innermost configuration in equilibrium at ``speed.inner`` and at the outermost at
    ``speed.outer`` (the textbook's question, ch. 3, Examples 4 and 8: "find the initial load
    on the sleeve and the spring's stiffness"; Hamabe, Example 1, ``kappa = (F_a - F_i) /
    (2 (l_a - l_i))``): two linear equations in ``kappa`` and ``kappa l0``
    (:func:`govopt.analysis.statics.band_spring`). Friction is not in them: with a friction
    band the governor's own band is wider than the spec's by it. Raises :class:`SpecError`
    where no spring does it, saying why (:func:`govopt.analysis.statics.band_spring`)."""
    from .analysis import statics

    ds = spec.design
    try:
        kappa, l0, f_inner, f_outer = statics.band_spring(spec, ds.flying_mass,
                                                          ds.central_mass or 0.0)
    except DesignError as exc:  # the reason is the statics' (a band no spring can give)
        raise SpecError(f"{spec.path}: design: no spring given, and none floats the governor "
                        f"between speed.inner and speed.outer: {exc}; or give "
                        "spring_stiffness") from None
    design = replace(ds, spring_stiffness=kappa, free_half_length=l0)
    found = {"stiffness": kappa, "free_length": l0, "force_inner": f_inner,
             "force_outer": f_outer}
    return replace(spec, design=design, band_spring=found)


def _grade(mat: Reader, helical: bool) -> dict | None:
    """``material.grade`` and the keys that go with it (``tensile_strength``, ``surface``,
    ``tolerance_grade``, ``life_cycles``, ``rules``): Material fields, plus the grade's G and
    density as defaults and the rules' static stress correction (EN 13906-1/-2: uncorrected;
    Shigley: Bergstraesser's K_B; :data:`govopt.springs.helical.DEFAULT_CORRECTION`)."""
    if not mat.has("grade"):
        for key in ("tensile_strength", "surface", "tolerance_grade", "life_cycles", "rules"):
            if mat.has(key):
                mat.fail(key, "belongs with material.grade (a spring wire grade)")
        return None
    from .springs import helical as hx
    from .springs import materials as mt

    grade = mat.choice("grade", mt.GRADES, None)
    if not helical:
        mat.fail("grade", "wire grades are for helical springs (a leaf takes elastic_modulus "
                          "and allowable_bending_stress)")
    out = dict(grade=grade, tensile_strength=mat.quantity("tensile_strength", "stress",
                                                          required=grade == "custom"),
               surface=mat.choice("surface", ("not shot peened", "shot peened"),
                                  "not shot peened"),
               tolerance_grade=int(mat.choice("tolerance_grade", (1, 2, 3), 2)),
               life_cycles=mat.number("life_cycles", required=False, default=1e7, low=1.0),
               rules=mat.choice("rules", mt.METHODS, "EN13906"))
    wire = mt.materials()[grade]
    out["correction"] = hx.DEFAULT_CORRECTION[(out["rules"], "static")]
    out["density"] = wire.density
    out["G"] = wire.G if isinstance(wire.G, float) else None  # stepped in d: give it
    if out["G"] is None and not mat.has("shear_modulus"):
        mat.fail("shear_modulus", f"missing: grade {grade!r} has a shear modulus that varies "
                                  f"with the wire diameter ({wire.moduli_source}); give it")
    return out


def _spring_form(sp: Reader | None) -> SpringForm:
    """``[spring]``: the helical spring's form (:class:`SpringForm`)."""
    if sp is None:
        return SpringForm()
    from .springs import helical as hx

    d = SpringForm()
    out = SpringForm(
        ends=sp.choice("ends", tuple(hx.END_FORMS), d.ends),
        seating=sp.choice("seating", tuple(hx.SEATING), d.seating),
        inactive_turns=sp.number("inactive_turns", required=False, default=d.inactive_turns,
                                 nonnegative=True),
        overtravel=sp.number("overtravel", required=False, default=d.overtravel,
                             nonnegative=True),
        initial_tension=sp.quantity("initial_tension", "force", required=False,
                                    nonnegative=True),
        hook_bend_radius=sp.quantity("hook_bend_radius", "length", required=False),
    )
    sp.finish()
    return out


def _configuration(rd: Reader, name: str, governor: Governor) -> float:
    """A configuration ``x`` of ``governor`` (an angle or a length, within its range)."""
    if governor.coordinate == "angle":
        x = rd.quantity(name, "angle", **ANGLE_RANGE)
    else:
        x = rd.quantity(name, governor.coordinate)
    lo, hi = governor.x_inner, governor.x_outer
    if not lo - 1e-12 * abs(hi - lo) <= x <= hi + 1e-12 * abs(hi - lo):
        unit = SI_UNITS[governor.coordinate]
        rd.fail(name, f"expected a configuration within the governor's range "
                      f"[{lo:.6g}, {hi:.6g}] {unit}, got {rd.table[name]!r}")
    return x


def _speed(sp: Reader) -> Speed:
    given = [k for k in ("min", "max", "minimum", "maximum", "low", "high") if sp.has(k)]
    if given and not (sp.has("inner") or sp.has("outer") or sp.has("mean")):
        sp.fail(given[0], "unknown key (did you mean 'inner' and 'outer', the speeds at the "
                          "ends of the range? or 'mean' and 'irregularity')")
    if sp.has("inner") or sp.has("outer"):
        for conflicting in ("mean", "irregularity"):
            if sp.has(conflicting):
                sp.fail(conflicting, "give either mean and irregularity, or inner and outer")
        inner = sp.quantity("inner", "angular_velocity")
        outer = sp.quantity("outer", "angular_velocity")
        if outer <= inner:
            sp.fail("outer", "expected outer > inner speed")
        speed = Speed((inner + outer) / 2.0, 2.0 * (outer - inner) / (outer + inner),
                      band=True)
    else:
        speed = Speed(sp.quantity("mean", "angular_velocity"),
                      sp.number("irregularity", high=2.0))
    sp.finish()
    return speed


def _design(ds: Reader | None, governor: Governor, material: Material | None,
            band: bool = False) -> Design | None:
    """``[design]``: the flying mass (``<mass_key>_weight`` or ``_mass``), the central load, the
    spring (``wire_diameter``, ``coil_radius``, ``active_turns`` with ``[material]``, or
    ``spring_stiffness``; the free length under the type's key), dash-pot and friction. With
    a speed band (``band``) the spring may be left out: :func:`band_spring` finds it."""
    if ds is None:
        return None
    angular = governor.coordinate == "angle"
    damping = "damping" if angular else "linear_damping"
    if ds.has("dashpot_f") and ds.has("dashpot_a1"):
        ds.fail("dashpot_a1", "give either dashpot_f (f) or dashpot_a1 (Hamabe's a1 = f/3)")
    dashpot = ds.quantity("dashpot_f", damping, required=False, nonnegative=True)
    a1 = ds.quantity("dashpot_a1", damping, required=False, nonnegative=True)
    spring = {}
    kind = governor.spring_kind
    spring_keys = () if kind is None else (
        "spring_stiffness", *(key for key, _ in kind.section), governor.free_length_key)
    if kind is not None and band and not any(map(ds.has, spring_keys)):
        pass  # no spring: the one that floats the governor between the band's speeds
    elif kind is not None:
        if ds.has("spring_stiffness"):
            spring["spring_stiffness"] = ds.quantity("spring_stiffness", "stiffness")
        else:  # the kind's section (a leaf's length is the governor type's)
            if material is None:
                ds.fail(*kind.needs_material)
            spring = {key: ds.number(key) if dim is None else ds.quantity(key, dim)
                      for key, dim in kind.section}
            bad = kind.section_error(spring)
            if bad:
                ds.fail(*bad)
    key = governor.mass_key
    design = Design(
        flying_mass=ds.weight_or_mass(key),
        central_mass=ds.weight_or_mass("central", required=False),
        free_half_length=ds.quantity(governor.free_length_key, "length", required=False,
                                     positive=governor.free_length_positive)
        if governor.spring is not None else None,
        flying_inertia=ds.quantity(f"{key}_inertia", "inertia" if angular else "mass",
                                     required=False),
        dashpot=3.0 * a1 if a1 is not None else dashpot,
        friction_moment=ds.quantity("friction_moment", "moment", required=False,
                                    nonnegative=True) if angular else None,
        **spring,
    )
    ds.finish()
    return design


def _analysis(an: Reader | None) -> Analysis:
    from .fidelity import USE_CASES

    if an is None:
        return Analysis()
    out = Analysis(
        geometry=an.choice("geometry", ("exact", "series"), "exact"),
        reaction_speed=an.choice("reaction_speed", ("local", "mean"), "local"),
        reaction_slope=an.boolean("reaction_slope", True),
        valve_table=an.choice("valve_table", ("pchip", "cubic", "linear"), "pchip"),
        points=an.number("points", required=False, default=31, low=2,
                         high=limits.MAX_POINTS + 1, integer=True,
                         range_text=f"[3, {limits.MAX_POINTS}] (govopt's limit)"),
        harmonics=an.number("harmonics", required=False, default=12, low=0,
                            high=limits.MAX_HARMONICS + 1, integer=True,
                            range_text=f"[1, {limits.MAX_HARMONICS}] (govopt's limit)"),
        settling_band=an.number("settling_band", required=False, default=0.02, high=1.0),
        use_case=an.choice("use_case", tuple(USE_CASES), None),
        tolerance=an.number("tolerance", required=False, default=1e-6, high=1.0),
        speed_change=read_speed_change(an),
    )
    an.finish()
    return out


def read_speed_change(rd: Reader, name: str = "speed_change") -> float | str:
    """``[analysis] speed_change`` (or the option ``--speed-change``, read as a table of one
    key: one rule for both): a fraction of the speed in (0, 1), within govopt's range, or
    ``"range"``; default 0.01."""
    text = "(0, 1) (a fraction of the speed, e.g. 0.01), or \"range\""
    value = rd.table.get(name)
    if isinstance(value, str) and value != "range":
        rd.fail(name, "expected a fraction of the speed in (0, 1), e.g. 0.01, or \"range\", "
                f"got {limits.shorten(value)}")
    if isinstance(value, str):
        return rd.choice(name, ("range",), "range")
    return rd.number(name, required=False, default=0.01, high=1.0, range_text=text)


def _pair(rd: Reader, name, dimension, default):
    """A ``[low, high]`` bound; a bare number list for dimensionless."""
    value = rd.raw(name, False)
    if value is None:
        return default
    if not isinstance(value, list) or len(value) != 2:
        rd.fail(name, f"expected [low, high], got {value!r}")
    if dimension == "dimensionless":
        sub = Reader(rd.file, {"low": value[0], "high": value[1]}, rd.key(name), rd.entries)
        lo, hi = sub.number("low"), sub.number("high")
    else:
        lo, hi = rd.quantities(name, dimension)
    if not lo < hi:
        rd.fail(name, f"expected low < high, got {value!r}")
    return (float(lo), float(hi))


def _mass_pair(rd: Reader, stem: str, default, single: bool = False):
    """Bounds ``<stem>_weight = [lo, hi]`` (forces) or ``<stem>_mass``; with ``single`` one
    value fixes it (a spring governor's sleeve load)."""
    w, m = f"{stem}_weight", f"{stem}_mass"
    if rd.has(w) and rd.has(m):
        rd.fail(w, f"give either {w} or {m}, not both")
    name, dim, scale = (w, "force", G_STANDARD) if rd.has(w) else (m, "mass", 1.0)
    if single and rd.has(name) and not isinstance(rd.table[name], list):
        value = rd.quantity(name, dim, nonnegative=True) / scale
        return (value, value)
    pair = _pair(rd, name, dim, None)
    return default if pair is None else (pair[0] / scale, pair[1] / scale)


def _requirements(top: Reader, governor: Governor) -> Requirements | None:
    """``[requirements]``, ``[bounds]`` and ``[catalogue]`` for `govopt design`."""
    req, bnd, cat = (top.sub(k, required=False) for k in ("requirements", "bounds", "catalogue"))
    if req is None and bnd is None and cat is None:
        return None
    d = Requirements()
    kind = governor.spring_kind
    kw = {}
    if req is not None:
        kw.update(
            objective=req.choice("objective", OBJECTIVES, d.objective),
            k2_margin=req.number("k2_margin", required=False, default=d.k2_margin,
                                 nonnegative=True, high=0.5),
            hurwitz_margin=req.number("hurwitz_margin", required=False,
                                      default=d.hurwitz_margin, nonnegative=True),
            max_settling_time=req.quantity("max_settling_time", "time", required=False),
            max_vibration=req.quantity("max_vibration", "angle", required=False),
            spring_index=_pair(req, "spring_index", "dimensionless", d.spring_index),
            max_outer_diameter=req.quantity("max_outer_diameter", "length", required=False),
            min_surge_frequency=req.quantity("min_surge_frequency", "frequency",
                                             required=False),
            min_fatigue_safety=req.number("min_fatigue_safety", required=False),
            surge_detuning=req.number("surge_detuning", required=False,
                                      default=d.surge_detuning, nonnegative=True),
            robust_spring_grade=req.number("robust_spring_grade", required=False, low=0.5,
                                           high=3.5, integer=True, range_text="1, 2 or 3"),
            robust_dashpot=req.number("robust_dashpot", required=False, default=0.0,
                                      nonnegative=True, high=0.5),
            robust_masses=req.number("robust_masses", required=False, default=0.0,
                                     nonnegative=True, high=0.5),
            robust_torque_slope=req.number("robust_torque_slope", required=False, default=0.0,
                                           nonnegative=True, high=0.5),
            adjusting_nut=req.quantity("adjusting_nut", "length", required=False, default=0.0,
                                       nonnegative=True),
            dashpot_valve=req.number("dashpot_valve", required=False, default=0.0,
                                     nonnegative=True, high=0.9),
            robust_samples=req.number("robust_samples", required=False,
                                      default=d.robust_samples, low=9,
                                      high=limits.MAX_ROBUST_SAMPLES + 1, integer=True,
                                      range_text=f"[10, {limits.MAX_ROBUST_SAMPLES}]"),
            robust_seed=req.number("robust_seed", required=False, default=d.robust_seed,
                                   nonnegative=True, integer=True),
        )
        for key, high in kind.requirement_numbers if kind is not None else ():
            kw[key] = req.number(key, required=False, default=getattr(d, key), high=high)
        req.finish()
    if bnd is not None:
        mk = governor.mass_key
        kw.update(
            flying_mass=_mass_pair(bnd, mk, d.flying_mass),
            central_mass=_mass_pair(bnd, "central", d.central_mass, single=True),
            dashpot=_pair(bnd, "dashpot_f", "damping" if governor.coordinate == "angle"
                          else "linear_damping", None),
        )
        for key, dim in kind.bounds if kind is not None else ():
            kw[key] = _pair(bnd, key, dim, getattr(d, key))
        bnd.finish()
    if cat is not None:
        for key, choices, default in kind.catalogue_choices if kind is not None else ():
            cat.choice(key, choices, default)
        wires = cat.raw("wire_diameters", False)
        kw.update(
            wire_diameters=PREFERRED_WIRE if wires in (None, "preferred")
            else tuple(sorted(cat.quantities("wire_diameters", "length"))),
            turn_step=cat.number("turn_step", required=False, default=d.turn_step),
            coil_radius_step=cat.quantity("coil_radius_step", "length", required=False,
                                          default=d.coil_radius_step),
            mass_step=cat.quantity("weight_step", "force", required=False,
                                   default=d.mass_step * G_STANDARD) / G_STANDARD,
        )
        cat.finish()
    return Requirements(**{**d.__dict__, **kw})
