"""Command-line interface: typer parses, each command's module (:mod:`govopt.commands`) calls
the API and prints. No physics here.

Start-up (docs/decisions.md: imports on demand): the root is built for the command a run names
(:func:`app`): that command's module is imported, and the others are there by name and one
line of help (:data:`COMMANDS`), enough for the root's help and its errors; a command imports
what it uses when it runs (numpy with the evaluator, rich only for the help, the report on a
terminal and the study's progress bar). `benchmarks/bench_startup.py` measures the commands'
start-up against ``python -c "import numpy"`` and ``python -c "import cvxpy"``.
"""

from __future__ import annotations

import importlib
import os
import signal
import sys
from collections.abc import Collection
from typing import Annotated

import typer

from .commands.common import State, echo, fail, internal, unwritable

#: command -> (module in govopt.commands, its typer app, the one line of the root's help)
COMMANDS = {
    "evaluate": ("evaluate", "evaluate_app", "Evaluate the spec's design (default: the bundled "
                                             "Hamabe case a)."),
    "design": ("evaluate", "design_app", "Find the best design for the spec's requirements "
                                         "(default: bundled hamabe-design)."),
    "at": ("questions", "at_app", "Speeds, forces, effort and power at the configurations a "
                                  "problem names."),
    "solve": ("questions", "solve_app", "Find the spec input at which a figure meets its target "
                                        "(any unknown)."),
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


def _version(value: bool) -> None:
    if value:
        from . import __version__

        echo(f"govopt {__version__}")
        raise typer.Exit()


def _root(ctx: typer.Context,
          debug: Annotated[bool, typer.Option(
              "--debug", metavar="", help="Show the traceback of an unexpected error, and "
                                          "warnings as they come. \\[env var: GOVOPT_DEBUG]")]
          = False,
          version: Annotated[bool, typer.Option(
              "--version", metavar="", callback=_version, is_eager=True,
              help="Print govopt's version and exit.")] = False) -> None:
    State.debug = debug or _debug_env()
    if ctx.invoked_subcommand is None:  # no command: the help, and exit code 2 (nothing ran)
        echo(ctx.get_help())
        raise SystemExit(2)


def _listed() -> None:
    """A command this run does not name: its line in the root's help."""


def app(loaded: Collection[str] = ()) -> typer.Typer:
    """govopt's command line with the commands ``loaded`` (their modules imported now); the
    others are there by name and one line of help (:data:`COMMANDS`), in that order."""
    root = typer.Typer(help=DESCRIPTION, invoke_without_command=True,
                       context_settings={"help_option_names": ["-h", "--help"]},
                       pretty_exceptions_enable=False)
    root.callback()(_root)
    for name, (module, attribute, short) in COMMANDS.items():
        if name in loaded:
            sub = getattr(importlib.import_module(f"govopt.commands.{module}"), attribute)
        else:
            sub = typer.Typer()
            sub.command(name, help=short, short_help=short)(_listed)
        root.add_typer(sub)
    return root


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
    # shell completion (typer's, asked through this variable) may complete any command's words
    loaded = COMMANDS if "_GOVOPT_COMPLETE" in os.environ else argv[at:at + 1]
    try:
        code = app(loaded)(args=argv, prog_name="govopt", standalone_mode=False)
    except typer.Abort:
        raise SystemExit(1) from None
    except typer.TyperException as exc:  # a bad command line: typer's usage errors
        context = getattr(exc, "ctx", None)
        where = context.command_path if context is not None else _command_path(argv)
        fail(f"{exc.format_message().rstrip('.')} (see '{where} --help')")
    if isinstance(code, int) and code:
        raise SystemExit(code)


def _command_path(argv: list[str]) -> str:
    """``govopt`` and the command words of ``argv`` (``govopt study run``)."""
    words = [a for a in argv if not a.startswith("-")][:2]
    if words[:1] and words[0] in COMMANDS:
        return " ".join(["govopt", *words[:2 if words[0] in DEFAULT_SUBCOMMANDS else 1]])
    return "govopt"


def on_sigterm(signum, frame) -> None:
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
        signal.signal(signal.SIGTERM, on_sigterm)
    argv = sys.argv[1:] if argv is None else [str(a) for a in argv]
    try:
        _run(argv)
    except KeyboardInterrupt:
        sys.exit(130)
    except BrokenPipeError as exc:  # stdout gone outside a command's output: the shell's
        unwritable(sys.stdout, exc)  # convention (128 + SIGPIPE), quietly
        sys.exit(128 + signal.SIGPIPE)
    except Exception as exc:  # outside a command (the commands are guarded)
        if State.terminated:
            sys.exit(State.terminated)
        if State.debug or "--debug" in argv:
            raise
        internal(exc)
        sys.exit(3)


if __name__ == "__main__":
    main()
