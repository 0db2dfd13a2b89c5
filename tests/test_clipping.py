"""Clipping: Cohen–Sutherland, Liang–Barsky and Sutherland–Hodgman, exactly.

Properties (hypothesis): the two line clippers agree exactly on random segments and windows;
a clipped segment lies in the closed window and on the original segment; Sutherland–Hodgman's
output for a convex polygon has the area of its intersection with the window, computed here
independently (the convex hull of the vertices inside the other shape and the edge crossings).
Textbook examples are checked value by value, each with its source.

Example counts (the whole suite within 5 minutes): 100 a property (they were 200 to 400);
Liang–Barsky is also compared on random segments with Cyrus–Beck (``test_cyrus_beck``, 200
examples) and the midpoint subdivision (``test_midpoint_clip``), so Cohen–Sutherland and
Liang–Barsky together meet about 450 random segments a run.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.clipping import (
    Case,
    Edge,
    cohen_sutherland,
    is_convex,
    liang_barsky,
    overlapping_edges,
    polygon_area,
    region_code,
    sutherland_hodgman,
)
from scanconv.answers.process.clip.rectangle import clip_line_solution
from scanconv.answers.process.clip.sutherland_hodgman import MAX_VERTICES, clip_polygon_solution
from scanconv.answers.process.pipeline import pipeline_line_solution, pipeline_polygon_solution
from scanconv.core.checks import InputError
from scanconv.render import Format, Options, render

from .helpers import assert_refused, run

coord = st.fractions(min_value=-20, max_value=20, max_denominator=6)
point = st.tuples(coord, coord)


@st.composite
def windows(draw):
    x0, x1 = sorted(draw(st.lists(coord, min_size=2, max_size=2, unique=True)))
    y0, y1 = sorted(draw(st.lists(coord, min_size=2, max_size=2, unique=True)))
    return (x0, y0, x1, y1)


def inside(p, w):
    return w[0] <= p[0] <= w[2] and w[1] <= p[1] <= w[3]


def on_segment(q, a, b):
    """q is on the closed segment a-b (exactly)."""
    cross = (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])
    dot = (q[0] - a[0]) * (b[0] - a[0]) + (q[1] - a[1]) * (b[1] - a[1])
    length2 = (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2
    return cross == 0 and 0 <= dot <= length2 and (length2 or q == a)


# --- properties -------------------------------------------------------------------------------


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@settings(max_examples=100, deadline=None)  # was 400: see the module's note
@given(point, point, windows())
def test_cohen_sutherland_and_liang_barsky_agree_exactly(p1, p2, w):
    cs, lb = cohen_sutherland(p1, p2, w), liang_barsky(p1, p2, w)
    assert cs.accepted == lb.accepted
    assert cs.segment == lb.segment
    assert len(cs.iterations) <= 4


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@settings(max_examples=100, deadline=None)  # was 400: see the module's note
@given(point, point, windows())
def test_a_clipped_segment_is_inside_the_window_and_on_the_line(p1, p2, w):
    r = liang_barsky(p1, p2, w)
    if r.segment is None:
        # rejected: no point of the segment is inside (checked at the segment's LB-free
        # samples: its end points and its crossings with the window's edge lines)
        assert not inside(p1, w) and not inside(p2, w)
        return
    for q in r.segment:
        assert inside(q, w)
        assert on_segment(q, p1, p2)
    # an end point inside the window is kept
    if inside(p1, w):
        assert r.segment[0] == p1
    if inside(p2, w):
        assert r.segment[1] == p2


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@settings(max_examples=100, deadline=None)  # was 300: see the module's note
@given(point, point, windows())
def test_region_codes_follow_the_tbrl_bits(p, _q, w):
    code = region_code(p, w)
    assert bool(code & 1) == (p[0] < w[0])
    assert bool(code & 2) == (p[0] > w[2])
    assert bool(code & 4) == (p[1] < w[1])
    assert bool(code & 8) == (p[1] > w[3])


def hull(points):
    """Convex hull (monotone chain), counter-clockwise, without collinear points."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def segment_crossings(a, b, c, d):
    """Points where the closed segments a-b and c-d meet (end points of an overlap too)."""
    r = (b[0] - a[0], b[1] - a[1])
    s = (d[0] - c[0], d[1] - c[1])
    den = r[0] * s[1] - r[1] * s[0]
    out = []
    if den == 0:
        out += [p for p in (a, b) if on_segment(p, c, d)]
        out += [p for p in (c, d) if on_segment(p, a, b)]
        return out
    t = Fraction((c[0] - a[0]) * s[1] - (c[1] - a[1]) * s[0]) / den
    u = Fraction((c[0] - a[0]) * r[1] - (c[1] - a[1]) * r[0]) / den
    if 0 <= t <= 1 and 0 <= u <= 1:
        out.append((a[0] + t * r[0], a[1] + t * r[1]))
    return out


