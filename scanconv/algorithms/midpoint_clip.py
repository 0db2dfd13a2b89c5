"""Midpoint subdivision line clipping (Sproull & Sutherland): a segment that is neither
trivially accepted (both region codes 0000) nor trivially rejected (codes AND to non-zero) is
split at its midpoint, and each half is tested the same way, until every piece is decided or
is one pixel long.

Each step is one :class:`Piece` (in the order they are taken, depth first, the half nearer P1
first): the piece, its end codes, the AND, and what was done. Conventions, named and settable:
``midpoint`` ``rounded`` (half up, pixel coordinates: the default), ``floor`` (the hardware
shift ``(a + b) >> 1``) or ``exact`` (fractions); a piece at most one unit long that is still
undecided keeps its inside end (``precision`` 1). ``stop``: ``length`` (the default: split
until decided or one unit long) or ``edge`` (as published answers that stop when a midpoint
lands on the window's edge: a piece from a point on an edge to a point beyond that same edge
lies outside but for that point, which is kept as the clipped end without further splits).

References: R. F. Sproull and I. E. Sutherland, "A clipping divider", AFIPS FJCC 1968;
Hearn & Baker, *Computer Graphics*, C version, 2nd ed., §6-7 (midpoint subdivision).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize, round_half_up
from .clipping import Point, Rect, region_code

MIDPOINTS = ("rounded", "floor", "exact")
STOPS = ("length", "edge")


class Piece(NamedTuple):
    """One piece of the segment and what the subdivision does with it."""

    k: int
    a: Point
    b: Point
    code_a: int
    code_b: int
    action: str
    """``accept``, ``reject``, ``split``, ``keep inside end`` (one unit long) or ``edge
    point`` (``stop="edge"``: the end on the window's edge kept, the rest beyond it)."""
    mid: Point | None
    """The midpoint a split uses."""
    code_mid: int | None


def _mid(a: Number, b: Number, how: str) -> Number:
    s = Fraction(a) + Fraction(b)
    if how == "exact":
        return normalize(s / 2)
    return math.floor(s / 2) if how == "floor" else round_half_up(s / 2)


def _on_edge_end(a: Point, b: Point, ca: int, cb: int, window: Rect) -> Point | None:
    """The end of ``a``-``b`` on a window edge when the other end is beyond that same edge
    (so the piece is outside but for that end), else ``None``."""
    for on, code, other in ((a, ca, cb), (b, cb, ca)):
        if code:
            continue
        beyond = (
            (on[0] == window[0] and other & 1)
            or (on[0] == window[2] and other & 2)
            or (on[1] == window[1] and other & 4)
            or (on[1] == window[3] and other & 8)
        )
        if beyond:
            return on
    return None


def subdivide(
    p1: Point, p2: Point, window: Rect, midpoint: str = "rounded", stop: str = "length"
) -> Iterator[Piece]:
    """The pieces, depth first.

    >>> for p in subdivide((-4, 2), (4, 2), (0, 0, 8, 8)):
    ...     print(p.a, p.b, p.action, p.mid)
    (-4, 2) (4, 2) split (0, 2)
    (-4, 2) (0, 2) split (-2, 2)
    (-4, 2) (-2, 2) reject None
    (-2, 2) (0, 2) split (-1, 2)
    (-2, 2) (-1, 2) reject None
    (-1, 2) (0, 2) keep inside end None
    (0, 2) (4, 2) accept None

    With ``stop="edge"`` the first midpoint, (0, 2), is on the left edge, so the half beyond
    it is decided at once:

    >>> for p in subdivide((-4, 2), (4, 2), (0, 0, 8, 8), stop="edge"):
    ...     print(p.a, p.b, p.action, p.mid)
    (-4, 2) (4, 2) split (0, 2)
    (-4, 2) (0, 2) edge point None
    (0, 2) (4, 2) accept None
    """
    if midpoint not in MIDPOINTS:
        raise InputError(f"midpoint must be rounded, floor or exact, got {midpoint!r}", "midpoint")
    if stop not in STOPS:
        raise InputError(f"stop must be length or edge, got {stop!r}", "stop")
    todo: list[tuple[Point, Point]] = [(p1, p2)]
    k = 0
    while todo:
        a, b = todo.pop()
        ca, cb = region_code(a, window), region_code(b, window)
        if ca == 0 and cb == 0:
            yield Piece(k, a, b, ca, cb, "accept", None, None)
        elif ca & cb:
            yield Piece(k, a, b, ca, cb, "reject", None, None)
        elif stop == "edge" and _on_edge_end(a, b, ca, cb, window) is not None:
            yield Piece(k, a, b, ca, cb, "edge point", None, None)
        elif abs(Fraction(b[0] - a[0])) <= 1 and abs(Fraction(b[1] - a[1])) <= 1:
            yield Piece(k, a, b, ca, cb, "keep inside end", None, None)
        else:
            m = (_mid(a[0], b[0], midpoint), _mid(a[1], b[1], midpoint))
            yield Piece(k, a, b, ca, cb, "split", m, region_code(m, window))
            todo += [(m, b), (a, m)]  # the half nearer P1 is taken first
        k += 1


def visible(pieces: list[Piece]) -> list[tuple[Point, Point]]:
    """The visible parts: accepted pieces (and kept inside ends), joined where they meet.

    >>> visible(list(subdivide((-4, 2), (4, 2), (0, 0, 8, 8))))
    [((0, 2), (4, 2))]
    """
    parts: list[tuple[Point, Point]] = []
    for p in pieces:
        if p.action == "accept":
            seg = (p.a, p.b)
        elif p.action in ("keep inside end", "edge point"):
            end = p.a if p.code_a == 0 else p.b if p.code_b == 0 else None
            if end is None:
                continue
            seg = (end, end)
        else:
            continue
        if parts and parts[-1][1] == seg[0]:
            parts[-1] = (parts[-1][0], seg[1])
        else:
            parts.append(seg)
    return parts
