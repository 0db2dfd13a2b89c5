"""The scan-line method of visible surfaces (``scanconv 3d scanline``): the active edge list
and in/out flags of each scan line, the depth comparison where flags overlap, and the final
pixels against a per-pixel brute force written here."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import visible_scanline

from .helpers import run
from .test_zbuffer import EXAMPLE, FRAME
from .visible_oracle import as_words, frame_rows, nearest

# Worked by hand: A, the triangle (0, 0), (4, 0), (0, 4) at z = 1; B, the triangle (1, 0),
# (4, 0), (4, 3) at z = 2. On scan line y = 1 the active edges are A's x = 0 and x = 3 (the
# edge x + y = 4) and B's x = 2 (the edge y = x - 1) and x = 4: sorted 0 (A in), 2 (B in),
# 3 (A out), 4 (B out); so [0, 2) is A alone (pixels 0, 1), [2, 3) has both flags on and
# compares z_A = 1 with z_B = 2 at x = 2 (B, nearer), [3, 4) is B alone (pixel 3).
HAND = (
    "0",
    "0",
    "1",
    "4",
    "0",
    "1",
    "0",
    "4",
    "1",
    ":",
    "1",
    "0",
    "2",
    "4",
    "0",
    "2",
    "4",
    "3",
    "2",
)


def test_the_hand_worked_scan_line() -> None:
    sol = visible_scanline(list(HAND), size="5")
    table = next(t for t in sol.tables if t.title.startswith("Scan lines"))
    rows = [r for r in table.rows() if r[0] == 1]
    assert rows[0][1] == "A.e2 0, B.e2 2, A.e1 3, B.e1 4"
    assert [(r[2], r[3]) for r in rows] == [("[0, 2)", "A"), ("[2, 3)", "A, B"), ("[3, 4)", "B")]
    assert rows[1][4] == "2: z_A = 1, z_B = 2: B"


def test_the_z_buffer_s_example_gives_the_z_buffer_s_frame() -> None:
    assert frame_rows(visible_scanline(list(EXAMPLE), size="5").data, 5, 5) == FRAME


coord = st.integers(-2, 7)
depth = st.integers(-5, 5)
triangle = st.tuples(*(st.tuples(coord, coord, depth) for _ in range(3)))


@pytest.mark.slow  # a property of many answers: over 50 ms
@settings(deadline=None)
@given(
    st.lists(triangle, min_size=1, max_size=4),
    st.sampled_from(["larger-nearer", "smaller-nearer"]),
    st.sampled_from(["keep", "replace"]),
)
def test_the_frame_is_the_brute_force_nearest_at_each_pixel(
    triangles: list[tuple[tuple[int, int, int], ...]], nearer: str, ties: str
) -> None:
    triangles, flat = as_words(triangles)
    if not triangles:
        return
    frame = visible_scanline(flat, size="6x5", depth=nearer, ties=ties).data["frame"]
    brute = nearest(triangles, 6, 5, nearer, ties)
    for y in range(5):
        for x in range(6):
            best = brute.get((x, y))
            assert frame.get(f"{x},{y}") == (None if best is None else "ABCD"[best[0]]), (x, y)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((*HAND, "--size", "0"), "1 to 32"),
        (("0", "0", "0", "0", "1", "0", "0", "0", "1"), "edge-on"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args: tuple[str, ...], message: str) -> None:
    result = run("3d", "scanline", *args)
    assert result.code == 2 and result.out == ""
    assert message in result.err and result.err.count("\n") == 1
