"""Bezier curves: the Bernstein form, tabulated, and de Casteljau's construction at one t.

Both are generators of :class:`~scanconv.core.records.Step` records with ``p`` and
``decision`` ``None`` and the algorithm's columns in ``extra``, exact for rational control
points and parameters.

References
----------
G. Farin, *Curves and Surfaces for CAGD: A Practical Guide*, 5th ed., Morgan Kaufmann, 2002:
the de Casteljau algorithm and the Bernstein form of a Bezier curve.
"""

from __future__ import annotations

import itertools
import math
import operator
from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import Any

from ..core.numeric import normalize
from ..core.records import Step
from .curve_limits import DEFAULT_SAMPLES, Point, Value, check_points, check_samples, norm_value
from .sampling import curve_pixel


def bernstein(n: int, t: Any, s: Any = None) -> tuple[Any, ...]:
    """The Bernstein weights ``B_{i,n}(t) = C(n, i) t^i (1 - t)^(n - i)``, ``i = 0 .. n``.

    Exact for exact ``t``; works elementwise on numpy arrays too. With ``s`` given it stands for
    ``1 - t``: ``bernstein(n, k, N - k)`` gives the integer numerators of the weights at
    ``t = k / N`` (their common denominator is ``N^n``).

    References
    ----------
    G. Farin, *Curves and Surfaces for CAGD: A Practical Guide*, 5th ed., Morgan Kaufmann,
    2002 (the Bernstein form of a Bezier curve).

    Examples
    --------
    >>> [str(w) for w in bernstein(3, Fraction(1, 2))]
    ['1/8', '3/8', '3/8', '1/8']
    >>> bernstein(3, 1, 1)
    (1, 3, 3, 1)
    """
    if s is None:
        s = 1 - t
    return tuple(math.comb(n, i) * t**i * s ** (n - i) for i in range(n + 1))


def bezier(points: Sequence[Point], samples: int = DEFAULT_SAMPLES) -> Iterator[Step]:
    """Tabulate the Bezier curve of ``points`` at ``t = k / samples``, ``k = 0 .. samples``.

    ``Step.extra`` is ``(t, B_{0,n}(t), ..., B_{n,n}(t), x(t), y(t))``, exact for rational
    control points.

    Notes
    -----
    ``B(t) = sum_i B_{i,n}(t) P_i`` with the Bernstein weights of :func:`bernstein`, degree
    ``n = len(points) - 1``; each row is computed directly (no accumulated error). Pixels are
    ``floor(v + 1/2)`` of each coordinate.

    References
    ----------
    G. Farin, *Curves and Surfaces for CAGD: A Practical Guide*, 5th ed., Morgan Kaufmann,
    2002 (the Bernstein form of a Bezier curve).

    Examples
    --------
    >>> for s in bezier([(0, 0), (1, 2), (3, 3), (4, 0)], 2):
    ...     print(s.k, *(str(v) for v in s.extra), s.pixel)
    0 0 1 0 0 0 0 0 (0, 0)
    1 1/2 1/8 3/8 3/8 1/8 2 15/8 (2, 2)
    2 1 0 0 0 1 4 0 (4, 0)
    """
    pts = check_points(points, 2, "a Bezier curve")
    n = len(pts) - 1
    big_n = check_samples(samples)
    # Integer arithmetic: at t = k/N the weights are c_i / N^n with integer c_i, and with the
    # points scaled to integers by their common denominator L, x(t) = sum c_i X_i / (N^n L).
    den = big_n**n
    scale = math.lcm(*(Fraction(c).denominator for p in pts for c in p))
    xs = [int(p[0] * scale) for p in pts]
    ys = [int(p[1] * scale) for p in pts]
    # bezier([(0,0), (1,2), (3,3), (4,0)], 8) -> t = 1/2: B = 1/8 3/8 3/8 1/8 ; point (2, 1.875)
    for k in range(big_n + 1):
        c = bernstein(n, k, big_n - k)
        w = tuple(normalize(Fraction(ci, den)) for ci in c)
        x = normalize(Fraction(sum(map(operator.mul, c, xs)), den * scale))
        y = normalize(Fraction(sum(map(operator.mul, c, ys)), den * scale))
        yield Step(k, None, None, curve_pixel(x, y), (normalize(Fraction(k, big_n)), *w, x, y))


def lerp(p: Point, q: Point, t: Value) -> Point:
    """``(1 - t) p + t q``, exact for exact values.

    >>> lerp((0, 0), (1, 2), Fraction(1, 2))
    (Fraction(1, 2), 1)
    """
    return norm_value(p[0] + t * (q[0] - p[0])), norm_value(p[1] + t * (q[1] - p[1]))


def de_casteljau(points: Sequence[Point], t: Value) -> Iterator[Step]:
    """De Casteljau's construction of the Bezier point at ``t``: one step per level.

    Step ``r`` holds the points ``P_i^(r)``, ``i = 0 .. n - r``, in ``extra`` (padded with
    ``None`` to ``n + 1`` entries); the last step holds the curve point alone. ``pixel`` is the
    rounded ``P_0^(r)`` (the control points of the left half of the subdivided curve).

    Notes
    -----
    ``P_i^(0) = P_i`` and ``P_i^(r) = (1 - t) P_i^(r-1) + t P_{i+1}^(r-1)``; exact for rational
    ``t`` and points. The final point equals the Bernstein form ``B(t)``.

    References
    ----------
    G. Farin, *Curves and Surfaces for CAGD: A Practical Guide*, 5th ed., Morgan Kaufmann,
    2002 (the de Casteljau algorithm).

    Examples
    --------
    >>> for s in de_casteljau([(0, 0), (1, 2), (3, 3), (4, 0)], Fraction(1, 2)):
    ...     print(s.k, *(f"({v[0]}, {v[1]})" for v in s.extra if v is not None))
    0 (0, 0) (1, 2) (3, 3) (4, 0)
    1 (1/2, 1) (2, 5/2) (7/2, 3/2)
    2 (5/4, 7/4) (11/4, 2)
    3 (2, 15/8)
    """
    level = check_points(points, 2, "a Bezier curve")
    n = len(level) - 1
    # de_casteljau([(0,0), (1,2), (3,3), (4,0)], 1/2) -> r=1: (0.5,1) (2,2.5) (3.5,1.5) ;
    #   r=2: (1.25,1.75) (2.75,2) ; r=3: (2, 1.875)
    for r in range(n + 1):
        yield Step(r, None, None, curve_pixel(*level[0]), (*level, *(None,) * r))
        level = tuple(lerp(p, q, t) for p, q in itertools.pairwise(level))
