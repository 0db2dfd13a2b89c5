"""Nicholl-Lee-Nicholl line clipping (scanconv.algorithms.nll).

No published worked example of NLL with numbers was found (searched: pages, code and docs
corpora, "Nicholl Lee Nicholl line clipping example" and variants, 2026-11; the textbook
treatments, Hearn & Baker section 6-7 and the tutorial pages that follow it, describe the
regions without a numeric example; docs/errata.md says so). The checks are therefore the
notes' past-paper numbers (Mumbai University: the line (30, 60)-(60, 25) against the window
(10, 10)-(50, 50), which the papers clip by Cohen-Sutherland and Liang-Barsky: the answer is
(38.57, 50)-(50, 36.67)), worked here by hand from the algorithm's slope tests, and exact
agreement with Liang-Barsky (an independent computation) on random lines.
"""

from __future__ import annotations

from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.clipping import liang_barsky
from scanconv.algorithms.nll import nicholl_lee_nicholl, point_region

W = (10, 10, 50, 50)


def test_mumbai_past_paper_line() -> None:
    """P1 (30, 60) is above the window (top edge region); from it the inverse slopes
    dx/dy of the rays are TL (-20/-10) = 2, TR (20/-10) = -2, BR (20/-50) = -2/5,
    BL (-20/-50) = 2/5, and of P1P2 (30/-35) = -6/7: between TR and TL (it meets the window),
    on TR's side of BL and of BR: in through the top, out through the right (region TR);
    x = 30 + (50 - 60)(-6/7) = 270/7 on the top, y = 60 + (50 - 30)(-35/30) = 110/3 on the
    right: (38.57, 50) to (50, 36.67), the papers' answer by Cohen-Sutherland."""
    r = nicholl_lee_nicholl((30, 60), (60, 25), W)
    assert r.region1 == "T" and r.uses_inverse
    assert dict(r.slopes) == {"P2": F(-6, 7), "TL": 2, "TR": -2, "BR": F(-2, 5), "BL": F(2, 5)}
    assert [(t.left, t.relation, t.right) for t in r.tests] == [
        ("y2", "<", "ymax"),
        ("m'", "<", "m'_TL"),
        ("m'", ">", "m'_TR"),
        ("m'", "<", "m'_BL"),
        ("m'", "<", "m'_BR"),
        ("x2", ">", "xmax"),
    ]
    assert r.region2 == "TR"
    assert r.segment == ((F(270, 7), 50), (50, F(110, 3)))
    assert liang_barsky((30, 60), (60, 25), W).segment == r.segment


def test_left_edge_region_by_hand() -> None:
    """Hearn & Baker's canonical case: P1 (0, 30) left of the window; m = 20/60 = 1/3 is
    between m_BL = -2 and m_TL = 2, below m_TR = 2/5, above m_BR = -2/5:
    region LR; P2 (60, 50) is beyond the right edge: y = 30 + 50/3 = 140/3."""
    r = nicholl_lee_nicholl((0, 30), (60, 50), W)
    assert r.region1 == "L" and r.region2 == "LR"
    assert r.segment == ((10, F(100, 3)), (50, F(140, 3)))


def test_corner_regions_both_cases() -> None:
    # TL corner, P1 nearer the top edge line: m_TL = -1/5 > m_BR = -40/55: regions T, TR, LR,
    # LB, L; a line through the left and right edges
    r = nicholl_lee_nicholl((5, 51), (60, 12), W)
    assert r.region1 == "TL" and r.region2 == "LR"
    # P1 high above: m_TL = -50 < m_BR: the top-bottom case
    r = nicholl_lee_nicholl((9, 100), (12, 0), W)
    assert r.region2 == "TB"
    assert r.segment == liang_barsky((9, 100), (12, 0), W).segment


def test_rejections() -> None:
    r = nicholl_lee_nicholl((0, 0), (5, 60), W)  # both left of the window
    assert not r.accepted and [t.so[:3] for t in r.tests] == ["no", "yes"]
    r = nicholl_lee_nicholl((0, 30), (20, 80), W)  # steeper than the ray to TL
    assert not r.accepted and "misses" in r.tests[-1].so


