"""Spec files (TOML with units) -> validated, typed, SI-valued spec objects.

Every error is a :class:`SpecError` naming the file, the key path and what was expected; the CLI
prints it on one line and exits with code 2. Unknown keys are errors, so a typo cannot pass
silently. ``Spec.entries`` keeps every input as written and in SI, for reports.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from . import limits
from .errors import DesignError
from .governors import REGISTRY, Governor, governor_class
from .inputs import (
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
from .spec_keys import (
    ANALYSIS,
    SPEED,
    analysis_table,
    bounds_table,
    catalogue_table,
    design_table,
    engine_table,
    governor_table,
    load_change_table,
    material_table,
    requirements_table,
    spec_tables,
)
from .units import G_STANDARD, SI_UNITS


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
    """Validate a spec already read into a dict (keys as in the TOML file): every table read
    by its declaration (:mod:`govopt.spec_keys`, :func:`govopt.spec_keys.spec_tables`)."""
    entries: list[Entry] = []
    top = Reader(file, data, "", entries)
    gov = top.sub("governor")
    gtype = gov.raw("type", True)
    if not isinstance(gtype, str) or gtype not in REGISTRY:
        gov.fail("type", f"expected one of {', '.join(map(repr, REGISTRY))}, got {gtype!r}")
    tables = spec_tables(gtype)
    top.declared = tables[""]
    top.guide = gov.guide = f"docs/reference/spec.md under {gtype}:"
    name = top.read(top.declared.key("name"))
    top.read(top.declared.key("description"))
    name = name or Path(file).stem
    cls = governor_class(gtype)
    gov.declared = governor_table(cls)
    entries.append(Entry("governor.type", gtype, gtype, "", gov.declared.key("type").meaning))
    gov.top = top  # a type may read top-level tables of its own (the shaft's [valve_gear])
    governor = cls.parse(gov)
    kind = governor.spring_kind
    # the speed range to meet: optional where a design is only evaluated (the textbook's "find
    # the equilibrium speeds"); whatever needs it says so
    speed = _speed(top.sub("speed", declared=SPEED), falling=top.has("design")) \
        if top.has("speed") or not top.has("design") else None
    mat = top.sub("material", required=False, declared=material_table())
    material = None if mat is None else _material(mat, kind is None or kind.helical)
    design = _design(top.sub("design", required=False, declared=design_table(governor, kind)),
                     governor, material, band=speed is not None and speed.band)
    eng = top.sub("engine", required=False, declared=engine_table(governor))
    engine = None if eng is None else _engine(eng, governor)
    load_changes = []
    changes = top.tables("load_change", declared=load_change_table(governor))
    if len(changes) > limits.MAX_LOAD_CHANGES:
        top.fail("load_change", limits.count_error(len(changes), limits.MAX_LOAD_CHANGES,
                                                   "load changes"))
    for i, lc in enumerate(changes):
        lc_name = lc.read(lc.declared.key("name")) or f"load change {i + 1}"
        load_changes.append(LoadChange(name=lc_name,
                                       alpha_from=_configuration(lc, "from", governor),
                                       alpha_to=_configuration(lc, "to", governor)))
        lc.finish()

    if load_changes and engine is None:  # never dropped without a word
        top.fail("load_change", "a load change needs [engine] (the flywheel's inertia and the "
                 "engine's torque slope): add [engine], or drop the [[load_change]] tables")
    analysis = _analysis(top.sub("analysis", required=False, declared=analysis_table(governor)))
    if speed is not None:
        analysis = replace(analysis, omega_mean=speed.omega_mean)
    requirements = _requirements(top, governor)
    if requirements is not None and requirements.robust_torque_slope > 0 and engine is None:
        top.sub("requirements").fail("robust_torque_slope", "spreads the engine's torque slope, "
                                     "and there is no [engine]: add [engine], or drop the key")
    too_big = requirements and limits.design_size_error(requirements, analysis.points,
                                                        kind, governor.mass_key)
    if too_big:  # counted before anything is allocated
        top.fail(*too_big)
    form = _spring_form(top.sub("spring", required=False, declared=tables["spring"])) \
        if "spring" in tables else SpringForm()
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


def _material(mat: Reader, helical: bool) -> Material:
    """``[material]``: shear values for a helical spring (or a wire grade), E for a leaf."""
    decl = mat.declared
    grade = _grade(mat, helical)
    v = {}
    for name, need, default in (
            ("allowable_shear_stress", helical and grade is None, None),
            ("shear_modulus", helical and not (grade and grade["G"]), grade and grade["G"]),
            ("density", False, grade["density"] if grade else None),
            ("stress_correction", False, grade["correction"] if grade else None),
            ("elastic_modulus", not helical, None),
            ("allowable_bending_stress", False, None)):
        key = decl.key(name)
        v[name] = mat.read(key, required=need)
        if default is not None and not mat.has(name):
            v[name] = default
    out = Material(**v, **({k: x for k, x in grade.items()
                            if k not in ("G", "density", "correction")} if grade else {}))
    mat.finish()
    return out


def _grade(mat: Reader, helical: bool) -> dict | None:
    """``material.grade`` and the keys that go with it (``tensile_strength``, ``surface``,
    ``tolerance_grade``, ``life_cycles``, ``rules``): Material fields, plus the grade's G and
    density as defaults and the rules' static stress correction (EN 13906-1/-2: uncorrected;
    Shigley: Bergstraesser's K_B; :data:`govopt.springs.helical.DEFAULT_CORRECTION`)."""
    decl = mat.declared
    with_grade = ("tensile_strength", "surface", "tolerance_grade", "life_cycles", "rules")
    if not mat.has("grade"):
        for key in with_grade:
            if mat.has(key):
                mat.fail(key, "belongs with material.grade (a spring wire grade)")
        return None
    from .springs import helical as hx
    from .springs import materials as mt

    grade = mat.read(decl.key("grade"))
    if not helical:
        mat.fail("grade", "wire grades are for helical springs (a leaf takes elastic_modulus "
                          "and allowable_bending_stress)")
    out = {"grade": grade}
    for key in with_grade:
        out[key] = mat.read(decl.key(key), required=key == "tensile_strength" and
                            grade == "custom" or None)
    out["tolerance_grade"] = int(out["tolerance_grade"])
    wire = mt.materials()[grade]
    out["correction"] = hx.DEFAULT_CORRECTION[(out["rules"], "static")]
    out["density"] = wire.density
    out["G"] = wire.G if isinstance(wire.G, float) else None  # stepped in d: give it
    if out["G"] is None and not mat.has("shear_modulus"):
        mat.fail("shear_modulus", f"missing: grade {grade!r} has a shear modulus that varies "
                                  f"with the wire diameter ({wire.moduli_source}); give it")
    return out


