"""Property tests for the three line algorithms, in all octants.

The checks are independent of the implementation: they compare against the ideal line
computed here with exact fractions, and against the textbook definition of p_k.
"""

from __future__ import annotations

import itertools
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.lines import basic, bresenham, dda
from scanconv.algorithms.midpoint_line import midpoint_line
from scanconv.answers.methods import methods_of
from scanconv.answers.primitives.line import line_solution
from scanconv.core.numeric import round_half_up
from scanconv.core.records import Move

coord = st.integers(min_value=-60, max_value=60)
lines = st.tuples(coord, coord, coord, coord)
NOT_ONE_PIXEL_A_STEP = {
    "wu": "anti-aliased: two pixels a column, each with an intensity",
    "symmetric-dda": "2^n steps of ε Δ, both coordinates rounded: a step can move the minor "
    "coordinate alone (a corner, a pixel off the major-step line) and points repeat a pixel "
    "(tests/test_lines_symmetric_dda.py checks it against its own definition)",
}
"""The line methods the pixel properties below do not hold for, and why."""
ALGOS = tuple(m for m in methods_of("line") if m not in NOT_ONE_PIXEL_A_STEP)
"""Every line method of the records that plots one pixel a step (a new one is walked at once)."""


def pixels(algo: str, x1: int, y1: int, x2: int, y2: int) -> list[tuple[int, int]]:
    sol = line_solution(algo, x1, y1, x2, y2)
    assert sol.pixels is not None
    return list(sol.pixels())


def major(x1: int, y1: int, x2: int, y2: int) -> int:
    """0 if x is the major axis, 1 if y is (|dy| > |dx|)."""
    return 1 if abs(y2 - y1) > abs(x2 - x1) else 0


def ideal_minor(line: tuple[int, int, int, int], a: int) -> Fraction:
    """The ideal line's minor coordinate at major coordinate ``a``."""
    x1, y1, x2, y2 = line
    if major(*line) == 0:
        return Fraction(y1) if x1 == x2 else y1 + Fraction(y2 - y1, x2 - x1) * (a - x1)
    return x1 + Fraction(x2 - x1, y2 - y1) * (a - y1)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", ALGOS)
@given(line=lines)
def test_both_end_points_plotted(algo, line):
    px = pixels(algo, *line)
    assert (line[0], line[1]) in px and (line[2], line[3]) in px


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", ALGOS)
@given(line=lines)
def test_one_pixel_per_major_step(algo, line):
    px = pixels(algo, *line)
    m = major(*line)
    n = abs(line[2 + m] - line[m])
    assert len(px) == n + 1
    assert sorted(p[m] for p in px) == list(
        range(min(line[m], line[2 + m]), max(line[m], line[2 + m]) + 1)
    )


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", ALGOS)
@given(line=lines)
def test_consecutive_pixels_are_8_connected(algo, line):
    px = pixels(algo, *line)
    for a, b in itertools.pairwise(px):
        assert max(abs(a[0] - b[0]), abs(a[1] - b[1])) == 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("algo", ALGOS)
@given(line=lines)
def test_within_half_a_pixel_of_the_ideal_line(algo, line):
    m = major(*line)
    for p in pixels(algo, *line):
        assert abs(p[1 - m] - ideal_minor(line, p[m])) <= Fraction(1, 2)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(line=lines)
def test_algorithms_agree_except_at_ties(line):
    """basic, dda and bresenham choose the same pixel wherever the ideal line is not half-way."""
    m = major(*line)
    by_major = {algo: {p[m]: p[1 - m] for p in pixels(algo, *line)} for algo in ALGOS}
    for a, b in by_major["basic"].items():
        tie = ideal_minor(line, a).denominator == 2
        if not tie:
            assert by_major["dda"][a] == b
            assert by_major["bresenham"][a] == b
        else:
            assert by_major["dda"][a] == b  # both round half up
            assert by_major["bresenham"][a] in (b, b - 1)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(line=lines)
def test_bresenham_p_is_the_textbook_decision_parameter(line):
    """p_k = Δmajor · (d1 - d2): the distances from the ideal line to the two candidates."""
    x1, y1, x2, y2 = line
    m = major(*line)
    start, end = (x1, y1), (x2, y2)
    if line[2 + m] < line[m]:
        start, end = end, start
    dmaj = end[m] - start[m]
    sign = 1 if end[1 - m] >= start[1 - m] else -1
    prev = start
    for s in bresenham(x1, y1, x2, y2):
        a = prev[m] + 1
        ideal = ideal_minor(line, a)
        d1 = (ideal - prev[1 - m]) * sign  # distance beyond the pixel kept
        d2 = (prev[1 - m] + sign - ideal) * sign  # distance short of the pixel stepped to
        assert s.p == dmaj * (d1 - d2)
        assert (s.p >= 0) == (s.pixel[1 - m] != prev[1 - m])
        prev = s.pixel


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(line=lines)
def test_bresenham_decision_names_the_move(line):
    sol = line_solution("bresenham", *line)
    assert sol.pixels is not None
    px = list(sol.pixels())
    for s, prev in zip(bresenham(*line), px, strict=False):
        assert s.decision is Move.from_delta(s.pixel[0] - prev[0], s.pixel[1] - prev[1])


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(line=lines)
def test_bresenham_integers_only(line):
    for s in bresenham(*line):
        assert type(s.p) is int and type(s.extra[0]) is int


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(line=lines)
def test_dda_is_exact(line):
    """x_k and y_k equal P1 + k/steps · (P2 - P1) exactly, and the last row is P2."""
    x1, y1, x2, y2 = line
    steps = list(dda(x1, y1, x2, y2))
    n = len(steps) - 1
    for s in steps:
        t = Fraction(s.k, n) if n else Fraction(0)
        assert s.extra[0] == x1 + t * (x2 - x1) and s.extra[1] == y1 + t * (y2 - y1)
        assert s.pixel == (round_half_up(s.extra[0]), round_half_up(s.extra[1]))
    assert steps[-1].extra[:2] == (x2, y2)


