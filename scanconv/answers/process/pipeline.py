"""The scan-conversion process end to end for a line: clip in world coordinates, map the
window to the viewport, round the end points, scan convert, and show the frame buffer.

The course notes' steps are (1) geometric description, (2) transformation from world to device
coordinates, (3) clipping, (4) scan conversion, (5) display. Clipping is done here *before* the
mapping, in world coordinates against the window: the window maps onto the viewport, so
clipping against either gives the same segment, and the world-coordinate window is the one
the question gives.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING, Any, NamedTuple

from ...algorithms.lines import ALGORITHMS
from ...algorithms.transform import Rect, rect_outline, viewport_scale
from ...core import lazy
from ...core.checks import InputError
from ...core.numeric import Number, fmt_short, normalize, round_half_up
from ...core.records import (
    NO_PLOT,
    Column,
    Pixel,
    Plot,
    Quantity,
    Solution,
    Table,
    Walk,
    step_getter,
)
from .. import methods
from ..asked import ClipLineQuestion
from ..primitives.line import line_solution
from ._shared import check_rect, fits, point_quantity, pt, pt_approx, rect_quantity, rect_text
from .clip.rectangle import check_method
from .clip.sutherland_hodgman import check_vertices, polygon_parts
from .viewport import mapping_table, scale_parts

if TYPE_CHECKING:
    from ...algorithms import polygon
    from ...core.choices import LineClipMethodName
else:
    polygon = lazy.module("scanconv.algorithms.polygon")


def _round_work(name: str, p: tuple[Number, Number], r: Pixel) -> Quantity:
    def one(v: Number, rv: int) -> str:
        return str(rv) if normalize(v) == rv else f"floor({fmt_short(v)} + 0.5) = {rv}"

    return Quantity(
        f"{name}_pixel",
        r,
        f"{name} = round{pt(p)} = ({one(p[0], r[0])}, {one(p[1], r[1])})",
        f"{name} = \\operatorname{{round}}{pt(p)} = ({r[0]}, {r[1]})",
    )


def _stage(text: str) -> Quantity:
    return Quantity(f"stage{text[0]}", None, f"[{text}]", f"\\textbf{{{text}}}")


def _to_device(
    points: Sequence[tuple[Number, Number]],
    names: Sequence[str],
    w: Rect,
    v: Rect,
    derived: list[Quantity],
    tables: list[Table],
) -> list[tuple[Number, Number]]:
    """Stage 2: the window-to-viewport scale (its working and mapping table added) and the
    exact device points."""
    derived.append(_stage("2. window to viewport"))
    derived += scale_parts(w, v)
    sx, sy, tx, ty = viewport_scale(w, v)
    dev = [(normalize(sx * x + tx), normalize(sy * y + ty)) for x, y in points]
    tables.append(
        mapping_table(list(zip(names, points, strict=True)), w, v, "Stage 2, window to viewport")
    )
    return dev


_LINE_NOTES = (
    "Stages: 1. clip the world-coordinate segment against the window; 2. map the window to "
    "the viewport (device coordinates); 3. round the end points half up, floor(v + 1/2); "
    "4. scan convert; 5. the frame buffer (the grid).",
    "The window is closed (a point on an edge is inside); region codes are written T B R L.",
)


def _check_line_method(algo: str, clip: str) -> LineClipMethodName:
    """The clipping method, checked (and the line algorithm)."""
    name = check_method(clip, "clip")
    if algo not in ALGORITHMS:
        raise InputError(
            f"unknown line algorithm {algo!r} (choose from {', '.join(ALGORITHMS)})", "algo"
        )
    return name


def _clipped_quantity(seg: tuple[tuple[Number, Number], ...]) -> Quantity:
    return Quantity(
        "clipped",
        [list(seg[0]), list(seg[1])],
        f"clipped: {pt_approx(seg[0])} to {pt_approx(seg[1])}",
        f"\\text{{clipped: }} {pt(seg[0])} \\text{{ to }} {pt(seg[1])}",
    )


def _device_quantities(dev: list[tuple[Number, Number]]) -> list[Quantity]:
    return [
        Quantity(
            name, list(q), f"{name} = (sx·x + tx, sy·y + ty) = {pt_approx(q)}", f"{name} = {pt(q)}"
        )
        for name, q in zip(("P1'", "P2'"), dev, strict=True)
    ]


def _scan_stage(
    algo: str, rounded: list[Pixel], derived: list[Quantity], tables: list[Table]
) -> Solution:
    """Stage 4: the line between the rounded end points (its working and step table added)."""
    (a, b), (c, d) = rounded
    line = line_solution(algo, a, b, c, d)
    if line.plot.shades is not None:  # grey levels: the frame buffer's pixels are on or off
        raise InputError(
            f"the pipeline scan converts with bresenham, dda or basic, not {algo}", "algo"
        )
    derived.append(_stage(f"4. scan convert ({line.title})"))
    derived += [q._replace(key=f"line_{q.key}") for q in line.derived]
    if line.columns:
        get = step_getter(line.columns, line.extra_keys)

        def rows() -> Iterator[tuple[Any, ...]]:
            return (get(s) for s in line.steps())

        tables.append(Table(f"Stage 4, scan conversion: {line.title}", line.columns, rows))
    return line


def _line_given(
    p1: tuple[Number, Number], p2: tuple[Number, Number], w: Rect, v: Rect
) -> tuple[Quantity, ...]:
    return (
        Quantity("P1", list(p1), f"P1 = {pt(p1)}", f"P_1 = {pt(p1)}"),
        Quantity("P2", list(p2), f"P2 = {pt(p2)}", f"P_2 = {pt(p2)}"),
        rect_quantity("window", w, "w"),
        rect_quantity("viewport", v, "v"),
    )


def _rounding_stage(dev: list[tuple[Number, Number]], derived: list[Quantity]) -> list[Pixel]:
    """Stage 3: the device end points rounded half up (their working added)."""
    derived.append(_stage("3. round the end points"))
    rounded = [(round_half_up(q[0]), round_half_up(q[1])) for q in dev]
    derived += [_round_work(n, q, r) for n, q, r in zip(("Q1", "Q2"), dev, rounded, strict=True)]
    return rounded


def _union_box(
    frame: tuple[int, int, int, int], bbox: tuple[int, int, int, int]
) -> tuple[int, int, int, int]:
    return (
        min(frame[0], bbox[0]),
        min(frame[1], bbox[1]),
        max(frame[2], bbox[2]),
        max(frame[3], bbox[3]),
    )


class PipelineLine(NamedTuple):
    """A line through the pipeline and each stage's end points, as values: what another answer
    quotes (the solution's ``data`` is output only). ``None`` past a rejecting clip."""

    solution: Solution
    clipped: tuple[tuple[Number, Number], tuple[Number, Number]] | None
    """The visible segment, world coordinates."""
    device: tuple[tuple[Number, Number], ...] | None
    """Its ends mapped to the viewport, exact."""
    rounded: tuple[Pixel, ...] | None
    """Those ends rounded half up: the pixels the line is drawn between."""


def pipeline_line_solution(
    x1: Number,
    y1: Number,
    x2: Number,
    y2: Number,
    window: Sequence[Number],
    viewport: Sequence[Number],
    *,
    algo: str = "bresenham",
    clip: str = "cohen-sutherland",
) -> Solution:
    """The line from world point P1 to P2 through the whole pipeline.

    >>> sol = pipeline_line_solution(-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10))
    >>> sol.data["rounded"]
    [[0, 3], [20, 8]]
    >>> list(sol.pixels())[:3]
    [(0, 3), (1, 3), (2, 4)]
    """
    return pipeline_line(x1, y1, x2, y2, window, viewport, algo=algo, clip=clip).solution


def pipeline_line(
    x1: Number,
    y1: Number,
    x2: Number,
    y2: Number,
    window: Sequence[Number],
    viewport: Sequence[Number],
    *,
    algo: str = "bresenham",
    clip: str = "cohen-sutherland",
) -> PipelineLine:
    """:func:`pipeline_line_solution` with each stage's end points as values."""
    w = check_rect(window, "window", "window")
    v = check_rect(viewport, "viewport", "viewport")
    name = _check_line_method(algo, clip)
    p1, p2 = (normalize(x1), normalize(y1)), (normalize(x2), normalize(y2))
    record = methods.method("clip", name)
    derived = [_stage(f"1. clip in world coordinates ({record.short})")]
    clip_work, clip_tables, seg = record.load("stage")(ClipLineQuestion(name, p1, p2, w))
    derived += clip_work
    tables = [Table(f"Stage 1, clipping: {t.title}", t.columns, t.rows) for t in clip_tables]
    notes = list(_LINE_NOTES)
    given = _line_given(p1, p2, w, v)
    title = f"Scan-conversion pipeline: line {pt(p1)} to {pt(p2)}, window {rect_text(w)}, viewport {rect_text(v)}"
    data: dict[str, Any] = {"clipped": None, "device": None, "rounded": None}
    if seg is None:
        derived.append(
            Quantity("clipped", None, "rejected: nothing reaches the viewport", r"\text{rejected}")
        )
        notes.append(
            "The segment is outside the window: stages 2 to 4 have nothing to do and the frame buffer stays empty."
        )
        rejected = Solution(
            primitive="pipeline",
            algorithm=algo,
            title=title,
            given=given,
            derived=tuple(derived),
            notes=tuple(notes),
            walk=Walk(tables=tuple(tables)),
            data=data,
        )
        return PipelineLine(rejected, None, None, None)
    derived.append(_clipped_quantity(seg))
    dev = _to_device(seg, ("P1'", "P2'"), w, v, derived, tables)
    derived += _device_quantities(dev)
    rounded = _rounding_stage(dev, derived)
    line = _scan_stage(algo, rounded, derived, tables)
    notes += list(line.notes)
    frame = (round_half_up(v[0]), round_half_up(v[1]), round_half_up(v[2]), round_half_up(v[3]))
    box = _union_box(frame, line.bbox)
    marks: tuple[Pixel, ...] = ()
    if fits(box):
        marks = tuple(rect_outline(frame))
        notes.append("In the grid, o marks the viewport's edge and # the plotted pixels (@ both).")
    data.update(
        clipped=[list(seg[0]), list(seg[1])],
        device=[list(q) for q in dev],
        rounded=[list(r) for r in rounded],
    )
    solution = Solution(
        primitive="pipeline",
        algorithm=algo,
        title=title,
        given=given,
        derived=tuple(derived),
        notes=tuple(notes),
        walk=line.walk._replace(shown=False, tables=tuple(tables)),
        plot=line.plot._replace(bbox=box, marks=marks, marks_label=None, figures=()),
        data=data,
    )
    return PipelineLine(solution, seg, tuple(dev), tuple(rounded))


# --- a polygon: clip (Sutherland-Hodgman), map, then outline or scan-line fill -----------------

_FILL_COLUMNS = (
    Column("y", "scan line y", r"\text{scan line } y"),
    Column("work", "active edges: x (exact)", r"\text{active edges: } x"),
    Column("arithmetic", "spans [xa, xb)", r"\text{spans } [x_a, x_b)"),
    Column("reason", "pixels x (ceil(xa) .. ceil(xb) - 1)", r"\text{pixels } x"),
)


def _fill_rows(vertices: Sequence[tuple[Number, Number]], rule: str) -> Iterator[tuple[Any, ...]]:
    for s in polygon.scanline_fill(vertices, rule):
        yield (
            s.y,
            ", ".join(fmt_short(a.x) for a in s.active) or "-",
            "; ".join(f"[{fmt_short(a)}, {fmt_short(b)})" for a, b in s.spans) or "-",
            ", ".join(f"{a}..{b}" if b >= a else "none" for a, b in s.runs) or "-",
        )


def _fill_stage(
    dev: list[tuple[Number, Number]], rule: str, tables: list[Table], notes: list[str]
) -> Callable[[], Iterator[Pixel]] | None:
    """Stage 3 with ``fill``: the scan-line fill of the exact device polygon (its table and
    note added), or ``None`` (noted) when the clipped polygon has no area."""
    try:
        pts, _ = polygon.check_polygon(dev)
    except InputError as err:
        if "degenerate" not in str(err):
            raise
        notes.append(
            "The clipped polygon has no area (it only touches the window): nothing is filled."
        )
        return None
    tables.append(
        Table(f"Stage 3, scan-line fill ({rule})", _FILL_COLUMNS, lambda: _fill_rows(pts, rule))
    )
    notes.append(
        "A pixel is filled when its centre is inside: a span [xa, xb) fills ceil(xa) .. ceil(xb) - 1, and an edge counts on the scan lines y_min <= y < y_max (so shared edges are filled once)."
    )
    return lambda: iter(polygon.fill_pixels(pts, rule))


def _outline_stage(
    dev: list[tuple[Number, Number]], rounded: list[tuple[int, int]]
) -> Callable[[], Iterator[Pixel]]:
    """Stage 3 without ``fill``: the edges by Bresenham between the rounded vertices."""
    length = sum(
        max(abs(rounded[i][0] - rounded[i - 1][0]), abs(rounded[i][1] - rounded[i - 1][1]))
        for i in range(len(rounded))
    )
    if length > polygon.MAX_FILL_CELLS:
        raise InputError(
            f"the outline in the viewport has about {length:,} pixels; at most "
            f"{polygon.MAX_FILL_CELLS:,} are drawn",
            "viewport",
        )
    return lambda: iter(polygon.outline_pixels(dev))


def pipeline_polygon_solution(
    coords: Sequence[Number],
    window: Sequence[Number],
    viewport: Sequence[Number],
    *,
    fill: bool = False,
    rule: str = "even-odd",
) -> Solution:
    """A world-coordinate polygon through the process: Sutherland–Hodgman against the window,
    the vertices mapped to the viewport, then its outline (Bresenham between the vertices
    rounded half up) or, with ``fill``, the scan-line fill of the exact device polygon
    (:mod:`scanconv.algorithms.polygon`: pixel centres, half-open spans).

    >>> sol = pipeline_polygon_solution([-2, 0, 6, 0, 2, 6], (0, 0, 4, 4), (0, 0, 8, 8), fill=True)
    >>> sol.data["clipped"]
    [[Fraction(10, 3), 4], [Fraction(2, 3), 4], [0, 3], [0, 0], [4, 0], [4, 3]]
    >>> len(list(sol.pixels()))
    63
    """
    w = check_rect(window, "window", "window")
    v = check_rect(viewport, "viewport", "viewport")
    if rule not in polygon.RULES:
        raise InputError(
            f"unknown fill rule {rule!r} (choose from {', '.join(polygon.RULES)})", "rule"
        )
    vertices = check_vertices(coords)
    derived = [_stage("1. clip in world coordinates (Sutherland-Hodgman)")]
    clip_work, clip_tables, final, notes = polygon_parts(vertices, w)
    derived += clip_work
    tables = [Table(f"Stage 1, clipping: {t.title}", t.columns, t.rows) for t in clip_tables]
    notes.insert(
        0,
        "Stages: 1. clip the world-coordinate polygon against the window; 2. map the window to "
        "the viewport; 3. "
        + ("scan-line fill the device polygon" if fill else "draw its edges by Bresenham")
        + "; 4. the frame buffer (the grid).",
    )
    given = (
        *(point_quantity(f"V{i}", p) for i, p in enumerate(vertices, 1)),
        rect_quantity("window", w, "w"),
        rect_quantity("viewport", v, "v"),
    )
    what = "filled" if fill else "outlined"
    title = f"Scan-conversion pipeline: polygon ({len(vertices)} vertices) clipped, mapped and {what}, window {rect_text(w)}, viewport {rect_text(v)}"
    data: dict[str, Any] = {"clipped": [list(p) for p in final], "device": None}

    def answer(plot: Plot = NO_PLOT) -> Solution:
        return Solution(
            primitive="pipeline",
            algorithm="scan-line fill" if fill else "outline",
            title=title,
            given=given,
            derived=tuple(derived),
            notes=tuple(notes),
            walk=Walk(tables=tuple(tables)),
            plot=plot,
            data=data,
        )

    if not final:
        notes.append("The polygon is outside the window: nothing reaches the viewport.")
        return answer()
    names = [f"V{i}'" for i in range(1, len(final) + 1)]
    dev = _to_device(final, names, w, v, derived, tables)
    data["device"] = [list(p) for p in dev]
    rounded = [(round_half_up(x), round_half_up(y)) for x, y in dev]
    frame = tuple(round_half_up(c) for c in v)
    xs, ys = [p[0] for p in rounded], [p[1] for p in rounded]
    box = (min(frame[0], *xs), min(frame[1], *ys), max(frame[2], *xs), max(frame[3], *ys))
    if fill:
        derived.append(_stage(f"3. scan-line fill ({rule}), the device vertices kept exact"))
        pixels = _fill_stage(dev, rule, tables, notes)
        if pixels is None:
            return answer()
    else:
        derived.append(_stage("3. draw the edges: Bresenham between the vertices rounded half up"))
        pixels = _outline_stage(dev, rounded)
    marks: tuple[Pixel, ...] = tuple(rect_outline(frame)) if fits(box) else ()  # type: ignore[arg-type]
    if marks:
        notes.append("In the grid, o marks the viewport's edge and # the pixels (@ both).")
    return answer(Plot(pixels=pixels, bbox=box, marks=marks))
