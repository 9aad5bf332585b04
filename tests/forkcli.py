"""``govopt`` command-line processes without paying Python's, numpy's and pandas's start-up each
time (~0.4-1 s of CPU): one server interpreter loads them once and forks a child per command,
which runs ``govopt.cli.main()`` as the console script does (``sys.argv``, its SIGTERM handler,
one BLAS thread) with stdin on /dev/null, its stdout and stderr in files, and exits with main's
exit code (a signal's death reported as -N, as :mod:`subprocess` does). Each command is its own
process, killed, run beside another and waited for as a ``subprocess.Popen`` is::

    with Server() as server:
        proc = server.start("study", "run", spec, "--db", db)
        os.kill(proc.pid, signal.SIGKILL)
        out, err = proc.communicate(timeout=60)   # proc.returncode: -9

:func:`run` runs one command to its end on a server shared by the test process. With
``modules=True`` a child also reports its ``sys.modules`` after the command (the import tests:
a server that loaded only ``govopt.cli`` starts each child as a fresh interpreter would be).

For tests whose subject is the processes (kills, two at once, exit codes), not the
interpreter's imports: a child holds the modules the server loaded. A fresh interpreter's
start-up is tested where a test starts ``python -m govopt.cli`` itself."""

from __future__ import annotations

import atexit
import functools
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

_SERVER = r"""
import json, os, sys
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # as govopt.cli.main, before numpy loads
import importlib
for name in sys.argv[1:]:  # what the commands will load anyway; "module:attribute" builds it
    module, _, attribute = name.partition(":")
    loaded = importlib.import_module(module)
    if attribute:
        getattr(loaded, attribute)
import govopt.cli
ask, answer = sys.stdin, sys.stdout
for line in ask:
    req = json.loads(line)
    if req["op"] == "start":
        files = [os.open(req[k], os.O_WRONLY | os.O_CREAT | os.O_TRUNC) for k in ("out", "err")]
        pid = os.fork()
        if pid == 0:
            for fd, file in zip((1, 2), files):
                os.dup2(file, fd)
                os.close(file)
            os.dup2(os.open(os.devnull, os.O_RDONLY), 0)
            sys.stdin = open(os.devnull)
            sys.stdout = os.fdopen(1, "w", closefd=False)
            sys.stderr = os.fdopen(2, "w", closefd=False)
            sys.argv = ["govopt", *req["args"]]
            try:
                if req["cwd"] is not None:
                    os.chdir(req["cwd"])
                govopt.cli.main()
                code = 0
            except SystemExit as exc:
                code = exc.code if isinstance(exc.code, int) else 0 if exc.code is None else 1
                if not isinstance(exc.code, int) and exc.code is not None:
                    print(exc.code, file=sys.stderr)
            except BaseException:
                import traceback
                traceback.print_exc()
                code = 1
            sys.stdout.flush()
            sys.stderr.flush()
            if req["modules"] is not None:
                with open(req["modules"], "w") as fh:
                    json.dump(sorted(sys.modules), fh)
            os._exit(code)
        for file in files:
            os.close(file)
        answer.write(json.dumps({"pid": pid}) + "\n")
    else:  # "poll": the exit code (a signal's as -N), or null while it runs
        done, status = os.waitpid(req["pid"], os.WNOHANG)
        answer.write(json.dumps({"code": os.waitstatus_to_exitcode(status) if done else None})
                     + "\n")
    answer.flush()
"""


class Proc:
    """A command run by the :class:`Server`: ``args``, ``pid``, ``poll()``, ``wait(timeout)``,
    ``send_signal(sig)``, ``communicate(timeout)`` and ``returncode`` as a ``subprocess.Popen``'s;
    ``modules()`` the modules it had loaded at its end (started with ``modules=True``)."""

    def __init__(self, server: Server, args: list[str], pid: int, files: dict[str, Path]):
        self.server, self.args, self.pid, self.files = server, args, pid, files
        self.returncode: int | None = None

    def poll(self) -> int | None:
        if self.returncode is None:
            self.returncode = self.server.ask({"op": "poll", "pid": self.pid})["code"]
        return self.returncode

    def wait(self, timeout: float | None = None) -> int:
        deadline = None if timeout is None else time.monotonic() + timeout
        while self.poll() is None:
            if deadline is not None and time.monotonic() > deadline:
                raise subprocess.TimeoutExpired(self.args, timeout)
            time.sleep(0.002)
        return self.returncode

    def send_signal(self, sig: int) -> None:
        if self.poll() is None:  # not reaped yet: the pid is still this process's
            os.kill(self.pid, sig)

    def communicate(self, timeout: float | None = 300) -> tuple[str, str]:
        """Wait for the end (killed after ``timeout``: TimeoutExpired); stdout and stderr."""
        try:
            self.wait(timeout)
        except subprocess.TimeoutExpired:
            self.send_signal(signal.SIGKILL)
            self.wait()
            raise
        return tuple(self.files[k].read_text(encoding="utf-8", errors="replace")
                     for k in ("out", "err"))

    def modules(self) -> frozenset[str]:
        self.wait()
        return frozenset(json.loads(self.files["modules"].read_text()))


