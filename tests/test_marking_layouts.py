"""Marking by steps in any layout: any heading, scanconv's own tables; one slip
costs one step.

Every student table here was written by hand from the mistake it shows, and its score worked
out by hand in the comment above it (never by running scanconv). A step is p_k, the decision
and the point it reaches; a question is out of the steps it asks for: 8 for the line (2, 2) to
(10, 6), whose states are (2,2) p 0, NE (3,3) -8, E (4,3) 0, NE (5,4) -8, E (6,4) 0,
NE (7,5) -8, E (8,5) 0, NE (9,6) -8, E (10,6) 0.
"""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest

from scanconv import _api as api
from scanconv.core.checks import InputError
from scanconv.marking.mark import mark
from scanconv.marking.student_table import parse_text

from .helpers import assert_refused, run

LINE = ("line", "2", "2", "10", "6")


def check_text(tmp_path: Path, name: str, text: str, *question: str) -> dict:
    (tmp_path / name).write_text(text, encoding="utf-8")
    r = run("check", str(tmp_path / name), "--", *question, "-f", "json")
    assert r.code == 0, r.err
    return json.loads(r.out)


def scored(result: dict) -> list[str]:
    return [row[4] for row in result["tables"][0]["rows"] if row[4] != "given (not scored)"]


def md(text: str) -> str:
    """A CSV table written again as a Markdown pipe table (the same cells)."""
    rows = list(csv.reader(io.StringIO(text)))
    lines = ["| " + " | ".join(rows[0]) + " |", "|" + "---|" * len(rows[0])]
    lines += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    return "Worked answer:\n\n" + "\n".join(lines) + "\n"


def both(name: str, text: str) -> list[tuple[str, str]]:
    return [(f"{name}.csv", text), (f"{name}.md", md(text))]


def line_of(name: str, csv_line: int) -> int:
    """The file line of a CSV line in the same table written by :func:`md` (3 lines later)."""
    return csv_line + (3 if name.endswith(".md") else 0)


# --- 1. the layout is found by the best follow-through score ----------------------------------

# The textbook layout (row k: p_k and the point it reaches), p_3 miscopied as 8 for -8 while
# the point (6, 4) was decided on the true -8: step 4 is wrong (p; and from p = 8 the rule
# would go NE to (6, 5)); step 5 (p 0, (7, 5)) is the answer's own. 7 of 8.
TEXTBOOK_MISCOPY = """k,p_k,"(x_{k+1}, y_{k+1})"
0,0,"(3, 3)"
1,-8,"(4, 3)"
2,0,"(5, 4)"
3,8,"(6, 4)"
4,0,"(7, 5)"
5,-8,"(8, 5)"
6,0,"(9, 6)"
7,-8,"(10, 6)"
"""


@pytest.mark.parametrize(("name", "text"), both("textbook-miscopy", TEXTBOOK_MISCOPY))
def test_a_miscopied_p_in_the_textbook_layout_costs_one_step(tmp_path, name, text):
    result = check_text(tmp_path, name, text, *LINE)
    assert (result["score"], result["out_of"]) == (7, 8)
    assert scored(result) == ["right"] * 3 + ["wrong"] + ["right"] * 4
    assert result["first_error"] == (
        f"Row 4 (line {line_of(name, 5)}): p should be -8, not 8 (the step from (4, 3) with p = 0)."
    )


# --- 2. follow-through charges each slip once --------------------------------------------------

# Alice, the notes' layout: at k = 4, (6, 4) with p = 0, she chose E (p >= 0 is NE) and wrote
# p_5 = 0 + 2dy = 8, then carried on by the rule from her own values: 8 >= 0 NE (8, 5) with
# 8 - 8 = 0, 0 NE (9, 6) -8, -8 E (10, 6) 0. Step 5 is wrong once (the decision; her point
# (7, 4) and p_5 = 8 follow from her E); step 6 follows from her (7, 4) p = 8. 7 of 8.
TIE_NOTES = """k,p_k,Decision,"Pixel Plotted (x, y)",Next p_{k+1}
0,0,NE,"(2, 2)",-8
1,-8,E,"(3, 3)",0
2,0,NE,"(4, 3)",-8
3,-8,E,"(5, 4)",0
4,0,E,"(6, 4)",8
5,8,NE,"(7, 4)",0
6,0,NE,"(8, 5)",-8
7,-8,E,"(9, 6)",0
8,0,,"(10, 6)",
"""

