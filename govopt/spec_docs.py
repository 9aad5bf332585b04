"""What a person reads about the spec file, generated from the key declarations
(:mod:`govopt.keys`, :func:`govopt.spec_keys.spec_tables`), never typed twice:

* :func:`reference`: ``docs/reference/spec.md``, every table and key of every governor type
  with its meaning, unit, default, allowed range and source. Regenerate it with
  ``python -m govopt.spec_docs docs/reference/spec.md`` (a test fails when it is stale);
* :func:`template`: the spec ``govopt init --type TYPE`` writes: every table and key, commented,
  with the values of the type's bundled design example (``Governor.example``), so that
  ``govopt design`` runs it as written.
"""

from __future__ import annotations

import json
import math
import os
import re
import sys
import textwrap
import tomllib
from collections.abc import Collection

from .keys import WEIGHT, Key, Table
from .references import REFERENCES, found_in
from .units import SI_UNITS

#: what a quantity of each dimension looks like in a spec, for the templates' commented keys
#: without an example of their own
EXAMPLES = {
    "length": "10 cm", "angle": "60 deg", "force": "10 kgf", "mass": "1 kg",
    "stress": "400 MPa", "angular_velocity": "240 rpm", "moment": "20 kgf*cm",
    "inertia": "40 kgf*m*s^2", "torque_per_angle": "-300 kgf*m/rad",
    "torque_per_length": "-50 kgf*m/cm", "linear_damping": "0.5 kgf*s/cm",
    "density": "7850 kg/m^3", "damping": "70 kgf*cm*s/rad", "time": "2 s",
    "frequency": "40 Hz", "stiffness": "50 kgf/cm",
}

#: the words for a key's kind in the reference
KIND_WORDS = {"number": "number", "count": "whole number", "choice": "choice", "text": "text",
              "flag": "true or false", "table": "table", "dimensionless": "number"}

INTRO = """\
# Spec file reference

Generated from the declarations of the keys in the code (`python -m govopt.spec_docs
docs/reference/spec.md` writes this file; a test fails when it is stale): do not edit it by
hand. `govopt init --type TYPE` writes a commented spec of a type with every key;
`govopt schema` writes the JSON Schema editors read for completion and checking. The spring
spec files of `govopt spring` and `govopt spring check` have their own page:
[spring-spec.md](spring-spec.md).

A spec is a TOML file. A quantity is a string with its unit, in any unit of its dimension
(`"18 cm"`, `"240 rpm"`, `"4000 kgf/cm^2"`, `"64 deg + 40 arcmin"`); govopt works in SI inside,
and the columns below give the SI unit. A *weight* key comes in two spellings, `<stem>_weight`
(a force, turned into a mass with standard gravity) or `<stem>_mass`: give one. A *number* is
a bare TOML number; a *whole number* a count. A search bound `[low, high]` with equal ends
fixes the value. A key not declared here is an error.

Defaults: a key with a default may be left out; *required* keys must be given (some only in
the configuration the meaning says). `[bounds]` are the search's bounds only, not requirements
of a made part: a design is not checked against them.
"""


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def kind_words(key: Key) -> str:
    if key.kind == WEIGHT:
        words = "weight (force) or mass (N or kg)"
    elif key.quantity:
        words = f"{key.kind.replace('_', ' ')} ({key.unit})"
    else:
        words = KIND_WORDS[key.kind]
    if key.shape == "pair":
        words = f"[low, high] of {words}"
    elif key.shape == "list":
        words = f"list of {words}"
    return words


def _key_names(key: Key) -> str:
    return " or ".join(f"`{n}`" for n in key.names)


def table_markdown(table: Table, heading: str, borrowed: Collection[str] = ()) -> list[str]:
    """One table's section of the reference: its meaning and a row per key (``borrowed``:
    :func:`source_words`)."""
    lines = [heading, "", table.meaning[0].upper() + table.meaning[1:] + "."]
    if table.when:
        lines[-1] += f" {table.when[0].upper()}{table.when[1:]}."
    if table.array:
        lines[-1] += f" An array of tables: `[[{table.name}]]`, one per item."
    if table.open:
        lines += ["", "Its keys are read by the command that uses it."]
        return lines + [""]
    lines += ["", "| key | meaning | kind (SI unit) | default | allowed | source |",
              "|---|---|---|---|---|---|"]
    for key in table.keys:
        when = f" ({key.when})" if key.kind == "table" else f" (applies {key.when})"
        meaning = key.meaning + (when if key.when else "")
        lines.append("| " + " | ".join(_cell(c) for c in (
            _key_names(key), meaning, kind_words(key),
            "required" if key.required else key.default_words(), key.range_words(),
            source_words(key.source, borrowed))) + " |")
    return lines + [""]


