"""Clipping against a rectangular window: Cohen–Sutherland and Liang–Barsky for line segments,
Sutherland–Hodgman for polygons. Exact arithmetic throughout (``int`` and ``Fraction``).

The window ``(xmin, ymin, xmax, ymax)`` is **closed**: a point on an edge is inside (its region
code is 0000), so a segment along an edge or touching a corner is kept.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from enum import Enum
from fractions import Fraction
from functools import partial
from typing import NamedTuple

from ..core.numeric import Number, normalize

Point = tuple[Number, Number]
Rect = tuple[Number, Number, Number, Number]
"""``(xmin, ymin, xmax, ymax)``."""


class Edge(str, Enum):
    """A window boundary, in Hearn & Baker's order (left, right, bottom, top)."""

    LEFT = "left"
    RIGHT = "right"
    BOTTOM = "bottom"
    TOP = "top"

    @property
    def bit(self) -> int:
        """Its bit in the region code: left 1, right 2, bottom 4, top 8 (written TBRL)."""
        return {"left": 1, "right": 2, "bottom": 4, "top": 8}[self.value]

    def __str__(self) -> str:
        return self.value


EDGES = (Edge.LEFT, Edge.RIGHT, Edge.BOTTOM, Edge.TOP)


def region_code(point: Point, window: Rect) -> int:
    """The 4-bit region code: bit 1 left (x < xmin), bit 2 right (x > xmax), bit 3 below
    (y < ymin), bit 4 above (y > ymax); written TBRL, most significant bit first.

    >>> f"{region_code((7, 9), (4, 4, 10, 8)):04b}", region_code((4, 8), (4, 4, 10, 8))
    ('1000', 0)
    """
    x, y = point
    xmin, ymin, xmax, ymax = window
    code = 1 if x < xmin else 2 if x > xmax else 0
    return code | (4 if y < ymin else 8 if y > ymax else 0)


def boundary(edge: Edge, window: Rect) -> Number:
    """The coordinate of an edge's line (``xmin`` for the left edge, ...)."""
    return window[{"left": 0, "bottom": 1, "right": 2, "top": 3}[edge.value]]


def crossing(p1: Point, p2: Point, edge: Edge, value: Number) -> Point:
    """Where the line through ``p1`` and ``p2`` meets the edge line at ``value``, exactly:
    ``y = y1 + m(x - x1)`` on a vertical edge, ``x = x1 + (y - y1)/m`` on a horizontal one
    (``x = x1`` if the line is vertical).

    >>> crossing((7, 9), (11, 4), Edge.TOP, 8)
    (Fraction(39, 5), 8)
    """
    (x1, y1), (x2, y2) = p1, p2
    if edge in (Edge.LEFT, Edge.RIGHT):
        m = Fraction(y2 - y1) / (x2 - x1)
        return normalize(value), normalize(y1 + m * (value - x1))
    if x1 == x2:
        return normalize(x1), normalize(value)
    return normalize(x1 + Fraction(x2 - x1) * (value - y1) / (y2 - y1)), normalize(value)


# --- Cohen–Sutherland -------------------------------------------------------------------------


class CSIteration(NamedTuple):
    """One clip of Cohen–Sutherland: end point ``end`` (1 or 2) with region code ``code`` is
    moved to ``point`` on ``edge``, where its code is ``new_code``; ``codes`` are both end
    points' codes afterwards."""

    k: int
    end: int
    code: int
    edge: Edge
    old: Point
    point: Point
    new_code: int
    codes: tuple[int, int]


class CSResult(NamedTuple):
    codes: tuple[int, int]
    """The given end points' region codes."""
    iterations: tuple[CSIteration, ...]
    accepted: bool
    segment: tuple[Point, Point] | None
    """The clipped segment, from the P1 side to the P2 side; ``None`` if rejected."""