# The same slip in the textbook layout: row k holds p_k, the decision, (x_{k+1}, y_{k+1}) and
# p_{k+1}; row 4 is the slip, from (6, 4) with p = 0. 7 of 8.
TIE_TEXTBOOK = """k,p_k,decision,"(x_{k+1}, y_{k+1})",p_{k+1}
0,0,NE,"(3, 3)",-8
1,-8,E,"(4, 3)",0
2,0,NE,"(5, 4)",-8
3,-8,E,"(6, 4)",0
4,0,E,"(7, 4)",8
5,8,NE,"(8, 5)",0
6,0,NE,"(9, 6)",-8
7,-8,E,"(10, 6)",0
"""


@pytest.mark.parametrize(
    ("name", "text", "line"),
    [(n, t, 6) for n, t in both("tie-notes", TIE_NOTES)]
    + [(n, t, 6) for n, t in both("tie-textbook", TIE_TEXTBOOK)],
)
def test_a_wrong_decision_at_a_tie_costs_one_step_and_is_named(tmp_path, name, text, line):
    result = check_text(tmp_path, name, text, *LINE)
    assert (result["score"], result["out_of"]) == (7, 8)
    assert scored(result) == ["right"] * 4 + ["wrong", "right (follow-through)"] + ["right"] * 2
    assert result["first_error"] == (
        f"Row 5 (line {line_of(name, line)}): the decision should be NE, not E "
        "(at (6, 4) with p = 0, p >= 0 chooses NE)."
    )
    assert "decision" in result["marked"]
    row5 = result["tables"][0]["rows"][5 if name.startswith("tie-notes") else 4]
    assert "p = 0, E," in row5[2] and "p = 0, NE," in row5[3]


# Without a decision column the slip shows in the point: step 5 (7, 4) for (7, 5), named with
# the state and the rule; p_5 = 8 follows from her own E. 7 of 8.
TIE_NO_DECISION = """k,p,x,y
0,0,2,2
1,-8,3,3
2,0,4,3
3,-8,5,4
4,0,6,4
5,8,7,4
6,0,8,5
7,-8,9,6
8,0,10,6
"""


def test_a_tie_slip_without_a_decision_column_is_named_at_its_state(tmp_path):
    result = check_text(tmp_path, "tie.csv", TIE_NO_DECISION, *LINE)
    assert (result["score"], result["out_of"]) == (7, 8)
    assert result["first_error"] == (
        "Row 5 (line 7): the pixel should be (7, 5), not (7, 4) "
        "(at (6, 4) with p = 0, p >= 0 chooses NE)."
    )


# A decision that disagrees with the student's own p: at (5, 4) p = -8 written NE, the point
# (6, 5) and p_4 = -8 - 8 = -16 follow from that NE; then -16 E (7, 5) -8, E (8, 5) 0,
# NE (9, 6) -8, E (10, 6) 0 -- all from her own values. Step 4 wrong once: 7 of 8.
DECISION_AGAINST_P = """k,p_k,decision,"(x_k, y_k)"
0,0,NE,"(2, 2)"
1,-8,E,"(3, 3)"
2,0,NE,"(4, 3)"
3,-8,NE,"(5, 4)"
4,-16,E,"(6, 5)"
5,-8,E,"(7, 5)"
6,0,NE,"(8, 5)"
7,-8,E,"(9, 6)"
8,0,,"(10, 6)"
"""


def test_a_decision_against_the_students_own_p_is_wrong_once(tmp_path):
    result = check_text(tmp_path, "against.csv", DECISION_AGAINST_P, *LINE)
    assert (result["score"], result["out_of"]) == (7, 8)
    assert scored(result)[3] == "wrong" and scored(result)[4] == "right (follow-through)"
    assert (
        "the decision should be E, not NE (at (5, 4) with p = -8, p < 0 chooses E)"
        in (result["first_error"])
    )


# --- 3. one denominator -------------------------------------------------------------------------

RIGHT_NOTES = TIE_NOTES.replace('4,0,E,"(6, 4)",8', '4,0,NE,"(6, 4)",-8').replace(
    '5,8,NE,"(7, 4)",0', '5,-8,E,"(7, 5)",0'
)


