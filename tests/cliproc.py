"""``python -m govopt.cli ARGS`` as a process of its own, started in a moment: forked from a
server that has already imported what the commands load (numpy, pint, openpyxl, govopt's
modules; multiprocessing's forkserver), instead of a new interpreter importing it all again
(~0.3-0.4 s of CPU a process, most of a quick case's cost).

The child runs ``govopt.cli`` as ``__main__``, as ``python -m`` does: the console entry point
with its catch-all and its SIGTERM handler; in its own folder, stdin on /dev/null, stdout and
stderr on files of their own; it exits with govopt's exit code, or dies of a signal sent to
its pid (a negative :attr:`Proc.returncode`, as :mod:`subprocess` reports it). A fresh
interpreter's start-up (the imports on demand) is tested where a test starts ``python -m
govopt.cli`` itself (the CLI tests, the kill tests' clean-up run)."""

from __future__ import annotations

import atexit
import multiprocessing
import os
import runpy
import shutil
import subprocess
import sys
import tempfile
import threading

#: imported once, by the server (not ``govopt.cli`` itself: run as ``__main__`` after being
#: imported, runpy would warn on stderr)
PRELOAD = ["numpy", "numpy.fft", "numpy.ma", "numpy.polynomial", "pint", "openpyxl",
           "xml.sax.saxutils", "tomlkit", "govopt.commands.common", "govopt.commands.evaluate",
           "govopt.commands.spring", "govopt.commands.study", "govopt.spec", "govopt.fidelity",
           "govopt.evaluation", "govopt.optimize.search", "govopt.report.text",
           "govopt.report.files", "govopt.report.excel", "govopt.spring_command",
           "govopt.study"]

_LOCK = threading.Lock()
_CONTEXT = None


def _context():
    """The forkserver context, its server started with :data:`PRELOAD` and one BLAS thread
    (what ``govopt.cli.main`` sets before numpy loads) without changing this process's
    environment."""
    global _CONTEXT
    with _LOCK:
        if _CONTEXT is None:
            from multiprocessing import forkserver

            ctx = multiprocessing.get_context("forkserver")
            ctx.set_forkserver_preload(PRELOAD)
            saved = os.environ.get("OPENBLAS_NUM_THREADS")
            os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
            try:
                forkserver.ensure_running()
            finally:
                if saved is None:
                    os.environ.pop("OPENBLAS_NUM_THREADS", None)
            # stopped (and waited for) at exit: the CPU time of the server and of every
            # process it forked then counts among this process's children, as a
            # subprocess's does (``time pytest`` measures it)
            atexit.register(forkserver._forkserver._stop)
            _CONTEXT = ctx
    return _CONTEXT


def _child(args: list[str], cwd: str, out: str, err: str) -> None:
    """In the forked process: ``python -m govopt.cli ARGS`` in ``cwd``."""
    os.chdir(cwd)
    for fd, path, flags in ((0, os.devnull, os.O_RDONLY),
                            (1, out, os.O_WRONLY | os.O_CREAT | os.O_TRUNC),
                            (2, err, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)):
        new = os.open(path, flags, 0o600)
        os.dup2(new, fd)
        os.close(new)
    sys.argv = ["govopt", *args]
    runpy.run_module("govopt.cli", run_name="__main__", alter_sys=True)


class Proc:
    """``govopt ARGS`` running in ``cwd``: the part of :class:`subprocess.Popen` the tests use
    (``pid``, ``poll``, ``wait``, ``send_signal``, ``communicate``, ``returncode``); stdout and
    stderr are kept outside ``cwd``. From one thread only: multiprocessing's ``start`` polls
    the other running processes, and two threads reading one exit status make it 255."""

    def __init__(self, args, cwd):
        self._files = tempfile.mkdtemp(prefix="govopt-proc-")
        self._out = os.path.join(self._files, "stdout")
        self._err = os.path.join(self._files, "stderr")
        self.args = [str(a) for a in args]
        self._p = _context().Process(target=_child,
                                     args=(self.args, str(cwd), self._out, self._err))
        self._p.start()
        self.pid = self._p.pid

    @property
    def returncode(self) -> int | None:
        return self._p.exitcode

    def poll(self) -> int | None:
        return self._p.exitcode

    def wait(self, timeout: float | None = None) -> int:
        self._p.join(timeout)
        if self._p.exitcode is None:
            raise subprocess.TimeoutExpired(self.args, timeout)
        return self._p.exitcode

    def send_signal(self, sig: int) -> None:
        if self._p.exitcode is None:
            os.kill(self.pid, sig)

    def communicate(self, timeout: float | None = None) -> tuple[str, str]:
        """Wait for the end (killed after ``timeout``: TimeoutExpired); stdout and stderr."""
        try:
            self.wait(timeout)
        except subprocess.TimeoutExpired:
            self._p.kill()
            self._p.join()
            raise
        finally:
            if self._p.exitcode is not None:
                texts = []
                for path in (self._out, self._err):
                    with open(path, encoding="utf-8", errors="replace") as fh:
                        texts.append(fh.read())
                shutil.rmtree(self._files, ignore_errors=True)
        return texts[0], texts[1]


def run(args, cwd, timeout: float | None = None) -> subprocess.CompletedProcess:
    """``govopt ARGS`` in ``cwd`` to its end, as :func:`subprocess.run` with
    ``capture_output=True, text=True`` would report it."""
    p = Proc(args, cwd)
    out, err = p.communicate(timeout)
    return subprocess.CompletedProcess(p.args, p.returncode, out, err)