def reference() -> str:
    """``docs/reference/spec.md``: the tables every type shares word for word once, then each
    type's own (its ``[governor]``, and the shared tables its coordinate, flying mass or spring
    changes: ``[design]``, ``[bounds]`` ...), with their keys, defaults and ranges."""
    from .governors import REGISTRY, governor_class
    from .spec_keys import spec_tables

    types = list(REGISTRY)
    every = {t: spec_tables(t) for t in types}
    borrowed = {t: borrowed_sources(t) for t in types}
    names = list(dict.fromkeys(n for t in types for n in every[t]))
    shared = [n for n in names if n and all(n in every[t] for t in types)
              and len({tuple(table_markdown(every[t][n], "", borrowed[t]))
                       for t in types}) == 1]
    out = [INTRO, "## Contents", ""]
    out += [f"- [{t}](#{t}): {governor_class(t).title}" for t in types]
    out += ["- [Tables every type shares](#tables-every-type-shares): "
            + ", ".join(f"`[{n}]`" for n in shared), ""]
    for t in types:
        cls = governor_class(t)
        out += [f"## {t}", "", f"{cls.title}. `govopt init --type {t}` writes a spec of it "
                f"with every key (its values from the bundled `{cls.example}`)."
                + _spring_words(cls), ""]
        for n in names:
            if n in every[t] and n not in shared:
                title = f"[[{n}]]" if every[t][n].array else f"[{n}]" if n else "top level"
                out += table_markdown(every[t][n], f"### {t}: {title}", borrowed[t])
        out.append("Shared: " + ", ".join(f"[`[{n}]`](#{_anchor(n)})" for n in shared
                                          if n in every[t]) + ".")
        out.append("")
    out += ["## Tables every type shares", ""]
    for n in shared:
        out += table_markdown(every[types[0]][n], f"### [{n}]")
    return "\n".join(out).rstrip() + "\n"


SPRING_INTRO = """\
# Spring spec file reference

Generated from the declarations of the keys in the code (`python -m govopt.spec_docs
docs/reference/spring-spec.md` writes this file; a test fails when it is stale): do not edit it
by hand. The governor spec file has its own page: [spec.md](spec.md).

A spring spec is the file `govopt spring` (a spring to design) and `govopt spring check` (a
spring you have) read: TOML with units, as a governor spec (a quantity is a string with its unit,
in any unit of its dimension; the columns below give the SI unit). It has a `name`, a
`description` and a `[spring]` table whose keys are the command's options with underscores:
`max_outer_diameter = "40 mm"` is `--max-outer-diameter "40 mm"`, and an option given on the
command line overrides the file's key. The report speaks the units the spring is written in.

`[spring]` takes one of three forms, told apart by its keys: a spring's geometry
(`wire_diameter`, `mean_diameter` ...) makes it a spring to check, `problem` a problem of the
literature, anything else a spring to design. `govopt init --type spring` and `govopt init
--type spring-check` write a commented spec of a spring to design and of one to check, every key
with its meaning, that run as written; `govopt schema` writes the JSON Schema editors read, which
covers spring specs too. A key not declared here is an error.
"""


def spring_reference() -> str:
    """``docs/reference/spring-spec.md``: the top level of a spring spec and each form of its
    ``[spring]`` (:data:`govopt.spring_keys.FORMS`) with its keys, defaults and ranges."""
    from .spring_keys import FORMS, TEMPLATES, top_table

    inits = {form: name for name, (form, _, _) in TEMPLATES.items()}
    out = [SPRING_INTRO, "## Contents", ""]
    out += [f"- [{name}](#{_anchor(name)}): {table.meaning.split(':')[0]} (`{command} "
            "SPEC`)" for name, (table, command) in FORMS.items()]
    out += ["- [top level](#top-level): `name`, `description`, `[spring]`", ""]
    for name, (table, command) in FORMS.items():
        init = (f" `govopt init --type {inits[name]}` writes one with every key."
                if name in inits else "")
        out += [f"## {name}", "", f"Read by `{command} SPEC`.{init}", ""]
        out += table_markdown(table, f"### {name}: [spring]")
    out += ["## top level", ""]
    out += table_markdown(top_table("the spring: a spring to design, a problem of the "
                                    "literature or a spring to check (above)"), "### top level")
    return "\n".join(out).rstrip() + "\n"


