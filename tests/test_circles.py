"""Property tests for the circle methods, checked against definitions written out here.

The independent references: the midpoint circle as "in each column of the first octant, the
pixel nearest the circle" found by brute-force search over integer pixels, with exact integer
comparisons; ``skimage.draw.circle_perimeter(method="bresenham")``; the symmetric DDA's exact
recurrence and its conserved quantity; and the pixel order spelled out with a full set.
"""

from __future__ import annotations

import math
import subprocess
import sys
from collections import deque
from fractions import Fraction
from itertools import islice, pairwise

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.circles import (
    FLOAT_METHODS,
    METHODS,
    SDDA_MAX_RADIUS,
    bresenham,
    midpoint,
    polynomial,
    symmetric_dda,
    symmetric_pixels,
    trig,
    trig_steps,
)
from scanconv.answers.primitives.circle import circle_solution

from .helpers import assert_refused, run, run_process

VARIANTS = [(m, "half-up") for m in METHODS] + [(m, "trunc") for m in FLOAT_METHODS]
radius = st.integers(min_value=0, max_value=400)
centre = st.integers(min_value=-50, max_value=50)

Pixel = tuple[int, int]


def octant(method: str, r: int, rounding: str = "half-up") -> list[Pixel]:
    """The octant points in plotting order, taken from the step records."""
    sol = circle_solution(method, r, rounding=rounding)
    pts = [s.pixel for s in sol.steps()]
    return [(0, r), *pts] if method == "midpoint" else pts


def pixel_list(method: str, r: int, xc: int = 0, yc: int = 0, rounding: str = "half-up"):
    sol = circle_solution(method, r, xc, yc, rounding)
    assert sol.pixels is not None
    return list(sol.pixels())


def eight(x: int, y: int) -> list[Pixel]:
    return [(x, y), (-x, y), (x, -y), (-x, -y), (y, x), (-y, x), (y, -x), (-y, -x)]


def brute_midpoint(r: int) -> set[Pixel]:
    """For each column x of the first octant, the y with (y - 1/2)² < r² - x² < (y + 1/2)²,
    found by scanning every y (no square roots, no recurrence), mirrored 8 ways."""
    out: set[Pixel] = set()
    for x in range(r + 1):
        n4 = 4 * (r * r - x * x)
        ys = [y for y in range(r + 1) if (2 * y - 1) ** 2 < n4 < (2 * y + 1) ** 2 or n4 == 0 == y]
        assert len(ys) == 1
        if x <= ys[0]:
            for p in eight(x, ys[0]):
                out.add(p)
    return out


def nearest_rows(r: int) -> set[Pixel]:
    """The same definition with integer square roots, for larger radii."""
    out: set[Pixel] = set()
    for x in range(r + 1):
        y = (math.isqrt(4 * (r * r - x * x)) + 1) // 2  # floor(sqrt(r² - x²) + 1/2)
        if x <= y:
            out.update(eight(x, y))
    return out


def one_piece(pixels: list[Pixel]) -> bool:
    """The pixels form one 8-connected piece: scipy's labelling of them as an image (in C; the
    breadth-first search of :func:`tests.helpers.connected` in Python took most of the CPU of
    the sweep below)."""
    ndimage = pytest.importorskip("scipy.ndimage")
    xs, ys = (np.array(v) for v in zip(*pixels, strict=True))
    image = np.zeros((xs.max() - xs.min() + 1, ys.max() - ys.min() + 1), dtype=bool)
    image[xs - xs.min(), ys - ys.min()] = True
    _, pieces = ndimage.label(image, structure=np.ones((3, 3), dtype=int))
    return pieces == 1


def touches_circle(p: Pixel, r: int, h: Fraction = Fraction(1)) -> bool:
    """The circle passes through the square of half-side ``h`` around ``p`` (exact integers)."""
    hn, hd = h.numerator, h.denominator
    lo = [max(0, hd * abs(c) - hn) for c in p]  # the square's nearest |coordinates|, times hd
    hi = [hd * abs(c) + hn for c in p]
    return lo[0] ** 2 + lo[1] ** 2 <= (hd * r) ** 2 <= hi[0] ** 2 + hi[1] ** 2


