"""``check`` marks the tables of issue 41's clipping and frame-buffer questions, written by
hand as a student writes them: a Sutherland-Hodgman stage (the one whose polygon edges the
student copied: a triangle window's C3C1 edge, a rectangle's left edge; each row's case and
output stand alone) and a pixel's frame-buffer address (with follow-through from the
student's own k)."""

from __future__ import annotations

import json
from pathlib import Path

from .helpers import run, run_process

TRIANGLE = ("clip", "polygon", "0", "0", "4", "0", "4", "4", "0", "4",
            "--window-vertices", "1", "-1", "6", "4", "1", "4")  # fmt: skip

# worked by hand: the square after C1C2 (y >= x - 2) and C2C3 (y <= 4) is (4, 2), (4, 4),
# (0, 4), (0, 0), (2, 0); against C3C1 (x >= 1): (4, 4) -> (0, 4) leaves at (1, 4),
# (0, 0) -> (2, 0) enters at (1, 0)
C3C1 = """polygon edge V1 -> V2,case,output
"(4, 2) -> (4, 4)",in -> in,"(4, 4)"
"(4, 4) -> (0, 4)",in -> out,"(1, 4)"
"(0, 4) -> (0, 0)",out -> out,-
"(0, 0) -> (2, 0)",out -> in,"(1, 0), (2, 0)"
"(2, 0) -> (4, 2)",in -> in,"(4, 2)"
"""

# the first stage, C1C2 (y >= x - 2): (0, 0) -> (4, 0) leaves at (2, 0), (4, 0) -> (4, 4)
# enters at (4, 2)
C1C2 = """polygon edge V1 -> V2,case,output
"(0, 0) -> (4, 0)",in -> out,"(2, 0)"
"(4, 0) -> (4, 4)",out -> in,"(4, 2), (4, 4)"
"(4, 4) -> (0, 4)",in -> in,"(0, 4)"
"(0, 4) -> (0, 0)",in -> in,"(0, 0)"
"""


def _check(tmp_path: Path, text: str, question: tuple[str, ...]) -> dict:
    path = tmp_path / "s.csv"
    path.write_text(text, encoding="utf-8")
    r = run("check", str(path), "--format", "json", "--", *question)
    assert r.code == 0 and r.err == "", r.err
    return json.loads(r.out)


def test_the_stage_written_is_the_one_marked(tmp_path: Path) -> None:
    assert (
        _check(tmp_path, C3C1, TRIANGLE)["score"],
        _check(tmp_path, C3C1, TRIANGLE)["out_of"],
    ) == (5, 5)
    data = _check(tmp_path, C1C2, TRIANGLE)
    assert (data["score"], data["out_of"]) == (4, 4)


def test_one_slip_costs_its_row(tmp_path: Path) -> None:
    slipped = C3C1.replace('"(2, 0) -> (4, 2)",in -> in', '"(2, 0) -> (4, 2)",in -> out')
    data = _check(tmp_path, slipped, TRIANGLE)
    assert (data["score"], data["out_of"]) == (4, 5)
    assert data["first_error"].startswith("Row 5") and "in -> in" in data["first_error"]


def test_a_rectangles_left_edge_as_a_student_writes_it(tmp_path: Path) -> None:
    """The triangle (0, 0), (4, 0), (0, 4) against x >= 1 (the window 1 1 3 3's left edge):
    (0, 0) -> (4, 0) enters at (1, 0); (4, 0) -> (0, 4) along x + y = 4 stays inside until
    (1, 3); (0, 4) -> (0, 0) is outside. The second output written as (1, 4) is wrong."""
    left = """polygon edge V1 -> V2,case,output
"(0, 0) -> (4, 0)",out -> in,"(1, 0), (4, 0)"
"(4, 0) -> (0, 4)",in -> out,"(1, 4)"
"(0, 4) -> (0, 0)",out -> out,-
"""
    path = tmp_path / "left.csv"
    path.write_text(left, encoding="utf-8")
    question = ("clip", "polygon", "0", "0", "4", "0", "0", "4", "--window", "1", "1", "3", "3")
    r = run_process("check", str(path), "--", *question)
    assert r.code == 0 and "2/3" in r.out.replace(" ", ""), (r.out, r.err)


FRAMEBUFFER = ("framebuffer", "640", "480", "8", "--pixel", "340", "150")


def test_a_pixels_address_follows_through(tmp_path: Path) -> None:
    """HyperGraph's question: 640 x 480 at 8 bits, pixel (340, 150), row-major from the top,
    from 0: k = 150 x 640 + 340 = 96,340, the bit offset 96,340 x 8 = 770,720, the byte
    address 0 + 770,720 / 8 = 96,340. A student who slips in k (96,430) and carries it on
    loses that row only."""
    right = "quantity,value\nk,96340\nbit offset,770720\nbyte address,96340\n"
    data = _check(tmp_path, right, FRAMEBUFFER)
    assert (data["score"], data["out_of"]) == (3, 3)
    carried = "quantity,value\nk,96430\nbit offset,771440\nbyte address,96430\n"
    data = _check(tmp_path, carried, FRAMEBUFFER)
    assert (data["score"], data["out_of"]) == (2, 3)
    assert data["first_error"].startswith("Row 1")
    wrong_byte = right.replace("byte address,96340", "byte address,770720")
    assert _check(tmp_path, wrong_byte, FRAMEBUFFER)["score"] == 2


def test_a_bit_inside_its_byte(tmp_path: Path) -> None:
    """16 x 2 at 1 bit a pixel, pixel (3, 1): k = 1 x 16 + 3 = 19, the bit offset 19, so the
    byte 19 div 8 = 2 and the bit 19 mod 8 = 3 in it; a byte written as 19 / 8 is wrong."""
    question = ("framebuffer", "16", "2", "1", "--pixel", "3", "1")
    right = "quantity,value\nk,19\nbit offset,19\nbyte address,2\nbit in byte,3\n"
    assert (_check(tmp_path, right, question)["score"]) == 4
    assert (
        _check(tmp_path, right.replace("byte address,2", "byte address,2.375"), question)["score"]
        == 3
    )
