"""``scanconv check``: reading students' tables, follow-through marking, diagnosis, batches.

Every wrong table in ``tests/data/check/`` was written by hand from the mistake it shows (the
arithmetic is in the comments of :data:`DIAGNOSES`), never by running scanconv with a bug.
The step models that follow-through re-runs are checked against the library's own tables in
every octant and for every convention knob.

The two random-input properties (any bytes, any table) run 100 examples each (they ran
300 before the suite had a time budget); the hand-written wrong tables and
``test_marking_layouts`` cover the reader's known hazards one by one.
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import re
import shutil
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanconv
from scanconv import _api as api
from scanconv.core.checks import InputError
from scanconv.marking.mark import mark
from scanconv.marking.models import (
    BresenhamCircle,
    BresenhamLine,
    DDALine,
    GeneralCircle,
    MidpointCircle,
    MidpointEllipse,
    State,
    chain,
)
from scanconv.marking.student_table import Cell, field_of, parse_text, read_table
from scanconv.render import formats
from scanconv.render.documents.scores import neutral

from .helpers import assert_refused, run

DATA = Path(__file__).resolve().parent / "data" / "check"
LINE = ("line", "2", "2", "10", "6")


def check(name: str, *question: str, fmt: str = "json") -> dict:
    r = run("check", str(DATA / name), "--", *question, "-f", fmt)
    assert r.code == 0, r.err
    return json.loads(r.out) if fmt == "json" else {"text": r.out}


def marks(result: dict) -> list[str]:
    """The marks of the scored steps (the given start row, shown, is left out)."""
    return [row[4] for row in result["tables"][0]["rows"] if row[4] != "given (not scored)"]


# --- the step models are the library's algorithms ---------------------------------------------

ENDS = [
    (2, 2, 10, 6),
    (10, 6, 2, 2),
    (2, 2, 5, 10),
    (5, 10, 2, 2),
    (0, 0, -3, 7),
    (0, 0, 7, -3),
    (0, 0, -7, -3),
    (0, 0, -4, 4),
    (4, 4, 0, 0),
    (3, 3, 3, 3),
    (1, 5, 6, 5),
    (0, 0, 0, -6),
    (-2, 1, 4, -3),
]


@pytest.mark.parametrize("ends", ENDS)
def test_line_models_make_the_library_tables_in_every_octant(ends):
    for tie, start in itertools.product(("step", "keep"), ("swap", "given")):
        sol = api.line(*ends, algo="bresenham", tie=tie, start=start)
        want = [(s.pixel, s.p) for s in sol.steps()]
        assert [(s.point, s.p) for s in chain(BresenhamLine(*ends, tie, start))] == want
    for rounding in ("half-up", "trunc", "half-even", "c-cast", "half-away"):
        for start in ("swap", "given"):
            sol = api.line(*ends, algo="dda", rounding=rounding, start=start)
            want = [(s.pixel, tuple(s.extra[:2])) for s in sol.steps()]
            got = [(s.point, s.exact) for s in chain(DDALine(*ends, rounding, start))]
            assert got == want


def test_the_dda_model_takes_fractional_end_points():
    ends = (Fraction(1, 2), 0, Fraction(7, 2), Fraction(5, 3))
    sol = api.line(*ends, algo="dda")
    assert [s.point for s in chain(DDALine(*ends))] == [s.pixel for s in sol.steps()]


@pytest.mark.parametrize("r", [0, 1, 2, 5, 7, 10, 13, 29])
def test_circle_models_make_the_library_tables(r):
    for tie, p0, loop in itertools.product(
        ("step", "keep"), ("1-r", "5/4-r"), ("strict", "inclusive")
    ):
        sol = api.circle(r, method="midpoint", tie=tie, p0=p0, loop=loop)
        want = [(s.pixel, s.p) for s in sol.steps()]
        assert [(s.point, s.p) for s in chain(MidpointCircle(r, tie, p0, loop))] == want
        sol = api.circle(r, method="general", tie=tie, loop=loop)
        want = [(s.pixel, s.p) for s in sol.steps()]
        assert [(s.point, s.p) for s in chain(GeneralCircle(r, tie, loop))] == want
    for tie in ("step", "keep"):
        sol = api.circle(r, method="bresenham", tie=tie)
        want = [(s.pixel, s.p) for s in sol.steps()]
        assert [(s.point, s.p) for s in chain(BresenhamCircle(r, tie))] == want


@pytest.mark.parametrize(("rx", "ry"), [(8, 6), (6, 8), (3, 2), (10, 1), (1, 10), (5, 5), (1, 1)])
def test_the_ellipse_model_makes_the_library_table_in_both_regions(rx, ry):
    for loop, tie, p0 in itertools.product(
        ("strict", "inclusive"), ("step", "keep"), ("exact", "rounded")
    ):
        sol = api.ellipse(rx, ry, loop=loop, tie=tie, p0=p0)
        states = list(chain(MidpointEllipse(rx, ry, loop, tie, p0)))
        rows = [(states[i + 1].point, states[i].p) for i in range(len(states) - 1)]
        assert rows == [(s.pixel, s.p) for s in sol.steps()]


def test_a_model_steps_from_a_state_the_algorithm_never_reaches():
    # by hand: from (3, 2) with p = -3 < 0 the line (2,2)-(10,6) keeps y, p += 2dy = 8
    assert BresenhamLine(2, 2, 10, 6).advance(State((3, 2), -3)) == State((4, 2), 5, k=1)
    # the midpoint circle r = 10 from (3, 10) with p = 2 >= 0: SE to (4, 9), p += 2*4 + 1 - 18
    assert MidpointCircle(10).advance(State((3, 10), 2)) == State((4, 9), -7, k=1)


# --- reading a student's table ----------------------------------------------------------------


@pytest.mark.parametrize(
    ("heading", "field"),
    [
        ("p_k", "p"),
        ("$p_k$", "p"),
        ("pₖ", "p"),
        (" P K ", "p"),
        ("d_k", "p"),
        ("p1_k", "p"),
        ("p_{k+1}", "p_next"),
        ("Next p_{k+1}", "p_next"),
        ("(x_{k+1}, y_{k+1})", "xy"),
        ("(x, y)", "xy"),
        ("(xk,yk)", "xy"),
        ("pixel", "pxy"),
        ("Plot", "pxy"),
        ("Pixel Plotted (x, y)", "pxy"),
        ("round(x)", "px"),
        ("Round(Y)", "py"),
        ("x_k", "x"),
        ("Y", "y"),
        ("k", "k"),
        ("2ry²x", None),
    ],
)
def test_headings_are_matched_forgivingly(heading, field):
    assert field_of(heading)[0] == field


def test_values_are_read_forgivingly():
    a = parse_text("k,p,x,y\n0,2.5,3,3\n", "a.csv")
    b = parse_text("k,p,(x, y)\n0,2.500,(3,3)\n", "b.csv")
    c = parse_text("| k | p | pixel |\n|---|---|---|\n| 0 | 5/2 | ( 3 , 3 ) |\n", "c.md")
    d = parse_text('[{"k": 0, "p": 2.5, "pixel": [3, 3]}]', "d.json")
    values = []
    for t in (a, b, c, d):
        cells = t.rows[0].cells
        point = cells.get("xy") or cells.get("pxy") or (cells["x"], cells["y"])
        values.append((cells["p"].value, tuple(v.value for v in point)))
    assert values == [(Fraction(5, 2), (3, 3))] * 4
    minus = parse_text("k,p,x,y\n0,\u22128,3,3\n", "m.csv")
    assert minus.rows[0].cells["p"] == Cell(Fraction(-8), 0)


def test_an_unquoted_pair_in_a_csv_is_one_cell():
    t = parse_text("k,p_k,(x_{k+1}, y_{k+1})\n0,0,(3, 3)\n", "a.csv")
    assert t.after and t.rows[0].cells["xy"] == (Cell(Fraction(3), 0), Cell(Fraction(3), 0))


def test_scanconv_json_is_a_student_table(tmp_path):
    r = run(*LINE, "-f", "json")
    (tmp_path / "own.json").write_text(r.out)
    result = json.loads(run("check", str(tmp_path / "own.json"), "--", *LINE, "-f", "json").out)
    assert (result["score"], result["out_of"]) == (8, 8)  # 8 steps, the start row not scored


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("missing-column.csv", ("missing-column.csv", "no column for the pixels")),
        ("ragged.csv", ("ragged.csv, line 3", "3 cells", "4 columns")),
        ("not-a-number.csv", ("not-a-number.csv, line 3", "'abc' is not a number")),
        ("empty.csv", ("empty.csv", "empty")),
        ("binary.csv", ("binary.csv", "binary")),
        ("latin1.csv", ("latin1.csv, line 3", "not UTF-8")),
    ],
)
def test_a_malformed_table_is_one_clear_line(name, words):
    r = run("check", str(DATA / name), "--", *LINE)
    assert_refused(r, *words)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_other_bad_tables(tmp_path):
    cases = {
        "x-only.csv": ("k,p,x\n0,0,2\n", "no column for y"),
        "two-p.csv": ("p,p_k,x,y\n0,1,2,2\n", "both read as p"),
        "no-rows.csv": ("k,p,x,y\n", "no rows"),
        "bad-pair.csv": ('k,p,pixel\n0,0,"(2)"\n', "not a pixel"),
        "nan.csv": ("k,p,x,y\n0,nan,2,2\n", "not a finite number"),
        "bad.json": ('{"k": 1', "not valid JSON"),
        "scalar.json": ("[1, 2]", "list of row objects"),
        "no-table.md": ("Just words, no table.\n| not | a table\n", "separator"),
    }
    for name, (text, words) in cases.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
        assert_refused(run("check", str(tmp_path / name), "--", *LINE), name, words)
    assert_refused(run("check", str(tmp_path / "absent.csv"), "--", *LINE), "absent.csv")
    assert_refused(run("check", str(tmp_path), "--", *LINE), "not a regular file")


def test_nothing_in_a_cell_is_evaluated():
    with pytest.raises(InputError, match="not a number"):
        parse_text("k,p,x,y\n0,__import__('os'),2,2\n", "evil.csv")
    with pytest.raises(InputError, match="not a number"):
        parse_text("k,p,x,y\n0,2*3,2,2\n", "expr.csv")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_bad_question_is_one_line():
    student = str(DATA / "slip.csv")
    assert_refused(run("check", student, "--", "line", "2", "2"), "Missing argument")
    assert_refused(run("check", student, "--", "check", student), "not 'check'")
    assert_refused(run("check", student, "--", "line", "2", "2", "10", "6", "--tie", "x"), "'x'")
    assert_refused(run("check", student), "no question")
    assert_refused(run("check", student, "--", "storage", "8", "8", "--bits", "8"), "step table")
    assert_refused(run("check", student, "--", "parametric"), "incomplete")
    assert_refused(run("check", student, "--", "bogus", "1"), "No such command")
    assert_refused(run("check", student, "--", *LINE, "--svg", "x.svg"), "draws no figure")
    assert_refused(run("check", student, "--", *LINE, "--help"), "--help")


def test_a_question_in_a_group_is_marked_by_position():
    r = run("check", str(DATA / "slip.csv"), "--", "parametric", "line", "2", "2", "10", "6")
    assert r.code == 0 and "without follow-through" in r.out


# --- follow-through ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "question", "wrong_row", "rows"),
    [
        # (2,2)-(10,6): row 4 writes p = -4 for -8; from it by hand: -4 < 0 E (6,4) p = 4,
        # 4 >= 0 NE (7,5) p = -4, ... every later row follows from the slip (8 steps)
        ("slip.csv", LINE, 4, 8),
        # ellipse 8 6, row k = 2 writes p1 = -40 for -44; then -40 + 2*36*3 + 36 = 212 SE (4,5),
        # 212 + 288 - 640 + 36 = -104, -104 + 360 + 36 = 292, 292 + 432 - 512 + 36 = 248, and
        # region 2 starts at (7, 3) with p2_0 = -23 as in the answer
        ("ellipse-slip.csv", ("ellipse", "8", "6"), 3, 10),
        # Bresenham circle r = 10, d = 1 for -1 at (2, 10): SE, 1 + 4(2 - 10) + 10 = -21 at
        # (3, 9); -21 + 12 + 6 = -3; -3 + 16 + 6 = 19; 19 + 4(5 - 9) + 10 = 13; 13 - 8 + 10 = 15
        ("circle-bresenham-slip.csv", ("circle", "10", "--method", "bresenham"), 3, 7),
    ],
)
def test_one_slip_costs_one_row(name, question, wrong_row, rows):
    result = check(name, *question)
    assert (result["score"], result["out_of"]) == (rows - 1, rows)
    got = marks(result)
    assert got[wrong_row - 1] == "wrong"
    assert got[: wrong_row - 1] == ["right"] * (wrong_row - 1)
    assert all(m.startswith("right") for m in got[wrong_row:])
    assert got[wrong_row] == "right (follow-through)"  # the row after the slip follows from it
    assert result["first_error"].startswith(f"Row {wrong_row} (line")


def test_a_typo_not_carried_on_costs_one_row():
    # typo.csv is the right table with (6, 5) written for (6, 4) in row 5 and the rest right:
    # the rows after it are the answer's own, so they are right (not judged from the typo);
    # step 4 is row k = 3's p and decision with the point (6, 5) of row k = 4
    result = check("typo.csv", *LINE)
    assert (result["score"], result["out_of"]) == (7, 8)
    assert marks(result) == ["right"] * 3 + ["wrong"] + ["right"] * 4


def test_the_first_error_is_explained_in_one_sentence():
    text = check("slip.csv", *LINE)["first_error"]
    assert text == "Row 4 (line 5): p should be -8, not -4 (the step from (4, 3) with p = 0)."


def test_a_wrong_pixel_after_the_slip_is_still_wrong():
    rows = (DATA / "slip.csv").read_text().splitlines()
    # step k is row k's p with row k + 1's point. Step 6: from (7,5) p = -4 < 0 the point is
    # (8, 5): (8, 6) is a second error. Step 7: the next p, 4, follows from -4 by the rule's E
    # (a slip of the pen in the point), but from (8, 6) p = 4 NE reaches (9, 7), not (9, 6):
    # a third. Step 8: (10, 6) with p = 4 + ... from (9, 6) p = -4 (E) follows.
    rows[7] = "6,4,8,6"
    table = parse_text("\n".join(rows) + "\n", "two.csv")
    m = mark(table, api.line(2, 2, 10, 6))
    assert [v.mark for v in m.verdicts][4:] == [
        "wrong",
        "right (follow-through)",
        "wrong",
        "wrong",
        "right (follow-through)",
    ]
    assert (m.right, m.total) == (5, 8)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_start_row_present_or_not():
    # the notes' layout without its start row: p0 is never written (step 1 wrong), the rest
    # follows
    assert check("no-start-row.csv", *LINE)["score"] == 7
    assert check("right-notes.csv", *LINE)["score"] == 8
    # a table of (x_{k+1}, y_{k+1}) against the notes' layout of the question, and the reverse
    assert check("circle-textbook.csv", "circle", "10")["score"] == 7
    right = check("right-notes.csv", *LINE, "--layout", "textbook")
    assert (right["score"], right["out_of"]) == (8, 8)


def test_a_textbook_table_with_a_start_row_has_it_left_unmarked(tmp_path):
    text = "k,p_k,(x_{k+1}, y_{k+1})\n-,,(2, 2)\n" + "\n".join(
        (DATA / "line-late-textbook.csv").read_text().splitlines()[1:-1]
    )
    (tmp_path / "start.csv").write_text(text + "\n")
    result = json.loads(run("check", str(tmp_path / "start.csv"), "--", *LINE, "-f", "json").out)
    assert (result["score"], result["out_of"]) == (8, 8)
    assert any(
        "start pixel (2, 2), given in the question: shown, not scored" in n for n in result["notes"]
    )


def test_the_ellipse_in_two_markdown_tables():
    assert check("ellipse-right.md", "ellipse", "8", "6")["score"] == 10


def test_a_command_without_a_model_is_marked_without_follow_through(tmp_path):
    sol = api.circle(5, method="polynomial")
    rows = ["x,y"] + [f"{s.pixel[0]},{s.pixel[1]}" for s in sol.steps()]
    rows[2] = "1,4"
    (tmp_path / "poly.csv").write_text("\n".join(rows) + "\n")
    r = run(
        "check", str(tmp_path / "poly.csv"), "--", "circle", "5", "-m", "polynomial", "-f", "json"
    )
    result = json.loads(r.out)
    assert result["follow_through"] is False
    assert (result["score"], result["out_of"]) == (len(rows) - 2, len(rows) - 1)
    assert any("without follow-through" in n for n in result["notes"])


# --- diagnosis --------------------------------------------------------------------------------

DIAGNOSES = [
    # tie keep, (2,2)-(10,6): p0 = 0 keeps y: (3,2) p = 8, NE (4,3) p = 0, keep (5,3) ...
    ("tie-keep.csv", LINE, "tie = keep"),
    ("tie-keep.csv", LINE, "foley"),
    # Python's round(): y = 2.5 -> 2, 3.5 -> 4, 4.5 -> 4, 5.5 -> 6
    ("dda-half-even.csv", (*LINE, "--algo", "dda"), "Python's round()"),
    # truncation: y = 2.5 -> 2, 3.5 -> 3, ...
    ("dda-trunc.csv", (*LINE, "--algo", "dda"), "rounding = trunc"),
    # C's (int)(v + 0.5), (0,0)-(-6,-2): x = -k gives int(-1/2) = 0, int(-3/2) = -1, ...;
    # y = -k/3 gives int(1/6) = 0, int(-1/6) = 0, int(-1/2) = 0, int(-5/6) = 0,
    # int(-7/6) = -1, int(-3/2) = -1
    ("dda-c-cast.csv", ("line", "0", "0", "-6", "-2", "--algo", "dda"), "hearn-baker"),
    # from P1 = (10,6) with p <= 0 keeping y: p0 = 0 W (9,6) 8, SW (8,5) 0, W (7,5) 8, ...
    ("wikipedia.csv", ("line", "10", "6", "2", "2"), "tie = keep"),
    ("wikipedia.csv", ("line", "10", "6", "2", "2"), "start = given"),
    # the notes' printed table, copied
    ("notes-e1.md", LINE, "exactly the one the course notes print"),
    # p0 = 2*4*2.5 - 2*8*3 = -28, then the algorithm run correctly from it: -28 -20 -12 -4 4
    # (6,2), NE (7,3) -4, E (8,3) 4, NE (9,4) -4, E (10,4) 4
    ("notes-p0-run.csv", LINE, "p0 = 2"),
    ("notes-p0-run.csv", LINE, "-28"),
    # (10,6) to (2,2) not swapped: dx = -8, dy = -4, p0 = -8 + 8 = 0, always p >= 0 so
    # x + 1, y + 1 and p += 2dy - 2dx = 8: (11,7) 8, (12,8) 16, ... (18,14) 64
    ("unswapped.csv", ("line", "10", "6", "2", "2"), "forgetting to swap"),
    # r = 10 with p + 2x_k + 1: -9, -8, -5, 0, SE -11, -2, 9, SE 6, SE 7; stops at (8, 7)
    ("old-x.md", ("circle", "10"), "old x"),
    # the midpoint circle r = 10 without its last row (7, 7)
    ("circle-early.json", ("circle", "10"), "one step early"),
    # (2,2)-(10,6) in the textbook layout, one step past (10, 6): p = 0 NE (11, 7)
    ("line-late-textbook.csv", LINE, "one step late"),
    # general method r = 5, p = 0 keeps y: (1,5) p = 3, SE (2,4) p = 0, E (3,4) 7, SE (4,3) 10
    ("general-tie-keep.csv", ("circle", "5", "--method", "general"), "tie = keep"),
    # p0 = 5/4 - 10 = -8.75, then the same increments: -5.75 -0.75 6.25 -2.75 8.25 5.25 6.25
    ("midpoint-five-fourths.csv", ("circle", "10"), "p0 = 5/4-r"),
]


@pytest.mark.parametrize(("name", "question", "words"), DIAGNOSES, ids=lambda v: str(v)[:40])
def test_every_known_mistake_and_convention_is_recognised(name, question, words):
    result = check(name, *question)
    assert result["score"] < result["out_of"]
    assert words in result["diagnosis"], result["diagnosis"]


def test_a_convention_is_named_before_a_mistake_that_gives_the_same_table(tmp_path):
    # the midpoint circle r = 10 one step late is loop while x <= y: (8, 6), p = 6 + 17 - 12
    rows = (DATA / "circle-early.json").read_text()
    more = [*json.loads(rows), {"k": 7, "p": 6, "x": 7, "y": 7}, {"k": 8, "p": 11, "x": 8, "y": 6}]
    (tmp_path / "late.json").write_text(json.dumps(more))
    r = run("check", str(tmp_path / "late.json"), "--", "circle", "10", "-f", "json")
    diagnosis = json.loads(r.out)["diagnosis"]
    assert "loop = inclusive" in diagnosis and "late" not in diagnosis


def test_a_right_table_has_no_diagnosis():
    result = check("right-notes.csv", *LINE)
    assert (result["score"], result["first_error"], result["diagnosis"]) == (8, "", "")


# --- output -----------------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("fmt", formats("answer"))
def test_every_format_shows_the_marks(fmt):
    r = run("check", str(DATA / "slip.csv"), "--", *LINE, "-f", fmt)
    assert r.code == 0 and r.err == ""
    assert "follow-through" in r.out and "wrong" in r.out
    if fmt == "csv":
        rows = list(csv.reader(io.StringIO(r.out)))
        assert rows[0] == ["row", "line", "written", "expected", "mark"] and len(rows) == 10


def test_the_options_may_follow_the_question(tmp_path):
    target = tmp_path / "marks.md"
    r = run("check", str(DATA / "slip.csv"), "--", *LINE, "-o", str(target))
    assert r.code == 0 and r.out == ""
    assert target.read_text().startswith("## Marking")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_markdown_renders_through_pandoc(tmp_path):
    pytest.importorskip("pypandoc")
    from .test_documents import _to_html

    html, warnings = _to_html(
        tmp_path, run("check", str(DATA / "slip.csv"), "--", *LINE, "-f", "md").out, "gfm"
    )
    assert "[WARNING]" not in warnings
    assert html.tables and len(html.tables[0]["rows"]) == 9


@pytest.mark.external
@pytest.mark.slow
def test_latex_compiles(tmp_path):
    from .external import overfull
    from .test_documents import _compile

    fragments = [
        run("check", str(DATA / name), "--", *q, "-f", "latex").out for name, q, _ in DIAGNOSES[:6]
    ]
    log = _compile(tmp_path, *fragments)
    assert "Undefined control sequence" not in log and not overfull(log)


# --- batches ----------------------------------------------------------------------------------

TABLES = ["slip.csv", "right-notes.csv", "tie-keep.csv", "notes-p0-run.csv", "no-start-row.csv"]


def _class_of_30(folder: Path) -> list[str]:
    names = []
    for i in range(30):
        name = f"student{i:02d}-{TABLES[i % len(TABLES)]}"
        if i == 29:
            name = "=HYPERLINK(1).csv"
        shutil.copy(DATA / TABLES[i % len(TABLES)], folder / name)
        names.append(name)
    return sorted(names)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_thirty_csvs_make_one_score_csv(tmp_path):
    folder = tmp_path / "class"
    folder.mkdir()
    names = _class_of_30(folder)
    out = tmp_path / "scores.csv"
    r = run("check", "--batch", str(folder), "-o", str(out), "--", *LINE)
    assert r.code == 0 and r.out == "" and r.err == ""
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert len(rows) == 30
    assert [row["name"] for row in rows] == [neutral(n) for n in names]
    assert "'=HYPERLINK(1).csv" in [row["name"] for row in rows]
    scores = {row["name"]: (int(row["score"]), int(row["out_of"])) for row in rows}
    assert scores["student00-slip.csv"] == (7, 8)
    assert scores["student01-right-notes.csv"] == (8, 8)
    assert scores["student04-no-start-row.csv"] == (7, 8)
    by_name = {row["name"]: row for row in rows}
    assert "tie = keep" in by_name["student02-tie-keep.csv"]["diagnosis"]
    assert by_name["student01-right-notes.csv"]["first_error"] == ""


def test_a_batch_goes_to_stdout_and_exits_0_whatever_the_marks(tmp_path):
    shutil.copy(DATA / "unswapped.csv", tmp_path / "a.csv")
    r = run("check", "--batch", str(tmp_path), "--", *LINE)
    assert r.code == 0
    assert r.out.splitlines()[0] == "name,score,out_of,first_error,diagnosis"
    assert r.out.splitlines()[1].startswith("a.csv,0,8,")


def test_an_unreadable_file_is_a_row_of_the_sheet_with_its_name_and_line(tmp_path):
    """One bad file no longer stops the class: it gets a row saying why it was not marked."""
    folder = tmp_path / "class"
    folder.mkdir()
    shutil.copy(DATA / "slip.csv", folder / "a.csv")
    shutil.copy(DATA / "not-a-number.csv", folder / "b.csv")
    out = tmp_path / "scores.csv"
    out.write_text("keep")
    r = run("check", "--batch", str(folder), "-o", str(out), "--", *LINE)
    assert r.code == 0 and r.err == "", r.err
    rows = {row[0]: row for row in csv.reader(io.StringIO(out.read_text()))}
    assert rows["a.csv"][1:3] == ["7", "8"]
    assert rows["b.csv"][1:3] == ["", ""] and "b.csv, line 3" in rows["b.csv"][3]
    assert_refused(run("check", "--batch", str(tmp_path / "none"), "--", *LINE), "none")


@pytest.mark.parametrize("fmt", ["markdown", "plain", "latex", "rich"])
def test_a_batch_in_a_text_format_is_a_table(tmp_path, fmt):
    shutil.copy(DATA / "slip.csv", tmp_path / "a.csv")
    shutil.copy(DATA / "tie-keep.csv", tmp_path / "b|c.csv")
    r = run("check", "--batch", str(tmp_path), "-f", fmt, "--", *LINE)
    assert r.code == 0 and r.err == ""
    text = " ".join(r.out.split())  # the terminal wraps the notes
    assert "a.csv" in text and "tie = keep" in text and "Scores" in text


def test_spreadsheet_formulas_are_neutralised():
    assert [neutral(t) for t in ("=1+1", "+1", "-1", "@SUM(A1)", "ok")] == [
        "'=1+1",
        "'+1",
        "'-1",
        "'@SUM(A1)",
        "ok",
    ]


def test_read_table_refuses_a_file_beyond_the_size_limit():
    with pytest.raises(InputError, match="bytes"):
        read_table(DATA / "too-large.csv")


def test_the_api_marks_against_a_question_or_a_solution():
    by_words = scanconv.check(DATA / "slip.csv", ["line", "2", "2", "10", "6"])
    by_solution = scanconv.check(DATA / "slip.csv", api.line(2, 2, 10, 6))
    assert by_words.data["score"] == by_solution.data["score"] == 7
    assert by_solution.data["first_error"] == by_words.data["first_error"]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=100, deadline=None)  # was 300: see the module's note
@given(st.binary(max_size=300))
def test_any_bytes_are_a_table_or_one_input_error(data):
    from scanconv.marking.student_table import parse_bytes

    for suffix in ("", ".csv", ".md", ".json"):
        try:
            table = parse_bytes(data, "f", suffix)
        except InputError as err:
            assert str(err).startswith("f") and "\n" not in str(err)
            continue
        mark(table, api.line(2, 2, 10, 6))


HEADINGS = ["k", "p", "p_k", "x", "y", "(x, y)", "pixel", "round(x)", "round(y)", "p_{k+1}"]
HEADINGS += ["region", "(x_{k+1}, y_{k+1})", "decision"]
QUESTIONS = [
    api.line(2, 2, 10, 6),
    api.line(2, 2, 10, 6, algo="dda"),
    api.line(10, 6, 2, 2, layout="textbook"),
    api.circle(5),
    api.circle(4, method="general"),
    api.circle(4, method="bresenham"),
    api.circle(5, method="polynomial"),
    api.ellipse(4, 3),
    api.ellipse(10, 1),
]
_NUM = st.one_of(st.integers(-20, 20).map(str), st.sampled_from(["", "-", "2.5", "1/3", "-0.25"]))
_PAIR = st.tuples(st.integers(-12, 12), st.integers(-12, 12)).map(lambda t: f"({t[0]}, {t[1]})")


@st.composite
def _tables(draw):
    head = draw(st.lists(st.sampled_from(HEADINGS), min_size=1, max_size=6, unique=True))
    cells = [_PAIR | st.just("") if "(" in h or h == "pixel" else _NUM for h in head]
    rows = draw(st.lists(st.tuples(*cells), max_size=14))
    lines = [",".join(f'"{c}"' for c in row) for row in [head, *rows]]
    return "\n".join(lines) + "\n"


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@settings(max_examples=100, deadline=None)  # was 300: see the module's note
@given(_tables(), st.sampled_from(QUESTIONS))
def test_any_table_is_marked_or_refused_in_one_line(text, question):
    try:
        table = parse_text(text, "f.csv", ".csv")
    except InputError as err:
        assert str(err).startswith("f.csv") and "\n" not in str(err)
        return
    m = mark(table, question)
    scored = [v for v in m.verdicts if v.row > 0]
    assert 0 <= m.right <= m.total <= len(scored)
    assert (m.first_error == "") == (m.right == m.total)


@pytest.mark.slow  # a real process
def test_check_echoes_the_question_as_typed(tmp_path: Path) -> None:
    """A dither question came back as ``--image 10 200_ 60 90``, its quotes
    lost and its ``;`` made ``_``. The echo is the question a shell reads back to the same
    words (quoted where a word holds a space), in the text formats and in the JSON notes."""
    import shlex

    from tests.helpers import run_process

    question = ["dither", "ordered", "--image", "10 200 60 90; 30 150 220 5", "--matrix", "2"]
    table = run_process(*question, "--format", "csv").out
    (tmp_path / "d.csv").write_text(table, encoding="utf-8")
    for fmt in ("plain", "json"):
        done = run_process("check", str(tmp_path / "d.csv"), "--", *question, "--format", fmt)
        assert done.code == 0, done.err
        echoed = re.search(r"against scanconv (.*?)\.(?:\"|$|\n)", done.out, re.MULTILINE)
        assert echoed, done.out
        assert shlex.split(echoed.group(1)) == question, echoed.group(1)


@pytest.mark.slow  # a real process
def test_the_notes_topic_9_circle_marked_against_bresenham_is_named(tmp_path: Path) -> None:
    """A student who works the notes' Topic 9 circle (p = 1 - r, worked here
    by hand for r = 5: p = -4, -1, 4, 3, 6) and is marked against Bresenham's d0 = 3 - 2r is
    told which form it is, by the notes' own name for it."""
    from tests.helpers import run_process

    table = "k,x,y,p,decision\n0,0,5,-4,E\n1,1,5,-1,E\n2,2,5,4,SE\n3,3,4,3,SE\n4,4,3,6,\n"
    (tmp_path / "t9.csv").write_text(table, encoding="utf-8")
    done = run_process(
        "check", str(tmp_path / "t9.csv"), "--", "circle", "5", "--method", "bresenham"
    )
    assert done.code == 0, done.err
    diagnosis = next(ln for ln in done.out.splitlines() if "Diagnosis" in ln)
    assert "Topic 9" in diagnosis and "p0 = 1 - r" in diagnosis and "d0 = 3 - 2r" in diagnosis