# --- octant walk ---------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize(("method", "rounding"), VARIANTS)
@given(r=radius)
@settings(deadline=None)
def test_octant_starts_at_top_and_is_an_8_connected_monotone_walk(method, rounding, r):
    pts = octant(method, r, rounding)
    assert pts[0] == (0, r)
    for (x0, y0), (x1, y1) in pairwise(pts):
        assert max(abs(x1 - x0), abs(y1 - y0)) <= 1
        assert x1 >= x0 and y1 <= y0  # what the duplicate-free pixel order relies on
    # every point but the midpoint's last (which may cross by one) lies in the first octant
    assert all(x <= y for x, y in pts[:-1]) and pts[-1][0] <= pts[-1][1] + 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize(("method", "rounding"), VARIANTS)
@given(r=radius, xc=centre, yc=centre)
@settings(deadline=None)
def test_pixels_are_symmetric_about_the_centre_and_unique(method, rounding, r, xc, yc):
    px = pixel_list(method, r, xc, yc, rounding)
    assert len(px) == len(set(px))
    rel = {(x - xc, y - yc) for x, y in px}
    for x, y in rel:
        assert set(eight(x, y)) <= rel
    sol = circle_solution(method, r, xc, yc, rounding)
    xs, ys = [p[0] for p in px], [p[1] for p in px]
    assert (min(xs), min(ys), max(xs), max(ys)) == sol.bbox


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@pytest.mark.parametrize(("method", "rounding"), VARIANTS)
def test_the_whole_circle_is_closed_without_gaps(method, rounding):
    """Including at 45°, where an octant that stops short leaves its mirror image 2 away."""
    for r in range(0, 260):
        assert one_piece(pixel_list(method, r, rounding=rounding)), r


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize(("method", "rounding"), VARIANTS)
@given(r=st.integers(min_value=0, max_value=3000))
@settings(deadline=None, max_examples=50)
def test_every_pixel_is_within_one_pixel_of_the_circle(method, rounding, r):
    # The symmetric DDA follows the ellipse x² + y² + εxy = r², up to rε/4 < 1/4 inside the
    # circle near the diagonal; truncating can then land up to 1 + 1/4 away (r = 42: the point
    # (22.952, 34.995), 0.15 inside, truncates to (22, 34), 1.5 inside the circle).
    h = Fraction(5, 4) if (method, rounding) == ("symmetric-dda", "trunc") else Fraction(1)
    sol = circle_solution(method, r, rounding=rounding)
    for p in islice(sol.pixels(), 4000):
        assert touches_circle(p, r, h), p


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("method", ["midpoint", "bresenham", "polynomial"])
@given(r=st.integers(min_value=0, max_value=3000))
@settings(deadline=None, max_examples=50)
def test_nearest_pixel_methods_are_within_half_a_pixel_radially(method, r):
    # (r - 1/2)² < x² + y² < (r + 1/2)², in integers
    for x, y in octant(method, r):
        assert max(0, 2 * r - 1) ** 2 <= 4 * (x * x + y * y) <= (2 * r + 1) ** 2


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow  # about a second of CPU
def test_pixel_order_is_the_documented_one():
    """Rebuilt with a full set: each octant point's 8 images in order, first occurrence only."""
    for method, rounding in VARIANTS:
        for r in range(0, 60):
            for xc, yc in ((0, 0), (7, -3)):
                expected: list[Pixel] = []
                seen: set[Pixel] = set()
                for x, y in octant(method, r, rounding):
                    for dx, dy in eight(x, y):
                        p = (xc + dx, yc + dy)
                        if p not in seen:
                            seen.add(p)
                            expected.append(p)
                assert pixel_list(method, r, xc, yc, rounding) == expected, (method, r)


