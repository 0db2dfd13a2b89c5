"""Hearn & Baker's supersampling of a line: Bresenham on a 3 x 3 sub-pixel
grid, its decision table, and each pixel's intensity from its count of sub-pixels; against two
published worked examples, Hearn & Baker's own description, and independent computations."""

from __future__ import annotations

import json
import math
from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import _api as api
from scanconv.algorithms.lines import bresenham
from scanconv.algorithms.subpixel import counts, sub_line, walk

from .helpers import run


def intensities(sol) -> dict[tuple[int, int], F]:
    return {row[0]: row[2] for row in sol.tables[0].rows()}


def test_slideplayer_supersampling_table_is_reproduced():
    """ "Anti-aliasing" lecture slides (https://slideplayer.com/slide/14029777/): "Plot (0,0 to
    2,1) ... multiply both directions by 3 (adding a 3x3 grid) ... (microgrid) Δx = 8, Δy = 4,
    P0 = 2Δy - Δx = 0", the table K, P_K, (X_K+1, Y_K+1): 0, 0, (1, 1); 1, -8, (2, 1); 2, 0,
    (3, 2); ... 7, -8, (8, 4); "3 = full, 2 = 2/3, 1 = 1/3"."""
    sol = api.antialias_line(0, 0, 2, 1, method="subpixel")
    steps = list(sol.steps())
    assert [s.p for s in steps][:8] == [0, -8, 0, -8, 0, -8, 0, -8]
    assert [s.extra for s in steps][1:] == [(1, 1), (2, 1), (3, 2), (4, 2), (5, 3), (6, 3),
                                           (7, 4), (8, 4)]  # fmt: skip
    assert intensities(sol) == {(0, 0): 1, (1, 0): F(2, 3), (1, 1): F(1, 3), (2, 1): 1}


def test_ucsc_homework_sub_grid_is_reproduced():
    """CMPS 160 (UC Santa Cruz, Fall 2004), homework 2 answers
    (http://www.soe.ucsc.edu/classes/cmps160/Fall04/hw/hw2_answers.htm): the line of slope
    1/2 over x = 0 .. 4 is run "from x = 0 to 14 (15 pixels of data, 3 times as many)" with
    y_k+1 = y_k + 1/2 up to 7; rounded half up, the sub-rows are Bresenham's."""
    line = sub_line(0, 0, 4, 2, 3)
    assert (line.du, line.dv) == (14, 7)
    rows = [v for _, _, _, v in walk(line)]
    assert rows == [math.floor(F(k, 2) + F(1, 2)) for k in range(15)]


def test_hearn_bakers_stated_levels_appear_on_a_line_from_10_20():
    """Hearn & Baker, Computer Graphics (C version, 2nd ed.), section 4-8, Fig. 4-38: a line
    from (10, 20) on a 3 x 3 sub-pixel grid, "(10, 20) is set to the maximum intensity
    (level 3); pixels at (11, 21) and (12, 21) ... level 2; and pixels at (11, 20) and
    (12, 22) ... level 1". The figure's far end is not in the text: a slope of 3/4 gives these
    levels (a consistency check, not a reproduction of the figure's numbers)."""
    found = counts(sub_line(10, 20, 14, 23, 3), 3)
    assert {p: c for p, c in found.items() if p[0] <= 12} == {
        (10, 20): 3, (11, 21): 2, (12, 21): 2, (11, 20): 1, (12, 22): 1,
    }  # fmt: skip


