"""Points in the unit cube for sampled studies: a Latin hypercube or scrambled Sobol' points
(:mod:`scipy.stats.qmc`), seeded, so that a study's points are the same in every process and
every run. The samplers' columns become values by :meth:`govopt.study.definition.Sweep.sample`
or :meth:`govopt.study.tolerances.Tolerance.draw`."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .errors import StudyError

#: the samplers: Latin hypercube (McKay, Beckman and Conover 1979) and Sobol' points with Owen
#: scrambling, as scipy.stats.qmc implements them
SAMPLERS = ("lhs", "sobol")
#: the largest seed (numpy's SeedSequence takes any non-negative integer; 64 bits keep it exact
#: in JSON readers that hold numbers as doubles up to 2^53 ... and as integers beyond)
MAX_SEED = 2**64 - 1


def check_seed(seed, where: str = "seed") -> int:
    """``seed`` as a whole number from 0 to :data:`MAX_SEED` (one line naming ``where`` if
    not).

    >>> check_seed(7)
    7
    >>> check_seed(-1, "--seed")
    Traceback (most recent call last):
    ...
    govopt.study.errors.StudyError: --seed: expected a whole number from 0 to 2^64 - 1, got -1
    """
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer) or not (
            0 <= seed <= MAX_SEED):
        from ..limits import shorten

        raise StudyError(f"expected a whole number from 0 to 2^64 - 1, got {shorten(seed)}",
                         where=where)
    return int(seed)


@lru_cache(maxsize=2)
def unit_cube(kind: str, n: int, dim: int, seed: int) -> np.ndarray:
    """``n`` points in the unit cube of ``dim`` dimensions (an ``(n, dim)`` array, read-only):
    ``kind`` ``"sobol"`` (scrambled) or ``"lhs"``. Cached by its arguments: each process makes
    a study's points once (8 bytes a coordinate: 24 MB for a million points in three keys)."""
    from scipy.stats import qmc

    engine = (qmc.Sobol(d=dim, scramble=True, seed=seed) if kind == "sobol"
              else qmc.LatinHypercube(d=dim, seed=seed))
    u = engine.random(n)
    u.flags.writeable = False
    return u