def test_notes_examples():
    """The notes' examples, with the corrected Bresenham table (docs/errata.md, E1)."""
    assert [s.p for s in bresenham(2, 2, 10, 6)] == [0, -8] * 4
    assert pixels("bresenham", 2, 2, 10, 6) == [
        (2, 2), (3, 3), (4, 3), (5, 4), (6, 4), (7, 5), (8, 5), (9, 6), (10, 6),
    ]  # fmt: skip
    assert pixels("dda", 2, 2, 10, 6) == pixels("bresenham", 2, 2, 10, 6)
    assert pixels("basic", 2, 2, 8, 5) == [(2, 2), (3, 3), (4, 3), (5, 4), (6, 4), (7, 5), (8, 5)]
    assert pixels("dda", 2, 2, 5, 10)[4] == (4, 6)  # x = 3.5 rounds half up


def test_half_up_not_half_even():
    """Python's round() would put (2,3)->(12,8) at (5, 4) and (9, 6)."""
    px = pixels("dda", 2, 3, 12, 8)
    assert (5, 5) in px and (9, 7) in px


@pytest.mark.parametrize(
    ("line", "moves"),
    [
        ((0, 0, 5, 0), {"E"}),
        ((0, 0, 0, -5), {"N"}),  # walked from the lower end
        ((0, 0, 4, 4), {"NE"}),
        ((0, 0, 4, -4), {"SE"}),
        ((0, 0, -4, 4), {"SE"}),  # right-to-left: swapped to walk in +x
        ((0, 0, 2, 7), {"N", "NE"}),
        ((0, 0, -2, 7), {"N", "NW"}),
        ((0, 0, 7, -2), {"E", "SE"}),
    ],
)
def test_moves_by_octant(line, moves):
    assert {s.decision.value for s in bresenham(*line) if s.decision} == moves


def test_the_excluded_methods_are_line_methods():
    assert set(NOT_ONE_PIXEL_A_STEP) < set(methods_of("line"))
    assert {"basic", "dda", "bresenham", "midpoint"} <= set(ALGOS)


@pytest.mark.parametrize("algo", ALGOS)
def test_single_point(algo):
    assert pixels(algo, 3, -3, 3, -3) == [(3, -3)]


def test_bresenham_refuses_fractions():
    with pytest.raises(ValueError, match="integer end points"):
        line_solution("bresenham", Fraction(5, 2), 0, 4, 4)


def test_unknown_algorithm():
    with pytest.raises(ValueError, match="unknown line algorithm"):
        line_solution("spiral", 0, 0, 1, 1)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=50)
@given(
    x1=st.fractions(min_value=-20, max_value=20, max_denominator=8),
    y1=st.fractions(min_value=-20, max_value=20, max_denominator=8),
    x2=st.fractions(min_value=-20, max_value=20, max_denominator=8),
    y2=st.fractions(min_value=-20, max_value=20, max_denominator=8),
)
def test_fractional_end_points_stay_connected(x1, y1, x2, y2):
    for algo in ("dda", "basic"):
        px = pixels(algo, x1, y1, x2, y2)
        for a, b in itertools.pairwise(px):
            assert max(abs(a[0] - b[0]), abs(a[1] - b[1])) <= 1
        assert px[0] == (round_half_up(x1), round_half_up(y1)) or algo == "basic"


def test_dda_pixels_are_listed_once():
    """Two rows of (0.5, 0) -> (1.4, 0.2) round to the same pixel; it is plotted once."""
    rows = [s.pixel for s in dda(Fraction(1, 2), 0, Fraction(7, 5), Fraction(1, 5))]
    assert rows == [(1, 0), (1, 0)]
    assert pixels("dda", Fraction(1, 2), 0, Fraction(7, 5), Fraction(1, 5)) == [(1, 0)]


def test_basic_matches_its_equation():
    for s in basic(0, 0, 3, 7):
        y, x_exact, x_rounded = s.extra
        assert x_exact == Fraction(3, 7) * y and x_rounded == round_half_up(x_exact)


def test_the_midpoint_line_in_halves_by_hand():
    # (0, 0) to (5, 2): dx = 5, dy = 2. d = F(M) starts at dy - dx/2 = -1/2 and grows by
    # dy = 2 after E, dy - dx = -3 after NE; d < 0 chooses E. d: -1/2 E (1, 0), 3/2 NE (2, 1),
    # -3/2 E (3, 1), 1/2 NE (4, 2), -5/2 E (5, 2); each step's d_{k+1}: 3/2, -3/2, 1/2, -5/2,
    # -1/2. The integer scale is 2F(M): every value doubled.
    half = Fraction(1, 2)
    d = [-half, 3 * half, -3 * half, half, -5 * half, -half]
    moves = [Move.E, Move.NE, Move.E, Move.NE, Move.E]
    pixels = [(1, 0), (2, 1), (3, 1), (4, 2), (5, 2)]
    steps = list(midpoint_line(0, 0, 5, 2, scale="half"))
    assert [(s.p, s.decision, s.pixel, s.extra) for s in steps] == [
        (d[k], moves[k], pixels[k], (d[k + 1],)) for k in range(5)
    ]
    doubled = list(midpoint_line(0, 0, 5, 2))
    assert [(s.p, s.extra) for s in doubled] == [(2 * d[k], (2 * d[k + 1],)) for k in range(5)]
