"""The bulk rasterizers give exactly the generators' pixels, in the same order.

Each closed form in :mod:`scanconv.raster` is checked against the step generator it replaces
(``Solution.pixels()``), on thousands of random inputs and on the degenerate cases, and the
integer helper against Python's exact integers. No timing here: see ``benchmarks/bench.py``.

Example counts (the whole suite within 5 minutes): the line property ran 1,000 examples per
algorithm, the floor-sum and isqrt helpers 600 and 500; 100 each now (the project's most), with
the degenerate cases pinned by ``@example`` and the small inputs swept exhaustively (every
circle of radius below 200, every ellipse of semi-axes below 40). The same closed forms are
compared with the generators again through every golden case and the CLI's own tests, and the
inner loop runs 20 examples of each.
"""

from __future__ import annotations

import math
import threading
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from scanconv.algorithms import (
    raster,
    raster_conic,
)  # the modules themselves: constants are patched
from scanconv.algorithms.ellipses import quadrant_points, symmetric_pixels
from scanconv.answers.primitives.circle import circle_solution
from scanconv.answers.primitives.ellipse import ellipse_solution
from scanconv.answers.primitives.line import line_solution

pytestmark = pytest.mark.slow

coord = st.integers(min_value=-60, max_value=60)
far = st.integers(min_value=-(10**9), max_value=10**9)
short = st.integers(min_value=-300, max_value=300)
frac = st.builds(Fraction, st.integers(-480, 480), st.sampled_from([1, 2, 3, 4, 5, 8, 10, 12]))


def as_pixels(coords: raster.Coords) -> list[tuple[int, int]]:
    xs, ys = coords
    assert xs.dtype == np.int64 and ys.dtype == np.int64
    assert xs.ndim == ys.ndim == 1 and xs.shape == ys.shape
    return list(zip(xs.tolist(), ys.tolist(), strict=True))


def generator_pixels(algo: str, *line: int | Fraction) -> list[tuple[int, int]]:
    sol = line_solution(algo, *line)
    assert sol.pixels is not None
    return list(sol.pixels())


