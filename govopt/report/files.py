"""Output files that never destroy anything, and the design-as-spec writer (formats only).

Every file govopt writes goes through :func:`atomic_write`: the content is written to a
temporary file ``.<name>.govopt-tmp-<pid>-<random>`` in the destination folder and renamed
into place, so the output is either absent, the previous file, or the complete new file. The
temporary file is removed on every exit path Python sees (exceptions, ``SystemExit`` from the
CLI's SIGTERM handler, Ctrl-C); one left by a run killed with SIGKILL is removed by the next
write into that folder (its process is gone) and otherwise never looked at. Only a regular file
is ever replaced, and only with ``overwrite=True`` (the CLI's ``--force``, ``govopt spring``'s
``--replace``: :func:`overwrite_option`); a new file gets mode
0666 minus the umask, a replaced file keeps its mode.
"""

from __future__ import annotations

import contextlib
import contextvars
import errno
import math
import os
import re
import secrets
import signal
import stat
from collections.abc import Callable, Iterable
from pathlib import Path

from ..errors import GovoptError
from ..result import Result
from ..units import G_STANDARD

_TMP_TAG = ".govopt-tmp-"
_TMP_NAME = re.compile(r"\..*\.govopt-tmp-(\d+)-[0-9a-f]+")
_CLOEXEC = getattr(os, "O_CLOEXEC", 0)
_OVERWRITE = contextvars.ContextVar("govopt_overwrite", default=True)
#: the running command's option that allows replacing (:func:`overwrite_option`), named in
#: the "already exists" messages: ``--force``, but ``govopt spring`` spells it ``--replace``
#: (its ``--force`` is the spring's force)
_OPTION = contextvars.ContextVar("govopt_overwrite_option", default="--force")
#: the folders :func:`output_folder` made within :func:`removed_on_error` (None outside)
_MADE = contextvars.ContextVar("govopt_made_folders", default=None)
_KINDS = ((stat.S_ISDIR, "a directory"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISFIFO, "a FIFO"), (stat.S_ISSOCK, "a socket"))


def _kind(mode: int) -> str:
    return next((name for test, name in _KINDS if test(mode)), "not a regular file")


def _reason(exc: OSError) -> str:
    return exc.strerror or str(exc)


def _alive(pid: int) -> bool:
    """Whether process ``pid`` exists (a reused pid counts as alive: its file is only kept). Off
    POSIX every process counts as alive (there ``os.kill`` would end it)."""
    if os.name != "posix":
        return True
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    except (OverflowError, OSError):
        return False
    return True


def remove_stale_temps(directory: str | Path) -> list[Path]:
    """Remove govopt temporary files in ``directory`` whose process is gone; return them."""
    removed = []
    with contextlib.suppress(OSError), os.scandir(directory) as entries:
        for entry in entries:
            match = _TMP_NAME.fullmatch(entry.name)
            if match and not _alive(int(match[1])):
                with contextlib.suppress(OSError):
                    if entry.is_file(follow_symlinks=False):
                        os.unlink(entry.path)
                        removed.append(Path(entry.path))
    return removed


def names_folder(path: str | Path) -> bool:
    """Whether ``path`` as typed ends with a separator (``out/``): it names a folder. (A
    :class:`~pathlib.Path` has dropped it: the CLI passes outputs on as the text typed.)"""
    return isinstance(path, str) and path.endswith(tuple(filter(None, (os.sep, os.altsep))))


#: the installed package's own folder (its data; its bundled specs in a plain install) and the
#: bundled specs' folder (``specs/`` of an editable install): govopt writes nothing there
PACKAGE = Path(__file__).resolve().parent.parent


