"""The scan-line polygon fill: the textbook edge table and AET, the pixel-ownership rules
(shared edges never overlap, no gaps), the fill rules, the bulk version and bad input."""

from __future__ import annotations

import json
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from skimage.draw import polygon as sk_polygon

from scanconv.algorithms import raster_fill
from scanconv.algorithms.polygon import (
    MAX_FILL_CELLS,
    MAX_VERTICES,
    check_polygon,
    edge_table,
    fill_pixels,
    outline_pixels,
    scanline_fill,
    vertices_from_coords,
)
from scanconv.answers.process.fill.scanline import polygon_solution, shape
from scanconv.core.checks import InputError
from scanconv.render import Format, render

# Foley, van Dam, Feiner & Hughes, Computer Graphics: Principles and Practice, 2nd ed.,
# section 3.6, Fig. 3.22 (the polygon) and Fig. 3.28 (its edge table): A(2, 3), B(7, 1),
# C(13, 5), D(13, 11), E(7, 7), F(2, 9).
FOLEY = [2, 3, 7, 1, 13, 5, 13, 11, 7, 7, 2, 9]
FOLEY_PTS = [(2, 3), (7, 1), (13, 5), (13, 11), (7, 7), (2, 9)]
LABEL = {0: "AB", 1: "BC", 2: "CD", 3: "DE", 4: "EF", 5: "FA"}


def test_foley_edge_table_value_by_value():
    """Fig. 3.28: bucket 1: AB (y_max 3, x 7, 1/m -5/2), BC (5, 7, 6/4); bucket 3: FA (9, 2,
    0); bucket 5: CD (11, 13, 0); bucket 7: EF (9, 7, -5/2), DE (11, 7, 6/4)."""
    edges, horizontal = edge_table(FOLEY_PTS)
    assert horizontal == ()
    got = [(e.y_min, LABEL[e.idx], e.y_max, e.x_bottom, e.inv_m) for e in edges]
    assert got == [
        (1, "AB", 3, 7, Fraction(-5, 2)),
        (1, "BC", 5, 7, Fraction(6, 4)),
        (3, "FA", 9, 2, 0),
        (5, "CD", 11, 13, 0),
        (7, "EF", 9, 7, Fraction(-5, 2)),
        (7, "DE", 11, 7, Fraction(6, 4)),
    ]


def test_foley_active_edge_table_per_scan_line():
    """Fig. 3.29(a) shows the AET at scan line 9 before its step 3.2 removes FA and EF (y =
    y_max): FA (x 2), EF (x 2), DE (x 10), CD (x 13); Fig. 3.29(b) at scan line 10: DE at
    11 1/2, CD at 13. Scanconv lists each scan line after the removal."""
    rows = {s.y: s for s in scanline_fill(FOLEY_PTS)}
    aet = {y: [(LABEL[a.edge], a.x, a.inv_m, a.y_max) for a in s.active] for y, s in rows.items()}
    assert aet[1] == [("AB", 7, Fraction(-5, 2), 3), ("BC", 7, Fraction(3, 2), 5)]
    assert aet[2] == [
        ("AB", Fraction(9, 2), Fraction(-5, 2), 3),
        ("BC", Fraction(17, 2), Fraction(3, 2), 5),
    ]
    assert aet[7] == [
        ("FA", 2, 0, 9),
        ("EF", 7, Fraction(-5, 2), 9),
        ("DE", 7, Fraction(3, 2), 11),
        ("CD", 13, 0, 11),
    ]
    assert [LABEL[i] for i in rows[9].removed] == ["FA", "EF"]
    assert aet[9] == [("DE", 10, Fraction(3, 2), 11), ("CD", 13, 0, 11)]
    assert aet[10] == [("DE", Fraction(23, 2), Fraction(3, 2), 11), ("CD", 13, 0, 11)]
    assert [LABEL[i] for i in rows[11].removed] == ["CD", "DE"] and aet[11] == []
    assert rows[1].runs == ((7, 6),)  # the local minimum B: a span of length zero
    assert rows[8].runs == ((2, 4), (9, 12))
    assert rows[10].runs == ((12, 12),)
    assert len(fill_pixels(FOLEY_PTS)) == 66


