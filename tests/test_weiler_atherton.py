"""Weiler-Atherton clipping (scanconv.algorithms.weiler_atherton): by hand, and the area it
keeps equal to Sutherland-Hodgman's (an independent algorithm) against rectangles."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from scanconv.algorithms.clipping import polygon_area, sutherland_hodgman
from scanconv.algorithms.weiler_atherton import weiler_atherton
from scanconv.answers.process.clip.weiler_atherton import weiler_atherton_solution
from scanconv.core.checks import InputError

U_SHAPE = [(0, 0), (8, 0), (8, 8), (6, 8), (6, 2), (2, 2), (2, 8), (0, 8)]


def test_a_u_clipped_to_its_top_is_two_polygons() -> None:
    # the strip y >= 4 cuts both prongs: I1 (8, 4) in, I2 (6, 4) out, I3 (2, 4) in, I4 (0, 4)
    r = weiler_atherton(U_SHAPE, [(-1, 4), (9, 4), (9, 9), (-1, 9)])
    assert r.polygons == (((8, 4), (8, 8), (6, 8), (6, 4)), ((2, 4), (2, 8), (0, 8), (0, 4)))
    assert [e.label for e in r.subject if e.crossing is not None] == ["in", "out", "in", "out"]


def test_no_crossing() -> None:
    square = [(0, 0), (4, 0), (4, 4), (0, 4)]
    big = [(-1, -1), (5, -1), (5, 5), (-1, 5)]
    assert weiler_atherton(square, big).polygons == (tuple(square),)
    assert weiler_atherton(big, square).polygons == (tuple(square),)
    assert weiler_atherton(square, [(10, 10), (11, 10), (11, 11)]).polygons == ()


def test_clockwise_input_is_reversed_and_said() -> None:
    r = weiler_atherton(U_SHAPE[::-1], [(-1, 4), (9, 4), (9, 9), (-1, 9)])
    assert r.reversed == ("subject",)
    assert sum(polygon_area(p) for p in r.polygons) == 16  # two prongs, 2 x 4 each


@pytest.mark.parametrize(
    ("subject", "clip", "polygons", "labels"),
    [
        # worked by hand: a triangle's vertex (4, 2) on the square's left edge x = 4, from
        # outside: they meet at that point only, and the clipped region is empty
        ([(0, 0), (4, 2), (0, 4)], [(4, 0), (8, 0), (8, 4), (4, 4)], [], ["touch"]),
        # two triangles along y = 0 from (2, 0) to (4, 0); the clip triangle's edge
        # y = 2 (x - 2) / 3 meets x = 4 at (4, 4/3): the region is (2, 0), (4, 0), (4, 4/3)
        ([(0, 0), (4, 0), (4, 4)], [(2, 0), (8, 0), (8, 4)],
         [[(2, 0), (4, 0), (4, Fraction(4, 3))]], ["in", "touch", "out"]),
        # a triangle along the square's top edge from outside: empty
        ([(2, 4), (6, 4), (6, 8)], [(0, 0), (4, 0), (4, 4), (0, 4)], [], ["touch", "touch"]),
        # x <= 2, y >= 4 - x, y <= 6 against x <= 2, y >= 0, y <= x + 2: along x = 2 from
        # (2, 2) to (2, 4), and 4 - x = x + 2 at x = 1: the triangle (1, 3), (2, 2), (2, 4)
        ([(2, 2), (2, 6), (-2, 6)], [(2, 0), (2, 4), (-2, 0)],
         [[(1, 3), (2, 2), (2, 4)]], ["touch", "out", "in"]),
        # the square's corners on the diamond |x - 2| + |y - 2| = 4: the square, untouched
        ([(0, 0), (4, 0), (4, 4), (0, 4)], [(2, -2), (6, 2), (2, 6), (-2, 2)],
         [[(0, 0), (4, 0), (4, 4), (0, 4)]], ["touch"] * 4),
        # a triangle on the square's bottom edge: the triangle
        ([(0, 0), (6, 0), (6, 6), (0, 6)], [(0, 0), (6, 0), (3, 3)],
         [[(0, 0), (6, 0), (3, 3)]], ["in", "out"]),
    ],
)  # fmt: skip
def test_polygons_that_touch_are_clipped(subject, clip, polygons, labels) -> None:
    """A vertex on an edge, vertices together, edges along each other (published questions
    have them; they were refused): each by hand, its meeting points' labels along the subject."""
    r = weiler_atherton(subject, clip)
    assert [list(p) for p in r.polygons] == polygons
    assert [e.label for e in r.subject if e.crossing is not None] == labels