def test_the_same_answer_is_out_of_the_same_steps_in_every_layout(tmp_path):
    notes = (
        "k,p,(x_k, y_k)\n0,0,(2 2)\n1,-8,(3 3)\n2,0,(4 3)\n3,-8,(5 4)\n4,0,(6 4)\n"
        "5,-8,(7 5)\n6,0,(8 5)\n7,-8,(9 6)\n8,0,(10 6)\n"
    )
    textbook = TIE_TEXTBOOK.replace('4,0,E,"(7, 4)",8', '4,0,NE,"(7, 5)",-8').replace(
        '5,8,NE,"(8, 5)",0', '5,-8,E,"(8, 5)",0'
    )
    for name, text in (("n.csv", notes), ("t.csv", textbook)):
        result = check_text(tmp_path, name, text, *LINE)
        assert (result["score"], result["out_of"]) == (8, 8), name
    # the start row is shown and said to be unscored
    result = check_text(tmp_path, "n.csv", notes, *LINE)
    assert result["tables"][0]["rows"][0][4] == "given (not scored)"
    assert any("shown, not scored" in n for n in result["notes"])


# --- 5. the notes' names and headings ------------------------------------------------------------

# The notes' Topic 9 ("Bresenham's circle", p0 = 1 - r) for r = 8, in the notes' own heading:
# -7 E (1,8) -7 + 3 = -4, E (2,8) -4 + 5 = 1, SE (3,7) 1 + 6 - 14 + 1 = -6, E (4,7) -6 + 9 = 3,
# SE (5,6) 3 + 10 - 12 + 1 = 2, SE (6,5) 2 + 12 - 10 + 1 = 5. Against d0 = 3 - 2r the pixels
# are Bresenham's (0,8) (1,8) (2,8) (3,7) (4,7) (5,6): its 5 steps, all right: 5 of 5.
NOTES_TOPIC9 = """k,x,y,p,Plot Point (one octant)
0,0,8,-7,"(0,8)"
1,1,8,-4,"(1,8)"
2,2,8,1,"(2,8)"
3,3,7,-6,"(3,7)"
4,4,7,3,"(4,7)"
5,5,6,2,"(5,6)"
6,6,5,5,"(6,5)"
"""

# The reverse: d0 = 3 - 2r = -13, -13 + 6 = -7, -7 + 4 + 6 = 3, 3 + 4(2 - 8) + 10 = -11,
# -11 + 12 + 6 = 7, 7 + 4(4 - 7) + 10 = 5, against the midpoint question (6 steps, to (6, 5)):
# its 5 points are right, (6, 5) is missing: 5 of 6.
BRESENHAM_D = """k,d_k,"(x_k, y_k)"
0,-13,"(0, 8)"
1,-7,"(1, 8)"
2,3,"(2, 8)"
3,-11,"(3, 7)"
4,7,"(4, 7)"
5,5,"(5, 6)"
"""


@pytest.mark.parametrize(
    ("name", "text", "question", "marks"),
    [
        (n, t, ("circle", "8", "--method", "bresenham"), (5, 5))
        for n, t in both("topic9", NOTES_TOPIC9)
    ]
    + [(n, t, ("circle", "8"), (5, 6)) for n, t in both("d", BRESENHAM_D)],
)
def test_the_other_circle_form_is_diagnosed_and_its_pixels_marked(
    tmp_path, name, text, question, marks
):
    result = check_text(tmp_path, name, text, *question)
    assert (result["score"], result["out_of"]) == marks
    assert "the other circle form" in result["diagnosis"]
    assert "p" not in result["marked"] and "pixel" in result["marked"]


def test_practice_words_circles_by_the_notes_names():
    import random

    from scanconv.practice.notes import _CIRCLE_NAMES, _circle

    assert "p0 = 1 - r" in _CIRCLE_NAMES["midpoint"]
    assert "d0 = 3 - 2r" in _CIRCLE_NAMES["bresenham"]
    for method in ("midpoint", "bresenham"):
        q = _circle(random.Random(1), "easy", (method, False))
        assert q.argv[3] == method and _CIRCLE_NAMES[method] in q.wording


@pytest.mark.parametrize(
    "heading",
    [
        "k,p_k,Decision,Pixel Plotted (x y),Next p_{k+1}",
        "k,p_k,Decision,(x y),Next p_{k+1}",
        "k,p_k,decision,Pixel Plotted (x, y),p_{k+1}",
    ],
)
def test_the_notes_own_headings_are_read(tmp_path, heading):
    body = RIGHT_NOTES.split("\n", 1)[1]
    result = check_text(tmp_path, "h.csv", heading + "\n" + body, *LINE)
    assert (result["score"], result["out_of"]) == (8, 8)