# --- midpoint against independent definitions -------------------------------------------------


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@pytest.mark.parametrize("r", range(0, 201))
def test_midpoint_equals_bresenham_and_the_nearest_pixel_definition(r):
    mid = set(pixel_list("midpoint", r))
    assert mid == set(pixel_list("bresenham", r))
    assert mid == (brute_midpoint(r) if r <= 60 else nearest_rows(r))
    assert mid == set(pixel_list("polynomial", r))  # column rounding, octant closed at 45°


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@given(r=st.integers(min_value=200, max_value=5000))
@settings(deadline=None, max_examples=60)
def test_midpoint_equals_bresenham_for_large_radii(r):
    mid = set(pixel_list("midpoint", r))
    assert mid == set(pixel_list("bresenham", r)) == nearest_rows(r)


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@given(r=st.integers(min_value=0, max_value=2000))
@settings(deadline=None, max_examples=80)
def test_midpoint_equals_skimage_bresenham(r):
    draw = pytest.importorskip("skimage.draw")
    rr, cc = draw.circle_perimeter(0, 0, r, method="bresenham")
    theirs = {(int(c), int(row)) for row, c in zip(rr, cc, strict=True)}
    assert set(pixel_list("midpoint", r)) == theirs


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_midpoint_decision_parameter_is_the_midpoint_residual():
    # p_k = f(x_k + 1, y_k - 1/2) - 1/4 with f = x² + y² - r² (Hearn & Baker's integer form)
    for r in range(0, 150):
        x, y = 0, r
        for s in midpoint(r):
            assert s.p == (x + 1) ** 2 + Fraction(2 * y - 1, 2) ** 2 - r * r - Fraction(1, 4)
            assert s.extra == (2 * s.pixel[0], 2 * s.pixel[1])
            x, y = s.pixel


def test_bresenham_d_is_the_sum_of_the_two_candidates_residuals():
    for r in range(0, 150):
        for s in bresenham(r):
            x, y = s.pixel
            assert s.p == (x + 1) ** 2 * 2 + y * y + (y - 1) ** 2 - 2 * r * r


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_bresenham_d_is_twice_the_midpoint_p_plus_one():
    for r in range(0, 300):
        pairs = list(zip(bresenham(r), midpoint(r), strict=False))
        assert all(b.p == 2 * m.p + 1 and b.decision == m.decision for b, m in pairs)


def test_hearn_and_baker_r10_table():
    """Hearn & Baker, midpoint circle example (r = 10): the published table."""
    rows = [(s.k, s.p, s.pixel, *s.extra) for s in midpoint(10)]
    assert rows == [
        (0, -9, (1, 10), 2, 20),
        (1, -6, (2, 10), 4, 20),
        (2, -1, (3, 10), 6, 20),
        (3, 6, (4, 9), 8, 18),
        (4, -3, (5, 9), 10, 18),
        (5, 8, (6, 8), 12, 16),
        (6, 5, (7, 7), 14, 14),
    ]


# --- the floating-point methods ---------------------------------------------------------------


def check_polynomial_step(s, r: int, rounding: str) -> None:
    x, (y6, ry) = s.k, s.extra
    n = r * r - x * x
    assert y6 * y6 <= n < (y6 + Fraction(1, 10**6)) ** 2  # sqrt(n) truncated to 6 decimals
    want = (math.isqrt(4 * n) + 1) // 2 if rounding == "half-up" else math.isqrt(n)
    assert s.pixel == (x, want) and ry == want


@given(r=st.integers(min_value=0, max_value=10**9))
def test_polynomial_rounds_the_true_square_root(r):
    for rounding in ("half-up", "trunc"):
        for s in islice(polynomial(r, rounding), 3):
            check_polynomial_step(s, r, rounding)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("rounding", ["half-up", "trunc"])
