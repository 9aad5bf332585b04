"""Outputs never destroy anything, spec files are read safely, the CLI never shows a traceback;
and govopt killed (SIGTERM, SIGKILL) at many moments never leaves a corrupt output or a stray
temporary file."""

import os
import signal
import stat
import subprocess
import sys
import threading
import time
import tomllib
import warnings
import zipfile
from pathlib import Path
from xml.etree import ElementTree

import forkcli
import openpyxl
import pytest
from clirun import invoke

from govopt.errors import GovoptError
from govopt.report import excel
from govopt.report.files import PACKAGE, atomic_write, check_output, remove_stale_temps
from govopt.spec import SpecError, load_spec

SPECS = Path(__file__).resolve().parent.parent / "specs"
SPEC_A, SPEC_DESIGN = SPECS / "hamabe-a.toml", SPECS / "hamabe-design.toml"
#: passes every check, so a complete `govopt evaluate` exits 0 (case a misses its irregularity)
SPEC_PASS = SPECS / "hamabe-b.toml"
CLI = [sys.executable, "-m", "govopt.cli"]
TAG = ".govopt-tmp-"


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _temps(directory: Path) -> list[str]:
    return sorted(n for n in os.listdir(directory) if TAG in n)


def _writing(directory: Path) -> bool:
    """A temporary file with content exists (the empty one of the check before the run is
    not a write)."""
    for name in _temps(directory):
        try:
            if os.stat(directory / name).st_size > 0:
                return True
        except FileNotFoundError:
            pass
    return False


def _dead_pid() -> int:
    p = subprocess.Popen([sys.executable, "-c", "pass"])
    p.wait()
    return p.pid


def _run(args):
    return invoke(args)


def _one_error_line(result, code=2) -> str:
    assert result.exit_code == code, result.output
    assert "Traceback" not in result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1, result.output
    return lines[0]


def _assert_valid_xlsx(path: Path) -> None:
    """Opens in openpyxl with govopt's sheets (in their order; the Spring and Optimisation
    sheets where they apply), and every XML part parses (expat, as minidom's parser, without
    building a DOM in Python: a tenth of the time)."""
    names = openpyxl.load_workbook(path).sheetnames
    assert names == [s for s in excel.SHEETS if s in names]
    assert {"Summary", "Design", "Checks", "Characteristic", "Method"} <= set(names)
    with zipfile.ZipFile(path) as z:
        for name in z.namelist():
            if name.endswith((".xml", ".rels")):
                ElementTree.fromstring(z.read(name))


# ------------------------------------------------------------------------------------------
# atomic_write: one implementation for every output


def test_new_file_gets_umask_mode_and_replace_keeps_mode(tmp_path):
    new = atomic_write(tmp_path / "a.txt", lambda t: t.write_text("one"))
    assert stat.S_IMODE(new.stat().st_mode) == 0o666 & ~_umask()  # not mkstemp's 0600
    new.chmod(0o640)
    atomic_write(new, lambda t: t.write_text("two"))
    assert new.read_text() == "two" and stat.S_IMODE(new.stat().st_mode) == 0o640
    assert os.listdir(tmp_path) == ["a.txt"]


def test_no_overwrite_leaves_existing_file(tmp_path):
    target = tmp_path / "a.txt"
    target.write_text("precious")
    with pytest.raises(GovoptError, match="already exists; use --force"):
        atomic_write(target, lambda t: t.write_text("new"), overwrite=False)
    assert target.read_text() == "precious" and os.listdir(tmp_path) == ["a.txt"]
    atomic_write(tmp_path / "b.txt", lambda t: t.write_text("new"), overwrite=False)
    assert (tmp_path / "b.txt").read_text() == "new"


def test_output_appearing_during_the_run_is_not_replaced(tmp_path):
    target = tmp_path / "a.txt"

    def write(tmp):
        tmp.write_text("new")
        target.write_text("someone else's")  # created while govopt was computing

    with pytest.raises(GovoptError, match="appeared while govopt was running"):
        atomic_write(target, write, overwrite=False)
    assert target.read_text() == "someone else's" and os.listdir(tmp_path) == ["a.txt"]


