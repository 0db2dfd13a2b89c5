"""Area sampling of a line of width w: measured along the minor axis (the
default, a parallelogram) or perpendicular to the line (a rectangle); against a published
exercise and an independent clipping of the strip to every pixel square."""

from __future__ import annotations

import json
from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import _api as api
from scanconv.algorithms.coverage import area_coverage, exact_sqrt, line_strip

from .helpers import run


def clip(poly, keep):
    """Sutherland–Hodgman against one half-plane ``keep(p) >= 0`` (linear in p)."""
    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        fp, fq = keep(p), keep(q)
        if fp >= 0:
            out.append(p)
        if (fp < 0 <= fq) or (fq < 0 <= fp):
            t = fp / (fp - fq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def area_in_pixel(poly, i, j):
    """The polygon's area inside pixel (i, j), by clipping to its four sides (independent of
    the trapezoid sweep of coverage.py)."""
    h = F(1, 2)
    for keep in (
        lambda p: p[0] - (i - h),
        lambda p: (i + h) - p[0],
        lambda p: p[1] - (j - h),
        lambda p: (j + h) - p[1],
    ):
        poly = clip(poly, keep)
        if not poly:
            return 0
    twice = sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(poly, poly[1:] + poly[:1], strict=True))
    return abs(twice) / 2


def test_codeshive_exercise_is_reproduced():
    """CS 447/547 Computer Graphics, homework 4, question 1a (as posted at
    https://codeshive.com/questions-and-answers/cs-447-547-computer-graphics-homework-4-solved/):
    a one-pixel-wide line from (1, 1.33) to (6, 1.33), integer locations at pixel centres,
    area-weighted: "the value for (1, 1) is 1/3". Horizontal, so both conventions agree."""
    for across in ("minor", "perpendicular"):
        sol = api.antialias_line(1, F(4, 3), 6, F(4, 3), across=across)
        values = {row[0]: row[1] for row in sol.tables[0].rows()}
        assert values[(1, 1)] == F(1, 3)
        assert values[(3, 1)] == F(2, 3) and values[(3, 2)] == F(1, 3)


TRIPLES = [(3, 4), (4, 3), (5, 12), (-8, 6), (6, -8), (0, 5), (-4, -3)]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(deadline=None, max_examples=60)
@given(
    st.sampled_from(TRIPLES),
    st.integers(-3, 3),
    st.integers(-3, 3),
    st.fractions(min_value=F(1, 4), max_value=3, max_denominator=4),
)
def test_perpendicular_strip_equals_clipping_each_pixel(d, x1, y1, w):
    dx, dy = d
    x2, y2 = x1 + dx, y1 + dy
    poly = list(line_strip(x1, y1, x2, y2, w, "perpendicular"))
    length = exact_sqrt(dx * dx + dy * dy)
    assert length is not None
    ours = area_coverage(poly)
    xs, ys = [p[0] for p in poly], [p[1] for p in poly]
    for i in range(int(min(xs)) - 2, int(max(xs)) + 3):
        for j in range(int(min(ys)) - 2, int(max(ys)) + 3):
            assert ours.get((i, j), 0) == area_in_pixel(poly, i, j)
    assert sum(ours.values()) == w * length


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@given(
    *(st.integers(-6, 6) for _ in range(4)),
    st.fractions(min_value=F(1, 2), max_value=2, max_denominator=2),
)
def test_minor_strip_covers_each_column_by_w(x1, y1, x2, y2, w):
    if (x1, y1) == (x2, y2):
        return
    sol = api.antialias_line(x1, y1, x2, y2, width=w)
    values = {row[0]: row[1] for row in sol.tables[0].rows()}
    assert sum(values.values()) == w * max(abs(x2 - x1), abs(y2 - y1))


def test_an_irrational_length_gives_float_areas_close_to_the_exact_clipping():
    sol = api.antialias_line(0, 0, 4, 1, across="perpendicular")
    rows = list(sol.tables[0].rows())
    assert all(isinstance(r[1], float) and r[2] == "-" for r in rows)
    assert sum(r[1] for r in rows) == pytest.approx(17**0.5, abs=1e-9)
    poly = [(F(x), F(y)) for x, y in line_strip(0, 0, 4, 1, 1, "perpendicular")]
    for (i, j), value, *_ in rows:
        assert value == pytest.approx(float(area_in_pixel(poly, i, j)), abs=1e-12)


def test_the_conventions_differ_on_a_slanted_line_and_are_named():
    minor = api.antialias_line(0, 0, 4, 3)
    perp = api.antialias_line(0, 0, 4, 3, across="perpendicular")
    assert minor.derived[-2].value == 4 and perp.derived[-2].value == 5  # w|dx| against wL
    assert "across = minor" in minor.notes[0] and "across = perpendicular" in perp.notes[0]
    out = json.loads(run("antialias", "line", "0", "0", "4", "3", "--across", "perpendicular",
                         "--width", "2", "-f", "json").out)  # fmt: skip
    assert out["conventions"] == {"across": "perpendicular"} and out["width"] == 2


def test_supersampling_takes_the_same_strip():
    sol = api.antialias_line(0, 0, 4, 3, method="supersample", samples=4, across="perpendicular")
    assert "L = √(4² + 3²) = 5" in sol.derived[0].text


@pytest.mark.parametrize(
    ("args", "word"),
    [
        (("--width", "0"), "positive"),
        (("--width", "-1"), "positive"),
        (("--method", "wu", "--width", "2"), "one pixel wide"),
        (("--method", "wu", "--across", "perpendicular"), "one pixel wide"),
        (("--across", "diagonal"), "across"),
        (("--width", "3000"), "pixel cells"),
    ],
)
def test_bad_widths_are_one_line_and_exit_2(args, word):
    r = run("antialias", "line", "0", "0", "4", "3", *args)
    assert r.code == 2 and not r.out and word in r.err and len(r.err.splitlines()) == 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_budget_counts_the_width():
    from scanconv.render.work import estimate

    narrow = estimate("antialias_line", {"x1": 0, "y1": 0, "x2": 40, "y2": 0})
    wide = estimate("antialias_line", {"x1": 0, "y1": 0, "x2": 40, "y2": 0, "width": 20})
    assert narrow is not None and wide is not None and wide.rows > narrow.rows
    rows = len(list(api.antialias_line(0, 0, 40, 0, width=20).tables[0].rows()))
    assert rows <= wide.rows


def test_a_question_file_takes_every_new_option(tmp_path):
    questions = tmp_path / "aa.questions"
    questions.write_text(
        "antialias line 0 0 4 3 --across perpendicular --width 2\n"
        "antialias line 0 1 10 2 --method wu --ends coverage\n"
        "antialias line 0 0 2 1 --method subpixel --subgrid centre\n",
        encoding="utf-8",
    )
    r = run("sheet", str(questions), "-f", "json")
    assert r.code == 0, r.err
    answers = [q["answer"] for q in json.loads(r.out)["questions"]]
    assert [a["algorithm"] for a in answers] == ["area", "wu", "subpixel"]
    assert answers[0]["conventions"] == {"across": "perpendicular"}
