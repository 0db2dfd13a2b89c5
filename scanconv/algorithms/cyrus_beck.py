"""Cyrus–Beck line clipping against any convex polygon window, with exact parameters.

The segment is ``P(t) = P0 + t·D``, ``D = P1 - P0``, ``0 <= t <= 1``. For each window edge with
outward normal ``N`` and a point ``E`` on it, ``P(t)`` is on the inner side where
``N·(P(t) - E) <= 0``; the boundary is crossed at ``t = N·(P0 - E) / (-N·D)``. With ``N·D < 0``
the segment is entering (``tE = max``), with ``N·D > 0`` leaving (``tL = min``), with
``N·D = 0`` parallel (outside if ``N·(P0 - E) > 0``). It is rejected when ``tE > tL``.

Conventions, named and settable: the ``normals`` are ``outward`` (Cyrus & Beck's and Foley's
form, the default) or ``inward`` (Hearn & Baker's: every sign in the table flips, ``t`` does
not); the clipped ``ends`` are kept ``exact`` or ``truncated`` toward zero (C's integer cast).
On a rectangle it is Liang–Barsky: the same ``t`` values (``tests/test_cyrus_beck.py``).

References: M. Cyrus and J. Beck, "Generalized two- and three-dimensional clipping",
Computers & Graphics 3(1), 1978; Foley, van Dam, Feiner & Hughes, *Computer Graphics*,
2nd ed., §3.12.4.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize, round_trunc

Point = tuple[Number, Number]

NORMALS = ("outward", "inward")
ENDS = ("exact", "truncated")
MAX_EDGES = 64


class CBRow(NamedTuple):
    """One window edge against the segment."""

    edge: int
    """The edge from window vertex i to vertex i + 1."""
    point: Point
    """``E``: the edge's first vertex."""
    normal: Point
    """``N`` as the table shows it (outward or inward)."""
    n_dot_d: Number
    """``N·D`` (shown normal)."""
    n_dot_w: Number
    """``N·(P0 - E)`` (shown normal)."""
    t: Number | None
    """Where the segment's line crosses the edge's line; ``None`` when parallel."""
    kind: str
    """``entering``, ``leaving``, ``parallel, inside`` or ``parallel, outside``."""
    t_enter: Number
    t_leave: Number
    """``tE`` and ``tL`` after this edge."""


class CBResult(NamedTuple):
    rows: tuple[CBRow, ...]
    accepted: bool
    segment: tuple[Point, Point] | None


def _dot(a: Point, b: Point) -> Number:
    return normalize(a[0] * b[0] + a[1] * b[1])


def check_convex(window: Sequence[Point]) -> int:
    """The window's orientation, ``+1`` counter-clockwise or ``-1`` clockwise; an
    :class:`InputError` unless it is a convex polygon with area.

    >>> check_convex([(0, 0), (4, 0), (4, 4), (0, 4)]), check_convex([(0, 0), (0, 4), (4, 0)])
    (1, -1)
    """
    n = len(window)
    if not 3 <= n <= MAX_EDGES:
        raise InputError(f"a window has 3 to {MAX_EDGES} vertices, got {n}", "window")
    signs = set()
    for i in range(n):
        a, b, c = window[i], window[(i + 1) % n], window[(i + 2) % n]
        cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
        if cross:
            signs.add(cross > 0)
    if len(signs) != 1:
        raise InputError("the window must be a convex polygon (with area)", "window")
    return 1 if signs.pop() else -1


def cyrus_beck(
    p0: Point, p1: Point, window: Sequence[Point], normals: str = "outward", ends: str = "exact"
) -> CBResult:
    """Cyrus–Beck clipping of ``p0``–``p1`` against the convex ``window``.

    >>> r = cyrus_beck((-2, 1), (6, 3), [(0, 0), (4, 0), (4, 4), (0, 4)])
    >>> [(row.normal, row.t, row.kind) for row in r.rows]
    [((0, -4), Fraction(-1, 2), 'entering'), ((4, 0), Fraction(3, 4), 'leaving'), ((0, 4), Fraction(3, 2), 'leaving'), ((-4, 0), Fraction(1, 4), 'entering')]
    >>> r.segment
    ((0, Fraction(3, 2)), (4, Fraction(5, 2)))
    """
    if normals not in NORMALS:
        raise InputError(f"normals are outward or inward, got {normals!r}", "normals")
    if ends not in ENDS:
        raise InputError(f"ends are exact or truncated, got {ends!r}", "ends")
    turn = check_convex(window)
    d = (normalize(p1[0] - p0[0]), normalize(p1[1] - p0[1]))
    shown = 1 if normals == "outward" else -1
    t_enter: Number = 0
    t_leave: Number = 1
    outside = False
    rows = []
    n = len(window)
    for i in range(n):
        e, f = window[i], window[(i + 1) % n]
        ex, ey = f[0] - e[0], f[1] - e[1]
        out = (ey * turn, -ex * turn)  # the outward normal
        nd = _dot(out, d)
        nw = _dot(out, (p0[0] - e[0], p0[1] - e[1]))
        t: Number | None = None
        if nd == 0:
            kind = "parallel, outside" if nw > 0 else "parallel, inside"
            outside = outside or nw > 0
        else:
            t = normalize(Fraction(nw) / -nd)
            if nd < 0:
                kind, t_enter = "entering", max(t_enter, t)
            else:
                kind, t_leave = "leaving", min(t_leave, t)
        normal = (normalize(shown * out[0]), normalize(shown * out[1]))
        rows.append(CBRow(i, e, normal, shown * nd, shown * nw, t, kind, t_enter, t_leave))
    if outside or t_enter > t_leave:
        return CBResult(tuple(rows), False, None)

    def at(t: Number) -> Point:
        x, y = normalize(p0[0] + t * d[0]), normalize(p0[1] + t * d[1])
        return (round_trunc(x), round_trunc(y)) if ends == "truncated" else (x, y)

    return CBResult(tuple(rows), True, (at(t_enter), at(t_leave)))
