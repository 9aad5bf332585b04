"""Statistics helpers on the ground floor (no govopt imports): the studies' tolerance summaries
and the robust design's Monte-Carlo verification both read them."""

from __future__ import annotations

import math

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