# --- lines ------------------------------------------------------------------------------------


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", raster.LINE_ALGORITHMS)
@settings(max_examples=100, deadline=None)  # was 1000: see the module's note
@given(x1=coord, y1=coord, x2=coord, y2=coord)
@example(x1=3, y1=3, x2=3, y2=3)  # single point
@example(x1=-4, y1=2, x2=9, y2=2)  # horizontal
@example(x1=5, y1=9, x2=5, y2=-7)  # vertical, downward
@example(x1=0, y1=0, x2=-7, y2=7)  # 45 degrees
@example(x1=2, y1=2, x2=10, y2=6)  # the notes' example: p_k = 0 ties
@example(x1=10, y1=6, x2=2, y2=2)  # the same, right to left
def test_line_matches_generator(algo, x1, y1, x2, y2):
    assert as_pixels(raster.line(x1, y1, x2, y2, algo=algo)) == generator_pixels(
        algo, x1, y1, x2, y2
    )


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", raster.LINE_ALGORITHMS)
@settings(max_examples=100, deadline=None)
@given(x1=far, y1=far, dx=short, dy=short)
def test_line_far_from_the_origin(algo, x1, y1, dx, dy):
    x2 = max(-(10**9), min(10**9, x1 + dx))
    y2 = max(-(10**9), min(10**9, y1 + dy))
    assert as_pixels(raster.line(x1, y1, x2, y2, algo=algo)) == generator_pixels(
        algo, x1, y1, x2, y2
    )


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", ["dda", "basic"])
@settings(max_examples=100, deadline=None)  # was 400: see the module's note
@given(x1=frac, y1=frac, x2=frac, y2=frac)
@example(x1=Fraction(1, 2), y1=Fraction(1, 2), x2=Fraction(1, 2), y2=Fraction(1, 2))
@example(x1=Fraction(0), y1=Fraction(0), x2=Fraction(3, 2), y2=Fraction(4))
def test_fractional_line_matches_generator(algo, x1, y1, x2, y2):
    assert as_pixels(raster.line(x1, y1, x2, y2, algo=algo)) == generator_pixels(
        algo, x1, y1, x2, y2
    )


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", raster.LINE_ALGORITHMS)
@pytest.mark.parametrize(
    "end",
    [(70_001, 23_456), (-70_001, 23_456), (23_456, -70_001), (-31_337, -70_001)],
    ids=["E", "W", "S", "SW-steep"],
)
def test_long_line_crosses_blocks(algo, end):
    assert abs(end[0]) > 2 * raster.BLOCK or abs(end[1]) > 2 * raster.BLOCK
    got = as_pixels(raster.line(-5, 7, end[0], end[1], algo=algo))
    assert got == generator_pixels(algo, -5, 7, *end)


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=100, deadline=None)
@given(x1=st.integers(-500, 500), y1=st.integers(-500, 500), dx=st.integers(0, 500), dy=short)
def test_bresenham_equals_skimage_when_walking_the_same_way(x1, y1, dx, dy):
    """skimage.draw.line walks from its first point; ours from the smaller major coordinate."""
    draw = pytest.importorskip("skimage.draw")
    if abs(dy) > dx:  # steep: walk upward, as scanconv does
        x2, y2 = x1 + (dx if dy > 0 else -dx), y1 + abs(dy)
    else:
        x2, y2 = x1 + dx, y1 + dy
    rr, cc = draw.line(y1, x1, y2, x2)
    xs, ys = raster.line(x1, y1, x2, y2)
    assert np.array_equal(xs, cc) and np.array_equal(ys, rr)


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", ["bresenham", "dda"])
@settings(max_examples=100, deadline=None)
@given(x1=short, y1=short, x2=short, y2=short)
def test_parallel_line_matches_generator(algo, x1, y1, x2, y2):
    """With the threshold lowered to one pixel, every line takes the two-thread path."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(raster, "PARALLEL_MIN", 1)
        got = as_pixels(raster.line(x1, y1, x2, y2, algo=algo))
    assert got == generator_pixels(algo, x1, y1, x2, y2)


@pytest.mark.parametrize("algo", ["bresenham", "dda"])
def test_long_line_is_the_same_on_one_thread_or_two(algo):
    n = raster.PARALLEL_MIN + 12_345
    one = raster.line(7, -3, 7 - 987_654, -3 - n + 1, algo=algo, parallel=False)
    two = raster.line(7, -3, 7 - 987_654, -3 - n + 1, algo=algo)
    assert len(one[0]) == n
    assert all(np.array_equal(a, b) for a, b in zip(one, two, strict=True))
    ends = {(int(one[0][i]), int(one[1][i])) for i in (0, -1)}
    assert ends == {(7, -3), (7 - 987_654, -3 - n + 1)}


def test_parallel_line_hands_a_worker_error_to_the_caller(monkeypatch):
    """The second thread's exception is raised in the caller, after the caller's own half."""
    real = raster._floor_affine
    calls = []

    def fails_on_the_worker(*args, **kwargs):
        calls.append(threading.current_thread().name)
        if threading.current_thread() is not threading.main_thread():
            raise MemoryError("no room")
        return real(*args, **kwargs)

    monkeypatch.setattr(raster, "PARALLEL_MIN", 1)
    monkeypatch.setattr(raster, "_floor_affine", fails_on_the_worker)
    with pytest.raises(MemoryError, match="no room"):
        raster.line(0, 0, 5, 3)
    assert sorted(calls) == ["MainThread", "scanconv-raster"]


def test_line_rejects_bad_input():
    with pytest.raises(ValueError, match="x1 must be an integer"):
        raster.line(Fraction(1, 2), 0, 4, 4)
    with pytest.raises(ValueError, match="out of range"):
        raster.line(0, 0, 10**9 + 1, 0)
    with pytest.raises(ValueError, match="unknown line algorithm 'wu'"):
        raster.line(0, 0, 1, 1, algo="wu")
    with pytest.raises(TypeError, match="int or a Fraction, got float"):
        raster.line(0.5, 0, 1, 1, algo="dda")


def test_line_accepts_numpy_integers():
    got = raster.line(np.int64(2), np.int32(2), np.int16(10), np.uint8(6))
    assert as_pixels(got) == generator_pixels("bresenham", 2, 2, 10, 6)


# --- the exact integer helper -----------------------------------------------------------------


def _expected(alpha: Fraction, beta: Fraction, n: int, offset: int, sign: int) -> list[int]:
    return [offset + sign * math.floor(alpha + beta * k) for k in range(n)]


@settings(max_examples=100, deadline=None)  # was 600: see the module's note
@given(
    num=st.integers(-(10**30), 10**30),
    den=st.one_of(st.integers(1, 1000), st.integers(1, 10**20)),
    bnum=st.integers(-(10**20), 10**20),
    bden=st.one_of(st.integers(1, 1000), st.integers(1, 10**20)),
    n=st.integers(1, 300),
    offset=st.integers(-(10**9), 10**9),
    sign=st.sampled_from([1, -1]),
)
def test_floor_affine_is_exact(num, den, bnum, bden, n, offset, sign):
    alpha, beta = Fraction(num, den), Fraction(bnum, bden) % 3 - Fraction(3, 2)
    expected = _expected(alpha, beta, n, offset, sign)
    if any(abs(v) >= 2**62 for v in expected):
        return  # results themselves beyond int64 are out of scope
    got = raster._floor_affine(alpha, beta, n, offset=offset, sign=sign)
    assert got.dtype == np.int64 and got.tolist() == expected


def _numerators(alpha: Fraction, beta: Fraction, sign: int, offset: int) -> tuple[int, int, int]:
    """``(a, b, c)`` with ``offset + sign floor(alpha + beta k) = floor((a + b k) / c)``."""
    c = math.lcm(alpha.denominator, beta.denominator)
    a = offset * c + sign * alpha.numerator * (c // alpha.denominator) + (c - 1 if sign < 0 else 0)
    return a, sign * beta.numerator * (c // beta.denominator), c


@settings(max_examples=40, deadline=None)
@given(
    c=st.integers(2**20, 2**40),
    a=st.integers(-(10**15), 10**15),
    share=st.floats(0.5, 1),
    sign=st.sampled_from([1, -1]),
)
def test_floor_affine_fixed_point_at_its_limit(c, a, share, sign):
    """A whole block whose scaled sums come within a factor of two of int64's limit."""
    k = raster._scale_bits(c)
    top = (2**63 >> k) // raster.BLOCK - 1  # the largest |b| // c + 1 that still fits
    b = sign * max(1, int(share * top) - 1) * c + sign * (c // 3)
    n = raster.BLOCK + 3
    assert raster._affine_path(a, b, c, n).startswith("fixed")
    got = raster._floor_affine(Fraction(a, c), Fraction(b, c), n)
    assert got.tolist() == [(a + b * k) // c for k in range(n)]


@pytest.mark.parametrize(
    ("alpha", "beta", "n", "path"),
    [
        (Fraction(1, 2), Fraction(3141, 9999), 3 * raster.BLOCK + 17, "fixed"),
        (Fraction(10**18 + 1, 2), Fraction(-7, 3), 2 * raster.BLOCK + 5, "fixed+q"),
        (Fraction(1, 3), Fraction(7, 10**13 + 1), 2 * raster.BLOCK + 5, "int64"),
        (Fraction(5, 10**17 + 3), Fraction(1, 10**16 + 1), 2000, "object"),
        (Fraction(-7), Fraction(-1), 2 * raster.BLOCK, "arange"),
        (Fraction(9, 4), Fraction(0), 5, "constant"),
    ],
    ids=["fixed", "fixed+q", "int64", "object", "arange", "constant"],
)
@pytest.mark.parametrize("sign", [1, -1])
def test_floor_affine_every_path(alpha, beta, n, path, sign):
    offset = 123
    a, b, c = _numerators(alpha, beta, sign, offset)
    assert raster._affine_path(a, b, c, n) == path
    got = raster._floor_affine(alpha, beta, n, offset=offset, sign=sign).tolist()
    # every value against the same floor in Python's integers (a hundred times faster than
    # Fractions over these 100,000 values), and that integer form against the
    # Fraction definition at both ends and on each side of every block boundary
    assert got == [(a + b * k) // c for k in range(n)]
    seams = {j + d for j in range(0, n + 1, raster.BLOCK) for d in (-2, -1, 0, 1)}
    for k in sorted(i for i in seams | {0, 1, n - 2, n - 1} if 0 <= i < n):
        assert got[k] == offset + sign * math.floor(alpha + beta * k), k


# --- circles ----------------------------------------------------------------------------------


def test_circle_every_small_radius():
    for r in range(200):
        for centre in ((0, 0), (-3, 7)):
            expected = list(circle_solution("midpoint", r, *centre).pixels())
            assert as_pixels(raster_conic.circle(r, *centre)) == expected, (r, centre)


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=100, deadline=None)
@given(r=st.integers(0, 1500), xc=st.integers(-(10**9), 10**9), yc=st.integers(-(10**9), 10**9))
def test_circle_matches_both_generators(r, xc, yc):
    got = as_pixels(raster_conic.circle(r, xc, yc))
    assert got == list(circle_solution("midpoint", r, xc, yc).pixels())
    assert got == list(circle_solution("bresenham", r, xc, yc).pixels())


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=100, deadline=None)
@given(r=st.integers(0, 3000), xc=st.integers(-500, 500), yc=st.integers(-500, 500))
def test_circle_pixel_set_equals_skimage_bresenham(r, xc, yc):
    draw = pytest.importorskip("skimage.draw")
    rr, cc = draw.circle_perimeter(yc, xc, r, method="bresenham")
    assert set(as_pixels(raster_conic.circle(r, xc, yc))) == set(
        zip(cc.tolist(), rr.tolist(), strict=True)
    )


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("r", [98_765, 123_457])
def test_circle_large_radius(r):
    assert as_pixels(raster_conic.circle(r, 5, -5)) == list(
        circle_solution("midpoint", r, 5, -5).pixels()
    )


def test_circle_rejects_bad_input():
    with pytest.raises(ValueError, match="radius must be a non-negative integer"):
        raster_conic.circle(-1)
    with pytest.raises(ValueError, match="radius must be an integer"):
        raster_conic.circle(Fraction(5, 2))
    with pytest.raises(ValueError, match="out of range"):
        raster_conic.circle(5, 10**9 + 1, 0)


# --- ellipses ---------------------------------------------------------------------------------


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
def test_ellipse_every_small_pair_of_semi_axes():
    # The step generator's quadrant and its images, as Solution.pixels() yields them
    # (scanconv/answers/primitives/ellipse.py), without the worked answer that costs ten times the pixels
    # on these small ellipses; the property below compares the Solution itself.
    for rx in range(40):
        for ry in range(40):
            expected = list(symmetric_pixels(quadrant_points(rx, ry), 2, -3))
            assert as_pixels(raster_conic.ellipse(rx, ry, 2, -3)) == expected, (rx, ry)


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=100, deadline=None)
@given(
    rx=st.integers(0, 1200),
    ry=st.integers(0, 1200),
    xc=st.integers(-(10**9), 10**9),
    yc=st.integers(-(10**9), 10**9),
)
@example(rx=10, ry=1, xc=0, yc=0)  # flat: region 1 reaches y = 0 before the tip
@example(rx=1, ry=10, xc=0, yc=0)
@example(rx=7, ry=7, xc=0, yc=0)  # rx = ry
@example(rx=0, ry=5, xc=1, yc=1)  # a segment on the y axis
@example(rx=5, ry=0, xc=1, yc=1)  # a segment on the x axis
def test_ellipse_matches_generator(rx, ry, xc, yc):
    got = as_pixels(raster_conic.ellipse(rx, ry, xc, yc))
    assert got == list(ellipse_solution(rx, ry, xc, yc).pixels())


