"""The worked answer of the scan-line polygon fill: the edge table, then one row per scan line
(the active edge table, the intersections, the spans and pixels filled, the edges added and
removed), the conventions stated as notes, and the outline drawn with the fill."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from fractions import Fraction
from typing import Any

from ....algorithms.polygon import (
    Edge,
    Point,
    ScanLine,
    check_polygon,
    check_rule,
    edge_table,
    fill_rule,
    outline_pixels,
    scanline_fill,
    vertices_from_coords,
)
from ....core.ideal import Polyline
from ....core.numeric import Number, fmt_paren, fmt_short, normalize, round_half_up
from ....core.records import (
    MAX_GRID_CELLS,
    Pixel,
    PixelFigure,
    Plot,
    Quantity,
    Solution,
    Table,
    Walk,
    heading,
    rule,
    worked,
)

#: The conventions, as every answer of this module states them.
PIXEL_RULE = (
    "Pixel centres: pixel (x, y) is filled when its centre (x, y) is inside. A span "
    "[x_a, x_b) fills x = ceil(x_a) .. ceil(x_b) - 1: a centre exactly on a left edge is "
    "filled, one on a right edge is not."
)
VERTEX_RULE = (
    "Edges are half-open in y: an edge takes part in the scan lines y_min <= y < y_max (its "
    "upper end excluded). So a vertex between a rising and a falling edge counts once, a local "
    "minimum twice (a span of length zero) and a local maximum not at all, and the top row "
    "along a horizontal top edge is left to the polygon above: with the left rule, polygons "
    "sharing an edge never overlap and leave no gap."
)
EVEN_ODD_TEXT = (
    "Even-odd rule: sort the intersections by x and fill from the 1st to the 2nd, the 3rd to "
    "the 4th, ..."
)
NONZERO_TEXT = (
    "Nonzero rule: from left to right add +1 at an edge going up (from vertex i to i + 1) and "
    "-1 at one going down; fill where the sum (the winding number) is not 0."
)


def names(n: int) -> list[str]:
    """Vertex names: ``A, B, C, ...`` (as in Foley et al.) up to 26 vertices, else ``V1 ...``.

    >>> names(3), names(27)[-1]
    (['A', 'B', 'C'], 'V27')
    """
    if n <= 26:
        return [chr(ord("A") + i) for i in range(n)]
    return [f"V{i + 1}" for i in range(n)]


def pt(p: Point) -> str:
    """``(2, 3)``; fractions exactly."""
    return f"({fmt_short(p[0])}, {fmt_short(p[1])})"


def num(v: Number) -> int | str:
    """A table value: an ``int`` as it is, anything else exactly as a short string (``-2.5``,
    ``13/3``), since the edge table's x and 1/m are read as exact fractions.

    >>> num(3), num(Fraction(-5, 2)), num(Fraction(13, 3))
    (3, '-2.5', '13/3')
    """
    v = normalize(v)
    return v if isinstance(v, int) else fmt_short(v)


def _edge_work(label: str, a: Point, b: Point) -> Quantity:
    dx, dy = normalize(b[0] - a[0]), normalize(b[1] - a[1])
    head = f"{label}: {pt(a)} \\to {pt(b)}:\\ "
    if dy == 0:
        return worked(f"inv_m_{label}", None, head + r"\Delta y = 0 \text{ (horizontal: dropped)}")
    inv = normalize(Fraction(dx) / dy)
    return worked(
        f"inv_m_{label}",
        inv,
        head + f"1/m = \\frac{{\\Delta x}}{{\\Delta y}} = \\frac{{{fmt_short(b[0])} - "
        f"{fmt_paren(a[0])}}}{{{fmt_short(b[1])} - {fmt_paren(a[1])}}} = {fmt_short(inv)}",
    )


def _segments_cross(p: Point, q: Point, r: Point, s: Point) -> bool:
    """Whether segments pq and rs share a point (exact orientation tests)."""

    def orient(a: Point, b: Point, c: Point) -> int:
        v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        return (v > 0) - (v < 0)

    def on(a: Point, b: Point, c: Point) -> bool:
        return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(
            a[1], b[1]
        )

    o1, o2, o3, o4 = orient(p, q, r), orient(p, q, s), orient(r, s, p), orient(r, s, q)
    if o1 != o2 and o3 != o4:
        return True
    return any(
        o == 0 and on(a, b, c)
        for o, a, b, c in ((o1, p, q, r), (o2, p, q, s), (o3, r, s, p), (o4, r, s, q))
    )


def shape(pts: Sequence[Point]) -> str:
    """``convex``, ``concave`` or ``self-intersecting``.

    >>> shape([(0, 0), (4, 0), (0, 4), (4, 4)]), shape([(0, 0), (4, 0), (2, 1), (2, 4)])
    ('self-intersecting', 'concave')
    """
    n = len(pts)
    for i in range(n):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue
            if _segments_cross(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n]):
                return "self-intersecting"
    signs = set()
    for i in range(n):
        a, b, c = pts[i], pts[(i + 1) % n], pts[(i + 2) % n]
        v = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
        if v:
            signs.add(v > 0)
    return "convex" if len(signs) == 1 else "concave"


def _scan_row(
    s: ScanLine, labels: dict[int, str], edges: dict[int, Edge], nonzero: bool
) -> tuple[Any, ...]:
    def edge_list(ix: Sequence[int]) -> str:
        return ", ".join(labels[i] for i in ix) if ix else "-"

    aet = "; ".join(
        f"{labels[a.edge]}: {fmt_short(a.x)}, {fmt_short(a.inv_m)}, {fmt_short(a.y_max)}"
        for a in s.active
    )
    if nonzero:
        cuts = ", ".join(
            f"{fmt_short(a.x)} ({'+1' if edges[a.edge].direction > 0 else '-1'})" for a in s.active
        )
    else:
        cuts = ", ".join(fmt_short(a.x) for a in s.active)
    spans = " ".join(f"[{fmt_short(a)}, {fmt_short(b)})" for a, b in s.spans)
    pixels = ", ".join((str(f) if f == last else f"{f}..{last}") for f, last in s.runs if last >= f)
    return (
        s.y,
        edge_list(s.removed),
        edge_list(s.added),
        aet or "(empty)",
        cuts or "-",
        spans or "-",
        pixels or "none",
    )


def _polygon_notes(
    pts: Sequence[Point], rule_name: str, kind: str, horizontal: list[str], dropped: int
) -> list[str]:
    """The notes: the pixel, vertex and fill rules, and what was dropped or crosses."""
    rule_text = EVEN_ODD_TEXT if fill_rule(rule_name).alternates else NONZERO_TEXT
    notes = [PIXEL_RULE, VERTEX_RULE, rule_text]
    if horizontal:
        notes.append(
            "Horizontal edges dropped (their neighbours bound the spans): "
            + ", ".join(horizontal)
            + "."
        )
    if dropped:
        notes.append(
            f"{dropped} repeated vertex (consecutive, or the first repeated last) dropped."
        )
    if kind == "self-intersecting":
        notes.append(
            "The polygon crosses itself: even-odd leaves the parts covered twice empty, "
            "nonzero fills them when both windings agree."
        )
    if any(normalize(c) != round_half_up(c) for p in pts for c in p):
        notes.append("The outline joins the vertices rounded half up (Bresenham needs integers).")
    return notes


def _rounded_bbox(pts: Sequence[Point]) -> tuple[int, int, int, int]:
    rounded = [(round_half_up(x), round_half_up(y)) for x, y in pts]
    xs, ys = [p[0] for p in rounded], [p[1] for p in rounded]
    return min(xs), min(ys), max(xs), max(ys)


def _polygon_figures(
    pts: Sequence[Point], bbox: tuple[int, int, int, int], pixels: Callable[[], Iterator[Pixel]]
) -> tuple[PixelFigure, ...]:
    """The outline and the fill, when they fit a figure."""
    if bbox[2] - bbox[0] + 3 > MAX_GRID_CELLS or bbox[3] - bbox[1] + 3 > MAX_GRID_CELLS:
        return ()
    return (
        PixelFigure(
            tuple(pixels()),
            tuple(outline_pixels(pts)),
            bbox,
            legend="# = filled, o = outline (Bresenham edges) not filled, @ = outline and filled",
            title="Outline and fill:",
        ),
    )


_EDGE_COLUMNS = (
    heading("edge", r"\text{edge}"),
    heading("y_min", r"y_{\min}"),
    heading("y_max", r"y_{\max}"),
    heading("x", r"x \text{ at } y_{\min}"),
    heading("inv_m", "1/m"),
    heading("direction", r"\text{direction}"),
)
_SCAN_COLUMNS = (
    heading("y", "y"),
    heading("removed", r"\text{removed}"),
    heading("added", r"\text{added}"),
    heading("aet", r"\text{AET}", role="working"),
    heading("intersections", r"\text{intersections}"),
    heading("spans", r"\text{spans}"),
    heading("pixels", r"\text{pixels } x"),
)


def _edge_table(
    pts: Sequence[Point], edges: Sequence[Edge], horizontal: Sequence[int], label: dict[int, str]
) -> Table:
    """The edge table: the edges sorted by y_min, then the horizontal ones dropped."""
    n = len(pts)

    def rows() -> Iterator[tuple[Any, ...]]:
        for e in edges:
            lo, hi = pts[e.idx], pts[(e.idx + 1) % n]
            yield (
                label[e.idx],
                num(e.y_min),
                num(e.y_max),
                num(e.x_bottom),
                num(e.inv_m),
                "up" if hi[1] > lo[1] else "down",
            )
        for i in horizontal:
            yield (label[i], num(pts[i][1]), num(pts[i][1]), "-", "-", "horizontal: dropped")

    return Table("Edge table (sorted by y_min, then x)", _EDGE_COLUMNS, rows)


def _scan_table(
    pts: Sequence[Point], rule_name: str, edges: Sequence[Edge], label: dict[int, str]
) -> Table:
    """One row per scan line: the edges removed and added, the AET, the spans and pixels."""
    by_index = {e.idx: e for e in edges}
    winding = not fill_rule(rule_name).alternates  # the winding number shown

    def rows() -> Iterator[tuple[Any, ...]]:
        for s in scanline_fill(pts, rule_name):
            yield _scan_row(s, label, by_index, winding)

    return Table("Scan lines (AET entries: edge: x, 1/m, y_max)", _SCAN_COLUMNS, rows)


def _filled(pts: Sequence[Point], rule_name: str) -> Iterator[Pixel]:
    for s in scanline_fill(pts, rule_name):
        for f, last_x in s.runs:
            for x in range(f, last_x + 1):
                yield (x, s.y)


def _polygon_derived(
    pts: Sequence[Point], edges: Sequence[Edge], label: dict[int, str], kind: str
) -> tuple[Quantity, ...]:
    """The scan lines' range, each edge's 1/m, the step to the next line and the shape."""
    n = len(pts)
    ys = [p[1] for p in pts]
    first = min(e.first_line for e in edges)
    last = max(round_half_up(Fraction(e.y_max) - Fraction(1, 2)) for e in edges)
    return (
        worked(
            "scan_lines",
            (first, last),
            f"y = \\lceil y_{{\\min}} \\rceil \\ldots \\lfloor y_{{\\max}} \\rfloor = "
            f"\\lceil {fmt_short(min(ys))} \\rceil \\ldots \\lfloor {fmt_short(max(ys))} "
            f"\\rfloor = {first} \\ldots {last}",
        ),
        *(_edge_work(label[i], pts[i], pts[(i + 1) % n]) for i in range(n)),
        rule("x_next", r"x_{k+1} = x_k + 1/m \text{ (each active edge, to the next scan line)}"),
        Quantity("shape", kind, f"the polygon is {kind}", f"\\text{{the polygon is {kind}}}"),
    )


def _edge_data(edges: Sequence[Edge], label: dict[int, str]) -> list[dict[str, Any]]:
    return [
        {
            "edge": label[e.idx],
            "y_min": e.y_min,
            "y_max": e.y_max,
            "x": e.x_bottom,
            "inv_m": e.inv_m,
            "direction": e.direction,
        }
        for e in edges
    ]


def polygon_solution(coords: Sequence[Number], rule_name: str = "even-odd") -> Solution:
    """The scan-line fill of the polygon ``x1 y1 x2 y2 ...`` as a worked answer.

    >>> sol = polygon_solution([2, 3, 7, 1, 13, 5, 13, 11, 7, 7, 2, 9])
    >>> [r[:5] for r in sol.tables[0].rows()][:2]
    [('AB', 1, 3, 7, '-2.5'), ('BC', 1, 5, 7, '1.5')]
    >>> [r for r in sol.tables[1].rows()][8][3]
    'DE: 10, 1.5, 11; CD: 13, 0, 11'
    """
    check_rule(rule_name)
    given_pts = vertices_from_coords(coords)
    pts, dropped = check_polygon(given_pts)
    labels_v = names(len(pts))
    n = len(pts)
    edge_label = {i: labels_v[i] + labels_v[(i + 1) % n] for i in range(n)}
    edges, horizontal = edge_table(pts)
    kind = shape(pts)
    given = (
        *(worked(f"V{i + 1}", p, f"{labels_v[i]} = {pt(p)}") for i, p in enumerate(pts)),
        Quantity("rule", rule_name, f"rule: {rule_name}", f"\\text{{rule: {rule_name}}}"),
    )
    notes = _polygon_notes(pts, rule_name, kind, [edge_label[i] for i in horizontal], dropped)

    def pixels() -> Iterator[Pixel]:
        return _filled(pts, rule_name)

    bbox = _rounded_bbox(pts)
    figures = _polygon_figures(pts, bbox, pixels)
    shown = (
        ", ".join(f"{labels_v[i]}{pt(p)}" for i, p in enumerate(pts)) if n <= 8 else f"{n} vertices"
    )
    return Solution(
        primitive="polygon",
        algorithm="scanline",
        title=f"Scan-line polygon fill ({rule_name} rule): {shown}",
        given=given,
        derived=_polygon_derived(pts, edges, edge_label, kind),
        notes=tuple(notes),
        walk=Walk(
            tables=(
                _edge_table(pts, edges, horizontal, edge_label),
                _scan_table(pts, rule_name, edges, edge_label),
            )
        ),
        plot=Plot(
            pixels=pixels,
            bbox=bbox,
            figures=figures,
            ideal=(Polyline([(float(x), float(y)) for x, y in (*pts, pts[0])], "polygon"),),
            outline=tuple(outline_pixels(pts)) if figures else (),
            outline_name="outline pixel (Bresenham edges)",
            numbering="none",
        ),
        data={
            "vertices": [list(p) for p in pts],
            "edge_table": _edge_data(edges, edge_label),
            "horizontal": [edge_label[i] for i in horizontal],
        },
    )
