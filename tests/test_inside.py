"""Inside-outside tests (scanconv.algorithms.inside, scanconv.answers.process.fill.inside): hand-worked
cases and agreement with the scan-line fill, an independent computation."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from scanconv.algorithms.inside import edge_tests, on_segment, verdict
from scanconv.algorithms.polygon import fill_pixels
from scanconv.answers.process.fill.inside import inside_solution
from scanconv.core.checks import InputError

SQUARE = [(0, 0), (4, 0), (4, 4), (0, 4)]
STAR = [(0, 0), (4, 8), (8, 0), (-1, 5), (9, 5)]  # a pentagram: its centre winds twice


def test_square_by_hand() -> None:
    # (1, 2): the ray y = 2 meets BC at x = 4 (> 1, up: +1) and DA at x = 0 (< 1): 1 crossing
    v = verdict(SQUARE, (1, 2))
    assert (v.crossings, v.winding, v.even_odd, v.nonzero) == (1, 1, True, True)
    # (5, 2): both meetings left of the point: 0 crossings
    assert verdict(SQUARE, (5, 2)).even_odd is False


def test_the_pentagram_centre_is_where_the_rules_differ() -> None:
    # the centre (4, 4): the ray meets two edges, both going the same way: crossings 2 (even,
    # outside), winding 2 (nonzero, inside)
    v = verdict(STAR, (4, 4))
    assert v.crossings == 2 and abs(v.winding) == 2
    assert (v.even_odd, v.nonzero) == (False, True)


def test_a_ray_through_a_vertex_counts_once_or_not_at_all() -> None:
    diamond = [(2, 0), (4, 2), (2, 4), (0, 2)]
    # the ray from (1, 2) passes through vertex (4, 2): the boundary passes through there
    assert verdict(diamond, (1, 2)).crossings == 1
    # the ray from (-1, 4) only touches the top vertex (2, 4): no crossing
    assert verdict(diamond, (-1, 4)).crossings == 0


def test_boundary_points_follow_the_stated_convention() -> None:
    assert verdict(SQUARE, (4, 2)).on_boundary == 1
    assert verdict(SQUARE, (4, 2)).even_odd is True
    assert verdict(SQUARE, (4, 2), "outside").nonzero is False
    assert verdict(SQUARE, (0, 0), "outside").even_odd is False
    with pytest.raises(InputError):
        verdict(SQUARE, (1, 1), "maybe")


def test_edge_rows_by_hand() -> None:
    rows = list(edge_tests([(0, 0), (6, 0), (6, 6), (3, 2), (0, 6)], (3, 4)))
    # CD from (6, 6) to (3, 2) meets y = 4 at x = 6 + (4 - 6)(3 - 6)/(2 - 6) = 4.5, going down
    assert rows[2].x == Fraction(9, 2) and rows[2].sign == -1
    assert [r.crossing for r in rows] == [False, True, True, False, False]


def _star_shaped(draw_angles: list[int], radii: list[int]) -> list[tuple[int, int]]:
    """A simple polygon: vertices at increasing angles around (0, 0)."""
    pts = []
    for a, r in zip(sorted(set(draw_angles)), radii, strict=False):
        t = 2 * math.pi * a / 360
        pts.append((round(r * math.cos(t)), round(r * math.sin(t))))
    return list(dict.fromkeys(pts))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@given(
    vertices=st.lists(st.tuples(st.integers(-8, 8), st.integers(-8, 8)), min_size=3, max_size=7),
    rule=st.sampled_from(["even-odd", "nonzero"]),
)
def test_agrees_with_the_scan_line_fill_off_the_boundary(vertices, rule) -> None:
    """Every integer point not on an edge: inside by the ray test exactly when the scan-line
    fill (active edge table, half-open spans) fills that pixel centre."""
    try:
        filled = set(fill_pixels(vertices, rule))
    except InputError:
        assume(False)
    n = len(vertices)
    for x in range(-9, 10):
        for y in range(-9, 10):
            if any(on_segment((x, y), vertices[i], vertices[(i + 1) % n]) for i in range(n)):
                continue
            v = verdict(vertices, (x, y))
            assert (v.even_odd if rule == "even-odd" else v.nonzero) == ((x, y) in filled)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@given(
    angles=st.lists(st.integers(0, 359), min_size=3, max_size=9, unique=True),
    radii=st.lists(st.integers(2, 9), min_size=9, max_size=9),
    point=st.tuples(st.integers(-10, 10), st.integers(-10, 10)),
)
def test_the_rules_agree_on_a_simple_polygon(angles, radii, point) -> None:
    pts = _star_shaped(angles, radii)
    assume(len(pts) >= 3)
    v = verdict(pts, point)
    assert v.even_odd == v.nonzero
    assert v.winding in (-1, 0, 1)


def test_answer_tables_and_verdicts() -> None:
    sol = inside_solution([0, 0, 6, 0, 6, 6, 3, 2, 0, 6], [3, 1, 3, 4, 6, 3])
    verdicts = [r for r in sol.tables[-1].rows()]
    assert [r[3] for r in verdicts] == ["inside (odd)", "outside (even)", "inside (boundary)"]
    assert [r[5] for r in verdicts] == ["inside", "outside", "inside"]
    assert len(sol.tables) == 4  # one edge table per point, then the verdicts


@pytest.mark.parametrize(
    ("kwargs", "param"),
    [
        ({"vertices": [0, 0, 1, 1], "points": [0, 0]}, "vertices"),
        ({"vertices": [0, 0, 4, 0, 0, 4], "points": [1]}, "points"),
        ({"vertices": [0, 0, 4, 0, 0, 4], "points": [1, 1], "rule_name": "odd"}, "rule"),
    ],
)
def test_bad_input_names_its_parameter(kwargs, param) -> None:
    with pytest.raises(InputError) as info:
        inside_solution(**kwargs)
    assert info.value.param == param


def test_the_left_bottom_rule_by_hand() -> None:
    """The square (0, 0)-(4, 4): on the left edge (0, 2) and the bottom edge (2, 0) inside, on
    the right (4, 2) and the top (2, 4) outside; the corner (0, 0) inside (the square lies up
    and to its right), the three others outside."""
    got = [
        verdict(SQUARE, p, "left-bottom").even_odd
        for p in ((0, 2), (2, 0), (4, 2), (2, 4), (0, 0), (4, 0), (4, 4), (0, 4))
    ]
    assert got == [True, True, False, False, True, False, False, False]
    assert verdict(SQUARE, (4, 2), "left-bottom").on_boundary == 1  # still said to be on BC


@settings(deadline=None, max_examples=150)
@given(
    vertices=st.lists(st.tuples(st.integers(-6, 6), st.integers(-6, 6)), min_size=3, max_size=7,
                      unique=True),
    point=st.tuples(st.integers(-7, 7), st.integers(-7, 7)),
)  # fmt: skip
def test_the_left_bottom_rule_is_the_point_moved_up_and_right(vertices, point) -> None:
    """On the boundary or not, the left-bottom verdict is the plain verdict of the point moved
    a hair right and a hair less up, (x + d, y + d^2), which is on no edge (d small against
    the grid's smallest features)."""
    shapely_geometry = pytest.importorskip("shapely.geometry")
    poly = shapely_geometry.Polygon(vertices)
    assume(poly.is_valid and poly.area > 0)
    d = Fraction(1, 10**4)
    moved = (point[0] + d, point[1] + d * d)
    n = len(vertices)
    assert not any(on_segment(moved, vertices[i], vertices[(i + 1) % n]) for i in range(n))
    want = poly.contains(shapely_geometry.Point(float(moved[0]), float(moved[1])))
    assert verdict(vertices, point, "left-bottom").even_odd == want