def refuse_package(path: str | Path, what: str) -> None:
    """One line (:class:`GovoptError`) if ``path`` (a file or folder to write, through any
    symbolic link) lies inside the installed package, whose bundled specs and data every run
    reads: an ``-o ... --force`` there would replace a bundled spec for every later run. The
    one rule for every output of every command (design specs, workbooks, plots, copies of
    examples, benchmark reports, study databases and tables)."""
    from ..examples import SPECS

    real = Path(os.path.realpath(path))
    for folder in (PACKAGE, SPECS.resolve()):
        if real == folder or folder in real.parents:
            raise GovoptError(f"{path}: cannot write {what} inside the installed govopt package "
                              f"({folder}), whose bundled specs and data it reads; write it "
                              "elsewhere (govopt init NAME copies a bundled spec to start from)")


def _file_name(path: str | Path, what: str) -> Path:
    """``path`` as a file's path, refused (one line) if it names a folder."""
    if str(path) == "" or Path(path).name in ("", ".", ".."):
        raise GovoptError(f"{what}: expected a file name, got {str(path)!r}")
    if names_folder(path) and not os.path.isdir(path):
        raise GovoptError(f"{path}: cannot write {what}: a name ending in '/' is a folder, and "
                          f"{path} does not exist; expected a file name")
    return Path(path)


def output_folder(directory: str | Path, what: str) -> Path:
    """The folder ``directory`` for outputs, made if only its parent exists (as ``--plots``);
    one line if it is not a folder or cannot be made."""
    directory = Path(directory)
    refuse_package(directory, what)
    try:
        is_dir = directory.is_dir()
    except OSError as exc:  # a name the system refuses (too long)
        raise GovoptError(f"{directory}: cannot write {what} ({_reason(exc)})") from None
    if is_dir:
        return directory
    if directory.exists() or directory.is_symlink():
        raise GovoptError(f"{directory}: cannot write {what}: it is not a folder")
    if not directory.absolute().parent.is_dir():
        raise GovoptError(f"{directory}: cannot write {what}: folder {directory.parent} does not "
                          "exist")
    try:
        directory.mkdir()
    except OSError as exc:
        raise GovoptError(f"{directory}: cannot make the folder for {what} "
                          f"({_reason(exc)})") from None
    made = _MADE.get()
    if made is not None:
        made.append(directory)
    return directory


@contextlib.contextmanager
def removed_on_error():
    """Within this block, a folder :func:`output_folder` makes is removed again (if it is still
    empty) when the block ends in an error: a refused run leaves no empty folder behind."""
    made: list[Path] = []
    token = _MADE.set(made)
    try:
        yield
    except BaseException:
        for folder in reversed(made):
            with contextlib.suppress(OSError):
                folder.rmdir()
        raise
    finally:
        _MADE.reset(token)


def check_output(path: str | Path, *, overwrite: bool = False, inputs: Iterable = (),
                 others: Iterable = (), databases: Iterable = (), what: str = "output") -> Path:
    """Check before a run that ``path`` can be written: a file name (not a folder's: ``x/``),
    its folder exists, it is not the input (``inputs``), a study's database (``databases``)
    nor another output of the same run (``others``), and it is absent or a regular file that
    ``overwrite`` allows to replace. Raises :class:`GovoptError` with one line."""
    path = _file_name(path, what)
    try:
        st = os.stat(path)
    except FileNotFoundError:
        st = None
    except OSError as exc:
        raise GovoptError(f"{path}: cannot use as {what} ({_reason(exc)})") from None
    if st is None:
        parent = path.parent
        if not parent.is_dir():
            raise GovoptError(f"{path}: cannot write {what}: folder {parent} does not exist")
    elif not stat.S_ISREG(st.st_mode):
        raise GovoptError(f"{path}: cannot write {what}: it is {_kind(st.st_mode)} "
                          "(govopt only ever replaces regular files)")
    real = Path(os.path.realpath(path))
    for other, role in [(p, "the input spec") for p in inputs] + \
                       [(p, "the study database") for p in databases] + \
                       [(p, "another output of this run") for p in others]:
        same = real == Path(os.path.realpath(other))
        if not same and st is not None:
            with contextlib.suppress(OSError):
                same = os.path.samefile(path, other)
        if same:
            raise GovoptError(f"{path}: cannot write {what}: it is the same file as {role} "
                              f"({other})")
    refuse_package(path, what)
    if st is not None and not overwrite:
        raise GovoptError(f"{path}: {what} already exists; use {_OPTION.get()} to replace it")
    tmp = None
    try:  # a probe, so that an unwritable folder fails now rather than after the run
        with _signals_held():
            tmp = _create_temp(real.parent, real.name, None)
    except OSError as exc:
        raise GovoptError(f"{path}: cannot write {what} ({_reason(exc)})") from None
    finally:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
    return path


