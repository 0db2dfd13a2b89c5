"""Property tests for the midpoint ellipse, against definitions written out here.

References: Hearn & Baker's published table (rx = 8, ry = 6), the ideal ellipse checked with
exact integer arithmetic, the midpoint circle (rx = ry), and, loosely, skimage's
``ellipse_perimeter`` (a different algorithm, so only "within one pixel of each other").
"""

from __future__ import annotations

from fractions import Fraction
from itertools import pairwise

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.ellipses import (
    midpoint_ellipse,
    quadrant_points,
    region1_end,
    symmetric_pixels,
)
from scanconv.answers.primitives.circle import circle_solution
from scanconv.answers.primitives.ellipse import ellipse_solution
from scanconv.core.records import Move

from .helpers import connected

Pixel = tuple[int, int]
axis = st.integers(min_value=0, max_value=300)
centre = st.integers(min_value=-40, max_value=40)
# very flat and very tall ellipses, where the textbook loops stop early or jump: with ry <= 3
# region 1 reaches y = 0 long before the tip from rx = 10 on (tests/test_raster.py pins rx = 10,
# ry = 1); rx up to 1,000 (was 3,000: each example walks and checks every pixel twice in Python)
flat = st.tuples(st.integers(min_value=1, max_value=1000), st.integers(min_value=0, max_value=3))


def pixel_list(rx: int, ry: int, xc: int = 0, yc: int = 0) -> list[Pixel]:
    sol = ellipse_solution(rx, ry, xc, yc)
    assert sol.pixels is not None
    return list(sol.pixels())


def pixel_set(rx: int, ry: int) -> set[Pixel]:
    """The pixels of :func:`pixel_list` (centre 0, 0) straight from the algorithm's quadrant,
    without the worked answer around them: the tests of the pixels' geometry call it on
    hundreds of ellipses, and the answer's working cost ten times the pixels.
    ``Solution.pixels()`` is exactly these images of these points (scanconv/answers/primitives/ellipse.py),
    and :func:`test_pixel_order_is_the_documented_one` checks the answer's own list."""
    return set(symmetric_pixels(quadrant_points(rx, ry)))


def quadrant(rx: int, ry: int) -> list[Pixel]:
    return [(0, ry), *(s.pixel for s in midpoint_ellipse(rx, ry))]


def touches_ellipse(p: Pixel, rx: int, ry: int) -> bool:
    """The ideal ellipse passes through the square of half-side 1 around ``p`` (exact)."""
    f = lambda x, y: ry * ry * x * x + rx * rx * y * y - rx * rx * ry * ry  # noqa: E731
    near = [0 if abs(c) <= 1 else abs(c) - 1 for c in p]
    far = [abs(c) + 1 for c in p]
    return f(*near) <= 0 <= f(*far)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(rx=axis, ry=axis)
@settings(deadline=None)
def test_quadrant_is_an_8_connected_walk_from_top_to_tip(rx, ry):
    pts = quadrant(rx, ry)
    assert pts[0] == (0, ry) and pts[-1] == (rx, 0)
    assert len(pts) == len(set(pts)) <= rx + ry + 1  # terminates, each step moves
    for (x0, y0), (x1, y1) in pairwise(pts):
        assert (x1 - x0, y1 - y0) in ((1, 0), (1, -1), (0, -1))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(rx=axis, ry=axis, xc=centre, yc=centre)
@settings(deadline=None)
def test_pixels_are_symmetric_unique_and_in_the_box(rx, ry, xc, yc):
    px = pixel_list(rx, ry, xc, yc)
    assert len(px) == len(set(px))
    rel = {(x - xc, y - yc) for x, y in px}
    assert all({(x, y), (-x, y), (x, -y), (-x, -y)} <= rel for x, y in rel)
    xs, ys = [p[0] for p in px], [p[1] for p in px]
    assert (min(xs), min(ys), max(xs), max(ys)) == ellipse_solution(rx, ry, xc, yc).bbox


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(rx=axis, ry=axis)
@settings(deadline=None)
def test_closed_outline_close_to_the_ideal_ellipse(rx, ry):
    px = pixel_set(rx, ry)
    assert connected(px)
    assert all(touches_ellipse(p, rx, ry) for p in px)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(axes=flat)