# The notes' own tables, copied as they are printed (tab-separated, the notes' headings). The
# DDA for (2, 2) to (10, 6) is right: 8 of 8. The Bresenham table is the notes' p0 = -28 one
# (errata E1): its whole table is named.
NOTES_DDA_TSV = "k\tx_k (Calculated)\ty_k (Calculated)\t$\\text{round}(x_k)$\t$\\text{round}(y_k)$\tPixel (x, y)\n0\t2.000\t2.000\t2\t2\t(2, 2)\n1\t3.000\t2.500\t3\t3\t(3, 3)\n2\t4.000\t3.000\t4\t3\t(4, 3)\n3\t5.000\t3.500\t5\t4\t(5, 4)\n4\t6.000\t4.000\t6\t4\t(6, 4)\n5\t7.000\t4.500\t7\t5\t(7, 5)\n6\t8.000\t5.000\t8\t5\t(8, 5)\n7\t9.000\t5.500\t9\t6\t(9, 6)\n8\t10.000\t6.000\t10\t6\t(10, 6)\n"
NOTES_E1_TSV = "k\tp_k\tDecision\tPixel Plotted (x, y)\tNext p_{k+1}\n0\t-28\tE\t(2, 2)\t-20\n1\t-20\tE\t(3, 2)\t-12\n2\t-12\tE\t(4, 2)\t-4\n3\t-4\tE\t(5, 2)\t4\n4\t4\tNE\t(6, 3)\t-20\n5\t-20\tE\t(7, 3)\t-12\n6\t-12\tE\t(8, 3)\t-4\n7\t-4\tE\t(9, 3)\t4\n8\t4\tNE\t(10, 4)\t-20\n"


def test_the_notes_own_tables_are_read_as_printed(tmp_path):
    result = check_text(tmp_path, "dda.tsv", NOTES_DDA_TSV, *LINE, "--algo", "dda")
    assert (result["score"], result["out_of"]) == (8, 8)
    result = check_text(tmp_path, "e1.txt", NOTES_E1_TSV, *LINE)
    assert "exactly the one the course notes print" in result["diagnosis"]


def test_headings_with_k_plus_1_and_units_are_read(tmp_path):
    # the textbook layout in two columns x_k+1, y_k+1 with units: 8 of 8
    text = "k,p_k,x_k+1 (px),y_k+1 (px)\n" + "".join(
        f"{k},{p},{x},{y}\n"
        for k, p, x, y in [
            (0, 0, 3, 3),
            (1, -8, 4, 3),
            (2, 0, 5, 4),
            (3, -8, 6, 4),
            (4, 0, 7, 5),
            (5, -8, 8, 5),
            (6, 0, 9, 6),
            (7, -8, 10, 6),
        ]
    )
    result = check_text(tmp_path, "units.csv", text, *LINE)
    assert (result["score"], result["out_of"]) == (8, 8)


def test_a_heading_it_cannot_read_is_one_line_naming_the_columns(tmp_path):
    (tmp_path / "odd.csv").write_text("step,value,where\n0,0,here\n")
    r = run("check", str(tmp_path / "odd.csv"), "--", *LINE)
    assert_refused(r, "odd.csv", "'step', 'value', 'where'", "(x, y)", "Pixel Plotted (x, y)")


# --- 6. diagnoses ---------------------------------------------------------------------------------

# r = 5 centred at (10, 10), the octant written with the centre added: (0,5) -4, (1,5) -1,
# (2,5) 4, (3,4) 3, (4,3) 6 as (10,15) (11,15) (12,15) (13,14) (14,13): right points, 4 of 4.
ABSOLUTE = """k,p,x,y
0,-4,10,15
1,-1,11,15
2,4,12,15
3,3,13,14
4,6,14,13
"""

# r = 5, x and y exchanged: (5,0) (5,1) (5,2) (4,3) (3,4) with the right p: every point
# wrong, 0 of 4.
SWAPPED = """k,p,x,y
0,-4,5,0
1,-1,5,1
2,4,5,2
3,3,4,3
4,6,3,4
"""

# The DDA (2,2)-(10,6) in the notes' own DDA heading, y = 2 + k/2 rounded by truncation:
# 2.5 -> 2, 3.5 -> 3, 4.5 -> 4, 5.5 -> 5: steps 1, 3, 5, 7 wrong, 4 of 8.
DDA_TRUNC = """k,x_k (Calculated),y_k (Calculated),round(x_k),round(y_k)
0,2,2,2,2
1,3,2.5,3,2
2,4,3,4,3
3,5,3.5,5,3
4,6,4,6,4
5,7,4.5,7,4
6,8,5,8,5
7,9,5.5,9,5
8,10,6,10,6
"""

