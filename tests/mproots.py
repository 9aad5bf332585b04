"""mpmath's polynomial roots for the tests' high-precision references, on every mpmath."""

from __future__ import annotations

import mpmath


def polyroots(coeffs, **kwargs):
    """Roots of the polynomial with ``coeffs`` highest power first, on mpmath 1.3 and >= 1.4
    (which deprecates the descending order and takes ``asc=True``).

    >>> sorted(float(r.real) for r in polyroots([1, -3, 2]))
    [1.0, 2.0]
    """
    try:
        return mpmath.polyroots(list(coeffs)[::-1], asc=True, **kwargs)
    except TypeError:
        return mpmath.polyroots(list(coeffs), **kwargs)
