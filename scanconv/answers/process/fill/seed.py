"""The worked answer of a seed fill (boundary fill, flood fill, the span fill): the trace of
the stack or queue, then the filled grid, and the 4/8 leak explained where it happens."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING, Any, cast

from ....algorithms.polygon import check_polygon, outline_pixels, vertices_from_coords
from ....algorithms.seedfill import (
    BOUNDARY,
    EIGHT,
    EMPTY,
    FILLED,
    FOUR,
    METHODS,
    ORDERS,
    FillStep,
    Grid,
    SpanStep,
    check_fill,
    check_size,
    grid_around,
    seed_fill,
    span_fill,
    squeezes,
)
from ....core.checks import InputError, check_whole
from ....core.numeric import Number, fmt_pixel
from ....core.records import (
    MAX_GRID_CELLS,
    Column,
    Pixel,
    PixelFigure,
    Plot,
    Quantity,
    Solution,
    Table,
    Walk,
    heading,
)
from ....core.working import tex_text
from ... import methods
from ...asked import FillQuestion

if TYPE_CHECKING:
    from ....core.choices import FillMethodName, OrderName
    from ...asked import Connectivity

GRID_CHARS = {"#": BOUNDARY, ".": EMPTY, "*": FILLED}
"""How a grid given as text is read: ``#`` boundary, ``.`` empty, ``*`` already the fill
colour; any other printable character is a colour of its own."""

LEAK = (
    "An 8-connected fill needs a 4-connected boundary: where the boundary steps diagonally "
    "(as Bresenham edges do), two boundary pixels touch only at a corner and the fill passes "
    "between them. A 4-connected fill cannot, so 4-connected fills suit 8-connected "
    "boundaries and 8-connected fills need 4-connected ones."
)


def parse_rows(rows: Sequence[str]) -> Grid:
    """A grid from text rows, top row first (so the last row is y = 0); rows may also be given
    as one string separated by ``/`` or newlines.

    >>> g = parse_rows(["###", "#.#", "###"])
    >>> g.width, g.height, g.colours[(1, 1)], g.colours[(0, 2)]
    (3, 3, 0, 1)
    """
    lines: list[str] = []
    for r in rows:
        lines.extend(part for part in r.replace("\n", "/").split("/") if part)
    if not lines:
        raise InputError("the grid has no rows", "rows")
    width = len(lines[0])
    if any(len(r) != width for r in lines):
        raise InputError(
            f"every grid row must have the same length ({width}), got "
            + ", ".join(str(len(r)) for r in lines),
            "rows",
        )
    check_size(width, len(lines))
    extra: dict[str, int] = {}
    colours: dict[Pixel, int] = {}
    for row, text in enumerate(lines):
        y = len(lines) - 1 - row
        for x, ch in enumerate(text):
            if not ch.isprintable() or ch == " ":
                raise InputError(
                    f"grid cell ({x}, {y}) is {ch!r}: use '#', '.', '*' or a letter", "rows"
                )
            if ch not in GRID_CHARS:
                extra.setdefault(ch, 3 + len(extra))
            colours[(x, y)] = GRID_CHARS.get(ch, extra.get(ch, EMPTY))
    return Grid(0, 0, width, len(lines), colours)


def _colour_names(rows: Sequence[str] | None) -> dict[int, str]:
    names = {EMPTY: "empty", BOUNDARY: "boundary", FILLED: "filled"}
    if rows:
        seen: dict[str, int] = {}
        for r in rows:
            for ch in r.replace("\n", "/"):
                if ch not in GRID_CHARS and ch != "/" and ch not in seen:
                    seen[ch] = 3 + len(seen)
        names.update({v: f"'{k}'" for k, v in seen.items()})
    return names


def _pixels(ps: Sequence[Pixel]) -> str:
    return " ".join(fmt_pixel(p) for p in ps) if ps else "-"


def _pending(n: int, upcoming: Sequence[Pixel], order: str) -> str:
    if not n:
        return "(empty)"
    more = f" ... (+{n - len(upcoming)})" if n > len(upcoming) else ""
    return _pixels(upcoming) + more


_Leak = tuple[int, Pixel, Pixel, tuple[Pixel, Pixel]]


def _start_grid(vertices: Sequence[Number] | None, rows: Sequence[str] | None) -> tuple[Grid, str]:
    """The grid to fill and where it comes from."""
    if vertices is not None:
        pts, _ = check_polygon(vertices_from_coords(vertices))
        grid = grid_around(outline_pixels(pts))
        return grid, f"the Bresenham outline of the polygon {' '.join(str(p) for p in pts)}"
    assert rows is not None
    grid = parse_rows(rows)
    return grid, f"the {grid.width} x {grid.height} grid given"


def _fill_order(trace: list[Any], span: bool, before: Grid) -> tuple[list[Pixel], _Leak | None]:
    """The pixels in the order they are filled, and the first diagonal squeeze (a leak)."""
    filled_order: list[Pixel] = []
    leak: _Leak | None = None
    for s in trace:
        if not s.filled:
            continue
        if span:
            filled_order.extend((x, s.pixel[1]) for x in range(s.span[0], s.span[1] + 1))
            continue
        filled_order.append(s.pixel)
        for q in s.pushed:
            where = squeezes(before, s.pixel, q)
            if where and leak is None:
                leak = (s.k, s.pixel, q, where)
    return filled_order, leak


def _said(key: str, value: Any, text: str) -> Quantity:
    """A quantity stated in words (the same words in TeX's text mode, escaped: ``x_left``
    would stop pdflatex)."""
    return Quantity(key, value, text, f"\\text{{{tex_text(text)}}}")


def _neighbours(connectivity: int, span: bool) -> str:
    if span:
        wide = " - 1" if connectivity == 8 else ""
        return (
            f"seeds: the rows y + 1 and y - 1 are scanned from x_left{wide} to "
            f"x_right{wide.replace('-', '+')}"
        )
    steps = FOUR if connectivity == 4 else EIGHT
    return "neighbours, in order: " + ", ".join(
        f"(x{dx:+d}, y{dy:+d})".replace("+0", "").replace("-0", "") for dx, dy in steps
    )


def _fill_given(
    grid: Grid, source: str, seed: Pixel, connectivity: int, order: str
) -> tuple[Quantity, ...]:
    sx, sy = seed
    where = (
        f"grid: {source}, x {grid.x0} .. {grid.x0 + grid.width - 1}, "
        f"y {grid.y0} .. {grid.y0 + grid.height - 1}"
    )
    return (
        _said("grid", (grid.x0, grid.y0, grid.width, grid.height), where),
        Quantity("seed", (sx, sy), f"seed = ({sx}, {sy})", f"\\text{{seed}} = ({sx}, {sy})"),
        _said("connectivity", connectivity, f"{connectivity}-connected"),
        _said("order", order, f"order: {order}"),
    )


def _fill_derived(
    test: str, connectivity: int, span: bool, order: str, filled: int, steps: int
) -> tuple[Quantity, ...]:
    lifo = "the last pushed first (LIFO)" if order == "stack" else "the first pushed first (FIFO)"
    return (
        _said("test", test, f"fill test: {test}"),
        _said("neighbours", connectivity, _neighbours(connectivity, span)),
        _said("taken", order, f"taken: {lifo}"),
        _said("filled", filled, f"pixels filled: {filled} in {steps} steps"),
    )


def _leak_note(leak: _Leak, grid: Grid, filled_order: list[Pixel]) -> str:
    k, frm, to, (a, b) = leak
    edge = any(
        p[0] in (grid.x0, grid.x0 + grid.width - 1) or p[1] in (grid.y0, grid.y0 + grid.height - 1)
        for p in filled_order
    )
    return (
        f"Leak: at step {k} the fill went diagonally from {fmt_pixel(frm)} to {fmt_pixel(to)}, "
        f"between the boundary pixels {fmt_pixel(a)} and {fmt_pixel(b)}"
        + ("; it reached the edge of the grid, outside the region." if edge else ".")
    )


def _span_leak_note(before: Grid, seed: Pixel, method: str, order: str, filled: int) -> str | None:
    """The 8-connected span fill against the 4-connected one: the pixels it leaked into."""
    four = before.copy()
    list(span_fill(four, seed, method, 4, order))
    extra = filled - sum(1 for c in four.colours.values() if c == FILLED)
    if not extra:
        return None
    return (
        f"Leak: the 8-connected span fill covers {extra} pixels more than the "
        "4-connected one: it passed diagonally between boundary pixels."
    )


_SPAN_NOTE = (
    "Span fill: each seed taken fills its whole run on its row, left and right up to "
    "the boundary, then pushes the rightmost pixel of every fillable run in the rows "
    "above and below (one pixel further left and right when 8-connected)."
)
_SEED_NOTE = (
    "The colour is tested when a pixel is taken, as the recursive procedure tests on "
    "entry; only neighbours that pass the test when pushed are pushed, so a pixel "
    "pushed twice is skipped the second time."
)


def _trace_rows(
    trace: list[Any], names: dict[int, str], span: bool, order: str
) -> Callable[[], Iterator[tuple[Any, ...]]]:
    def rows_fn() -> Iterator[tuple[Any, ...]]:
        for s in trace:
            colour = names.get(s.colour, str(s.colour))
            outcome = (
                "fill" if s.filled else ("skip: already filled" if s.colour == FILLED else "skip")
            )
            head = (s.k, fmt_pixel(s.pixel), colour, outcome)
            tail = (_pixels(s.pushed), s.pending, _pending(s.pending, s.upcoming, order))
            if span:
                assert isinstance(s, SpanStep)
                yield (*head, f"x = {s.span[0]} .. {s.span[1]}" if s.span else "-", *tail)
            else:
                assert isinstance(s, FillStep)
                yield (*head, *tail)

    return rows_fn


def _trace_columns(span: bool, order: str) -> tuple[Column, ...]:
    nxt = "top of the stack" if order == "stack" else "front of the queue"
    return (
        heading("k", "k", role="label"),
        heading("pixel", r"\text{taken}"),
        heading("colour", r"\text{colour}"),
        heading("test", r"\text{test}"),
        *((heading("span", r"\text{span filled}"),) if span else ()),
        heading("pushed", r"\text{pushed}"),
        heading("size", r"\text{size}"),
        heading("next", f"\\text{{{nxt}}}"),
    )


def _check_fill(
    seed: Sequence[Number],
    vertices: Sequence[Number] | None,
    rows: Sequence[str] | None,
    order: str,
) -> Pixel:
    """The seed pixel, once the arguments are checked."""
    if (vertices is None) == (rows is None):
        raise InputError("give either the polygon's vertices or the grid's rows", "rows")
    if order not in ORDERS:
        raise InputError(f"order must be stack or queue, got {order!r}", "order")
    if len(seed) != 2:
        raise InputError(f"the seed is one pixel x y, got {len(seed)} numbers", "seed")
    sx, sy = (check_whole(v, "seed coordinate", param="seed") for v in seed)
    return sx, sy


def _fill_figures(
    grid: Grid, filled: list[Pixel], marks: tuple[Pixel, ...], bbox: tuple[int, int, int, int]
) -> tuple[PixelFigure, ...]:
    """The filled grid, when it fits a figure."""
    if grid.width + 2 > MAX_GRID_CELLS or grid.height + 2 > MAX_GRID_CELLS:
        return ()
    return (
        PixelFigure(
            tuple(filled),
            tuple(sorted(set(marks))),
            bbox,
            legend="# = filled, o = boundary (or another colour)",
            title="Filled grid:",
        ),
    )


def seed_fill_solution(
    method: str,
    seed: Sequence[Number],
    *,
    vertices: Sequence[Number] | None = None,
    rows: Sequence[str] | None = None,
    connectivity: int = 4,
    order: str = "stack",
    span: bool = False,
) -> Solution:
    """Boundary or flood fill (``span``: the scan-line seed fill) over a polygon's Bresenham
    outline (``vertices``: ``x1 y1 x2 y2 ...``) or over a grid given as text ``rows``: the
    answer of ``method``'s record to the question (:class:`~scanconv.answers.asked.FillQuestion`),
    which the answer keeps.

    >>> sol = seed_fill_solution("boundary", (1, 1), rows=["####", "#..#", "####"])
    >>> [r[1] for r in sol.tables[0].rows()]
    ['(1, 1)', '(2, 1)']
    >>> sol.question.connectivity, sol.question.order
    (4, 'stack')
    """
    if method not in METHODS:
        raise InputError(f"unknown fill {method!r} (choose from {', '.join(METHODS)})", "method")
    answer = methods.method("fill", method).load("answer")
    sx, sy = _check_fill(seed, vertices, rows, order)
    check_fill(method, connectivity, order)
    q = FillQuestion(
        cast("FillMethodName", method),
        (sx, sy),
        None if vertices is None else tuple(vertices),
        None if rows is None else tuple(rows),
        cast("Connectivity", connectivity),
        cast("OrderName", order),
        span,
    )  # each choice checked above
    sol: Solution = answer(q)
    sol.question = q
    return sol


def boundary_answer(q: FillQuestion) -> Solution:
    """Boundary fill: a cell is filled when its colour is neither the boundary's nor the
    fill's."""
    return _fill_solution("boundary", lambda seed_colour: _BOUNDARY_TEST, q)