#: what every command's start loads: units, the CLI's option conversion (typer's, through
#: pydantic), the terminal's tables, and the shaft governor's scipy numerics (its valve table)
COMMON = ("numpy", "pint", "pydantic", "typer", "rich.console", "rich.table",
          "scipy.interpolate", "govopt.units:ureg")
#: what ``govopt study`` loads
STUDY = (*COMMON, "pandas", "govopt.cli", "govopt.study", "govopt.commands.study")
#: what every command loads, for :func:`run`'s shared server
EVERY = (*COMMON, "numpy.fft", "numpy.ma", "numpy.polynomial", "openpyxl",
         "xml.sax.saxutils", "tomlkit", "pandas", "govopt.commands.common",
         "govopt.commands.evaluate", "govopt.commands.spring", "govopt.commands.study",
         "govopt.spec", "govopt.fidelity", "govopt.evaluator", "govopt.optimize.search",
         "govopt.report.text", "govopt.report.files", "govopt.report.excel", "govopt.study",
         "govopt.spring_command", "govopt.made", "govopt.made_words")


class Server:
    """The forking server (a context manager): ``start(*args, cwd=None, modules=False)`` runs
    ``govopt ARGS`` in ``cwd`` (default the server's); ``preload``: the modules it imports
    first (``module:attribute`` also builds the attribute); ``cwd`` and ``env``: its folder and
    environment (default this process's, with this checkout first on PYTHONPATH)."""

    def __init__(self, preload=STUDY, *, cwd=None, env=None):
        root = Path(__file__).resolve().parent.parent
        self.folder = tempfile.TemporaryDirectory(prefix="govopt-forkcli-")
        self.count = 0
        self.lock = threading.Lock()  # one request at a time, from any thread
        env = env or {**os.environ, "PYTHONPATH": os.pathsep.join(
            [str(root), *filter(None, [os.environ.get("PYTHONPATH")])])}
        self.proc = subprocess.Popen([sys.executable, "-c", _SERVER, *preload], cwd=cwd,
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
                                     env=env)

    def ask(self, request: dict) -> dict:
        with self.lock:
            self.proc.stdin.write(json.dumps(request) + "\n")
            self.proc.stdin.flush()
            line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError(f"the govopt fork server ended (exit {self.proc.wait()})")
        return json.loads(line)

    def start(self, *args, cwd=None, modules: bool = False) -> Proc:
        with self.lock:
            self.count += 1
            n = self.count
        files = {k: Path(self.folder.name) / f"{n}.{k}" for k in ("out", "err", "modules")}
        args = [str(a) for a in args]
        pid = self.ask({"op": "start", "args": args, "out": str(files["out"]),
                        "err": str(files["err"]), "cwd": None if cwd is None else str(cwd),
                        "modules": str(files["modules"]) if modules else None})["pid"]
        return Proc(self, args, pid, files)

    def run(self, *args, cwd=None, timeout: float | None = 120) -> subprocess.CompletedProcess:
        """``govopt ARGS`` in ``cwd`` to its end, as :func:`subprocess.run` with
        ``capture_output=True, text=True`` would report it."""
        p = self.start(*args, cwd=cwd)
        out, err = p.communicate(timeout)
        return subprocess.CompletedProcess(p.args, p.returncode, out, err)

    def close(self) -> None:
        """Stop the server and wait for it: its CPU time and its children's then count among
        this process's children, as a subprocess's do (``time pytest`` measures them)."""
        if self.proc.poll() is None:
            self.proc.stdin.close()
            self.proc.wait(timeout=60)
            self.proc.stdout.close()
        self.folder.cleanup()

    def __enter__(self) -> Server:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


@functools.cache
def shared() -> Server:
    """One server for the test process (:data:`EVERY` loaded), stopped at its exit."""
    server = Server(EVERY)
    atexit.register(server.close)
    return server


def run(args, cwd, timeout: float | None = None) -> subprocess.CompletedProcess:
    """:meth:`Server.run` on the :func:`shared` server."""
    return shared().run(*args, cwd=cwd, timeout=timeout)
