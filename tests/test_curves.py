"""Curves: Bezier, B-spline, parametric and continuity, checked against independent facts."""

from __future__ import annotations

import itertools
import math
import random
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.bezier import bernstein, bezier, de_casteljau
from scanconv.algorithms.bspline import (
    basis,
    basis_float,
    bspline,
    bspline_samples,
    knot_vector,
    span,
)
from scanconv.algorithms.continuity import continuity_level
from scanconv.algorithms.curve_limits import MAX_DEGREE
from scanconv.algorithms.lines import bresenham
from scanconv.algorithms.local_control import local_control
from scanconv.algorithms.parametric import parametric
from scanconv.algorithms.sampling import coord, curve_pixels, sample_ts
from scanconv.answers.curves.bezier import bezier_solution
from scanconv.answers.curves.bspline import bspline_solution
from scanconv.answers.primitives.parametric import parametric_solution
from scanconv.core.checks import InputError
from scanconv.core.ideal import ControlPolygon, Polyline
from scanconv.render import formats

from .helpers import assert_refused, connected, run

coords = st.integers(-20, 20)
points = st.lists(st.tuples(coords, coords), min_size=2, max_size=7)
unit_t = st.fractions(0, 1, max_denominator=64)


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _hull(pts):
    """Andrew's monotone chain, exact; counter-clockwise, no collinear points."""
    pts = sorted(set(pts))
    if len(pts) <= 2:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and _cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and _cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _in_hull(q, pts) -> bool:
    hull = _hull(pts)
    if len(hull) == 1:
        return q == hull[0]
    if len(hull) == 2:  # a segment: collinear and between the ends
        a, b = hull
        return (
            _cross(a, b, q) == 0
            and min(a[0], b[0]) <= q[0] <= max(a[0], b[0])
            and min(a[1], b[1]) <= q[1] <= max(a[1], b[1])
        )
    return all(_cross(hull[i], hull[(i + 1) % len(hull)], q) >= 0 for i in range(len(hull)))


def _point(step):
    return step.extra[-2], step.extra[-1]


# --- Bezier -------------------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(points, st.integers(1, 12))
def test_bezier_interpolates_its_end_points(pts, samples):
    rows = list(bezier(pts, samples))
    assert len(rows) == samples + 1
    assert _point(rows[0]) == pts[0]
    assert _point(rows[-1]) == pts[-1]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(points, st.integers(1, 10))
def test_bezier_stays_in_the_convex_hull(pts, samples):
    for s in bezier(pts, samples):
        assert _in_hull(_point(s), pts)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(st.integers(1, 12), unit_t)
def test_bernstein_weights_are_nonnegative_and_sum_to_one(n, t):
    w = bernstein(n, t)
    assert sum(w) == 1
    assert all(v >= 0 for v in w)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(points, unit_t)
def test_de_casteljau_equals_bernstein_exactly(pts, t):
    *_, last = de_casteljau(pts, t)
    n = len(pts) - 1
    w = bernstein(n, t)
    expected = (
        sum(wi * p[0] for wi, p in zip(w, pts, strict=True)),
        sum(wi * p[1] for wi, p in zip(w, pts, strict=True)),
    )
    assert last.extra[0] == expected
    assert all(isinstance(v, (int, Fraction)) for v in last.extra[0])


def test_de_casteljau_has_one_row_per_level():
    rows = list(de_casteljau([(0, 0), (1, 2), (3, 3), (4, 0)], Fraction(1, 2)))
    assert [sum(v is not None for v in r.extra) for r in rows] == [4, 3, 2, 1]
    # Level 1 by hand: midpoints of the control polygon's legs.
    assert rows[1].extra[:3] == (
        (Fraction(1, 2), 1),
        (2, Fraction(5, 2)),
        (Fraction(7, 2), Fraction(3, 2)),
    )