@pytest.mark.parametrize("kind", ["fifo", "directory"])
def test_only_regular_files_are_replaced(tmp_path, kind):
    target = tmp_path / "t"
    if kind == "fifo":
        os.mkfifo(target)
    else:
        target.mkdir()
    with pytest.raises(GovoptError, match="only ever replaces regular files"):
        atomic_write(target, lambda t: t.write_text("x"), overwrite=True)
    assert (stat.S_ISFIFO if kind == "fifo" else stat.S_ISDIR)(os.lstat(target).st_mode)
    assert os.listdir(tmp_path) == ["t"]


def test_symlink_is_written_through(tmp_path):
    real = tmp_path / "real.txt"
    real.write_text("old")
    (tmp_path / "link.txt").symlink_to(real)
    atomic_write(tmp_path / "link.txt", lambda t: t.write_text("new"))
    assert (tmp_path / "link.txt").is_symlink() and real.read_text() == "new"


@pytest.mark.parametrize("exc", [RuntimeError("writer failed"), KeyboardInterrupt(),
                                 SystemExit(143), OSError(28, "No space left on device")])
def test_temp_file_removed_on_every_exit_path(tmp_path, exc):
    target = tmp_path / "a.txt"
    target.write_text("old")

    def write(tmp):
        tmp.write_text("half")
        raise exc

    with pytest.raises(GovoptError if isinstance(exc, OSError) else type(exc)):
        atomic_write(target, write)
    assert os.listdir(tmp_path) == ["a.txt"] and target.read_text() == "old"


def test_stale_temps_of_dead_processes_removed_at_next_write(tmp_path):
    dead = tmp_path / f".w.xlsx{TAG}{_dead_pid()}-0123abcd"
    alive = tmp_path / f".w.xlsx{TAG}{os.getpid()}-0123abcd"  # a running writer's: kept
    other = tmp_path / ".w.xlsx.tmp1234"  # not govopt's pattern: never touched
    for p in (dead, alive, other):
        p.write_text("partial")
    atomic_write(tmp_path / "w.xlsx", lambda t: t.write_text("complete"))
    assert sorted(os.listdir(tmp_path)) == sorted([alive.name, other.name, "w.xlsx"])
    assert remove_stale_temps(tmp_path) == []


def test_long_file_name_still_gets_a_temporary_file(tmp_path):
    name = "a" * 250 + ".txt"  # the temporary name would exceed NAME_MAX if not shortened
    atomic_write(tmp_path / name, lambda t: t.write_text("x"))
    assert os.listdir(tmp_path) == [name]


# ------------------------------------------------------------------------------------------
# check_output: before the run


