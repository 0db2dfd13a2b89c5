"""``scanconv check`` on tables written by hand, as students write them (CSV, Markdown).

Every table below and every expected score was worked out on paper from the method's
definition, never by running scanconv's generators: the arithmetic is in the comment above
each table. They sit where the marker's rules have edges: a number at the tolerance's edge
(one unit in its last decimal place, two or more places; none for one decimal), a blank
cell in the middle of a table, a slip at a tie for each tie rule (``>=`` and ``>``), and
the follow-through of each carried quantity (Cyrus-Beck's t_E and t_L, the error a
Floyd-Steinberg pixel passes on). Each test fails on a marker that, for example, gives
one-decimal answers a tolerance, accepts a blank p_{k+1} in any row, flips a tie in its
follow-through model or carries the answer's t_E instead of the student's.
"""

from __future__ import annotations

import json

import pytest

from .helpers import assert_refused, run, run_process

# The DDA from (2, 2) to (5, 10): dx = 3, dy = 8, 8 steps, x grows by 3/8 = 0.375 a step and
# y by 1. Exact x: 2, 2.375, 2.75, 3.125, 3.5, 3.875, 4.25, 4.625, 5; the pixel rounds x half
# up: 2, 2, 3, 3, 4, 4, 4, 5, 5.
DDA = ("line", "2", "2", "5", "10", "--algo", "dda")
DDA_X = ["2", "2.375", "2.75", "3.125", "3.5", "3.875", "4.25", "4.625", "5"]
DDA_PX = [2, 2, 3, 3, 4, 4, 4, 5, 5]

# Bresenham from (2, 2) to (10, 6): dx = 8, dy = 4, p0 = 2dy - dx = 0; p < 0 chooses E and
# adds 2dy = 8, else NE and adds 2dy - 2dx = -8. So p alternates 0, -8, 0, -8, ... and the
# points are (3, 3), (4, 3), (5, 4), (6, 4), (7, 5), (8, 5), (9, 6), (10, 6). The notes'
# layout: a row per point, the start first, p_k, the decision and p_{k+1} on the point's row.
BRESENHAM = ("line", "2", "2", "10", "6")
NOTES_ROWS = [
    ["0", "0", "NE", "(2, 2)", "-8"],
    ["1", "-8", "E", "(3, 3)", "0"],
    ["2", "0", "NE", "(4, 3)", "-8"],
    ["3", "-8", "E", "(5, 4)", "0"],
    ["4", "0", "NE", "(6, 4)", "-8"],
    ["5", "-8", "E", "(7, 5)", "0"],
    ["6", "0", "NE", "(8, 5)", "-8"],
    ["7", "-8", "E", "(9, 6)", "0"],
    ["8", "0", "", "(10, 6)", ""],
]


def check(tmp_path, name: str, text: str, *question: str) -> dict:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    r = run("check", str(path), "--", *question, "-f", "json")
    assert r.code == 0, r.err
    return json.loads(r.out)


def score(result: dict) -> tuple[int, int]:
    return result["score"], result["out_of"]


def scored(result: dict) -> list[str]:
    """The marks of the scored rows (a given start row, shown, is left out)."""
    return [row[4] for row in result["tables"][0]["rows"] if row[4] != "given (not scored)"]


def dda_csv(xs: list[str]) -> str:
    rows = [
        f'{k},{x},{2 + k},"({px}, {2 + k})"'
        for k, (x, px) in enumerate(zip(xs, DDA_PX, strict=True))
    ]
    return "k,x,y,pixel\n" + "\n".join(rows) + "\n"


def notes_csv(rows: list[list[str]]) -> str:
    return (
        'k,p_k,decision,"(x_k, y_k)",p_{k+1}\n'
        + "\n".join(",".join(f'"{c}"' if "," in c else c for c in r) for r in rows)
        + "\n"
    )


def test_the_dda_table_written_exactly_gets_every_step(tmp_path):
    assert score(check(tmp_path, "dda.csv", dda_csv(DDA_X), *DDA)) == (8, 8)


