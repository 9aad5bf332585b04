"""``govopt`` command-line processes without paying Python's, numpy's and pandas's start-up each
time (~1 s of CPU): one server interpreter loads them once and forks a child per command, which
runs ``govopt.cli.main()`` as the console script does (``sys.argv``, its SIGTERM handler, one
BLAS thread) with its stdout and stderr in files, and exits with main's exit code. Each command
is its own process, killed, run beside another and waited for as a ``subprocess.Popen`` is::

    with Server() as server:
        proc = server.start("study", "run", spec, "--db", db)
        os.kill(proc.pid, signal.SIGKILL)
        out, err = proc.communicate(timeout=60)   # proc.returncode: -9

For tests whose subject is the processes (kills, two at once), not the interpreter's imports:
a child holds the modules the server loaded."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

_SERVER = r"""
import json, os, sys, traceback
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # as govopt.cli.main, before numpy loads
import importlib
for name in sys.argv[1:]:  # what the commands will load anyway: "module" or "module:attribute"
    module, _, attribute = name.partition(":")
    module = importlib.import_module(module)
    if attribute:
        getattr(module, attribute)
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
                govopt.cli.main()
                code = 0
            except SystemExit as exc:
                code = exc.code if isinstance(exc.code, int) else 0 if exc.code is None else 1
                if not isinstance(exc.code, int) and exc.code is not None:
                    print(exc.code, file=sys.stderr)
            except BaseException:
                traceback.print_exc()
                code = 1
            sys.stdout.flush()
            sys.stderr.flush()
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
    """A command run by the :class:`Server`: ``pid``, ``poll()``, ``communicate(timeout)`` and
    ``returncode`` as a ``subprocess.Popen``'s."""

    def __init__(self, server: Server, pid: int, out: Path, err: Path):
        self.server, self.pid, self.out, self.err = server, pid, out, err
        self.returncode: int | None = None

    def poll(self) -> int | None:
        if self.returncode is None:
            self.returncode = self.server.ask({"op": "poll", "pid": self.pid})["code"]
        return self.returncode

    def communicate(self, timeout: float = 300) -> tuple[str, str]:
        deadline = time.monotonic() + timeout
        while self.poll() is None:
            if time.monotonic() > deadline:
                raise subprocess.TimeoutExpired(["govopt", "(forked)"], timeout)
            time.sleep(0.01)
        return (self.out.read_text(encoding="utf-8"), self.err.read_text(encoding="utf-8"))


#: what ``govopt study`` loads, and its unit registry (built on first use)
STUDY = ("numpy", "pandas", "govopt.cli", "govopt.study", "govopt.commands.study",
         "govopt.units:ureg")


class Server:
    """The forking server (a context manager): ``start(*args)`` runs ``govopt ARGS`` in
    ``cwd``; ``preload``: the modules it imports first (``module:attribute``: and gets that
    attribute of it); ``env``: its environment (default
    this process's, with this checkout first on PYTHONPATH)."""

    def __init__(self, preload=STUDY, *, cwd=None, env=None):
        root = Path(__file__).resolve().parent.parent
        self.folder = tempfile.TemporaryDirectory(prefix="govopt-forkcli-")
        self.count = 0
        env = env or {**os.environ, "PYTHONPATH": os.pathsep.join(
            [str(root), *filter(None, [os.environ.get("PYTHONPATH")])])}
        self.proc = subprocess.Popen([sys.executable, "-c", _SERVER, *preload], cwd=cwd,
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
                                     env=env)

    def ask(self, request: dict) -> dict:
        self.proc.stdin.write(json.dumps(request) + "\n")
        self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError(f"the govopt fork server ended (exit {self.proc.wait()})")
        return json.loads(line)

    def start(self, *args) -> Proc:
        self.count += 1
        out, err = (Path(self.folder.name) / f"{self.count}.{s}" for s in ("out", "err"))
        pid = self.ask({"op": "start", "args": [str(a) for a in args], "out": str(out),
                        "err": str(err)})["pid"]
        return Proc(self, pid, out, err)

    def __enter__(self) -> Server:
        return self

    def __exit__(self, *exc) -> None:
        self.proc.stdin.close()
        self.proc.stdout.close()
        self.proc.wait(timeout=60)
        self.folder.cleanup()