def test_polynomial_whole_octant(rounding):
    for r in range(0, 300):
        steps = list(polynomial(r, rounding))
        assert [s.k for s in steps] == list(range(len(steps)))
        for s in steps:
            check_polynomial_step(s, r, rounding)
            assert s.pixel[0] <= s.pixel[1]
        x = len(steps)  # the first x not plotted: its rounded y is below the diagonal
        n = r * r - x * x
        assert (
            n < 0 or ((math.isqrt(4 * n) + 1) // 2 if rounding == "half-up" else math.isqrt(n)) < x
        )
        sol = circle_solution("polynomial", r, rounding=rounding)
        assert sol.derived[1].value == x - 1  # the working names the last x


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(r=st.integers(min_value=1, max_value=3000))
@settings(deadline=None, max_examples=50)
def test_trig_follows_cos_and_sin(r):
    def point(k: int) -> tuple[int, int]:
        t = math.pi / 2 - k / r
        return math.floor(r * math.cos(t) + 0.5), math.floor(r * math.sin(t) + 0.5)

    steps = list(trig(r))
    # every θ >= 45°, and at most one more row whose point is still on the diagonal
    assert len(steps) - 1 in (math.floor(math.pi * r / 4), math.floor(math.pi * r / 4) + 1)
    nxt = point(len(steps))
    assert nxt[0] > nxt[1]
    for s in steps:
        deg, rad, x, y = s.extra
        assert math.isclose(rad, math.pi / 2 - s.k / r, abs_tol=1e-12)
        assert math.isclose(deg, math.degrees(rad), abs_tol=1e-9)
        assert math.isclose(x, r * math.cos(rad), abs_tol=1e-9)
        assert math.isclose(y, r * math.sin(rad), abs_tol=1e-9)
        assert s.pixel == point(s.k) and s.pixel[0] <= s.pixel[1]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_trig_step_count_is_exact():
    for r in range(1, 20000):
        v = math.pi * r / 4
        assert abs(v - round(v)) > 1e-9  # far enough from an integer for floats to decide
        assert trig_steps(r) == math.floor(v)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_symmetric_dda_is_the_exact_recurrence():
    for r in range(1, 70):
        n = max(k for k in range(1, 12) if 2 ** (k - 1) <= r)
        assert 2 ** (n - 1) <= r < 2**n
        eps = Fraction(1, 2**n)
        x, y = Fraction(0), Fraction(r)
        got = list(symmetric_dda(r))
        half = Fraction(1, 2)
        for s in got:
            assert s.extra == (x, y)
            assert s.pixel == (math.floor(x + half), math.floor(y + half))
            assert s.pixel[0] <= s.pixel[1]
            # the symmetric DDA conserves x² + y² + ε x y, so the points stay on one ellipse
            assert x * x + y * y + eps * x * y == r * r
            x = x + eps * y
            y = y - eps * x
        assert math.floor(x + half) > math.floor(y + half)  # stopped at the first point past 45°


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow  # about a second of CPU
def test_symmetric_dda_trunc_and_largest_radius():
    for s in symmetric_dda(37, "trunc"):
        assert s.pixel == (math.floor(s.extra[0]), math.floor(s.extra[1]))
    last = deque(symmetric_dda(SDDA_MAX_RADIUS), maxlen=1).pop()
    assert last.extra[0] <= last.extra[1]
    with pytest.raises(ValueError, match="at most"):
        circle_solution("symmetric-dda", SDDA_MAX_RADIUS + 1)


@pytest.mark.parametrize(("method", "rounding"), VARIANTS)
def test_radius_zero_plots_the_centre_only(method, rounding):
    assert pixel_list(method, 0, 3, -4, rounding) == [(3, -4)]


# --- library and CLI errors -------------------------------------------------------------------


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("midpoint", -1), "non-negative integer"),
        (("midpoint", Fraction(5, 2)), "must be an integer"),
        (("midpoint", 5, Fraction(1, 2)), "xc must be an integer"),
        (("wu", 5), "unknown circle method"),
        (("trig", 5, 0, 0, "even"), "unknown rounding"),
        (("midpoint", 5, 0, 0, "trunc"), "a rounding rule applies only to"),
        (("midpoint", 10**10), "out of range"),
    ],
)
def test_library_errors_name_the_rule(args, message):
    with pytest.raises(ValueError, match=message):
        circle_solution(*args)


