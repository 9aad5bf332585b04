"""A study's SQLite database: one row per point, one typed column per input and figure.

Tables (format :data:`FORMAT_VERSION`; docs/reference/study-database.md):

* ``points``: ``point`` (the point's number, the primary key), ``status``, ``message`` and one
  column per input, figure and check (REAL, INTEGER or TEXT), added as the rows bring them;
* ``columns``: each column of ``points``: its SQL type, SI unit (an input's: the unit
  written), role, label (the spec key, figure or check it is), what it is, and the unit a
  person reads it in with its factor (``shown_factor`` SI per shown unit);
* ``meta``: ``format_version``, ``govopt_version`` (the version that started the study) and
  ``govopt_versions`` (every version that wrote to it), the study's ``definition`` and
  ``digest``, and ``total`` (its number of points), each as JSON.

The SQLite header carries govopt's ``application_id`` and the format in ``user_version``: a
database govopt wrote is recognised as its own even when damaged (so ``--force`` may replace
it), and nothing else is ever written into or replaced.

One transaction per block of rows (:meth:`Store.add`), ``INSERT OR IGNORE`` on the point's
number: a process killed at any moment leaves the database as of its last commit, and two
processes running the same study write each point once. The write-ahead journal is used while
a study runs and folded back when it ends (:meth:`Store.close`): no ``-wal`` or ``-shm`` file
is left beside a database that no process holds.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import sqlite3
from collections.abc import Callable, Iterable
from pathlib import Path

import numpy as np
import pandas as pd

from ..errors import GovoptError
from .errors import StudyError
from .keys import study_digest
from .rows import Column, Rows, identifier

#: the format of the database this govopt writes and reads (1: govopt 0.1.0's, every point's
#: figures in one blob; 2: one typed column per figure)
FORMAT_VERSION = 2
#: the SQLite header's application id of a govopt study database ("govo")
APPLICATION_ID = 0x676F766F
#: seconds a writer waits for another's transaction (a block's rows) before giving up
BUSY_SECONDS = 30.0
#: rows read at a time (a batch of ~70 columns holds ~15 MB of Python values while it is
#: typed)
BATCH = 5000
#: the columns every ``points`` table has
FIXED = ("point", "status", "message")

#: the tables of a new database (docs/reference/study-database.md)
SCHEMA = (
    "CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)",
    "CREATE TABLE columns (name TEXT PRIMARY KEY, position INTEGER NOT NULL UNIQUE, "
    "type TEXT NOT NULL, unit TEXT NOT NULL, role TEXT NOT NULL, label TEXT NOT NULL, "
    "about TEXT NOT NULL, shown_unit TEXT NOT NULL, shown_factor REAL NOT NULL)",
    "CREATE TABLE points (point INTEGER PRIMARY KEY, status TEXT NOT NULL, "
    "message TEXT NOT NULL)",
)
#: the columns of the ``columns`` table
_COLUMNS_COLUMNS = ("name", "position", "type", "unit", "role", "label", "about", "shown_unit",
                    "shown_factor")
#: the fixed columns' rows of ``columns``
_FIXED_COLUMNS = (
    ("point", 0, "INTEGER", "", "point", "point", "the point's number in the study's order"),
    ("status", 1, "TEXT", "", "status", "status",
     "pass, fail or error (evaluate); optimal, infeasible or error (design)"),
    ("message", 2, "TEXT", "", "message", "message",
     "the failed checks, the error or the optimiser's message"),
)


# ---------------------------------------------------------------------------------------------
# Errors and checks before opening
# ---------------------------------------------------------------------------------------------

def describe(exc: sqlite3.Error, path) -> StudyError:
    """An SQLite error as one line naming the database, its kind as data (SQLite's error
    code)."""
    name = getattr(exc, "sqlite_errorname", "") or ""
    said = f"SQLite: {exc}"
    if name.startswith("SQLITE_CORRUPT"):
        return StudyError(f"the study database is damaged ({said})", file=path, kind="damaged",
                          advice="run the study again with --force to start it afresh")
    if name == "SQLITE_NOTADB":
        return StudyError("not a govopt study database (not an SQLite file)", file=path,
                          kind="foreign")
    if name.startswith(("SQLITE_BUSY", "SQLITE_LOCKED")):
        return StudyError(f"the study database is busy: another process kept it locked for "
                          f"more than {BUSY_SECONDS:g} s ({said})", file=path, kind="busy")
    if name.startswith("SQLITE_READONLY"):
        return StudyError(f"the study database cannot be written ({said})", file=path,
                          kind="readonly")
    if name.startswith(("SQLITE_CANTOPEN", "SQLITE_PERM", "SQLITE_AUTH")):
        return StudyError(f"cannot open the study database ({said})", file=path, kind="open")
    return StudyError(f"study database error ({said})", file=path, kind="sqlite")


def _os_error(exc: OSError, path, what: str = "read") -> StudyError:
    reason = exc.strerror or type(exc).__name__
    return StudyError(f"cannot {what} the study database ({reason.lower()})", file=path,
                      kind="open")


def _uri(path: Path, **options) -> str:
    from urllib.parse import quote

    query = "&".join(f"{k}={v}" for k, v in options.items())
    return f"file:{quote(str(path.absolute()))}?{query}"


def header(path: str | Path) -> tuple[bool, int | None, int]:
    """``(SQLite file, application id, user version)`` of the file's 100-byte header (an
    unreadable or short file: not an SQLite file)."""
    try:
        with open(path, "rb") as fh:
            head = fh.read(100)
    except OSError:
        return False, None, 0
    if len(head) < 100 or not head.startswith(b"SQLite format 3\x00"):
        return False, None, 0
    return True, int.from_bytes(head[68:72], "big"), int.from_bytes(head[60:64], "big")


def is_study_database(path: str | Path, *, empty: bool = False) -> bool:
    """Whether ``path`` is a govopt study database: its header names govopt (even if the rest
    is damaged), or an older one's tables are there; with ``empty``, also an empty file or
    one with no tables (one being created). Looked at read-only: nothing is written."""
    path = Path(path)
    try:
        if empty and path.stat().st_size == 0:
            return True
    except OSError:
        return False
    sqlite, app, _ = header(path)
    if not sqlite:
        return False
    if app == APPLICATION_ID:
        return True
    try:
        conn = sqlite3.connect(_uri(path, mode="ro"), uri=True, timeout=BUSY_SECONDS)
    except sqlite3.Error:
        return False
    try:
        names = {n for (n,) in conn.execute("SELECT name FROM sqlite_master WHERE type = "
                                            "'table'")}
    except sqlite3.Error as exc:  # busy: being written by another (govopt's writer)
        return getattr(exc, "sqlite_errorname", "").startswith(("SQLITE_BUSY",
                                                                  "SQLITE_LOCKED"))
    finally:
        conn.close()
    return {"layouts", "meta", "points"} <= names or (empty and not names)


def check_database(path: str | Path, *, inputs: Iterable = ()) -> Path:
    """Check before a run that ``path`` can be a study's database (one line if not): not the
    spec or another input, a regular file or none, in a folder that exists and can be
    written; an existing file must be a govopt study database (or empty): nothing else is
    ever written into, nor replaced."""
    from ..report.files import names_folder, refuse_package

    if str(path) in ("", ".") or Path(path).name in ("", ".", "..") or names_folder(path):
        raise StudyError(f"expected a database file name, got {str(path)!r}", where="--db")
    refuse_package(path, "the study database")
    path = Path(path)
    for other in inputs:
        with contextlib.suppress(OSError):
            if os.path.realpath(path) == os.path.realpath(other) or (
                    path.exists() and os.path.samefile(path, other)):
                raise StudyError(f"cannot use as the study database: it is the spec ({other}); "
                                 "give another --db", file=path)
    try:
        exists = path.exists()
        if exists and not path.is_file():
            raise StudyError("cannot use as the study database: not a regular file", file=path)
        parent = path.absolute().parent
        if not parent.is_dir():
            raise StudyError(f"cannot create the study database: folder {path.parent} does not "
                             "exist", file=path)
    except OSError as exc:
        raise _os_error(exc, path, "use") from None
    if not os.access(parent, os.W_OK | os.X_OK):
        raise StudyError(f"cannot create the study database: folder {path.parent} cannot be "
                         "written (SQLite keeps its journal beside the database)", file=path)
    if exists:
        if not os.access(path, os.R_OK | os.W_OK):
            raise StudyError("the study database cannot be written (permission denied)",
                             file=path)
        if not is_study_database(path, empty=True):
            raise StudyError("not a govopt study database (govopt writes only into its own "
                             "databases); give another --db", file=path, kind="foreign")
    return path


def remove_database(path: Path) -> None:
    """Remove a study database and its journal files (regular files only)."""
    for suffix in ("", "-wal", "-shm", "-journal"):
        p = Path(str(path) + suffix)
        if p.is_file():
            os.unlink(p)


# ---------------------------------------------------------------------------------------------
# The store
# ---------------------------------------------------------------------------------------------

def _column_name(role: str, label: str) -> str:
    """The name a column wants (made unique by the store)."""
    prefix = {"check value": "value_", "check margin": "margin_", "check passed": "passed_"}
    if role in ("objective", "objective value"):
        return identifier(label)
    return prefix.get(role, "") + identifier(label)


class Store:
    """A study's SQLite database (see the module's docstring).

    ``create=True`` opens it for a run (creating it if absent); ``create=False`` opens it
    read-only (``show``, ``export``): nothing is written, not even to a file that turns out
    not to be a study database. Every SQLite or file error becomes one line naming the file
    (:class:`StudyError`)."""

    def __init__(self, path: str | Path, *, create: bool = True):
        self.path = Path(path)
        self.writable = create
        self.digest: str | None = None
        self._names: dict[tuple[str, str], str] = {}
        self._meta: dict = {}
        try:
            if create:
                check_database(self.path)
                self.conn = sqlite3.connect(self.path, timeout=BUSY_SECONDS,
                                            isolation_level=None)
                self.conn.execute("PRAGMA synchronous=NORMAL")
                if not self._tables():
                    with self._transaction():  # another process may have made it meanwhile
                        if not self._tables():
                            self._create()
            else:
                self._open_read_only()
        except sqlite3.Error as exc:
            self._close_quietly()
            raise describe(exc, self.path) from None
        except OSError as exc:
            self._close_quietly()
            raise _os_error(exc, self.path) from None

    def _open_read_only(self) -> None:
        try:
            if not self.path.is_file():
                raise StudyError("no such study database" if not self.path.exists()
                                 else "not a study database (not a regular file)", file=self.path)
            with open(self.path, "rb"):  # readable (a permission error said as one)
                pass
        except OSError as exc:
            raise _os_error(exc, self.path) from None
        if self.path.stat().st_size == 0 or not header(self.path)[0]:
            raise StudyError("not a govopt study database", file=self.path, kind="foreign")
        self.conn = sqlite3.connect(_uri(self.path, mode="ro"), uri=True, timeout=BUSY_SECONDS)
        try:
            self.conn.execute("SELECT COUNT(*) FROM sqlite_master").fetchone()
        except sqlite3.OperationalError:  # a read-only folder: no WAL index can be made
            self.conn.close()
            self.conn = sqlite3.connect(_uri(self.path, mode="ro", immutable=1), uri=True)
        tables = self._tables()
        if not {"meta", "points"} <= tables and header(self.path)[1] != APPLICATION_ID:
            raise StudyError("not a govopt study database (no study tables)", file=self.path,
                             kind="foreign")
        self.require_format()
        self.validate()

    def _tables(self) -> set[str]:
        return {n for (n,) in self.conn.execute(
            "SELECT name FROM sqlite_master WHERE type = 'table'")}

    def _create(self) -> None:
        for statement in SCHEMA:
            self.conn.execute(statement)
        self.conn.executemany("INSERT INTO columns VALUES (?, ?, ?, ?, ?, ?, ?, '', 1.0)",
                              [(n, p, t, u, r, lab, about)
                               for n, p, t, u, r, lab, about in _FIXED_COLUMNS])
        self.conn.execute(f"PRAGMA application_id = {APPLICATION_ID}")
        self.conn.execute(f"PRAGMA user_version = {FORMAT_VERSION}")
        self._set_meta({"format_version": FORMAT_VERSION})
        self._meta.clear()

    def _close_quietly(self) -> None:
        conn = getattr(self, "conn", None)
        if conn is not None:
            with contextlib.suppress(sqlite3.Error):
                conn.close()

    def close(self) -> None:
        """Close; a writer folds the write-ahead journal back into the database (when no other
        process holds it) so that no ``-wal`` or ``-shm`` file is left."""
        if self.writable:
            with contextlib.suppress(sqlite3.Error):  # not while another holds it: no wait
                self.conn.execute("PRAGMA busy_timeout = 50")
                self.conn.execute("PRAGMA journal_mode=DELETE")
        self.conn.close()

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, tb):
        self._close_quietly() if isinstance(exc, sqlite3.Error) else self.close()
        if isinstance(exc, sqlite3.Error):
            raise describe(exc, self.path) from None

    @contextlib.contextmanager
    def _transaction(self):
        """``BEGIN IMMEDIATE ... COMMIT``: the write lock first (waiting up to
        :data:`BUSY_SECONDS` for another writer), so that what is read inside holds."""
        self.conn.execute("BEGIN IMMEDIATE")
        try:
            yield
        except BaseException:
            with contextlib.suppress(sqlite3.Error):
                self.conn.execute("ROLLBACK")
            raise
        self.conn.execute("COMMIT")

    # -- meta --

    def meta(self, key: str):
        """A value of ``meta`` (None if absent); read once while opened read-only."""
        if key in self._meta:
            return self._meta[key]
        row = self.conn.execute("SELECT value FROM meta WHERE key = ?", (key,)).fetchone()
        try:
            value = None if row is None else json.loads(row[0])
        except (TypeError, ValueError):
            raise StudyError(f"the study database is damaged: meta {key!r} is not JSON",
                             file=self.path, kind="damaged", advice="run the study again with "
                             "--force to start it afresh") from None
        if not self.writable:
            self._meta[key] = value
        return value

    def _set_meta(self, values: dict) -> None:
        self.conn.executemany("INSERT OR REPLACE INTO meta VALUES (?, ?)",
                              [(k, json.dumps(v)) for k, v in values.items()])

    def set_meta(self, values: dict) -> None:
        with self._transaction():
            self._set_meta(values)

    def format_version(self) -> int:
        """The database's format: its ``meta``'s, or 1 for govopt 0.1.0's (no format
        recorded)."""
        tables = self._tables()
        if "meta" in tables:
            v = self.meta("format_version")
            if v is not None:
                return int(v) if isinstance(v, int) else -1
        return 1 if "layouts" in tables else FORMAT_VERSION

    def require_format(self) -> None:
        """Refuse (one line) a database of another format than this govopt's."""
        found = self.format_version()
        if found == FORMAT_VERSION:
            return
        from .. import __version__

        what = ("an older govopt's (one blob of numbers a point)" if found < FORMAT_VERSION
                else "a newer govopt's")
        raise StudyError(f"a study database of format {found}, {what}; govopt {__version__} "
                         f"reads format {FORMAT_VERSION}", file=self.path, kind="format",
                         advice="read it with the govopt that wrote it, or run the study "
                         "again with --force to start afresh")

    # -- its own structure --

    def validate(self) -> None:
        """Refuse (one line, kind ``"damaged"``) a database whose structure or totals are not
        what govopt writes, so that nothing is shown, exported, resumed or counted from a row
        the study did not write: the three tables and the columns of each; every column of
        ``points`` described in ``columns`` (and only those), each with its type and a finite
        positive ``shown_factor``; the study's definition with its digest, and its number of
        points as the definition gives it; each row a point of the study (a number below that
        total, a status, every input given)."""
        try:
            problem = self._problem()
        except sqlite3.DatabaseError as exc:
            raise describe(exc, self.path) from None
        if problem:
            raise StudyError(f"the study database is damaged: {problem}", file=self.path,
                             kind="damaged",
                             advice="run the study again with --force to start it afresh")

    def _problem(self) -> str:
        """What is wrong with the database's structure or totals, ``""`` if nothing."""
        tables = self._tables()
        missing = [t for t in ("meta", "columns", "points") if t not in tables]
        if missing:
            return f"no table {', '.join(missing)}"
        for table, want in (("meta", ("key", "value")), ("columns", _COLUMNS_COLUMNS)):
            have = self._columns_of(table)
            if have != list(want):
                return f"table {table} has columns {', '.join(have)}, not {', '.join(want)}"
        described = self.conn.execute(
            "SELECT name, type, shown_factor FROM columns ORDER BY position").fetchall()
        names = [n for n, _, _ in described]
        have = self._columns_of("points")
        if names[:len(FIXED)] != list(FIXED) or sorted(names) != sorted(have):
            extra = sorted(set(have) - set(names)) or sorted(set(names) - set(have))
            return (f"the columns of points ({len(have)}) are not those described in columns "
                    f"({len(names)}): {', '.join(map(str, extra[:3])) or 'their order'}")
        for name, kind, factor in described:
            if kind not in ("REAL", "INTEGER", "TEXT"):
                return f"column {name}: type {kind!r}"
            if not isinstance(factor, int | float) or not (math.isfinite(factor)
                                                           and factor > 0):
                return f"column {name}: shown_factor {factor!r}, expected a number > 0"
        study = self.meta("study")
        rows = self.count()
        if study is None:
            return f"no study, but {rows} rows" if rows else ""
        if not isinstance(study, dict) or self.meta("digest") != study_digest(study):
            return "the study's definition does not match its digest"
        from .definition import Study

        try:
            total = Study.from_definition(study).count()
        except (GovoptError, KeyError, TypeError, ValueError, AttributeError):
            return "the study's definition cannot be read"
        if self.meta("total") != total or isinstance(self.meta("total"), bool):
            return f"total {self.meta('total')!r}, but the study has {total} points"
        inputs = self.names("input")
        foreign = self.conn.execute(
            "SELECT COUNT(*), MIN(point) FROM points WHERE point < 0 OR point >= ? "
            "OR typeof(point) != 'integer' OR typeof(status) != 'text' OR status = '' "
            + "".join(f" OR {_quoted(c)} IS NULL" for c in inputs), (total,)).fetchone()
        if foreign[0]:
            return (f"{foreign[0]} row{'s' if foreign[0] != 1 else ''} the study did not write, "
                    f"the first point {foreign[1]} (expected a point number from 0 to "
                    f"{total - 1}, a status and every input)")
        return ""

    def _columns_of(self, table: str) -> list[str]:
        return [row[1] for row in self.conn.execute(f"PRAGMA table_info({_quoted(table)})")]

    # -- the study it holds --

    def study(self) -> dict:
        """The study's definition (:meth:`Study.definition`), ``{}`` before one is claimed."""
        return self.meta("study") or {}

    def claim(self, definition: dict, total: int, *, resume: bool = False, fresh: bool = False,
              recompute: Callable[[np.ndarray], Rows] | None = None) -> list[str]:
        """Make this database the study ``definition``'s, atomically (under the write lock):
        a database of another format or holding another study is refused (``fresh``: emptied
        first), one holding rows of this study needs ``resume``. A database written by another
        govopt version is resumed only if this version computes its first points alike
        (``recompute``: the rows of some points, compared with those stored); else refused.
        Returns the notes to tell the user (one line each). Rows written later check that the
        database still holds this study (:meth:`add`)."""
        try:
            return self._claim(definition, total, resume, fresh, recompute)
        except sqlite3.Error as exc:  # a damaged database: said as one
            raise describe(exc, self.path) from None

    def _claim(self, definition, total, resume, fresh, recompute) -> list[str]:
        from .. import __version__

        digest = study_digest(definition)
        notes: list[str] = []
        with self._transaction():
            if fresh:
                for (name,) in self.conn.execute("SELECT name FROM sqlite_master WHERE type = "
                                                 "'table' AND name NOT LIKE 'sqlite_%'")\
                        .fetchall():
                    self.conn.execute(f'DROP TABLE "{name}"')
                self._create()
                self._names.clear()
            self.require_format()
            self.validate()
            old = self.meta("digest")
            if old is not None and old != digest:
                study = self.study()
                raise StudyError(f"the database holds another study ({study.get('name')!r}, "
                                 f"{study.get('spec_path')})", file=self.path, kind="other study",
                                 advice="use another --db, or --force to start afresh")
            n_old = self.count()
            if n_old and not resume:
                raise StudyError(f"the database already holds {n_old} rows", file=self.path,
                                 kind="rows", advice="use --resume to continue the study, or "
                                 "--force to start afresh")
            versions = self.meta("govopt_versions") or []
            if n_old and __version__ not in versions and recompute is not None:
                notes.append(self._same_results(recompute, versions))
            self._set_meta({"study": definition, "digest": digest, "total": total,
                            "govopt_version": self.meta("govopt_version") or __version__,
                            "govopt_versions": [*versions, *([__version__] if __version__
                                                             not in versions else [])]})
        self.digest = digest
        return notes

    def _same_results(self, recompute, versions: list[str]) -> str:
        """Recompute the first stored points (up to three) and compare: one line if alike,
        else refused (:class:`StudyError`, kind ``"version"``)."""
        from .. import __version__

        written = ", ".join(versions) or "another version"
        self._read_names()
        stored = self.frame(self.conn.execute(
            "SELECT * FROM points ORDER BY point LIMIT 3"))
        points = stored["point"].to_numpy(dtype=np.int64)
        rows = recompute(points)
        differ = self._difference(stored, rows)
        if differ:
            raise StudyError(f"written by govopt {written}, whose results differ from govopt "
                             f"{__version__}'s ({differ})", file=self.path, kind="version",
                             advice=f"resume it with govopt {written}, or run the study again "
                             "with --force to start afresh")
        return (f"{self.path}: written by govopt {written}; its first {len(points)} points "
                f"recomputed by govopt {__version__} agree: resumed")

    def _difference(self, stored: pd.DataFrame, rows: Rows) -> str:
        """The first value that differs between the stored rows and ``rows`` (the same
        points), ``""`` if none (numbers to 1e-9 relative)."""
        stored = stored.set_index("point")
        got = {"status": rows.status, "message": rows.message}
        got.update({self._names.get((c.role, c.label)) or _column_name(c.role, c.label): d
                    for c, d in zip(rows.columns, rows.data, strict=True)})
        for name, values in got.items():
            for p, v in zip(rows.points, values, strict=True):
                s = stored[name].get(int(p)) if name in stored else None
                if not _same(s, v):
                    unit = self._unit(name)
                    return (f"point {int(p)}, {name}: {_shown(s)}{unit} stored, "
                            f"{_shown(v)}{unit} now")
        return ""

    def _unit(self, name: str) -> str:
        """`` UNIT`` of column ``name`` (SI, as stored), ``""`` where it has none."""
        row = self.conn.execute("SELECT unit FROM columns WHERE name = ?", (name,)).fetchone()
        return f" {row[0]}" if row and row[0] else ""

    # -- rows --

    def count(self) -> int:
        return self.conn.execute("SELECT COUNT(*) FROM points").fetchone()[0]

    def failures(self) -> int:
        return self.conn.execute("SELECT COUNT(*) FROM points WHERE status NOT IN "
                                 "('pass', 'optimal')").fetchone()[0]

    def done(self, lo: int, hi: int) -> set[int]:
        """The numbers of the points in ``[lo, hi)`` already in the database."""
        return {p for (p,) in self.conn.execute(
            "SELECT point FROM points WHERE point >= ? AND point < ?", (lo, hi))}

    def start(self) -> None:
        """The write-ahead journal for the run: readers (``study show``) do not hold the
        writers up. :meth:`close` folds it back."""
        self.conn.execute("PRAGMA journal_mode=WAL")

    def add(self, rows: Rows) -> None:
        """The rows of some points, in one transaction, their new columns added first; a point
        already written (by another process running the same study) is kept. After
        :meth:`claim`, refused if the database no longer holds that study."""
        if not len(rows):
            return
        with self._transaction():
            if self.digest is not None and self.meta("digest") != self.digest:
                raise StudyError("another study took this database over while this one ran "
                                 "(--force); stopped", file=self.path, kind="other study")
            names = [self._name(c) for c in rows.columns]
            quoted = ", ".join(_quoted(n) for n in (*FIXED, *names))
            sql = (f"INSERT OR IGNORE INTO points ({quoted}) "
                   f"VALUES ({', '.join('?' * (3 + len(names)))})")
            self.conn.executemany(sql, zip(rows.points.tolist(), rows.status.tolist(),
                                           rows.message.tolist(),
                                           *(d.tolist() for d in rows.data), strict=True))

    def _name(self, column: Column) -> str:
        """The column's name in ``points``, the column added where the table has none yet
        (inside :meth:`add`'s transaction: another writer's columns are read first)."""
        key = (column.role, column.label)
        if key in self._names:
            return self._names[key]
        self._read_names()
        if key not in self._names:
            used = set(self._names.values()) | set(FIXED)
            base = _column_name(*key)
            name, k = base, 2
            while name in used:
                name, k = f"{base}_{k}", k + 1
            position = self.conn.execute("SELECT MAX(position) FROM columns").fetchone()[0] + 1
            self.conn.execute(f"ALTER TABLE points ADD COLUMN {_quoted(name)} {column.type}")
            self.conn.execute("INSERT INTO columns VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
                              (name, position, column.type, column.unit, column.role,
                               column.label, column.about, column.shown or column.unit,
                               float(column.factor)))
            self._names[key] = name
        return self._names[key]

    def _read_names(self) -> None:
        for name, role, label in self.conn.execute("SELECT name, role, label FROM columns"):
            self._names[(role, label)] = name

    # -- reading --

    def columns(self) -> pd.DataFrame:
        """The ``columns`` table in order (name, type, unit, role, label, about, shown_unit,
        shown_factor)."""
        frame = pd.read_sql_query("SELECT * FROM columns ORDER BY position", self.conn)
        return frame.drop(columns="position")

    def names(self, role: str | None = None) -> list[str]:
        """The columns of ``points`` in order (of one ``role`` only)."""
        sql = "SELECT name FROM columns" + (" WHERE role = ?" if role else "") + \
            " ORDER BY position"
        return [n for (n,) in self.conn.execute(sql, (role,) if role else ())]

    def frame(self, cursor: sqlite3.Cursor, types: dict | None = None) -> pd.DataFrame:
        """The rows of ``cursor`` (a SELECT from ``points``) as a frame, each column of its
        type: REAL numbers (NaN where NULL), a check's verdict nullable booleans, TEXT
        objects."""
        names = [d[0] for d in cursor.description]
        types = self._types() if types is None else types
        records = cursor.fetchall()
        return self._typed(records, names, types)

    def _types(self) -> dict[str, tuple[str, str]]:
        return {n: (t, r) for n, t, r in self.conn.execute("SELECT name, type, role FROM "
                                                          "columns")}

    @staticmethod
    def _typed(records: list, names: list[str], types: dict) -> pd.DataFrame:
        cols = list(zip(*records, strict=True)) if records else [()] * len(names)
        out = {}
        for name, values in zip(names, cols, strict=True):
            kind, role = types.get(name, ("TEXT", ""))
            if kind == "REAL":
                out[name] = np.array(values, dtype=float)  # NULL (None) as NaN
            elif role == "check passed":
                out[name] = pd.array([None if v is None else bool(v) for v in values],
                                     dtype="boolean")
            elif kind == "INTEGER":
                out[name] = pd.array(list(values), dtype="Int64") if None in values else \
                    np.array(values, dtype=np.int64)
            else:
                out[name] = np.array(values, dtype=object)
        return pd.DataFrame(out, columns=names)

    def batches(self, columns: Iterable[str] | None = None, *, batch: int = BATCH,
                where: str = ""):
        """The rows in the study's order, ``batch`` at a time: frames of the columns of
        ``points`` (``columns``: only those that exist, with ``point``), each of its type. A
        study of a million points is read a batch at a time, never held."""
        have = self.names()
        want = have if columns is None else ["point", *(c for c in dict.fromkeys(columns)
                                                       if c in have and c != "point")]
        types = self._types()
        cursor = self.conn.execute(f"SELECT {', '.join(_quoted(c) for c in want)} FROM points "
                                   f"{where} ORDER BY point")
        while records := cursor.fetchmany(batch):
            yield self._typed(records, want, types)

    def table(self, columns: Iterable[str] | None = None, *, batch: int = BATCH
              ) -> pd.DataFrame:
        """Every row, in the study's order, with ``pareto`` marked where the study names
        objectives (``columns``: only those, and what the front needs). For a whole table; a
        large study is read by :meth:`batches`."""
        from .pareto import objectives, pareto_mark

        study = self.study()
        if columns is not None:
            columns = [*columns, *objectives(study)]
        parts = list(self.batches(columns, batch=batch))
        if not parts:
            names = self.names() if columns is None else ["point", *columns]
            return pd.DataFrame(columns=names)
        frame = pd.concat(parts, ignore_index=True) if len(parts) > 1 else parts[0]
        if study.get("pareto"):
            frame["pareto"] = pareto_mark(frame, study)
        return frame

    def row(self, point: int) -> dict:
        """The row of point ``point``."""
        frame = self.frame(self.conn.execute("SELECT * FROM points WHERE point = ?", (point,)))
        return frame.iloc[0].to_dict()

    def integrity(self) -> str:
        return self.conn.execute("PRAGMA integrity_check").fetchone()[0]


def _quoted(name: str) -> str:
    return '"' + name.replace('"', '""') + '"'


def _same(stored, now) -> bool:
    """A stored value and a recomputed one alike (numbers to 1e-9 relative)."""
    if stored is None or stored is pd.NA or (isinstance(stored, float) and math.isnan(stored)):
        return now is None or (isinstance(now, float) and math.isnan(now))
    if isinstance(now, float | np.floating) or isinstance(stored, float):
        try:
            a, b = float(stored), float(now)
        except (TypeError, ValueError):
            return False
        return a == b or abs(a - b) <= 1e-9 * max(abs(a), abs(b))
    return stored == now or str(stored) == str(now)


def _shown(value) -> str:
    """A stored or computed value as a person reads it: numbers to 10 significant digits
    (numpy's scalars as plain numbers), text quoted, a missing value as "none"."""
    if value is None or (isinstance(value, float | np.floating) and np.isnan(value)):
        return "none"
    if isinstance(value, int | float | np.integer | np.floating) and not isinstance(value, bool):
        return f"{float(value):.10g}"
    return repr(str(value)) if isinstance(value, str | np.str_) else repr(value)