def check_planned(planned: Iterable[tuple[str | Path, str]], *, overwrite: bool = False,
                  inputs: Iterable = ()) -> None:
    """Every file a run will write (``planned``: ``(path, what)`` in order), each checked by
    :func:`check_output` before anything is computed or written: against the input and against
    every *other* planned output by position (two outputs named alike are a collision, however
    the names are spelt), whatever ``overwrite`` says. Raises :class:`GovoptError` with one
    line."""
    planned = list(planned)
    inputs = list(inputs)
    for i, (path, what) in enumerate(planned):
        check_output(path, overwrite=overwrite, inputs=inputs, what=what,
                     others=[p for j, (p, _) in enumerate(planned) if j != i])


@contextlib.contextmanager
def overwrite_policy(allowed: bool):
    """Within this block, writers called without ``overwrite`` (e.g.
    :func:`govopt.report.excel.write_workbook`) replace an existing file only if ``allowed``
    (the CLI's ``--force``); the library's default outside is to replace."""
    token = _OVERWRITE.set(allowed)
    try:
        yield
    finally:
        _OVERWRITE.reset(token)


@contextlib.contextmanager
def overwrite_option(option: str):
    """Within this block, messages of files that exist name ``option`` (the running command's
    way to allow replacing them) instead of ``--force``."""
    token = _OPTION.set(option)
    try:
        yield
    finally:
        _OPTION.reset(token)


@contextlib.contextmanager
def _signals_held():
    """Hold SIGTERM and SIGINT for a few statements, so that a temporary file cannot be created
    without its name being recorded for clean-up."""
    held = {signal.SIGTERM, signal.SIGINT}
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, held)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def _create_temp(directory: Path, name: str, mode: int | None) -> Path:
    """A new empty file ``.<name>.govopt-tmp-<pid>-<random>`` in ``directory`` (0666 minus the
    umask, or ``mode``)."""
    while True:
        tmp = directory / f".{name[:100]}{_TMP_TAG}{os.getpid()}-{secrets.token_hex(4)}"
        try:
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | _CLOEXEC, 0o666)
        except FileExistsError:
            continue
        os.close(fd)
        if mode is not None:
            os.chmod(tmp, mode)
        return tmp


def _fsync(path: Path) -> None:
    fd = os.open(path, os.O_RDONLY | _CLOEXEC)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _commit(tmp: Path, target: Path, overwrite: bool, shown: Path, what: str) -> None:
    """Move the finished ``tmp`` to ``target``: replace only a regular file, and only when
    ``overwrite``; otherwise link without replacing (atomic: fails if ``target`` appeared)."""
    try:
        st = os.stat(target)
    except FileNotFoundError:
        st = None
    if st is not None and not stat.S_ISREG(st.st_mode):
        raise GovoptError(f"{shown}: cannot write {what}: it is {_kind(st.st_mode)} "
                          "(govopt only ever replaces regular files)")
    if overwrite:
        os.replace(tmp, target)
        return
    appeared = GovoptError(f"{shown}: {what} appeared while govopt was running; use "
                           f"{_OPTION.get()} to replace it")
    try:
        os.link(tmp, target)
    except FileExistsError:
        raise appeared from None
    except OSError as exc:  # no hard links on this file system: check, then rename
        if exc.errno not in (errno.EPERM, errno.ENOTSUP, errno.EOPNOTSUPP, errno.ENOSYS,
                             errno.EXDEV, errno.EMLINK):
            raise
        if os.path.lexists(target):
            raise appeared from None
        os.replace(tmp, target)
        return
    os.unlink(tmp)


