"""``check`` marks the tables of three conventions a question may set: midpoint subdivision
stopping where a midpoint lands on the window's edge (``--stop edge``), the left-bottom rule
for a point on the boundary (``--boundary left-bottom``) and a line mask applied from its
least significant bit (``--bits lsb``). The students' tables are written here by hand, the
numbers in each docstring, not taken from scanconv's output."""

from __future__ import annotations

import json
from pathlib import Path

from .helpers import run


def _check(tmp_path: Path, text: str, question: str) -> dict:
    path = tmp_path / "s.csv"
    path.write_text(text, encoding="utf-8")
    r = run("check", str(path), "--format", "json", "--", *question.split())
    assert r.code == 0 and r.err == "", r.err
    return json.loads(r.out)


EDGE_Q = "clip line -4 2 4 2 --window 0 0 8 8 --method midpoint-subdivision --stop edge"
EDGE = """k,piece,code1,code2,AND,action,midpoint,its code
0,(-4 2) to (4 2),0001,0000,0000,split,"(0, 2)",0000
1,(-4 2) to (0 2),0001,0000,0000,edge point,-,-
2,(0 2) to (4 2),0000,0000,0000,accept,-,-
"""


def test_midpoint_edge_stop_pieces(tmp_path: Path) -> None:
    """(-4, 2) to (4, 2) against (0, 0)-(8, 8): P1 is left (0001), P2 inside (0000), AND
    0000, split at (0, 2) (code 0000), which is on the left edge: the piece (-4, 2)-(0, 2)
    stops there (an edge point) and (0, 2)-(4, 2) is accepted. Splitting the edge piece again
    (the length rule's action) is wrong under the edge rule."""
    assert _check(tmp_path, EDGE, EDGE_Q)["score"] == 3
    data = _check(tmp_path, EDGE.replace("edge point", "split"), EDGE_Q)
    assert (data["score"], data["out_of"]) == (2, 3) and data["first_error"].startswith("Row 2")


BOUNDARY_Q = "inside 0 0 4 0 4 4 0 4 --points 0 2 4 2 2 2 --boundary left-bottom --rule even-odd"
BOUNDARY = """point,crossings,even-odd
P1,1,inside
P2,0,outside
P3,1,inside
"""


def test_left_bottom_verdicts(tmp_path: Path) -> None:
    """The square [0, 4]^2, rays to the right counted half-open: (0, 2) on the left edge
    crosses x = 4 only (1: inside), (4, 2) on the right edge crosses nothing beyond it (0:
    outside), (2, 2) crosses x = 4 (1: inside). Calling the right-edge point inside (the
    inside rule's verdict) is wrong here."""
    assert _check(tmp_path, BOUNDARY, BOUNDARY_Q)["score"] == 3
    data = _check(tmp_path, BOUNDARY.replace("P2,0,outside", "P2,0,inside"), BOUNDARY_Q)
    assert (data["score"], data["out_of"]) == (2, 3) and data["first_error"].startswith("Row 2")


MASK_Q = "linestyle 0 0 12 4 --mask 1110 --bits lsb"
# Bresenham from (0, 0) to (12, 4): dx = 12, dy = 4, p0 = -4, +8 or -16 a step
PIXELS = [(0, 0), (1, 0), (2, 1), (3, 1), (4, 1), (5, 2), (6, 2), (7, 2), (8, 3), (9, 3),
          (10, 3), (11, 4), (12, 4)]  # fmt: skip


def _mask_table(bits: str) -> str:
    rows = [
        f"{k},{x},{y},{k % 4},{bits[k % 4]},{'draw' if bits[k % 4] == '1' else 'skip'}"
        for k, (x, y) in enumerate(PIXELS)
    ]
    return "k,x,y,bit_index,bit,action\n" + "\n".join(rows) + "\n"


def test_mask_read_from_its_least_significant_bit(tmp_path: Path) -> None:
    """The mask 1110 as written, bit 0 (the rightmost, 0) applied first: 0, 1, 1, 1, 0, ...
    so pixels 0, 4, 8, 12 are skipped. The mask applied as written (msb first: 1, 1, 1, 0)
    is wrong in every row where the two orders differ (k mod 4 = 0 or 3: 7 of 13); a slip in
    one bit with its action following from it costs that row only."""
    assert _check(tmp_path, _mask_table("0111"), MASK_Q)["score"] == 13
    assert _check(tmp_path, _mask_table("1110"), MASK_Q)["score"] == 13 - 7
    slip = _mask_table("0111").replace("5,5,2,1,1,draw", "5,5,2,1,0,skip")
    data = _check(tmp_path, slip, MASK_Q)
    assert (data["score"], data["out_of"]) == (12, 13) and data["first_error"].startswith("Row 6")
