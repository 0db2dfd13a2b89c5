"""Seed fills: boundary and flood fill, 4 and 8 connectivity, stack and queue, the span fill,
the 4/8 leak through a diagonal boundary, and bad input."""

from __future__ import annotations

from collections import deque

import pytest
from hypothesis import given
from hypothesis import strategies as st

from scanconv.algorithms.polygon import outline_pixels
from scanconv.algorithms.seedfill import (
    BOUNDARY,
    EIGHT,
    FILLED,
    FOUR,
    MAX_SEED_CELLS,
    check_size,
    grid_around,
    seed_fill,
    span_fill,
)
from scanconv.answers.process.fill.seed import parse_rows, seed_fill_solution
from scanconv.core.checks import InputError
from scanconv.render import Format, render

DIAMOND = [4, 1, 7, 4, 4, 7, 1, 4]  # every edge diagonal: an 8-connected outline
ROOM = ["#######", "#..x..#", "#.....#", "#######"]


def _filled(sol):
    return set(sol.pixels())


def test_the_first_steps_follow_hearn_and_baker_order():
    sol = seed_fill_solution("boundary", (2, 1), rows=ROOM)
    first, second = list(sol.tables[0].rows())[:2]
    # Neighbours pushed in the order (x+1, y), (x-1, y), (x, y+1), (x, y-1), if fillable:
    # (2, 0) is boundary.
    assert first[:5] == (0, "(2, 1)", "empty", "fill", "(3, 1) (1, 1) (2, 2)")
    assert first[5] == 3 and first[6] == "(2, 2) (1, 1) (3, 1)"  # the top of the stack first
    assert second[1] == "(2, 2)"
    queue = seed_fill_solution("boundary", (2, 1), rows=ROOM, order="queue")
    assert next(iter(queue.tables[0].rows()))[6] == "(3, 1) (1, 1) (2, 2)"


def test_boundary_fill_overwrites_other_colours_flood_fill_does_not():
    boundary = _filled(seed_fill_solution("boundary", (1, 1), rows=ROOM))
    flood = seed_fill_solution("flood", (1, 1), rows=ROOM)
    assert (3, 2) in boundary and len(boundary) == 10
    assert (3, 2) not in _filled(flood) and len(_filled(flood)) == 9
    assert any("other colours" in n and "(3, 2)" in n for n in flood.notes)


def test_the_8_connected_fill_leaks_through_a_diagonal_boundary():
    four = seed_fill_solution("flood", (4, 4), vertices=DIAMOND, connectivity=4)
    eight = seed_fill_solution("flood", (4, 4), vertices=DIAMOND, connectivity=8)
    inside = _filled(four)
    assert inside == {
        (x, y) for x in range(2, 7) for y in range(2, 7) if abs(x - 4) + abs(y - 4) <= 2
    }
    assert inside < _filled(eight)
    assert (0, 0) in _filled(eight)  # out through a corner, to the edge of the grid
    leak = [n for n in eight.notes if n.startswith("Leak:")]
    assert len(leak) == 1 and "reached the edge of the grid" in leak[0]
    assert not any(n.startswith("Leak:") for n in four.notes)


@pytest.mark.parametrize("method", ["boundary", "flood"])
@pytest.mark.parametrize("connectivity", [4, 8])
def test_stack_queue_and_span_fill_fill_the_same_pixels(method, connectivity):
    sets = [
        _filled(
            seed_fill_solution(
                method,
                (3, 3),
                vertices=[0, 0, 9, 1, 6, 8, 1, 6],
                connectivity=connectivity,
                order=order,
                span=span,
            )
        )
        for order in ("stack", "queue")
        for span in (False, True)
    ]
    assert all(s == sets[0] for s in sets)


def _component(grid, seed, connectivity):
    """The reference: breadth-first search over non-boundary cells."""
    steps = FOUR if connectivity == 4 else EIGHT
    seen, todo = {seed}, deque([seed])
    while todo:
        x, y = todo.popleft()
        for dx, dy in steps:
            q = (x + dx, y + dy)
            if grid.inside(q) and q not in seen and grid.colours[q] != BOUNDARY:
                seen.add(q)
                todo.append(q)
    return seen


rows_st = st.integers(2, 8).flatmap(
    lambda w: st.lists(st.text("#.", min_size=w, max_size=w), min_size=2, max_size=8)
)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(rows=rows_st, data=st.data())
def test_every_fill_is_the_connected_component(rows, data):
    grid = parse_rows(rows)
    free = sorted(p for p, c in grid.colours.items() if c != BOUNDARY)
    if not free:
        return
    seed = data.draw(st.sampled_from(free))
    connectivity = data.draw(st.sampled_from([4, 8]))
    order = data.draw(st.sampled_from(["stack", "queue"]))
    expected = _component(grid, seed, connectivity)
    for fill in (seed_fill, span_fill):
        g = grid.copy()
        steps = list(fill(g, seed, "boundary", connectivity, order))
        got = {p for p, c in g.colours.items() if c == FILLED}
        assert got == expected
        assert steps[-1].pending == 0


