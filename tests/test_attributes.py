"""Line attributes (scanconv.algorithms.attributes, scanconv.answers.primitives.attributes): masks,
replication and brushes on Bresenham's centre line, checked by hand and by properties."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.attributes import centre_line, parse_mask, styled, thick
from scanconv.algorithms.raster import line as raster_line
from scanconv.answers.primitives.attributes import line_style_solution, thick_line_solution
from scanconv.core.checks import InputError

ENDS = st.tuples(*(st.integers(-20, 20) for _ in range(4)))


def test_mask_by_hand() -> None:
    # OpenGL's 0x00FF read lsb first: bit 0 is 1, so the first 8 pixels are drawn
    assert parse_mask("0x00FF", "lsb").bits == (1,) * 8 + (0,) * 8
    assert parse_mask("0x00FF", "msb").bits == (0,) * 8 + (1,) * 8
    # repeat 2: each bit covers two pixels: 1 1 0 0 1 1 ...
    drawn = [s.extra[1] for s in styled(0, 0, 5, 0, parse_mask("10", repeat=2))]
    assert drawn == [1, 1, 0, 0, 1, 1]


@pytest.mark.parametrize(("text", "param"), [("12", "mask"), ("0x", "mask"), ("1" * 65, "mask")])
def test_bad_masks(text: str, param: str) -> None:
    with pytest.raises(InputError) as info:
        parse_mask(text)
    assert info.value.param == param


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=80)
@given(ends=ENDS)
def test_the_centre_line_is_bresenhams(ends) -> None:
    """The centre line's pixels are the bulk rasterizer's (numpy closed form), as sets."""
    xs, ys = raster_line(*ends)
    assert {p for _, p in centre_line(*ends)} == set(zip(xs.tolist(), ys.tolist(), strict=True))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=80)
@given(ends=ENDS, mask=st.text("01", min_size=1, max_size=12), repeat=st.integers(1, 4))
def test_a_solid_mask_draws_every_pixel_and_the_mask_is_periodic(ends, mask, repeat) -> None:
    steps = list(styled(*ends, parse_mask(mask, repeat=repeat)))
    period = len(mask) * repeat
    assert all(s.extra[1] == steps[s.k % period].extra[1] for s in steps)
    solid = list(styled(*ends, parse_mask("1")))
    assert all(s.extra[1] == 1 for s in solid)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=80)
@given(ends=ENDS, width=st.integers(1, 6), brush=st.booleans())
def test_thick_lines_cover_the_span_of_every_centre_pixel(ends, width, brush) -> None:
    steps = list(thick(*ends, width, brush))
    drawn = [p for s in steps for p in s.extra[0]]
    assert len(drawn) == len(set(drawn))  # each pixel added once
    steep = abs(ends[3] - ends[1]) > abs(ends[2] - ends[0])
    lo, hi = -((width - 1) // 2), width // 2
    for s in steps:
        x, y = s.pixel
        for d in range(lo, hi + 1):
            assert ((x + d, y) if steep else (x, y + d)) in set(drawn)
    if not brush:  # replication: exactly w pixels in each column (row) of the centre line
        assert len(drawn) == width * len(steps)


def test_thick_line_by_hand() -> None:
    # (0, 0)-(4, 0) width 2 brush: squares {0,1} x {0,1} around each pixel: 2 x 5 + 2 = 10
    sol = thick_line_solution(0, 0, 4, 0, 2, brush=True)
    assert sorted(sol.pixels()) == sorted((x, y) for x in range(6) for y in range(2))


def test_style_answer() -> None:
    sol = line_style_solution(0, 0, 7, 2, "110")
    assert [s.extra[2] for s in sol.steps()] == ["draw", "draw", "skip"] * 2 + ["draw", "draw"]
    assert sol.marks == ((2, 1), (5, 1))


@settings(deadline=None, max_examples=150)
@given(
    mask=st.text("01", min_size=1, max_size=16),
    order=st.sampled_from(["msb", "lsb"]),
    length=st.integers(1, 40),
)
def test_the_mask_is_shown_as_written_and_each_pixel_takes_its_bit(mask, order, length) -> None:
    """The answer gives the mask as written (and in hexadecimal) with its bit order; pixel k
    takes the written mask's bit (k mod n) places from its left (msb) or its right (lsb)."""
    sol = line_style_solution(0, 0, length, 1, mask, bits=order)
    written = next(q for q in sol.given if q.key == "written")
    hex_shown = written.text.split(" = ")[2].split(" ")[0]
    assert written.value == mask and int(hex_shown, 16) == int(mask, 2)
    assert len(hex_shown) - 2 == -(-len(mask) // 4)  # a digit for every 4 bits
    assert f"{mask} (read {order} first" in sol.title
    n = int(mask, 2)
    for k, step in enumerate(sol.steps()):
        place = k % len(mask)
        want = n >> (len(mask) - 1 - place) & 1 if order == "msb" else n >> place & 1
        assert step.extra[1] == want
        assert step.extra[2] == ("draw" if want else "skip")