def atomic_write(path: str | Path, write: Callable[[Path], object], *,
                 overwrite: bool | None = None, what: str = "file") -> Path:
    """Call ``write(tmp)`` on a temporary file beside ``path``, then move it into place.

    ``path`` is either left as it was or holds the complete new content, on every exit path.
    A symbolic link is written through (the file it points to is replaced, the link kept). An
    existing ``path`` must be a regular file and is replaced only with ``overwrite`` (default:
    :func:`overwrite_policy`, outside it True). Any
    :class:`OSError` becomes a one-line :class:`GovoptError` naming ``path`` and ``what``.
    """
    shown = _file_name(path, what)
    refuse_package(shown, what)
    overwrite = _OVERWRITE.get() if overwrite is None else overwrite
    target = Path(os.path.realpath(shown))
    directory = target.parent
    if not directory.is_dir():
        raise GovoptError(f"{shown}: cannot write {what}: folder {shown.parent} does not exist")
    remove_stale_temps(directory)
    tmp = None
    try:
        mode = None
        with contextlib.suppress(FileNotFoundError):
            st = os.stat(target)
            mode = stat.S_IMODE(st.st_mode) if stat.S_ISREG(st.st_mode) else None
            if not overwrite:
                raise GovoptError(f"{shown}: {what} already exists; use {_OPTION.get()} to "
                                  "replace it")
        with _signals_held():
            tmp = _create_temp(directory, target.name, mode)
        write(tmp)
        _fsync(tmp)
        _commit(tmp, target, overwrite, shown, what)
    except BaseException as exc:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
        if isinstance(exc, OSError):
            raise GovoptError(f"{shown}: cannot write {what} ({_reason(exc)})") from exc
        raise
    return shown


#: Design keys never rounded for the drawing: the optimiser picks them from a catalogue
#: (wire sizes of the grade or the grid, turns at the catalogue's step) already.
CATALOGUE_KEYS = ("wire_diameter", "active_turns")

#: Significant digits a drawing carries, tried in turn (:func:`drawn_design`): 4 is 0.1 mm on
#: a length of 100-999 mm; the last, None, writes the exact design.
DRAWING_DIGITS = (4, 5, 6, None)


def design_toml(res: Result, digits: int | None = None) -> str:
    """The spec file of ``res`` with its ``[design]`` table set to the chosen design.

    The engineer's file is edited, not rewritten (tomlkit): comments, order, layout and every
    other value stay as they were. A design key already in ``[design]`` keeps its place, its
    comment, its form (``pendulum_weight`` or ``_mass``, ``dashpot_a1`` or ``dashpot_f``) and
    its unit (a value that reads back exactly keeps its text); a new key takes the unit of the
    same key in ``[bounds]``, else of the spec's first value of that dimension, else SI. Each
    number is written at the shortest precision that reads back to the same float (``"13 mm"``,
    not ``"0.013000000000000001 m"``), so that `govopt evaluate` reproduces the design. Design
    keys the chosen design does not set are removed (an old ``friction_moment`` would change
    the evaluation).

    ``digits``: round each new number (but the catalogue's, :data:`CATALOGUE_KEYS`) to this
    many significant digits in its unit, as a drawing carries it (``"12.64 cm"``, not
    ``"12.63583051390083 cm"``); :func:`drawn_design` checks that the rounded design passes.
    """
    import tomlkit

    spec = res.spec
    try:
        doc = tomlkit.parse(Path(spec.path).read_text(encoding="utf-8-sig"))
    except (OSError, ValueError) as exc:  # tomlkit's ParseError is a ValueError
        raise GovoptError(f"{spec.path}: cannot read the spec to write the design into it "
                          f"({exc})") from None
    table = doc.get("design")
    if table is None:
        table = tomlkit.table()
        table.comment("written by govopt design")
        doc.add(tomlkit.nl())
        doc.add("design", table)
    old, bounds = dict(table), doc.get("bounds") or {}
    values = _design_values(res, old, bounds)
    for key in [k for k in old if k not in values]:
        del table[key]
    _analysis_as_run(doc, spec)
    for key, (dimension, target, scale) in values.items():
        if _close(_reads_as(old.get(key), dimension, scale), target):
            continue  # unchanged: as the engineer wrote it ("9.510 cm" stays)
        if dimension == "dimensionless":
            table[key] = _shortest_number(target)
            continue
        unit = _unit_for(spec, dimension, old.get(key), bounds.get(key) or
                         bounds.get("dashpot_f" if key == "dashpot_a1" else key))
        places = None if key in CATALOGUE_KEYS else digits
        text = _shortest_quantity(target, dimension, unit, scale, places)
        if key in CATALOGUE_KEYS and dimension == "length" and _digits(text) > 6:
            text = _shortest_quantity(target, dimension, "mm", scale)  # a metric size: 2 mm,
            # not 0.078740157480315 in
        table[key] = text
    return tomlkit.dumps(doc)


