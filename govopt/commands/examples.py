"""`govopt examples` lists the bundled example specs; `govopt init NAME` copies one here."""

from pathlib import Path
from typing import Annotated

import typer

from . import common
from .common import FORCE_HELP, echo, guarded

EXAMPLES_SHORT = "List the bundled example specs."
EXAMPLES_HELP = "List the bundled example specs. `govopt init NAME` copies one to start from."
INIT_SHORT = "Copy a bundled example spec here, to start from."
INIT_HELP = ("Copy a bundled example spec here, to start from. E.g. `govopt init hamabe-a` "
             "writes hamabe-a.toml in the current folder.")

examples_app = typer.Typer(add_completion=False)
init_app = typer.Typer(add_completion=False)


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
        name: Annotated[str, typer.Argument(
            metavar="name", show_default=False,
            help="A bundled example (see `govopt examples`).")],
        output: Annotated[str | None, common.option(
            "-o", "--output", metavar="<path>", help="Where to write it (default: NAME.toml "
            "here; a folder: NAME.toml in it).")] = None,
        force: Annotated[bool, common.flag("--force", help=FORCE_HELP)] = False) -> None:
    """Copy a bundled example spec here, to start from.

    E.g. `govopt init hamabe-a` writes hamabe-a.toml in the current folder."""
    import tomllib

    from ..examples import example
    from ..report.files import atomic_write, check_output, names_folder, output_folder

    source = example(name)
    target = Path(output) if output is not None else Path(source.name)
    if names_folder(output):  # 'DIR/new/': a folder, made if only its parent exists
        target = output_folder(target, "the spec") / source.name
    elif target.is_dir():
        target = target / source.name
    check_output(target, overwrite=force, inputs=[source], what="spec")
    data = source.read_bytes()
    atomic_write(target, lambda tmp: tmp.write_bytes(data), overwrite=force, what="spec")
    table = tomllib.loads(data.decode("utf-8"))
    command = ("study" if "study" in table else "spring" if "spring" in table and
               "governor" not in table else "evaluate" if "design" in table else "design")
    echo(f"wrote {target.absolute()} (the bundled {source.stem}); edit it, then: "
          f"govopt {command} {target}")


