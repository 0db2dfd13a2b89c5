"""``check`` reads what students write: decisions in words (East, North-East, right,
diagonal, ...), a name and roll number above the table, and a decision it cannot read named
as such, never as blank. Every table here is written by hand from the
notes' algorithms: Bresenham's line (2, 2) to (10, 6) takes p = 0, -8, 0, -8, ... and NE, E,
NE, E, ...; the midpoint circle r = 5 takes p = -4, -1, 4, 3 and E, E, SE, SE."""

from __future__ import annotations

import json

import pytest

from .helpers import run, run_process

LINE = ("--", "line", "2", "2", "10", "6")
CIRCLE = ("--", "circle", "5")

LINE_ROWS = [(0, 0, "NE", 2, 2), (1, -8, "E", 3, 3), (2, 0, "NE", 4, 3), (3, -8, "E", 5, 4),
             (4, 0, "NE", 6, 4), (5, -8, "E", 7, 5), (6, 0, "NE", 8, 5), (7, -8, "E", 9, 6)]  # fmt: skip
WORDS = {
    "NE": ["North-East", "north east", "northeast", "NORTH-EAST", "diagonal", "ne"],
    "E": ["East", "east", "right", "horizontal", "straight", "e"],
    "SE": ["South-East", "south east", "diagonal", "se"],
}


def _score(r) -> tuple[int, int]:
    assert r.code == 0, r.err
    right, total = json.loads(r.out)["derived"]["score"].split("/")
    return int(right), int(total)


def _line_csv(words: dict[str, str], preamble: str = "") -> str:
    rows = [f"{k},{p},{words.get(d, d)},{x},{y}" for k, p, d, x, y in LINE_ROWS]
    return preamble + "k,p,decision,x,y\n" + "\n".join(rows) + "\n8,,,10,6\n"


@pytest.mark.parametrize("i", range(6))
def test_decisions_in_words_are_read(tmp_path, i):
    words = {"NE": WORDS["NE"][i], "E": WORDS["E"][i]}
    f = tmp_path / "a.csv"
    f.write_text(_line_csv(words))
    assert _score(run("check", str(f), "-f", "json", *LINE)) == (8, 8)


def test_a_wrong_word_is_wrong_once(tmp_path):
    f = tmp_path / "a.csv"
    f.write_text(_line_csv({}).replace("2,0,NE,4,3", "2,0,East,4,3"))  # step 2 says E for NE
    r = run("check", str(f), "-f", "plain", *LINE)
    assert "score = 7 / 8" in r.out and "should be NE, not E" in r.out


def test_the_circle_s_south_east_in_words(tmp_path):
    f = tmp_path / "c.csv"
    f.write_text("k,p,decision,x,y\n0,-4,East,0,5\n1,-1,right,1,5\n2,4,South-East,2,5\n"
                 "3,3,diagonal,3,4\n4,,,4,3\n")  # fmt: skip
    assert _score(run("check", str(f), "-f", "json", *CIRCLE)) == (4, 4)


def test_an_unreadable_decision_is_named_not_called_blank(tmp_path):
    f = tmp_path / "a.csv"
    f.write_text(_line_csv({}).replace("1,-8,E,3,3", "1,-8,keep y,3,3"))
    r = run("check", str(f), "-f", "plain", *LINE)
    assert "score = 7 / 8" in r.out
    assert "'keep y' (not a move)" in r.out and "not blank" not in r.out


@pytest.mark.parametrize(
    "preamble",
    ["Name:,Gita\nRoll no:,42\n\n", "Gita Sharma\nRoll 42\n", "Name\tGita\n", "# homework 3\n"],
)
def test_a_name_and_roll_number_above_the_table(tmp_path, preamble):
    f = tmp_path / "gita.csv"
    text = _line_csv({}, preamble)
    if "\t" in preamble:
        text = preamble + _line_csv({}).replace(",", "\t")
    f.write_text(text)
    assert _score(run("check", str(f), "-f", "json", *LINE)) == (8, 8)


@pytest.mark.slow  # a real process, as a teacher runs it
def test_as_a_teacher_runs_it(tmp_path):
    f = tmp_path / "gita.csv"
    f.write_text(_line_csv({"NE": "North-East", "E": "East"}, "Name:,Gita\nRoll no:,42\n"))
    r = run_process("check", str(f), *LINE)
    assert (r.code == 0 and "8/8" in r.out.replace(" ", "")) or "score = 8 / 8" in r.out, r.out