def _analysis_as_run(doc, spec) -> None:
    """Set the ``[analysis]`` keys of the document ``doc`` to the values the run read
    (:attr:`Spec.data`: the file with the command's options, ``--speed-change range``), so
    that the written spec reproduces the report."""
    import tomlkit

    ran = (spec.data or {}).get("analysis")
    if not isinstance(ran, dict):
        return
    table = doc.get("analysis")
    changed = {k: v for k, v in ran.items() if table is None or table.get(k) != v}
    if not changed:
        return
    if table is None:
        table = tomlkit.table()
        doc.add(tomlkit.nl())
        doc.add("analysis", table)
    for key, value in changed.items():
        table[key] = value
        table[key].comment("as run by govopt design")


def drawn_design(res: Result) -> tuple[str, Result, str]:
    """The design of ``res`` as a drawing carries it: ``(spec text, its Result, note)``.

    Each new number of ``[design]`` is rounded to the fewest of :data:`DRAWING_DIGITS`
    significant digits (catalogue sizes kept) at which the rounded design, read back from the
    text and evaluated again, passes every check the exact design passes (and keeps a yield
    the exact design meets, ``requirements.min_yield``: :mod:`govopt.made`); where none does,
    the exact design is written. The result is the rounded design's evaluation, with the
    optimiser's record of ``res``; the note says what was rounded, or which check rounding
    breaks and what to do.
    """
    import dataclasses
    import tomllib

    from ..evaluator import evaluate
    from ..spec import parse_spec
    from .text import check_name, margin_words

    passed = {c.name for c in res.checks if c.passed}
    first_broken: list[str] = []
    last_broken: list[str] = []
    drawn = res
    for digits in DRAWING_DIGITS:
        text = design_toml(res, digits)
        if digits is None:
            drawn = res
            break
        design = parse_spec(tomllib.loads(text), str(res.spec.path)).design
        if _same_design(design, res.design):
            return text, res, ""  # nothing to round: the design is already as drawn
        drawn = evaluate(res.spec.with_design(design))  # the friction run reads spec.design
        broken = [f"{check_name(c, drawn)} ({margin_words(c)})" for c in drawn.checks
                  if c.name in passed and not c.passed]
        if not broken and _meets(res):  # a yield the exact design meets: kept too
            from ..made import with_yield
            from .text import yield_line

            drawn = with_yield(drawn)
            if not _meets(drawn):
                broken = [f"the yield ({yield_line(drawn)})"]
        if not broken:
            break
        first_broken = first_broken or broken
        last_broken = broken
    if digits is None:
        note = ("design written at full precision: rounded to "
                f"{DRAWING_DIGITS[-2]} significant digits it fails {'; '.join(last_broken)}; "
                "round it by hand with some margin to spare (or tighten the requirement a "
                "little and design again) and check it with govopt evaluate")
    else:
        note = (f"design written rounded to {digits} significant digits for the drawing "
                f"(catalogue sizes kept) and evaluated again: this report is the rounded "
                f"design's, and every check the exact design passed still passes")
        if digits > DRAWING_DIGITS[0]:
            note += (f" ({DRAWING_DIGITS[0]} digits would fail "
                     f"{'; '.join(first_broken)})")
    if drawn is not res:
        notes = [*(res.optimisation or {}).get("notes", []), note]
        drawn = dataclasses.replace(drawn, kind=res.kind,
                                    optimisation={**res.optimisation, "notes": notes})
    elif note:
        drawn = dataclasses.replace(res, optimisation={
            **res.optimisation, "notes": [*(res.optimisation or {}).get("notes", []), note]})
    return text, drawn, note