def test_cubic_bezier_matches_the_notes_formula():
    p = [(0, 0), (1, 2), (3, 3), (4, 0)]
    for s in bezier(p, 8):
        t = s.extra[0]
        c = [(1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t**2 * (1 - t), t**3]
        assert _point(s) == (
            sum(ci * q[0] for ci, q in zip(c, p, strict=True)),
            sum(ci * q[1] for ci, q in zip(c, p, strict=True)),
        )


# --- B-spline -----------------------------------------------------------------------------------


@st.composite
def spline_cases(draw):
    """Random control points, degree and a valid (possibly unclamped) knot vector."""
    n = draw(st.integers(1, 7))
    p = draw(st.integers(1, n))
    pts = draw(st.lists(st.tuples(coords, coords), min_size=n + 1, max_size=n + 1))
    kind = draw(st.sampled_from(["open", "uniform", "random"]))
    if kind != "random":
        return pts, p, knot_vector(kind, n, p)
    while True:
        raw = sorted(draw(st.lists(st.integers(0, 6), min_size=n + p + 2, max_size=n + p + 2)))
        knots = tuple(Fraction(u, 2) for u in raw)
        try:
            return pts, p, knot_vector(knots, n, p)
        except ValueError:
            continue


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=60)
@given(spline_cases(), st.integers(1, 9))
def test_bspline_basis_is_a_partition_of_unity_on_the_domain(case, samples):
    pts, p, knots = case
    n = len(pts) - 1
    for s in bspline(pts, p, knots, samples):
        w = s.extra[1 : n + 2]
        assert sum(w) == 1, (knots, s.extra[0], w)
        assert all(v >= 0 for v in w)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=60)
@given(spline_cases(), st.integers(1, 9), st.data())
def test_bspline_local_control(case, samples, data):
    pts, p, knots = case
    n = len(pts) - 1
    i = data.draw(st.integers(0, n))
    moved = list(pts)
    moved[i] = (pts[i][0] + 7, pts[i][1] - 5)
    lo, hi = knots[i], knots[i + p + 1]
    for a, b in zip(
        bspline(pts, p, knots, samples), bspline(moved, p, knots, samples), strict=True
    ):
        t = a.extra[0]
        if not lo <= t <= hi:
            assert _point(a) == _point(b), (t, lo, hi)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(points)
def test_clamped_bspline_interpolates_its_end_points(pts):
    n = len(pts) - 1
    for p in range(1, n + 1):
        rows = list(bspline(pts, p, "open", 5))
        assert _point(rows[0]) == pts[0]
        assert _point(rows[-1]) == pts[-1]


def test_right_end_of_the_domain_is_closed():
    # The half-open rule alone gives all-zero basis values at t = u_(n+1); we must not.
    knots = knot_vector("open", 3, 3)
    assert basis(knots, 3, 3, 1) == (0, 0, 0, 1)
    assert span(knots, 3, 1) == 3
    # A non-clamped end: the last span still closes and the values still sum to 1.
    u = knot_vector("uniform", 3, 2)
    assert sum(basis(u, 2, 3, u[4])) == 1


def test_clamped_bspline_without_inner_knots_is_the_bezier_curve():
    pts = [(0, 0), (1, 2), (3, 3), (4, 0)]
    for a, b in zip(bspline(pts, 3, (0, 0, 0, 0, 1, 1, 1, 1), 8), bezier(pts, 8), strict=True):
        assert a.extra[1:] == b.extra[1:]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