def test_check_output_refuses_the_input_spec_in_any_spelling(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text("x = 1")
    (tmp_path / "hard.toml").hardlink_to(spec)
    (tmp_path / "soft.toml").symlink_to(spec)
    for out in (spec, tmp_path / "." / "s.toml", tmp_path / "hard.toml", tmp_path / "soft.toml"):
        with pytest.raises(GovoptError, match="same file as the input spec"):
            check_output(out, overwrite=True, inputs=[spec])
    assert spec.read_text() == "x = 1"


def test_check_output_refuses_two_outputs_in_one_file(tmp_path):
    a = tmp_path / "out"
    with pytest.raises(GovoptError, match="same file as another output"):
        check_output(a, others=[tmp_path / "." / "out"])


@pytest.mark.parametrize("path, message", [
    ("/dev/null", "character device"), ("/tmp", "a directory"), ("", "expected a file name"),
    ("/proc/x.toml", "cannot write"), ("/nonexistent-folder/x.toml", "does not exist")])
def test_check_output_bad_targets(path, message):
    with pytest.raises(GovoptError, match=message):
        check_output(Path(path), overwrite=True)
    assert os.path.exists("/dev/null") and stat.S_ISCHR(os.stat("/dev/null").st_mode)


# ------------------------------------------------------------------------------------------
# the CLI: --force, one line, exit codes


def test_cli_existing_output_needs_force(tmp_path):
    out = tmp_path / "w.xlsx"
    out.write_bytes(b"precious")
    line = _one_error_line(_run(["evaluate", SPEC_A, "--xlsx", out]))
    assert line == f"error: {out}: workbook already exists; use --force to replace it"
    assert out.read_bytes() == b"precious"
    run = _run(["evaluate", SPEC_A, "--xlsx", out, "--force"])
    # exit 1: case a misses its irregularity 0.12 (a failed check exits 1); the
    # workbook is written all the same
    assert run.exit_code == 1, run.output
    _assert_valid_xlsx(out)
    assert os.listdir(tmp_path) == ["w.xlsx"]


@pytest.mark.parametrize("args, message", [
    (["evaluate", SPEC_A, "--xlsx", SPEC_A, "--force"], "same file as the input spec"),
    (["design", SPEC_DESIGN, "-o", "{d}/x", "--xlsx", "{d}/./x"], "same file as another output"),
    (["design", SPEC_DESIGN, "-o", "/dev/null", "--force"], "character device"),
    (["design", SPEC_DESIGN, "-o", "/proc/x.toml"], "cannot write design spec"),
    (["design", SPEC_DESIGN, "-o", "{d}"], "is a directory"),
    (["design", SPEC_DESIGN, "-o", ""], "expected a file name"),
    (["evaluate", SPEC_A, "--plots", "{d}/p", "--xlsx", "{d}/p"], "it is the plots folder"),
    (["evaluate", SPEC_A, "--plots", "{d}/p", "--xlsx", "{d}/p/w.xlsx"], "folder {d}/p does not "
                                                                          "exist"),
    (["init", "hamabe-a", "-o", ""], "-o: expected a file or folder name, got ''")])
def test_cli_bad_outputs_fail_at_once_with_one_line(tmp_path, monkeypatch, args, message):
    """A bad output path fails with one line before the evaluation or the search runs."""
    ran = []
    for target in ("govopt.optimize.search.design", "govopt.evaluator.evaluate"):
        monkeypatch.setattr(target, lambda *a, target=target, **k: ran.append(target))
    before = SPEC_A.read_bytes()
    result = _run([str(a).format(d=tmp_path) for a in args])
    line = _one_error_line(result)
    assert message.format(d=tmp_path) in line, line
    assert ran == []
    assert SPEC_A.read_bytes() == before and os.listdir(tmp_path) == []


SPRING = ("--force", "606 kgf", "--stiffness", "59.7 kgf/cm", "--allowable-stress",
          "4000 kgf/cm^2", "--shear-modulus", "850000 kgf/cm^2")
SPRING_CHECK = ("--wire-diameter", "3 mm", "--mean-diameter", "20 mm", "--free-length", "60 mm",
                "--force", "100 N", "--active-coils", "8", "--material", "EN10270-1 SH")


@pytest.mark.parametrize("command", [("spring", *SPRING), ("spring", "check", *SPRING_CHECK)])
def test_refused_spring_outputs_leave_no_folder(tmp_path, command):
    """A spring's workbook onto the folder its plots would make: one line, exit 2, and no
    empty folder left behind."""
    result = _run([*command, "--plots", f"{tmp_path}/p", "--xlsx", f"{tmp_path}/p"])
    assert "it is the plots folder of this run" in _one_error_line(result)
    assert os.listdir(tmp_path) == []


def test_cli_unexpected_error_is_one_line_exit_3(monkeypatch):
    import govopt.evaluator

    def broken(spec):
        warnings.warn("noise that must not be shown", RuntimeWarning, stacklevel=1)
        raise ZeroDivisionError("float division by zero\nsecond line")

    monkeypatch.setattr(govopt.evaluator, "evaluate", broken)
    line = _one_error_line(_run(["evaluate"]), code=3)
    assert line.startswith("internal error: ZeroDivisionError: float division by zero second")
    assert "please report" in line and "--debug" in line
    with pytest.warns(RuntimeWarning, match="noise"):  # --debug shows warnings as they come
        debug = _run(["--debug", "evaluate"])
    assert isinstance(debug.exception, ZeroDivisionError)  # --debug lets the traceback through


def test_cli_debug_from_the_environment(monkeypatch):
    """GOVOPT_DEBUG=1 is --debug; 0 (or empty) is not; anything else is a user's error."""
    import govopt.evaluator

    def broken(spec):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(govopt.evaluator, "evaluate", broken)
    for value, code in (("1", 1), ("yes", 1), ("0", 3), ("", 3), ("maybe", 2)):
        monkeypatch.setenv("GOVOPT_DEBUG", value)
        run = _run(["evaluate"])
        assert run.exit_code == code, (value, run.output)
        assert isinstance(run.exception, ZeroDivisionError) == (code == 1), value
    assert _one_error_line(run) == ("error: GOVOPT_DEBUG: expected 1 or 0 (true/false, yes/no, "
                                    "on/off), got 'maybe'")


def test_cli_warnings_shown_one_line_each_on_success_only(monkeypatch):
    import govopt.evaluator

    real = govopt.evaluator.evaluate

    def noisy(spec):
        warnings.warn("something odd\nin two lines", UserWarning, stacklevel=1)
        return real(spec)

    monkeypatch.setattr(govopt.evaluator, "evaluate", noisy)
    result = _run(["evaluate"])
    # the run completes (exit 1: case a's irregularity check fails): warnings
    # are shown after a completed run whatever its checks say
    assert result.exit_code == 1 and "warning: something odd" in result.stderr
    assert "UserWarning" not in result.output and "stacklevel" not in result.output


def test_control_characters_in_names_give_a_valid_workbook(tmp_path):
    text = SPEC_A.read_text().replace('name = "', 'name = "\\u0007bell\\u001b[31m', 2)
    assert text.count("\\u0007bell") == 2  # the spec's name and the load change's
    spec = tmp_path / "ctl.toml"
    spec.write_text(text)
    out = tmp_path / "ctl.xlsx"
    result = _run(["evaluate", spec, "--xlsx", out])
    assert result.exit_code == 1, result.output  # case a's failed check
    _assert_valid_xlsx(out)
    assert "\\x07bell\\x1b[31m" in openpyxl.load_workbook(out).properties.title


# ------------------------------------------------------------------------------------------
# spec files: regular, bounded, UTF-8, shallow


def test_fifo_spec_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "spec.toml"
    os.mkfifo(fifo)
    outcome = []
    worker = threading.Thread(target=lambda: outcome.append(_run(["evaluate", fifo])),
                              daemon=True)
    worker.start()
    worker.join(10)
    assert outcome, "reading a FIFO spec hangs"
    assert "expected a regular spec file, got a FIFO" in _one_error_line(outcome[0])


@pytest.mark.parametrize("content, message", [
    (b'name = "caf\xe9"\n', r"not UTF-8 text: byte 0xe9 at byte offset 11 \(line 1\)"),
    (b"# ok\n" * 3 + b"\xff", r"byte 0xff at byte offset 15 \(line 4\)"),
    (b"a = " + b"[" * 2000 + b"]" * 2000, r"nested too deeply"),
    (b"a = " + b"{b = " * 2000 + b"1" + b"}" * 2000, r"nested too deeply"),
    (b"a" + b".b" * 40 + b" = 1", r"nested too deeply"),
    (b"#" * (1 << 20) + b"\n", r"larger than 1048576 bytes"),
], ids=["latin-1", "latin-1 line 4", "deep arrays", "deep inline tables", "deep dotted keys",
        "1 MiB + 1"])
def test_bad_spec_bytes(tmp_path, content, message):
    path = tmp_path / "bad.toml"
    path.write_bytes(content)
    with pytest.raises(SpecError, match=message):
        load_spec(path)
    line = _one_error_line(_run(["evaluate", path]))
    assert line.startswith(f"error: {path}: ")


@pytest.mark.parametrize("path, message", [("/dev/zero", "got a device"),
                                           ("/tmp", "got a folder")])
def test_non_regular_spec(path, message):
    with pytest.raises(SpecError, match=message):
        load_spec(path)


def test_utf8_bom_is_accepted(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + SPEC_A.read_bytes())
    assert load_spec(path).name == load_spec(SPEC_A).name


# ------------------------------------------------------------------------------------------
# kill tests: SIGTERM / SIGKILL at many moments


def _kill(args, cwd: Path, sig, delay: float | None):
    """Run ``govopt ARGS`` in a process of its own (:mod:`forkcli`: forked, not a new
    interpreter, so that the moments fall in govopt's work rather than in Python's start-up),
    send ``sig`` after ``delay`` s (None: as soon as a temporary file is written); return
    (returncode, stderr, whether a temporary file was seen)."""
    p = forkcli.shared().start(*args, cwd=cwd)
    seen = False
    if delay is None:
        while p.poll() is None and not seen:
            seen = _writing(cwd)
            if not seen:
                time.sleep(0.0005)
        if seen:
            p.send_signal(sig)
    else:
        try:
            p.wait(timeout=delay)
        except subprocess.TimeoutExpired:
            p.send_signal(sig)
    _, err = p.communicate(timeout=60)
    return p.returncode, err, seen


def _check_outputs(cwd: Path, old: dict[str, bytes]) -> None:
    """Each output is absent, untouched (its old bytes) or a complete valid file."""
    for name in ("out.xlsx", "out.toml"):
        path = cwd / name
        if not path.exists() or old.get(name) == path.read_bytes():
            continue
        if name.endswith(".xlsx"):
            _assert_valid_xlsx(path)
        else:
            assert "design" in tomllib.loads(path.read_text())


def _after_kill(cwd: Path, sig, rc: int, err: str) -> None:
    assert "Traceback" not in err
    if sig == signal.SIGTERM:
        assert rc in (0, 128 + signal.SIGTERM, -signal.SIGTERM), (rc, err)
        assert _temps(cwd) == []  # removed by the dying process itself
    else:
        assert rc in (0, -signal.SIGKILL), (rc, err)
        atomic_write(cwd / "next.txt", lambda t: t.write_text("next run"))  # the next write
        assert _temps(cwd) == []  # ... removes what the killed process left
        os.unlink(cwd / "next.txt")


def _prepare(cwd: Path, existing: bool) -> dict[str, bytes]:
    """An empty folder, or one holding the previous outputs (not valid files: to tell them from
    a new output)."""
    for name in os.listdir(cwd):
        os.unlink(cwd / name)
    old = {"out.xlsx": b"old workbook", "out.toml": b"old = 'design'\n"} if existing else {}
    for name, data in old.items():
        (cwd / name).write_bytes(data)
    return old


@pytest.fixture(scope="module")
def durations(tmp_path_factory):
    """Seconds of one full run of each command, started as the kill tests start theirs (and
    that it succeeds)."""
    d = tmp_path_factory.mktemp("full")
    out = {}
    for cmd, args in (("evaluate", ["evaluate", SPEC_PASS, "--xlsx", "out.xlsx"]),
                      ("design", ["design", SPEC_DESIGN, "--xlsx", "out.xlsx", "-o", "out.toml"])):
        _prepare(d, existing=False)
        t0 = time.perf_counter()
        p = forkcli.run(args, d)
        out[cmd] = time.perf_counter() - t0
        assert p.returncode == 0, p.stderr
        _check_outputs(d, {})
        assert _temps(d) == []
    assert load_spec(d / "out.toml").design is not None
    for name in ("out.toml", "out.xlsx"):  # -o used to write 0600
        assert stat.S_IMODE((d / name).stat().st_mode) == 0o666 & ~_umask()
    return out


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL], ids=["TERM", "KILL"])
def test_kill_evaluate_at_many_moments(tmp_path, durations, sig):
    n = 6
    for i in range(n):
        delay = durations["evaluate"] * (0.5 + 0.6 * i / (n - 1))  # 0.5 .. 1.1 of a run
        existing = i % 2 == 1
        old = _prepare(tmp_path, existing)
        args = ["evaluate", SPEC_PASS, "--xlsx", "out.xlsx"] + (["--force"] if existing else [])
        rc, err, _ = _kill(args, tmp_path, sig, delay)
        _after_kill(tmp_path, sig, rc, err)
        _check_outputs(tmp_path, old)


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL], ids=["TERM", "KILL"])
@pytest.mark.parametrize("command", ["evaluate", "design"])
def test_kill_while_writing(tmp_path, durations, sig, command):
    """The signal is sent the moment a temporary file appears: in the middle of a write. A
    small file (the design spec) can be written and renamed between its temporary file being
    seen and SIGKILL landing; then nothing is left to clean up, and the run is tried again (up
    to 5 times) until the kill leaves a temporary file behind."""
    args = (["evaluate", SPEC_PASS, "--xlsx", "out.xlsx"] if command == "evaluate" else
            ["design", SPEC_DESIGN, "--xlsx", "out.xlsx", "-o", "out.toml"]) + ["--force"]
    for _ in range(5 if sig == signal.SIGKILL else 1):
        old = _prepare(tmp_path, existing=True)
        rc, err, seen = _kill(args, tmp_path, sig, None)
        assert seen, "the run ended before a temporary file was seen"
        _check_outputs(tmp_path, old)
        if sig != signal.SIGKILL or _temps(tmp_path):
            break
    if sig == signal.SIGTERM:
        assert rc == 128 + signal.SIGTERM, (rc, err)
        _after_kill(tmp_path, sig, rc, err)
        return
    assert rc == -signal.SIGKILL and _temps(tmp_path)  # SIGKILL cannot be cleaned up after
    # ... but the next run into that folder ignores the dead process's files and removes them
    # (after the evaluate, a new interpreter: `python -m govopt.cli`, its imports on demand)
    args = ["evaluate", SPEC_PASS, "--xlsx", "out.xlsx", "--force"]
    p = (subprocess.run(CLI + [str(a) for a in args], cwd=tmp_path, capture_output=True,
                        text=True) if command == "evaluate" else forkcli.run(args, tmp_path))
    assert p.returncode == 0, p.stderr
    assert _temps(tmp_path) == []
    _assert_valid_xlsx(tmp_path / "out.xlsx")


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL], ids=["TERM", "KILL"])
def test_kill_design_late(tmp_path, durations, sig):
    for frac in (0.9,):
        old = _prepare(tmp_path, existing=True)
        args = ["design", SPEC_DESIGN, "--xlsx", "out.xlsx", "-o", "out.toml", "--force"]
        rc, err, _ = _kill(args, tmp_path, sig, durations["design"] * frac)
        _after_kill(tmp_path, sig, rc, err)
        _check_outputs(tmp_path, old)


