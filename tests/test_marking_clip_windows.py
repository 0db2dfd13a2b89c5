"""``check`` marks a Sutherland-Hodgman stage table, written by hand as a student writes it:
the stage is the one whose polygon edges the student copied (a triangle window's C3C1 edge, a
rectangle's left edge), and each row's case and output stand alone."""

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