def in_convex(p, poly):
    """p in the closed convex polygon ``poly`` (counter-clockwise)."""
    n = len(poly)
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        if (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) < 0:
            return False
    return True


def intersection_area(poly, w):
    box = [(w[0], w[1]), (w[2], w[1]), (w[2], w[3]), (w[0], w[3])]
    cands = [p for p in poly if inside(p, w)] + [c for c in box if in_convex(c, poly)]
    for i in range(len(poly)):
        for j in range(4):
            cands += segment_crossings(poly[i], poly[(i + 1) % len(poly)], box[j], box[(j + 1) % 4])
    h = hull(cands)
    return abs(polygon_area(h)) if len(h) >= 3 else 0


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@settings(max_examples=100, deadline=None)  # was 250: see the module's note
@given(st.lists(point, min_size=3, max_size=9), windows())
def test_sutherland_hodgman_of_a_convex_polygon_is_the_intersection(points, w):
    poly = hull(points)
    if len(poly) < 3:
        return
    out = sutherland_hodgman(poly, w)[-1].outputs
    area = abs(polygon_area(out)) if out else 0
    assert area == intersection_area(poly, w)
    assert all(inside(p, w) for p in out)
    if area:  # (a polygon touching the window along an edge clips to that edge, there and back)
        assert not overlapping_edges(out, w)


@st.composite
def points_inside(draw):
    """A window and 3 to 9 points in it (closed): drawn from the whole plane, as this test's
    points once were, not one polygon in 100 fell inside its window, so the test ran
    its assertion on none of them."""
    w = draw(windows())
    xs = st.fractions(min_value=w[0], max_value=w[2], max_denominator=6)
    ys = st.fractions(min_value=w[1], max_value=w[3], max_denominator=6)
    return draw(st.lists(st.tuples(xs, ys), min_size=3, max_size=9)), w


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.slow
@settings(max_examples=100, deadline=None)  # was 200: see the module's note
@given(points_inside())
def test_sutherland_hodgman_keeps_a_polygon_inside_the_window(case):
    points, w = case
    poly = hull(points)
    assert all(inside(p, w) for p in poly)
    if len(poly) < 3:
        return
    k = 4 % len(poly)  # each stage's output starts at the second vertex of its input
    assert sutherland_hodgman(poly, w)[-1].outputs == tuple(poly[k:] + poly[:k])


# --- textbook examples ------------------------------------------------------------------------

#: GeeksforGeeks, "Line Clipping | Set 1 (Cohen–Sutherland Algorithm)",
#: https://www.geeksforgeeks.org/line-clipping-set-1-cohen-sutherland-algorithm/ :
#: window x_min = 4, y_min = 4, x_max = 10, y_max = 8; its program prints
#: "Line accepted from 5.00, 5.00 to 7.00, 7.00", "Line accepted from 7.80, 8.00 to 10.00, 5.25",
#: "Line rejected".
GFG_WINDOW = (4, 4, 10, 8)


def test_geeksforgeeks_cohen_sutherland_examples():
    inside_line = cohen_sutherland((5, 5), (7, 7), GFG_WINDOW)
    assert inside_line.codes == (0, 0) and not inside_line.iterations
    assert inside_line.segment == ((5, 5), (7, 7))

    r = cohen_sutherland((7, 9), (11, 4), GFG_WINDOW)
    assert [f"{c:04b}" for c in r.codes] == ["1000", "0010"]  # P1 above, P2 right
    first, second = r.iterations
    assert (first.end, first.edge, first.point, first.new_code) == (
        1,
        Edge.TOP,
        (Fraction(39, 5), 8),
        0,
    )
    assert (second.end, second.edge, second.point, second.new_code) == (
        2,
        Edge.RIGHT,
        (10, Fraction(21, 4)),
        0,
    )
    assert r.segment == ((Fraction("7.8"), 8), (10, Fraction("5.25")))

    rejected = cohen_sutherland((1, 5), (4, 1), GFG_WINDOW)
    assert [f"{c:04b}" for c in rejected.codes] == ["0001", "0100"]
    (only,) = rejected.iterations  # P1 moved to (4, 1) on the left edge, below the window
    assert only.point == (4, 1) and f"{only.new_code:04b}" == "0100"
    assert not rejected.accepted and rejected.segment is None