def cohen_sutherland(p1: Point, p2: Point, window: Rect) -> CSResult:
    """Cohen–Sutherland line clipping, Hearn & Baker's form.

    Notes
    -----
    Repeat: if ``code1 OR code2 = 0000`` accept; if ``code1 AND code2 != 0000`` reject (both
    end points beyond the same edge); otherwise take the end point that is outside (P1 if its
    code is not 0000, else P2), find the first edge of its code in the order left, right,
    bottom, top, move the end point to the line's crossing with that edge, and recompute its
    code. Each clip clears a bit for good, so there are at most four iterations. The end
    points keep their names (no swap), so the result runs from the P1 side to the P2 side.

    References: Cohen & Sutherland (1967), in Newman & Sproull, *Principles of Interactive
    Computer Graphics*; Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 6-7.

    Examples
    --------
    GeeksforGeeks' example, window (4, 4)-(10, 8):

    >>> r = cohen_sutherland((7, 9), (11, 4), (4, 4, 10, 8))
    >>> [(i.end, i.edge.value, i.point) for i in r.iterations]
    [(1, 'top', (Fraction(39, 5), 8)), (2, 'right', (10, Fraction(21, 4)))]
    >>> cohen_sutherland((1, 5), (4, 1), (4, 4, 10, 8)).accepted
    False
    """
    pts = [p1, p2]
    codes = [region_code(p1, window), region_code(p2, window)]
    given = (codes[0], codes[1])
    iterations: list[CSIteration] = []
    while True:
        if not codes[0] | codes[1]:
            return CSResult(given, tuple(iterations), True, (pts[0], pts[1]))
        if codes[0] & codes[1]:
            return CSResult(given, tuple(iterations), False, None)
        i = 0 if codes[0] else 1
        edge = next(e for e in EDGES if codes[i] & e.bit)
        old = pts[i]
        pts[i] = crossing(p1, p2, edge, boundary(edge, window))
        codes[i] = region_code(pts[i], window)
        iterations.append(
            CSIteration(
                len(iterations) + 1, i + 1, region_code(old, window), edge, old, pts[i],
                codes[i], (codes[0], codes[1]),
            )
        )  # fmt: skip


# --- Liang–Barsky -----------------------------------------------------------------------------


class LBRow(NamedTuple):
    """One boundary of Liang–Barsky: ``p_k``, ``q_k``, ``r_k = q_k/p_k`` (``None`` when
    ``p_k = 0``) and ``u1``, ``u2`` after it."""

    k: int
    edge: Edge
    p: Number
    q: Number
    r: Number | None
    u1: Number
    u2: Number


class LBResult(NamedTuple):
    rows: tuple[LBRow, ...]
    outside: Edge | None
    """An edge the segment is parallel to and outside of (rejected at once), or ``None``."""
    accepted: bool
    segment: tuple[Point, Point] | None