def _engine(eng: Reader, governor: Governor) -> Engine:
    """``[engine]``: the flywheel and the torque's slope (negative)."""
    v = eng.read_all(eng.declared)
    if v["torque_slope"] >= 0:
        s_name = governor.coordinate_name if governor.travel == "angle" else "s"
        eng.fail("torque_slope", f"expected dT/d{s_name} < 0 (torque falls as the governor "
                                 "moves out)")
    eng.finish()
    return Engine(flywheel_inertia=v["flywheel_inertia"], torque_slope=v["torque_slope"],
                  insensibility=v["insensibility"],
                  speed_fluctuation_cos=v["speed_fluctuation_E2"],
                  speed_fluctuation_sin=v["speed_fluctuation_F2"])


def _spring_form(sp: Reader | None) -> SpringForm:
    """``[spring]``: the helical spring's form (:class:`SpringForm`)."""
    if sp is None:
        return SpringForm()
    out = SpringForm(**sp.read_all(sp.declared))
    sp.finish()
    return out


def _configuration(rd: Reader, name: str, governor: Governor) -> float:
    """A configuration ``x`` of ``governor`` (an angle or a length, within its range)."""
    x = rd.read(rd.declared.key(name))
    lo, hi = governor.x_inner, governor.x_outer
    if not lo - 1e-12 * abs(hi - lo) <= x <= hi + 1e-12 * abs(hi - lo):
        unit = SI_UNITS[governor.coordinate]
        rd.fail(name, f"expected a configuration within the governor's range "
                      f"[{lo:.6g}, {hi:.6g}] {unit}, got {rd.table[name]!r}")
    return x