def _anchor(name: str) -> str:
    """The anchor GitHub gives the heading ``### [name]``."""
    return name.replace(".", "").replace(" ", "-").lower()


def _spring_words(cls) -> str:
    kind = cls.declared_spring_kind()
    if kind is None:
        return " A dead-weight governor: no spring."
    if cls.spring is None:
        return (f" Its spring is optional (`spring = ...` in `[governor]`): a helical spring "
                f"({kind.name} or compression).")
    return f" Its spring: {'a helical ' + kind.name + ' spring' if kind.helical else 'a leaf'}."


# -- templates -----------------------------------------------------------------------------


def _toml(value) -> str:
    """A value as TOML writes it (strings, numbers, booleans, lists)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, int | float):
        return repr(value) if not isinstance(value, float) or math.isfinite(value) else "nan"
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    raise TypeError(f"no TOML for {value!r}")


def _suggested(key: Key, name: str):
    """A value to show, commented, for a key the example does not give: its example, its
    default as a spec writes it, or a value of its dimension."""
    if key.example is not None:
        return key.example
    default = key.default
    dim = key.dimension if name.endswith("_mass") or key.kind != WEIGHT else "force"
    if key.kind == "choice":
        options = key.options()
        return default if default in options else options[0]
    if key.kind == "flag":
        return bool(default)
    if key.kind == "text":
        return default or ""
    if key.shape == "pair":
        if isinstance(default, tuple) and dim in (None, "dimensionless"):
            return list(default)
        if isinstance(default, tuple):
            return [f"{default[0]:g} {SI_UNITS[dim]}", f"{default[1]:g} {SI_UNITS[dim]}"]
        return [EXAMPLES.get(dim, "1"), EXAMPLES.get(dim, "1")]
    if key.shape == "list":
        return key.options()[0] if key.options() else [EXAMPLES.get(dim, "1")]
    if isinstance(default, int | float) and not isinstance(default, bool):
        if dim in (None, "dimensionless"):
            return default
        return f"{default:g} {SI_UNITS[dim]}"
    if dim in (None, "dimensionless"):
        return 1
    return EXAMPLES[dim]


def describe(key: Key, borrowed: Collection[str] = ()) -> str:
    """A key in sentences: its meaning, kind, default, range, when it applies and its source
    (the templates' comments, the schema's descriptions). ``borrowed``: bibliography keys of
    other governor types' sources (:func:`borrowed_sources`); a key whose source cites only
    those says it is borrowed.

    >>> from govopt.keys import Key
    >>> describe(Key("dashpot_f", "number", "the dash-pot's f", source="Hamabe Part III"),
    ...          borrowed=("hamabe",))
    "The dash-pot's f. number; required; > 0 (borrowed from Hamabe Part III)."
    """
    facts = [kind_words(key), "required" if key.required and not key.when else
             f"default {key.default_words()}" if not key.required else "", key.range_words()]
    source = source_words(key.source, borrowed)
    return (key.meaning[0].upper() + key.meaning[1:] + ". " + "; ".join(f for f in facts if f)
            + (f"; applies {key.when}" if key.when else "")
            + (f" ({source})" if source else "") + ".")


def source_words(source: str, borrowed: Collection[str] = ()) -> str:
    """A key's source as a type reads it: ``"borrowed from Hamabe Part III"`` where it cites
    only ``borrowed`` bibliography keys (other types' own sources), else as declared."""
    cited = found_in(source)
    return f"borrowed from {source}" if cited and set(cited) <= set(borrowed) else source


def borrowed_sources(type_name: str) -> frozenset[str]:
    """The bibliography keys of the other governor types' own sources
    (:attr:`Reference.governor`, but ``type_name``'s own :attr:`Governor.source`): what a key
    or criterion of ``type_name`` borrows when it cites them."""
    from .governors import governor_class

    own = governor_class(type_name).source
    return frozenset(k for k, r in REFERENCES.items() if r.governor) - {own}


def option_help(key: Key, table: Table, reference: str = "docs/reference/spring-spec.md") -> str:
    """The help of the command-line option of ``key`` of ``table`` (``--max-outer-diameter``
    for ``max_outer_diameter``: a spring spec's keys are `govopt spring`'s options): its meaning
    and unit (an example in the unit), its choices where they are known without loading
    anything, its default or that it is required, and when it applies; the table's keys it
    names written as options; choices loaded on first use are pointed to in ``reference``.
    Loads nothing (a command's ``--help`` builds it).

    >>> from govopt.spring_keys import DESIGN
    >>> option_help(DESIGN.key("max_outer_diameter"), DESIGN)
    "The largest outside diameter D + d (the bore it works in): a length, e.g. '40 mm'."
    >>> option_help(DESIGN.key("length_1"), DESIGN)
    "The working (installed) length L1 at --min-force: a length, e.g. '80 mm'. Applies to \
compression springs."
    """
    dim = key.dimension
    example = key.example if key.example is not None else EXAMPLES.get(dim or "")
    if key.shape == "list":
        what = (" or ".join(f"'{c}'" for c in key.options()) + f", or {dim}s as one text, "
                f"e.g. '{', '.join(example)}'")
    elif key.quantity:
        what = f"a {dim.replace('_', ' ')}, e.g. '{example}'"
    elif key.kind == "choice" and isinstance(key.choices, tuple):
        what = "one of " + ", ".join(f"'{c}'" if isinstance(c, str) else str(c)
                                     for c in key.choices)
    elif key.kind == "choice":  # loaded on first use: where they are listed
        what = f"a name listed in {reference}" + (f", e.g. '{example}'" if example else "")
    elif key.kind in ("number", "count"):
        words = key.range_words()
        what = f"a number in {words}" if words not in ("> 0", ">= 0") else ""
    else:
        what = ""
    text = key.meaning[0].upper() + key.meaning[1:] + (f": {what}." if what else ".")
    if key.required:
        text += " Required (here or in the spec)."
    elif key.default is not None or key.default_text:
        text += f" Default: {key.default_words()}."
    if key.when:
        text += f" Applies {key.when}."
    names = sorted((n for n in table.names if "_" in n), key=len, reverse=True)
    if names:
        text = re.sub(r"(?<![\w/.])(" + "|".join(names) + r")(?!\w|\.\w)",
                      lambda m: "--" + m[1].replace("_", "-"), text)
    return text


def _comment(key: Key, borrowed: Collection[str] = ()) -> list[str]:
    """The comment above a key in a template (:func:`describe`)."""
    return ["# " + line for line in textwrap.wrap(describe(key, borrowed), 96)]


def _table_lines(table: Table, data: dict | None, tables: dict, prefix: str = "",
                 borrowed: Collection[str] = ()) -> list[str]:
    """A table of the template: its header, then each key commented with the example's value
    (``data``), or commented out where the example leaves it to its default. A table the
    example has not is written commented out."""
    on = data is not None
    data = data or {}
    mark = "" if on else "# "
    header = f"[[{table.name}]]" if table.array else f"[{table.name}]"
    out = ["# " + line for line in textwrap.wrap(
        table.meaning[0].upper() + table.meaning[1:] + "."
        + (f" {table.when[0].upper()}{table.when[1:]}." if table.when else ""), 96)]
    out.append(mark + header)
    later = []
    for key in table.keys:
        if key.kind == "table":  # a sub-table: its own section after this one's keys
            sub = tables.get(f"{table.name}.{key.name}")
            if sub is not None:
                later += [""] + _table_lines(sub, data.get(key.name) if on else None, tables,
                                             borrowed=borrowed)
            continue
        given = [n for n in key.names if n in data]
        out += _comment(key, borrowed)
        if given:
            out += [f"{mark}{n} = {_toml(data[n])}" for n in given]
        else:
            name = key.names[0]
            out.append(f"# {name} = {_toml(_suggested(key, name))}")
    return out + later


def template(type_name: str) -> str:
    """The spec ``govopt init --type TYPE`` writes: every table and key of the type
    (:func:`govopt.spec_keys.spec_tables`), each with its meaning as a comment; the values
    are the type's bundled design example's (``Governor.example``), the keys it leaves out
    commented, with their defaults or a value to start from."""
    from .examples import example
    from .governors import governor_class
    from .spec_keys import spec_tables
    from .spring_keys import TEMPLATES

    if type_name in TEMPLATES:
        return spring_template(type_name)
    cls = governor_class(type_name)
    source = example(cls.example)
    data = tomllib.loads(source.read_text(encoding="utf-8"))
    tables = spec_tables(type_name)
    borrowed = borrowed_sources(type_name)
    head = [f"# A {type_name} governor spec: {cls.title}.",
            f"# Written by `govopt init --type {type_name}`: every key of the type, each with "
            "its meaning;",
            f"# the values are those of the bundled example {source.stem} (`govopt init "
            f"{source.stem}`),",
            "# so `govopt design FILE` runs it as written. A key commented out takes its "
            "default; a table",
            "# commented out is not used. docs/reference/spec.md lists every key; for "
            "completion in an editor,",
            "# `govopt schema -o govopt.schema.json` and `#:schema ./govopt.schema.json` as "
            "this file's first line.",
            ""]
    out = list(head)
    top = tables[""]
    for key in top.keys:
        if key.kind != "table":
            out += _comment(key)
            value = {"name": f"{type_name}-design",
                     "description": f"a {type_name} governor to design"}[key.name]
            out.append(f"{key.name} = {_toml(value)}")
    for name, table in tables.items():
        if not name or "." in name or table.open:
            continue
        if table.array:
            items = data.get(name) or [None]
            for item in items:
                out += [""] + _table_lines(table, item, tables, borrowed=borrowed)
        else:
            out += [""] + _table_lines(table, data.get(name), tables, borrowed=borrowed)
    return "\n".join(out) + "\n"


def spring_template(name: str) -> str:
    """The spring spec ``govopt init --type NAME`` writes (``spring``, ``spring-check``:
    :data:`govopt.spring_keys.TEMPLATES`): every key of its ``[spring]``, each with its meaning
    as a comment; the values are a bundled example's or the template's own, the keys they leave
    out commented, with their defaults or a value to start from; its command runs it as
    written."""
    from .examples import example
    from .spring_keys import FORMS, TEMPLATES, top_table

    form, start, description = TEMPLATES[name]
    table, command = FORMS[form]
    if isinstance(start, str):
        data = tomllib.loads(example(start).read_text(encoding="utf-8"))["spring"]
        origin = f"the bundled example {start} (`govopt init {start}`)"
    else:
        data, origin = start, "a spring to start from"
    out = [f"# A spring spec: {description} (`{command}`).",
           f"# Written by `govopt init --type {name}`: every key of [spring], each with its "
           "meaning; the values",
           f"# are {origin}, so `{command} FILE` runs it as written.",
           "# A key commented out takes its default. Each key is an option too (max_outer_diameter",
           f"# is --max-outer-diameter), which overrides the file: see `{command} --help`.",
           "# docs/reference/spring-spec.md lists every key; for completion in an editor,",
           "# `govopt schema -o govopt.schema.json` and `#:schema ./govopt.schema.json` as this "
           "file's first line.", ""]
    top = top_table(table.meaning)
    for key, value in zip(top.keys, (name, description), strict=False):
        out += _comment(key) + [f"{key.name} = {_toml(value)}"]
    return "\n".join(out + [""] + _table_lines(table, data, {})) + "\n"


#: the reference pages ``python -m govopt.spec_docs PATH ...`` writes, by file name
PAGES = {"spec.md": reference, "spring-spec.md": spring_reference}


def main(argv: list[str] | None = None) -> None:
    """``python -m govopt.spec_docs [PATH ...]``: each reference page its file name names
    (:data:`PAGES`; another name, the governor spec's), to PATH, or the governor spec's to
    stdout."""
    argv = sys.argv[1:] if argv is None else argv
    if not argv:
        sys.stdout.write(reference())
    for path in argv:
        text = PAGES.get(os.path.basename(path), reference)()
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text)


if __name__ == "__main__":
    main()