def test_inside_cases() -> None:
    assert nicholl_lee_nicholl((20, 20), (30, 40), W).segment == ((20, 20), (30, 40))
    r = nicholl_lee_nicholl((20, 20), (80, 30), W)
    assert r.region2 == "R" and r.segment == ((20, 20), (50, 25))
    r = nicholl_lee_nicholl((20, 20), (20, 90), W)
    assert r.region2 == "T" and r.segment == ((20, 20), (20, 50))
    r = nicholl_lee_nicholl((50, 20), (90, 20), W)  # on the right edge, leaving at once
    assert r.segment == ((50, 20), (50, 20))


def test_along_an_edge_line_never_divides_by_zero() -> None:
    r = nicholl_lee_nicholl((0, 50), (70, 50), W)  # along the top edge's line
    assert r.segment == ((10, 50), (50, 50))


def test_point_region() -> None:
    assert [point_region(p, W) for p in ((5, 5), (30, 5), (55, 55), (10, 50))] == [
        "BL", "B", "TR", "",
    ]  # fmt: skip


C = st.integers(-20, 80)
Q = st.fractions(min_value=-20, max_value=80, max_denominator=7)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=600)
@given(p1=st.tuples(C, C), p2=st.tuples(C, C))
def test_equals_liang_barsky_on_integer_lines(p1, p2) -> None:
    lb = liang_barsky(p1, p2, W)
    r = nicholl_lee_nicholl(p1, p2, W)
    assert r.accepted == lb.accepted, (p1, p2, r)
    assert r.segment == lb.segment, (p1, p2, r)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=300)
@given(p1=st.tuples(Q, Q), p2=st.tuples(Q, Q), w=st.sampled_from([W, (0, 0, 1, 1), (-3, 2, 4, 3)]))
def test_equals_liang_barsky_on_fraction_lines(p1, p2, w) -> None:
    lb = liang_barsky(p1, p2, w)
    r = nicholl_lee_nicholl(p1, p2, w)
    assert r.accepted == lb.accepted and r.segment == lb.segment, (p1, p2, w, r)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=200)
@given(
    p1=st.tuples(st.sampled_from([10, 30, 50, 0, 60]), st.sampled_from([10, 30, 50, 0, 60])),
    p2=st.tuples(st.sampled_from([10, 30, 50, 0, 60, 70]), st.sampled_from([10, 30, 50, 0, 60])),
)
def test_equals_liang_barsky_through_corners_and_along_edges(p1, p2) -> None:
    """Lines on the window's edge lines and through its corners: every tie."""
    lb = liang_barsky(p1, p2, W)
    r = nicholl_lee_nicholl(p1, p2, W)
    assert r.accepted == lb.accepted and r.segment == lb.segment, (p1, p2, r)


def test_cli_and_pipeline() -> None:
    from .helpers import run

    r = run("clip", "line", "30", "60", "60", "25", "--window", "10", "10", "50", "50",
            "--method", "nicholl-lee-nicholl", "--format", "json")  # fmt: skip
    assert r.code == 0 and '"region2": "TR"' in r.out
    r = run("pipeline", "line", "-5", "0", "15", "10", "--window", "0", "0", "10", "10",
            "--viewport", "0", "0", "20", "10", "--clip", "cyrus-beck", "--format", "json")  # fmt: skip
    assert r.code == 0, r.err  # was a KeyError traceback before NLL joined the pipeline
    r = run("pipeline", "line", "-5", "0", "15", "10", "--window", "0", "0", "10", "10",
            "--viewport", "0", "0", "20", "10", "--clip", "midpoint-subdivision")  # fmt: skip
    assert r.code == 2 and r.out == "" and "midpoint-subdivision" in r.err
    assert len(r.err.strip().splitlines()) == 1


@pytest.mark.parametrize(
    ("p1", "p2", "segment"),
    [
        # along the left and the right edges' lines (vertical): the part on the window's edge
        ((10, 0), (10, 70), ((10, 10), (10, 50))),
        ((10, 70), (10, 0), ((10, 50), (10, 10))),
        ((50, 0), (50, 70), ((50, 10), (50, 50))),
        # along the bottom edge's line (horizontal)
        ((0, 10), (70, 10), ((10, 10), (50, 10))),
    ],
)
def test_along_an_edge_line_keeps_the_edge(p1, p2, segment) -> None:
    assert nicholl_lee_nicholl(p1, p2, W).segment == segment