def test_geeksforgeeks_cohen_sutherland_answer_text():
    sol = clip_line_solution(7, 9, 11, 4, GFG_WINDOW)
    text = "".join(c for c in render(sol, Format.plain, Options()) if isinstance(c, str))
    assert "code(P1) = 1000: y = 9 > ymax = 8 (T)" in text
    assert "y = 8, x = x1 + (y - y1)/m = 7 + (8 - 9)/(-1.25) = 7.8" in text
    assert "clipped segment: (7.8, 8) to (10, 5.25)" in text


#: Amagnum, "Liang-Barsky line clipping algorithm cpp code with all intermediate steps",
#: https://github.com/Amagnum/Liang-Barsky-line-clipping-algorithm-cpp (README and liang.in):
#: Xmin Xmax Ymin Ymax = 25 75 30 80, P1 = (5, 20), P2 = (55, 90); it prints p1 = -50,
#: q1 = -20, p2 = 50, q2 = 70, p3 = -70, q3 = -10, p4 = 70, q4 = 60, t = 0.4, 1.4, 0.142857,
#: 0.857143, t_min = 0.4, t_max = 0.857143.
def test_amagnum_liang_barsky_example():
    r = liang_barsky((5, 20), (55, 90), (25, 30, 75, 80))
    assert [(row.p, row.q) for row in r.rows] == [(-50, -20), (50, 70), (-70, -10), (70, 60)]
    assert [row.r for row in r.rows] == [
        Fraction(2, 5),
        Fraction(7, 5),
        Fraction(1, 7),
        Fraction(6, 7),
    ]
    assert [round(float(row.r), 6) for row in r.rows] == [0.4, 1.4, 0.142857, 0.857143]
    assert (r.rows[-1].u1, r.rows[-1].u2) == (Fraction(2, 5), Fraction(6, 7))
    # the clipped end points, exactly: (5 + 0.4*50, 20 + 0.4*70), (5 + 50*6/7, 20 + 70*6/7)
    assert r.segment == ((25, 48), (Fraction(335, 7), 80))


#: GeeksforGeeks, "Polygon Clipping | Sutherland–Hodgman Algorithm",
#: https://www.geeksforgeeks.org/polygon-clipping-sutherland-hodgman-algorithm/ : polygon
#: (100,150), (200,250), (300,200), clipping square (150,150)-(200,200); its output
#: "(150, 162) (150, 200) (200, 200) (200, 174)" comes from integer arithmetic: the exact
#: crossings are (150, 162.5) and (200, 175).
def test_geeksforgeeks_sutherland_hodgman_example():
    stages = sutherland_hodgman([(100, 150), (200, 250), (300, 200)], (150, 150, 200, 200))
    assert [s.edge for s in stages] == [Edge.LEFT, Edge.RIGHT, Edge.BOTTOM, Edge.TOP]
    final = stages[-1].outputs
    assert final == ((150, Fraction(325, 2)), (150, 200), (200, 200), (200, 175))
    assert [(int(x), int(y)) for x, y in final][:3] == [(150, 162), (150, 200), (200, 200)]
    left = stages[0].rows
    assert [r.case for r in left] == [Case.OUT_IN, Case.IN_IN, Case.IN_OUT]
    assert left[0].output == ((150, 200), (200, 250))


# --- special cases ----------------------------------------------------------------------------

W = (1, 1, 3, 3)