@pytest.mark.parametrize(
    ("last", "right"),
    [
        ("4.999", True),  # 3 places, 0.001 below 5: one unit in the last place, the edge
        ("5.001", True),  # 0.001 above
        ("4.998", False),  # two units below: past the edge
        ("5.002", False),
        ("4.99", True),  # 2 places: 0.01 is the edge
        ("5.01", True),
        ("4.98", False),
        ("5.1", False),  # 1 place: no tolerance at all
        ("4.9", False),
    ],
)
def test_three_and_two_decimal_answers_at_the_tolerance_edge(tmp_path, last, right):
    # only the last step's x is changed, so no later step follows from it
    result = check(tmp_path, "dda.csv", dda_csv([*DDA_X[:-1], last]), *DDA)
    assert score(result) == ((8, 8) if right else (7, 8))
    assert scored(result)[-1] == ("right" if right else "wrong")


def test_one_decimal_answers_have_no_tolerance(tmp_path):
    # x to one decimal: 2.4, 2.8, 3.1, 3.5, 3.9, 4.3, 4.6, 5. Only 3.5 and 5 are the exact x
    # values; 2.4 for 2.375 is 0.025 off, well inside 0.1, and still wrong: a value written to
    # one decimal must be exact (the course asks for three places where x is not whole).
    xs = ["2", "2.4", "2.8", "3.1", "3.5", "3.9", "4.3", "4.6", "5"]
    result = check(tmp_path, "dda-1dp.csv", dda_csv(xs), *DDA)
    assert score(result) == (2, 8)
    marks = scored(result)
    assert [i + 1 for i, m in enumerate(marks) if m.startswith("right")] == [4, 8]


def test_three_decimal_answers_rounded_are_right(tmp_path):
    # 2.375 etc. written to two places, rounded half up: 2.38, 2.75, 3.13, 3.5, 3.88, 4.25,
    # 4.63, 5; each is at most 0.005 from the exact value, inside 0.01.
    xs = ["2", "2.38", "2.75", "3.13", "3.5", "3.88", "4.25", "4.63", "5"]
    assert score(check(tmp_path, "dda-2dp.csv", dda_csv(xs), *DDA)) == (8, 8)


def test_the_hand_written_notes_table_gets_every_step(tmp_path):
    assert score(check(tmp_path, "notes.csv", notes_csv(NOTES_ROWS), *BRESENHAM)) == (8, 8)


def test_a_blank_next_p_in_the_middle_of_the_table_costs_its_step(tmp_path):
    # row k = 3 leaves p_{k+1} blank: the step from (5, 4) is incomplete, the others follow
    # (row 4's p_k = 0 is what row 3's p = -8 gives by the rule: -8 + 8)
    rows = [list(r) for r in NOTES_ROWS]
    rows[3][4] = ""
    result = check(tmp_path, "blank-mid.csv", notes_csv(rows), *BRESENHAM)
    assert score(result) == (7, 8)
    assert [i for i, m in enumerate(scored(result)) if not m.startswith("right")] == [3]


def test_a_blank_next_p_in_the_last_step_is_not_judged(tmp_path):
    # the table may stop at the last point: p_{k+1} of the step into (10, 6) left blank
    rows = [list(r) for r in NOTES_ROWS]
    rows[7][4] = ""
    assert score(check(tmp_path, "blank-last.csv", notes_csv(rows), *BRESENHAM)) == (8, 8)


def test_a_blank_point_in_the_middle_of_the_table_costs_one_step(tmp_path):
    # the point (6, 4) left blank: that step is wrong; the next steps follow from p alone
    rows = [list(r) for r in NOTES_ROWS]
    rows[4][3] = ""
    result = check(tmp_path, "blank-point.csv", notes_csv(rows), *BRESENHAM)
    assert score(result) == (7, 8)


# Thresholding at 128, rule value >= threshold (the threshold command's): 128 >= 128 is on.
# The student writes 0 at that tie: one of four rows wrong.
THRESHOLD = ("dither", "threshold", "--image", "128 200; 60 90", "--at", "128")