BAD = [
    (["circle", "-5"], "non-negative integer"),
    (["circle", "2.5"], "radius must be an integer"),
    (["circle", "5", "--method", "wu"], "'wu' is not one of"),
    (["circle", "5", "--center", "1"], "requires 2 arguments"),
    (["circle", "5", "--center", "1", "2", "3"], "unexpected extra argument"),
    (["circle", "5", "--center", "1.5", "2"], "xc must be an integer"),
    (["circle", "5", "--center", "x", "2"], "not a number"),
    (["circle", "5", "--rounding", "trunc"], "--rounding: a rounding rule applies only to"),
    (["circle", "5", "--rounding", "even", "-m", "trig"], "'even' is not one of"),
    (["circle", "20000", "-m", "symmetric-dda"], "at most 16383"),
    (["circle", "nan"], "not a finite number"),
    (["circle"], "Missing argument"),
    (["ellipse", "8"], "Missing argument"),
    (["ellipse", "8", "-6"], "ry must be a non-negative integer"),
    (["ellipse", "8", "6.5"], "ry must be an integer"),
    (["ellipse", "8", "6", "--center", "0"], "requires 2 arguments"),
]


@pytest.mark.parametrize(("args", "message"), BAD, ids=[" ".join(a) for a, _ in BAD])
def test_bad_input_is_one_line_exit_2(args, message):
    assert_refused(run(*args), message)


def test_general_is_the_notes_method_and_options_are_case_insensitive():
    a = run("circle", "6", "-m", "GENERAL", "-f", "json")
    b = run("circle", "6", "--method", "POLYNOMIAL", "-f", "json")
    assert a.code == b.code == 0 and a.out != b.out
    assert '"algorithm": "general"' in a.out and '"algorithm": "polynomial"' in b.out
    c = run("circle", "6", "-m", "Trig", "--rounding", "TRUNC", "-f", "csv")
    assert c.code == 0 and c.out.startswith("k,x,y,theta_deg")


def test_negative_centre_is_an_option_value():
    r = run("circle", "3", "--center", "-4", "-5", "-f", "csv")
    assert r.code == 0, r.err
    px = pixel_list("midpoint", 3, -4, -5)
    assert (-4, -2) in px and (-7, -5) in px


def test_grid_too_large_is_noted_and_the_table_still_printed():
    r = run("circle", "60", "-f", "markdown")
    assert r.code == 0
    assert "grid left out" in r.err and r.err.count("\n") == 1
    assert "(1, 60)" in r.out and "(-60, 0)" in r.out and "```text" not in r.out


