"""Command-line interface: typer parses, each command's module (:mod:`govopt.commands`) calls
the API and prints. No physics here.

Start-up (docs/decisions.md: imports on demand): the root knows its commands by name and one
line of help; a command's module is imported when it runs or shows its help, and a command
imports what it uses when it runs (numpy with the evaluator, rich only for the help, the report
on a terminal and the study's progress bar). typer's pydantic path is not taken: the commands'
options are converted by :class:`govopt.commands.common.Command`. `benchmarks/bench_startup.py`
measures `govopt --help` and `govopt evaluate` against ``python -c "import numpy"``.
"""

from __future__ import annotations

import functools
import importlib
import os
import signal
import sys
from typing import Annotated

import typer
import typer.core

from .commands.common import Group, PipeClosed, State, UsageError, echo, fail, internal

#: command -> (module in govopt.commands, its typer app, the one line of the root's help)
COMMANDS = {
    "evaluate": ("evaluate", "evaluate_app", "Evaluate the spec's design (default: the bundled "
                                             "Hamabe case a)."),
    "design": ("evaluate", "design_app", "Find the best design for the spec's requirements "
                                         "(default: bundled hamabe-design)."),
    "spring": ("spring", "app", "Least-mass helical spring for a force and stiffness (an exact "
                                "GP, certified global), or check one you have."),
    "bench": ("bench", "app", "Speed against error of every analysis and the speed targets "
                              "beside what was measured."),
    "examples": ("examples", "examples_app", "List the bundled example specs."),
    "init": ("examples", "init_app", "Copy a bundled example spec here, or write a type's "
                                     "template, to start from."),
    "schema": ("examples", "schema_app", "Write the JSON Schema of a spec file, for TOML "
                                         "editors."),
    "study": ("study", "app", "Batch trade studies: sweep a spec's inputs, one row per point "
                              "in an SQLite database; export, plot and summarise it."),
}

DESCRIPTION = ("Design and evaluate speed governors and their springs: Hamabe's shaft governor, "
               "the textbook's Watt, Porter, Proell, Hartnell, spring-loaded and "
               "spring-and-gravity governors, and the traction-engine coil- and flat-spring "
               "governors (`govopt examples` lists a spec of each).")


@functools.cache
def command(name: str):
    """The click command of ``govopt NAME``, built from its module (imported now), once per
    process (typer builds it from the functions' signatures: ~5 ms, paid again by every run of
    an embedding's or a test's ``main(argv)`` otherwise)."""
    module, attribute, _ = COMMANDS[name]
    app = getattr(importlib.import_module(f"govopt.commands.{module}"), attribute)
    return typer.main.get_command(app)


class _Root(Group):
    """The root: its commands by name, each built when it is asked for; the root's help lists
    them from :data:`COMMANDS` without importing one."""

    listing = False  # while the root's help is drawn

    def list_commands(self, ctx) -> list[str]:
        return list(COMMANDS)

    def get_command(self, ctx, name: str):
        if name not in COMMANDS:
            return None
        if self.listing:  # the line of the root's help, not the command
            return typer.core.TyperCommand(name, short_help=COMMANDS[name][2],
                                           rich_markup_mode=self.rich_markup_mode)
        return command(name)

    def format_help(self, ctx, formatter) -> None:
        self.listing = True
        try:
            super().format_help(ctx, formatter)
        finally:
            self.listing = False


app = typer.Typer(cls=_Root, help=DESCRIPTION, invoke_without_command=True,
                  context_settings={"help_option_names": ["-h", "--help"]})


def _version(value: bool) -> None:
    if value:
        from . import __version__

        echo(f"govopt {__version__}")
        raise typer.Exit()


@app.callback()
def _root(ctx: typer.Context,
          debug: Annotated[bool, typer.Option(
              "--debug", help="Show the traceback of an unexpected error, and warnings as they "
                              "come. \\[env var: GOVOPT_DEBUG]")] = False,
          version: Annotated[bool, typer.Option(
              "--version", callback=_version, is_eager=True,
              help="Print govopt's version and exit.")] = False) -> None:
    State.debug = debug or _debug_env()
    if ctx.invoked_subcommand is None:  # no command: the help, and exit code 2 (nothing ran)
        echo(ctx.get_help())
        raise SystemExit(2)