def flood_answer(q: FillQuestion) -> Solution:
    """Flood fill: a cell is filled when it has the seed's colour."""
    return _fill_solution(
        "flood", lambda seed_colour: f"colour = {seed_colour} (the seed's colour)", q
    )


_BOUNDARY_TEST = "colour is neither boundary nor filled"


def _fill_solution(method: str, test_of: Callable[[str], str], q: FillQuestion) -> Solution:
    """The fill's answer by the colour test ``method``, ``test_of`` the wording of its test
    (given the seed's colour's name)."""
    connectivity, order, span = q.connectivity, q.order, q.span
    vertices, rows, (sx, sy) = q.vertices, q.rows, q.seed
    grid, source = _start_grid(vertices, rows)
    names = _colour_names(rows)
    before = grid.copy()
    trace: list[Any] = list(
        (span_fill if span else seed_fill)(grid, (sx, sy), method, connectivity, order)
    )
    filled_order, leak = _fill_order(trace, span, before)
    test = test_of(names[before.colours[(sx, sy)]])
    notes = [_SPAN_NOTE if span else _SEED_NOTE, *((LEAK,) if connectivity == 8 else ())]
    if leak is not None:
        notes.append(_leak_note(leak, grid, filled_order))
    if span and connectivity == 8:
        more = _span_leak_note(before, (sx, sy), method, order, len(filled_order))
        notes.extend(() if more is None else (more,))
    others = sorted(p for p, c in grid.colours.items() if c not in (EMPTY, BOUNDARY, FILLED))
    if others:
        notes.append("Cells of other colours left as they were: " + _pixels(others) + ".")
    boundary_px = tuple(p for p, c in before.colours.items() if c == BOUNDARY)
    bbox = (grid.x0, grid.y0, grid.x0 + grid.width - 1, grid.y0 + grid.height - 1)
    figures = _fill_figures(grid, filled_order, (*boundary_px, *others), bbox)
    named = methods.method("fill", method).title  # "boundary fill"
    title = named[:1].upper() + named[1:]
    if span:
        title = f"Span (scan-line seed) fill, {method} test"
    return Solution(
        primitive="fill",
        algorithm="span" if span else method,
        title=f"{title}, {connectivity}-connected, {order}: seed ({sx}, {sy})",
        given=_fill_given(grid, source, (sx, sy), connectivity, order),
        derived=_fill_derived(test, connectivity, span, order, len(filled_order), len(trace)),
        notes=tuple(notes),
        walk=Walk(
            tables=(
                Table("Trace", _trace_columns(span, order), _trace_rows(trace, names, span, order)),
            )
        ),
        plot=Plot(
            pixels=lambda: iter(filled_order),
            bbox=bbox,
            marks=(),
            figures=figures,
            outline=figures[0].marks if figures else (),
            outline_name="boundary pixel (or another colour)",
            numbering="order",
            order_name="fill order (0: the seed)",
        ),
        data=dict(boundary=[list(p) for p in sorted(boundary_px)]),
    )