@pytest.mark.parametrize(("rx", "ry"), [(0, 0), (0, 5), (5, 0), (1, 10), (10, 1)])
def test_ellipse_on_or_near_an_axis_matches_generator(rx, ry):
    """The degenerate cases of the property above, traced (it is not: tracing its long walks
    tripled their CPU), so that coverage sees the closed form's special cases."""
    got = as_pixels(raster_conic.ellipse(rx, ry, 1, -1))
    assert got == list(ellipse_solution(rx, ry, 1, -1).pixels())


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=60, deadline=None)
@given(rx=st.integers(1, 5_000), ry=st.integers(1, 25))
def test_flat_ellipse_matches_generator(rx, ry):
    for a, b in ((rx, ry), (ry, rx)):
        assert as_pixels(raster_conic.ellipse(a, b)) == list(ellipse_solution(a, b).pixels())


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
def test_ellipse_large_semi_axes():
    got = as_pixels(raster_conic.ellipse(100_003, 60_001, -7, 9))
    assert got == list(ellipse_solution(100_003, 60_001, -7, 9).pixels())


# --- the exact count behind both ---------------------------------------------------------------


def _odd_count(d: int, p: int, q: int, strict: bool) -> int:
    """Reference: odd t >= 1 with (q t)**2 < 4 p**2 d (or <=), in exact integers."""
    v = 4 * p * p * max(d, 0)
    if strict and v == 0:
        return 0
    top = (math.isqrt(v - 1) if strict else math.isqrt(v)) // q
    return (top + 1) // 2


