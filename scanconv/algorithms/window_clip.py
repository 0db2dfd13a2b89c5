"""Sutherland–Hodgman polygon clipping against any convex window (a triangle, a hexagon, ...),
edge by edge in the window's own order, with exact arithmetic.

The window's edges ``C1 -> C2``, ``C2 -> C3``, ..., ``Cn -> C1`` are taken counter-clockwise
(a window given clockwise is reversed, and the answer says so). A point is inside an edge when
it lies on the window's side of its line or on the line: ``(C2 - C1) x (P - C1) >= 0``. The
closed window keeps what lies on its edges, as the rectangle's clipping does
(:func:`scanconv.algorithms.clipping.sutherland_hodgman`, whose cases and rows these are).
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from .clipping import Point, SHRow, polygon_area, stage_rows

MAX_WINDOW_VERTICES = 64
"""Most vertices of a clipping window (one stage, a table, per window edge)."""


class WindowEdge(NamedTuple):
    """One edge of a convex window, ``a -> b``, named after its vertices (``C1C2``)."""

    name: str
    a: Point
    b: Point

    def __str__(self) -> str:
        return self.name


class WindowStage(NamedTuple):
    """Clipping against one window edge: its input vertices, a row per polygon edge, and the
    output vertices (the next stage's input)."""

    edge: WindowEdge
    inputs: tuple[Point, ...]
    rows: tuple[SHRow, ...]
    outputs: tuple[Point, ...]


def side(p: Point, edge: WindowEdge) -> Number:
    """``(b - a) x (p - a)``: positive on the window's side (left of ``a -> b``), 0 on the line.

    >>> side((1, 1), WindowEdge("C1C2", (0, 0), (4, 0))), side((1, -1), WindowEdge("", (0, 0), (4, 0)))
    (4, -4)
    """
    (ax, ay), (bx, by) = edge.a, edge.b
    return (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax)


def crossing(v1: Point, v2: Point, edge: WindowEdge) -> Point:
    """Where ``v1 -> v2`` crosses the line of ``edge``: ``v1 + t (v2 - v1)`` with
    ``t = s1 / (s1 - s2)``, ``s`` the :func:`side` values (exact).

    >>> crossing((2, -2), (2, 2), WindowEdge("C1C2", (0, 0), (4, 0)))
    (2, 0)
    """
    s1, s2 = side(v1, edge), side(v2, edge)
    t = Fraction(s1) / (s1 - s2)
    return (normalize(v1[0] + t * (v2[0] - v1[0])), normalize(v1[1] + t * (v2[1] - v1[1])))


def convex_window(vertices: Sequence[Point]) -> tuple[tuple[Point, ...], bool]:
    """The window's vertices counter-clockwise, and whether they were given clockwise; a
    window that is not a convex polygon of 3 or more distinct corners is refused.

    >>> convex_window([(0, 0), (0, 4), (4, 0)])
    (((4, 0), (0, 4), (0, 0)), True)
    """
    pts = tuple(vertices)
    if len(pts) < 3:
        raise InputError(f"a window needs at least 3 vertices, got {len(pts)}", "window")
    if len(pts) > MAX_WINDOW_VERTICES:
        raise InputError(f"at most {MAX_WINDOW_VERTICES} window vertices, got {len(pts)}", "window")
    area = polygon_area(pts)
    if area == 0:
        raise InputError("the window has no area (its vertices are on one line)", "window")
    n = len(pts)
    ccw = pts if area > 0 else pts[::-1]
    for i in range(n):
        a, b, c = ccw[i], ccw[(i + 1) % n], ccw[(i + 2) % n]
        if a == b or side(c, WindowEdge("", a, b)) < 0:
            raise InputError(
                "the window is not convex (Sutherland-Hodgman clips against a convex window; "
                "Weiler-Atherton clips against any polygon)",
                "window",
            )
    return ccw, area < 0


def window_edges(window: Sequence[Point]) -> tuple[WindowEdge, ...]:
    """The edges ``Ci -> Ci+1`` of a counter-clockwise window, named ``CiCi+1``."""
    n = len(window)
    return tuple(
        WindowEdge(f"C{i + 1}C{(i + 1) % n + 1}", window[i], window[(i + 1) % n]) for i in range(n)
    )


def _stage(current: tuple[Point, ...], edge: WindowEdge) -> WindowStage:
    rows, out = stage_rows(current, lambda p: side(p, edge) >= 0, lambda a, b: crossing(a, b, edge))
    return WindowStage(edge, current, rows, out)


def sutherland_hodgman_window(
    vertices: Sequence[Point], window: Sequence[Point]
) -> tuple[WindowStage, ...]:
    """Sutherland–Hodgman clipping of ``vertices`` against the convex, counter-clockwise
    ``window``, one stage per window edge in the window's order.

    Notes
    -----
    For each window edge, each polygon edge V1 -> V2 emits: in -> in: V2; in -> out: the
    crossing I; out -> in: I and V2; out -> out: nothing (on the edge's line counts as
    inside; a crossing that *is* the vertex is emitted once).

    References: Sutherland & Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974 (any
    convex clipping region); Foley, van Dam, Feiner & Hughes, *Computer Graphics*, 2nd ed.,
    section 3.14.1.

    Examples
    --------
    A square clipped by a triangle:

    >>> stages = sutherland_hodgman_window([(0, 0), (4, 0), (4, 4), (0, 4)],
    ...                                    [(1, -1), (6, 4), (1, 4)])
    >>> [str(s.edge) for s in stages], stages[-1].outputs
    (['C1C2', 'C2C3', 'C3C1'], ((4, 4), (1, 4), (1, 0), (2, 0), (4, 2)))
    """
    stages = []
    current = tuple(vertices)
    for edge in window_edges(window):
        stage = _stage(current, edge)
        stages.append(stage)
        current = stage.outputs
    return tuple(stages)


def overlapping_window_edges(
    vertices: Sequence[Point], window: Sequence[Point]
) -> tuple[tuple[Point, Point], ...]:
    """Edges of the clipped ``vertices`` along one window edge's line that overlap another such
    edge: the degenerate connecting edges a concave polygon leaves
    (:func:`scanconv.algorithms.clipping.overlapping_edges` for any convex window).

    >>> overlapping_window_edges([(0, 2), (1, 2), (1, 3), (2, 3), (2, 2), (3, 2), (2, 2),
    ...                           (1, 2)], [(0, 2), (3, 2), (0, 5)])
    (((0, 2), (1, 2)), ((2, 2), (3, 2)), ((3, 2), (2, 2)), ((1, 2), (0, 2)))
    """
    n = len(vertices)
    along: list[tuple[int, Fraction, Fraction, tuple[Point, Point]]] = []
    for k, edge in enumerate(window_edges(window)):
        dx, dy = edge.b[0] - edge.a[0], edge.b[1] - edge.a[1]
        for i in range(n):
            a, b = vertices[i], vertices[(i + 1) % n]
            if a != b and side(a, edge) == 0 and side(b, edge) == 0:
                ta = Fraction((a[0] - edge.a[0]) * dx + (a[1] - edge.a[1]) * dy)
                tb = Fraction((b[0] - edge.a[0]) * dx + (b[1] - edge.a[1]) * dy)
                along.append((k, min(ta, tb), max(ta, tb), (a, b)))
    return tuple(
        e
        for i, (k, lo, hi, e) in enumerate(along)
        if any(
            j != i and k2 == k and min(hi, hi2) > max(lo, lo2)
            for j, (k2, lo2, hi2, _) in enumerate(along)
        )
    )
