"""The continuity of two Bezier segments at their join: end derivatives compared exactly.

Segment ``A`` with control points ``P_0 .. P_n`` ends where segment ``B`` with ``Q_0 .. Q_m``
starts; the join is C^k when the derivatives of orders ``0 .. k`` agree at ``A(1)`` and ``B(0)``.

References
----------
G. Farin, *Curves and Surfaces for CAGD: A Practical Guide*, 5th ed., Morgan Kaufmann, 2002
(derivatives of a Bezier curve; C1 and C2 joins of piecewise Bezier curves).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

from ..core.numeric import Number
from .curve_limits import Point, norm_value


class EndDerivatives(NamedTuple):
    """A Bezier segment at one end: its position and first and second derivatives."""

    position: Point
    first: Point
    second: Point


def _sub(p: Point, q: Point) -> Point:
    """``p - q``.

    >>> _sub((3, 1), (1, 2))
    (2, -1)
    """
    return norm_value(p[0] - q[0]), norm_value(p[1] - q[1])


def _scale(c: Number, p: Point) -> Point:
    """``c p``.

    >>> _scale(3, (1, -2))
    (3, -6)
    """
    return norm_value(c * p[0]), norm_value(c * p[1])


def end_derivatives(points: Sequence[Point], at_end: bool) -> EndDerivatives:
    """Position, first and second derivative of a Bezier segment at ``t = 1`` or ``t = 0``.

    ``B'(1) = n (P_n - P_{n-1})``, ``B''(1) = n (n - 1) (P_n - 2 P_{n-1} + P_{n-2})``, and at
    ``t = 0`` the same with ``P_0, P_1, P_2`` (``B'(0) = n (P_1 - P_0)``). A degree-1 segment
    has ``B'' = 0``.

    >>> end_derivatives([(0, 0), (1, 2), (3, 3), (4, 0)], True)
    EndDerivatives(position=(4, 0), first=(3, -9), second=(-6, -24))
    """
    pts = tuple(points)
    n = len(pts) - 1
    if at_end:
        pts = pts[::-1]
    d1 = _scale(n, _sub(pts[1], pts[0]))
    d2: Point = (0, 0)
    if n >= 2:
        d2 = _scale(n * (n - 1), _sub(_sub(pts[2], pts[1]), _sub(pts[1], pts[0])))
    if at_end:
        d1 = _scale(-1, d1)
    return EndDerivatives(pts[0], d1, d2)


def continuity_level(first: Sequence[Point], second: Sequence[Point]) -> int:
    """The highest ``k`` in 0, 1, 2 with C^k at the join, or -1 if the segments do not meet.

    >>> continuity_level([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)])
    1
    """
    a = end_derivatives(first, True)
    b = end_derivatives(second, False)
    level = -1
    for k in range(3):
        if a[k] != b[k]:
            break
        level = k
    return level


def same_direction(u: Point, v: Point) -> bool:
    """True if ``v`` is a positive multiple of ``u`` and both are non-zero (a G1 tangent).

    >>> same_direction((2, 1), (4, 2)), same_direction((2, 1), (-2, -1)), same_direction((0, 0), (1, 0))
    (True, False, False)
    """
    cross = u[0] * v[1] - u[1] * v[0]
    dot = u[0] * v[0] + u[1] * v[1]
    return cross == 0 and dot > 0
