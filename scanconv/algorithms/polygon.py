"""Scan-line polygon filling with an edge table and an active edge table, exactly.

:func:`scanline_fill` yields one :class:`ScanLine` per scan line (the active edges, their
intersections, the spans filled, the edges added and removed); :func:`fill_pixels` gives just
the filled pixels. Coordinates are ``(x, y)`` with y up; vertices may be integers or
:class:`~fractions.Fraction` values, and every intersection is an exact fraction.

Conventions (stated once, used by every function here, by
:mod:`scanconv.algorithms.coverage` and by :mod:`scanconv.algorithms.raster_fill`):

* **Pixel centres.** Pixel ``(x, y)`` is the unit square centred on the integer point
  ``(x, y)``; a pixel is inside the polygon when its centre is. Scan line ``y`` runs through
  the centres of row ``y``.
* **Half-open spans (left rule).** A span between intersections ``x_a <= x_b`` is
  ``[x_a, x_b)``: it fills the pixels ``ceil(x_a) .. ceil(x_b) - 1``. A centre exactly on a
  left edge is filled, one exactly on a right edge is not.
* **Half-open edges (bottom rule, upper end excluded).** An edge takes part in the scan lines
  ``y_min <= y < y_max``. So a vertex between a rising and a falling edge is counted once
  (one edge ends there, the other starts), a local minimum twice (both edges start: a span of
  length zero), a local maximum not at all (both end); the top row of a polygon with a
  horizontal top edge is left to the polygon above it. Horizontal edges are dropped: their
  two neighbours already bound the spans.

With these rules two polygons sharing an edge never fill the same pixel and leave no gap
between them (``tests/test_polygon.py`` checks it).

References
----------
Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 3-11 (scan-line polygon fill,
sorted edge table, active edge list); Foley, van Dam, Feiner & Hughes, *Computer Graphics:
Principles and Practice*, 2nd ed., section 3.6 (the half-open rules for spans and edges).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize, round_half_up
from ..core.records import Pixel
from .lines import bresenham, orient
from .process_choices import FillRule

Point = tuple[Number, Number]
"""A vertex ``(x, y)``, exact."""


RULES = tuple(r.value for r in FillRule)
"""The fill rules: even-odd (alternate) and nonzero winding."""


class Rule(NamedTuple):
    """A fill rule: its name, and whether a scan line's crossings alternate between inside
    and outside (even-odd: odd crossings are inside) or add up, +1 up and -1 down, to the
    winding number that is inside where it is not 0 (nonzero)."""

    name: str
    alternates: bool


_RULES = (Rule("even-odd", True), Rule("nonzero", False))


def fill_rule(rule: str) -> Rule:
    """The fill rule named ``rule`` (checked: :func:`check_rule`).

    >>> fill_rule("nonzero").alternates
    False
    """
    check_rule(rule)
    return next(r for r in _RULES if r.name == rule)


MAX_VERTICES = 1000
"""Most vertices of a polygon filled with tables (every row lists the active edges)."""

MAX_FILL_CELLS = 10**6
"""Largest pixel bounding box (columns x rows) of a filled polygon: its pixels are listed."""


class Edge(NamedTuple):
    """A row of the edge table: a non-horizontal edge, stored from its lower end."""

    idx: int
    """``i``: the edge runs from vertex ``i`` to vertex ``i + 1`` (0-based, cyclic)."""
    y_min: Number
    """y of the lower end."""
    y_max: Number
    """y of the upper end (excluded)."""
    x_bottom: Number
    """x at the lower end."""
    inv_m: Number
    """``1/m = Δx / Δy``: how much x changes from one scan line to the next."""
    direction: int
    """``+1`` if the edge runs upward from vertex i to vertex i + 1, ``-1`` if downward (the
    nonzero rule adds it at each crossing)."""

    @property
    def first_line(self) -> int:
        """The first scan line the edge crosses: ``ceil(y_min)``."""
        return math.ceil(self.y_min)

    def x_at(self, y: Number) -> Number:
        """The exact x where scan line ``y`` crosses the edge's line."""
        return normalize(self.x_bottom + (y - self.y_min) * Fraction(self.inv_m))