def test_the_answer_prints_the_edge_table_and_the_rules():
    sol = polygon_solution(FOLEY)
    text = "".join(c for c in render(sol, Format.plain) if isinstance(c, str))
    assert "AB: (2, 3) -> (7, 1): 1/m = dx / dy = (7 - 2) / (1 - 3) = -2.5" in text
    assert "ceil(x_a) .. ceil(x_b) - 1" in text and "upper end excluded" in text
    assert "DE: 10, 1.5, 11; CD: 13, 0, 11" in text
    assert "the polygon is concave" in text
    assert text.isascii()
    outline = set(outline_pixels(FOLEY_PTS))
    figure = sol.figures[0]
    assert set(figure.marks) == outline and set(figure.pixels) == set(fill_pixels(FOLEY_PTS))
    data = json.loads("".join(render(sol, Format.json)))
    assert data["edge_table"][0] == {
        "edge": "AB",
        "y_min": 1,
        "y_max": 3,
        "x": 7,
        "inv_m": -2.5,
        "direction": -1,
    }
    assert len(data["pixels"]) == 66
    md = "".join(c for c in render(sol, Format.markdown) if isinstance(c, str))
    assert "**Edge table (sorted by y\\_min, then x):**" in md  # through md_text


def test_triangle_vertex_rules():
    # A local maximum (top vertex) fills nothing; the right vertex's centre is not filled.
    assert fill_pixels([(0, 0), (4, 0), (2, 2)]) == [(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1)]
    # A vertex between a rising and a falling edge counts once: (0, 2) on the left.
    rows = {s.y: s for s in scanline_fill([(0, 0), (4, 0), (4, 4), (0, 2)])}
    assert [a.x for a in rows[2].active] == [0, 4] and rows[2].runs == ((0, 3),)


def test_horizontal_edges_are_dropped_and_said_so():
    edges, horizontal = edge_table([(0, 0), (4, 0), (4, 3), (0, 3)])
    assert horizontal == (0, 2) and len(edges) == 2
    sol = polygon_solution([0, 0, 4, 0, 4, 3, 0, 3])
    assert any("Horizontal edges dropped" in n and "AB, CD" in n for n in sol.notes)
    assert [r[-1] for r in sol.tables[0].rows()][-2:] == ["horizontal: dropped"] * 2
    # The top row and the right column are left to the neighbours: 4 x 3 pixels.
    assert len(fill_pixels([(0, 0), (4, 0), (4, 3), (0, 3)])) == 12


def test_collinear_and_repeated_vertices():
    square = [(0, 0), (4, 0), (4, 4), (0, 4)]
    assert fill_pixels([(0, 0), (2, 0), (4, 0), (4, 4), (4, 4), (0, 4), (0, 0)]) == fill_pixels(
        square
    )
    pts, dropped = check_polygon([(0, 0), (2, 0), (4, 0), (4, 4), (4, 4), (0, 4), (0, 0)])
    assert dropped == 2 and len(pts) == 5
    sol = polygon_solution([0, 0, 4, 0, 4, 0, 4, 4, 0, 4])
    assert any("repeated vertex" in n for n in sol.notes)


def test_self_intersecting_star_even_odd_and_nonzero():
    star = [(5, 0), (8, 9), (0, 3), (10, 3), (2, 9)]  # a pentagram
    odd, nonzero = set(fill_pixels(star)), set(fill_pixels(star, "nonzero"))
    assert (5, 4) in nonzero and (5, 4) not in odd  # the pentagon in the middle
    assert odd < nonzero
    assert shape(star) == "self-intersecting"
    sol = polygon_solution([c for p in star for c in p], "nonzero")
    assert any("crosses itself" in n for n in sol.notes)
    assert "(+1)" in next(iter(sol.tables[1].rows()))[4]


def test_convex_and_fractional_vertices():
    assert shape([(0, 0), (4, 0), (2, 3)]) == "convex"
    pts = [(Fraction(1, 2), Fraction(1, 2)), (Fraction(9, 2), Fraction(1, 2)), (Fraction(5, 2), 4)]
    assert fill_pixels(pts)[:4] == [(1, 1), (2, 1), (3, 1), (4, 1)]
    sol = polygon_solution(
        [Fraction(1, 2), Fraction(1, 2), Fraction(9, 2), Fraction(1, 2), Fraction(5, 2), 4]
    )
    assert any("rounded half up" in n for n in sol.notes)


# --- pixel ownership: shared edges ------------------------------------------------------

coord = st.integers(-8, 8)


