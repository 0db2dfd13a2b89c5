"""Seed fills: boundary fill, flood fill and the span (scan-line seed) fill, traced step by
step over a small grid of colours.

A :class:`Grid` holds one colour per cell (small integers: :data:`EMPTY`, :data:`BOUNDARY`,
:data:`FILLED`, and any other value for other colours). :func:`seed_fill` and
:func:`span_fill` fill a copy of it from a seed pixel and yield one record per pixel (or span)
taken from the stack or queue, so an answer can print the trace.

Conventions
-----------
* Neighbours in Hearn & Baker's order: 4-connected ``(x+1, y), (x-1, y), (x, y+1),
  (x, y-1)``; 8-connected adds ``(x+1, y+1), (x-1, y+1), (x-1, y-1), (x+1, y-1)``. With a
  stack the last one pushed is taken first (the order of the recursive textbook procedure,
  reversed); with a queue the first.
* The colour is tested when a pixel is taken (as the recursive procedure tests on entry);
  a neighbour is pushed only if it is inside the grid and passes the test at that moment, so
  a pixel can be pushed twice and is skipped the second time ("already filled").
* Boundary fill fills every pixel whose colour is neither the boundary colour nor the fill
  colour; flood fill fills the pixels of the seed's colour. Cells outside the grid are never
  taken: the grid's edge stops a fill that leaks.

References
----------
Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 3-11 (boundary-fill and
flood-fill, 4- and 8-connected, the stack of pixel spans); Foley et al., *Computer Graphics:
Principles and Practice*, 2nd ed., section 19.5 (4- and 8-connected regions: an 8-connected
fill needs a boundary that is 4-connected, or it leaks through the diagonal steps).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from itertools import islice
from typing import NamedTuple

from ..core.checks import InputError
from ..core.records import Pixel
from .process_choices import Order

EMPTY, BOUNDARY, FILLED = 0, 1, 2
"""The colours every grid knows: background, boundary and the fill colour."""

MAX_SEED_CELLS = 10_000
"""Largest grid (columns x rows) a seed fill traces: the trace has a row per pixel taken."""

SHOWN = 6
"""How many of the pending pixels a trace row lists (the next ones to be taken)."""

FOUR = ((1, 0), (-1, 0), (0, 1), (0, -1))
EIGHT = (*FOUR, (1, 1), (-1, 1), (-1, -1), (1, -1))


METHODS = ("boundary", "flood")
"""The colour tests: stop at the boundary colour, or replace the seed's colour."""
ORDERS = tuple(o.value for o in Order)
CONNECTIVITIES = (4, 8)
"""The neighbours a fill visits: the 4 edge neighbours, or the 8 with the corners."""


@dataclass(slots=True)
class Grid:
    """A rectangle of coloured cells: ``x0 .. x0 + width - 1`` by ``y0 .. y0 + height - 1``."""

    x0: int
    y0: int
    width: int
    height: int
    colours: dict[Pixel, int]
    """The colour of every cell of the rectangle."""

    def inside(self, p: Pixel) -> bool:
        return self.x0 <= p[0] < self.x0 + self.width and self.y0 <= p[1] < self.y0 + self.height

    def copy(self) -> Grid:
        return Grid(self.x0, self.y0, self.width, self.height, dict(self.colours))


def check_size(width: int, height: int, param: str = "rows") -> None:
    """Refuse a grid beyond :data:`MAX_SEED_CELLS` before it is built.

    >>> check_size(101, 100)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: a seed fill grid of 101 x 100 = 10,100 cells is too large (at most 10,000 cells)
    """
    if width * height > MAX_SEED_CELLS:
        raise InputError(
            f"a seed fill grid of {width} x {height} = {width * height:,} cells is too large "
            f"(at most {MAX_SEED_CELLS:,} cells)",
            param,
        )


