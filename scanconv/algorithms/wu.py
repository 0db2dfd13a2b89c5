"""Xiaolin Wu's anti-aliased line, with exact intensities.

Conventions
-----------
As in the published algorithm the end points are integers and are drawn at full intensity:
the line starts and ends on pixel centres. At each step of the major axis the ideal line
passes between two pixels of the minor axis, at exact distance ``f = frac(minor)`` above the
lower one; the lower pixel gets intensity ``1 - f`` and the upper ``f``, so every column (or
row, on steep lines) sums to exactly 1. The end points have ``f = 0``: the upper pixel's
intensity is 0 (it is listed, not drawn).

Wu's paper keeps ``f`` as an n-bit integer error term ``D`` and takes the top m bits as the
intensity level (2**m levels), drawing from both ends at once by symmetry; here ``f`` is
exact and an answer quantizes it only when asked for levels.

End points (:data:`ENDS`, the ``ends`` convention): ``full`` (the default, above) or
``coverage``, the widely copied version (Wikipedia's "Xiaolin Wu's line algorithm", Rosetta
Code's task): each end column is weighted by the part of it the line covers along the major
axis, ``xgap = 1 - frac(x1 + 1/2)`` at the first end and ``frac(x2 + 1/2)`` at the last (1/2
each for integer end points). Either way the end points may be fractions (:func:`wu_line`):
the end columns are ``round(x) = floor(x + 1/2)`` and the minor coordinate there is read off
the line, ``y_end = y1 + g (round(x1) - x1)``.

References
----------
Xiaolin Wu, "An efficient antialiasing technique", *Computer Graphics* (SIGGRAPH '91
Proceedings) 25(4), 143-152, 1991; Michael Abrash, "Fast Antialiasing", *Dr. Dobb's Journal*,
June 1992 (the same algorithm with the end points drawn at full intensity).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from fractions import Fraction

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from ..core.records import Step, new_step


def wu(x1: int, y1: int, x2: int, y2: int) -> Iterator[Step]:
    """Wu's line from (x1, y1) to (x2, y2), all octants: one step per unit of the major axis.

    ``Step.pixel`` is the lower (or left) pixel and ``Step.extra`` is ``(major, minor,
    lower_pixel, upper_pixel, lower_intensity, upper_intensity)`` with the minor coordinate
    and both intensities exact. The walk goes in the direction the major axis increases (the
    end points are swapped if needed, as for Bresenham). The major axis is x when
    ``|Δy| <= |Δx|``.

    Examples
    --------
    >>> for s in wu(0, 0, 4, 1):
    ...     print(s.extra[0], s.extra[1], s.extra[2], s.extra[3], s.extra[4], s.extra[5])
    0 0 (0, 0) (0, 1) 1 0
    1 1/4 (1, 0) (1, 1) 3/4 1/4
    2 1/2 (2, 0) (2, 1) 1/2 1/2
    3 3/4 (3, 0) (3, 1) 1/4 3/4
    4 1 (4, 1) (4, 2) 1 0
    """
    steep = abs(y2 - y1) > abs(x2 - x1)
    a1, b1, a2, b2 = (y1, x1, y2, x2) if steep else (x1, y1, x2, y2)
    if a2 < a1:
        a1, b1, a2, b2 = a2, b2, a1, b1
    da = a2 - a1
    grad = Fraction(b2 - b1, da) if da else Fraction(0)
    make, cls = new_step, Step
    for k in range(da + 1):
        a = a1 + k
        b: Number = normalize(b1 + grad * k)
        low = math.floor(b)
        f = normalize(b - low)
        lo_i, up_i = normalize(1 - f), f
        if steep:
            p, q = (low, a), (low + 1, a)
        else:
            p, q = (a, low), (a, low + 1)
        yield make(cls, (k, None, None, p, (a, b, p, q, lo_i, up_i)))


HALF = Fraction(1, 2)

ENDS = {
    "full": "end points drawn at full intensity (Wu 1991, Abrash 1992): each end column sums to 1",
    "coverage": "end columns weighted by the part of the column the line covers, "
    "xgap = 1 - frac(x1 + 1/2) and frac(x2 + 1/2) (Wikipedia's widely copied pseudocode)",
}
"""The ``ends`` convention of Wu's line, by name (the default first)."""


def end_gaps(a1: Number, a2: Number, ends: str) -> tuple[Number, Number]:
    """The weights of the first and last column: 1 each (``full``) or the covered part.

    >>> [str(g) for g in end_gaps(0, 10, "coverage") + end_gaps(Fraction(1, 4), Fraction(5, 2), "coverage")]
    ['1/2', '1/2', '1/4', '0']
    """
    if ends == "full":
        return 1, 1
    first = normalize(1 - (Fraction(a1) + HALF - math.floor(Fraction(a1) + HALF)))
    last = normalize(Fraction(a2) + HALF - math.floor(Fraction(a2) + HALF))
    return first, last


def wu_line(x1: Number, y1: Number, x2: Number, y2: Number, ends: str = "full") -> Iterator[Step]:
    """Wu's line with exact (possibly fractional) end points and the ``ends`` convention.

    One step per column ``a = round(a1) .. round(a2)`` of the major axis (end points swapped
    so that it increases); ``Step.extra`` is ``(major, minor, lower_pixel, upper_pixel,
    lower_intensity, upper_intensity, gap)``: the intensities are ``(1 - f) gap`` and
    ``f gap`` with ``gap`` the column's weight (1 inside, :func:`end_gaps` at the ends). With
    integer end points and ``ends="full"`` the steps are :func:`wu`'s.

    Rosetta Code's "Xiaolin Wu's line algorithm" (0, 1) to (10, 2), ends = coverage:

    >>> [(s.extra[2], str(s.extra[4])) for s in wu_line(0, 1, 10, 2, "coverage")][:3]
    [((0, 1), '1/2'), ((1, 1), '9/10'), ((2, 1), '4/5')]
    """
    if ends not in ENDS:
        raise InputError(f"unknown ends {ends!r} (choose from {', '.join(ENDS)})", "ends")
    steep = abs(Fraction(y2 - y1)) > abs(Fraction(x2 - x1))
    a1, b1, a2, b2 = (y1, x1, y2, x2) if steep else (x1, y1, x2, y2)
    if a2 < a1:
        a1, b1, a2, b2 = a2, b2, a1, b1
    grad = Fraction(b2 - b1) / (a2 - a1) if a2 != a1 else Fraction(0)
    c1, c2 = math.floor(Fraction(a1) + HALF), math.floor(Fraction(a2) + HALF)
    gap1, gap2 = end_gaps(a1, a2, ends)
    for k, a in enumerate(range(c1, c2 + 1)):
        b: Number = normalize(b1 + grad * (a - Fraction(a1)))
        low = math.floor(b)
        f = normalize(b - low)
        gap: Number = gap1 if a == c1 else gap2 if a == c2 else 1
        if a == c1 == c2:
            gap = normalize(gap1 + gap2 - 1) if ends == "coverage" else 1
        lo_i, up_i = normalize((1 - f) * gap), normalize(f * gap)
        p, q = ((low, a), (low + 1, a)) if steep else ((a, low), (a, low + 1))
        yield Step(k, None, None, p, (a, b, p, q, lo_i, up_i, normalize(gap)))


def is_steep(x1: int, y1: int, x2: int, y2: int) -> bool:
    """Whether y is the major axis (``|Δy| > |Δx|``).

    >>> is_steep(0, 0, 1, 3)
    True
    """
    return abs(y2 - y1) > abs(x2 - x1)