@functools.cache
def root():
    """govopt's command line as a click group (its commands built on demand), built once per
    process."""
    return typer.main.get_command(app)


def _debug_env() -> bool:
    """GOVOPT_DEBUG as a flag (1/true/yes/on, 0/false/no/off or empty)."""
    value = os.environ.get("GOVOPT_DEBUG", "").strip().lower()
    if value in ("", "0", "false", "f", "no", "n", "off"):
        return False
    if value in ("1", "true", "t", "yes", "y", "on"):
        return True
    fail(f"GOVOPT_DEBUG: expected 1 or 0 (true/false, yes/no, on/off), got {value!r}")


#: a group's default subcommand: `govopt study SPEC` is `govopt study run SPEC`, `govopt
#: spring ...` is `govopt spring design ...`
DEFAULT_SUBCOMMANDS = {"study": ("run", ("run", "export", "show")),
                       "spring": ("design", ("design", "check"))}


def _run(argv: list[str]) -> None:
    """Parse ``argv`` and run its command (a group's default subcommand inserted:
    :data:`DEFAULT_SUBCOMMANDS`); a bad command line is one line ``error: ...`` and exit
    code 2."""
    State.debug = False
    at = next((i for i, a in enumerate(argv) if not a.startswith("-")), len(argv))
    group = argv[at] if at < len(argv) else None
    if group in DEFAULT_SUBCOMMANDS:
        default, subcommands = DEFAULT_SUBCOMMANDS[group]
        if argv[at + 1:at + 2] not in ([], *([c] for c in subcommands), ["-h"], ["--help"]):
            argv = [*argv[:at + 1], default, *argv[at + 1:]]
    try:
        code = root().main(args=argv, prog_name="govopt", standalone_mode=False)
    except UsageError as exc:
        where = exc.ctx.command_path if exc.ctx is not None else _command_path(argv)
        fail(f"{exc.format_message()} (see '{where} --help')")
    except typer.Abort:
        raise SystemExit(1) from None
    if isinstance(code, int) and code:
        raise SystemExit(code)


def _command_path(argv: list[str]) -> str:
    """``govopt`` and the command words of ``argv`` (``govopt study run``)."""
    words = [a for a in argv if not a.startswith("-")][:2]
    if words[:1] and words[0] in COMMANDS:
        return " ".join(["govopt", *words[:2 if words[0] in DEFAULT_SUBCOMMANDS else 1]])
    return "govopt"


def _on_sigterm(signum, frame) -> None:
    """SIGTERM unwinds like an exception, so every ``finally`` runs (temporary files are
    removed); a second SIGTERM during that clean-up is ignored."""
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    State.terminated = 128 + signum  # where a library's bare except turns the exit into an
    raise SystemExit(128 + signum)  # error of its own (openpyxl's descriptors), it still wins


def main(argv: list[str] | None = None) -> None:
    """Console-script entry point (``argv``: the words after ``govopt``, default
    ``sys.argv[1:]``): never a traceback unless ``--debug``. Run as the console script it owns
    the process's SIGTERM; called with ``argv`` (tests, embedding) it leaves it alone."""
    # One BLAS thread unless told otherwise (before numpy loads): govopt's matrices are small,
    # and OpenBLAS's pool costs ~0.05 s of CPU to start and spins idle after each call (it was a
    # third of `govopt evaluate`'s CPU); studies run processes in parallel anyway.
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    if argv is None:
        signal.signal(signal.SIGTERM, _on_sigterm)
    argv = sys.argv[1:] if argv is None else [str(a) for a in argv]
    try:
        _run(argv)
    except KeyboardInterrupt:
        sys.exit(130)
    except (BrokenPipeError, PipeClosed):  # `govopt evaluate | head`: quiet, stdout is gone
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(1)
    except Exception as exc:  # outside a command (the commands are guarded)
        if State.terminated:
            sys.exit(State.terminated)
        if State.debug or "--debug" in argv:
            raise
        internal(exc)
        sys.exit(3)


if __name__ == "__main__":
    main()
