"""Numbers and quantities as a spec file writes them: read (with govopt's rules for units)
and written back for the spec parser."""

from __future__ import annotations

from .. import limits
from .errors import StudyError


def quantity(text: str, where: str):
    """``text`` as a pint quantity; an error names ``where`` (``sweep KEY``)."""
    from ..units import UnitError, malformed, normalise, registry, strict_units

    if len(text) > limits.MAX_QUANTITY_CHARS:
        raise StudyError(f"{limits.shorten(text)}: a quantity of at most "
                         f"{limits.MAX_QUANTITY_CHARS} characters (govopt's limit)", where=where)
    try:  # what pint would misread, or take minutes over ('9**9**9'), refused first
        strict_units(normalise(text), shown=text)
    except UnitError as exc:
        raise StudyError(f"cannot read {text!r} as a quantity: {exc}", where=where) from None
    try:
        return registry().Quantity(normalise(text))
    except Exception as exc:  # pint's own errors (undefined unit, syntax)
        raise StudyError(f"cannot read {text!r} as a quantity: {malformed(exc)}",
                         where=where) from None


def number_text(x: float) -> str:
    """A number as a spec writes it: the shortest text that reads back as the same double.

    >>> number_text(260.0), number_text(0.1), number_text(1e-7)
    ('260', '0.1', '1e-07')
    """
    s = repr(float(x))
    return s[:-2] if s.endswith(".0") else s