# ---------------------------------------------------------------------------------------------
# a trailing '/' names a folder; bench checks its outputs first


def test_trailing_slash_names_a_folder(tmp_path, monkeypatch):
    """`-o x.toml/`, `--xlsx x.xlsx/`, `--out x.csv/`: a name ending in '/' is a folder, never a
    file of that name; `init -o DIR/new/` makes the folder (its parent exists) and writes into
    it, `init -o missing/new/` refuses."""
    monkeypatch.chdir(tmp_path)
    spec = SPECS / "hamabe-a.toml"
    for args in (["evaluate", spec, "--xlsx", "x.xlsx/"],
                 ["design", SPECS / "hamabe-design.toml", "-o", "y.toml/"],
                 ["study", "run", spec, "--sweep", "speed.irregularity=0.1,0.2", "--db",
                  "s.db", "--out", "s.csv/"]):
        line = _one_error_line(_run(args))
        assert "a name ending in '/' is a folder" in line, line
    assert sorted(p.name for p in tmp_path.iterdir()) == []
    (tmp_path / "dd").mkdir()
    r = _run(["init", "hamabe-a", "-o", "dd/newdir/"])
    assert r.exit_code == 0, r.output
    assert (tmp_path / "dd" / "newdir" / "hamabe-a.toml").read_bytes() == spec.read_bytes()
    assert "folder nodir does not exist" in _one_error_line(
        _run(["init", "hamabe-a", "-o", "nodir/newdir/"]))
    assert not (tmp_path / "nodir").exists()