def _speed(sp: Reader, falling: bool = False) -> Speed:
    """``[speed]``: the band's ends, or the mean speed and irregularity; ``falling``: an outer
    speed below the inner one is allowed (a governor evaluated, found unstable), else (a design
    search) refused."""
    given = [k for k in ("min", "max", "minimum", "maximum", "low", "high") if sp.has(k)]
    if given and not (sp.has("inner") or sp.has("outer") or sp.has("mean")):
        sp.fail(given[0], "unknown key (did you mean 'inner' and 'outer', the speeds at the "
                          "ends of the range? or 'mean' and 'irregularity')")
    inner, outer, mean, irregularity = SPEED.keys
    if sp.has("inner") or sp.has("outer"):
        for conflicting in ("mean", "irregularity"):
            if sp.has(conflicting):
                sp.fail(conflicting, "give either mean and irregularity, or inner and outer")
        w_in, w_out = sp.read(inner), sp.read(outer)
        if w_out == w_in or (w_out < w_in and not falling):
            sp.fail("outer", "expected outer > inner speed" + (
                "" if w_out == w_in else " (a falling pair is evaluated where [design] gives "
                                         "the governor, not designed for)"))
        if max(w_out, w_in) > limits.MAX_SPEED_RATIO * min(w_out, w_in):
            sp.fail("outer", f"expected at most {limits.MAX_SPEED_RATIO} times speed.inner "
                             f"(govopt's limit), got {w_out / w_in:.4g} times")
        speed = Speed((w_in + w_out) / 2.0, 2.0 * (w_out - w_in) / (w_out + w_in), band=True)
    else:
        speed = Speed(sp.read(mean), sp.read(irregularity))
        if speed.irregularity > limits.MAX_IRREGULARITY:
            sp.fail("irregularity", f"expected at most {limits.MAX_IRREGULARITY:.4g} (the highest "
                                    f"speed at most {limits.MAX_SPEED_RATIO} times the lowest: "
                                    f"govopt's limit), got {speed.irregularity:g}")
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
    decl = ds.declared
    if ds.has("dashpot_f") and ds.has("dashpot_a1"):
        ds.fail("dashpot_a1", "give either dashpot_f (f) or dashpot_a1 (Hamabe's a1 = f/3)")
    dashpot, a1 = ds.read(decl.key("dashpot_f")), ds.read(decl.key("dashpot_a1"))
    spring = {}
    kind = governor.spring_kind
    section = () if kind is None else tuple(decl.key(k.name) for k in kind.section)
    spring_keys = () if kind is None else (
        "spring_stiffness", *(k.name for k in section), governor.free_length_key)
    if kind is not None and band and not any(map(ds.has, spring_keys)):
        pass  # no spring: the one that floats the governor between the band's speeds
    elif kind is not None:
        if ds.has("spring_stiffness"):
            spring["spring_stiffness"] = ds.read(decl.key("spring_stiffness"))
        else:  # the kind's section (a leaf's length is the governor type's)
            if material is None:
                ds.fail(*kind.needs_material)
            spring = {k.name: ds.read(k, required=True) for k in section}
            bad = kind.section_error(spring)
            if bad:
                ds.fail(*bad)
    key = governor.mass_key
    design = Design(
        flying_mass=ds.read(decl.key(key)),
        central_mass=ds.read(decl.key("central")) if governor.central_load else None,
        free_half_length=ds.read(decl.key(governor.free_length_key))
        if governor.spring is not None else None,
        flying_inertia=ds.read(decl.key(f"{key}_inertia")),
        dashpot=3.0 * a1 if a1 is not None else dashpot,
        friction_moment=ds.read(decl.key("friction_moment"))
        if governor.coordinate == "angle" else None,
        **spring,
    )
    ds.finish()
    return design


def _analysis(an: Reader | None) -> Analysis:
    if an is None:
        return Analysis()
    out = Analysis(**an.read_all(an.declared))
    an.finish()
    return out


def read_speed_change(rd: Reader, name: str = "speed_change") -> float | str:
    """``[analysis] speed_change`` (or the option ``--speed-change``, read as a table of one
    key): one declaration, one rule for both (a fraction of the speed in (0, 1), within govopt's
    range, or ``"range"``)."""
    key = ANALYSIS.key("speed_change")
    return rd.read(key if name == key.name else replace(key, name=name))


def _requirements(top: Reader, governor: Governor) -> Requirements | None:
    """``[requirements]``, ``[bounds]`` and ``[catalogue]`` for `govopt design`."""
    kind = governor.spring_kind
    req, bnd, cat = (top.sub(k, required=False, declared=t) for k, t in (
        ("requirements", requirements_table(kind)), ("bounds", bounds_table(governor, kind)),
        ("catalogue", catalogue_table(kind))))
    if req is None and bnd is None and cat is None:
        return None
    kw = {}
    if req is not None:
        kw.update(req.read_all(req.declared))
        req.finish()
    if bnd is not None:
        v = bnd.read_all(bnd.declared)
        kw.update(flying_mass=v.pop(governor.mass_key), dashpot=v.pop("dashpot_f"), **v)
        if "central" in kw:
            kw["central_mass"] = kw.pop("central")
        bnd.finish()
    if cat is not None:
        v = cat.read_all(cat.declared)
        if v.get("wire_diameters") == "preferred":
            v["wire_diameters"] = PREFERRED_WIRE
        elif "wire_diameters" in v:
            v["wire_diameters"] = tuple(sorted(v["wire_diameters"]))
        v.pop("leaf_sections", None)  # one catalogue of stock sections, so far
        kw.update(mass_step=v.pop("weight_step") / G_STANDARD, **v)
        cat.finish()
    return Requirements(**{**Requirements().__dict__, **kw})