def grid_around(boundary: Sequence[Pixel], margin: int = 1) -> Grid:
    """An empty grid around the boundary pixels (their bounding box plus ``margin``) with the
    boundary drawn in it.

    >>> g = grid_around([(0, 0), (1, 0)])
    >>> (g.x0, g.y0, g.width, g.height), g.colours[(1, 0)], g.colours[(2, 1)]
    ((-1, -1, 4, 3), 1, 0)
    """
    xs, ys = [p[0] for p in boundary], [p[1] for p in boundary]
    x0, y0 = min(xs) - margin, min(ys) - margin
    width, height = max(xs) - x0 + 1 + margin, max(ys) - y0 + 1 + margin
    check_size(width, height, "vertices")
    colours = {(x, y): EMPTY for x in range(x0, x0 + width) for y in range(y0, y0 + height)}
    for p in boundary:
        colours[p] = BOUNDARY
    return Grid(x0, y0, width, height, colours)


def check_seed(grid: Grid, seed: Pixel, method: str) -> None:
    """Refuse a seed outside the grid or on the boundary."""
    if not grid.inside(seed):
        raise InputError(
            f"the seed ({seed[0]}, {seed[1]}) is outside the grid "
            f"(x {grid.x0} .. {grid.x0 + grid.width - 1}, y {grid.y0} .. "
            f"{grid.y0 + grid.height - 1})",
            "seed",
        )
    if grid.colours[seed] == BOUNDARY:
        raise InputError(f"the seed ({seed[0]}, {seed[1]}) is on the boundary", "seed")
    if grid.colours[seed] == FILLED:
        raise InputError(f"the seed ({seed[0]}, {seed[1]}) is already the fill colour", "seed")


class FillStep(NamedTuple):
    """One pixel taken from the stack or queue."""

    k: int
    pixel: Pixel
    colour: int
    """Its colour when taken."""
    filled: bool
    """Whether it passed the colour test and was filled."""
    pushed: tuple[Pixel, ...]
    """The neighbours pushed, in order."""
    pending: int
    """How many pixels wait in the stack or queue after this step."""
    upcoming: tuple[Pixel, ...]
    """The next :data:`SHOWN` pixels to be taken, first one first."""


class SpanStep(NamedTuple):
    """One seed taken by the span fill."""

    k: int
    pixel: Pixel
    colour: int
    filled: bool
    span: tuple[int, int] | None
    """The run ``(x_left, x_right)`` filled on the seed's row; ``None`` if skipped."""
    pushed: tuple[Pixel, ...]
    """The seeds pushed: the rightmost pixel of each fillable run above, then below."""
    pending: int
    upcoming: tuple[Pixel, ...]


def check_fill(method: str, connectivity: int, order: str) -> None:
    """InputError for an unknown colour test, connectivity or order."""
    if method not in METHODS:
        raise InputError(f"unknown fill {method!r} (choose from {', '.join(METHODS)})", "method")
    if connectivity not in CONNECTIVITIES:
        raise InputError(f"connectivity must be 4 or 8, got {connectivity}", "connectivity")
    if order not in ORDERS:
        raise InputError(f"order must be stack or queue, got {order!r}", "order")


class _Test(NamedTuple):
    """A fill's colour test: whether a cell of colour ``c`` is filled, the seed's colour
    ``target`` known."""

    method: str
    fillable: Callable[[int, int], bool]


_TESTS = (
    _Test("boundary", lambda c, target: c not in (BOUNDARY, FILLED)),  # up to the boundary
    _Test("flood", lambda c, target: c == target),  # the seed's colour replaced
)
"""Each of :data:`METHODS`' colour tests."""


def _fillable(method: str, target: int) -> Callable[[int], bool]:
    """The colour test of ``method`` (one of :data:`METHODS`), for the seed's colour."""
    test = next(t.fillable for t in _TESTS if t.method == method)
    return lambda c: test(c, target)


def _upcoming(todo: deque[Pixel], order: str) -> tuple[Pixel, ...]:
    if order == "stack":
        return tuple(todo[-i] for i in range(1, min(SHOWN, len(todo)) + 1))
    return tuple(islice(todo, SHOWN))


