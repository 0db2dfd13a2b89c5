"""Wu's line conventions: the end points at full intensity (Wu 1991, the
default) or weighted by their fractional coverage (the widely copied version), and fractional
end points; against a published table and an independent transcription of the pseudocode."""

from __future__ import annotations

import json
import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import _api as api
from scanconv.algorithms.wu import end_gaps, is_steep, wu, wu_line

from .helpers import run

coords = st.fractions(min_value=-12, max_value=12, max_denominator=8)


def wikipedia_wu(x0: float, y0: float, x1: float, y1: float) -> dict[tuple[int, int], float]:
    """Wikipedia's "Xiaolin Wu's line algorithm" pseudocode, transcribed line by line in floats
    (ipart = floor, round(x) = ipart(x + 0.5), fpart(x) = x - ipart(x), rfpart = 1 - fpart);
    ``plot`` keeps the last value written to a pixel, as the pseudocode's plot does."""
    out: dict[tuple[int, int], float] = {}

    def ipart(x: float) -> int:
        return math.floor(x)

    def fpart(x: float) -> float:
        return x - math.floor(x)

    def rfpart(x: float) -> float:
        return 1 - fpart(x)

    steep = abs(y1 - y0) > abs(x1 - x0)
    if steep:
        x0, y0, x1, y1 = y0, x0, y1, x1
    if x0 > x1:
        x0, x1, y0, y1 = x1, x0, y1, y0

    def plot(x: int, y: int, c: float) -> None:
        out[(y, x) if steep else (x, y)] = c

    dx, dy = x1 - x0, y1 - y0
    gradient = dy / dx if dx else 1.0
    xend = ipart(x0 + 0.5)
    yend = y0 + gradient * (xend - x0)
    xgap = rfpart(x0 + 0.5)
    xpxl1, ypxl1 = xend, ipart(yend)
    plot(xpxl1, ypxl1, rfpart(yend) * xgap)
    plot(xpxl1, ypxl1 + 1, fpart(yend) * xgap)
    intery = yend + gradient
    xend = ipart(x1 + 0.5)
    yend = y1 + gradient * (xend - x1)
    xgap = fpart(x1 + 0.5)
    xpxl2, ypxl2 = xend, ipart(yend)
    plot(xpxl2, ypxl2, rfpart(yend) * xgap)
    plot(xpxl2, ypxl2 + 1, fpart(yend) * xgap)
    for x in range(xpxl1 + 1, xpxl2):
        plot(x, ipart(intery), rfpart(intery))
        plot(x, ipart(intery) + 1, fpart(intery))
        intery += gradient
    return out


def test_rosetta_code_table_is_reproduced():
    """Rosetta Code, "Xiaolin Wu's line algorithm", the Sidef entry's printed output for
    drawLine(0, 1, 10, 2) (https://trizen.gitbook.io/sidef-lang/programming_tasks/x/
    xiaolin_wus_line_algorithm): plot 0 1 0.5, plot 10 2 0.5, then 1 1 0.9, 1 2 0.1, ...,
    9 1 0.1, 9 2 0.9 (zero intensities not printed)."""
    published = {(0, 1): 0.5, (10, 2): 0.5}
    for x in range(1, 10):
        published[(x, 1)] = round(1 - x / 10, 1)
        published[(x, 2)] = round(x / 10, 1)
    ours = {}
    for s in wu_line(0, 1, 10, 2, "coverage"):
        for pixel, value in ((s.extra[2], s.extra[4]), (s.extra[3], s.extra[5])):
            if value:
                ours[pixel] = round(float(value), 1)
    assert ours == published


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=100)
@given(coords, coords, coords, coords)
def test_coverage_ends_equal_the_pseudocode_transcribed(x1, y1, x2, y2):
    steps = list(wu_line(x1, y1, x2, y2, "coverage"))
    if len({s.extra[0] for s in steps}) < len(steps) or len(steps) < 2:
        return  # the pseudocode needs two distinct end columns (checked separately)
    ours: dict[tuple[int, int], float] = {}
    for s in steps:
        ours[s.extra[2]] = float(s.extra[4])
        ours[s.extra[3]] = float(s.extra[5])
    theirs = wikipedia_wu(float(x1), float(y1), float(x2), float(y2))
    # the floats' accumulated intery can land a hair below an integer: a pixel of intensity
    # ~1e-16 where ours is exactly 0, so compare the pixels that get ink
    ink = {p: v for p, v in theirs.items() if v > 1e-9}
    assert {p for p, v in ours.items() if v > 1e-9} == ink.keys()
    for p, v in ink.items():
        assert ours[p] == pytest.approx(v, abs=1e-9)


def _covered(lo: Fraction, hi: Fraction, column: int) -> Fraction:
    """The length of [lo, hi] inside the column [c - 1/2, c + 1/2] (independent of wu.py)."""
    half = Fraction(1, 2)
    return max(Fraction(0), min(hi, column + half) - max(lo, column - half))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(deadline=None, max_examples=100)