@pytest.mark.parametrize(("at_tie", "right"), [("0", 3), ("1", 4)])
def test_a_slip_at_the_threshold_tie_greater_or_equal(tmp_path, at_tie, right):
    text = f"x,y,value,threshold,output\n0,0,128,128,{at_tie}\n1,0,200,128,1\n0,1,60,128,0\n1,1,90,128,0\n"
    assert score(check(tmp_path, "threshold.csv", text, *THRESHOLD)) == (right, 4)


# Ordered dither, Bayer matrix of order 2, D = [[0, 2], [3, 1]] (row y, column x), raw
# thresholds D x TOP / 4 with TOP = 4: 0, 2 on row 0 and 3, 1 on row 1; every value 2; the
# rule is value > threshold: 2 > 0 on, 2 > 2 off (the tie), 2 > 3 off, 2 > 1 on.
ORDERED = ("dither", "ordered", "--image", "2 2; 2 2", "--top", "4")


@pytest.mark.parametrize(("at_tie", "right"), [("1", 3), ("0", 4)])
def test_a_slip_at_the_ordered_tie_greater_than(tmp_path, at_tie, right):
    text = f"x,y,value,threshold,output\n0,0,2,0,1\n1,0,2,2,{at_tie}\n0,1,2,3,0\n1,1,2,1,1\n"
    assert score(check(tmp_path, "ordered.csv", text, *ORDERED)) == (right, 4)


def test_a_wrong_threshold_is_followed_through_at_a_tie(tmp_path):
    # the student misreads the threshold at (1, 0) as 3 and then rightly writes 2 > 3 off:
    # the threshold is wrong, the output follows from it (one slip, one row)
    text = "x,y,value,threshold,output\n0,0,2,0,1\n1,0,2,3,0\n0,1,2,3,0\n1,1,2,1,1\n"
    result = check(tmp_path, "ordered-t.csv", text, *ORDERED)
    assert score(result) == (3, 4)
    # ... and writing 2 for a threshold of 1 makes 2 > 2 a tie: off, by the student's own cells
    text = "x,y,value,threshold,output\n0,0,2,0,1\n1,0,2,2,0\n0,1,2,3,0\n1,1,2,2,0\n"
    result = check(tmp_path, "ordered-t2.csv", text, *ORDERED)
    assert score(result) == (3, 4)
    assert scored(result)[3] == "wrong"


# Floyd-Steinberg on [[5, 1], [2, 3]], TOP = 10, on when value >= 5 (the half). Row by row:
# (0, 0): 5 >= 5 is on: output 10, error -5. A student who writes output 0 at this tie has
# error 5 - 0 = 5 and, following through, passes on 7/16, 3/16, 5/16, 1/16 of 5:
#   (1, 0) [x = 1, y = 0] receives 35/16 = 2.1875: value 3.1875, off, error 3.1875;
#   (0, 1) receives 5/16 * 5 + 3/16 * 3.1875 = 1.5625 + 0.59765625 = 2.16015625: value
#          4.16015625, off, error 4.16015625;
#   (1, 1) receives 1/16 * 5 + 5/16 * 3.1875 + 7/16 * 4.16015625
#          = 0.3125 + 0.99609375 + 1.820068359375 = 3.128662109375: value 6.128662109375,
#          on (10), error -3.871337890625.
FLOYD = ("dither", "floyd-steinberg", "--image", "5 1; 2 3", "--top", "10")
FLOYD_SLIP = """x,y,received,value,output,error
0,0,0,5,0,5
1,0,2.1875,3.1875,0,3.1875
0,1,2.16015625,4.16015625,0,4.16015625
1,1,3.128662109375,6.128662109375,10,-3.871337890625
"""


def test_a_slip_at_the_floyd_steinberg_tie_is_followed_through(tmp_path):
    result = check(tmp_path, "floyd.csv", FLOYD_SLIP, *FLOYD)
    assert score(result) == (3, 4)
    assert scored(result) == ["wrong"] + ["right (follow-through)"] * 3