class Active(NamedTuple):
    """An entry of the active edge table on one scan line."""

    edge: int
    """The edge's index (see :attr:`Edge.idx`)."""
    x: Number
    """The intersection with this scan line (exact)."""
    inv_m: Number
    """The increment of x to the next scan line."""
    y_max: Number
    """The edge leaves the table at the first scan line ``>= y_max``."""


class ScanLine(NamedTuple):
    """What the scan-line algorithm does on one scan line."""

    y: int
    removed: tuple[int, ...]
    """Edges that left the active table here (``y >= y_max``)."""
    added: tuple[int, ...]
    """Edges that entered from the edge table here (``ceil(y_min) = y``)."""
    active: tuple[Active, ...]
    """The active edge table, sorted by x (ties: by 1/m, the order just above)."""
    spans: tuple[tuple[Number, Number], ...]
    """The half-open spans ``[x_a, x_b)`` the rule fills."""
    runs: tuple[tuple[int, int], ...]
    """For each span, the pixels ``(first, last)`` it fills: ``ceil(x_a)``, ``ceil(x_b) - 1``
    (``last < first``: the span contains no pixel centre)."""


def check_rule(rule: str) -> str:
    """``rule`` if it is one of :data:`RULES`, else :class:`InputError`.

    >>> check_rule("odd")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: unknown fill rule 'odd' (choose from even-odd, nonzero)
    """
    if rule not in RULES:
        raise InputError(f"unknown fill rule {rule!r} (choose from {', '.join(RULES)})", "rule")
    return rule


def vertices_from_coords(coords: Sequence[Number]) -> tuple[Point, ...]:
    """Pair the coordinates ``x1 y1 x2 y2 ...`` into vertices (counts checked, not shape).

    >>> vertices_from_coords([0, 0, 4, 0, 2])
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: a polygon needs an x and a y for each vertex: got 5 coordinates, an odd number
    """
    n = len(coords)
    if n % 2:
        raise InputError(
            f"a polygon needs an x and a y for each vertex: got {n} coordinates, an odd number",
            "vertices",
        )
    if n // 2 > MAX_VERTICES:
        raise InputError(f"at most {MAX_VERTICES} polygon vertices, got {n // 2}", "vertices")
    return tuple((normalize(coords[i]), normalize(coords[i + 1])) for i in range(0, n, 2))


def check_polygon(vertices: Sequence[Sequence[Number]]) -> tuple[tuple[Point, ...], int]:
    """The vertices with consecutive repeats dropped (also the last equal to the first), and
    how many were dropped; :class:`InputError` for fewer than 3 vertices, too many, a bounding
    box beyond :data:`MAX_FILL_CELLS`, or a degenerate polygon (all vertices on one line).

    >>> check_polygon([(0, 0), (4, 0), (4, 0), (2, 3), (0, 0)])
    (((0, 0), (4, 0), (2, 3)), 2)
    >>> check_polygon([(0, 0), (2, 2), (5, 5)])
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: degenerate polygon: all 3 vertices lie on one line, so it has no area
    """
    given = len(vertices)
    if given < 3:
        raise InputError(f"a polygon needs at least 3 vertices, got {given}", "vertices")
    if given > MAX_VERTICES:
        raise InputError(f"at most {MAX_VERTICES} polygon vertices, got {given}", "vertices")
    pts: list[Point] = []
    for v in vertices:
        p = (normalize(Fraction(v[0])), normalize(Fraction(v[1])))
        if not pts or p != pts[-1]:
            pts.append(p)
    while len(pts) > 1 and pts[-1] == pts[0]:
        pts.pop()
    if len(pts) < 3 or all(_cross(pts[0], pts[1], p) == 0 for p in pts[2:]):
        raise InputError(
            f"degenerate polygon: all {given} vertices lie on one line, so it has no area",
            "vertices",
        )
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    cells = (math.floor(max(xs)) - math.ceil(min(xs)) + 1) * (
        math.floor(max(ys)) - math.ceil(min(ys)) + 1
    )
    if cells > MAX_FILL_CELLS:
        raise InputError(
            f"the polygon covers {cells:,} pixel cells; at most {MAX_FILL_CELLS:,} are filled",
            "vertices",
        )
    return tuple(pts), given - len(pts)