def test_bench_checks_its_outputs_before_the_benchmark(tmp_path):
    """`bench --out` onto a file, a device or a missing folder, or a folder whose report files
    exist (without --force), fails in a moment with one line, before the benchmark runs."""
    (tmp_path / "f").write_text("keep")
    done = tmp_path / "done"
    done.mkdir()
    (done / "speed-vs-error.csv").write_text("keep")
    for out, expected in ((tmp_path / "f", "not a folder"), ("/dev/null", "not a folder"),
                          (tmp_path / "no" / "x", "does not exist"),
                          (done, "already exists; use --force")):
        t0 = time.perf_counter()
        line = _one_error_line(_run(["bench", "--quick", "--no-targets", "--out", out]))
        assert expected in line and time.perf_counter() - t0 < 5, line
    assert (tmp_path / "f").read_text() == (done / "speed-vs-error.csv").read_text() == "keep"


def test_sigterm_inside_a_bare_except_still_exits_as_sigterm(monkeypatch):
    """SIGTERM raises SystemExit from wherever the process is; inside openpyxl's descriptors
    (``_convert``: a bare ``except:`` around ``float(value)``) it came out as "TypeError:
    expected <class 'float'>", an internal error (exit 3) instead of the signal's 143. The
    handler records the signal, and a command interrupted by it exits by it."""
    from openpyxl.descriptors.base import _convert

    from govopt import cli
    from govopt.commands.common import State, guarded

    monkeypatch.setattr(State, "terminated", 0)

    class Interrupted:
        def __float__(self):  # the signal arriving during float(): the handler runs here
            cli.on_sigterm(signal.SIGTERM, None)

    @guarded
    def command():
        _convert(float, Interrupted())

    previous = signal.getsignal(signal.SIGTERM)
    try:
        with pytest.raises(SystemExit) as exc:
            command()
    finally:
        signal.signal(signal.SIGTERM, previous)
    assert exc.value.code == 128 + signal.SIGTERM