@settings(max_examples=100, deadline=None)  # was 500: see the module's note
@given(
    p=st.integers(0, 10**9),
    q=st.integers(1, 10**9),
    s=st.integers(0, 10**5),
    t=st.integers(0, 10**4).map(lambda n: 2 * n + 1),
    nudge=st.sampled_from([-1, 0, 1]),
    strict=st.booleans(),
)
def test_odd_below_is_exact_at_and_next_to_ties(p, q, s, t, nudge, strict):
    """d chosen so that 2p·sqrt(d)/q is exactly the odd number t (q = 2p s), then nudged."""
    q = max(1, 2 * p * s) if s else q
    d = min((s * t) ** 2 + nudge, 10**18) if s else min(t * t * q + nudge, 10**18)
    got = raster_conic._odd_below(np.array([d], dtype=np.int64), p, q, strict=strict)
    assert got.tolist() == [_odd_count(d, p, q, strict)]


@settings(max_examples=100, deadline=None)
@given(
    d=st.lists(st.integers(-5, 10**18), min_size=1, max_size=50),
    p=st.integers(0, 10**9),
    q=st.integers(1, 10**9),
    strict=st.booleans(),
)
@example(d=[19_083_147_054_427_484], p=73_830_124, q=1, strict=False)  # a count past 2**53
def test_odd_below_is_exact(d, p, q, strict):
    got = raster_conic._odd_below(np.array(d, dtype=np.int64), p, q, strict=strict)
    assert got.tolist() == [_odd_count(v, p, q, strict) for v in d]
