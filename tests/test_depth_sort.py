"""The depth-sort (painter's) method (``scanconv 3d depth-sort``): the tests of each pair in
order, the painting order, a cyclic overlap split along the other polygon's plane (a split
point worked by hand), and the painted frame against the per-pixel brute force of
tests/visible_oracle.py, interpenetrating and cyclic scenes included."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from scanconv import visible_depth_sort
from scanconv.algorithms.visible_depthsort import MAX_SPLITS, max_pair_tests
from scanconv.core.checks import InputError

from .helpers import assert_refused, run
from .visible_oracle import as_words, covering


def _words(*polys: tuple[int, ...]) -> list[object]:
    out: list[object] = []
    for p in polys:
        out += [":", *p]
    return out


LOW = (0, 0, 1, 4, 0, 1, 0, 4, 1)  # z = 1
HIGH = (0, 0, 3, 4, 0, 3, 0, 4, 3)  # z = 3, over LOW
RIGHT = (6, 0, 5, 9, 0, 5, 6, 3, 0)  # x 6..9: beside LOW
SLANT = (1, 1, 3, 5, 1, 0, 1, 5, 0)  # the plane 3x + 3y + 4z = 18


def test_the_tests_stop_at_the_first_that_passes() -> None:
    # worked by hand: LOW (z = 1) is the farthest; against HIGH (z = 3) its depth extent 1..1
    # lies wholly behind 3..3, so the z test passes and LOW is painted first
    sol = visible_depth_sort(_words(HIGH, LOW))
    assert sol.data["initial"] == ["B", "A"] and sol.data["painted"] == ["B", "A"]
    assert [t["passed"] for t in sol.data["tests"]] == ["z"]
    # LOW (z = 1) and RIGHT (z 0..5): depth extents overlap; x extents 0..4 and 6..9 do not
    side = visible_depth_sort(_words(LOW, RIGHT))
    assert side.data["tests"][0]["passed"] == "x"


def test_a_failing_pair_is_reordered_and_the_plane_test_settles_it() -> None:
    # SLANT's farthest depth (0) is farther than LOW's (1), so SLANT comes first; against LOW
    # every test fails (extents overlap; SLANT's vertex (1, 1, 3) is in front of z = 1; LOW's
    # (0, 0, 1) is behind SLANT's plane: 3*0 + 3*0 + 4*1 = 4 < 18; the projections overlap),
    # so LOW moves before SLANT; then LOW is wholly behind SLANT's plane (4, 16 and 16 < 18)
    sol = visible_depth_sort(_words(LOW, SLANT), size="6")
    assert sol.data["initial"] == ["B", "A"]
    assert [t["passed"] for t in sol.data["tests"]] == [None, "behind"]
    assert sol.data["painted"] == ["A", "B"] and not sol.data["cycle"]


TILTED = (0, 0, 0, 6, 0, 6, 0, 6, 0)  # z = x
FALLING = (0, 0, 5, 6, 0, 2, 0, 6, 5)  # z = 5 - x/2: the two pierce each other along x = 10/3


def test_interpenetrating_polygons_are_split_along_the_other_plane() -> None:
    # worked by hand: TILTED (A) is the farther first; A and B fail every test both ways
    # (each crosses the other's plane), so B, moved before A once, would move again: it is
    # split by A's plane. A's N = (6, 0, 6) x (0, 6, 0) = (-36, 0, 36), D = 0, C > 0 so the
    # viewer's side is -36x + 36z > 0: B's vertices give 180, -216 + 72 = -144 and 180. On
    # the edge (0,0,5)-(6,0,2): t = 180/(180 + 144) = 5/9, the point (6 * 5/9, 0, 5 - 3 * 5/9)
    # = (10/3, 0, 10/3); on (6,0,2)-(0,6,5): t = 144/324 = 4/9, (6 - 8/3, 8/3, 2 + 4/3) =
    # (10/3, 8/3, 10/3): both on z = x and on z = 5 - x/2, where x = 10/3
    sol = visible_depth_sort(_words(TILTED, FALLING), size="7")
    (cut,) = sol.data["splits"]
    third, y = Fraction(10, 3), Fraction(8, 3)
    assert (cut["polygon"], cut["by"], cut["sides"]) == ("B", "A", [180, -144, 180])
    assert cut["line"] == [[third, 0, third], [third, y, third]]
    assert cut["pieces"] == {
        "B1": [[0, 0, 5], [third, 0, third], [third, y, third], [0, 6, 5]],
        "B2": [[third, 0, third], [6, 0, 2], [third, y, third]],
    }
    # the far piece first, then A, then the near piece (x < 10/3, where B is nearer)
    assert sol.data["painted"] == ["B2", "A", "B1"] and sol.data["cycle"]
    assert sol.data["tests"][2] == {"S": "A", "S2": "B", "passed": None}
    assert sol.data["frame"]["3,0"] == "B" and sol.data["frame"]["4,0"] == "A"
    text = run("3d", "depth-sort", *map(str, _words(TILTED, FALLING)), "-f", "plain").out
    assert "B split by the plane of A into B1 and B2" in text
    assert "(10/3, 0, 10/3) to (10/3, 8/3, 10/3)" in text


#: Three strips overlapping in a ring, none piercing another: A over B (where they overlap,
#: A's z = x - 3 is 4..6 and B's z = y is 1..3), B over C (B's 5..7, C's 3) and C over A
#: (C's 3, A's -2..2): no order paints them right, so the sort must split.
RING = (
    (0, 1, -3, 10, 1, 7, 10, 3, 7, 0, 3, -3),
    (7, 0, 0, 9, 0, 0, 9, 9, 9, 7, 9, 9),
    (0, 0, 3, 2, 0, 3, 9, 7, 3, 7, 7, 3),
)

Poly = tuple[tuple[int, int, int], ...]


def _polys(*flat: tuple[int, ...]) -> list[Poly]:
    return [tuple((p[i], p[i + 1], p[i + 2]) for i in range(0, len(p), 3)) for p in flat]


def _assert_brute_force(data: dict[str, Any], polys: list[Poly], w: int, h: int, near: str) -> None:
    """Every pixel with one nearest polygon shows it (equal depths: the painting order
    decides, any is right); an uncovered pixel is the background."""
    frame = data["frame"]
    for y in range(h):
        for x in range(w):
            cover = covering(polys, x, y)
            if not cover:
                assert f"{x},{y}" not in frame
                continue
            zs = sorted({z for _, z in cover}, reverse=near == "larger-nearer")
            nearest = [i for i, z in cover if z == zs[0]]
            if len(nearest) == 1:
                assert frame[f"{x},{y}"] == "ABCDEFGH"[nearest[0]], (x, y)


def test_a_ring_of_three_is_split_until_it_paints_right() -> None:
    sol = visible_depth_sort(_words(*RING), size="11x10")
    assert sol.data["cycle"] and [s["polygon"] for s in sol.data["splits"]] == ["B", "C"]
    # B is cut by A's plane z = x - 3 where y = x - 3 on its sides x = 9 and x = 7
    assert sol.data["splits"][0]["line"] == [[9, 6, 6], [7, 4, 4]]
    assert sol.data["painted"] == ["B2", "A", "C1", "C2", "B1"]
    _assert_brute_force(sol.data, _polys(*RING), 11, 10, "larger-nearer")
    for x, y, seen in ((7, 2, "A"), (7, 6, "B"), (2, 1, "C")):  # each overlap, by hand
        assert sol.data["frame"][f"{x},{y}"] == seen


def test_more_splits_than_the_limit_are_refused_in_one_line() -> None:
    # four triangles whose cyclic overlaps need more than MAX_SPLITS splits (found by search)
    tris = ((2, 4, -4, 7, 4, -3, 6, 1, 1), (5, -1, 4, 3, 6, 3, 0, -2, -2),
            (1, -2, 0, 1, 1, 3, 6, 4, 3), (4, 0, -2, -2, 1, 3, 6, -2, 5))  # fmt: skip
    assert_refused(run("3d", "depth-sort", *map(str, _words(*tris))), f"more than {MAX_SPLITS}")
    # and four that need exactly MAX_SPLITS are answered, and painted right
    tris = ((0, 2, -1, -2, 5, 5, 7, 0, 1), (4, 6, -1, 7, 6, 5, -1, -1, -1),
            (1, 1, -2, 7, 5, 3, 1, 5, 4), (-2, 4, 5, 4, 3, 1, 4, -1, -2))  # fmt: skip
    sol = visible_depth_sort(_words(*tris), size="6x5")
    assert len(sol.data["splits"]) == MAX_SPLITS
    _assert_brute_force(sol.data, _polys(*tris), 6, 5, "larger-nearer")


def test_the_pair_rows_are_bounded_within_the_terminal_limit() -> None:
    # each pass over at most 8 + 8 polygons ends in a painting, a move or a split
    assert max_pair_tests() == ((8 + 2) * 16 + 9) * 15 <= 10_000


coord = st.integers(-2, 7)
depth = st.integers(-5, 5)
triangle = st.tuples(*(st.tuples(coord, coord, depth) for _ in range(3)))
nearer_z = st.sampled_from(["larger-nearer", "smaller-nearer"])


def _sorted(flat: list[object], nearer: str) -> dict[str, Any] | None:
    """The answer's data, or ``None`` when refused for needing too many splits."""
    try:
        sol = visible_depth_sort(flat, size="6x5", depth=nearer)
    except InputError as e:
        assert f"more than {MAX_SPLITS} splits" in str(e)
        return None
    assert len(sol.data["tests"]) <= max_pair_tests()
    return sol.data


