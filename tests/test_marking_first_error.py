"""One account of a slip: the first-error sentence and the expected column say the same.

A right table (Bresenham's line, the midpoint circle, written here from the notes' rules, not
by scanconv) gets one slip in one cell; ``check`` marks it, and every value the sentence calls
expected ("the pixel should be (3, 3)") is the value the expected column shows for that row.
A right cell is never called wrong: the row of a decision word slipped with the right pixel
and next p is wrong in its decision only (never "the pixel should be (3, 2), not (3, 3)" beside an
expected column showing (3, 3)).
"""

from __future__ import annotations

import json
import re

from hypothesis import given, settings
from hypothesis import strategies as st

from .helpers import run


def bresenham_rows(x1: int, y1: int, x2: int, y2: int) -> list[list[str]]:
    """The notes' table of a first-octant line: k, p_k, decision, (x_k, y_k), p_{k+1}."""
    dx, dy = x2 - x1, y2 - y1
    p, x, y, rows = 2 * dy - dx, x1, y1, []
    for k in range(dx):
        move = "E" if p < 0 else "NE"
        nxt = p + 2 * dy - (2 * dx if move == "NE" else 0)
        rows.append([str(k), str(p), move, f"({x}, {y})", str(nxt)])
        x, y, p = x + 1, y + (move == "NE"), nxt
    rows.append([str(dx), str(p), "", f"({x}, {y})", ""])
    return rows


def midpoint_circle_rows(r: int) -> list[list[str]]:
    """The notes' octant of the midpoint circle: k, p_k, decision, (x_k, y_k)."""
    x, y, p, rows, k = 0, r, 1 - r, [], 0
    while x < y:
        move = "E" if p < 0 else "SE"
        rows.append([str(k), str(p), move, f"({x}, {y})"])
        x += 1
        if move == "SE":
            y -= 1
            p += 2 * x + 1 - 2 * y
        else:
            p += 2 * x + 1
        k += 1
    rows.append([str(k), "", "", f"({x}, {y})"])
    return rows


def _slipped(rows: list[list[str]], row: int, col: int) -> list[list[str]]:
    out = [list(r) for r in rows]
    cell = out[row][col]
    if col == 2:
        out[row][col] = {"E": "NE", "NE": "E", "SE": "E"}[cell]
    elif col == 3:
        x, y = map(int, re.findall(r"-?\d+", cell))
        out[row][col] = f"({x}, {y + 1})"
    else:
        out[row][col] = str(int(cell) + 2)
    return out


def _check(tmp_path, heading: str, rows: list[list[str]], question: list[str]) -> dict:
    f = tmp_path / "t.csv"
    f.write_text(heading + "\n" + "\n".join(",".join(f'"{c}"' for c in r) for r in rows) + "\n")
    r = run("check", str(f), "-f", "json", "--", *question)
    assert r.code == 0, r.err
    return json.loads(r.out)


_PART = re.compile(r"(the pixel|p|the decision|the next p) should be (.+?), not ")


def _said_matches_column(data: dict) -> None:
    sentence = data["first_error"]
    row = int(re.match(r"Row (\d+)", sentence).group(1))
    marking = data["tables"][0]
    expected = next(r for r in marking["rows"] if r[0] == row)[3]
    for name, value in _PART.findall(sentence):
        shown = {"the pixel": value, "p": f"p = {value}", "the decision": f", {value},",
                 "the next p": f"next p = {value}"}[name]  # fmt: skip
        assert shown in expected, (sentence, expected)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 5), st.integers(0, 5), st.integers(4, 10), st.integers(0, 10), st.data())
def test_a_line_slip_is_told_once(tmp_path_factory, x1, y1, dx, dy, data):
    dy = min(dy, dx)
    rows = bresenham_rows(x1, y1, x1 + dx, y1 + dy)
    row = data.draw(st.integers(1, len(rows) - 2))
    col = data.draw(st.sampled_from([1, 2, 3, 4]))
    tmp = tmp_path_factory.mktemp("slip")
    question = ["line", str(x1), str(y1), str(x1 + dx), str(y1 + dy)]
    marked = _check(tmp, "k,p_k,decision,(x_k; y_k),p_k+1", _slipped(rows, row, col), question)
    assert marked["score"] == marked["out_of"] - 1  # one slip costs one step
    _said_matches_column(marked)


@settings(max_examples=25, deadline=None)
@given(st.integers(3, 14), st.data())
def test_a_circle_slip_is_told_once(tmp_path_factory, r, data):
    rows = midpoint_circle_rows(r)
    row = data.draw(st.integers(1, len(rows) - 2))
    col = data.draw(st.sampled_from([1, 2, 3]))
    tmp = tmp_path_factory.mktemp("slip")
    marked = _check(tmp, "k,p_k,decision,(x_k; y_k)", _slipped(rows, row, col), ["circle", str(r)])
    assert marked["score"] == marked["out_of"] - 1
    _said_matches_column(marked)


def test_a_decision_word_slipped_beside_the_right_pixel(tmp_path):
    rows = bresenham_rows(2, 2, 10, 6)
    rows[0][2] = "E"  # p0 = 0 chooses NE; the pixel (3, 3) and next p -8 are NE's
    marked = _check(tmp_path, "k,p_k,decision,(x_k; y_k),p_k+1", rows, "line 2 2 10 6".split())
    assert marked["score"] == 7 and marked["out_of"] == 8
    assert marked["first_error"].startswith("Row 1 (line 2): the decision should be NE, not E")
    assert "pixel" not in marked["first_error"] and "next p" not in marked["first_error"]
