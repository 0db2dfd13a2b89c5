"""2D transformations, exact radicals and the window-to-viewport mapping.

Properties (hypothesis): the radicals form a field (x·(1/x) = 1 exactly); composing a random
transformation with its inverse gives the identity exactly; sin and cos at multiples of 15
degrees satisfy cos² + sin² = 1 exactly and agree with floating point; the viewport mapping
sends the window's corners to the viewport's corners. Textbook examples value by value.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.radical import Radical, floor_exact, round_half_up_exact, simplify
from scanconv.algorithms.transform import (
    IDENTITY,
    REFLECTIONS,
    apply,
    compose,
    cos_sin,
    inverse,
    map_to_viewport,
    matmul,
    reflection_through_origin,
    rotation,
    translation,
    viewport_scale,
)
from scanconv.answers.process._shared import MAX_POINTS, text
from scanconv.answers.process.transform import (
    MAX_TRANSFORMS,
    parse_angle,
    parse_transforms,
    transform_solution,
)
from scanconv.answers.process.viewport import viewport_solution
from scanconv.core.checks import InputError
from scanconv.render import Format, Options, render

from .helpers import assert_refused, run

small = st.fractions(min_value=-12, max_value=12, max_denominator=5)
nonzero = small.filter(lambda v: v != 0)
radicals = st.builds(Radical, small, small, small, small)
size = st.fractions(min_value=Fraction(1, 5), max_value=30, max_denominator=5)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=100, deadline=None)
@given(radicals, radicals)
def test_radicals_are_a_field(a, b):
    assert (a + b) - b == a
    assert a * b == b * a
    if simplify(b) != 0:
        assert (a * b) / b == a
        assert simplify(b * (1 / b)) == 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=100, deadline=None)
@given(radicals)
def test_floor_is_exact(a):
    f = floor_exact(a)
    assert f <= float(a) + 1e-9 and float(a) < f + 1 + 1e-9
    assert round_half_up_exact(a) == floor_exact(a + Fraction(1, 2))


_OPS = st.one_of(
    st.tuples(st.just("translate"), small, small).map(lambda t: f"translate {t[1]} {t[2]}"),
    st.tuples(st.just("scale"), nonzero, nonzero, small, small).map(
        lambda t: f"scale {t[1]} {t[2]} about {t[3]} {t[4]}"
    ),
    st.tuples(st.integers(-24, 24), small, small).map(
        lambda t: f"rotate {15 * t[0]} about {t[1]} {t[2]}"
    ),
    st.tuples(st.integers(-360, 360)).map(lambda t: f"rotate {t[0]}"),
    st.sampled_from(["x-axis", "y-axis", "origin", "y=x", "y=-x"]).map(lambda a: f"reflect {a}"),
    st.tuples(small, small, nonzero, small).map(
        lambda t: f"reflect line {t[0]} {t[1]} {t[0] + t[2]} {t[1] + t[3]}"
    ),
    st.tuples(small, small)
    .filter(lambda t: t[0] * t[1] != 1)
    .map(lambda t: f"shear {t[0]} {t[1]}"),
)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=100, deadline=None)
@given(st.lists(_OPS, min_size=1, max_size=5))
def test_composing_with_the_inverse_gives_the_identity(ops):
    stages = parse_transforms(ops)
    m = compose([compose([f.matrix for f in s.factors]) for s in stages])
    inv = inverse(m)
    assert matmul(m, inv) == IDENTITY
    assert matmul(inv, m) == IDENTITY


@settings(max_examples=60, deadline=None)
@given(st.integers(-48, 48))
def test_sin_and_cos_at_multiples_of_15_degrees_are_exact(k):
    c, s, exact = cos_sin(Fraction(15 * k))
    assert exact
    assert simplify(c * c + s * s) == 1
    assert math.isclose(float(c), math.cos(math.radians(15 * k)), abs_tol=1e-12)
    assert math.isclose(float(s), math.sin(math.radians(15 * k)), abs_tol=1e-12)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=100, deadline=None)
@given(small, small, size, size, small, small, size, size)
def test_the_window_corners_go_to_the_viewport_corners(wx, wy, ww, wh, vx, vy, vw, vh):
    w, v = (wx, wy, wx + ww, wy + wh), (vx, vy, vx + vw, vy + vh)
    for cx, cy in ((0, 1), (2, 1), (2, 3), (0, 3)):
        assert map_to_viewport((w[cx], w[cy]), w, v) == (v[cx], v[cy])
    centre = ((w[0] + w[2]) / 2, (w[1] + w[3]) / 2)
    assert map_to_viewport(centre, w, v) == ((v[0] + v[2]) / 2, (v[1] + v[3]) / 2)


# --- textbook examples ------------------------------------------------------------------------

R2 = Radical(0, 1)  # sqrt(2)


def test_ugc_net_rotation_of_a_triangle_by_45_degrees_about_a_point():
    """UGC-NET CSE, June 2015, paper III, question 14 (https://gateoverflow.in/61157, a
    Schaum's-outline problem): the triangle A(0, 0), B(1, 1), C(5, 2) rotated 45° about
    P(-1, -1) gives A'(-1, √2 - 1), B'(-1, 2√2 - 1), C'(3√2/2 - 1, 9√2/2 - 1) (option 3, with
    the correction of C' the discussion makes). About the origin: A'(0, 0), B'(0, √2),
    C'(3√2/2, 7√2/2)."""
    pts = [0, 0, 1, 1, 5, 2]
    a = transform_solution(pts, "rotate 45").data["after"]
    assert a == [[0, 0], [0, text(R2)], [text(R2 * Fraction(3, 2)), text(R2 * Fraction(7, 2))]]
    b = transform_solution(pts, "rotate 45 about -1 -1").data["after"]
    assert b == [
        [-1, text(R2 - 1)],
        [-1, text(2 * R2 - 1)],
        [text(R2 * Fraction(3, 2) - 1), text(R2 * Fraction(9, 2) - 1)],
    ]
    assert b[2] == ["-1 + 3*sqrt(2)/2", "-1 + 9*sqrt(2)/2"]


def test_hearn_baker_pivot_rotation_matrix():
    """Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 5-2: rotation about a
    pivot (xr, yr) is T(xr, yr)·R(θ)·T(-xr, -yr) = [[cos θ, -sin θ, xr(1 - cos θ) + yr sin θ],
    [sin θ, cos θ, yr(1 - cos θ) - xr sin θ], [0, 0, 1]]."""
    for deg, xr, yr in ((30, 2, 1), (90, 2, 1), (135, -3, 5), (20, 4, -2)):
        c, s, _ = cos_sin(Fraction(deg))
        (stage,) = parse_transforms([f"rotate {deg} about {xr} {yr}"])
        m = compose([f.matrix for f in stage.factors])
        expected = (
            (c, -s, simplify(xr * (1 - c) + yr * s)),
            (s, c, simplify(yr * (1 - c) - xr * s)),
            (0, 0, 1),
        )
        assert m == tuple(tuple(simplify(v) for v in r) for r in expected)


def test_the_brief_example_rotate_about_a_point_then_translate():
    sol = transform_solution(
        [0, 0, 4, 0, 4, 3], ["rotate", "90", "about", "2", "1", "translate", "3", "0"]
    )
    assert sol.data["matrix"] == [[0, -1, 6], [1, 0, -1], [0, 0, 1]]
    assert sol.data["after"] == [[6, -1], [6, 3], [3, 3]]


def test_reflections():
    assert reflection_through_origin(1, 1) == REFLECTIONS["y=x"]
    assert reflection_through_origin(1, -1) == REFLECTIONS["y=-x"]
    assert reflection_through_origin(1, 0) == REFLECTIONS["x-axis"]
    assert reflection_through_origin(0, 1) == REFLECTIONS["y-axis"]
    # about y = 2x + 1 (through (0, 1) and (1, 3)): (1, 0) goes to (-7/5, 6/5)
    sol = transform_solution([1, 0], "reflect line 0 1 1 3")
    assert sol.data["after"] == [[Fraction(-7, 5), Fraction(6, 5)]]
    twice = parse_transforms(["reflect line 0 1 1 3", "reflect line 0 1 1 3"])
    assert compose([compose([f.matrix for f in s.factors]) for s in twice]) == IDENTITY


def test_other_angles_are_rounded_to_six_decimals_and_said_so():
    sol = transform_solution([1, 0], "rotate 20")
    assert sol.data["after"] == [[Fraction("0.939693"), Fraction("0.342020")]]
    assert any("6 decimals" in n for n in sol.notes)
    c, _s, exact = cos_sin(Fraction(20))
    assert not exact and abs(float(c) - math.cos(math.radians(20))) < 5e-7


@pytest.mark.parametrize(
    ("word", "degrees"),
    [("90", 90), ("-30", -30), ("12.5deg", Fraction(25, 2)), ("pi/4", 45), ("3pi/2", 270),
     ("-pi/6", -30), ("2*pi/3", 120), ("π", 180), ("1.5rad", None)],
)  # fmt: skip
def test_angles(word, degrees):
    assert parse_angle(word)[0] == degrees


def test_rotation_by_pi_over_3_is_exact():
    (stage,) = parse_transforms(["rotate pi/3"])
    assert stage.factors[0].matrix == rotation(Fraction(1, 2), Radical(0, 0, Fraction(1, 2)))


def test_viewport_example_with_distortion():
    """Window (0, 0)-(10, 10) to viewport (100, 100)-(150, 200): sx = 5, sy = 10, so the
    picture is stretched vertically by sy/sx = 2."""
    assert viewport_scale((0, 0, 10, 10), (100, 100, 150, 200)) == (5, 10, 100, 100)
    sol = viewport_solution([5, 5], (0, 0, 10, 10), (100, 100, 150, 200))
    assert sol.data["mapped"] == [[125, 150]]
    assert "distorted" in next(q.text for q in sol.derived if q.key == "aspect")
    same = viewport_solution([], (0, 0, 4, 2), (0, 0, 8, 4))
    assert "no distortion" in next(q.text for q in same.derived if q.key == "aspect")


@pytest.mark.parametrize("fmt", list(Format)[1:])
def test_every_format_renders(fmt):
    for sol in (
        transform_solution([0, 0, 1, 1, 5, 2], "rotate 45 about -1 -1", inverse_too=True),
        transform_solution([0, 0, 4, 0, 4, 3], "scale 2 1/2 about 1 1, shear 1 0, reflect y=-x"),
        viewport_solution([0, 0, 2, 1], (0, 0, 4, 4), (10, 10, 20, 16)),
    ):
        out = "".join(str(c) for c in render(sol, fmt, Options()))
        assert out
        if fmt is Format.plain:
            assert out.isascii()


# --- bad input --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("call", "param", "words"),
    [
        (lambda: transform_solution([0, 0], "scale 0 1", inverse_too=True), "inverse", "singular"),
        (lambda: transform_solution([0, 0], "shear 1 1", inverse_too=True), "inverse", "det M"),
        (lambda: transform_solution([0, 0], "twist 30"), "transforms", "unknown transformation 'twist'"),
        (lambda: transform_solution([0, 0], "rotate"), "transforms", "needs an angle"),
        (lambda: transform_solution([0, 0], "rotate north"), "transforms", "not an angle"),
        (lambda: transform_solution([0, 0], "translate 1"), "transforms", "needs 2 numbers"),
        (lambda: transform_solution([0, 0], "about 1 1"), "transforms", "must follow"),
        (lambda: transform_solution([0, 0], "reflect z"), "transforms", "cannot reflect"),
        (lambda: transform_solution([0, 0], "reflect line 1 1 1 1"), "transforms", "two different"),
        (lambda: transform_solution([0, 0], ""), "transforms", "no transformation"),
        (lambda: transform_solution([0, 0], "translate 1 1 " * (MAX_TRANSFORMS + 1)), "transforms", f"at most {MAX_TRANSFORMS}"),
        (lambda: transform_solution([0] * (2 * MAX_POINTS + 2), "translate 1 1"), "points", f"at most {MAX_POINTS}"),
        (lambda: transform_solution([0, 0, 1], "translate 1 1"), "points", "odd"),
        (lambda: transform_solution([], "translate 1 1"), "points", "at least one"),
        (lambda: viewport_solution([], (0, 0, 1, 1), (5, 5, 5, 9)), "viewport", "xmin < xmax"),
        (lambda: viewport_solution([], (0, 0, 1, 1), (5, 5, 9, 5)), "viewport", "ymin < ymax"),
        (lambda: viewport_solution([], (0, 0, 0, 1), (5, 5, 9, 9)), "window", "xmin < xmax"),
    ],
)  # fmt: skip
def test_bad_input_is_an_input_error(call, param, words):
    with pytest.raises(InputError, match=words) as err:
        call()
    assert err.value.param == param
    assert "--" not in str(err.value)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_limits_are_inclusive():
    assert transform_solution([0, 0], "translate 1 1 " * MAX_TRANSFORMS).data["after"] == [[20, 20]]
    assert len(transform_solution([1] * (2 * MAX_POINTS), "rotate 30").data["after"]) == MAX_POINTS