@pytest.mark.parametrize(
    ("p1", "p2", "expected"),
    [
        ((2, 2), (3, 3), ((2, 2), (3, 3))),  # fully inside, one end point on a corner
        ((0, 0), (0, 5), None),  # fully outside, left of the window
        ((4, 0), (5, 4), None),  # outside, both end points right of it
        ((0, 4), (4, 5), None),  # outside above, codes share T
        ((0, 2), (4, 2), ((1, 2), (3, 2))),  # crosses both sides
        ((1, 0), (1, 5), ((1, 1), (1, 3))),  # along the left edge
        ((0, 3), (5, 3), ((1, 3), (3, 3))),  # along the top edge
        ((3, 2), (5, 2), ((3, 2), (3, 2))),  # end point on the edge, rest outside: one point
        ((0, 2), (2, 0), ((1, 1), (1, 1))),  # touches the corner (1, 1) only
        ((0, 3), (3, 6), None),  # passes above the corner (1, 3): not trivially rejected
        ((0, 5), (5, 0), ((2, 3), (3, 2))),  # cuts the corner (3, 3) off
        ((2, 2), (2, 2), ((2, 2), (2, 2))),  # a single point inside
        ((0, 0), (0, 0), None),  # a single point outside
    ],
)
def test_special_cases_agree(p1, p2, expected):
    cs, lb = cohen_sutherland(p1, p2, W), liang_barsky(p1, p2, W)
    assert cs.segment == expected
    assert lb.segment == expected


def test_a_parallel_line_outside_is_rejected_by_its_p_equal_zero_row():
    r = liang_barsky((0, 5), (4, 5), W)
    assert r.outside is Edge.TOP and not r.accepted
    assert r.rows[3].p == 0 and r.rows[3].q < 0


def test_a_concave_polygon_leaves_degenerate_edges_and_a_note():
    # a U shape; its two arms cross the window's top strip, which cuts the bottom off
    u = [(0, 0), (6, 0), (6, 6), (4, 6), (4, 2), (2, 2), (2, 6), (0, 6)]
    assert not is_convex(u)
    final = sutherland_hodgman(u, (1, 3, 5, 5))[-1].outputs
    assert overlapping_edges(final, (1, 3, 5, 5))
    assert abs(polygon_area(final)) == 4  # two 1 x 2 pieces
    sol = clip_polygon_solution([c for p in u for c in p], (1, 3, 5, 5))
    assert any("degenerate edges" in n for n in sol.notes)
    assert sol.data["degenerate_edges"]


def test_a_polygon_fully_outside_clips_to_nothing():
    sol = clip_polygon_solution([10, 10, 12, 10, 11, 12], (0, 0, 5, 5))
    assert sol.data["clipped"] == []
    assert "clipped polygon (0 vertices): (none)" in sol.derived[-2].text


@pytest.mark.parametrize("fmt", list(Format)[1:])
def test_every_format_renders_the_clipping_answers(fmt):
    for sol in (
        clip_line_solution(7, 9, 11, 4, GFG_WINDOW),
        clip_line_solution(5, 20, 55, 90, (25, 30, 75, 80), "liang-barsky"),
        clip_line_solution(0, 0, 0, 5, W, "liang-barsky"),
        clip_polygon_solution([100, 150, 200, 250, 300, 200], (150, 150, 200, 200)),
    ):
        out = "".join(str(c) for c in render(sol, fmt, Options()))
        assert out
        if fmt is Format.plain:
            assert out.isascii()


# --- bad input --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("call", "param", "words"),
    [
        (lambda: clip_line_solution(0, 0, 1, 1, (5, 0, 5, 3)), "window", "xmin < xmax"),
        (lambda: clip_line_solution(0, 0, 1, 1, (6, 0, 5, 3)), "window", "xmin < xmax"),
        (lambda: clip_line_solution(0, 0, 1, 1, (0, 3, 5, 3)), "window", "ymin < ymax"),
        (lambda: clip_line_solution(0, 0, 1, 1, (0, 0, 5)), "window", "4 numbers"),
        (
            lambda: clip_line_solution(0, 0, 1, 1, W, "nicholl-lee"),
            "method",
            "unknown line clipping",
        ),
        (lambda: clip_polygon_solution([0, 0, 1, 1], W), "vertices", "at least 3"),
        (lambda: clip_polygon_solution([0, 0, 1], W), "vertices", "x y pairs"),
        (
            lambda: clip_polygon_solution([0] * (2 * MAX_VERTICES + 2), W),
            "vertices",
            f"at most {MAX_VERTICES}",
        ),
    ],
)
def test_bad_input_is_an_input_error(call, param, words):
    with pytest.raises(InputError, match=words) as err:
        call()
    assert err.value.param == param
    assert "--" not in str(err.value)


