"""Statistics helpers on the ground floor (no govopt imports): the studies' tolerance summaries
and samples, the yield of made governors and the robust design's Monte-Carlo verification all
read them."""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

#: z of the two-sided 95 % confidence interval (Wilson score interval)
Z95 = 1.959963984540054


def wilson(k: int, n: int, z: float = Z95) -> tuple[float, float]:
    """Wilson score interval of a binomial proportion ``k/n`` (E. B. Wilson, "Probable inference,
    the law of succession, and statistical inference", JASA 22, 1927; Agresti & Coull, Am. Stat.
    52, 1998): ``(p + z^2/2n -+ z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n)``.

    >>> [round(v, 4) for v in wilson(95, 100)]
    [0.8882, 0.9785]
    """
    if n == 0:
        return math.nan, math.nan
    p = k / n
    den = 1.0 + z * z / n
    mid = p + z * z / (2 * n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    lo = 0.0 if k == 0 else max(0.0, (mid - half) / den)  # exact ends, not rounding
    hi = 1.0 if k == n else min(1.0, (mid + half) / den)
    return lo, hi


#: a tolerance band ``+-X`` is read as +-3 standard deviations of a normal scatter (the usual
#: reading of a manufacturing tolerance: 99.73 % of the parts within it)
TOLERANCE_SIGMAS = 3.0


def truncated_normal(u, sigmas: float = TOLERANCE_SIGMAS) -> np.ndarray:
    """Offsets in half-widths of a tolerance band, at uniform fractions ``u`` (0 .. 1): a normal
    scatter whose band ``+-1`` is ``+-sigmas`` standard deviations, truncated at the band (a part
    outside its tolerance is rejected at inspection, so none is made), by the inverse of its
    distribution function: ``z = Phi^-1(Phi(-s) + u (Phi(s) - Phi(-s))) / s``. Every offset is
    inside ``(-1, 1)``; ``u = 0.5`` is the nominal part. (Johnson, Kotz and Balakrishnan,
    Continuous Univariate Distributions vol. 1, 2nd ed., 1994, section 10.1: the doubly
    truncated normal.)

    >>> [round(float(z), 4) for z in truncated_normal(np.array([0.0, 0.5, 0.841, 1.0]))]
    [-1.0, 0.0, 0.3316, 1.0]
    """
    from statistics import NormalDist  # the standard library's: no scipy on the yield's path

    phi = NormalDist()
    lo = phi.cdf(-sigmas)
    p = lo + np.clip(np.asarray(u, dtype=float), 0.0, 1.0) * (1.0 - 2.0 * lo)
    z = np.frompyfunc(lambda q: phi.inv_cdf(q) if 0.0 < q < 1.0 else math.copysign(
        math.inf, q - 0.5), 1, 1)(p).astype(float)
    return np.clip(z / sigmas, -1.0, 1.0)


#: the unit cube's samplers: Latin hypercube (McKay, Beckman and Conover 1979) and Sobol' points
#: with Owen scrambling, as scipy.stats.qmc implements them
SAMPLERS = ("lhs", "sobol")


@lru_cache(maxsize=2)
def unit_cube(kind: str, n: int, dim: int, seed: int) -> np.ndarray:
    """``n`` points in the unit cube of ``dim`` dimensions (an ``(n, dim)`` array, read-only):
    ``kind`` ``"sobol"`` (scrambled) or ``"lhs"``, seeded, so that the points are the same in
    every process and every run. Cached by its arguments: each process makes a study's points
    once (8 bytes a coordinate: 24 MB for a million points in three keys)."""
    if kind == "sobol":
        from scipy.stats import qmc

        u = qmc.Sobol(d=dim, scramble=True, seed=seed).random(n)
    else:
        u = latin_hypercube(n, dim, seed)
    u.flags.writeable = False
    return u


def latin_hypercube(n: int, dim: int, seed: int) -> np.ndarray:
    """``n`` points of a seeded Latin hypercube in ``dim`` dimensions (McKay, Beckman and
    Conover 1979): each coordinate's ``n`` strata ``((k - 1)/n, k/n]`` hit once, in a random
    order, at a uniform point within. The points of ``scipy.stats.qmc.LatinHypercube(d=dim,
    seed=seed).random(n)`` (its plain, scrambled form: the same generator draws the same
    numbers in the same order), with numpy alone (scipy.stats takes longer to import than the
    sample takes to make).

    >>> u = latin_hypercube(4, 2, 0)
    >>> sorted(np.floor(u[:, 0] * 4).astype(int).tolist()), bool(np.all((u > 0) & (u < 1)))
    ([0, 1, 2, 3], True)
    """
    rng = np.random.default_rng(seed)
    within = rng.uniform(size=(n, dim))
    perms = np.tile(np.arange(1, n + 1), (dim, 1))
    for i in range(dim):
        rng.shuffle(perms[i, :])
    return (perms.T - within) / n
