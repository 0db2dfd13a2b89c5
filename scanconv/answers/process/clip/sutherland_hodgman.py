"""The worked answer of Sutherland–Hodgman polygon clipping against a closed rectangular
window, or any convex one (a triangle, a hexagon: edge by edge in the window's order): one table per window edge (its input vertices, each polygon edge's case and output),
the clipped polygon and its area, and the degenerate edges a concave polygon leaves.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ....algorithms.clipping import (
    Edge,
    Point,
    Rect,
    boundary,
    is_convex,
    overlapping_edges,
    polygon_area,
    sutherland_hodgman,
)
from ....algorithms.window_clip import (
    WindowEdge,
    convex_window,
    overlapping_window_edges,
    sutherland_hodgman_window,
)
from ....core.checks import InputError
from ....core.numeric import Number, fmt_short, normalize
from ....core.records import Column, Plot, Quantity, Solution, Table, Walk
from .._shared import (
    check_points,
    check_rect,
    clip_figure,
    point_quantity,
    pt,
    rect_quantity,
    rect_text,
    window_figure,
)

if TYPE_CHECKING:
    from ...asked import ClipPolygonQuestion

MAX_VERTICES = 100
"""Most vertices of a clipped polygon (one table row per edge for each window edge)."""

_SH_COLUMNS = (
    Column("point_edge", "polygon edge V1 -> V2", r"\text{polygon edge } V_1 \to V_2"),
    Column("method", "case", r"\text{case}"),
    Column("point_out", "output", r"\text{output}"),
)

_EDGE_LINE = {
    Edge.LEFT: "x = xmin",
    Edge.RIGHT: "x = xmax",
    Edge.BOTTOM: "y = ymin",
    Edge.TOP: "y = ymax",
}


def pts(points: Sequence[Point]) -> str:
    return ", ".join(pt(p) for p in points) if points else "(none)"


def check_vertices(coords: Sequence[Number]) -> tuple[Point, ...]:
    """``x1 y1 x2 y2 ...`` as 3 to :data:`MAX_VERTICES` vertices, or InputError."""
    if len(coords) // 2 > MAX_VERTICES:
        raise InputError(
            f"at most {MAX_VERTICES} polygon vertices, got {len(coords) // 2}", "vertices"
        )
    vertices = tuple((normalize(x), normalize(y)) for x, y in check_points(coords, "vertices"))
    if len(vertices) < 3:
        raise InputError(f"a polygon needs at least 3 vertices, got {len(vertices)}", "vertices")
    return vertices


def _stage_parts(stages: Sequence[Any], line_of: Any) -> tuple[list[Quantity], list[Table]]:
    """Each stage's output (working) and its table: the polygon edges' cases and outputs."""
    derived, tables = [], []
    for st in stages:
        line = line_of(st.edge)
        derived.append(
            Quantity(
                f"after_{st.edge}",
                [list(p) for p in st.outputs],
                f"after the {st.edge} edge ({line}): {pts(st.outputs)}",
                f"\\text{{after the {st.edge} edge ({line}): }} {pts(st.outputs)}",
            )
        )

        def rows(st: Any = st) -> list[tuple[str, str, str]]:
            return [
                (f"{pt(r.v1)} -> {pt(r.v2)}", str(r.case), pts(r.output) if r.output else "-")
                for r in st.rows
            ]

        tables.append(
            Table(
                f"Clip against the {st.edge} edge ({line}); input {len(st.inputs)} vertices: {pts(st.inputs)}",
                _SH_COLUMNS,
                rows,
            )
        )
    return derived, tables


def _convex_quantity(vertices: Sequence[Point]) -> tuple[bool, Quantity]:
    convex = is_convex(vertices)
    word = "convex" if convex else "concave"
    return convex, Quantity(
        "convex", convex, f"the polygon is {word}", f"\\text{{the polygon is {word}}}"
    )


def _result(vertices: Sequence[Point], final: Sequence[Point]) -> list[Quantity]:
    area_in, area_out = (
        abs(polygon_area(vertices)),
        abs(polygon_area(final)) if final else Fraction(0),
    )
    return [
        Quantity(
            "clipped",
            [list(p) for p in final],
            f"clipped polygon ({len(final)} vertices): {pts(final)}",
            f"\\text{{clipped polygon ({len(final)} vertices): }} {pts(final)}",
        ),
        Quantity(
            "area",
            normalize(area_out),
            f"area = |shoelace sum|/2 = {fmt_short(area_out)} (the polygon's own area: {fmt_short(area_in)})",
            f"\\text{{area}} = {fmt_short(area_out)} \\quad (\\text{{before: }} {fmt_short(area_in)})",
        ),
    ]


_CASES_NOTE = (
    "For each polygon edge V1 -> V2: in -> in outputs V2; in -> out the crossing I; out -> in I "
    "and V2; out -> out nothing. On the edge counts as inside, and a crossing that is the "
    "vertex itself is output once."
)


def _concave_note(degenerate: Sequence[tuple[Point, Point]]) -> str:
    extra = (
        (" Here: " + "; ".join(f"{pt(a)} -> {pt(b)}" for a, b in degenerate) + ".")
        if degenerate
        else " Here the clipped part is in one piece, so there are none."
    )
    return (
        "The polygon is concave: where its clipped part falls into pieces, Sutherland-Hodgman still returns one polygon, joining the pieces by degenerate edges that run along the window boundary and back."
        + extra
    )


def polygon_parts(
    vertices: Sequence[Point], w: Rect
) -> tuple[list[Quantity], list[Table], tuple[Point, ...], list[str]]:
    """The working, the per-edge tables, the clipped polygon and the notes of a
    Sutherland–Hodgman run (for :mod:`.pipeline` too)."""
    stages = sutherland_hodgman(vertices, w)
    final = stages[-1].outputs
    convex, convex_q = _convex_quantity(vertices)
    derived, tables = _stage_parts(
        stages, lambda edge: f"{_EDGE_LINE[edge]} = {fmt_short(boundary(edge, w))}"
    )
    derived = [convex_q, *derived, *_result(vertices, final)]
    notes = [
        "The window edges are taken in the order left, right, bottom, top; each one's output is the next one's input.",
        _CASES_NOTE,
    ]
    if not convex:
        notes.append(_concave_note(overlapping_edges(final, w) if final else ()))
    return derived, tables, final, notes


def clip_polygon_solution(coords: Sequence[Number], window: Sequence[Number]) -> Solution:
    """The worked answer of Sutherland–Hodgman clipping of the polygon ``x1 y1 x2 y2 ...``.

    >>> sol = clip_polygon_solution([100, 150, 200, 250, 300, 200], (150, 150, 200, 200))
    >>> sol.derived[-2].text
    'clipped polygon (4 vertices): (150, 162.5), (150, 200), (200, 200), (200, 175)'
    """
    w = check_rect(window, "window", "window")
    vertices = check_vertices(coords)
    derived, tables, final, notes = polygon_parts(vertices, w)
    return Solution(
        primitive="clip",
        algorithm="sutherland-hodgman",
        title=f"Sutherland-Hodgman polygon clipping: {len(vertices)} vertices, window {rect_text(w)}",
        given=(
            *(point_quantity(f"V{i}", v) for i, v in enumerate(vertices, 1)),
            rect_quantity("window", w),
        ),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(tables=tuple(tables)),
        plot=Plot(figures=clip_figure(final, w, vertices, "clipped polygon")),
        data={
            "clipped": [list(p) for p in final],
            "degenerate_edges": [[list(a), list(b)] for a, b in overlapping_edges(final, w)]
            if final
            else [],
        },
    )


def _window_line(edge: WindowEdge) -> str:
    return f"from {pt(edge.a)} to {pt(edge.b)}"


def clip_polygon_window_solution(
    coords: Sequence[Number], window_coords: Sequence[Number]
) -> Solution:
    """The worked answer of Sutherland–Hodgman clipping of the polygon ``x1 y1 x2 y2 ...``
    against the convex window ``x1 y1 x2 y2 x3 y3 ...`` (a triangle, a hexagon, ...).

    >>> sol = clip_polygon_window_solution([0, 0, 4, 0, 4, 4, 0, 4], [1, -1, 6, 4, 1, 4])
    >>> sol.derived[-2].text
    'clipped polygon (5 vertices): (4, 4), (1, 4), (1, 0), (2, 0), (4, 2)'
    """
    vertices = check_vertices(coords)
    window, flipped = convex_window(check_points(window_coords, "window"))
    stages = sutherland_hodgman_window(vertices, window)
    final = stages[-1].outputs
    convex, convex_q = _convex_quantity(vertices)
    derived, tables = _stage_parts(stages, _window_line)
    notes = [
        "The window's edges C1 -> C2, C2 -> C3, ... are taken in order, counter-clockwise; each "
        "one's output is the next one's input. A point is inside an edge when it is on the "
        "window's side of its line or on it: (C2 - C1) x (P - C1) >= 0.",
        _CASES_NOTE,
    ]
    if flipped:
        notes.append("The window was given clockwise: its vertices are taken in reverse order.")
    if not convex:
        notes.append(_concave_note(overlapping_window_edges(final, window) if final else ()))
    return Solution(
        primitive="clip",
        algorithm="sutherland-hodgman",
        title=f"Sutherland-Hodgman polygon clipping: {len(vertices)} vertices, a convex window of {len(window)}",
        given=(
            *(point_quantity(f"V{i}", v) for i, v in enumerate(vertices, 1)),
            *(point_quantity(f"C{i}", c) for i, c in enumerate(window, 1)),
        ),
        derived=(convex_q, *derived, *_result(vertices, final)),
        notes=tuple(notes),
        walk=Walk(tables=tuple(tables)),
        plot=Plot(figures=window_figure(final, window, vertices, "clipped polygon")),
        data={"clipped": [list(p) for p in final], "window": [list(c) for c in window]},
    )


def polygon_answer(q: ClipPolygonQuestion) -> Solution:
    """The question's polygon clipped against its window: a convex polygon's ``x y x y ...``
    (a pass per edge), or the rectangle ``(xmin, ymin, xmax, ymax)`` (four passes) (the
    record's ``answer``)."""
    if q.polygon:
        return clip_polygon_window_solution(q.vertices, q.window)
    return clip_polygon_solution(q.vertices, q.window)