def _cross(a: Point, b: Point, c: Point) -> Number:
    """``(b - a) x (c - a)``: zero when the three points are collinear."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def edge_table(vertices: Sequence[Point]) -> tuple[tuple[Edge, ...], tuple[int, ...]]:
    """The sorted edge table (by y_min, then x, then 1/m) and the horizontal edges dropped.

    >>> edges, horizontal = edge_table([(0, 0), (4, 0), (2, 3)])
    >>> horizontal
    (0,)
    >>> [(e.idx, e.y_min, e.y_max, e.x_bottom, e.inv_m) for e in edges]
    [(2, 0, 3, 0, Fraction(2, 3)), (1, 0, 3, 4, Fraction(-2, 3))]
    """
    edges, horizontal = [], []
    n = len(vertices)
    for i in range(n):
        (xa, ya), (xb, yb) = vertices[i], vertices[(i + 1) % n]
        if ya == yb:
            horizontal.append(i)
            continue
        direction = 1 if yb > ya else -1
        if yb < ya:
            xa, ya, xb, yb = xb, yb, xa, ya
        inv = normalize(Fraction(xb - xa) / (yb - ya))
        edges.append(Edge(i, ya, yb, xa, inv, direction))
    edges.sort(key=lambda e: (e.y_min, e.x_bottom, e.inv_m, e.idx))
    return tuple(edges), tuple(horizontal)


def spans_at(edges: Sequence[Edge], y: Number, rule: str) -> list[tuple[Number, Number]]:
    """The half-open spans ``[x_a, x_b)`` the rule fills on the horizontal line at any exact
    ``y`` (the scan line's rule with a fractional y: the sample rows of supersampling).

    >>> edges, _ = edge_table([(0, 0), (4, 0), (2, 4)])
    >>> spans_at(edges, Fraction(1, 2), "even-odd")
    [(Fraction(1, 4), Fraction(15, 4))]
    """
    entries = sorted(
        (Active(e.idx, e.x_at(y), e.inv_m, e.y_max) for e in edges if e.y_min <= y < e.y_max),
        key=lambda a: (a.x, a.inv_m, a.edge),
    )
    return _spans(entries, {e.idx: e for e in edges}, rule)


def _spans(
    active: Sequence[Active], edges: dict[int, Edge], rule: str
) -> list[tuple[Number, Number]]:
    """The filled spans of one scan line from its sorted active edges."""
    if fill_rule(rule).alternates:
        return [(active[i].x, active[i + 1].x) for i in range(0, len(active) - 1, 2)]
    spans: list[tuple[Number, Number]] = []
    winding = 0
    start: Number = 0
    for a in active:
        before = winding
        winding += edges[a.edge].direction
        if before == 0 and winding != 0:
            start = a.x
        elif before != 0 and winding == 0:
            spans.append((start, a.x))
    return spans


def scanline_fill(
    vertices: Sequence[Sequence[Number]], rule: str = "even-odd"
) -> Iterator[ScanLine]:
    """The scan-line fill, one :class:`ScanLine` per scan line from the lowest to the highest
    that meets the polygon (see the module's conventions).

    On each scan line y, as in Hearn & Baker: remove the edges with ``y_max <= y``, move the
    edges whose first scan line is y from the edge table, sort by x, fill between pairs of
    intersections (even-odd) or where the winding number is not zero (nonzero), then each x
    grows by its 1/m. The x values are exact (``x_bottom + (y - y_min) / m``).

    Examples
    --------
    >>> for s in scanline_fill([(0, 0), (4, 0), (2, 3)]):
    ...     print(s.y, [str(a.x) for a in s.active], s.runs)
    0 ['0', '4'] ((0, 3),)
    1 ['2/3', '10/3'] ((1, 3),)
    2 ['4/3', '8/3'] ((2, 2),)
    3 [] ()
    """
    check_rule(rule)
    pts, _ = check_polygon(vertices)
    edges, _ = edge_table(pts)
    by_index = {e.idx: e for e in edges}
    y_lo = min(e.first_line for e in edges)
    y_hi = math.floor(max(e.y_max for e in edges))
    pending = list(edges)  # sorted by y_min: the edge table
    active: list[Edge] = []
    for y in range(y_lo, y_hi + 1):
        removed = tuple(e.idx for e in active if e.y_max <= y)
        active = [e for e in active if e.y_max > y]
        added = []
        while pending and pending[0].first_line <= y:
            e = pending.pop(0)
            if e.y_max > y:  # an edge between two scan lines crosses none
                active.append(e)
                added.append(e.idx)
        entries = sorted(
            (Active(e.idx, e.x_at(y), e.inv_m, e.y_max) for e in active),
            key=lambda a: (a.x, a.inv_m, a.edge),
        )
        spans = tuple(_spans(entries, by_index, rule))
        runs = tuple((math.ceil(a), math.ceil(b) - 1) for a, b in spans)
        yield ScanLine(y, removed, tuple(added), tuple(entries), spans, runs)


def fill_pixels(vertices: Sequence[Sequence[Number]], rule: str = "even-odd") -> list[Pixel]:
    """The pixels the scan-line fill sets, bottom row first, left to right.

    >>> fill_pixels([(0, 0), (4, 0), (2, 3)])
    [(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1), (2, 2)]
    """
    out: list[Pixel] = []
    for s in scanline_fill(vertices, rule):
        for first, last in s.runs:
            out.extend((x, s.y) for x in range(first, last + 1))
    return out


def outline_pixels(vertices: Sequence[Point]) -> list[Pixel]:
    """The polygon's outline: Bresenham's line along each edge between the vertices rounded
    half up, each pixel once, in drawing order.

    >>> outline_pixels([(0, 0), (2, 0), (0, 2)])
    [(0, 0), (1, 0), (2, 0), (1, 1), (0, 2), (0, 1)]
    """
    pts = [(round_half_up(x), round_half_up(y)) for x, y in vertices]
    seen: set[Pixel] = set()
    out: list[Pixel] = []

    def add(p: Pixel) -> None:
        if p not in seen:
            seen.add(p)
            out.append(p)

    for i, (xa, ya) in enumerate(pts):
        xb, yb = pts[(i + 1) % len(pts)]
        sx, sy = orient(xa, ya, xb, yb)[:2]
        walk = [(sx, sy)] + [s.pixel for s in bresenham(xa, ya, xb, yb)]
        if (sx, sy) != (xa, ya):
            walk.reverse()  # bresenham walks its major axis upward: swapped end points
        for p in walk:
            add(p)
    return out


def polygon_area(vertices: Sequence[Point]) -> Number:
    """The signed shoelace area (positive counter-clockwise); for a simple polygon its
    absolute value is the area.

    >>> polygon_area([(0, 0), (4, 0), (2, 3)])
    6
    """
    n = len(vertices)
    twice = sum(
        vertices[i][0] * vertices[(i + 1) % n][1] - vertices[(i + 1) % n][0] * vertices[i][1]
        for i in range(n)
    )
    return normalize(Fraction(twice) / 2)
