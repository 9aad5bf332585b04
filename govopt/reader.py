"""Reading a spec file: the TOML read safely (:func:`read_spec_data`) and its tables read key by
key (:class:`Reader`: units, types, ranges, unknown keys with a did-you-mean). A table read with
its declaration (:class:`govopt.keys.Table`) is read by :meth:`Reader.read`, one declared key at
a time (dimension, default, range and meaning from the declaration), and takes no key that is
not declared. Every error is a :class:`SpecError` naming the file, the key path and what was
expected. Governor specs (:mod:`govopt.spec`) and spring specs (:mod:`govopt.spring_command`)
read through it; it knows no governor, so ``govopt spring`` loads none."""

from __future__ import annotations

import difflib
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import limits
from .errors import GovoptError
from .keys import WEIGHT, Key, Table
from .units import G_STANDARD, SI_UNITS, UnitError, parse_quantity


@dataclass(frozen=True)
class Entry:
    """One input as written in the spec and in SI (``Spec.entries``, for reports)."""

    key: str
    written: str
    si: float | str
    unit: str
    #: what the key is, one line (its declaration's :attr:`govopt.keys.Key.meaning`)
    meaning: str = ""


class SpecError(GovoptError):
    """A spec that cannot be used, with the file and key path in the message."""


#: Keys an engineer may write for what a spec names otherwise: key -> (the spec's key, how
#: they differ), for the did-you-mean of a missing key.
KEY_SYNONYMS: dict[str, tuple[str, str]] = {
    "coil_diameter": ("coil_radius", "the mean coil radius, half the mean coil diameter"),
    "mean_diameter": ("coil_radius", "the mean coil radius, half the mean coil diameter"),
    "mean_coil_diameter": ("coil_radius", "the mean coil radius, half the mean coil diameter"),
    "wire": ("wire_diameter", "the wire's diameter"),
    "turns": ("active_turns", "the active turns"),
    "min": ("inner", "the speed at the inner end of the range"),
    "max": ("outer", "the speed at the outer end of the range"),
    "minimum": ("inner", "the speed at the inner end of the range"),
    "maximum": ("outer", "the speed at the outer end of the range"),
    "low": ("inner", "the speed at the inner end of the range"),
    "high": ("outer", "the speed at the outer end of the range"),
}


#: the longest list of allowed keys an error line gives in full; a longer one is pointed to
#: the reference (:attr:`Reader.guide`), never cut short
ALLOWED_CHARS = 160