def test_the_answer_renders_trace_and_grid():
    sol = seed_fill_solution("flood", (4, 4), vertices=DIAMOND, connectivity=4)
    text = "".join(c for c in render(sol, Format.plain) if isinstance(c, str))
    assert "Trace:" in text and "top of the stack" in text and "Filled grid:" in text
    assert text.isascii()
    span = seed_fill_solution("boundary", (3, 2), rows=ROOM, span=True)
    rows = list(span.tables[0].rows())
    assert rows[0][4] == "x = 1 .. 5" and rows[0][5] == "(5, 1)"


def test_outline_is_the_bresenham_edges():
    assert outline_pixels([(4, 1), (7, 4), (4, 7), (1, 4)])[:4] == [(4, 1), (5, 2), (6, 3), (7, 4)]


@pytest.mark.parametrize(
    ("kwargs", "word", "param"),
    [
        ({"seed": (9, 9), "rows": ROOM}, "outside the grid", "seed"),
        ({"seed": (0, 0), "rows": ROOM}, "on the boundary", "seed"),
        ({"seed": (4, 1), "vertices": DIAMOND}, "on the boundary", "seed"),
        ({"seed": (1, 1), "rows": ["###", "#."]}, "same length", "rows"),
        ({"seed": (1, 1), "rows": ["." * 101] * 100}, "too large", "rows"),
        ({"seed": (1, 1), "rows": ROOM, "vertices": DIAMOND}, "either", "rows"),
        ({"seed": (1, 1), "rows": ROOM, "connectivity": 6}, "4 or 8", "connectivity"),
        ({"seed": (1, 1), "rows": ROOM, "order": "heap"}, "stack or queue", "order"),
        ({"seed": (1, 1), "vertices": [0, 0, 1, 1]}, "at least 3", "vertices"),
    ],
)
def test_bad_input_is_refused(kwargs, word, param):
    with pytest.raises(InputError, match=word) as err:
        seed_fill_solution("boundary", **kwargs)
    assert err.value.param == param


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_grid_limit_at_its_edge():
    check_size(100, 100)
    assert MAX_SEED_CELLS == 100 * 100
    with pytest.raises(InputError, match="10,000"):
        grid_around([(0, 0), (99, 99)])  # 102 x 102 with the margin
    sol = seed_fill_solution("flood", (1, 1), rows=["." * 100] * 100, order="queue")
    assert len(_filled(sol)) == 10_000


def test_the_span_fill_reports_the_8_connected_leak():
    sol = seed_fill_solution("flood", (4, 4), vertices=DIAMOND, connectivity=8, span=True)
    assert any(n.startswith("Leak: the 8-connected span fill covers") for n in sol.notes)
    assert "x_left - 1 to x_right + 1" in sol.derived[1].text
    with pytest.raises(InputError, match="one pixel x y") as err:
        seed_fill_solution("flood", (1, 1, 1), rows=ROOM)
    assert err.value.param == "seed"


# A room whose top row is cut in two by a boundary pixel at (3, 3) (rows top first, the last
# row is y = 0). The span fill from (3, 2), worked by hand: its row x = 1 .. 5 filled, then
# the row above (y + 1 = 3, the order the working states) gives the runs 1..2 and 4..5, whose
# rightmost pixels (2, 3) and (5, 3) are pushed, then the row below (y - 1 = 1) one run, (5, 1).
SPLIT_ROOM = ["#######", "#..#..#", "#.....#", "#.....#", "#######"]
SPLIT_PUSHED = ((2, 3), (5, 3), (5, 1))


@pytest.mark.parametrize(
    ("order", "trace"),
    [
        # a stack takes the last pushed first: (5, 1), then (5, 3) (its run 4..5), then (2, 3)
        ("stack", [((3, 2), (1, 5), SPLIT_PUSHED, 3), ((5, 1), (1, 5), (), 2),
                   ((5, 3), (4, 5), (), 1), ((2, 3), (1, 2), (), 0)]),
        # a queue takes them as pushed: (2, 3), (5, 3), (5, 1)
        ("queue", [((3, 2), (1, 5), SPLIT_PUSHED, 3), ((2, 3), (1, 2), (), 2),
                   ((5, 3), (4, 5), (), 1), ((5, 1), (1, 5), (), 0)]),
    ],
)  # fmt: skip
def test_span_fill_scans_the_row_above_then_the_row_below(order, trace):
    grid = parse_rows(SPLIT_ROOM)
    steps = list(span_fill(grid, (3, 2), "boundary", 4, order))
    assert [(s.pixel, s.span, s.pushed, s.pending) for s in steps] == trace
