"""`govopt examples` lists the bundled example specs; `govopt init NAME` copies one here, `govopt
init --type TYPE` writes a commented spec of a governor type, or of a spring spec (``spring``,
``spring-check``), with every key (its template, :func:`govopt.spec_docs.template`); `govopt
schema` writes the JSON Schema of a spec file."""

from pathlib import Path
from typing import Annotated

import typer

from ..errors import GovoptError
from . import common
from .common import FORCE_HELP, echo, guarded

EXAMPLES_SHORT = "List the bundled example specs."
EXAMPLES_HELP = "List the bundled example specs. `govopt init NAME` copies one to start from."
INIT_SHORT = "Copy a bundled example spec here, or write a type's template, to start from."
INIT_HELP = ("Copy a bundled example spec here, to start from, or write the template of a "
             "governor type or of a spring spec: every key, with its meaning. E.g. `govopt init "
             "hamabe-a` writes hamabe-a.toml in the current folder; `govopt init --type "
             "hartnell` writes hartnell.toml, which `govopt design` runs as written; `govopt "
             "init --type spring-check` a spring for `govopt spring check`.")
SCHEMA_SHORT = "Write the JSON Schema of a spec file, for TOML editors."
SCHEMA_HELP = ("Write the JSON Schema of a spec file, governor or spring (every type's keys, "
               "meanings, units, defaults and ranges), for the completion and checking of TOML "
               "editors (Even Better TOML / taplo: put `#:schema ./govopt.schema.json` on a "
               "spec's first line). Printed, or written with -o.")

examples_app = typer.Typer(add_completion=False)
init_app = typer.Typer(add_completion=False)
schema_app = typer.Typer(add_completion=False)


@examples_app.command("examples", help=EXAMPLES_HELP, short_help=EXAMPLES_SHORT)
@guarded
def examples_command() -> None:
    """List the bundled example specs.

    `govopt init NAME` copies one to start from."""
    from ..examples import description, examples

    found = examples()
    width = max(map(len, found))
    for name, path in found.items():
        echo(f"{name:<{width}}  {description(path)}")


@init_app.command("init", help=INIT_HELP, short_help=INIT_SHORT)
@guarded
def init_command(
        name: Annotated[str | None, typer.Argument(
            metavar="[name]", show_default=False,
            help="A bundled example (see `govopt examples`).")] = None,
        gtype: Annotated[str | None, common.option(
            "--type", metavar="<type>", help="Write the template of this governor type "
            "instead: shaft, watt, porter, proell, hartnell, spring_loaded, spring_gravity, "
            "traction_coil or traction_leaf; or of a spring spec: spring (a spring to design, "
            "`govopt spring`) or spring-check (a spring you have, `govopt spring check`).")]
        = None,
        output: Annotated[str | None, common.option(
            "-o", "--output", metavar="<path>", help="Where to write it (default: NAME.toml "
            "or TYPE.toml here; a folder: that file in it).")] = None,
        force: Annotated[bool, common.flag("--force", help=FORCE_HELP)] = False) -> None:
    """Copy a bundled example spec here, or write a type's template, to start from.

    E.g. `govopt init hamabe-a` writes hamabe-a.toml in the current folder; `govopt init
    --type hartnell` writes hartnell.toml."""
    import tomllib

    from ..report.files import atomic_write, check_output, names_folder, output_folder

    if (name is None) == (gtype is None):
        raise GovoptError("init: give a bundled example's NAME or --type TYPE, one of the two "
                          "(see 'govopt init --help')")
    if gtype is not None:
        from ..governors import REGISTRY
        from ..spec_docs import template
        from ..spring_keys import TEMPLATES

        if gtype not in (*REGISTRY, *TEMPLATES):
            raise GovoptError(f"--type: expected one of {', '.join((*REGISTRY, *TEMPLATES))}, "
                              f"got {gtype!r}")
        data, inputs, stem = template(gtype).encode("utf-8"), [], gtype
        what = f"the {gtype} template"
    else:
        from ..examples import example

        source = example(name)
        data, inputs, stem = source.read_bytes(), [source], source.stem
        what = f"the bundled {source.stem}"
    if output is not None and not output.strip():
        raise GovoptError(f"-o: expected a file or folder name, got {output!r}")
    target = Path(output) if output is not None else Path(f"{stem}.toml")
    if names_folder(output):  # 'DIR/new/': a folder, made if only its parent exists
        target = output_folder(target, "the spec") / f"{stem}.toml"
    elif target.is_dir():
        target = target / f"{stem}.toml"
    check_output(target, overwrite=force, inputs=inputs, what="spec")
    atomic_write(target, lambda tmp: tmp.write_bytes(data), overwrite=force, what="spec")
    table = tomllib.loads(data.decode("utf-8"))
    if "governor" not in table and isinstance(table.get("spring"), dict):  # a spring spec's
        from ..spring_keys import FORMS, form

        command = FORMS[form(table["spring"])][1].removeprefix("govopt ")
    else:
        command = "study" if "study" in table else "evaluate" if "design" in table else "design"
    echo(f"wrote {target} ({what}); edit it, then: govopt {command} {target}")


@schema_app.command("schema", help=SCHEMA_HELP, short_help=SCHEMA_SHORT)
@guarded
def schema_command(
        output: Annotated[str | None, common.option(
            "-o", "--output", metavar="<path>", help="Write it to this file (default: print "
            "it).")] = None,
        force: Annotated[bool, common.flag("--force", help=FORCE_HELP)] = False) -> None:
    """Write the JSON Schema of a spec file, for TOML editors.

    Printed, or written with -o; a spec's first line `#:schema ./govopt.schema.json` points
    Even Better TOML (taplo) to it."""
    from ..spec_schema import text

    body = text()
    if output is None:
        echo(body.removesuffix("\n"))
        return
    from ..report.files import atomic_write, check_output

    target = Path(output)
    check_output(target, overwrite=force, inputs=[], what="schema")
    atomic_write(target, lambda tmp: tmp.write_text(body, encoding="utf-8"), overwrite=force,
                 what="schema")
    echo(f"wrote {target}")
