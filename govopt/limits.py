"""Limits on every size a spec or an option can set, each with its reason.

A spec is a few KiB written by a person; these limits are far beyond any real governor and
keep every run within seconds and a few hundred MB whatever a spec says. Each one exceeded is
an error (exit 2) naming the key and the limit; the README's "Errors" section lists them.
Spec files themselves (regular, at most 1 MiB, UTF-8, nested at most 32 deep) are checked by
:func:`govopt.spec.load_spec`.
"""

from __future__ import annotations

import math
import re

#: characters in one quantity string: pint's parser is recursive and super-linear (a 2 kB sum
#: takes 0.2 s, 7 kB exhausts the recursion); a spec's quantity is ~20 characters
MAX_QUANTITY_CHARS = 200
#: largest |exponent| of a power in a quantity string (``cm^2``, ``2.1*10^11 Pa``): Python's
#: integers are exact, so ``9**9**9`` would compute a number of 370 million digits. Powers are
#: not nested (no power of a power) and an exponent is a plain number
MAX_EXPONENT = 30
#: every quantity and number of a spec, in SI units, is zero or of magnitude within
#: [MIN_MAGNITUDE, MAX_MAGNITUDE]: the real range is ~1e-4 m to ~2e11 Pa; beyond it products
#: and powers (``d^4``, ``1/I``) over- or underflow double precision
MIN_MAGNITUDE, MAX_MAGNITUDE = 1e-12, 1e12
#: characters of a text (name, description): it is shown in reports and workbook cells
MAX_TEXT_CHARS = 1000
#: items in one list of a spec (a valve-gear table, a catalogue's wire diameters)
MAX_LIST_ITEMS = 1000
#: ``analysis.points``: configurations of the characteristic (default 31); a curve of a
#: thousand points is finer than any drawing, and design arrays grow with it
MAX_POINTS = 1001
#: ``analysis.harmonics``: Fourier harmonics of a periodic forcing (default 12); past the 50th
#: the valve gear's reaction is its friction's square wave alone, falling as 1/n
#: (:func:`govopt.governors.shaft.valvegear.truncation_error`); ``govopt design``'s vibration
#: objective takes ~30 s at 50 harmonics (the bundled design; ~20 s at 12)
MAX_HARMONICS = 50
#: ``[[load_change]]`` tables: each is a transient solved for every design candidate
MAX_LOAD_CHANGES = 20
#: uniform points of a load change's time grid (24 a period of its fastest oscillation): the
#: bundled specs use at most ~600; a flywheel 1e5 times Hamabe's would need millions and take
#: minutes. Past it the grid is cut: the settling time is then found on the modes' envelope
#: (settling.envelope_settling), or reported inf with ``truncated`` ("not decided"), never
#: silently
MAX_TRANSIENT_POINTS = 20_000
#: (flying mass, central load) pairs on the design's weight grid (``bounds.*_weight`` on
#: ``catalogue.weight_step``)
MAX_MASSES = 100_000
#: weight-grid pairs x ``analysis.points``: the design's statics arrays hold ~100 bytes per
#: cell, so at most ~200 MB
MAX_GRID_CELLS = 2_000_000
#: springs in a helical catalogue (wire diameters x coil radii x turns within the bounds):
#: ~100 bytes each
MAX_SPRINGS = 1_000_000
#: weight-grid pairs x catalogue springs screened by ``govopt design`` (time ~0.1 s per
#: million, and the candidates that pass are kept)
MAX_COMBINATIONS = 50_000_000
#: points of a trade study (``govopt study run``: a sweep's NUM, a grid's product, samples):
#: each is a row of ~0.7 kB in the study's database and a list entry in memory
MAX_STUDY_POINTS = 1_000_000
#: characters of a value quoted in an error message
SHOWN_CHARS = 80


def shorten(value, width: int = SHOWN_CHARS) -> str:
    """``repr(value)``, or if longer than ``width`` characters its first ``width // 2`` with
    the full size stated.

    >>> shorten("18 cm")
    "'18 cm'"
    >>> shorten("1 cm + " * 1000, 20)
    "'1 cm + 1 ... (7000 characters)"
    """
    text = repr(value)
    if len(text) <= width:
        return text
    size = (f"{len(value)} characters" if isinstance(value, str)
            else f"{len(value)} items" if isinstance(value, list | tuple | dict)
            else f"{len(text)} characters")
    return f"{text[:width // 2]}... ({size})"


