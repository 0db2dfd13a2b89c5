"""Cyrus-Beck clipping (scanconv.algorithms.cyrus_beck): by hand, and equal to Liang-Barsky on
every rectangle (an independent implementation in scanconv.algorithms.clipping)."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from scanconv.algorithms.clipping import liang_barsky
from scanconv.algorithms.cyrus_beck import check_convex, cyrus_beck
from scanconv.answers.process.clip.cyrus_beck import cyrus_beck_solution
from scanconv.core.checks import InputError

C = st.integers(-30, 30)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=200)
@given(p0=st.tuples(C, C), p1=st.tuples(C, C), a=st.tuples(C, C), b=st.tuples(C, C))
def test_equals_liang_barsky_on_rectangles(p0, p1, a, b) -> None:
    xmin, xmax = sorted((a[0], b[0]))
    ymin, ymax = sorted((a[1], b[1]))
    assume(xmin < xmax and ymin < ymax and p0 != p1)
    window = [(xmin, ymin), (xmax, ymin), (xmax, ymax), (xmin, ymax)]
    cb = cyrus_beck(p0, p1, window)
    lb = liang_barsky(p0, p1, (xmin, ymin, xmax, ymax))
    assert cb.accepted == lb.accepted
    assert cb.segment == lb.segment
    if lb.accepted:
        assert (cb.rows[-1].t_enter, cb.rows[-1].t_leave) == (lb.rows[-1].u1, lb.rows[-1].u2)
    # the window given clockwise: the same answer
    assert cyrus_beck(p0, p1, window[::-1]).segment == cb.segment


def test_inward_normals_flip_the_signs_not_t() -> None:
    window = [(0, 0), (4, 0), (4, 4), (0, 4)]
    out = cyrus_beck((-2, 1), (6, 3), window)
    inward = cyrus_beck((-2, 1), (6, 3), window, normals="inward")
    assert [r.t for r in out.rows] == [r.t for r in inward.rows]
    assert [r.n_dot_d for r in out.rows] == [-r.n_dot_d for r in inward.rows]
    assert out.segment == inward.segment


def test_a_triangle_by_hand() -> None:
    # window (0,0), (8,0), (0,8) (counter-clockwise); segment (-1, 2) to (9, 2): D = (10, 0)
    # edge (0,0)-(8,0): N = (0,-8), N.D = 0, N.(P0-E) = -16 < 0: parallel, inside
    # edge (8,0)-(0,8): N = (8,8), N.D = 80 (leaving), N.(P0-E) = 8*(-9) + 8*2 = -56, t = 56/80
    # edge (0,8)-(0,0): N = (-8,0), N.D = -80 (entering), N.(P0-E) = 8, t = 8/80 = 1/10
    r = cyrus_beck((-1, 2), (9, 2), [(0, 0), (8, 0), (0, 8)])
    assert [row.kind for row in r.rows] == ["parallel, inside", "leaving", "entering"]
    assert [row.t for row in r.rows] == [None, Fraction(7, 10), Fraction(1, 10)]
    assert r.segment == ((0, 2), (6, 2))


def test_rejections() -> None:
    square = [(0, 0), (4, 0), (4, 4), (0, 4)]
    assert cyrus_beck((5, 1), (6, 3), square).accepted is False  # tE > tL
    assert cyrus_beck((-1, 5), (6, 5), square).accepted is False  # parallel, outside


def test_truncated_ends() -> None:
    r = cyrus_beck((-2, 1), (6, 3), [(0, 0), (4, 0), (4, 4), (0, 4)], ends="truncated")
    assert r.segment == ((0, 1), (4, 2))


@pytest.mark.parametrize(
    "window",
    [
        [(0, 0), (4, 0)],
        [(0, 0), (4, 0), (1, 1), (0, 4)],  # concave
        [(0, 0), (1, 1), (2, 2)],  # no area
    ],
)
def test_the_window_must_be_convex(window) -> None:
    with pytest.raises(InputError) as info:
        check_convex(window)
    assert info.value.param == "window"


def test_answer_states_the_result() -> None:
    sol = cyrus_beck_solution(-2, 1, 6, 3, [0, 0, 4, 0, 4, 4, 0, 4])
    assert sol.data["accepted"] and sol.data["t_enter"] == Fraction(1, 4)
    assert len(list(sol.tables[0].rows())) == 4
    assert "rejected" in cyrus_beck_solution(5, 1, 6, 3, [0, 0, 4, 0, 4, 4, 0, 4]).derived[-1].key


UNIT = [(0, 0), (1, 0), (1, 1), (0, 1)]


@pytest.mark.parametrize(
    ("p0", "p1", "segment"),
    [
        # parallel to an edge of the unit square, one unit outside: N.(P0 - E) = 1 > 0, rejected
        ((-1, 2), (3, 2), None),
        ((2, -1), (2, 3), None),
        ((-1, -1), (3, -1), None),
        ((-1, -1), (-1, 3), None),
        # on the top edge's line: N.(P0 - E) = 0, inside; the edge's part is kept
        ((-1, 1), (3, 1), ((0, 1), (1, 1))),
    ],
)
def test_a_line_parallel_to_an_edge_by_hand(p0, p1, segment):
    r = cyrus_beck(p0, p1, UNIT)
    assert r.accepted == (segment is not None)
    assert r.segment == segment