def liang_barsky(p1: Point, p2: Point, window: Rect) -> LBResult:
    """Liang–Barsky line clipping with exact parameters.

    Notes
    -----
    With ``x = x1 + u·Δx``, ``y = y1 + u·Δy``, 0 <= u <= 1, the segment is inside where
    ``u·p_k <= q_k`` for k = 1..4: ``p1 = -Δx, q1 = x1 - xmin`` (left), ``p2 = Δx,
    q2 = xmax - x1`` (right), ``p3 = -Δy, q3 = y1 - ymin`` (bottom), ``p4 = Δy,
    q4 = ymax - y1`` (top). ``p_k = 0``: parallel to that edge, outside if ``q_k < 0``;
    ``p_k < 0``: entering, ``u1 = max(u1, q_k/p_k)``; ``p_k > 0``: leaving,
    ``u2 = min(u2, q_k/p_k)``; rejected if ``u1 > u2``. All four rows are computed (an
    exam answer shows them); ``u1 = u2`` keeps a single point.

    References: Liang & Barsky, "A new concept and method for line clipping", ACM TOG 3(1),
    1984; Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 6-7.

    Examples
    --------
    >>> r = liang_barsky((5, 20), (55, 90), (25, 30, 75, 80))
    >>> [(row.p, row.q) for row in r.rows]
    [(-50, -20), (50, 70), (-70, -10), (70, 60)]
    >>> r.rows[-1].u1, r.rows[-1].u2, r.segment
    (Fraction(2, 5), Fraction(6, 7), ((25, 48), (Fraction(335, 7), 80)))
    """
    (x1, y1), (x2, y2) = p1, p2
    dx, dy = x2 - x1, y2 - y1
    xmin, ymin, xmax, ymax = window
    pq = ((-dx, x1 - xmin), (dx, xmax - x1), (-dy, y1 - ymin), (dy, ymax - y1))
    u1: Number = 0
    u2: Number = 1
    outside = None
    rows = []
    for k, (edge, (p, q)) in enumerate(zip(EDGES, pq, strict=True), 1):
        r = None
        if p == 0:
            if q < 0 and outside is None:
                outside = edge
        else:
            r = normalize(Fraction(q) / p)
            if p < 0:
                u1 = max(u1, r)
            else:
                u2 = min(u2, r)
        rows.append(LBRow(k, edge, normalize(p), normalize(q), r, u1, u2))
    if outside is not None or u1 > u2:
        return LBResult(tuple(rows), outside, False, None)
    a = (normalize(x1 + u1 * dx), normalize(y1 + u1 * dy))
    b = (normalize(x1 + u2 * dx), normalize(y1 + u2 * dy))
    return LBResult(tuple(rows), None, True, (a, b))


# --- Sutherland–Hodgman -----------------------------------------------------------------------


class Case(str, Enum):
    """Where an edge V1 -> V2 of the polygon runs, relative to one window edge."""

    IN_IN = "in -> in"
    IN_OUT = "in -> out"
    OUT_IN = "out -> in"
    OUT_OUT = "out -> out"

    def __str__(self) -> str:
        return self.value


class SHRow(NamedTuple):
    v1: Point
    v2: Point
    case: Case
    output: tuple[Point, ...]


class SHStage(NamedTuple):
    """Clipping against one window edge: its input vertices, a row per polygon edge, and
    the output vertices (the next stage's input)."""

    edge: Edge
    inputs: tuple[Point, ...]
    rows: tuple[SHRow, ...]
    outputs: tuple[Point, ...]


def inside(point: Point, edge: Edge, window: Rect) -> bool:
    """True if ``point`` is on the window's side of ``edge`` (on the edge counts as inside)."""
    return not region_code(point, window) & edge.bit


def sutherland_hodgman(vertices: Sequence[Point], window: Rect) -> tuple[SHStage, ...]:
    """Sutherland–Hodgman polygon clipping against the window's four edges in turn.

    Notes
    -----
    For each window edge, each polygon edge V1 -> V2 (the edges V_i -> V_{i+1} in order,
    the last one V_n -> V_1) emits:
    in -> in: V2; in -> out: the crossing I; out -> in: I and V2; out -> out: nothing. A
    vertex on the edge is inside, and a crossing that *is* the vertex (V1 or V2 on the edge)
    is emitted once, not twice. A concave polygon whose clipped part falls into pieces comes
    out as one polygon, the pieces joined by edges along the window boundary.

    References: Sutherland & Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974; Hearn &
    Baker, *Computer Graphics, C Version*, 2nd ed., section 6-8.

    Examples
    --------
    GeeksforGeeks' example (which prints 162 and 174 from integer arithmetic):

    >>> stages = sutherland_hodgman([(100, 150), (200, 250), (300, 200)], (150, 150, 200, 200))
    >>> stages[-1].outputs
    ((150, Fraction(325, 2)), (150, 200), (200, 200), (200, 175))
    """
    stages = []
    current = tuple(vertices)
    for edge in EDGES:
        value = boundary(edge, window)
        rows, out = stage_rows(
            current,
            partial(inside, edge=edge, window=window),
            partial(crossing, edge=edge, value=value),
        )
        stages.append(SHStage(edge, current, rows, out))
        current = out
    return tuple(stages)