@pytest.mark.slow  # a property of many answers: over 50 ms
@settings(deadline=None)
@given(st.lists(triangle, min_size=1, max_size=4), nearer_z)
def test_the_painted_frame_is_the_brute_force_nearest(triangles: list[Poly], nearer: str) -> None:
    triangles, flat = as_words(triangles)
    assume(triangles)
    data = _sorted(flat, nearer)
    if data is not None:  # cyclic overlaps included: they are split now
        _assert_brute_force(data, triangles, 6, 5, nearer)


@pytest.mark.slow
@settings(deadline=None)
@given(st.lists(triangle, min_size=3, max_size=4), nearer_z)
def test_cyclic_overlaps_are_split_and_painted_right(triangles: list[Poly], nearer: str) -> None:
    triangles, flat = as_words(triangles)
    assume(len(triangles) >= 3)
    data = _sorted(flat, nearer)
    assume(data is not None and data["splits"])
    assert data is not None
    _assert_brute_force(data, triangles, 6, 5, nearer)


@pytest.mark.slow
@settings(deadline=None)
@given(
    st.lists(st.tuples(coord, coord), min_size=3, max_size=3),
    st.lists(depth, min_size=3, max_size=3),
    st.lists(depth, min_size=3, max_size=3),
    nearer_z,
)
def test_interpenetrating_pairs_are_split_and_painted_right(
    xy: list[tuple[int, int]], za: list[int], zb: list[int], nearer: str
) -> None:
    # one projected triangle, two depths at its vertices whose difference changes sign: the
    # planes meet inside the triangle, so each polygon pierces the other
    (x1, y1), (x2, y2), (x3, y3) = xy
    assume((x2 - x1) * (y3 - y1) != (x3 - x1) * (y2 - y1))
    diff = [a - b for a, b in zip(za, zb, strict=True)]
    assume(max(diff) > 0 > min(diff))
    pair = [tuple((x, y, z) for (x, y), z in zip(xy, zs, strict=True)) for zs in (za, zb)]
    kept, flat = as_words(pair)
    data = _sorted(flat, nearer)
    assert data is not None and data["splits"]
    _assert_brute_force(data, kept, 6, 5, nearer)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("0", "0", "0", "4", "0", "0", "1", "1", "0", "0", "4", "0"), "not convex"),
        (tuple(map(str, (*LOW, "--size", "99"))), "1 to 32"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args: tuple[str, ...], message: str) -> None:
    result = run("3d", "depth-sort", *args)
    assert result.code == 2 and result.out == ""
    assert message in result.err and result.err.count("\n") == 1