def _meets(res: Result) -> bool:
    """Whether the result's made governors meet a yield the spec asks for."""
    y = (res.made or {}).get("yield") or {}
    return bool(y.get("meets_required"))


def _design_values(res: Result, old: dict, bounds: dict) -> dict[str, tuple[str, float, float]]:
    """``[design]`` key -> (dimension, SI value it must read back as, divisor from the parsed
    quantity to that value) for the design of ``res``, in the forms the spec's ``[design]``
    (``old``), else its ``[bounds]``, use."""
    gov, d = res.spec.governor, res.design
    angular = gov.coordinate == "angle"
    out: dict[str, tuple[str, float, float]] = {}

    def mass(stem: str, value: float | None) -> None:
        if value is None:
            return
        m = f"{stem}_mass"
        if m in old or (f"{stem}_weight" not in old and m in bounds):
            out[m] = ("mass", value, 1.0)
        else:  # a weight: a force read back through standard gravity
            out[f"{stem}_weight"] = ("force", value, G_STANDARD)

    mass(gov.mass_key, d.flying_mass)
    mass("central", d.central_mass)
    if gov.spring is not None:
        for key in ("spring_stiffness", "leaf_width", "leaf_thickness", "wire_diameter",
                    "coil_radius", "active_turns"):
            value = getattr(d, key)
            if value is not None:
                dimension = {"spring_stiffness": "stiffness", "active_turns": "dimensionless"}
                out[key] = (dimension.get(key, "length"), value, 1.0)
        if d.free_half_length is not None:
            out[gov.free_length_key] = ("length", d.free_half_length, 1.0)
    if d.flying_inertia is not None:
        out[f"{gov.mass_key}_inertia"] = ("inertia" if angular else "mass",
                                          d.flying_inertia, 1.0)
    if d.dashpot is not None:
        damping = "damping" if angular else "linear_damping"
        if "dashpot_a1" in old:  # Hamabe's a1 = f/3
            out["dashpot_a1"] = (damping, d.dashpot / 3.0, 1.0)
        else:
            out["dashpot_f"] = (damping, d.dashpot, 1.0)
    if angular and d.friction_moment is not None:
        out["friction_moment"] = ("moment", d.friction_moment, 1.0)
    return out


_LEADING_NUMBER = re.compile(
    r"\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\s*(?P<unit>[^\s+-].*?)\s*")


def _unit_of(written, dimension: str) -> str | None:
    """The unit of a quantity as written (``"17 mm"`` -> ``"mm"``; a list: its first item), if
    it is one unit of ``dimension`` (not a sum such as ``"64 deg + 40 arcmin"``)."""
    from ..units import UnitError, parse_quantity

    if isinstance(written, list) and written:
        written = written[0]
    match = _LEADING_NUMBER.fullmatch(written) if isinstance(written, str) else None
    if match is None or re.search(r"[+-]", match["unit"]):
        return None
    try:
        parse_quantity(f"1 {match['unit']}", dimension)
    except UnitError:
        return None
    return match["unit"]


