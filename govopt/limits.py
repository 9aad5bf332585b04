"""Limits on every size a spec or an option can set, each with its reason.

A spec is a few KiB written by a person; these limits are far beyond any real governor and
keep every run within seconds and a few hundred MB whatever a spec says. Each one exceeded is
an error (exit 2) naming the key and the limit; docs/reference/limits-and-exit-codes.md lists
them. Work whose size a spec sets only through several keys (the robust design's evaluations,
the design search's dynamics) is counted as it is done, each part at its measured cost
(:func:`evaluation_seconds`, :class:`Work`), against a limit in estimated CPU seconds.
Spec files themselves (regular, at most 1 MiB, UTF-8, nested at most 32 deep) are checked by
:func:`govopt.spec.load_spec`.
"""

from __future__ import annotations

import contextlib
import contextvars
import math
import re
from dataclasses import dataclass

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
#: the highest speed of a speed band over its lowest (``speed.outer / speed.inner``; with
#: ``speed.irregularity`` delta: (2 + delta) / (2 - delta)): a governor floats over a band of a
#: few per cent to a few tens; past ten times its inner speed a band is a slip of the pen
#: (``1e7 rpm`` for ``300 rpm``), and its characteristic is no governor's
MAX_SPEED_RATIO = 10
#: the irregularity that gives that band: 2 (r - 1) / (r + 1)
MAX_IRREGULARITY = 2.0 * (MAX_SPEED_RATIO - 1) / (MAX_SPEED_RATIO + 1)
#: characters of a text (name, description): it is shown in reports and workbook cells
MAX_TEXT_CHARS = 1000
#: items in one list of a spec (a valve-gear table, a catalogue's wire diameters)
MAX_LIST_ITEMS = 1000
#: ``analysis.points``: configurations of the characteristic (default 31); a curve of a
#: thousand points is finer than any drawing, and design arrays grow with it
MAX_POINTS = 1001
#: ``analysis.harmonics``: Fourier harmonics of a periodic forcing (default 12); past the 50th
#: the valve gear's reaction is its friction's square wave alone, falling as 1/n
#: (:func:`govopt.governors.shaft.harmonics.truncation_error`); ``govopt design``'s vibration
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
#: each is a row of ~0.4 kB in the study's database (the points themselves are made a block at
#: a time, never held)
MAX_STUDY_POINTS = 1_000_000
#: ``requirements.robust_samples``: the Monte-Carlo verification's samples (default 2000):
#: its 95 % interval is then +-0.2 % at a probability near 1, +-0.6 % at 100 000; each sample
#: is one evaluation (:func:`evaluation_seconds`), so the samples a spec may ask are bounded
#: by :data:`MAX_MONTE_CARLO_SECONDS` too
MAX_ROBUST_SAMPLES = 100_000

# -- time: what one design's evaluation costs, and the work a run may do --------------------
# CPU seconds measured on the reference machine (2 cores shared, Python 3.11, numpy 2; the
# bulk evaluator over a few hundred designs), rounded up: each part of an evaluation that runs
# design by design, and the vectorised rest. An estimate of work counted before a run, not a
# timer: the same spec is refused or run on every machine.

#: the vectorised evaluation of one design (statics, k^2, the load changes' transients, the
#: classic measures): 0.35 ms at 31 configurations, 0.65 ms at 1001
ROW_SECONDS, ROW_SECONDS_PER_POINT = 4e-4, 4e-7
#: a type's forced vibration, design by design (Hamabe Part II: the valve gear's harmonics and
#: the response's peak-to-peak): 3.3-3.7 ms at 12-50 harmonics and 31 configurations, 4.2-5.2
#: ms at 1001
VIBRATION_SECONDS, VIBRATION_SECONDS_PER_POINT = 4e-3, 1.5e-6
#: a spring's own checks, design by design (a leaf's over the configurations: 9 ms at 31, 99 ms
#: at 1001; a wire grade's fatigue and the spring maker's checks: ~1.5 ms)
SPRING_CHECK_SECONDS, SPRING_CHECK_SECONDS_PER_POINT = 6e-3, 1e-4
#: a wire grade's checks of a helical spring, design by design (the static table, fatigue and
#: the spring maker's checks): 0.9-1.1 ms
WIRE_CHECK_SECONDS = 1.5e-3
#: Hamabe's friction strokes (eqs. 42-46) of one load change of one design with a friction band:
#: 15-20 ms
FRICTION_RUN_SECONDS = 2.5e-2
#: the robust design's search (corners, edges and inner maximisations of the candidates'
#: tolerance boxes, at every setting of the fitter's), estimated CPU seconds at most
MAX_ROBUST_SEARCH_SECONDS = 30.0
#: the robust design's Monte-Carlo verification (its samples, then the fitter's adjustment of
#: those that fail), estimated CPU seconds at most; the samples alone at most half of it
MAX_MONTE_CARLO_SECONDS = 20.0