C = st.integers(-9, 9)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=150)
@given(
    pts=st.lists(st.tuples(C, C), min_size=3, max_size=6, unique=True),
    box=st.tuples(C, C, C, C),
)
def test_the_area_kept_equals_sutherland_hodgman(pts, box) -> None:
    """Against a rectangle the clipped region's area is the same whichever algorithm clips it
    (Sutherland-Hodgman keeps degenerate joins, which add no area)."""
    xmin, xmax = sorted(box[::2])
    ymin, ymax = sorted(box[1::2])
    assume(xmin < xmax and ymin < ymax)
    rect = [(xmin, ymin), (xmax, ymin), (xmax, ymax), (xmin, ymax)]
    assume(polygon_area(pts) != 0 and _simple(pts))
    # move the subject off the integer grid so no vertex lies on a window edge
    shifted = [(x + Fraction(1, 7), y + Fraction(1, 11)) for x, y in pts]
    try:
        r = weiler_atherton(shifted, rect)
    except InputError:
        assume(False)
    ccw = shifted if polygon_area(shifted) > 0 else shifted[::-1]
    sh = sutherland_hodgman(ccw, (xmin, ymin, xmax, ymax))[-1].outputs
    expected = abs(polygon_area(sh)) if len(sh) >= 3 else 0
    assert sum(abs(polygon_area(p)) for p in r.polygons) == expected


def _simple(pts) -> bool:
    n = len(pts)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    for i in range(n):
        for j in range(i + 1, n):
            if j in (i, (i + 1) % n) or i == (j + 1) % n:
                continue
            a, b, c, d = pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n]
            d1, d2 = cross(c, d, a), cross(c, d, b)
            d3, d4 = cross(a, b, c), cross(a, b, d)
            if (d1 * d2 <= 0) and (d3 * d4 <= 0):
                return False
    return True


def test_answer_lists_and_walks() -> None:
    sol = weiler_atherton_solution(
        [0, 0, 8, 0, 8, 8, 6, 8, 6, 2, 2, 2, 2, 8, 0, 8], [-1, 4, 9, 4, 9, 9, -1, 9]
    )
    assert len(sol.data["polygons"]) == 2
    kinds = [r[2] for r in sol.tables[0].rows()]
    assert kinds.count("in (entering)") == 2 and kinds.count("out (leaving)") == 2


def test_the_diagonal_overlap_is_empty() -> None:
    """The edge (2, 2)-(6, 6) along the clip triangle's diagonal (0, 0)-(4, 4), the subject
    below it and the clip above: they share a segment and no area."""
    r = weiler_atherton([(2, 2), (6, 6), (6, 2)], [(0, 0), (4, 4), (0, 4)])
    assert r.polygons == ()
    assert {e.point for e in r.clip if e.crossing is not None} == {(2, 2), (4, 4)}


@st.composite
def star_polygons(draw):
    """A simple polygon (concave allowed) on a small integer grid: points around their
    centre in order of angle (vertices on the other polygon's edges are common there)."""
    import math

    pts = draw(st.lists(st.tuples(st.integers(-5, 5), st.integers(-5, 5)), min_size=3,
                        max_size=8, unique=True))  # fmt: skip
    cx, cy = sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts)
    angles = [math.atan2(y - cy, x - cx) for x, y in pts]
    assume(len(set(angles)) == len(angles))
    ordered = [p for _, p in sorted(zip(angles, pts, strict=True))]
    assume(polygon_area(ordered) != 0 and _simple(ordered))
    return ordered


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=400)
@given(subject=star_polygons(), clip=star_polygons())
def test_the_region_is_the_intersection_shapely_computes(subject, clip) -> None:
    """Any two simple polygons on a small integer grid, where vertices on edges and shared
    edges are common: the output polygons cover exactly the intersection a polygon library
    computes (shapely, test-only)."""
    shapely_geometry = pytest.importorskip("shapely.geometry")
    from shapely.ops import unary_union

    r = weiler_atherton(subject, clip)
    pieces = [shapely_geometry.Polygon([(float(x), float(y)) for x, y in p]).buffer(0)
              for p in r.polygons]  # fmt: skip
    got = unary_union(pieces) if pieces else shapely_geometry.Polygon()
    want = shapely_geometry.Polygon(subject).intersection(shapely_geometry.Polygon(clip))
    assert got.symmetric_difference(want).area < 1e-9
    assert sum(abs(polygon_area(p)) for p in r.polygons) == pytest.approx(want.area, abs=1e-9)