def _unit_for(spec, dimension: str, *candidates) -> str:
    """The unit to write a value of ``dimension`` in: the first of ``candidates`` (values as
    written) that has one, else that of the spec's first value of the dimension, else SI."""
    from ..units import SI_UNITS

    si = SI_UNITS[dimension]
    written = [e.written for e in spec.entries if e.unit == si]
    for value in (*candidates, *written):
        unit = _unit_of(value, dimension)
        if unit is not None:
            return unit
    return si


def _reads_as(written, dimension: str, scale: float) -> float | None:
    """The value a spec's ``written`` value reads as (divided by ``scale``), None if none."""
    from ..units import UnitError, parse_quantity

    if isinstance(written, bool) or not isinstance(written, str | int | float):
        return None
    try:
        return parse_quantity(written, dimension) / scale
    except UnitError:
        return None


def _digits(quantity: str) -> int:
    """The significant digits of a quantity's number: ``"0.0787401 in"`` -> 6."""
    number = quantity.split(" ", 1)[0]
    return len(re.sub(r"e.*|[-+.]", "", number.lower()).strip("0"))


def _shortest_number(value: float) -> int | float:
    """``value`` as an int where it is whole, else the float (TOML writes its shortest repr)."""
    return int(value) if float(value).is_integer() and abs(value) < 2**53 else float(value)


#: Units in ulps of the value: how far a quantity that is exact in its unit may read back from
#: the float it stands for, through the conversion's own rounding (a product and a quotient:
#: "3.5 kgf" reads as 3.4999999999999996 kg, and no decimal in kgf reads as 3.5 kg exactly).
READ_BACK_ULPS = 4


def _close(value: float | None, target: float) -> bool:
    return value is not None and abs(value - target) <= READ_BACK_ULPS * math.ulp(target)


def _shortest_quantity(target: float, dimension: str, unit: str, scale: float = 1.0,
                       digits: int | None = None) -> str:
    """``"<number> <unit>"`` with the fewest significant digits that parses back to ``target``
    (after dividing by ``scale``; to within :data:`READ_BACK_ULPS`), else to the nearest value
    any digits reach; with ``digits``, the number rounded to that many significant digits.

    >>> _shortest_quantity(0.013, "length", "mm"), _shortest_quantity(4.0, "force", "kgf", 9.80665)
    ('13 mm', '4 kgf')
    >>> _shortest_quantity(0.1263583051390083, "length", "cm", digits=4)
    '12.64 cm'
    """
    from ..units import parse_quantity

    value = target * scale / parse_quantity(f"1 {unit}", dimension)
    if digits is not None:
        return f"{_shortest_number(float(f'{value:.{digits}g}'))!r} {unit}"
    best = None
    for digits in range(1, 18):
        number = float(f"{value:.{digits}g}")
        text = f"{_shortest_number(number)!r} {unit}"
        value_read = parse_quantity(text, dimension) / scale
        if _close(value_read, target):
            return text
        error = abs(value_read - target)
        if best is None or error < best[0]:
            best = (error, text)
    return best[1]


def _same_design(a, b) -> bool:
    """Whether two designs are the same up to the unit conversions' rounding
    (:data:`READ_BACK_ULPS`)."""
    import dataclasses

    for f in dataclasses.fields(a):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if {x, y} <= {None, 0.0}:  # a springless type's free length: 0.0 designed, None read
            continue
        if isinstance(x, float) and isinstance(y, float):
            if not _close(x, y):
                return False
        elif x != y:
            return False
    return True


def write_design_spec(res: Result, path: str | Path, *, overwrite: bool | None = None,
                      text: str | None = None) -> Path:
    """Write the design of ``res`` as a spec file (:func:`design_toml`; ``text``: the spec's
    text already made, :func:`drawn_design`'s) atomically."""
    text = design_toml(res) if text is None else text
    return atomic_write(path, lambda tmp: tmp.write_text(text, encoding="utf-8"),
                        overwrite=overwrite, what="design spec")
