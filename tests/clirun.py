"""Run the CLI in-process, as a test sees it: ``invoke(args)`` calls ``govopt.cli.main(args)``
with stdout and stderr captured, and returns its exit code, what it printed and the exception
that escaped it, if any (``--debug`` lets a bug's exception through)."""

from __future__ import annotations

import io
import os
import sys
from dataclasses import dataclass


@dataclass
class Run:
    exit_code: int
    stdout: str
    stderr: str
    output: str  # stdout and stderr as they were written, interleaved (a terminal's view)
    exception: BaseException | None = None  # one that escaped main (not its SystemExit)


class _Capture(io.StringIO):
    """A stream that also copies what it is written into ``both``."""

    def __init__(self, both: io.StringIO):
        super().__init__()
        self.both = both

    def write(self, text: str) -> int:
        self.both.write(text)
        return super().write(text)


def invoke(args, cwd=None) -> Run:
    """``govopt ARGS`` in this process: exit code, stdout, stderr, both interleaved, and an
    exception other than SystemExit that escaped (exit code 1 then, as an uncaught exception
    in a process). A BaseException that is not an Exception (a test's time limit) passes.
    ``cwd``: the folder it runs in, as a shell's current folder (restored after)."""
    from govopt.cli import main

    both = io.StringIO()
    out, err = _Capture(both), _Capture(both)
    code, exception = 0, None
    saved = sys.stdout, sys.stderr
    here = os.getcwd()
    if cwd is not None:
        os.chdir(cwd)
    sys.stdout, sys.stderr = out, err
    try:
        main([str(a) for a in args])
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 0 if exc.code is None else 1
    except Exception as exc:
        code, exception = 1, exc
    finally:
        sys.stdout, sys.stderr = saved
        os.chdir(here)
    return Run(code, out.getvalue(), err.getvalue(), both.getvalue(), exception)