def seed_fill(
    grid: Grid, seed: Pixel, method: str = "boundary", connectivity: int = 4, order: str = "stack"
) -> Iterator[FillStep]:
    """Boundary or flood fill of ``grid`` (changed in place) from ``seed``, one step per pixel
    taken (see the module's conventions).

    >>> g = grid_around([(0, 0), (1, 0), (2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (0, 1)])
    >>> [(s.pixel, s.filled, s.pushed) for s in seed_fill(g, (1, 1))]
    [((1, 1), True, ())]
    """
    check_fill(method, connectivity, order)
    check_seed(grid, seed, method)
    ok = _fillable(method, grid.colours[seed])
    steps = FOUR if connectivity == 4 else EIGHT
    todo: deque[Pixel] = deque([seed])
    take = todo.pop if order == "stack" else todo.popleft
    colours = grid.colours
    k = 0
    while todo:
        p = take()
        c = colours[p]
        pushed: list[Pixel] = []
        filled = ok(c)
        if filled:
            colours[p] = FILLED
            for dx, dy in steps:
                q = (p[0] + dx, p[1] + dy)
                if grid.inside(q) and ok(colours[q]):
                    todo.append(q)
                    pushed.append(q)
        yield FillStep(k, p, c, filled, tuple(pushed), len(todo), _upcoming(todo, order))
        k += 1


def span_fill(
    grid: Grid, seed: Pixel, method: str = "boundary", connectivity: int = 4, order: str = "stack"
) -> Iterator[SpanStep]:
    """The scan-line seed fill: take a seed, fill its row left and right up to the boundary,
    then push one seed per fillable run on the rows above and below (the run's rightmost
    pixel), looking one pixel further left and right when 8-connected.

    >>> g = grid_around([(0, 0), (1, 0), (2, 0), (3, 0), (3, 1), (3, 2), (2, 2), (1, 2), (0, 2), (0, 1)])
    >>> [(s.pixel, s.span, s.pushed) for s in span_fill(g, (1, 1))]
    [((1, 1), (1, 2), ())]
    """
    check_fill(method, connectivity, order)
    check_seed(grid, seed, method)
    ok = _fillable(method, grid.colours[seed])
    todo: deque[Pixel] = deque([seed])
    take = todo.pop if order == "stack" else todo.popleft
    colours = grid.colours
    wide = 1 if connectivity == 8 else 0
    k = 0
    while todo:
        p = take()
        x, y = p
        c = colours[p]
        if not ok(c):
            yield SpanStep(k, p, c, False, None, (), len(todo), _upcoming(todo, order))
            k += 1
            continue
        left = x
        while grid.inside((left - 1, y)) and ok(colours[(left - 1, y)]):
            left -= 1
        right = x
        while grid.inside((right + 1, y)) and ok(colours[(right + 1, y)]):
            right += 1
        for xx in range(left, right + 1):
            colours[(xx, y)] = FILLED
        pushed = []
        for row in (y + 1, y - 1):
            run_end = None
            for xx in range(left - wide, right + wide + 1):
                q = (xx, row)
                if grid.inside(q) and ok(colours[q]):
                    run_end = q
                elif run_end is not None:
                    pushed.append(run_end)
                    run_end = None
            if run_end is not None:
                pushed.append(run_end)
        todo.extend(pushed)
        yield SpanStep(
            k, p, c, True, (left, right), tuple(pushed), len(todo), _upcoming(todo, order)
        )
        k += 1


def squeezes(grid: Grid, frm: Pixel, to: Pixel) -> tuple[Pixel, Pixel] | None:
    """The two boundary pixels a diagonal move from ``frm`` to ``to`` passes between, if both
    of its corner neighbours are boundary (an 8-connected fill leaking), else ``None``.

    >>> g = grid_around([(1, 0), (0, 1)])
    >>> squeezes(g, (0, 0), (1, 1))
    ((1, 0), (0, 1))
    """
    dx, dy = to[0] - frm[0], to[1] - frm[1]
    if dx == 0 or dy == 0:
        return None
    a, b = (frm[0] + dx, frm[1]), (frm[0], frm[1] + dy)
    if grid.colours.get(a) == BOUNDARY and grid.colours.get(b) == BOUNDARY:
        return a, b
    return None
