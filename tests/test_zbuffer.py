"""The z-buffer (``scanconv 3d zbuffer``): the depths from the plane equation and its
increments, the step table of comparisons, the final frame and depth buffers, against a
hand-worked example and a per-pixel brute-force depth comparison written here."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import visible_zbuffer

from .helpers import run
from .visible_oracle import as_words, frame_rows, nearest

# Worked by hand with Hearn & Baker's formulas (C version, 2nd ed., section 13-3:
# z = (-Ax - By - D)/C, z' = z - A/C along a scan line, z' = z + (A/m + B)/C down an edge).
# A lies in z = 2; B in x + y + z = 6. B covers (1..4, 1), (1..3, 2), (1..2, 3), (1, 4), A
# covers x < 5 - y; where both cover a pixel B's z = 6 - x - y is compared with 2: nearer
# (larger) at (1, 1), (2, 1), (1, 2); equal at (3, 1), (2, 2), (1, 3), where A, drawn first,
# keeps the pixel.
EXAMPLE = (
    "0",
    "0",
    "2",
    "5",
    "0",
    "2",
    "0",
    "5",
    "2",
    ":",
    "1",
    "1",
    "4",
    "5",
    "1",
    "0",
    "1",
    "5",
    "0",
)
FRAME = [
    "AB...",
    "AAB..",
    "ABAB.",
    "ABBAB",
    "AAAAA",
]


def test_the_hand_worked_example() -> None:
    sol = visible_zbuffer(list(EXAMPLE), size="5")
    assert frame_rows(sol.data, 5, 5) == FRAME
    assert sol.data["depth"]["1,1"] == 4 and sol.data["depth"]["3,1"] == 2
    replaced = visible_zbuffer(list(EXAMPLE), size="5", ties="replace")
    flipped = [list(r) for r in FRAME]
    for x, y in ((3, 1), (2, 2), (1, 3)):
        flipped[4 - y][x] = "B"
    assert frame_rows(replaced.data, 5, 5) == ["".join(r) for r in flipped]


def test_the_increments_are_the_plane_s() -> None:
    sol = visible_zbuffer(list(EXAMPLE), size="5")
    derived = {q.key: q.value for q in sol.derived}
    assert derived["dx_B"] == -1 and derived["dx_A"] == 0  # -A/C
    scan_b = next(t for t in sol.tables if t.title.startswith("Polygon B"))
    rows = list(scan_b.rows())
    # the left edge x = 1 (1/m = 0): down it z changes by (A/m + B)/C = (0 + 16)/16 = 1
    assert [r[5] for r in rows] == ["1", "2", "3", "4"]
    assert "+ 1" in rows[1][4]


coord = st.integers(-2, 7)
depth = st.integers(-5, 5)
triangle = st.tuples(*(st.tuples(coord, coord, depth) for _ in range(3)))


@pytest.mark.slow  # a property of many answers: over 50 ms
@settings(deadline=None)
@given(
    st.lists(triangle, min_size=1, max_size=4),
    st.sampled_from(["larger-nearer", "smaller-nearer"]),
    st.sampled_from(["keep", "replace"]),
    st.sampled_from([None, "zero", "farthest"]),
)
def test_the_frame_is_the_brute_force_nearest_at_each_pixel(
    triangles: list[tuple[tuple[int, int, int], ...]], nearer: str, ties: str, clear: str | None
) -> None:
    """With the buffer cleared to the farthest value every covering point competes; cleared
    to 0 (Hearn & Baker's and Foley's back clipping plane, the default preset's) a pixel is
    written only where the nearest point is in front of 0 (z > 0, or z >= 0 when ties
    replace); a preset's 0 means nothing when a smaller z is nearer."""
    triangles, flat = as_words(triangles)
    if not triangles:
        return
    if clear == "zero" and nearer == "smaller-nearer":
        with pytest.raises(ValueError, match="clear zero"):
            visible_zbuffer(flat, size="6x5", depth=nearer, ties=ties, clear=clear)
        return
    sol = visible_zbuffer(flat, size="6x5", depth=nearer, ties=ties, clear=clear)
    brute = nearest(triangles, 6, 5, nearer, ties)
    if clear != "farthest" and nearer == "larger-nearer":
        brute = {p: b for p, b in brute.items() if b[1] > 0 or (b[1] == 0 and ties == "replace")}
    for y in range(5):
        for x in range(6):
            key = f"{x},{y}"
            if (x, y) not in brute:
                assert key not in sol.data["frame"]
            else:
                i, z = brute[(x, y)]
                assert sol.data["frame"][key] == "ABCD"[i], (x, y)
                assert sol.data["depth"][key] == z


def test_the_far_value_keeps_what_is_behind_it() -> None:
    sol = visible_zbuffer(list(EXAMPLE), size="5", far=3)
    assert set(sol.data["frame"].values()) == {"B"}  # only B's z = 4 at (1, 1) is nearer than 3
    assert list(sol.data["frame"]) == ["1,1"]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((*EXAMPLE, "--size", "40"), "1 to 32"),
        ((*EXAMPLE, "--size", "4y4"), "W x H"),
        (("0", "0", "0", "0", "1", "0", "0", "0", "1"), "edge-on"),
        (("0", "0", "0", "100", "0", "0", "0", "1", "0"), "at most 64"),
        (("0", "0", "0", "1", "0", "0", "0", "1", "0", "1", "1", "1"), "not planar"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args: tuple[str, ...], message: str) -> None:
    result = run("3d", "zbuffer", *args)
    assert result.code == 2 and result.out == ""
    assert message in result.err and result.err.count("\n") == 1


def test_the_largest_question_is_bounded_by_the_limits_before_work() -> None:
    from scanconv.algorithms.visible_zbuffer import MAX_POLYGONS, MAX_SIDE
    from scanconv.render.work import BOUNDED

    # a row per polygon and pixel at most: within the terminal's 10,000 rows, so no format
    # refuses it and the limits alone bound it (one polygon more, or a side of 33, is refused)
    assert MAX_POLYGONS * MAX_SIDE * MAX_SIDE <= 10_000 and "visible_zbuffer" in BOUNDED
    too_many = " : ".join(["0 0 1 3 0 1 0 3 1"] * (MAX_POLYGONS + 1)).split()
    assert run("3d", "zbuffer", *too_many).code == 2
    assert run("3d", "zbuffer", *EXAMPLE, "--size", str(MAX_SIDE + 1)).code == 2
