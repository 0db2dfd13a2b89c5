"""Midpoint subdivision clipping (scanconv.algorithms.midpoint_clip): by hand, and against
Liang-Barsky's exact segment (an independent computation): with rounded midpoints the visible
part found is within one unit of the exact one at each end."""

from __future__ import annotations

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from scanconv.algorithms.clipping import liang_barsky
from scanconv.algorithms.midpoint_clip import subdivide, visible
from scanconv.answers.process.clip.midpoint import midpoint_clip_solution

C = st.integers(-40, 40)
WINDOW = (0, 0, 20, 20)


def test_by_hand() -> None:
    # (-4, 2)-(4, 2) against (0,0)-(8,8): split at (0, 2): the right half (0,2)-(4,2) is
    # inside; the left half splits at (-2, 2) (outside, reject), then (-1, 2): (-1,2)-(0,2) is
    # one unit long and keeps its inside end (0, 2)
    pieces = list(subdivide((-4, 2), (4, 2), (0, 0, 8, 8)))
    assert [p.action for p in pieces] == [
        "split", "split", "reject", "split", "reject", "keep inside end", "accept",
    ]  # fmt: skip
    assert visible(pieces) == [((0, 2), (4, 2))]


def test_the_edge_stop_rule_by_hand() -> None:
    """The published answers' stop rule: the first midpoint (0, 2) lands on the left edge
    x = 0, so (-4, 2)-(0, 2) lies beyond that edge but for (0, 2), which is the clipped end:
    three pieces where the length rule takes seven, the same visible part."""
    pieces = list(subdivide((-4, 2), (4, 2), (0, 0, 8, 8), stop="edge"))
    assert [p.action for p in pieces] == ["split", "edge point", "accept"]
    assert visible(pieces) == [((0, 2), (4, 2))]
    # a midpoint inside the window, or an end on an edge with the other end beyond another
    # edge, decides nothing early: (0, 4)-(10, 12) against (0, 0)-(8, 8) starts at the left
    # edge but leaves through the top
    pieces = list(subdivide((0, 4), (10, 12), (0, 0, 8, 8), stop="edge"))
    assert pieces[0].action == "split"


@settings(deadline=None, max_examples=200)
@given(p1=st.tuples(C, C), p2=st.tuples(C, C), how=st.sampled_from(["rounded", "floor", "exact"]))
def test_the_edge_stop_rule_keeps_what_the_length_rule_keeps(p1, p2, how) -> None:
    """A point on an edge with the other end beyond that edge: everything after it is outside
    (x < xmin beyond the left edge, ...), so stopping there keeps, with exact midpoints, the
    same visible part as splitting on (rounded midpoints may pull a later midpoint back
    inside: (0, 0)-(-1, 2) splits at (-1/2, 1), rounded to (0, 1), which the length rule then
    keeps); in no more pieces; and every piece it stops at is outside but for its kept end."""
    length = list(subdivide(p1, p2, WINDOW, how))
    edge = list(subdivide(p1, p2, WINDOW, how, stop="edge"))
    if how == "exact":
        assert visible(edge) == visible(length)
    assert len(edge) <= len(length)
    for p in edge:
        if p.action == "edge point":
            kept = p.a if p.code_a == 0 else p.b
            other = p.b if kept == p.a else p.a
            assert (kept[0] in (0, 20) or kept[1] in (0, 20)) and other != kept
            assert not (0 <= other[0] <= 20 and 0 <= other[1] <= 20)


def test_floor_midpoints_use_the_shift() -> None:
    pieces = list(subdivide((-3, 1), (4, 1), (0, 0, 8, 8), "floor"))
    assert pieces[0].mid == (0, 1)  # (-3 + 4) >> 1 = 0
    pieces = list(subdivide((-3, 1), (4, 1), (0, 0, 8, 8), "rounded"))
    assert pieces[0].mid == (1, 1)  # 1/2 rounded half up


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=150)
@given(p1=st.tuples(C, C), p2=st.tuples(C, C))
def test_exact_midpoints_agree_with_liang_barsky_to_a_unit(p1, p2) -> None:
    assume(p1 != p2)
    lb = liang_barsky(p1, p2, WINDOW)
    parts = visible(list(subdivide(p1, p2, WINDOW, "exact")))
    if not lb.accepted:
        assert parts == []
        return
    (sa, sb) = lb.segment
    if max(abs(sb[0] - sa[0]), abs(sb[1] - sa[1])) < 1:
        return  # a visible part shorter than a unit: found or not, to a unit
    assert parts, (p1, p2)
    (a, b), (la, lb_) = (parts[0][0], parts[-1][1]), lb.segment
    assert max(abs(a[0] - la[0]), abs(a[1] - la[1])) <= 1
    assert max(abs(b[0] - lb_[0]), abs(b[1] - lb_[1])) <= 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=150)
@given(p1=st.tuples(C, C), p2=st.tuples(C, C), how=st.sampled_from(["rounded", "floor"]))
def test_rounded_midpoints_keep_only_points_inside(p1, p2, how) -> None:
    """Rounded midpoints leave the ideal line by up to half a unit a level (the method's
    pixel approximation): what they keep is inside the window and integer."""
    for a, b in visible(list(subdivide(p1, p2, WINDOW, how))):
        for x, y in (a, b):
            assert 0 <= x <= 20 and 0 <= y <= 20
            assert isinstance(x, int) and isinstance(y, int)


def test_answer() -> None:
    sol = midpoint_clip_solution(-4, 2, 4, 2, [0, 0, 8, 8])
    assert sol.data["pieces"] == 7
    assert next(r[5] for r in sol.tables[0].rows()) == "split"


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=100)
@given(
    p1=st.tuples(st.integers(-(10**9), 10**9), st.integers(-(10**9), 10**9)),
    p2=st.tuples(st.integers(-(10**9), 10**9), st.integers(-(10**9), 10**9)),
    how=st.sampled_from(["rounded", "floor", "exact"]),
)
def test_the_pieces_are_few_even_for_the_longest_lines(p1, p2, how) -> None:
    """Each undecided piece is halved until it is a unit long: a line of length L takes
    about 2 log2(L) pieces a window edge it crosses, never many (no limit is needed)."""
    import math

    length = max(abs(p2[0] - p1[0]), abs(p2[1] - p1[1]), 2)
    pieces = list(subdivide(p1, p2, (-5, -5, 5, 5), how))
    assert len(pieces) <= 8 * (math.log2(length) + 2)