def test_floyd_steinberg_written_right_at_the_tie(tmp_path):
    # on at the tie: error -5; (1, 0) receives -35/16: value 1 - 2.1875 = -1.1875, off, error
    # -1.1875; (0, 1) receives -25/16 + 3/16 * -1.1875 = -1.5625 - 0.22265625 = -1.78515625:
    # value 0.21484375, off, error 0.21484375; (1, 1) receives -5/16 + 5/16 * -1.1875
    # + 7/16 * 0.21484375 = -0.3125 - 0.37109375 + 0.093994140625 = -0.589599609375: value
    # 2.410400390625, off, error 2.410400390625.
    text = """x,y,received,value,output,error
0,0,0,5,10,-5
1,0,-2.1875,-1.1875,0,-1.1875
0,1,-1.78515625,0.21484375,0,0.21484375
1,1,-0.589599609375,2.410400390625,0,2.410400390625
"""
    assert score(check(tmp_path, "floyd-right.csv", text, *FLOYD)) == (4, 4)


# Cyrus-Beck, the line (30, 60) to (60, 25), D = (30, -35), against the window 10..50 with
# outward normals: t = N.(P0 - E) / -N.D.
#   V1V2 bottom, N = (0, -40): N.D = 1400, N.(P0 - E) = -2000, t = 10/7, leaving: tL = 1
#   V2V3 right,  N = (40, 0):  N.D = 1200, N.(P0 - E) = -800, t = 2/3, leaving: tL = 2/3
#   V3V4 top,    N = (0, 40):  N.D = -1400, N.(P0 - E) = 400, t = 2/7, entering: tE = 2/7
#   V4V1 left,   N = (-40, 0): N.D = -1200, N.(P0 - E) = -800, t = -2/3, entering: tE = 2/7
CYRUS = (
    "clip", "line", "30", "60", "60", "25", "--window", "10", "10", "50", "50",
    "--method", "cyrus-beck",
)  # fmt: skip
CB_HEAD = "| edge | N·D | N·(P0 - E) | t | type | t_E | t_L |\n|---|---|---|---|---|---|---|\n"


def cyrus_md(t_e: tuple[str, str], t_l: tuple[str, str, str]) -> str:
    rows = [
        f"| V1V2 | 1400 | -2000 | 10/7 | leaving | 0 | {t_l[0]} |",
        f"| V2V3 | 1200 | -800 | 2/3 | leaving | 0 | {t_l[1]} |",
        f"| V3V4 | -1400 | 400 | 2/7 | entering | {t_e[0]} | {t_l[2]} |",
        f"| V4V1 | -1200 | -800 | -2/3 | entering | {t_e[1]} | {t_l[2]} |",
    ]
    return CB_HEAD + "\n".join(rows) + "\n"


def test_cyrus_beck_written_right(tmp_path):
    text = cyrus_md(("2/7", "2/7"), ("1", "2/3", "2/3"))
    assert score(check(tmp_path, "cb.md", text, *CYRUS)) == (4, 4)


def test_a_carried_t_enter_slip_costs_one_row(tmp_path):
    # V3V4: tE = max(0, 2/7) = 2/7, written 1/3; V4V1 then carries her 1/3: max(1/3, -2/3)
    text = cyrus_md(("1/3", "1/3"), ("1", "2/3", "2/3"))
    result = check(tmp_path, "cb-te.md", text, *CYRUS)
    assert score(result) == (3, 4)
    assert scored(result) == ["right", "right", "wrong", "right (follow-through)"]


def test_a_t_enter_slip_then_the_right_value_costs_its_row_only(tmp_path):
    # she writes 1/3 for V3V4 but the answer's 2/7 below: a cell equal to the answer's own
    # value is right whatever came before it (only the slip's row is lost)
    text = cyrus_md(("1/3", "2/7"), ("1", "2/3", "2/3"))
    result = check(tmp_path, "cb-te2.md", text, *CYRUS)
    assert score(result) == (3, 4)
    assert scored(result)[2:] == ["wrong", "right"]