@pytest.mark.slow
def test_a_huge_radius_streams_its_table():
    """r = 10^6 has 707,107 rows: the first ones arrive at once, nothing is built up first."""
    sol = circle_solution("midpoint", 10**6)
    assert [s.p for s in islice(sol.steps(), 3)] == [1 - 10**6, 1 - 10**6 + 3, 1 - 10**6 + 8]
    proc = subprocess.Popen(
        [sys.executable, "-m", "scanconv", "circle", "1000000", "-f", "csv"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stdout is not None
    head = [proc.stdout.readline() for _ in range(3)]
    proc.kill()
    proc.communicate(timeout=60)
    assert head == [
        "k,p,decision,plot_x,plot_y,x_k,y_k\n",
        "0,-999999,E,0,1000000,0,1000000\n",
        head[2],
    ]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_every_format_renders_a_circle_and_an_ellipse():
    for fmt in ("markdown", "plain", "latex", "csv", "json", "rich"):
        for args in (("circle", "4", "-m", "trig"), ("ellipse", "5", "3")):
            r = run(*args, "-f", fmt)
            assert r.code == 0 and r.err == "" and r.out, (args, fmt)
            if fmt == "plain":
                assert r.out.isascii()


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_real_process_error():
    r = run_process("circle", "-3")
    assert r.code == 2 and r.out == "" and "non-negative" in r.err


# --- the README's comparison table ------------------------------------------------------------

README_RADII = (5, 10)
README_MARK = "<!-- circle-methods-table: generated by `python -m tests.test_circles` -->"


def readme_table() -> str:
    """The README's table of every method's pixels for r = 5 and r = 10, from the code."""
    head = "| method | rounding |" + "".join(
        f" octant points, r = {r} | pixels | vs. midpoint |" for r in README_RADII
    )
    lines = [head, "|---|---|" + "---|---|---|" * len(README_RADII)]
    ref = {r: set(pixel_list("midpoint", r)) for r in README_RADII}
    for method, rounding in sorted(VARIANTS, key=lambda v: (METHODS.index(v[0]), v[1])):
        cells = [f"`{method}`", rounding if method in FLOAT_METHODS else "-"]
        for r in README_RADII:
            pts: list[Pixel] = []
            for p in octant(method, r, rounding):
                if not pts or pts[-1] != p:
                    pts.append(p)
            px = set(pixel_list(method, r, rounding=rounding))
            extra, missing = len(px - ref[r]), len(ref[r] - px)
            same = "same" if not extra and not missing else f"+{extra} / -{missing}"
            cells += [" ".join(f"({x},{y})" for x, y in pts), str(len(px)), same]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_readme_method_table_is_the_codes_output():
    """The circle-methods table in docs/guide.md is this code's output (regenerate it with
    ``python -m tests.test_circles``)."""
    from pathlib import Path

    readme = (Path(__file__).resolve().parent.parent / "docs" / "guide.md").read_text(
        encoding="utf-8"
    )
    assert README_MARK in readme
    block = readme.split(README_MARK, 1)[1].strip().split("\n\n", 1)[0]
    assert block == readme_table()


if __name__ == "__main__":
    print(README_MARK)
    print(readme_table())


class _NoPrivateConstructor(Fraction):
    """A Fraction whose constructor has neither private fast path (a future Python, say)."""

    def __new__(cls, numerator=0, denominator=None):
        return super().__new__(cls, numerator, denominator)


class _OnlyFromCoprime(Fraction):
    @classmethod
    def _from_coprime_ints(cls, numerator, denominator):
        return super().__new__(cls, numerator, denominator)


@pytest.mark.parametrize("cls", [Fraction, _NoPrivateConstructor, _OnlyFromCoprime])
def test_coprime_constructor_gives_the_value_on_every_python(cls):
    from scanconv.algorithms.circles import coprime_constructor

    make = coprime_constructor(cls)
    for num, den in [(3, 4), (-7, 16), (0, 1), (5, 1), (2**70 + 1, 2**71)]:
        value = make(num, den)
        assert (value.numerator, value.denominator) == (num, den)
        assert value == Fraction(num, den)


@pytest.mark.parametrize(
    ("walk", "pixels"),
    [
        # a point on an axis has 4 distinct images, each once: (3, 0) and its mirror (0, 3)
        ([(3, 0)], [(3, 0), (-3, 0), (0, 3), (0, -3)]),
        ([(0, 3)], [(0, 3), (0, -3), (3, 0), (-3, 0)]),
        # on the diagonal too: (2, 2)
        ([(2, 2)], [(2, 2), (-2, 2), (2, -2), (-2, -2)]),
        # off the axes and the diagonal, all 8
        ([(1, 3)], [(1, 3), (-1, 3), (1, -3), (-1, -3), (3, 1), (-3, 1), (3, -1), (-3, -1)]),
    ],
)
def test_symmetric_pixels_yields_each_image_once(walk, pixels):
    assert list(symmetric_pixels(walk)) == pixels
