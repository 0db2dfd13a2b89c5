"""Sutherland–Hodgman against any convex window (scanconv.algorithms.window_clip, ``scanconv
clip polygon ... --window-vertices``): a published example, a table worked by hand, and the
clipped polygon against the intersection a polygon library computes (shapely, test-only)."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from scanconv.algorithms.clipping import Case, polygon_area
from scanconv.algorithms.window_clip import (
    convex_window,
    overlapping_window_edges,
    sutherland_hodgman_window,
)
from scanconv.core.checks import InputError

shapely = pytest.importorskip("shapely")
from shapely.geometry import Polygon  # noqa: E402


def _without_collinear(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The corners of a polygon: repeated points and vertices in the middle of a straight run
    dropped (they do not change the shape)."""
    pts = [p for i, p in enumerate(points) if p != points[i - 1]]
    changed = True
    while changed and len(pts) > 3:
        changed = False
        for i in range(len(pts)):
            a, b, c = pts[i - 1], pts[i], pts[(i + 1) % len(pts)]
            if abs((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])) < 1e-9:
                del pts[i]
                changed = True
                break
    return pts


def _cyclic(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """A polygon's corners rounded, starting at the smallest, so that two listings compare."""
    pts = [(round(x, 6), round(y, 6)) for x, y in points]
    i = pts.index(min(pts))
    return pts[i:] + pts[:i]


def test_rosetta_codes_published_example() -> None:
    """Rosetta Code, "Sutherland-Hodgman polygon clipping" (the task's subject and clip
    polygons, and the output every solution there prints). The subject's vertex (100, 200)
    lies on the window's edge x = 100: kept here (on the edge counts as inside, the notes'
    rule), left out there; it is a vertex in the middle of a straight edge, so the polygon is
    the same."""
    subject = [(50, 150), (200, 50), (350, 150), (350, 300), (250, 300), (200, 250),
               (150, 350), (100, 250), (100, 200)]  # fmt: skip
    window, flipped = convex_window([(100, 100), (300, 100), (300, 300), (100, 300)])
    published = [(100, 116.666667), (125, 100), (275, 100), (300, 116.666667), (300, 300),
                 (250, 300), (200, 250), (175, 300), (125, 300), (100, 250)]  # fmt: skip
    out = sutherland_hodgman_window(subject, window)[-1].outputs
    assert not flipped
    assert (100, 200) in out
    got = _without_collinear([(float(x), float(y)) for x, y in out])
    assert _cyclic(got) == _cyclic(published)


def test_a_square_clipped_by_a_triangle_by_hand() -> None:
    """Worked by hand: the triangle C1 (1, -1), C2 (6, 4), C3 (1, 4) has the edges y = x - 2
    (C1C2), y = 4 (C2C3) and x = 1 (C3C1); the square [0, 4]^2 meets it in (1, 0), (2, 0),
    (4, 2), (4, 4), (1, 4)."""
    stages = sutherland_hodgman_window(
        [(0, 0), (4, 0), (4, 4), (0, 4)], convex_window([(1, -1), (6, 4), (1, 4)])[0]
    )
    first = stages[0]
    assert str(first.edge) == "C1C2"
    # (0,0) is above y = x - 2 (inside), (4,0) below: it leaves at (2, 0); (4,4) is inside
    # again, entering at (4, 2)
    assert [r.case for r in first.rows] == [Case.IN_OUT, Case.OUT_IN, Case.IN_IN, Case.IN_IN]
    assert first.outputs == ((2, 0), (4, 2), (4, 4), (0, 4), (0, 0))
    assert stages[1].outputs == first.outputs[1:] + first.outputs[:1]  # y <= 4 keeps all
    assert stages[2].outputs == ((4, 4), (1, 4), (1, 0), (2, 0), (4, 2))
    # the square (16) less the strip x < 1 (4) and the corner below y = x - 2 (2 x 2 / 2)
    assert polygon_area(stages[2].outputs) == 16 - 4 - 2


def test_a_clockwise_window_is_reversed() -> None:
    ccw, flipped = convex_window([(0, 0), (0, 4), (4, 0)])
    assert flipped and ccw == ((4, 0), (0, 4), (0, 0))


@pytest.mark.parametrize(
    "window",
    [
        [(0, 0), (4, 0), (1, 1), (0, 4)],  # concave
        [(0, 0), (1, 1), (2, 2)],  # no area
        [(0, 0), (4, 0)],  # two corners
    ],
)
def test_a_window_that_is_not_convex_is_refused(window: list[tuple[int, int]]) -> None:
    with pytest.raises(InputError):
        convex_window(window)


_coord = st.integers(-12, 12)


@st.composite
def convex_windows(draw: st.DrawFn) -> list[tuple[int, int]]:
    """The convex hull of random points (at least 3 corners, counter-clockwise)."""
    pts = draw(st.lists(st.tuples(_coord, _coord), min_size=3, max_size=12, unique=True))
    hull = Polygon(pts).convex_hull
    assume(hull.geom_type == "Polygon" and hull.area > 0)
    corners = [(int(x), int(y)) for x, y in list(hull.exterior.coords)[:-1]]
    return _without_collinear_int(corners)


def _without_collinear_int(corners: list[tuple[int, int]]) -> list[tuple[int, int]]:
    kept = _without_collinear([(float(x), float(y)) for x, y in corners])
    return [(int(x), int(y)) for x, y in kept]


@st.composite
def star_polygons(draw: st.DrawFn) -> list[tuple[int, int]]:
    """A simple polygon (concave allowed): points around a centre in order of their angle."""
    pts = draw(st.lists(st.tuples(_coord, _coord), min_size=3, max_size=10, unique=True))
    cx, cy = Fraction(sum(p[0] for p in pts), len(pts)), Fraction(sum(p[1] for p in pts), len(pts))
    angles = [math.atan2(float(y - cy), float(x - cx)) for x, y in pts]
    assume(len(set(angles)) == len(angles))
    ordered = [p for _, p in sorted(zip(angles, pts, strict=True))]
    poly = Polygon(ordered)
    assume(poly.is_valid and poly.area > 0)
    return ordered


@settings(max_examples=300, deadline=None)
@given(star_polygons(), convex_windows())
def test_the_area_kept_is_the_intersection(
    subject: list[tuple[int, int]], window: list[tuple[int, int]]
) -> None:
    """Any simple polygon, any convex window: the clipped polygon's area (its degenerate
    connecting edges add none) is the area of the intersection shapely computes."""
    ccw, _ = convex_window(window)
    out = sutherland_hodgman_window(subject, ccw)[-1].outputs
    want = Polygon(subject).intersection(Polygon(window)).area
    got = float(abs(polygon_area(out))) if out else 0.0
    assert got == pytest.approx(want, abs=1e-9)


@settings(max_examples=300, deadline=None)
@given(convex_windows(), convex_windows())
def test_a_convex_polygon_clips_to_the_intersection_itself(
    subject: list[tuple[int, int]], window: list[tuple[int, int]]
) -> None:
    """Two convex polygons: the clipped polygon has exactly the intersection's corners, in
    order, touching cases included (a shared edge, a vertex on an edge)."""
    ccw, _ = convex_window(window)
    out = sutherland_hodgman_window(subject, ccw)[-1].outputs
    meet = Polygon(subject).intersection(Polygon(window))
    if meet.geom_type != "Polygon" or meet.area == 0:
        assert not out or polygon_area(out) == 0
        return
    corners = _without_collinear([(float(x), float(y)) for x, y in out])
    want = _without_collinear([(float(x), float(y)) for x, y in list(meet.exterior.coords)[:-1]])
    if Polygon(want).exterior.is_ccw != (polygon_area(out) > 0):
        want = want[::-1]
    assert _cyclic(corners) == _cyclic(want)
    assert not overlapping_window_edges(out, ccw)  # a convex polygon leaves none
