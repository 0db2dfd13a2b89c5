"""The depth-sort (painter's) method (``scanconv 3d depth-sort``): the tests of each pair in
order, the painting order, a cyclic overlap said, and the painted frame against a per-pixel
brute force written here."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import visible_depth_sort

from .helpers import run
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


def test_interpenetrating_polygons_are_a_cyclic_overlap() -> None:
    # two triangles crossing each other along the line x = 2: each is partly in front
    one = (0, 0, 0, 4, 0, 4, 0, 4, 0)
    two = (0, 0, 4, 4, 0, 0, 0, 4, 4)
    sol = visible_depth_sort(_words(one, two))
    assert sol.data["cycle"]
    assert (
        "cyclic overlap" in run("3d", "depth-sort", *map(str, _words(one, two)), "-f", "plain").out
    )


coord = st.integers(-2, 7)
depth = st.integers(-5, 5)
triangle = st.tuples(*(st.tuples(coord, coord, depth) for _ in range(3)))


@pytest.mark.slow  # a property of many answers: over 50 ms
@settings(deadline=None)
@given(
    st.lists(triangle, min_size=1, max_size=4), st.sampled_from(["larger-nearer", "smaller-nearer"])
)
def test_the_painted_frame_is_the_brute_force_nearest(
    triangles: list[tuple[tuple[int, int, int], ...]], nearer: str
) -> None:
    triangles, flat = as_words(triangles)
    if not triangles:
        return
    sol = visible_depth_sort(flat, size="6x5", depth=nearer)
    if sol.data["cycle"]:
        return  # a cyclic overlap needs splitting: nothing to compare
    frame = sol.data["frame"]
    for y in range(5):
        for x in range(6):
            cover = covering(triangles, x, y)
            if not cover:
                assert f"{x},{y}" not in frame
                continue
            zs = sorted({z for _, z in cover}, reverse=nearer == "larger-nearer")
            nearest = [i for i, z in cover if z == zs[0]]
            if len(nearest) == 1:  # equal depths: the painting order decides, any is right
                assert frame[f"{x},{y}"] == "ABCD"[nearest[0]], (x, y)


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