def _package_files() -> dict:
    """Every file of the package folder and of the bundled specs' folder with its size and
    modification time."""
    return {p: (p.stat().st_size, p.stat().st_mtime_ns) for root in (PACKAGE, SPECS)
            for p in root.rglob("*") if p.is_file() and "__pycache__" not in p.parts}


def test_no_command_writes_into_the_package(tmp_path):
    """The bundled specs and data are read by every run: no output of any command goes into
    the package folder, not even an existing bundled spec with ``--force`` nor through a
    symbolic link (one rule, govopt.report.files.refuse_package)."""
    link = tmp_path / "link"
    link.symlink_to(SPECS)
    study = tmp_path / "study.toml"
    study.write_text(SPEC_A.read_text(encoding="utf-8"), encoding="utf-8")
    runs = [
        ["design", SPEC_DESIGN, "-o", SPEC_A, "--force"],
        ["design", SPEC_DESIGN, "-o", link / "hamabe-a.toml", "--force"],
        ["evaluate", SPEC_A, "--xlsx", PACKAGE / "data" / "new.xlsx"],
        ["evaluate", SPEC_A, "--plots", SPECS / "plots"],
        ["init", "hamabe-b", "-o", SPEC_A, "--force"],
        ["init", "hamabe-b", "-o", f"{SPECS}/springs/"],
        ["spring", "--force", "606 kgf", "--stiffness", "59.7 kgf/cm", "--allowable-stress",
         "4000 kgf/cm^2", "--shear-modulus", "850000 kgf/cm^2", "--xlsx", SPECS / "s.xlsx"],
        ["study", "run", study, "--db", SPECS / "new.db", "--sweep",
         "design.pendulum_weight=10 kgf:12 kgf:2"],
        ["bench", "--quick", "--out", SPECS / "bench"],
    ]
    before = _package_files()
    try:
        for args in runs:
            run = invoke([str(a) for a in args])
            assert run.exit_code == 2, (args, run.stderr)
            assert "inside the installed govopt package" in run.stderr, run.stderr
            assert run.stderr.count("\n") == 1, run.stderr
    finally:
        made = set(_package_files()) - set(before)
        for path in made:  # a regression must not leave files in the checkout
            path.unlink()
    assert not made and _package_files() == before