def test_a_carried_t_leave_slip_costs_one_row(tmp_path):
    # V2V3: tL = min(1, 2/3) = 2/3, written 3/4; the rows below carry her 3/4
    text = cyrus_md(("2/7", "2/7"), ("1", "3/4", "3/4"))
    result = check(tmp_path, "cb-tl.md", text, *CYRUS)
    assert score(result) == (3, 4)
    assert scored(result) == ["right", "wrong", "right (follow-through)", "right (follow-through)"]


@pytest.mark.slow  # a process: over 50 ms
def test_check_as_a_process_reads_the_students_csv(tmp_path):
    # the same one-decimal table through a real process: the score a teacher sees
    path = tmp_path / "dda-1dp.csv"
    path.write_text(dda_csv(["2", "2.4", "2.8", "3.1", "3.5", "3.9", "4.3", "4.6", "5"]))
    r = run_process("check", str(path), "--", *DDA, "-f", "json")
    assert r.code == 0, r.err
    assert score(json.loads(r.out)) == (2, 8)


def test_a_dda_slip_in_x_is_followed_through(tmp_path):
    # x_3 written 3.25 for 3.125 (a slip); from her own 3.25 the next values are 3.625, 4,
    # 4.375, 4.75, 5.125, each rounding to the answer's pixel: one slip, one step (7 of 8)
    xs = ["2", "2.375", "2.75", "3.25", "3.625", "4", "4.375", "4.75", "5.125"]
    result = check(tmp_path, "dda-slip.csv", dda_csv(xs), *DDA)
    assert score(result) == (7, 8)
    assert scored(result) == ["right"] * 2 + ["wrong"] + ["right (follow-through)"] * 5


def test_a_decision_against_the_rule_is_judged_by_her_own_decision(tmp_path):
    # the step from (4, 3) with p = 0: she writes E (the rule says NE, p >= 0) and the next p
    # 0 + 2dy = 8 that E gives, but the point (5, 4). Her p_{k+1} follows from her own
    # decision, so only the decision and the point are wrong in that step: E reaches (5, 3).
    rows = [list(r) for r in NOTES_ROWS]
    rows[2] = ["2", "0", "E", "(4, 3)", "8"]
    rows[3] = ["3", "8", "NE", "(5, 4)", "0"]
    result = check(tmp_path, "own-decision.csv", notes_csv(rows), *BRESENHAM)
    first = result["first_error"]
    assert first.startswith("Row 3 (line 4): the pixel should be (5, 3), not (5, 4)")
    assert "the decision should be NE, not E" in first
    assert "next p" not in first
    assert scored(result)[2] == "wrong"


def test_a_table_that_stops_early_is_followed_on_from_her_last_point(tmp_path):
    # five rows: the steps to (3, 3), (4, 3), (5, 4) right, then (6, 5) for (6, 4) (a slip),
    # and she stops. The four steps she did not write are missing (3 of 8), and what they
    # should hold follows on from her own last row by the rule: from (6, 5) with p = 0, NE to
    # (7, 6) (p -> -8), E to (8, 6) (p -> 0), NE to (9, 7), E to (10, 7).
    rows = [list(r) for r in NOTES_ROWS[:5]]
    rows[4][3] = "(6, 5)"
    result = check(tmp_path, "early.csv", notes_csv(rows), *BRESENHAM)
    assert score(result) == (3, 8)
    missing = [r for r in result["tables"][0]["rows"] if r[4] == "missing"]
    assert [r[3].split(", next")[0] for r in missing] == [
        "p = 0, NE, (7, 6)",
        "p = -8, E, (8, 6)",
        "p = 0, NE, (9, 7)",
        "p = -8, E, (10, 7)",
    ]


X_ROUNDED_Y = """k,x,round(x),y
0,2,2,2
1,2.375,2,3
2,2.75,{x2},4
3,3.125,3,5
4,3.5,4,6
5,3.875,4,7
6,4.25,4,8
7,4.625,5,9
8,5,5,10
"""