def test_the_vertex_limit_is_inclusive():
    coords = [c for i in range(MAX_VERTICES) for c in (i % 7, i % 5)]
    assert clip_polygon_solution(coords, (0, 0, 3, 3)).title


# --- the pipeline -----------------------------------------------------------------------------


def test_pipeline_line_stage_by_stage():
    """(-5, 0)-(15, 10) in the window (0, 0)-(10, 10): clipped at x = 0 (y = 0 + 0.5*5 = 2.5)
    and x = 10 (y = 7.5); the viewport (0, 0)-(20, 10) doubles x (sx = 2, sy = 1, so the
    picture is stretched); rounded half up the end points are (0, 3) and (20, 8); Bresenham
    then starts with p0 = 2*5 - 20 = -10."""
    sol = pipeline_line_solution(-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10))
    assert sol.data["clipped"] == [[0, Fraction(5, 2)], [10, Fraction(15, 2)]]
    assert sol.data["device"] == [[0, Fraction(5, 2)], [20, Fraction(15, 2)]]
    assert sol.data["rounded"] == [[0, 3], [20, 8]]
    assert next(s.p for s in sol.steps()) == -10
    pixels = list(sol.pixels())
    assert pixels[0] == (0, 3) and pixels[-1] == (20, 8) and len(pixels) == 21
    assert "distorted" in next(q.text for q in sol.derived if q.key == "aspect")


def test_pipeline_line_rejected_draws_nothing():
    sol = pipeline_line_solution(
        -5, 20, 15, 30, (0, 0, 10, 10), (0, 0, 20, 10), clip="liang-barsky"
    )
    assert sol.pixels is None and sol.data["clipped"] is None


def test_pipeline_polygon_fill_by_hand():
    """The triangle (-2, 0), (6, 0), (2, 6) clipped to (0, 0)-(4, 4) and doubled into the
    viewport (0, 0)-(8, 8) is (20/3, 8), (4/3, 8), (0, 6), (0, 0), (8, 0), (8, 6). Pixel centres
    inside, half-open: rows 0..6 fill x = 0..7 (8 each), row 7 runs from 2/3 to 22/3 and fills
    x = 1..7; 7 * 8 + 7 = 63 pixels."""
    sol = pipeline_polygon_solution([-2, 0, 6, 0, 2, 6], (0, 0, 4, 4), (0, 0, 8, 8), fill=True)
    pixels = list(sol.pixels())
    assert len(pixels) == 63
    assert {x for x, y in pixels if y == 7} == set(range(1, 8))
    assert {x for x, y in pixels if y == 0} == set(range(8))
    outline = pipeline_polygon_solution([-2, 0, 6, 0, 2, 6], (0, 0, 4, 4), (0, 0, 8, 8))
    assert set(outline.pixels()) <= set(pixels) | {(x, 8) for x in range(9)} | {
        (8, y) for y in range(9)
    }


def test_pipeline_polygon_outside_the_window():
    sol = pipeline_polygon_solution([20, 20, 30, 20, 25, 30], (0, 0, 4, 4), (0, 0, 8, 8), fill=True)
    assert sol.pixels is None and sol.data["device"] is None


@pytest.mark.parametrize(
    ("call", "param"),
    [
        (lambda: pipeline_line_solution(0, 0, 1, 1, (0, 0, 1, 1), (0, 0, 0, 1)), "viewport"),
        (lambda: pipeline_line_solution(0, 0, 1, 1, (0, 0, 1, 1), (0, 0, 1, 1), clip="x"), "clip"),
        (lambda: pipeline_line_solution(0, 0, 1, 1, (0, 0, 1, 1), (0, 0, 1, 1), algo="x"), "algo"),
        (
            lambda: pipeline_polygon_solution(
                [0, 0, 1, 0, 0, 1], (0, 0, 1, 1), (0, 0, 2, 2), fill=True, rule="x"
            ),
            "rule",
        ),
    ],
)
def test_pipeline_bad_input(call, param):
    with pytest.raises(InputError) as err:
        call()
    assert err.value.param == param


# --- the command line -------------------------------------------------------------------------


