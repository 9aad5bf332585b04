"""What every command of the CLI shares: output, the one-line error convention and exit codes
(0 ok, 1 a check failed, 2 a user's error, 3 a bug), held warnings, and :class:`Command`, the
typer command class whose options are converted here instead of through pydantic.

typer 0.29 builds a pydantic ``TypeAdapter`` for every option that is not a flag the first time
it reads it (pydantic's import and the adapters: ~0.1 s of CPU at every start of a command;
docs/decisions.md: imports on demand); govopt's options are text, numbers, paths and lists of
text, converted by :func:`convert` with govopt's own messages.
"""

from __future__ import annotations

import functools
import inspect
import re
import sys
import types
import typing
import warnings
from pathlib import Path

import typer
import typer.core

from ..errors import GovoptError
from ..limits import printable, shorten_values

#: typer's (vendored) click: its usage error, the base of every bad-command-line exception
UsageError = typer.BadParameter.__mro__[1]

_ANSI = re.compile(r"\033\[[;?0-9]*[a-zA-Z]")  # an escape sequence, stripped when not a terminal

FORCE_HELP = "Replace output files that exist (regular files only, never the spec)."
JSON_HELP = "Print a JSON object in SI units."


class State:
    """The run's settings from the root's options (``--debug`` / GOVOPT_DEBUG), and the signal
    that ended it (``terminated``: a SIGTERM's exit code, 0 while none came)."""

    debug = False
    terminated = 0


def echo(text: str, err: bool = False) -> None:
    """Print a line to stdout (stderr with ``err``), flushed; escape sequences are kept only
    on a terminal (a spec's name may carry them)."""
    stream = sys.stderr if err else sys.stdout
    if not stream.isatty():
        text = _ANSI.sub("", text)
    print(text, file=stream, flush=True)


def fail(message: str) -> typing.NoReturn:
    """A user's error: one line ``error: ...`` on stderr, exit code 2."""
    echo(f"error: {printable(shorten_values(message))}", err=True)
    raise SystemExit(2)


def internal(exc: BaseException) -> None:
    """One line for an unexpected exception: a bug, to be reported (exit code 3)."""
    text = " ".join(str(exc).split())
    text = text if len(text) <= 200 else text[:197] + "..."
    echo(f"internal error: {type(exc).__name__}: {printable(text)} -- this is a bug in "
         "govopt, please report it (run with --debug to see the traceback)", err=True)


class ChecksFailed(Exception):
    """The command ran and printed its result, and some of the design's checks failed."""


class PipeClosed(Exception):
    """stdout was closed under a command (``govopt evaluate | head``): :func:`govopt.cli.main`
    exits 1 quietly (typer's own handler would swap ``sys.stdout`` for good)."""


def guarded(command):
    """Run a command so that it never shows a traceback: a user's error (GovoptError) is one
    line and exit 2, anything unexpected one line, "please report" and exit 3 (``--debug``
    re-raises); a result whose checks fail exits 1. Warnings are held and shown one line each
    only if the command ran to its end (exit 0 or 1)."""

    @functools.wraps(command)
    def run(*args, **kwargs):
        debug, out, failed = State.debug, None, False
        with warnings.catch_warnings(record=not debug) as caught:
            try:
                out = command(*args, **kwargs)
            except ChecksFailed:
                failed = True
            except BrokenPipeError:
                raise PipeClosed from None
            except GovoptError as exc:
                fail(str(exc))
            except Exception as exc:
                if State.terminated:  # the SIGTERM's exit, turned into another error by a
                    raise SystemExit(State.terminated) from None  # library's bare except
                if debug:
                    raise
                internal(exc)
                raise SystemExit(3) from None
        for message in dict.fromkeys(str(w.message) for w in caught or ()):
            echo(f"warning: {printable(message)}", err=True)
        if failed:
            raise SystemExit(1)
        return out

    return run


def rich_text(text: str) -> str:
    """A help text as typer's rich help prints it: brackets (``[study]``) are text, not
    markup."""
    return text.replace("[", r"\[")


# ------------------------------------------------------------------------------------------
# options converted without pydantic

_WHAT = {int: "an integer", float: "a number"}


def _base(annotation):
    """The type an option's annotation declares, without ``Annotated`` and ``| None``."""
    while typing.get_origin(annotation) is typing.Annotated:
        annotation = typing.get_args(annotation)[0]
    args = [a for a in typing.get_args(annotation) if a is not type(None)]
    if typing.get_origin(annotation) in (typing.Union, types.UnionType):
        annotation = args[0]
    return annotation


def convert(kind, value, option: str):
    """``value`` (the words typed, or the default) as ``kind`` (str, int, float, Path, or a
    list of str); a word that is not a ``kind`` is a bad command line (typer's usage error:
    one line, exit 2)."""
    if value is None:
        return [] if typing.get_origin(kind) is list else None
    if kind is bool and not isinstance(value, bool):  # an environment variable's text
        return str(value).strip().lower() in ("1", "true", "t", "yes", "y", "on")
    if typing.get_origin(kind) is list:
        return [str(v) for v in value]
    if kind in (int, float) and not isinstance(value, kind):
        try:
            return kind(value)
        except ValueError:
            raise typer.BadParameter(f"expected {_WHAT[kind]}, got {value!r}") from None
    if kind is Path and not isinstance(value, Path):
        return Path(value)
    return value


class _Plain:
    """A command or group whose parameters are converted by :func:`convert` (no pydantic),
    each as the declared type of the function's argument (``kinds``), and whose flags read
    ``--json  Print ...`` in the help, as in git or pip, not ``--json <bool>`` (typer's rich
    help shows every option's type, the help and completion flags too)."""

    kinds: dict = {}

    def get_params(self, ctx):
        params = super().get_params(ctx)
        for param in params:
            flag = getattr(param, "is_flag", False)
            if flag:
                param.display_type_rich = _no_type
            if "process_value" not in vars(param):
                kind = self.kinds.get(param.name, bool if flag else str)
                param.process_value = functools.partial(_process, param, kind)
        return params


def _no_type(ctx) -> None:
    return None


class Group(_Plain, typer.core.TyperGroup):
    """A typer group: its options converted without pydantic, its flags shown without a type."""


class Command(_Plain, typer.core.TyperCommand):
    """A typer command whose options are converted by :func:`convert` (no pydantic): each
    option's value, as the declared type of the function's argument."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        hints = typing.get_type_hints(inspect.unwrap(self.callback), include_extras=True)
        self.kinds = {name: _base(hint) for name, hint in hints.items()}


def _process(param, kind, ctx, value):
    """click's ``Parameter.process_value`` with :func:`convert` for the conversion."""
    value = convert(kind, value, param.opts[0])
    if param.required and param.value_is_missing(value):
        raise _missing(ctx, param)
    if param.callback is not None:
        value = param.callback(ctx, param, value)
    return value


def _missing(ctx, param):
    """click's missing-parameter error (``Missing option '--force'``)."""
    names = " / ".join(f"'{name}'" for name in param.opts)
    return UsageError(f"Missing {param.param_type_name} {names}", ctx=ctx)


def option(*names: str, help: str, metavar: str = "<str>", **kw):
    """A typer option that takes a value (shown as ``metavar``), its help printed as written."""
    return typer.Option(*names, metavar=metavar, help=rich_text(help), **kw)


def flag(*names: str, help: str, **kw):
    """A typer flag (``--json``; ``--x/--no-x`` for a switch), its help printed as written."""
    return typer.Option(*names, help=rich_text(help), **kw)