def test_apply_and_translation():
    assert apply(translation(3, -1), (1, 1)) == (4, 0)


# --- the command line -------------------------------------------------------------------------


def test_transform_words_keep_their_order_and_both_point_spellings():
    a = run(
        "transform",
        "0",
        "0",
        "4",
        "0",
        "4",
        "3",
        "--rotate",
        "90",
        "--about",
        "2",
        "1",
        "--translate",
        "3",
        "0",
        "-f",
        "json",
    )
    b = run(
        "transform",
        "--points",
        "0",
        "0",
        "4",
        "0",
        "4",
        "3",
        "--rotate=90",
        "--about",
        "2",
        "1",
        "--translate",
        "3",
        "0",
        "-f",
        "json",
    )
    assert a.code == b.code == 0, (a.err, b.err)
    assert json.loads(a.out)["after"] == json.loads(b.out)["after"] == [[6, -1], [6, 3], [3, 3]]
    swapped = run(
        "transform",
        "0",
        "0",
        "4",
        "0",
        "4",
        "3",
        "--translate",
        "3",
        "0",
        "--rotate",
        "90",
        "--about",
        "2",
        "1",
        "-f",
        "json",
    )
    assert json.loads(swapped.out)["after"] == [[3, 2], [3, 6], [0, 6]]  # order matters


