"""Points in the unit cube for sampled studies: a Latin hypercube or scrambled Sobol' points
(:mod:`scipy.stats.qmc`), seeded, so that a study's points are the same in every process and
every run. The samplers' columns become values by :meth:`govopt.study.definition.Sweep.sample`
or :meth:`govopt.study.tolerances.Tolerance.draw`."""

from __future__ import annotations

import numpy as np

from ..stats import SAMPLERS, unit_cube
from .errors import StudyError

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




__all__ = ["MAX_SEED", "SAMPLERS", "check_seed", "unit_cube"]
