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


def is_steep(x1: int, y1: int, x2: int, y2: int) -> bool:
    """Whether y is the major axis (``|Δy| > |Δx|``).

    >>> is_steep(0, 0, 1, 3)
    True
    """
    return abs(y2 - y1) > abs(x2 - x1)