inner = st.fractions(min_value=0, max_value=1, max_denominator=8).filter(lambda t: 0 < t < 1)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(tx=inner, ty=inner, w=st.integers(1, 10), h=st.integers(1, 10))
def test_polygons_sharing_edges_never_overlap_and_leave_no_gap(tx, ty, w, h):
    """Four triangles fanned from a point inside a rectangle tile it: their fills are
    disjoint and together they are exactly the rectangle's fill."""
    x0, y0, x1, y1 = -5, -5, -5 + w, -5 + h
    px, py = x0 + tx * w, y0 + ty * h
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    seen: set = set()
    total = 0
    for i in range(4):
        tri = [(px, py), corners[i], corners[(i + 1) % 4]]
        pixels = fill_pixels(tri)
        assert len(set(pixels)) == len(pixels)
        assert not seen & set(pixels), "two triangles sharing an edge filled the same pixel"
        seen |= set(pixels)
        total += len(pixels)
    assert seen == set(fill_pixels(corners)) and total == w * h


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(suppress_health_check=[HealthCheck.filter_too_much])
@given(
    a=st.tuples(coord, coord),
    b=st.tuples(coord, coord),
    c=st.tuples(coord, coord),
    d=st.tuples(coord, coord),
)
def test_two_triangles_on_either_side_of_an_edge(a, b, c, d):
    """Triangles abc and abd with c and d on opposite sides of ab share the edge ab only."""

    def side(p):
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    assume(side(c) * side(d) < 0)  # opposite sides (half the draws), named so that c is left
    if side(c) < 0:
        c, d = d, c
    one, two = set(fill_pixels([a, b, c])), set(fill_pixels([a, b, d]))
    assert not one & two


polygons = st.lists(st.tuples(coord, coord), min_size=3, max_size=8)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(pts=polygons, rule=st.sampled_from(["even-odd", "nonzero"]))
def test_the_bulk_fill_is_the_table_fill(pts, rule):
    try:
        expected = fill_pixels(pts, rule)
    except InputError:
        assume(False)
        return
    xs, ys = raster_fill.polygon([p[0] for p in pts], [p[1] for p in pts], rule)
    assert xs.dtype == np.int64
    assert list(zip(xs.tolist(), ys.tolist(), strict=True)) == expected


def _on_boundary(p, pts):
    n = len(pts)
    for i in range(n):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % n]
        cross = (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax)
        if cross == 0 and min(ax, bx) <= p[0] <= max(ax, bx) and min(ay, by) <= p[1] <= max(ay, by):
            return True
    return False


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(pts=polygons)
def test_skimage_polygon_differs_only_on_the_boundary(pts):
    """skimage.draw.polygon fills the closed polygon (centres on any edge included); scanconv
    the half-open one. Off the boundary the two agree; on it, scanconv fills a subset."""
    try:
        mine = set(fill_pixels(pts))
    except InputError:
        assume(False)
        return
    rr, cc = sk_polygon([p[1] + 20 for p in pts], [p[0] + 20 for p in pts])
    theirs = {(c - 20, r - 20) for r, c in zip(rr.tolist(), cc.tolist(), strict=True)}
    for p in mine ^ theirs:
        assert _on_boundary(p, pts), f"{p} differs but is not on the boundary"


# --- bad input --------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("coords", "word"),
    [
        ([0, 0, 4, 0], "at least 3 vertices"),
        ([0, 0, 4, 0, 2], "odd number"),
        ([0, 0, 2, 2, 5, 5], "degenerate"),
        ([1, 1, 1, 1, 1, 1], "degenerate"),
        ([0, 0] * (MAX_VERTICES + 1), f"at most {MAX_VERTICES}"),
        ([0, 0, 1001, 0, 0, 1000], "pixel cells"),
    ],
)
def test_bad_polygons_are_refused(coords, word):
    with pytest.raises(InputError, match=word) as err:
        polygon_solution(coords)
    assert err.value.param == "vertices"


def test_the_limits_at_their_edge():
    assert len(vertices_from_coords([0, 0] * MAX_VERTICES)) == MAX_VERTICES
    check_polygon([(0, 0), (999, 0), (0, 999)])  # 1000 x 1000 cells: the limit
    assert 1000 * 1000 == MAX_FILL_CELLS
    with pytest.raises(InputError, match="rule"):
        fill_pixels([(0, 0), (4, 0), (2, 3)], "odd")
    with pytest.raises(InputError, match="floats"):
        raster_fill.polygon([0.5, 4, 2], [0, 0, 3])


def test_the_bulk_fill_and_wu_line_are_part_of_scanconv_raster():
    from scanconv import raster
    from scanconv.algorithms import raster_fill

    assert raster.polygon is raster_fill.polygon and raster.line_aa is raster_fill.line_aa


@pytest.mark.parametrize(
    ("vertices", "area"),
    [
        # the 3 x 2 rectangle from (1, 1): 6, negative when listed clockwise
        ([(1, 1), (4, 1), (4, 3), (1, 3)], 6),
        ([(1, 3), (4, 3), (4, 1), (1, 1)], -6),
        # the triangle (0, 0), (4, 0), (2, 3): base 4, height 3: 6
        ([(0, 0), (4, 0), (2, 3)], 6),
        # an L of three unit squares
        ([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)], 3),
    ],
)
def test_polygon_area_is_the_shoelace_by_hand(vertices, area):
    from scanconv.algorithms.polygon import polygon_area

    assert polygon_area(vertices) == area
