"""``scanconv compare``: the methods side by side, and the reasons they differ.

The expected values are computed here from the line equation, independently of the
algorithms: the exact minor coordinate at each major coordinate, rounded half up, and the
tie rule of Bresenham's walk.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from scanconv.answers.compare import DDA_MANY, DDA_OFF, TIE, compare_lines
from scanconv.answers.primitives.line import line_solution

from .helpers import run


def _rows(solution):
    return list(solution.tables[0].rows())


def _notes_rows(solution):
    """The rows as the notes' three methods see them: x, the exact y, basic, DDA, Bresenham,
    and the reason tags that concern them (a method compared after them, as the symmetric
    DDA, has its own column and ``SDDA`` tags, checked in tests/test_lines_symmetric_dda.py)."""
    out = []
    for r in _rows(solution):
        tags = [t for t in str(r[-1]).split(", ") if r[-1] is not None and "SDDA" not in t]
        out.append((*r[:5], ", ".join(tags) or None))
    return out


def test_notes_example_negative_slope_differs_exactly_at_the_ties():
    # y = 8 - (x - 2) / 2: a tie (y = k + 1/2) at every odd x; half up takes the upper pixel,
    # Bresenham (walking right, stepping y toward the end point) the lower one.
    rows = _notes_rows(compare_lines(2, 8, 10, 4))
    assert [r[0] for r in rows] == list(range(2, 11))
    for x, exact, basic, dda, bres, reason in rows:
        y = Fraction(16 - (x - 2), 2)
        assert exact == y
        assert basic == dda == math.floor(y + Fraction(1, 2))
        if y.denominator == 2:
            assert (bres, reason) == (math.floor(y), TIE)
        else:
            assert (bres, reason) == (y, None)


def test_positive_slope_all_agree_and_say_so():
    solution = compare_lines(2, 2, 10, 6)
    assert all(r[-1] is None for r in _notes_rows(solution))
    # the notes' three agree; the symmetric DDA's 16 steps of (1/2, 1/4) plot two pixels in
    # each of the columns x = 3, 5, 7, 9 (its points (2.5, 2.25) and (3, 2.5) round to (3, 2)
    # and (3, 3)): 13 pixels in all
    assert solution.notes[0].startswith("The methods differ in 4 of 9 columns (basic: 9 pixels")
    assert "sym. DDA: 13 pixels" in solution.notes[0]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=100, deadline=None)
@given(st.tuples(*[st.integers(-12, 12)] * 4))
def test_integer_lines_differ_only_at_ties(ends):
    x1, y1, x2, y2 = ends
    rows = _notes_rows(compare_lines(*ends))
    steep = abs(y2 - y1) > abs(x2 - x1)
    for _, exact, basic, dda, bres, reason in rows:
        assert basic == dda  # same exact points, same rounding
        if reason is None:
            assert basic == bres
        else:
            assert reason == TIE and Fraction(exact).denominator == 2
            # Bresenham walks toward increasing major coordinate and steps the minor one
            # toward the far end: down (or left) exactly when the slope is negative.
            da, db = (y2 - y1, x2 - x1) if steep else (x2 - x1, y2 - y1)
            assert (bres < basic) == (da * db < 0)
            assert abs(bres - basic) == 1
    # Every pixel of each method is in its column.
    for m, col in (("basic", 2), ("dda", 3), ("bresenham", 4)):
        pixels = set(line_solution(m, *ends).pixels())
        shown = {((r[col], r[0]) if steep else (r[0], r[col])) for r in rows}
        assert pixels == shown


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=100, deadline=None)
@given(st.tuples(*[st.integers(-40, 40).map(lambda n: Fraction(n, 4))] * 4))
def test_fractional_lines_compare_basic_and_dda_only(ends):
    assume(any(v.denominator != 1 for v in ends))
    solution = compare_lines(*ends)
    assert solution.data["methods"] == ["basic", "dda"]
    steep = abs(ends[3] - ends[1]) > abs(ends[2] - ends[0])

    def columns(method):
        out: dict[int, set[int]] = {}
        for x, y in line_solution(method, *ends).pixels():
            out.setdefault(y if steep else x, set()).add(x if steep else y)
        return out

    basic, dda = columns("basic"), columns("dda")
    rows = _rows(solution)
    # The DDA covers exactly the basic method's columns.
    assert set(dda) == set(basic) == {r[0] for r in rows}
    for a, _, _, _, reason in rows:
        assert (reason is None) == (basic[a] == dda[a])
        if reason is not None:
            assert reason == (DDA_MANY if len(dda[a]) > 1 else DDA_OFF)


def test_dda_off_centre_is_explained_with_its_numbers():
    solution = compare_lines(Fraction(1, 2), 0, Fraction(7, 2), 1)
    rows = _rows(solution)
    assert [r[-1] for r in rows] == [None, DDA_OFF, None, None]
    note = next(n for n in solution.notes if n.startswith("DDA off centre"))
    assert "(1.5, 1/3)" in note and "x = 2" in note


def test_cli_compare_line_plain_and_json():
    result = run("compare", "line", "2", "8", "10", "4", "--format", "plain")
    assert result.code == 0, result.err
    assert "Pixels side by side (y for each x):" in result.out
    assert "Tie (rows marked 'tie'): at x = 3 the line is at y = 7.5" in result.out
    assert "o = only some do" in result.out
    assert result.out.isascii()
    data = json.loads(run("compare", "line", "2", "8", "10", "4", "--format", "json").out)
    assert data["algorithm"] == "compare" and data["columns_differing"] == 4
    row = data["tables"][0]["rows"][1]
    assert row[:5] + row[-1:] == [3, 7.5, 8, 8, 7, "tie"]


def test_cli_compare_line_bad_input_is_one_line_exit_2():
    result = run("compare", "line", "1", "2", "3")
    assert result.code == 2 and result.out == "" and result.err.count("\n") == 1
    result = run("compare", "line", "1", "2", "3", "nan")
    assert result.code == 2 and result.out == "" and result.err.count("\n") == 1


def test_cli_compare_steep_negative_line_steps_left():
    result = run("compare", "line", "2", "2", "5", "-10", "--format", "plain")
    assert result.code == 0, result.err
    assert "x for each y" in result.out and "left to 2" in result.out


# --- circles ----------------------------------------------------------------------------------------


def _nearest(n: int) -> int:
    """floor(sqrt(n) + 1/2) with integers only: the pixel nearest the circle."""
    q = math.isqrt(n)
    return q + 1 if n > q * q + q else q


@pytest.mark.parametrize("r", [*range(0, 40), 97, 200])
def test_circle_midpoint_column_is_the_nearest_pixel_and_bresenham_agrees(r):
    from scanconv.answers.compare import compare_circles

    for row in compare_circles(r).tables[0].rows():
        x, exact, midpoint, bres = row[:4]
        assert 0 <= x and (midpoint is None or x <= midpoint)
        if midpoint is not None:
            assert midpoint == _nearest(r * r - x * x)
            # the circle's y, truncated to 6 decimals
            assert (
                Fraction(exact) ** 2 <= r * r - x * x < (Fraction(exact) + Fraction(1, 10**6)) ** 2
            )
        assert bres == midpoint
        assert row[-1] is None or "Bresenham" not in row[-1]


@pytest.mark.parametrize("r", [4, 5, 10, 13, 25, 60])
def test_circle_reasons_match_each_methods_octant(r):
    from scanconv.answers.compare import SHORT, compare_circles
    from scanconv.answers.primitives.circle import circle_solution

    solution = compare_circles(r)
    methods = solution.data["methods"]
    octants = {}
    for m in methods:
        cols: dict[int, set[int]] = {}
        for x, y in circle_solution(m, r).pixels():
            if 0 <= x <= y:
                cols.setdefault(x, set()).add(y)
        octants[m] = cols
    rows = list(solution.tables[0].rows())
    assert [row[0] for row in rows] == sorted(set().union(*octants.values()))
    for row in rows:
        x, reason = row[0], row[-1]
        tags = set() if reason is None else set(reason.split(", "))
        ref = octants["midpoint"].get(x, set())
        for m in methods[1:]:
            got = octants[m].get(x, set())
            if got == ref:
                assert not any(t.startswith(SHORT[m] + " ") for t in tags)
            elif not got:
                kind = "stops" if x > max(octants[m]) else "skips"
                assert f"{SHORT[m]} {kind}" in tags
            elif len(got) > 1:
                assert f"{SHORT[m]} twice" in tags
            else:
                assert f"{SHORT[m]} {'beyond' if not ref else 'off'}" in tags


@pytest.mark.parametrize("r", [1, 4, 10, 93])
def test_circle_notes_give_each_reasons_first_example(r):
    from scanconv.answers.compare import SHORT, compare_circles
    from scanconv.answers.primitives.circle import circle_solution

    solution = compare_circles(r)
    rows = [row for row in solution.tables[0].rows() if row[-1]]
    tags = list(dict.fromkeys(t for row in rows for t in row[-1].split(", ")))
    notes = solution.notes[2:]
    assert [n.split(" (rows marked")[0] for n in notes] == tags
    by_short = {v: k for k, v in SHORT.items()}
    for tag, note in zip(tags, notes, strict=True):
        x = next(row[0] for row in rows if tag in row[-1].split(", "))
        assert f"at x = {x} the circle" in note
        short, kind = tag.rsplit(" ", 1)
        if kind == "stops":
            # Independently: the method's last point with 0 <= x <= y, and the gap it leaves
            # to its mirror image when y - x > 1.
            octant = [p for p in circle_solution(by_short[short], r).pixels() if 0 <= p[0] <= p[1]]
            a = max(p[0] for p in octant)
            b = min(p[1] for p in octant if p[0] == a)
            assert f"last point in the octant is ({a}, {b})" in note
            assert ("gap between" in note) == (b - a > 1)


def test_cli_compare_circle():
    result = run("compare", "circle", "10", "--format", "plain")
    assert result.code == 0, result.err
    assert "First octant side by side (y for each x):" in result.out and result.out.isascii()
    for bad in ("-3", "2.5", "x"):
        result = run("compare", "circle", bad)
        assert result.code == 2 and result.out == "" and result.err.count("\n") == 1


def _notes_general_circle(r: int) -> dict[int, int]:
    """The notes' general method as its algorithm box prints it (Topic 7: x = 0, y = r,
    p = 0; while x < y: E adds 2x + 1, SE 2x - 2y + 1, with the new x and y): the y plotted
    at each x of the octant. Written here from the box, not from scanconv."""
    x, y, p = 0, r, 0
    out = {x: y}
    while x < y:
        x += 1
        if p < 0:
            p += 2 * x + 1
        else:
            y -= 1
            p += 2 * x - 2 * y + 1
        out[x] = y
    return out


def test_compare_circle_sets_the_notes_general_method_beside_bresenham() -> None:
    """Question 30 of the notes ("Compare general method and Bresenham's
    algorithm for circle drawing", docs/cheatsheet.md: ``compare circle 6 --theory``) asks
    for the general method, which the side-by-side table left out. Its column is the notes'
    box run by hand (r = 6: y = 6, 5, 5, 5, 4), and the rows where it differs from the
    midpoint method say why."""
    import json

    from tests.helpers import run

    done = json.loads(run("compare", "circle", "6", "--theory", "--format", "json").out)
    assert "general" in done["methods"]
    table = done["tables"][0]
    keys = [c["key"] if isinstance(c, dict) else c for c in table["columns"]]
    col, reason = keys.index("general"), keys.index("reason")
    by_hand = _notes_general_circle(6)
    assert by_hand == {0: 6, 1: 5, 2: 5, 3: 5, 4: 4}
    for row in table["rows"]:
        assert int(row[col]) == by_hand[int(row[0])], row
        assert ("general off" in (row[reason] or "")) == (by_hand[int(row[0])] != row[2]), row
    assert any("general method tests p = x² + y² - r² at its point" in n for n in done["notes"])