def stage_rows(
    current: Sequence[Point],
    is_inside: Callable[[Point], bool],
    cut: Callable[[Point, Point], Point],
) -> tuple[tuple[SHRow, ...], tuple[Point, ...]]:
    """One Sutherland–Hodgman stage, against one edge of any window: each polygon edge
    V1 -> V2's case and output (in -> in: V2; in -> out: the crossing; out -> in: the crossing
    and V2; out -> out: nothing; a crossing that *is* the vertex is output once), and the
    output vertices. ``is_inside`` tests a point against the edge, ``cut`` is where a polygon
    edge crosses it."""
    rows = []
    out: list[Point] = []
    n = len(current)
    for i in range(n):
        v1, v2 = current[i], current[(i + 1) % n]
        in1, in2 = is_inside(v1), is_inside(v2)
        emit: tuple[Point, ...]
        if in1 and in2:
            case, emit = Case.IN_IN, (v2,)
        elif in1:
            at = cut(v1, v2)
            case, emit = Case.IN_OUT, (() if at == v1 else (at,))
        elif in2:
            at = cut(v1, v2)
            case, emit = Case.OUT_IN, ((v2,) if at == v2 else (at, v2))
        else:
            case, emit = Case.OUT_OUT, ()
        rows.append(SHRow(v1, v2, case, emit))
        out.extend(emit)
    return tuple(rows), tuple(out)


def polygon_area(vertices: Sequence[Point]) -> Fraction:
    """The signed area by the shoelace formula, exactly (counter-clockwise positive).

    >>> polygon_area([(0, 0), (4, 0), (4, 3)])
    Fraction(6, 1)
    """
    n = len(vertices)
    twice = Fraction(0)
    for i in range(n):
        (x1, y1), (x2, y2) = vertices[i], vertices[(i + 1) % n]
        twice += x1 * y2 - x2 * y1
    return twice / 2


def is_convex(vertices: Sequence[Point]) -> bool:
    """True if every turn of the polygon goes the same way (collinear turns ignored).

    >>> is_convex([(0, 0), (4, 0), (4, 3)]), is_convex([(0, 0), (4, 0), (1, 1), (0, 4)])
    (True, False)
    """
    n = len(vertices)
    signs = set()
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = vertices[i], vertices[(i + 1) % n], vertices[(i + 2) % n]
        cross = (bx - ax) * (cy - by) - (by - ay) * (cx - bx)
        if cross:
            signs.add(cross > 0)
    return len(signs) <= 1


def overlapping_edges(vertices: Sequence[Point], window: Rect) -> tuple[tuple[Point, Point], ...]:
    """Edges of ``vertices`` along a window edge that overlap another such edge: the
    degenerate connecting edges Sutherland–Hodgman leaves in a clipped concave polygon.

    >>> overlapping_edges([(0, 0), (1, 0), (1, 2), (2, 2), (2, 0), (3, 0), (3, 3), (0, 3)],
    ...                   (0, 2, 3, 3))
    ()
    >>> overlapping_edges([(0, 2), (1, 2), (2, 2), (3, 2), (3, 3), (2, 3), (2, 2), (1, 2),
    ...                    (1, 3), (0, 3)], (0, 2, 3, 3))
    (((1, 2), (2, 2)), ((2, 2), (1, 2)))
    """
    n = len(vertices)
    along = []
    for i in range(n):
        a, b = vertices[i], vertices[(i + 1) % n]
        if a == b:
            continue
        for axis, values in ((0, (window[0], window[2])), (1, (window[1], window[3]))):
            if a[axis] == b[axis] and a[axis] in values:
                lo, hi = sorted((a[1 - axis], b[1 - axis]))
                along.append((axis, a[axis], lo, hi, (a, b)))
    found = []
    for i, (ax, v, lo, hi, e) in enumerate(along):
        if any(
            j != i and ax2 == ax and v2 == v and min(hi, hi2) > max(lo, lo2)
            for j, (ax2, v2, lo2, hi2, _) in enumerate(along)
        ):
            found.append(e)
    return tuple(found)