@pytest.mark.parametrize(("x2", "right"), [("3", 8), ("2", 7)])
def test_a_steep_dda_written_x_round_x_y(tmp_path, x2, right):
    # the steep DDA as the notes lay it out: the exact x, its rounding, and y; the pixel is
    # (round(x), y): 2.75 rounds to 3, so (2, 4) in row 2 is a slip
    result = check(tmp_path, "x-rx-y.csv", X_ROUNDED_Y.format(x2=x2), *DDA)
    assert score(result) == (right, 8)
    assert set(result["marked"]) == {"pixel", "exact"}


def test_a_short_basic_line_table_counts_its_missing_rows(tmp_path):
    # the basic line from (2, 2) to (8, 5): y = 2 + (x - 2)/2 rounded half up for x = 2 .. 8:
    # (2, 2), (3, 3), (4, 3), (5, 4), (6, 4), (7, 5), (8, 5). She writes the first three and
    # stops: 3 of 7, the four others missing, numbered on from hers
    text = "x,y\n2,2\n3,3\n4,3\n"
    result = check(tmp_path, "basic-short.csv", text, "line", "2", "2", "8", "5", "--algo", "basic")
    assert score(result) == (3, 7)
    rows = result["tables"][0]["rows"]
    assert [(r[0], r[3], r[4]) for r in rows] == [
        (1, "(2, 2)", "right"),
        (2, "(3, 3)", "right"),
        (3, "(4, 3)", "right"),
        (4, "(5, 4)", "missing"),
        (5, "(6, 4)", "missing"),
        (6, "(7, 5)", "missing"),
        (7, "(8, 5)", "missing"),
    ]


@pytest.mark.slow  # a table of 10,000 rows marked: over 50 ms
def test_a_plain_marked_question_at_the_row_limit(tmp_path):
    # the basic line from (0, 0) to (9999, 0) has 10,000 pixels, check's limit: marked (only
    # the first is written); to (10000, 0) it has 10,001: refused, naming the limit
    path = tmp_path / "one.csv"
    path.write_text("x,y\n0,0\n")
    r = run(
        "check", str(path), "--", "line", "0", "0", "9999", "0", "--algo", "basic", "-f", "json"
    )
    assert r.code == 0, r.err
    assert score(json.loads(r.out)) == (1, 10_000)
    r = run("check", str(path), "--", "line", "0", "0", "10000", "0", "--algo", "basic")
    assert_refused(r, "more than 10000 rows")


def test_a_short_threshold_table_numbers_its_missing_rows(tmp_path):
    # two of the four pixels written, both right: 2 of 4, rows 3 and 4 missing
    text = "x,y,value,threshold,output\n0,0,128,128,1\n1,0,200,128,1\n"
    result = check(tmp_path, "threshold-short.csv", text, *THRESHOLD)
    assert score(result) == (2, 4)
    rows = result["tables"][0]["rows"]
    assert [(r[0], r[-1]) for r in rows] == [
        (1, "right"),
        (2, "right"),
        (3, "missing"),
        (4, "missing"),
    ]


def test_a_table_without_pixel_columns_names_eight_of_its_columns(tmp_path):
    # ten columns, none for the pixels: the refusal names the first eight and counts the rest
    path = tmp_path / "no-pixels.csv"
    path.write_text("a,b,c,d,e,f,g,h,i,j\n1,2,3,4,5,6,7,8,9,10\n")
    r = run("check", str(path), "--", *BRESENHAM)
    assert_refused(r, "'a', 'b', 'c', 'd', 'e', 'f', 'g', 'h' and 2 more")
    # nine: eight named and one more
    path.write_text("a,b,c,d,e,f,g,h,i\n1,2,3,4,5,6,7,8,9\n")
    assert_refused(run("check", str(path), "--", *BRESENHAM), "'g', 'h' and 1 more;")
    # eight: all named, none "more"
    path.write_text("a,b,c,d,e,f,g,h\n1,2,3,4,5,6,7,8\n")
    r = run("check", str(path), "--", *BRESENHAM)
    assert_refused(r, "'g', 'h'; it needs")
    assert "more" not in r.err