def printable(text: str) -> str:
    r"""``text`` with control characters (other than newlines) shown as escapes: a file name or
    spec string never sends a terminal an escape sequence.

    >>> printable("a\x1b[31mred\tb\n")
    'a\\x1b[31mred\\tb\n'
    """
    return "".join(c if c == "\n" or c.isprintable() else repr(c)[1:-1] for c in text)


def shorten_values(message: str, width: int = SHOWN_CHARS) -> str:
    """``message`` with each quoted value or list longer than ``width`` characters cut as
    :func:`shorten` cuts it: no error line echoes a 200 kB value.

    >>> shorten_values("got '" + "x" * 100 + "' here", 10)
    "got 'xxxx... (102 characters) here"
    >>> shorten_values("'no over-regulation' " + "y" * 100 + " the mode's decay", 10)[-16:]
    "the mode's decay"
    """
    n = f"{{{width},}}"  # quotes that open and close a value, not an apostrophe ("mode's")
    long_value = rf"(?<!\w)('[^']{n}'|\"[^\"]{n}\"|\[[^\[\]]{n}\])(?!\w)"
    return re.sub(long_value, lambda m: f"{m[0][:width // 2]}... ({len(m[0])} characters)",
                  message)


def magnitude_error(value: float, unit: str = "") -> str | None:
    """Why an SI value is outside govopt's range (zero, or a magnitude within
    :data:`MIN_MAGNITUDE` .. :data:`MAX_MAGNITUDE`), else None.

    >>> magnitude_error(0.18, "m"), magnitude_error(0.0), magnitude_error(-3e5, "N")
    (None, None, None)
    >>> magnitude_error(1e-300, "m")
    "is 1e-300 m, outside govopt's range (zero or 1e-12 to 1e+12 m in magnitude)"
    """
    if value == 0 or MIN_MAGNITUDE <= abs(value) <= MAX_MAGNITUDE:
        return None
    unit = f" {unit}" if unit else ""
    return (f"is {value:.4g}{unit}, outside govopt's range (zero or {MIN_MAGNITUDE:g} to "
            f"{MAX_MAGNITUDE:g}{unit} in magnitude)")


def count_error(value: float, limit: int, what: str) -> str | None:
    """``"at most LIMIT WHAT (govopt's limit), got VALUE"`` when ``value > limit``."""
    if value > limit:
        shown = f"{value:.3g}" if value >= 1e6 else f"{int(value)}"
        return f"at most {limit} {what} (govopt's limit), got {shown}"
    return None


def steps(lo: float, hi: float, step: float) -> float:
    """How many points of the grid ``k * step`` lie in ``[lo, hi]``, counted without building
    it (as :func:`govopt.optimize.design._steps` builds it; ``inf`` when not finite).

    >>> steps(4.0, 16.0, 0.25), steps(0.0, 0.0, 0.25), steps(1.0, 1e9, 1e-9)
    (49, 1, 999999999000000001)
    """
    if lo == hi:
        return 1
    a, b = lo / step, hi / step
    if not (math.isfinite(a) and math.isfinite(b)):
        return math.inf
    return max(math.floor(b + 1e-9) - math.ceil(a - 1e-9) + 1, 0)


def design_size_error(req, points: int, spring: str | None, mass_key: str):
    """The first design grid past its limit, as ``(key, message)``, else None: weight-grid
    pairs, their cells with ``points``, catalogue springs and their combinations with the
    weights (``req``: :class:`govopt.inputs.Requirements`; ``spring``: the governor's spring
    kind, a :class:`govopt.springs.kinds.SpringKind` that counts its own catalogue, None for a
    dead-weight governor). Counted from the bounds and steps before anything is allocated."""
    grid = steps(*req.flying_mass, req.mass_step) * steps(*req.central_mass, req.mass_step)
    step_key = "catalogue.weight_step"
    what = (f"(flying, central) weight pairs on the weight grid (bounds.{mass_key}_weight on "
            f"{step_key})")
    checks = [(step_key, count_error(grid, MAX_MASSES, what)),
              ("analysis.points", count_error(grid * points, MAX_GRID_CELLS,
                                              "weight pairs x analysis.points"))]
    if spring is not None:
        checks += spring.size_errors(req, grid)
    return next(((key, msg) for key, msg in checks if msg), None)