# Half to even: 2.5 -> 2, 3.5 -> 4, 4.5 -> 4, 5.5 -> 6: steps 1 and 5 wrong, 6 of 8.
DDA_EVEN = DDA_TRUNC.replace("3,5,3.5,5,3", "3,5,3.5,5,4").replace("7,9,5.5,9,5", "7,9,5.5,9,6")

# The end point left out: 7 steps, the 8th missing: 7 of 8. Written twice: 8 right, one row
# past the end: 7 of 8.
ENDLESS = 'k,p_k,"(x_k, y_k)"\n' + "".join(
    f'{k},{p},"({x}, {y})"\n'
    for k, p, x, y in [
        (0, 0, 2, 2),
        (1, -8, 3, 3),
        (2, 0, 4, 3),
        (3, -8, 5, 4),
        (4, 0, 6, 4),
        (5, -8, 7, 5),
        (6, 0, 8, 5),
        (7, -8, 9, 6),
    ]
)
TWICE = ENDLESS + '8,0,"(10, 6)"\n9,,"(10, 6)"\n'

DIAGNOSES = [
    (
        ("circle", "5", "--center", "10", "10"),
        ABSOLUTE,
        (4, 4),
        "absolute pixels, the centre (10, 10)",
    ),
    (("circle", "5"), SWAPPED, (0, 4), "x and y exchanged"),
    ((*LINE, "--algo", "dda"), DDA_TRUNC, (4, 8), "rounding = trunc"),
    ((*LINE, "--algo", "dda"), DDA_EVEN, (6, 8), "half to even"),
    (LINE, ENDLESS, (7, 8), "the end point (10, 6) is omitted"),
    (LINE, TWICE, (7, 8), "the end point (10, 6) twice"),
]


@pytest.mark.parametrize(
    ("question", "text", "marks", "words", "fmt"),
    [(*d, fmt) for d in DIAGNOSES for fmt in ("csv", "md")],
    ids=lambda v: str(v)[:30],
)
def test_each_common_mistake_is_diagnosed(tmp_path, question, text, marks, words, fmt):
    result = check_text(tmp_path, f"t.{fmt}", text if fmt == "csv" else md(text), *question)
    assert (result["score"], result["out_of"]) == marks
    assert words in result["diagnosis"], result["diagnosis"]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_batch_csv_gives_each_file_its_single_run_score(tmp_path):
    folder = tmp_path / "class"
    folder.mkdir()
    tables = {
        "miscopy.csv": TEXTBOOK_MISCOPY,
        "tie.csv": TIE_NOTES,
        "trunc.csv": DDA_TRUNC,
        "end.md": md(ENDLESS),
    }
    for name, text in tables.items():
        (folder / name).write_text(text)
    r = run("check", "--batch", str(folder), "--", *LINE)
    assert r.code == 0, r.err
    batch = {row["name"]: row for row in csv.DictReader(io.StringIO(r.out))}
    for name in tables:
        single = json.loads(run("check", str(folder / name), "--", *LINE, "-f", "json").out)
        row = batch[name]
        assert (int(row["score"]), int(row["out_of"])) == (single["score"], single["out_of"])
        assert row["first_error"] == single["first_error"]


# --- the step models from any state, by any move -------------------------------------------------


