"""``govopt`` in a process of its own, as a user starts it: ``python -m govopt.cli ARGS`` (the
console entry point's code: its SIGTERM handler, one BLAS thread, its catch-all), stdin on
/dev/null, stdout and stderr in temporary files (a chatty command never blocks on a full pipe).
:func:`start` gives a :class:`subprocess.Popen` to kill, run beside another or wait for::

    proc = cliproc.start("study", "run", spec, "--db", db, cwd=folder)
    os.kill(proc.pid, signal.SIGKILL)
    out, err = proc.communicate(timeout=60)   # proc.returncode: -9

:func:`run` runs one to its end, as :func:`subprocess.run` with ``capture_output=True,
text=True`` reports it. With ``modules=True`` the process also lists the modules it had loaded
at its end (``proc.modules()``, for the import tests): a fresh interpreter's, as a user's."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: ``govopt ARGS`` that writes ``sorted(sys.modules)`` to the file named first, at its end
_LISTING = """import json, sys
listing, sys.argv = sys.argv[1], ["govopt", *sys.argv[2:]]
from govopt.cli import main
try:
    main()
finally:
    with open(listing, "w") as fh:
        json.dump(sorted(sys.modules), fh)
"""


class Proc(subprocess.Popen):
    """``govopt ARGS`` running (a :class:`subprocess.Popen`): ``communicate(timeout)`` waits
    for its end (killed after ``timeout``: TimeoutExpired) and gives its stdout and stderr."""

    def __init__(self, args, cwd=None, env=None, modules: bool = False):
        if env is None:  # this checkout's govopt, whatever is installed
            env = {**os.environ, "PYTHONPATH": os.pathsep.join(
                [str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])}
        self.files = tempfile.TemporaryFile(), tempfile.TemporaryFile()
        self.texts = None  # stdout and stderr, once ended
        self.listing = None
        if modules:
            fd, self.listing = tempfile.mkstemp(suffix=".json")
            os.close(fd)
            command = [sys.executable, "-c", _LISTING, self.listing, *args]
        else:
            command = [sys.executable, "-m", "govopt.cli", *args]
        super().__init__(command, cwd=cwd, env=env, stdin=subprocess.DEVNULL,
                         stdout=self.files[0], stderr=self.files[1])

    def communicate(self, timeout: float | None = 300) -> tuple[str, str]:
        try:
            self.wait(timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            self.wait()
            raise
        if self.texts is None:
            self.texts = []
            for fh in self.files:
                fh.seek(0)
                self.texts.append(fh.read().decode("utf-8", errors="replace"))
                fh.close()
        return self.texts[0], self.texts[1]

    def modules(self) -> frozenset[str]:
        """The modules loaded at the end (started with ``modules=True``)."""
        self.communicate()
        try:
            return frozenset(json.loads(Path(self.listing).read_text()))
        finally:
            os.unlink(self.listing)


def start(*args, cwd=None, env=None, modules: bool = False) -> Proc:
    """``govopt ARGS`` started in ``cwd`` (``env``: default this process's, with this checkout
    first on PYTHONPATH)."""
    return Proc([str(a) for a in args], cwd=cwd, env=env, modules=modules)


def run(args, cwd=None, timeout: float | None = 120, env=None) -> subprocess.CompletedProcess:
    """``govopt ARGS`` in ``cwd`` to its end."""
    p = start(*args, cwd=cwd, env=env)
    out, err = p.communicate(timeout)
    return subprocess.CompletedProcess(p.args, p.returncode, out, err)