def test_bspline_agrees_with_scipy_on_random_inputs():
    # imported here, not with the module: a second of CPU each pytest process would pay
    # collecting the file (every xdist worker does), for this one test
    from scipy import interpolate

    rng = random.Random(20240604)
    for _ in range(200):
        n = rng.randint(1, 9)
        p = rng.randint(1, min(n, 5))
        kind = rng.choice(["open", "uniform", "random"])
        if kind == "random":
            while True:
                raw = sorted(rng.randint(0, 40) for _ in range(n + p + 2))
                try:
                    knots = knot_vector(tuple(Fraction(u, 8) for u in raw), n, p)
                    break
                except ValueError:
                    continue
        else:
            knots = knot_vector(kind, n, p)
        pts = [
            (Fraction(rng.randint(-999, 999), 7), Fraction(rng.randint(-999, 999), 3))
            for _ in range(n + 1)
        ]
        lo, hi = float(knots[p]), float(knots[n + 1])
        ts = [
            Fraction(rng.randint(0, 1000), 1000) * (knots[n + 1] - knots[p]) + knots[p]
            for _ in range(8)
        ]
        ts.append(knots[n + 1])
        ref = interpolate.BSpline(
            np.array([float(u) for u in knots]),
            np.array([[float(x), float(y)] for x, y in pts]),
            p,
            extrapolate=False,
        )
        scale = max(1, *(abs(float(c)) for pt in pts for c in pt))
        for t in ts:
            mine = _combine(basis(knots, p, n, t), pts)
            x = float(t)
            if t == knots[n + 1]:
                # scipy looks up the span [t_n-1, t_n) at the right end, which is empty when the
                # end knot is repeated (a known trap): compare with its left limit.
                x = float(np.nextafter(x, -np.inf))
            theirs = ref(x)
            assert lo <= x <= hi
            assert abs(float(mine[0]) - theirs[0]) <= 1e-12 * scale, (knots, t)
            assert abs(float(mine[1]) - theirs[1]) <= 1e-12 * scale, (knots, t)


def _combine(w, pts):
    return sum(a * p[0] for a, p in zip(w, pts, strict=True)), sum(
        a * p[1] for a, p in zip(w, pts, strict=True)
    )


@pytest.mark.parametrize(
    ("knots", "p", "n", "rule"),
    [
        ((0, 0, 1, 1), 3, 3, "m + 1 = n + p + 2 = 8"),
        ((0, 0, 0, 0, 2, 1, 1, 1), 3, 3, "non-decreasing"),
        ((0, 0, 0, 0, 0, 1, 1, 1), 3, 3, "at most p + 1 = 4 times"),
        ((0, 0, 0, 1, 1, 2, 2, 2), 3, 3, "domain"),
        ("open", 4, 3, "1 <= p <= n"),
        ("open", 0, 3, "1 <= p <= n"),
        ("bogus", 2, 3, "unknown knot vector"),
    ],
)
def test_bad_knot_vectors_name_the_rule(knots, p, n, rule):
    with pytest.raises(ValueError, match=rule.replace("+", r"\+")):
        knot_vector(knots, n, p)


def test_knot_vectors_by_name():
    assert knot_vector("open", 4, 2) == (0, 0, 0, 1, 2, 3, 3, 3)
    assert knot_vector("uniform", 3, 2) == (0, 1, 2, 3, 4, 5, 6)


# --- parametric ---------------------------------------------------------------------------------


def test_parametric_circle_points_lie_on_the_circle():
    for s in parametric("3 + 5*cos(t)", "-2 + 5*sin(t)", 0, 2 * math.pi, 24):
        _, x, y = s.extra
        assert math.isclose(math.hypot(x - 3, y + 2), 5, rel_tol=1e-12)


def test_parametric_parabola_is_exact():
    rows = list(parametric("t", "t**2", -3, 3, 16))
    for s in rows:
        t, x, y = s.extra
        assert isinstance(t, (int, Fraction)) and x == t and y == t * t
    assert rows[1].extra[0] == Fraction(-21, 8)


def test_parametric_line_is_exact_and_ends_on_its_end_points():
    sol = parametric_solution("line", points=(0, 0, 10, 4))
    rows = list(sol.steps())
    assert len(rows) == 11 and rows[0].pixel == (0, 0) and rows[-1].pixel == (10, 4)
    assert all(s.extra[2] == Fraction(2, 5) * s.extra[1] for s in rows)


def test_sample_ts_are_exact_for_rational_ranges():
    assert list(sample_ts(-3, 3, 4)) == [-3, Fraction(-3, 2), 0, Fraction(3, 2), 3]
    ts = list(sample_ts(0.0, 2 * math.pi, 8))
    assert ts[-1] == 2 * math.pi and len(ts) == 9


def test_float_noise_does_not_move_a_pixel():
    # 5 sin(pi/6) is 2.4999999999999996 in floating point; the exact 5/2 rounds up to 3.
    assert 5 * math.sin(math.pi / 6) < 2.5
    assert coord(5 * math.sin(math.pi / 6)) == 3
    assert coord(Fraction(5, 2)) == 3 and coord(-2.5) == -2


