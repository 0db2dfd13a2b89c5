"""Thick lines (``thickline``): the pixels against a plain implementation written here, the
bounding box from the ends alone, and a long line answered in constant memory (attack
report N7: 1.24 GB for an accepted 2,000,000-pixel line)."""

from __future__ import annotations

import tracemalloc

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.answers.primitives.attributes import thick_line_solution
from scanconv.render import Format, Options, render

from .references import bresenham_ref


def plain_thick(x1, y1, x2, y2, width, brush):
    """Every pixel of the notes' Bresenham line widened by the offsets -(w-1)//2 .. w//2
    (across the minor axis, or a square brush), each pixel once: a set of all of them, no
    window."""
    steep = abs(y2 - y1) > abs(x2 - x1)
    span = range(-((width - 1) // 2), width // 2 + 1)
    if brush:
        offsets = [(dx, dy) for dy in span for dx in span]
    else:
        offsets = [(d, 0) if steep else (0, d) for d in span]
    return {(x + dx, y + dy) for x, y in bresenham_ref(x1, y1, x2, y2) for dx, dy in offsets}


coord = st.integers(-40, 40)


@pytest.mark.slow  # 150 examples
@settings(max_examples=150, deadline=None)
@given(coord, coord, coord, coord, st.integers(1, 7), st.booleans())
def test_the_pixels_and_their_box_are_the_plain_ones(x1, y1, x2, y2, width, brush):
    sol = thick_line_solution(x1, y1, x2, y2, width, brush=brush)
    pixels = list(sol.pixels())
    assert len(pixels) == len(set(pixels))  # each pixel once
    expected = plain_thick(x1, y1, x2, y2, width, brush)
    assert set(pixels) == expected
    centre = [s.pixel for s in sol.steps()]
    assert centre == bresenham_ref(x1, y1, x2, y2)  # one pixel a step, the notes' line
    xs, ys = [p[0] for p in expected], [p[1] for p in expected]
    assert sol.bbox == (min(xs), min(ys), max(xs), max(ys))
    assert f"pixels: }} {len(pixels)}" in "".join(str(d) for d in sol.derived)


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