@settings(deadline=None, max_examples=40)
def test_flat_ellipses_reach_their_tips(axes):
    for rx, ry in (axes, axes[::-1]):
        px = pixel_set(rx, ry)
        assert {(rx, 0), (-rx, 0), (0, ry), (0, -ry)} <= px
        assert connected(px)
        assert all(touches_ellipse(p, rx, ry) for p in px)


@pytest.mark.parametrize("rx", range(0, 40))
def test_every_row_and_column_of_the_ideal_ellipse_is_covered(rx):
    """No gap: for every column x there is a pixel within 1 of the ellipse's y(x), and for
    every row y one within 1 of x(y) (exact integer comparisons)."""
    for ry in range(0, 40):
        pts = quadrant(rx, ry)
        for x in range(rx + 1):
            n, d = ry * ry * (rx * rx - x * x), rx * rx  # y(x)² = n / d
            assert any(_within_one(y, n, d) for px, y in pts if px == x), (rx, ry, x)
        for y in range(ry + 1):
            n, d = rx * rx * (ry * ry - y * y), ry * ry
            assert any(_within_one(x, n, d) for x, py in pts if py == y), (rx, ry, y)


def _within_one(v: int, n: int, d: int) -> bool:
    """|v - sqrt(n / d)| <= 1 exactly (d = 0 means the ideal value is 0)."""
    if d == 0:
        return v <= 1
    return (max(v - 1, 0) ** 2) * d <= n <= ((v + 1) ** 2) * d


def test_hearn_and_baker_rx8_ry6_tables():
    """Hearn & Baker, midpoint ellipse example: both published region tables."""
    rows = [(s.extra[0], s.k, s.p, s.pixel, s.extra[1], s.extra[2]) for s in midpoint_ellipse(8, 6)]
    assert rows == [
        (1, 0, -332, (1, 6), 72, 768),
        (1, 1, -224, (2, 6), 144, 768),
        (1, 2, -44, (3, 6), 216, 768),
        (1, 3, 208, (4, 5), 288, 640),
        (1, 4, -108, (5, 5), 360, 640),
        (1, 5, 288, (6, 4), 432, 512),
        (1, 6, 244, (7, 3), 504, 384),
        (2, 0, -23, (8, 2), 576, 256),
        (2, 1, 361, (8, 1), 576, 128),
        (2, 2, 297, (8, 0), 576, 0),
    ]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_decision_parameters_are_the_midpoint_residuals():
    """p1_k = f(x_k + 1, y_k - 1/2) and p2_k = f(x_k + 1/2, y_k - 1), f = ry²x² + rx²y² - rx²ry²."""
    for rx in range(0, 25):
        for ry in range(0, 25):
            x, y = 0, ry
            for s in midpoint_ellipse(rx, ry):
                if s.p is not None:
                    if s.extra[0] == 1:  # 4·f(x + 1, y - 1/2)
                        mx, my = 2 * x + 2, 2 * y - 1
                    else:  # 4·f(x + 1/2, y - 1)
                        mx, my = 2 * x + 1, 2 * y - 2
                    assert 4 * s.p == ry * ry * mx * mx + rx * rx * my * my - 4 * rx * rx * ry * ry
                    ok = (Move.E, Move.SE) if s.extra[0] == 1 else (Move.S, Move.SE)
                    assert s.decision in ok
                else:
                    assert s.decision is Move.E and s.pixel[1] == 0  # the flat tip
                assert s.extra[1:] == (2 * ry * ry * s.pixel[0], 2 * rx * rx * s.pixel[1])
                x, y = s.pixel


