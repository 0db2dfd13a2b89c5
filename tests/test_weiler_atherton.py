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


def test_a_vertex_on_an_edge_is_refused_by_name() -> None:
    with pytest.raises(InputError, match=r"at a vertex, \(4, 2\)"):
        weiler_atherton([(0, 0), (4, 2), (0, 4)], [(4, 0), (8, 0), (8, 4), (4, 4)])
    with pytest.raises(InputError, match="overlap"):
        weiler_atherton([(0, 0), (4, 0), (4, 4)], [(2, 0), (8, 0), (8, 4)])


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


SQUARE = [(0, 0), (4, 0), (4, 4), (0, 4)]


@pytest.mark.parametrize(
    ("subject", "clip", "message"),
    [
        # along the square's top edge's line from (2, 4): it first meets the right edge at its
        # end, the corner (4, 4) (u = 1 on that edge), named before the overlap
        ([(2, 4), (6, 4), (6, 8)], SQUARE, r"at a vertex, \(4, 4\)"),
        # the edge (2, 2)-(6, 6) on the diagonal edge (0, 0)-(4, 4) of the clip triangle
        ([(2, 2), (6, 6), (6, 2)], [(0, 0), (4, 4), (0, 4)], r"overlap along \(6, 6\)-\(2, 2\)"),
        # a vertical overlap: x = 2 from y = 2 to 6 against the clip's edge x = 2, y = 0 to 4
        ([(2, 2), (2, 6), (-2, 6)], [(2, 0), (2, 4), (-2, 0)], r"overlap along \(2, 2\)-\(2, 6\)"),
    ],
)
def test_a_touch_or_an_overlap_is_refused_by_name(subject, clip, message) -> None:
    with pytest.raises(InputError, match=message):
        weiler_atherton(subject, clip)
