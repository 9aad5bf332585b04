"""Spec keys declared once: what a key of a spec table is, for every reader of it.

A :class:`Key` says what one key of a spec file's table holds: its name, its dimension (a
quantity with units, :data:`govopt.units.SI_UNITS`) or kind (a bare number, a count, a choice,
text, a flag), its default, its allowed range, one line of meaning and, where the key is a
figure of a source, the source. A :class:`Table` is a spec table's keys in reading order. The
parser reads the declared keys (:meth:`govopt.reader.Reader.read`), and the reference
(``docs/reference/spec.md``), the ``govopt init --type`` templates, the JSON Schema of the spec
file (``govopt schema``) and the workbook's input labels (:attr:`govopt.reader.Entry.meaning`)
are generated from the same declarations; a key nobody declared is an error in the parser and in
the schema alike.

Where a key is declared (each in the module that owns it):

* a governor type's ``[governor]`` keys: ``Governor.keys`` in its module (the bell-crank types'
  common keys in :mod:`govopt.governors.bellcrank`), its own top-level tables
  (``Governor.tables``: the shaft governor's ``[valve_gear]``);
* the spring kinds' keys (their ``[design]`` section, ``[bounds]``, ``[requirements]``,
  ``[catalogue]``) and the helical spring's ``[spring]`` form: :mod:`govopt.springs.kinds`;
* the shared tables (``[speed]``, ``[material]``, ``[design]``, ``[engine]``,
  ``[[load_change]]``, ``[analysis]``, ``[requirements]``, ``[bounds]``, ``[catalogue]``) and the
  top level: :mod:`govopt.spec_keys`, which puts a type's whole spec together
  (:func:`govopt.spec_keys.spec_tables`).

A default or a range may depend on keys read before it in the same table: it is then a function
of the values read so far (a dict, SI), with ``default_text`` or ``range_text`` saying it in
words for the reference.

>>> k = Key("ball_arm", "length", "the bell crank's arm from the fulcrum to the ball's centre",
...         example="15 cm")
>>> k.required, k.unit, k.names
(True, 'm', ('ball_arm',))
>>> Key("ball", "weight", "each ball").names
('ball_weight', 'ball_mass')
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from .units import SI_UNITS


class _Required:
    """The default of a key that must be given."""

    def __repr__(self) -> str:
        return "REQUIRED"


#: the default of a key that must be given (:attr:`Key.default`)
REQUIRED: Any = _Required()

#: kinds of value that are not a quantity: a bare number, a whole number (a count), one of
#: ``choices``, a string, true/false, a table read by its own reader (a study's ``[study]``)
KINDS = ("number", "count", "choice", "text", "flag", "table")

#: ``"weight"``: the key is a stem: ``<stem>_weight`` (a force, converted to a mass with
#: standard gravity) or ``<stem>_mass``, one of the two
WEIGHT = "weight"

#: shapes of a value: one value, ``[low, high]`` (a search bound; equal ends fix the value),
#: a non-empty list
SHAPES = ("scalar", "pair", "list")


@dataclass(frozen=True)
class Key:
    """One key of a spec table (see the module's text).

    ``kind``: a dimension of :data:`govopt.units.SI_UNITS` (a string with units, read into
    SI), :data:`WEIGHT`, or one of :data:`KINDS`. ``default``: the SI value taken when the
    key is absent, :data:`REQUIRED`, ``None`` (optional, no value) or a function of the
    values read before it. ``low``/``high``: exclusive limits (SI; numbers or functions of
    the values read before); ``positive`` (the default for quantities and numbers) or
    ``nonnegative``; ``range_text``: the range in words where the limits do not say it
    plainly. ``choices``: the allowed strings of a choice, or strings a number or a list
    also accepts (``speed_change = "range"``); a function returning them where they are
    loaded on first use. ``when``: when the key applies or is required (words). ``example``:
    a value as a spec writes it, for templates. ``single``: a ``pair`` that also takes one
    value (which fixes it)."""

    name: str
    kind: str
    meaning: str
    default: Any = REQUIRED
    default_text: str = ""
    shape: str = "scalar"
    choices: tuple | Callable[[], tuple] = ()
    low: float | Callable | None = None
    high: float | Callable | None = None
    high_inclusive: bool = False
    positive: bool = True
    nonnegative: bool = False
    range_text: str = ""
    source: str = ""
    when: str = ""
    example: Any = None
    single: bool = False

    def __post_init__(self):
        assert self.kind in SI_UNITS or self.kind in KINDS or self.kind == WEIGHT, self.kind
        assert self.shape in SHAPES, self.shape

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    @property
    def quantity(self) -> bool:
        """A string with units (a dimension), not a bare number or a choice."""
        return self.kind in SI_UNITS and self.kind != "dimensionless"

    @property
    def names(self) -> tuple[str, ...]:
        """The names the key takes in a spec file: its own, or a weight's two."""
        if self.kind == WEIGHT:
            return f"{self.name}_weight", f"{self.name}_mass"
        return (self.name,)

    @property
    def dimension(self) -> str | None:
        """The dimension of its value in SI (a weight's is a mass), None for the other kinds."""
        if self.kind == WEIGHT:
            return "mass"
        return self.kind if self.kind in SI_UNITS else None

    @property
    def unit(self) -> str:
        """The SI unit of its value ('' for a bare number or a choice)."""
        dim = self.dimension
        return SI_UNITS[dim] if dim else ""

    def options(self) -> tuple:
        """:attr:`choices`, loaded where they are a function."""
        return tuple(self.choices() if callable(self.choices) else self.choices)

    def limit(self, which: str, values: dict | None):
        """``low`` or ``high`` (SI) given the values read before (None: no limit, or one that
        depends on values not read)."""
        bound = getattr(self, which)
        if callable(bound):
            try:
                return bound(values or {})
            except (KeyError, TypeError):
                return None
        return bound

    def default_value(self, values: dict | None):
        """The default given the values read before (a function's, or the value itself)."""
        if callable(self.default):
            return self.default(values or {})
        return None if self.default is REQUIRED else self.default

    def range_words(self) -> str:
        """The allowed values in words, for the reference and the schema's descriptions."""
        if self.kind == "choice":
            return "one of " + ", ".join(f'"{c}"' if isinstance(c, str) else str(c)
                                         for c in self.options())
        if self.kind in ("text", "flag", "table"):
            return ""
        if self.range_text:
            text = self.range_text
        else:
            lo, hi = self.limit("low", None), self.limit("high", None)
            unit = f" {self.unit}" if self.unit else ""
            close = "]" if self.high_inclusive else ")"
            if lo is not None and hi is not None:
                text = f"({lo:g}, {hi:g}{close}{unit}"
            elif lo is not None:
                text = f"> {lo:g}{unit}"
            elif hi is not None:
                text = (f"[0, {hi:g}{close}{unit}" if self.nonnegative
                        else f"(0, {hi:g}{close}{unit}" if self.positive
                        else f"{'<=' if self.high_inclusive else '<'} {hi:g}{unit}")
            elif self.nonnegative:
                text = ">= 0"
            elif self.positive:
                text = "> 0"
            else:
                text = "any"
        if self.shape == "pair":
            text = f"[low, high], each {text}; low <= high (equal ends fix it)"
            if self.single:
                text += ", or one value"
        extra = [c for c in self.options() if f'"{c}"' not in text]
        if extra:
            text += " or " + ", ".join(f'"{c}"' for c in extra)
        return text

    def default_words(self) -> str:
        """The default in words ('' for a required key)."""
        if self.required:
            return ""
        if self.default_text:
            return self.default_text
        value = self.default
        if value is None:
            return "none"
        if isinstance(value, bool):
            return str(value).lower()
        if isinstance(value, str):
            return f'"{value}"'
        if isinstance(value, tuple):
            inner = ", ".join(_number(v) for v in value)
            return f"[{inner}]{f' {self.unit}' if self.unit else ''}"
        return f"{_number(value)}{f' {self.unit}' if self.unit else ''}"


def _number(value) -> str:
    return f"{value:g}" if isinstance(value, float) else str(value)


@dataclass(frozen=True)
class Table:
    """A spec table: its path (``"governor"``, ``"valve_gear.table"``), what it is for, its
    keys in reading order. ``required``: the spec must have it; ``array``: an array of tables
    (``[[load_change]]``); ``open``: its keys are another reader's (a study's ``[study]``);
    ``when``: when it applies (words). The same as data, for the readers that check it (the
    parser and the JSON Schema): ``alternatives``, the choices between groups of keys (a
    choice is a tuple of groups, a group a tuple of key names, ``?`` after an optional one:
    the spec gives every required key of exactly one group and no key of the others);
    ``required_unless``: the top-level table whose presence makes this one optional;
    ``needs``: the top-level tables this one is read with."""

    name: str
    meaning: str
    keys: tuple[Key, ...] = ()
    required: bool = False
    array: bool = False
    open: bool = False
    when: str = ""
    alternatives: tuple = ()
    required_unless: str = ""
    needs: tuple[str, ...] = ()
    #: keys a reader names on a mistake, beyond the declared ones: name -> the hint
    aliases: dict = field(default_factory=dict, compare=False)

    def __post_init__(self):
        names = [n for k in self.keys for n in k.names]
        assert len(names) == len(set(names)), (self.name, names)

    def key(self, name: str) -> Key:
        """The declared key ``name`` (a weight by its stem or either of its names)."""
        for k in self.keys:
            if name == k.name or name in k.names:
                return k
        raise KeyError(f"{self.name}.{name}")

    @property
    def names(self) -> list[str]:
        """Every name a key of the table may take in a spec file, in declared order."""
        return [n for k in self.keys for n in k.names]


__all__ = ["KINDS", "REQUIRED", "SHAPES", "WEIGHT", "Key", "Table"]