# Midpoint subdivision of (0, 2)-(12, 6) against the window x 2..8, y 0..8 (codes TBRL):
# (0, 2) is left (0001), (12, 6) right (0010); the pieces are halved at their integer
# midpoints, first halves first: (6, 4), (3, 3), (2, 3) inside, (1, 3) left; (0, 2)-(1, 3)
# both left: AND 0001, rejected; (1, 3)-(2, 3) a pixel apart: its inside end kept; (2, 3) is on
# the left edge, inside, so (2, 3)-(3, 3) is accepted: 0000, 0000. 13 pieces in all.
MIDPOINT_CLIP = """k,piece,code_a,code_b,and,action,mid,code_mid
0,"(0, 2) to (12, 6)",0001,0010,0000,split,"(6, 4)",0000
1,"(0, 2) to (6, 4)",0001,0000,0000,split,"(3, 3)",0000
2,"(0, 2) to (3, 3)",0001,0000,0000,split,"(2, 3)",0000
3,"(0, 2) to (2, 3)",0001,0000,0000,split,"(1, 3)",0001
4,"(0, 2) to (1, 3)",0001,0001,0001,reject,-,-
5,"(1, 3) to (2, 3)",0001,0000,0000,keep inside end,-,-
6,"(2, 3) to (3, 3)",0001,0000,0000,split,"(2, 3)",0000
"""


def test_a_code_slip_in_midpoint_subdivision_is_followed_to_a_split(tmp_path):
    # she codes (2, 3) as left (0001) in the last piece she writes: from her own codes the AND
    # is 0000 and the action a split, as she writes; only her code (and the midpoint, which is
    # not followed through) is wrong. 6 of 13, the last 6 pieces missing.
    question = ("clip", "line", "0", "2", "12", "6", "--window", "2", "0", "8", "8")
    result = check(
        tmp_path, "mid.csv", MIDPOINT_CLIP, *question, "--method", "midpoint-subdivision"
    )
    assert score(result) == (6, 13)
    assert result["first_error"].startswith("Row 7 (line 8): code₁, midpoint, its code wrong;")
    assert "action = split" in result["first_error"]


def test_an_empty_markdown_row_is_one_cell(tmp_path):
    # "||" between a table's rows is a row of one empty cell (the pipes only delimit it):
    # refused, naming its line and its one cell against the heading's three
    path = tmp_path / "empty-row.md"
    path.write_text("| k | x | y |\n|---|---|---|\n| 0 | 2 | 2 |\n||\n| 1 | 3 | 3 |\n")
    assert_refused(run("check", str(path), "--", *BRESENHAM), "line 4: 1 cells", "3 columns")


def test_a_circle_table_that_ends_early_numbers_its_missing_row(tmp_path):
    """The midpoint circle r = 5 by hand: p = -4 E (1, 5), p = -1 E (2, 5), p = 4 SE (3, 4),
    p = 3 SE (4, 3). She takes SE at p = -1 and again at 2, reaching (3, 3), where x = y ends
    her octant one step early: the step the answer still has is row 4, missing (the rows are
    numbered 0 to 4, none twice)."""
    from .helpers import run

    f = tmp_path / "short.csv"
    f.write_text("k,p,decision,x,y\n0,-4,E,0,5\n1,-1,SE,1,5\n2,2,SE,2,4\n3,,,3,3\n")
    r = run("check", str(f), "-f", "json", "--", "circle", "5")
    assert r.code == 0, r.err
    data = json.loads(r.out)
    assert (data["score"], data["out_of"]) == (1, 4)
    rows = data["tables"][0]["rows"]
    assert [row[0] for row in rows] == [0, 1, 2, 3, 4]
    assert rows[-1][3:] == ["p = 3, SE, (4, 3)", "missing"]
