"""Thick lines (``thickline``): the pixels against a plain implementation written here, the
bounding box from the ends alone, and a long line answered in constant memory (attack
report N7: 1.24 GB for an accepted 2,000,000-pixel line)."""

from __future__ import annotations

import tracemalloc

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.answers.attributes import thick_line_solution
from scanconv.render import Format, Options, render


def plain_bresenham(x1: int, y1: int, x2: int, y2: int) -> list[tuple[int, int]]:
    """The textbook all-octant Bresenham (integer error term), from (x1, y1)."""
    dx, dy = abs(x2 - x1), -abs(y2 - y1)
    sx, sy = (1 if x2 > x1 else -1), (1 if y2 > y1 else -1)
    err, x, y, out = dx + dy, x1, y1, []
    while True:
        out.append((x, y))
        if (x, y) == (x2, y2):
            return out
        e2 = 2 * err
        if e2 >= dy:
            err, x = err + dy, x + sx
        if e2 <= dx:
            err, y = err + dx, y + sy


def plain_thick(x1, y1, x2, y2, width, brush):
    """Every centre pixel widened by the offsets -(w-1)//2 .. w//2 (across the minor axis,
    or a square brush), each pixel once: a set of all of them, no window."""
    steep = abs(y2 - y1) > abs(x2 - x1)
    span = range(-((width - 1) // 2), width // 2 + 1)
    if brush:
        offsets = [(dx, dy) for dy in span for dx in span]
    else:
        offsets = [(d, 0) if steep else (0, d) for d in span]
    return {(x + dx, y + dy) for x, y in plain_bresenham(x1, y1, x2, y2) for dx, dy in offsets}


coord = st.integers(-40, 40)


@pytest.mark.slow  # 150 examples
@settings(max_examples=150, deadline=None)
@given(coord, coord, coord, coord, st.integers(1, 7), st.booleans())
def test_the_pixels_and_their_box_are_the_plain_ones(x1, y1, x2, y2, width, brush):
    sol = thick_line_solution(x1, y1, x2, y2, width, brush=brush)
    pixels = list(sol.pixels())
    assert len(pixels) == len(set(pixels))  # each pixel once
    expected = plain_thick(x1, y1, x2, y2, width, brush)
    # the centre line (the notes' Bresenham, tested in test_lines) may break a tie the other
    # way from this plain one: the box and the count exactly, the set from its own centre
    centre = {s.pixel for s in sol.steps()}
    assert set(pixels) == plain_thick_from(centre, x1, y1, x2, y2, width, brush)
    assert len(centre) == max(abs(x2 - x1), abs(y2 - y1)) + 1
    xs, ys = [p[0] for p in expected], [p[1] for p in expected]
    assert sol.bbox == (min(xs), min(ys), max(xs), max(ys))
    assert f"pixels: }} {len(pixels)}" in "".join(str(d) for d in sol.derived)


def plain_thick_from(centre, x1, y1, x2, y2, width, brush):
    steep = abs(y2 - y1) > abs(x2 - x1)
    span = range(-((width - 1) // 2), width // 2 + 1)
    offsets = (
        [(dx, dy) for dy in span for dx in span]
        if brush
        else [(d, 0) if steep else (0, d) for d in span]
    )
    return {(x + dx, y + dy) for x, y in centre for dx, dy in offsets}


def test_a_shallow_line_is_the_plain_one_exactly():
    sol = thick_line_solution(2, 2, 10, 6, 3)
    assert set(sol.pixels()) == plain_thick(2, 2, 10, 6, 3, False)


def _peak(x2: int, brush: bool) -> int:
    tracemalloc.start()
    try:
        sol = thick_line_solution(0, 0, x2, 1, 2, brush=brush)
        for _ in render(sol, Format.csv, Options(grid=False)):
            pass
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.slow  # 44,000 rows under tracemalloc
def test_a_long_thick_line_is_answered_in_constant_memory():
    """Ten times the length, about the same peak: nothing grows with the line."""
    for brush in (False, True):
        short, long = _peak(2_000, brush), _peak(20_000, brush)
        assert long < 2 * short + 200_000, (brush, short, long)