def test_negative_numbers_and_radians_on_the_command_line():
    r = run("transform", "-1", "-1", "--rotate", "-pi/2", "--about", "-1", "0", "-f", "json")
    assert r.code == 0, r.err
    assert json.loads(r.out)["after"] == [[-2, 0]]


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("transform", "0", "0", "--scale", "0", "1", "--inverse"), ("--inverse", "singular")),
        (("transform", "0", "0", "--twist", "30"), ("No such option: --twist",)),
        (("transform", "0", "0", "--rotate", "30", "twist"), ("unknown transformation 'twist'",)),
        (("transform", "0", "0", "1", "--translate", "1", "1"), ("odd",)),
        (("transform", "0", "0"), ("no transformation",)),
        (("viewport", "--window", "0", "0", "1", "1", "--viewport", "5", "5", "5", "9"), ("--viewport", "xmin < xmax")),
        (("viewport", "--window", "0", "3", "1", "3", "--viewport", "5", "5", "6", "9"), ("--window", "ymin < ymax")),
    ],
)  # fmt: skip
def test_bad_input_on_the_command_line_is_one_line_and_exit_2(args, words):
    assert_refused(run(*args), *words)


def test_viewport_defaults_to_the_window_corners():
    r = run(
        "viewport",
        "--window",
        "0",
        "0",
        "10",
        "10",
        "--viewport",
        "100",
        "100",
        "150",
        "200",
        "-f",
        "json",
    )
    assert json.loads(r.out)["mapped"] == [[100, 100], [150, 100], [150, 200], [100, 200]]


@pytest.mark.parametrize(
    ("closed", "pixels"),
    [
        # the corner (0, 0) -> (2, 0) -> (2, 2): each vertex, then the edge's pixels between
        (False, [(0, 0), (2, 0), (1, 0), (2, 2), (2, 1)]),
        # closed: the edge (2, 2) -> (0, 0) adds (1, 1)
        (True, [(0, 0), (2, 0), (1, 0), (2, 2), (2, 1), (1, 1)]),
    ],
)
def test_outline_of_an_open_and_a_closed_polyline(closed, pixels):
    from scanconv.algorithms.transform import outline

    assert list(outline([(0, 0), (2, 0), (2, 2)], closed=closed)) == pixels
    # two vertices are one edge, closed or not
    assert list(outline([(0, 0), (3, 0)], closed=closed)) == [(0, 0), (3, 0), (1, 0), (2, 0)]