@pytest.mark.parametrize(
    "args",
    [
        ("clip", "line", "7", "9", "11", "4", "--window", "4", "4", "10", "8", "-f", "plain"),
        ("clip", "line", "5", "20", "55", "90", "-w", "25", "30", "75", "80", "-m", "liang-barsky", "-f", "json"),
        ("clip", "polygon", "100", "150", "200", "250", "300", "200", "--window", "150", "150", "200", "200", "-f", "csv"),
        ("pipeline", "line", "-5", "0", "15", "10", "--window", "0", "0", "10", "10", "--viewport", "0", "0", "20", "10", "-f", "latex"),
        ("pipeline", "polygon", "-2", "0", "6", "0", "2", "6", "--window", "0", "0", "4", "4", "--viewport", "0", "0", "8", "8", "--fill", "-f", "rich"),
    ],
)  # fmt: skip
def test_the_commands_answer(args):
    r = run(*args)
    assert r.code == 0, r.err
    assert r.out and r.err == ""


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("clip", "line", "0", "0", "1", "1", "--window", "4", "4", "4", "8"), ("--window", "xmin < xmax")),
        (("clip", "line", "0", "0", "1", "1", "--window", "0", "0", "5"), ("--window",)),
        (("clip", "line", "0", "0", "1", "1", "--window", "0", "0", "5", "5", "-m", "sutherland"), ("--method",)),
        (("clip", "polygon", "0", "0", "1", "1", "--window", "0", "0", "5", "5"), ("at least 3",)),
        (("pipeline", "line", "0", "0", "1", "1", "-w", "0", "0", "5", "5", "--viewport", "0", "0", "9", "0"), ("--viewport", "ymin < ymax")),
    ],
)  # fmt: skip
def test_bad_input_on_the_command_line_is_one_line_and_exit_2(args, words):
    assert_refused(run(*args), *words)


@pytest.mark.parametrize(
    ("p1", "p2", "segment", "ends"),
    [
        # P1 left of the window (4, 4)-(10, 8), P2 inside: P1 moves to x = 4 along y = 5
        ((0, 5), (6, 5), ((4, 5), (6, 5)), [1]),
        # P1 inside, P2 right of it: P2 moves to x = 10
        ((6, 5), (12, 5), ((6, 5), (10, 5)), [2]),
        # P1 below, P2 inside: x = 5 + (4 - 2) * (7 - 5) / (6 - 2) = 6 at y = 4
        ((5, 2), (7, 6), ((6, 4), (7, 6)), [1]),
    ],
)
def test_cohen_sutherland_clips_the_one_end_outside(p1, p2, segment, ends):
    r = cohen_sutherland(p1, p2, (4, 4, 10, 8))
    assert r.accepted and r.segment == segment
    assert [i.end for i in r.iterations] == ends


@pytest.mark.parametrize(
    ("vertices", "convex"),
    [
        ([(0, 0), (4, 0), (4, 4), (0, 4)], True),
        ([(0, 0), (4, 0), (6, 2), (4, 4), (0, 4)], True),
        ([(0, 0), (2, 0), (4, 0), (4, 4)], True),  # a collinear turn is ignored
        # the square's left side pushed in to (2, 2): (0, 4) -> (2, 2) -> (0, 0) turns right,
        # cross = (2 - 0)(0 - 2) - (2 - 4)(0 - 2) = -8, against the others' left turns
        ([(0, 0), (4, 0), (4, 4), (0, 4), (2, 2)], False),
        ([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)], False),
    ],
)
def test_is_convex_by_the_turn_at_every_vertex(vertices, convex):
    assert is_convex(vertices) is convex


@pytest.mark.parametrize("method", ["cyrus-beck", "nicholl-lee-nicholl"])
def test_the_pipeline_takes_the_clipped_segment_as_a_value_not_from_json_data(
    method: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An answer's ``data`` is output only: with NLL's and Cyrus-Beck's answers emptied of
    their JSON fields, the pipeline still clips -5,0 - 15,10 to (0, 2.5) - (10, 7.5) (by hand:
    y = 2.5 + x/2 on the window 0..10)."""
    from scanconv.answers.process.clip import cyrus_beck, nll

    for module, name in ((cyrus_beck, "cyrus_beck_solution"), (nll, "nll_solution")):
        real = getattr(module, name)

        def emptied(*args: object, _real: object = real, **kwargs: object) -> object:
            sol = _real(*args, **kwargs)  # type: ignore[operator]
            sol.data = {}
            return sol

        monkeypatch.setattr(module, name, emptied)
    sol = pipeline_line_solution(-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10), clip=method)
    assert sol.data["clipped"] == [[0, Fraction(5, 2)], [10, Fraction(15, 2)]]