@given(coords, coords, coords, coords)
def test_each_columns_two_intensities_sum_to_its_coverage(x1, y1, x2, y2):
    steep = abs(y2 - y1) > abs(x2 - x1)
    lo, hi = sorted((y1, y2) if steep else (x1, x2))
    for s in wu_line(x1, y1, x2, y2, "coverage"):
        assert s.extra[4] + s.extra[5] == _covered(lo, hi, s.extra[0])
    for s in wu_line(x1, y1, x2, y2, "full"):
        assert s.extra[4] + s.extra[5] == 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=100)
@given(*(st.integers(-20, 20) for _ in range(4)))
def test_full_ends_with_integer_points_are_wus_steps(x1, y1, x2, y2):
    assert [s.extra[:6] for s in wu_line(x1, y1, x2, y2)] == [s.extra for s in wu(x1, y1, x2, y2)]


def test_the_minor_coordinate_lies_on_the_line_in_every_column():
    x1, y1, x2, y2 = Fraction(3, 10), Fraction(0), Fraction(11, 2), Fraction(2)
    for s in wu_line(x1, y1, x2, y2, "full"):
        a, b = s.extra[0], s.extra[1]
        assert (b - y1) * (x2 - x1) == (y2 - y1) * (a - x1)  # on the line through P1, P2
        assert s.extra[2] == (a, math.floor(b))


def test_integer_end_points_get_half_intensity_with_coverage():
    assert end_gaps(0, 8, "coverage") == (Fraction(1, 2), Fraction(1, 2))
    sol = api.antialias_line(0, 0, 8, 3, method="wu", ends="coverage")
    rows = list(sol.steps())
    assert (rows[0].extra[4], rows[-1].extra[4]) == (Fraction(1, 2), Fraction(1, 2))
    assert sol.data["conventions"] == {"ends": "coverage"}


def test_one_column_line_counts_its_length_once():
    # both ends in column 2: the column's coverage is x2 - x1 (the pseudocode would plot twice)
    steps = list(wu_line(Fraction(17, 10), 0, Fraction(23, 10), Fraction(1, 10), "coverage"))
    assert len(steps) == 1 and steps[0].extra[6] == Fraction(3, 5)


def test_every_answer_names_its_ends_convention():
    for ends, word in ((None, "ends = full"), ("coverage", "ends = coverage")):
        sol = api.antialias_line(0, 0, 5, 2, method="wu", ends=ends)
        assert any(word in n for n in sol.notes)
    out = json.loads(run("antialias", "line", "0", "0", "5", "2", "--method", "wu",
                         "-f", "json").out)  # fmt: skip
    assert out["conventions"] == {"ends": "full"}


def test_the_gap_column_is_shown_only_with_coverage():
    full = run("antialias", "line", "0", "0", "5", "2", "--method", "wu", "-f", "csv").out
    cov = run("antialias", "line", "0", "0", "5", "2", "--method", "wu", "--ends", "coverage",
              "-f", "csv").out  # fmt: skip
    assert "gap" not in full.splitlines()[0] and "gap" in cov.splitlines()[0]
    header, first = (line.split(",") for line in cov.splitlines()[:2])
    assert first[header.index("gap")] == "0.5"


def test_ends_with_another_method_is_refused():
    r = run("antialias", "line", "0", "0", "5", "2", "--ends", "coverage")
    assert r.code == 2 and not r.out and "ends" in r.err and len(r.err.splitlines()) == 1
    r = run("antialias", "line", "0", "0", "5", "2", "--method", "wu", "--ends", "half")
    assert r.code == 2 and not r.out


def test_line_algo_wu_takes_the_ends_convention_too():
    line = json.loads(run("line", "0", "1", "10", "2", "--algo", "wu", "--ends", "coverage",
                          "-f", "json").out)  # fmt: skip
    aa = json.loads(run("antialias", "line", "0", "1", "10", "2", "--method", "wu", "--ends",
                        "coverage", "-f", "json").out)  # fmt: skip
    assert line["steps"] == aa["steps"] and line["conventions"] == {"ends": "coverage"}
    r = run("line", "0", "1", "10", "2", "--ends", "coverage")
    assert r.code == 2 and not r.out and "ends" in r.err


@pytest.mark.parametrize(
    ("line", "steep"),
    [
        ((0, 0, 1, 3), True),  # |dy| = 3 > |dx| = 1
        ((0, -3, 1, 3), True),  # |dy| = 6 > 1
        ((0, 5, 4, 3), False),  # |dy| = 2 < |dx| = 4
        ((2, 2, 5, 5), False),  # the diagonal: x stays the major axis
        ((7, 1, 7, 1), False),  # a single point
    ],
)
def test_is_steep_by_hand(line, steep):
    assert is_steep(*line) is steep