class Reader:
    """Reads one TOML table, recording which keys were used; :meth:`finish` rejects the rest."""

    def __init__(self, file: str, table: dict, path: str, entries: list[Entry],
                 declared: Table | None = None):
        if not isinstance(table, dict):
            raise SpecError(f"{file}: {path or 'top level'}: expected a table, got "
                            f"{limits.shorten(table)}")
        self.file, self.table, self.path, self.entries = file, table, path, entries
        #: the table's declaration (:class:`govopt.keys.Table`): its keys are the ones allowed
        self.declared = declared
        #: where a person finds the keys of a table too long to list in an error line
        #: (``"docs/reference/spec.md under hartnell:"``); the tables read from this one inherit
        #: it
        self.guide = ""
        self.used: set[str] = set()
        self._meaning = ""  # the meaning of the key being read, for its Entry

    # -- declared keys ----------------------------------------------------------------------

    def read(self, key: Key, values: dict | None = None, *, required: bool | None = None):
        """The value of the declared ``key`` (SI; see :class:`govopt.keys.Key`), recorded with
        its meaning. ``values``: the values read before it in this table, for a default or a
        range that depends on them; the value read is added to it under ``key.name``.
        ``required`` overrides the declaration's (a key needed in one configuration only:
        then absent means None)."""
        values = {} if values is None else values
        need = key.required if required is None else required
        if not need and not any(map(self.has, key.names)):  # the default, from what is read
            self.used.update(key.names)
            value = key.default_value(values)
        else:
            self._meaning = key.meaning
            try:
                value = self._read(key, values, need, None)
            finally:
                self._meaning = ""
        values[key.name] = value
        return value

    def read_all(self, keys, values: dict | None = None) -> dict:
        """Every key of ``keys`` (a :class:`govopt.keys.Table` or keys) by :meth:`read`, in
        order: ``{name: value}`` of these keys (``values``, the values read before them, is
        updated with them too)."""
        values = {} if values is None else values
        keys = getattr(keys, "keys", keys)
        for key in keys:
            self.read(key, values)
        return {key.name: values[key.name] for key in keys}

    def _read(self, key: Key, values: dict, need: bool, default):
        name, kind = key.name, key.kind
        bounds = dict(low=key.limit("low", values), high=key.limit("high", values),
                      high_inclusive=key.high_inclusive, positive=key.positive,
                      nonnegative=key.nonnegative, range_text=key.range_text or None)
        if kind == WEIGHT:
            if key.shape == "pair":
                return self.weight_pair(name, default, single=key.single,
                                        nonnegative=key.nonnegative)
            return self.weight_or_mass(name, required=need, default=default)
        if key.shape == "pair":
            return self.pair(name, kind, default, nonnegative=key.nonnegative)
        if key.shape == "list":
            value = self.raw(name, False) if not need else None
            if (value is None and not need) or value in key.options():
                self.used.add(name)
                return default if value is None else value
            if isinstance(value, str) and key.options():  # not one of its words
                words = " or ".join(map(repr, key.options()))
                self.fail(name, f"expected {words} or a list of {kind} strings, got {value!r}")
            return tuple(self.quantities(name, kind, **bounds))
        if kind == "choice":
            if need:
                self.raw(name, True)
            return self.choice(name, key.options(), default)
        if kind == "text":
            return self.text(name, default)
        if kind == "flag":
            return self.boolean(name, default)
        if kind == "table":
            value = self.raw(name, need)
            return default if value is None else value
        if key.options() and isinstance(self.table.get(name), str):  # a number or a word
            if self.table[name] not in key.options():
                words = " or ".join(map(repr, key.options()))
                self.fail(name, f"expected a number in {key.range_text}, got "
                                f"{limits.shorten(self.table[name])}" if key.range_text else
                          f"expected a number or {words}, got "
                          f"{limits.shorten(self.table[name])}")
            return self.choice(name, key.options(), default)
        if kind in ("number", "count", "dimensionless"):
            return self.number(name, required=need, default=default, integer=kind == "count",
                               **bounds)
        return self.quantity(name, kind, required=need, default=default, **bounds)

    def key(self, name: str) -> str:
        return f"{self.path}.{name}" if self.path else name

    def fail(self, name: str, message: str):
        """``FILE: KEY: message`` (without a file, e.g. options read as a table: ``KEY:
        message``)."""
        value = self.table.get(name)
        if value is not None and len(repr(value)) > limits.SHOWN_CHARS:  # a 200 kB value
            message = message.replace(repr(value), limits.shorten(value))
        where = f"{self.file}: " if self.file else ""
        raise SpecError(f"{where}{self.key(name)}: {message}")

    def has(self, name: str) -> bool:
        return name in self.table

    def raw(self, name: str, required: bool):
        if self.declared is not None and not self.declared.open \
                and name not in self.declared.names:  # the parser's own mistake, not the user's
            raise AssertionError(f"{self.key(name)}: read, but not declared in "
                                 f"[{self.declared.name}]")
        self.used.add(name)
        if name not in self.table:
            if required:
                self.fail(name, "missing (required)" + self._misspelt(name))
            return None
        return self.table[name]

    def _misspelt(self, name: str) -> str:
        """A hint when a key of this table not read (yet) is close to the missing ``name``:
        ``irregularty`` for ``irregularity``, or names the same thing another way
        (:data:`KEY_SYNONYMS`: ``coil_diameter`` for ``coil_radius``)."""
        keys = [str(k) for k in self.table if k not in self.used]
        for key in keys:
            meant, note = KEY_SYNONYMS.get(key, (None, ""))
            if meant == name:
                return f"; the table has {key!r}: did you mean {name!r}? ({note})"
        close = difflib.get_close_matches(name, keys, n=1, cutoff=0.8)
        return f"; the table has {close[0]!r}: did you mean {name!r}?" if close else ""

    def quantity(self, name, dimension, *, required=True, default=None, positive=True,
                 nonnegative=False, low=None, high=None, range_text=None, high_inclusive=False):
        value = self.raw(name, required)
        if value is None:
            return default
        try:
            si = parse_quantity(value, dimension)
        except UnitError as exc:
            self.fail(name, str(exc))
        self._check_range(name, value, si, positive, nonnegative, low, high, range_text,
                          high_inclusive)
        self.entries.append(Entry(self.key(name), str(value), si, SI_UNITS[dimension],
                                  self._meaning))
        return si

    def number(self, name, *, required=True, default=None, positive=True, nonnegative=False,
               low=None, high=None, integer=False, range_text=None, high_inclusive=False):
        """A bare number; with ``integer``, a whole number returned as ``int`` (2.5 is an error,
        never truncated)."""
        value = self.raw(name, required)
        if value is None:
            return default
        if isinstance(value, bool) or not isinstance(value, int | float) \
                or not math.isfinite(value if isinstance(value, float) else 0.0):
            self.fail(name, f"expected a finite number, got {value!r}")
        # beyond floating point (a 400-digit integer), or far beyond any governor
        problem = ("is too large a number" if abs(value) > 1e300
                   else limits.magnitude_error(value))
        if problem:
            self.fail(name, f"{limits.shorten(value)} {problem}")
        if integer and not float(value).is_integer():
            self.fail(name, f"expected a whole number (a count), got {value!r}")
        self._check_range(name, value, float(value), positive, nonnegative, low, high,
                          range_text, high_inclusive)
        self.entries.append(Entry(self.key(name), str(value), float(value), "", self._meaning))
        return int(value) if integer else float(value)

    def _check_range(self, name, written, si, positive, nonnegative, low, high,
                     range_text=None, high_inclusive=False):
        above = high is not None and (si > high if high_inclusive else si >= high)
        if (low is not None and si <= low) or above:
            text = range_text or f"({low if low is not None else '-inf'}, "\
                                 f"{high if high is not None else 'inf'}" \
                                 f"{']' if high_inclusive else ')'}"
            self.fail(name, f"must lie in {text}, got {written!r}")
        if nonnegative and si < 0:
            self.fail(name, f"must not be negative, got {written!r}")
        elif positive and not nonnegative and si <= 0:
            self.fail(name, f"must be positive, got {written!r}")

    def choice(self, name, choices, default):
        value = self.raw(name, False)
        if value is None:
            return default
        if value not in choices or isinstance(value, bool):  # true is not the grade 1
            self.fail(name, f"expected one of {', '.join(map(repr, choices))}, got {value!r}")
        chosen = next(c for c in choices if c == value)  # the choice itself: 2.0 given is 2
        self.entries.append(Entry(self.key(name), str(value), chosen, "", self._meaning))
        return chosen

    def text(self, name, default=""):
        value = self.raw(name, False)
        if value is None:
            return default
        if not isinstance(value, str):
            self.fail(name, f"expected a string, got {value!r}")
        if len(value) > limits.MAX_TEXT_CHARS:
            self.fail(name, limits.count_error(len(value), limits.MAX_TEXT_CHARS, "characters"))
        self.entries.append(Entry(self.key(name), value, value, "", self._meaning))
        return value

    def boolean(self, name, default):
        value = self.raw(name, False)
        if value is None:
            return default
        if not isinstance(value, bool):
            self.fail(name, f"expected true or false, got {value!r}")
        self.entries.append(Entry(self.key(name), str(value).lower(), str(value).lower(), "",
                                  self._meaning))
        return value

    def quantities(self, name, dimension, **kw):
        values = self.raw(name, True)
        if not isinstance(values, list) or not values:
            self.fail(name, f"expected a non-empty list of {dimension} strings, got {values!r}")
        if len(values) > limits.MAX_LIST_ITEMS:
            self.fail(name, limits.count_error(len(values), limits.MAX_LIST_ITEMS, "items"))
        sub = Reader(self.file, {str(i): v for i, v in enumerate(values)}, self.key(name),
                      self.entries)
        sub.key = lambda i: f"{self.key(name)}[{i}]"  # type: ignore[method-assign]
        sub._meaning = self._meaning
        return np.array([sub.quantity(str(i), dimension, **kw) for i in range(len(values))])

    def pair(self, name, dimension, default, nonnegative=False):
        """A bound ``[low, high]`` of ``dimension`` (SI; bare numbers for "dimensionless"),
        ``low <= high`` (equal ends fix the value), each positive (or, with ``nonnegative``,
        not negative); ``default`` where absent."""
        value = self.raw(name, False)
        if value is None:
            return default
        if not isinstance(value, list) or len(value) != 2:
            self.fail(name, f"expected [low, high], got {value!r}")
        if dimension == "dimensionless":
            sub = Reader(self.file, {"low": value[0], "high": value[1]}, self.key(name),
                         self.entries)
            sub._meaning = self._meaning
            lo, hi = (sub.number(end, nonnegative=nonnegative) for end in ("low", "high"))
        else:
            lo, hi = self.quantities(name, dimension, nonnegative=nonnegative)
        if not lo <= hi:
            self.fail(name, f"expected low <= high, got {value!r}")
        return (float(lo), float(hi))

    def weight_pair(self, stem, default, single: bool = False, nonnegative: bool = False):
        """Bounds ``<stem>_weight = [lo, hi]`` (forces) or ``<stem>_mass`` (kg); with
        ``single`` one value fixes it (a spring governor's sleeve load); ``nonnegative``: zero
        allowed (no central load)."""
        w, m = f"{stem}_weight", f"{stem}_mass"
        if self.has(w) and self.has(m):
            self.fail(w, f"give either {w} or {m}, not both")
        self.used.update((w, m))
        name, dim, scale = (w, "force", G_STANDARD) if self.has(w) else (m, "mass", 1.0)
        if single and self.has(name) and not isinstance(self.table[name], list):
            value = self.quantity(name, dim, nonnegative=True) / scale
            return (value, value)
        pair = self.pair(name, dim, None, nonnegative=nonnegative)
        return default if pair is None else (pair[0] / scale, pair[1] / scale)

    def sub(self, name, required=True, declared: Table | None = None):
        value = self.raw(name, required)
        if value is None:
            return None
        out = Reader(self.file, value, self.key(name), self.entries, declared)
        out.guide = self.guide
        return out

    def tables(self, name, declared: Table | None = None):
        values = self.raw(name, False)
        if values is None:
            return []
        if not isinstance(values, list):
            self.fail(name, "expected an array of tables ([[" + name + "]])")
        out = [Reader(self.file, v, f"{self.key(name)}[{i}]", self.entries, declared)
               for i, v in enumerate(values)]
        for reader in out:
            reader.guide = self.guide
        return out

    def weight_or_mass(self, stem, *, required=True, default=None):
        """``<stem>_weight`` (a force, converted with standard gravity) or ``<stem>_mass``."""
        w, m = f"{stem}_weight", f"{stem}_mass"
        if self.has(w) and self.has(m):
            self.fail(w, f"give either {w} or {m}, not both")
        self.used.update((w, m))
        if self.has(m):
            return self.quantity(m, "mass")
        weight = self.quantity(w, "force", required=required and not self.has(m), default=None)
        return default if weight is None else weight / G_STANDARD

    def allowed(self) -> list[str]:
        """The keys this table may have: its declaration's (every key of the table, in
        declared order), else the keys read."""
        if self.declared is not None:
            return self.declared.names
        return sorted(self.used)

    def finish(self):
        """Reject a key not read (a misspelling, another type's key), naming the closest
        allowed key and every allowed key (in full: the list is the reference's)."""
        allowed = self.allowed()
        unknown = sorted(set(map(str, self.table)) - self.used)
        if unknown and unknown[0] in allowed:  # declared, but not read in this configuration
            when = self.declared.key(unknown[0]).when
            self.fail(unknown[0], f"does not apply here{f' (it applies {when})' if when else ''}")
        if unknown:
            absent = [k for k in allowed if k not in self.table]  # not given: the likelier
            close = (difflib.get_close_matches(unknown[0], absent, n=1, cutoff=0.6)
                     or difflib.get_close_matches(unknown[0], allowed, n=1, cutoff=0.6))
            hint = f"did you mean {close[0]!r}? " if close else ""
            listed = ", ".join(allowed)
            if len(listed) > ALLOWED_CHARS and self.guide:  # one line a person reads
                table = f"[{self.declared.name}]" if self.declared.name else "the top level"
                listed = f"{len(allowed)} keys allowed here, listed in {self.guide} {table}"
            else:
                listed = f"allowed here: {listed}"
            self.fail(unknown[0], f"unknown key ({hint}{listed})")