#: the yield beside the verdict (:mod:`govopt.made`: its samples of made governors), estimated
#: CPU seconds at most: fewer samples where each costs more
MAX_YIELD_SECONDS = 2.0


#: one candidate's dash-pot window in ``govopt design``'s search
#: (:func:`govopt.optimize.design.dashpot_window`: the load-change transients at 25 dash-pot
#: settings): ~7 ms a load change (Hamabe's governor; 13 ms each of twenty), and the forced
#: vibration's bound at those settings, ~0.035 ms a harmonic
WINDOW_SECONDS_PER_LOAD_CHANGE, WINDOW_SECONDS_PER_HARMONIC = 8e-3, 4e-5
#: ``govopt design``'s dynamics (the dash-pot windows of the candidates checked best first,
#: the surrogate ordering them, the lattice screening them), estimated CPU seconds at most
MAX_DESIGN_DYNAMICS_SECONDS = 20.0


class WorkLimit(Exception):
    """The work counted by the running :class:`Work` would pass its limit (not done)."""


@dataclass
class Work:
    """Work counted in estimated CPU seconds (the constants above) against ``limit``, and the
    items counted (evaluations, candidates)."""

    limit: float
    spent: float = 0.0
    items: int = 0

    def charge(self, seconds: float, items: int = 0) -> None:
        """Count ``seconds`` of work, or raise :class:`WorkLimit` (nothing counted) if they
        would take it past its limit."""
        if self.spent + seconds > self.limit:
            raise WorkLimit
        self.spent += seconds
        self.items += items

    def left(self) -> float:
        return self.limit - self.spent


_WORK: contextvars.ContextVar[Work | None] = contextvars.ContextVar("govopt_work",
                                                                    default=None)


@contextlib.contextmanager
def counting(work: Work):
    """Within this block :func:`charge` counts against ``work``."""
    token = _WORK.set(work)
    try:
        yield work
    finally:
        _WORK.reset(token)


def running() -> Work | None:
    """The :class:`Work` that :func:`counting` is counting against, or None outside it."""
    return _WORK.get()


def charge(seconds: float, items: int = 0) -> None:
    """Count work against the running :class:`Work` (:func:`counting`), if any."""
    work = _WORK.get()
    if work is not None:
        work.charge(seconds, items)


def evaluation_seconds(points: int, *, vibration: bool = False, spring_checks: bool = False,
                       friction_runs: int = 0, wire_checks: bool = False) -> float:
    """Estimated CPU seconds of one design's evaluation in a bulk frame at ``points``
    configurations, with the parts that run design by design: a forced ``vibration``, the
    spring's own checks (``spring_checks``: a type's own spring, a leaf), a wire grade's checks
    of a helical spring (``wire_checks``), and ``friction_runs`` (load changes run with
    Hamabe's friction strokes). See the constants above for what each was measured at.

    >>> round(evaluation_seconds(31) * 1e3, 3), round(evaluation_seconds(31, vibration=True), 4)
    (0.412, 0.0045)
    """
    return (ROW_SECONDS + ROW_SECONDS_PER_POINT * points
            + (VIBRATION_SECONDS + VIBRATION_SECONDS_PER_POINT * points if vibration else 0.0)
            + (SPRING_CHECK_SECONDS + SPRING_CHECK_SECONDS_PER_POINT * points
               if spring_checks else 0.0)
            + (WIRE_CHECK_SECONDS if wire_checks else 0.0)
            + FRICTION_RUN_SECONDS * friction_runs)


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
    it (as :func:`govopt.optimize.windows.grid_steps` builds it; ``inf`` when not finite).

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
