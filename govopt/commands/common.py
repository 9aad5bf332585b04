"""What every command of the CLI shares: output, the one-line error convention and exit codes
(0 ok, 1 a check failed, 2 a user's error, 3 a bug), held warnings, and the help's options and
flags. The commands are ordinary typer commands: typer parses and converts their options."""

from __future__ import annotations

import errno
import functools
import os
import re
import sys
import typing
import warnings

import typer

from ..errors import GovoptError
from ..limits import printable, shorten_values

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
    try:
        print(text, file=stream, flush=True)
    except OSError as exc:
        unwritable(stream, exc)


def unwritable(stream, exc: OSError) -> None:
    """A standard stream that cannot be written. Its reader gone (``govopt design | head -1``,
    a closed pipe): nothing more is printed there, and the command carries on (its files
    written, its exit code its own: the same however early the reader left). Anything else (a
    full disk, ``/dev/full``): one line naming the stream, exit code 2. Either way the stream
    is pointed at the null device, so that nothing left in its buffer fails again at exit."""
    name = "stderr" if stream is sys.stderr else "stdout"
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), stream.fileno())
    except (OSError, ValueError):  # not a file (a test's capture): nothing to point away
        pass
    if exc.errno in (errno.EPIPE, errno.ECONNRESET) or stream is sys.stderr:
        return
    from ..errors import GovoptError

    raise GovoptError(f"{name}: cannot write the output "
                      f"({(exc.strerror or type(exc).__name__).lower()})")


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


def option(*names: str, help: str, metavar: str = "<str>", **kw):
    """A typer option that takes a value (shown as ``metavar``), its help printed as written."""
    return typer.Option(*names, metavar=metavar, help=rich_text(help), **kw)


def flag(*names: str, help: str, **kw):
    """A typer flag (``--json``; ``--x/--no-x`` for a switch), its help printed as written and
    no value shown (``--json  Print ...``, as in git or pip, not ``--json <bool>``)."""
    return typer.Option(*names, metavar="", help=rich_text(help), **kw)