# --- rasterizing --------------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(st.lists(st.tuples(st.integers(-15, 15), st.integers(-15, 15)), min_size=1, max_size=12))
def test_curve_pixels_are_8_connected_without_duplicates(samples):
    out = list(curve_pixels(samples))
    assert len(out) == len(set(out))
    assert set(samples) <= set(out)
    assert connected(set(out))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(
    st.tuples(st.integers(-20, 20), st.integers(-20, 20)),
    st.tuples(st.integers(-20, 20), st.integers(-20, 20)),
)
def test_each_join_is_a_bresenham_line(a, b):
    out = list(curve_pixels([a, b]))
    assert out[0] == a and out[-1] == b
    assert len(out) == max(abs(b[0] - a[0]), abs(b[1] - a[1])) + 1
    forward = [a, *(s.pixel for s in bresenham(*a, *b))]
    backward = [
        (-x, -y)
        for x, y in [(-a[0], -a[1]), *(s.pixel for s in bresenham(-a[0], -a[1], -b[0], -b[1]))]
    ]
    assert out in (forward, backward)


def test_a_closed_curve_plots_its_start_once():
    sol = parametric_solution("circle", radius=5, samples=16)
    pix = list(sol.pixels())
    assert len(pix) == len(set(pix))
    assert all(abs(math.hypot(x, y) - 5) < 1 for x, y in pix)


def test_bezier_solution_marks_control_points_and_box_contains_everything():
    pts = [(0, 0), (1, 2), (3, 3), (4, 0)]
    sol = bezier_solution(pts, 8)
    assert sol.marks == tuple(pts)
    x0, y0, x1, y1 = sol.bbox
    assert all(x0 <= x <= x1 and y0 <= y <= y1 for x, y in sol.pixels())
    curve, control = sol.plot.ideal
    assert isinstance(curve, Polyline) and isinstance(control, ControlPolygon)
    assert control.points == [(0.0, 0.0), (1.0, 2.0), (3.0, 3.0), (4.0, 0.0)]
    poly = curve.points
    assert poly[0] == (0.0, 0.0) and poly[-1] == (4.0, 0.0) and len(poly) > 9


def test_bspline_polyline_matches_the_exact_samples():
    pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)]
    sol = bspline_solution(pts, 2, "open", 6)
    (poly,) = [s.points for s in sol.plot.ideal if isinstance(s, Polyline)]
    assert poly[-1] == pytest.approx((5.0, 2.0)) and poly[0] == (0.0, 0.0)


# --- continuity ---------------------------------------------------------------------------------


def _split(pts, t):
    """De Casteljau subdivision: the two halves of a Bezier curve at t (an independent C^n join)."""
    levels = [tuple(pts)]
    while len(levels[-1]) > 1:
        prev = levels[-1]
        levels.append(
            tuple(
                ((1 - t) * p[0] + t * q[0], (1 - t) * p[1] + t * q[1])
                for p, q in itertools.pairwise(prev)
            )
        )
    return [lv[0] for lv in levels], [lv[-1] for lv in reversed(levels)]


def test_continuity_of_a_subdivided_curve_is_c2():
    left, right = _split([(0, 0), (1, 2), (3, 3), (4, 0)], Fraction(1, 2))
    # Each half runs over its own 0 <= t <= 1 at half speed, so the derivatives agree.
    assert continuity_level(left, right) == 2


def test_continuity_levels():
    a = [(0, 0), (1, 1), (2, 0)]
    assert continuity_level(a, [(2, 0), (3, -1), (4, 0)]) == 1  # mirrored tangent, curvature flips
    assert continuity_level(a, [(2, 0), (4, -2), (6, 0)]) == 0  # same direction, twice as long
    assert continuity_level(a, [(2, 1), (3, -1), (4, 0)]) == -1  # gap
    assert continuity_level(a, [(2, 0), (3, -1), (4, -4)]) == 2  # Q2 - 2Q1 + Q0 = P2 - 2P1 + P0


