"""Warnock's area subdivision (``scanconv 3d warnock``): each polygon's class against each
window, the tests in order, the quadtree, and the final pixels against a per-pixel brute
force written here."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import visible_warnock

from .helpers import run
from .visible_oracle import as_words, nearest

# Worked by hand: A, the triangle (0, 0), (6, 0), (0, 6) at z = 1, and B, the triangle (2, 2),
# (7, 2), (2, 7) at z = 3, on an 8 x 8 grid (a window is its pixels' squares: W runs from
# -1/2 to 7 1/2 across). Both lie inside W (contained), so W is divided. Its top-left quadrant
# W1 (x 0..3, y 4..7) is crossed by A's edge x + y = 6 and by B's edges: both intersecting,
# divided again. W11 (x 0..1, y 6..7, the square -1/2 .. 1 1/2 by 5 1/2 .. 7 1/2) is crossed
# by x + y = 6 but lies left of B's edge x = 2: A intersecting, B disjoint, so only A, on the
# pixels it covers. The pixel (3, 3) is W322: B surrounds its square and its depth 3 is
# nearer than A's 1 at every corner, so B obscures A there.
HAND = (
    "0",
    "0",
    "1",
    "6",
    "0",
    "1",
    "0",
    "6",
    "1",
    ":",
    "2",
    "2",
    "3",
    "7",
    "2",
    "3",
    "2",
    "7",
    "3",
)


def test_the_hand_worked_windows() -> None:
    sol = visible_warnock(list(HAND), size="8")
    windows = {w["label"]: w for w in sol.data["windows"]}
    assert windows["W"]["classes"] == ["contained", "contained"]
    assert windows["W"]["decision"] == "subdivide"
    assert windows["W1"]["classes"] == ["intersecting", "intersecting"]
    assert windows["W11"]["classes"] == ["intersecting", "disjoint"]
    assert windows["W11"]["decision"] == "one"
    assert windows["W2"]["classes"] == ["disjoint", "intersecting"]  # x 4..7, y 4..7
    # W322 is the pixel (3, 3): B (z = 3) surrounds it and is nearer than A's z = 1
    assert windows["W322"]["decision"] == "obscures" and windows["W322"]["shown"] == "B"
    assert [k for k in windows if len(k) > 4] == []  # nothing below single pixels


coord = st.integers(-2, 9)
depth = st.integers(-4, 4)
triangle = st.tuples(*(st.tuples(coord, coord, depth) for _ in range(3)))


@pytest.mark.slow  # a property of many answers: over 50 ms
@settings(deadline=None)
@given(
    st.lists(triangle, min_size=1, max_size=4),
    st.sampled_from(["larger-nearer", "smaller-nearer"]),
    st.sampled_from(["keep", "replace"]),
)
def test_the_final_pixels_are_the_brute_force_nearest(
    triangles: list[tuple[tuple[int, int, int], ...]], nearer: str, ties: str
) -> None:
    triangles, flat = as_words(triangles)
    if not triangles:
        return
    sol = visible_warnock(flat, size="8", depth=nearer, ties=ties)
    brute = nearest(triangles, 8, 8, nearer, ties)
    assert sol.data["frame"] == {f"{x},{y}": "ABCD"[i] for (x, y), (i, _) in brute.items()}


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((*HAND, "--size", "6"), "2^n"),
        (("0", "0", "0", "4", "0", "0", "1", "1", "0", "0", "4", "0"), "not convex"),
        ((*HAND, "--size", "x"), "one number"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args: tuple[str, ...], message: str) -> None:
    result = run("3d", "warnock", *args)
    assert result.code == 2 and result.out == ""
    assert message in result.err and result.err.count("\n") == 1


@pytest.mark.parametrize("ties", ["keep", "replace"])
def test_a_surrounding_polygon_at_an_equal_depth_obscures_nothing(ties: str) -> None:
    # A, a square at z = 1 around the whole grid; B, a triangle at the same depth, given after
    # it: no window is decided by A obscuring B, and B's pixels are A's (keep) or B's (replace)
    square = ("-1", "-1", "1", "5", "-1", "1", "5", "5", "1", "-1", "5", "1")
    tri = ("0", "0", "1", "3", "0", "1", "0", "3", "1")
    sol = visible_warnock([*square, ":", *tri], size="4", ties=ties)
    assert all(w["decision"] != "obscures" for w in sol.data["windows"])
    b_pixels = {"0,0", "1,0", "2,0", "0,1", "1,1", "0,2"}
    want = {
        f"{x},{y}": ("B" if f"{x},{y}" in b_pixels and ties == "replace" else "A")
        for x in range(4)
        for y in range(4)
    }
    assert sol.data["frame"] == want