@pytest.mark.parametrize("r", range(0, 150))
def test_equal_axes_give_the_midpoint_circle(r):
    assert set(pixel_list(r, r)) == set(circle_solution("midpoint", r).pixels())


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
def test_loosely_agrees_with_skimage_ellipse_perimeter():
    draw = pytest.importorskip("skimage.draw")
    for rx in range(1, 30):
        for ry in range(1, 30):
            ours = pixel_set(rx, ry)
            rr, cc = draw.ellipse_perimeter(0, 0, ry, rx)
            theirs = {(int(c), int(r)) for r, c in zip(rr, cc, strict=True)}
            assert all(_near(p, theirs) for p in ours) and all(_near(p, ours) for p in theirs)


def _near(p: Pixel, pixels: set[Pixel]) -> bool:
    return any((p[0] + dx, p[1] + dy) in pixels for dx in (-1, 0, 1) for dy in (-1, 0, 1))


def test_pixel_order_is_the_documented_one():
    for rx, ry, xc, yc in ((8, 6, 0, 0), (5, 0, 2, 3), (0, 4, -1, 1), (10, 1, 0, 0), (0, 0, 3, 3)):
        expected: list[Pixel] = []
        for x, y in quadrant(rx, ry):
            for dx, dy in ((x, y), (-x, y), (x, -y), (-x, -y)):
                p = (xc + dx, yc + dy)
                if p not in expected:
                    expected.append(p)
        assert pixel_list(rx, ry, xc, yc) == expected


def test_degenerate_axes_are_segments():
    assert pixel_list(0, 0, 3, 4) == [(3, 4)]
    assert sorted(pixel_list(3, 0)) == [(x, 0) for x in range(-3, 4)]
    assert sorted(pixel_list(0, 2)) == [(0, y) for y in range(-2, 3)]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
def test_large_axes_terminate_quickly_with_every_step_a_unit_move():
    for rx, ry in ((100000, 3), (3, 100000), (20000, 15000)):
        n = sum(1 for _ in midpoint_ellipse(rx, ry))
        assert max(rx, ry) <= n <= rx + ry


@pytest.mark.parametrize(
    ("args", "message"),
    [((-1, 2), "rx must be a non-negative integer"), ((2, 1.5), "ry must be an integer")],
)
def test_library_errors(args, message):
    from fractions import Fraction

    with pytest.raises(ValueError, match=message):
        ellipse_solution(*(Fraction(a) for a in args))


def test_region_1_of_ellipse_3_2_with_the_keep_tie_by_hand():
    # rx = 3, ry = 2: p1_0 = ry^2 - rx^2 ry + rx^2 / 4 = 4 - 18 + 9/4 = -47/4. --tie keep
    # chooses E when p <= 0. p = -47/4: E to (1, 2), p += 2 ry^2 x + ry^2 = 8 + 4: 1/4.
    # p = 1/4 > 0: SE to (2, 1), p += 2 ry^2 x - 2 rx^2 y + ry^2 = 16 - 18 + 4: 9/4. Then SE to
    # (3, 0), where 2 ry^2 x = 24 >= 2 rx^2 y = 0 ends region 1: region 2 starts at (3, 0).
    steps = list(midpoint_ellipse(3, 2, tie="keep"))
    assert [(s.p, s.decision, s.pixel) for s in steps] == [
        (Fraction(-47, 4), Move.E, (1, 2)),
        (Fraction(1, 4), Move.SE, (2, 1)),
        (Fraction(9, 4), Move.SE, (3, 0)),
    ]
    assert region1_end(3, 2, tie="keep") == (3, 0)


@pytest.mark.parametrize("tie", ["step", "keep"])
@pytest.mark.parametrize("p0", ["exact", "rounded"])
@pytest.mark.parametrize("loop", ["strict", "inclusive"])
def test_region1_end_is_where_the_table_leaves_region_1(tie, p0, loop):
    # the working's "region 2 starts at" against the table's last region-1 point, for every
    # convention; ties (4 p = the threshold) occur at (3, 2) keep, (7, 1) rounded, (1, 1)
    for rx in range(1, 17):
        for ry in range(1, 17):
            steps = list(midpoint_ellipse(rx, ry, loop=loop, tie=tie, p0=p0))
            region1 = [s.pixel for s in steps if s.extra[0] == 1]
            assert region1_end(rx, ry, loop, tie, p0) == (region1[-1] if region1 else (0, ry))