def test_continuity_answer_reports_the_deciding_derivatives():
    r = run(
        "continuity",
        "0",
        "0",
        "1",
        "1",
        "2",
        "0",
        ":",
        "2",
        "0",
        "4",
        "-2",
        "6",
        "0",
        "-f",
        "plain",
    )
    assert r.code == 0, r.err
    assert "A'(1) = n(P2 - P1) = 2*((2, 0) - (1, 1)) = (2, -2)" in r.out
    assert "B'(0) = m(Q1 - Q0) = 2*((4, -2) - (2, 0)) = (4, -4)" in r.out
    assert "continuity at the join: C0 (C0 holds; C1 fails)" in r.out
    assert "G1" in r.out


# --- local control ------------------------------------------------------------------------------


def test_local_control_bezier_moves_everywhere_bspline_only_locally():
    pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2), (7, 1), (8, 3), (10, 0), (11, 2)]
    rows = list(local_control(pts, 4, (5, 8), 2, "open", 14))
    knots = knot_vector("open", 8, 2)
    lo, hi = knots[4], knots[7]
    for s in rows:
        t_z, t_s = s.extra[0], s.extra[4]
        assert s.extra[3] == (0 < t_z < 1)  # Bezier: every inner point moves
        assert s.extra[7] == (lo < t_s < hi)  # B-spline: only inside the support of N_4,2


# --- CLI ----------------------------------------------------------------------------------------

CURVE_COMMANDS = [
    # one command line of each curve and each of its forms, typed as a student types it
    "parametric circle --center 0 0 --radius 5 --samples 16",
    "parametric ellipse --center 0 0 --a 8 --b 4",
    "parametric parabola --t-range -3 3",
    "parametric line 0 0 10 4",
    'parametric custom --x "3*cos(t)" --y "2*sin(t)" --t-range 0 2*pi',
    "bezier 0 0 1 2 3 3 4 0 --samples 8",
    "bezier 0 0 1 2 3 3 4 0 --at 0.5",
    "bspline 0 0 1 2 3 3 4 0 5 2 --degree 2 --knots open",
    "bspline 0 0 1 2 3 3 4 0 --degree 3 --knots 0,0,0,0,1,1,1,1",
]


@pytest.mark.parametrize("command", CURVE_COMMANDS)
@pytest.mark.parametrize("fmt", formats("answer"))
def test_each_curve_command_line_answers_in_every_format(command, fmt):
    import shlex

    r = run(*shlex.split(command), "--format", fmt)
    assert r.code == 0 and r.err == "", r.err
    assert r.out
    if fmt == "plain":
        assert r.out.isascii()


BAD = [
    ("odd coordinates", "bezier 0 0 1 2 3", "odd count"),
    ("too few points", "bezier 0 0", "at least 2 control points"),
    ("too few B-spline points", "bspline 0 0", "at least 2 control points"),
    ("degree too high", "bspline 0 0 1 2 3 3 --degree 3", "1 <= p <= n"),
    ("degree zero", "bspline 0 0 1 2 3 3 --degree 0", "1 <= p <= n"),
    ("knot count", "bspline 0 0 1 2 3 3 4 0 --knots 0,0,1,1", "m + 1 = n + p + 2"),
    ("knot order", "bspline 0 0 1 2 3 3 4 0 --knots 0,0,0,0,1,1,0.5,1", "non-decreasing"),
    ("knot word", "bspline 0 0 1 2 3 3 4 0 --knots clamped", "unknown knot vector"),
    ("bezier t > 1", "bezier 0 0 1 2 3 3 4 0 --at 1.5", "[0, 1]"),
    ("bezier t < 0", "bezier 0 0 1 2 3 3 4 0 --at -0.25", "[0, 1]"),
    ("bspline t outside", "bspline 0 0 1 2 3 3 4 0 --at 2", "domain"),
    ("forbidden name", 'parametric custom --x "os.system(1)" --y t', "attribute access"),
    ("forbidden call", "parametric custom --x open(t) --y t", "function 'open'"),
    ("huge power", "parametric custom --x 9**9**9 --y t", "exponent"),
    ("malformed", "parametric custom --x 3*cos( --y t", "not a valid formula"),
    ("domain error", "parametric custom --x log(t) --y t --t-range -1 1", "undefined"),
    ("bad t range", "parametric custom --x t --y t --t-range 0 x", "unknown name 'x'"),
    ("zero samples", "bezier 0 0 1 2 --samples 0", "at least 1"),
    ("negative samples", "parametric circle --radius 5 --samples -4", "at least 1"),
    ("zero samples bspline", "bspline 0 0 1 2 3 3 4 0 --samples 0", "at least 1"),
    ("negative radius", "parametric circle --radius -1", "positive"),
    ("continuity separator", "continuity 0 0 1 1 2 0 2 0 3 -1", "separated by ':'"),
    ("continuity short", "continuity 0 0 1 1 : 1 1", "at least 2 control points"),
    ("move index", "local-control 0 0 1 1 2 0 3 3 --move 9 1 1", "index"),
]