pixels_ = st.integers(-8, 8)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=150)
@given(pixels_, pixels_, pixels_, pixels_, st.sampled_from([1, 3, 5]))
def test_centre_walk_is_bresenham_on_the_scaled_line(x1, y1, x2, y2, n):
    line = sub_line(x1, y1, x2, y2, n, "centre")
    c = (n - 1) // 2
    ours = {(u, v) for _, _, u, v in walk(line)}
    if line.steep:
        ours = {(v, u) for u, v in ours}
    a, b = (n * x1 + c, n * y1 + c), (n * x2 + c, n * y2 + c)
    theirs = {a, b} | {s.pixel for s in bresenham(*a, *b)}  # its steps leave out the start
    assert ours == theirs
    brute: dict[tuple[int, int], int] = {}
    for u, v in theirs:
        brute[(u // n, v // n)] = brute.get((u // n, v // n), 0) + 1
    sol = api.antialias_line(x1, y1, x2, y2, method="subpixel", samples=n, subgrid="centre")
    assert intensities(sol) == {p: F(k, n) for p, k in brute.items()}
    nine = api.antialias_line(x1, y1, x2, y2, method="subpixel", samples=n, subgrid="centre",
                              divide="n2")  # fmt: skip
    assert intensities(nine) == {p: F(k, n * n) for p, k in brute.items()}  # count / n²


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=150)
@given(pixels_, pixels_, pixels_, pixels_, st.integers(1, 5))
def test_span_walk_is_the_nearest_sub_row_and_fills_every_sub_column(x1, y1, x2, y2, n):
    line = sub_line(x1, y1, x2, y2, n)
    slope = F(line.dv) / line.du if line.du else F(0)
    per_column: dict[int, int] = {}
    for k, _, u, v in walk(line):
        exact = line.v0 + slope * k
        # the nearest sub-row, a tie rounded away from the start (the tie steps V)
        assert v == (math.floor(exact + F(1, 2)) if slope >= 0 else math.ceil(exact - F(1, 2)))
        per_column[u // n] = per_column.get(u // n, 0) + 1
    assert set(per_column.values()) == {n}  # every pixel column gets its n sub-pixels
    assert all(0 < c <= n for c in counts(line, n).values())


@pytest.mark.parametrize(
    ("args", "word"),
    [
        (("antialias", "circle", "3", "--method", "subpixel"), "lines only"),
        (
            (
                "antialias",
                "line",
                "0",
                "0",
                "4",
                "1",
                "--method",
                "subpixel",
                "--subgrid",
                "centre",
                "-n",
                "4",
            ),
            "odd",
        ),
        (
            ("antialias", "line", "0", "0", "4", "1", "--method", "subpixel", "--ends", "full"),
            "ends",
        ),
        (("antialias", "line", "0", "0", "4", "1", "--subgrid", "span"), "subgrid"),
        (("antialias", "line", "0", "0", "4", "1", "--divide", "n2"), "divide"),
        (("antialias", "line", "0", "0", "20000", "1", "--method", "subpixel"), "10,000"),
        (("antialias", "line", "0", "0", "4.5", "1", "--method", "subpixel"), "integer"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args, word):
    r = run(*args)
    assert r.code == 2 and not r.out and word in r.err and len(r.err.splitlines()) == 1


def test_every_answer_names_its_subgrid_and_divide():
    for subgrid, word in ((None, "subgrid = span, the default"), ("centre", "subgrid = centre")):
        sol = api.antialias_line(0, 0, 6, 2, method="subpixel", subgrid=subgrid)
        assert word in sol.notes[0] and "divide = n, the default" in sol.notes[1]
    sol = api.antialias_line(0, 0, 6, 2, method="subpixel", divide="n2")
    assert "divide = n2" in sol.notes[1] and sol.tables[0].columns[2].text == "I = c / 9"


def test_the_budget_bounds_the_rows():
    from scanconv.render.work import estimate

    work = estimate("antialias_line", {"x1": 0, "y1": 0, "x2": 40, "y2": 13, "method": "subpixel"})
    sol = api.antialias_line(0, 0, 40, 13, method="subpixel")
    assert work is not None and len(list(sol.steps())) <= work.rows <= len(list(sol.steps())) + 3


def test_check_marks_a_slip_in_the_sub_pixel_decision_table(tmp_path):
    table = run("antialias", "line", "0", "0", "2", "1", "--method", "subpixel", "-f", "csv").out
    rows = table.splitlines()
    head = rows[0].split(",")
    fourth = rows[4].split(",")
    fourth[head.index("p")] = "8"  # a slip: p_3 = 0 + 8 - 16 = -8 written as 8
    rows[4] = ",".join(fourth)
    student = tmp_path / "student.csv"
    student.write_text("\n".join(rows) + "\n", encoding="utf-8")
    r = run("check", str(student), "--", "antialias", "line", "0", "0", "2", "1", "--method",
            "subpixel", "-f", "json")  # fmt: skip
    assert r.code == 0, r.err
    marked = json.loads(r.out)
    assert marked["derived"]["score"] == "8/9"
    assert any("Row 4" in n and "should be -8, not 8" in n for n in marked["notes"])