def _bundled_hint(path) -> str:
    """Where a missing spec file bears a bundled example's name, how to get that example."""
    from .examples import examples

    p = Path(path)
    try:
        present = p.exists()
    except OSError:  # a name the system refuses (too long): no example bears it
        return ""
    if present or p.parent != Path() or (p.stem if p.suffix == ".toml" else p.name) not in \
            examples():
        return ""
    name = p.stem if p.suffix == ".toml" else p.name
    return f"; {name!r} is a bundled example: `govopt init {name}` copies it here"


def read_spec_data(path: str | Path, *, max_bytes: int = 1 << 20, max_depth: int = 32) -> dict:
    """A spec file's TOML as a dict, read safely (see :func:`load_spec`), not yet validated."""
    import os
    import stat

    path = Path(path)
    try:
        flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
        fd = os.open(path, flags)  # O_NONBLOCK: opening a FIFO must not block
        try:
            mode = os.fstat(fd).st_mode
            if not stat.S_ISREG(mode):
                kind = ("a folder" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode)
                        else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
                        else "not a regular file")
                raise SpecError(f"{path}: expected a regular spec file, got {kind}")
            with open(fd, "rb", closefd=False) as fh:
                raw = fh.read(max_bytes + 1)
        finally:
            os.close(fd)
    except OSError as exc:
        raise SpecError(f"{path}: cannot read spec file ({exc.strerror or exc})"
                        f"{_bundled_hint(path)}") from None
    if len(raw) > max_bytes:
        raise SpecError(f"{path}: spec file larger than {max_bytes} bytes (a spec is a few KiB)")
    bom = 3 if raw.startswith(b"\xef\xbb\xbf") else 0
    try:
        text = raw[bom:].decode("utf-8")
    except UnicodeDecodeError as exc:
        at, line = bom + exc.start, raw.count(b"\n", 0, bom + exc.start) + 1
        raise SpecError(f"{path}: not UTF-8 text: byte 0x{raw[at]:02x} at byte offset {at} "
                        f"(line {line}); save the file as UTF-8") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SpecError(f"{path}: malformed TOML: {exc}") from None
    except RecursionError:
        raise SpecError(f"{path}: TOML nested too deeply (at most {max_depth} levels)") from None
    stack = [(data, 1)]
    while stack:
        value, depth = stack.pop()
        if depth > max_depth:
            raise SpecError(f"{path}: TOML nested too deeply (at most {max_depth} levels)")
        items = value.values() if isinstance(value, dict) else value
        stack.extend((v, depth + 1) for v in items if isinstance(v, dict | list))
    return data