@pytest.mark.parametrize(("case", "command", "words"), BAD, ids=[b[0] for b in BAD])
def test_bad_input_is_one_line_exit_2_nothing_on_stdout(case, command, words):
    import shlex

    assert_refused(run(*shlex.split(command), "--format", "plain"), words)


# --- the basis from a degree and knots alone -------------------------------------------------


def test_bspline_basis_from_degree_and_knots_alone():
    from scanconv import _api

    sol = _api.bspline_basis(None, 2, [0, "1/4", "1/2", "3/4", 1], 8)
    rows = list(sol.tables[0].rows())
    assert [r[1] for r in rows] == [Fraction(k, 8) for k in range(9)]  # the whole knot range
    n0 = [r[2] for r in rows]
    assert n0 == [0, Fraction(1, 8), Fraction(1, 2), Fraction(3, 4), Fraction(1, 2),
                  Fraction(1, 8), 0, 0, 0]  # fmt: skip
    assert rows[4][-1] == 1  # the domain [u_2, u_2] = {1/2}: the sum is 1 there
    r = run("bspline", "--basis", "--degree", "2", "--knots", "0,.25,.5,.75,1", "-f", "json")
    assert r.code == 0, r.err


def test_bspline_basis_alone_needs_explicit_knots_and_the_curve_needs_points():
    from .helpers import assert_refused

    assert_refused(run("bspline", "--basis", "--degree", "2"), "--knots", "explicit knot list")
    assert_refused(run("bspline", "--degree", "2"), "control points")
    assert_refused(
        run("bspline", "--basis", "--degree", "2", "--knots", "0,1,0.5,2"), "non-decreasing"
    )


def test_the_degree_limit_at_its_edge():
    # degree MAX_DEGREE = 10 with n = 10: the open knot vector has n + p + 2 = 22 knots, one
    # inner span (n - p + 1 = 1): p + 1 = 11 zeros, then 11 ones; degree 11 is refused
    assert knot_vector("open", MAX_DEGREE, MAX_DEGREE) == (0,) * 11 + (1,) * 11
    with pytest.raises(InputError, match="too high"):
        knot_vector("open", MAX_DEGREE + 1, MAX_DEGREE + 1)


def test_the_float_basis_of_the_uniform_quadratic_by_hand():
    # uniform knots 0..5, p = 2: at the middle of a span the three non-zero basis functions
    # are (1/2)(1/2)^2 = 1/8, 3/4 and 1/8; at t = 2 (a knot) they are 1/2, 1/2, 0
    assert basis_float((0, 1, 2, 3, 4, 5), 2, 2, 2.5) == [0.125, 0.75, 0.125]
    assert basis_float((0, 1, 2, 3, 4, 5), 2, 2, 2.0) == [0.5, 0.5, 0.0]


def test_bspline_samples_count_only_the_domains_spans():
    # uniform knots 0..8, p = 3, n = 4: the domain [u3, u5] has 2 spans; at least 16 steps in
    # all with the same power of two per span: 8 a span, 16 (the spans outside the domain,
    # [u5, u6] and on, do not count: 3 spans would give 8 x 3 = 24)
    assert bspline_samples(tuple(range(9)), 3, 4) == 16
    # one span (n = p): 16 a span
    assert bspline_samples(tuple(range(8)), 3, 3) == 16