def test_each_model_steps_by_a_given_move_and_names_its_rule():
    from scanconv.marking.models import (
        BresenhamCircle,
        BresenhamLine,
        MidpointCircle,
        MidpointEllipse,
        State,
        UnswappedLine,
    )

    line = BresenhamLine(2, 2, 10, 6, tie="keep")
    s = State((6, 4), 0, k=4)
    # tie = keep: p <= 0 keeps y (E): 0 + 2dy = 8; the move NE taken anyway: 0 + 8 - 16 = -8
    assert line.decide(s) == "E" and line.rule(s) == "p <= 0 chooses E"
    assert line.step(s, "NE") == State((7, 5), -8, k=5)
    assert line.step(s, "SE") is None and line.step(s._replace(p=None), "E") is None
    assert BresenhamLine(2, 2, 10, 6).rule(State((2, 2), 3)) == "p >= 0 chooses NE"
    # not swapped, (10, 6) to (2, 2): dx = -8, dy = -4; E adds 2dy = -8
    assert UnswappedLine(10, 6, 2, 2).step(State((10, 6), 0), "E") == State((11, 6), -8, k=1)
    assert UnswappedLine(10, 6, 2, 2).step(State((10, 6), 0), "SE") is None
    # circles: a move that is not E or SE, or no p, is no step
    for model in (MidpointCircle(5), BresenhamCircle(5)):
        assert model.step(State((0, 5), -4), "NE") is None
        assert (
            model.step(State((0, 5), None), "E") is None and model.rule(State((0, 5), None)) == ""
        )
    assert BresenhamCircle(5).rule(State((0, 5), -7)) == "d < 0 chooses E"
    # the ellipse 8 x 6: region 2 from (7, 3) with p2 = -23 <= 0 goes SE; tie = keep at 0 is S
    e = MidpointEllipse(8, 6, tie="keep")
    r2 = State((7, 3), -23, region=2, k=7)
    assert e.decide(r2) == "SE" and e.rule(r2) == "p2 < 0 chooses SE"
    assert e.rule(r2._replace(p=0)) == "p2 >= 0 chooses S"
    assert MidpointEllipse(8, 6).rule(r2) == "p2 <= 0 chooses SE"
    assert e.at((7, 2), r2) == r2._replace(point=(7, 2))
    assert e.step(r2, "E") is None and e.step(r2._replace(p=None), "S") is None
    assert e.step(State((0, 6), None, region=1), "E") is None
    assert e.rule(State((0, 6), None, region=1)) == ""


@pytest.mark.parametrize(
    ("heading", "field"),
    [
        ("x (rounded)", "px"),
        ("y (Rounded)", "py"),
        ("round (x, y)", "pxy"),
        ("Pixel Plotted (x y)", "pxy"),
        ("x_k+1 (px)", "x"),
        ("Next (x, y)", None),
        ("(x_c+x, y_c+y)", None),
        ("Update p", "p_next"),
        ("Choose", "decision"),
    ],
)
def test_the_notes_headings_map_to_fields(heading, field):
    from scanconv.marking.student_table import field_of

    assert field_of(heading)[0] == field


def test_odd_tables_are_read_or_refused_in_one_line():
    # a document whose pipe tables have no pixels: the first is named in the refusal
    with pytest.raises(InputError, match="no column for the pixels among the columns 'a', 'b'"):
        parse_text("| a | b |\n|---|---|\n| 1 | 2 |\n\n| c |\n|---|\n| 3 |\n", "t.md", ".md")
    # pipe rows without a separator, no suffix: refused, naming the line
    with pytest.raises(InputError, match="line 1: a pipe table needs"):
        parse_text("| k | (x, y) |\n| 0 | (2, 2) |\n", "t")
    # x next to round(y): the pixel is (x, round(y)); a pixel of 2.5 is no pixel
    t = parse_text("x,y_sqrt,round(y)\n0,5,5\n1,4.899,5\n2,4.583,2.5\n", "p.csv")
    m = mark(t, api.circle(5, method="polynomial"))
    assert [v.mark for v in m.verdicts][:3] == ["right", "right", "wrong"]


def test_a_circle_with_a_blank_point_is_marked_and_the_centre_tried(tmp_path):
    # r = 5 at (10, 10), absolute points with one blank: the blank step is wrong, 3 of 4
    text = ABSOLUTE.replace("2,4,12,15", "2,4,,")
    result = check_text(tmp_path, "blank.csv", text, "circle", "5", "--center", "10", "10")
    assert (result["score"], result["out_of"]) == (3, 4)


# A table typed in a text file, columns lined up with spaces, in the notes' layout with the
# notes' heading: the line (2, 2) to (10, 6) all right, 8 of 8; the same with single spaces.
SPACED = """k   p_k   Pixel Plotted (x, y)
0   0     (2, 2)
1   -8    (3, 3)
2   0     (4, 3)
3   -8    (5, 4)
4   0     (6, 4)
5   -8    (7, 5)
6   0     (8, 5)
7   -8    (9, 6)
8   0     (10, 6)
"""


@pytest.mark.parametrize(
    "text",
    [
        SPACED,
        "k p x y\n0 0 2 2\n1 -8 3 3\n2 0 4 3\n3 -8 5 4\n"
        "4 0 6 4\n5 -8 7 5\n6 0 8 5\n7 -8 9 6\n8 0 10 6\n",
    ],
)
def test_a_table_lined_up_with_spaces_is_read(tmp_path, text):
    result = check_text(tmp_path, "typed.txt", text, *LINE)
    assert (result["score"], result["out_of"]) == (8, 8)
