"""The marker's small pieces at their edges, fed values and rows written by hand.

Each table and value below is written out here, never made by scanconv's generators, and
each expectation follows from the marking rules in words (``docs/marking.md``): a number
equals an answer exactly or to its last written decimal; a blank is never a number; a given
start row is never scored; which columns hold the pixel and which the exact values; the
notes' layout, where step k's p_{k+1} is read from the row after it; a comparison's relation,
a clipping piece's AND and action and an inside test's verdicts follow from the row's own
numbers. They fail on a marker that, for example, counts the given start row, reads whole x
values of a DDA table as its exact values, takes the p_{k+1} of the wrong row, or judges a
relation, an action or a verdict by the answer's numbers instead of the student's.
"""

from __future__ import annotations

from fractions import Fraction as F

import pytest

from scanconv.marking.mark import score
from scanconv.marking.rows import (
    Expected,
    Got,
    Layout,
    Verdict,
    _sources,
    exact_of,
    pixel_of,
    same,
    steps_of,
)
from scanconv.marking.student_table import Cell, parse_text
from scanconv.marking.table_models import (
    InsideVerdictsTable,
    MidpointClipTable,
    NLLTable,
    _relation,
)


def cell(text: str) -> Cell:
    """A number as written: ``"2.50"`` is 5/2 to two places."""
    places = len(text.split(".")[1]) if "." in text else 0
    return Cell(F(text), places)


def test_a_blank_is_never_a_number_and_two_blanks_agree() -> None:
    assert same(None, None)
    assert not same(cell("3"), None)  # a number where the answer has none
    assert not same(None, F(3))  # a blank where it has one
    assert same(cell("2.33"), F(7, 3)) and not same(cell("2.3"), F(7, 3))


def test_a_pixel_or_an_exact_pair_with_one_coordinate_blank_is_none() -> None:
    half = (cell("3"), None)
    other = (None, cell("4"))
    for pair in (half, other):
        got = Got("line 2", None, None, pair, pair, None)
        assert pixel_of(got) is None
        assert exact_of(got) is None
    whole = Got("line 2", None, None, (cell("3"), cell("4")), (cell("3.5"), cell("4")), None)
    assert pixel_of(whole) == (3, 4)
    assert exact_of(whole) == (F(7, 2), F(4))


def _verdict(row: int, mark: str) -> Verdict:
    return Verdict(row, f"line {row + 2}", None, Expected((row, row), None), mark)


def test_the_given_start_row_is_never_scored() -> None:
    # two steps asked, both right, the start row shown above them: 2 of 2
    shown = [_verdict(0, "given (not scored)"), _verdict(1, "right"), _verdict(2, "right")]
    assert score(shown, 2) == 2
    # a third step past the two asked costs one mark
    assert score([*shown, _verdict(3, "right")], 2) == 1


def _table(text: str):
    return parse_text(text, "s.csv", ".csv")


def test_a_dda_table_of_whole_x_and_y_holds_the_pixels_not_the_exact_values() -> None:
    # x, y alone, every value whole: the student wrote the plotted pixels
    whole = _table("k,x,y\n0,2,2\n1,3,2\n2,4,3\n")
    assert _sources(whole, True) == ("x", None)
    # a fractional value: these are the DDA's exact values (no pixel column)
    exact = _table("k,x,y\n0,2,2\n1,3,2.5\n2,4,3\n")
    assert _sources(exact, True) == (None, "x")
    # with a rounded column beside them: that is the pixel, x and y the exact values
    both = _table("k,x,y,round(y)\n0,2,2,2\n1,3,2.5,3\n")
    assert _sources(both, True) == ("px", "x")


def test_a_table_of_a_method_without_exact_values_reads_its_pixels_only() -> None:
    # Bresenham's table with a rounded column beside x, y: the pixel, and no exact values
    both = _table("k,x,y,round(y)\n0,2,2,2\n1,3,2.5,3\n")
    assert _sources(both, False) == ("px", None)
    plain = _table("k,x,y\n0,2,2\n1,3,2.5\n")
    assert _sources(plain, False) == ("x", None)


def _got(where: str, p: str, point: tuple[str, str]) -> Got:
    return Got(where, cell(p), "E", (cell(point[0]), cell(point[1])), None, None, where)


def test_the_notes_layout_reads_the_last_steps_next_p_from_the_last_row() -> None:
    # the notes' layout, the start row first: row k holds p_k and the point (x_k, y_k), so
    # step k is row k's p with row k + 1's point, and with no p_{k+1} column the last
    # step's p_{k+1} is the p written on the last row; the other steps' are read from
    # the step after them, not from a column
    rows = [
        _got("line 2", "0", ("2", "2")),
        _got("line 3", "-8", ("3", "3")),
        _got("line 4", "0", ("4", "3")),
    ]
    steps, start = steps_of(rows, Layout("at", True), {"p", "decision", "pixel"})
    assert start == rows[0]
    assert [s.p for s in steps] == [cell("0"), cell("-8")]
    assert [pixel_of(s) for s in steps] == [(3, 3), (4, 3)]
    assert [s.p_next for s in steps] == [None, cell("0")]
    # without the start row: the first step stands at no row before it
    steps, start = steps_of(rows, Layout("at", False), {"p", "decision", "pixel"})
    assert start is None
    assert [s.p for s in steps] == [None, cell("0"), cell("-8")]
    assert [s.p_next for s in steps] == [None, None, cell("0")]


def test_a_relation_of_two_equal_numbers_is_equals() -> None:
    assert _relation(F(1, 2), F(2, 4)) == "="
    assert _relation(F(1), F(2)) == "<" and _relation(F(3), F(2)) == ">"
    assert _relation("m1", F(2)) is None


def test_an_nll_relation_follows_from_the_students_own_numbers() -> None:
    # the answer compares m1 = 1/2 with m_L = 3/4: "<"; she wrote m1 as 1 (a slip): her
    # relation is then ">" (1 > 3/4), judged by her numbers
    answer = [
        {
            "left": "m1",
            "left_value": F(1, 2),
            "relation": "<",
            "right": "mL",
            "right_value": F(3, 4),
        }
    ]
    own = [{"left_value": F(1), "relation": ">", "right_value": F(3, 4)}]
    assert NLLTable().expect(0, answer, own)["relation"] == ">"
    equal = [{"left_value": F(3, 4), "relation": "=", "right_value": F(3, 4)}]
    assert NLLTable().expect(0, answer, equal)["relation"] == "="
    # a number she did not write: the answer's own relation stands
    blank = [{"left_value": None, "relation": "<", "right_value": F(3, 4)}]
    assert NLLTable().expect(0, answer, blank)["relation"] == "<"


PIECE = {"code_a": F(1), "code_b": F(0), "and": "0000", "action": "split", "mid": None}


def test_a_midpoint_piece_with_a_code_left_blank_is_judged_by_the_answer() -> None:
    for own in ({"code_a": None, "code_b": F(0)}, {"code_a": F(1), "code_b": None}):
        assert MidpointClipTable().expect(0, [PIECE], [own]) == PIECE


def test_a_midpoint_piece_with_both_codes_written_0000_is_accepted() -> None:
    # the answer's piece has codes 0001 and 0000 (split); she wrote 0000 and 0000: by her
    # own codes the piece is inside, so accept, and the AND is 0000
    exp = MidpointClipTable().expect(0, [PIECE], [{"code_a": F(0), "code_b": F(0)}])
    assert exp["and"] == "0000" and exp["action"] == "accept"
    # 1010 and 1000 (read as binary digits) share 1000: reject
    exp = MidpointClipTable().expect(0, [PIECE], [{"code_a": F(1010), "code_b": F(1000)}])
    assert exp["and"] == "1000" and exp["action"] == "reject"
    # 0001 and 0100 share nothing: the answer's accept or reject becomes a split
    accepted = {**PIECE, "action": "accept"}
    exp = MidpointClipTable().expect(0, [accepted], [{"code_a": F(1), "code_b": F(100)}])
    assert exp["and"] == "0000" and exp["action"] == "split"


def test_an_inside_verdict_follows_from_the_students_own_count() -> None:
    # the answer counts 2 crossings (outside) and winding 0 (outside); she counted 3 and
    # winding 1: by her own numbers both rules say inside
    answer = [{"crossings": F(2), "winding": F(0), "even_odd": "outside", "nonzero": "outside"}]
    own = [{"crossings": F(3), "winding": F(1)}]
    exp = InsideVerdictsTable().expect(0, answer, own)
    assert exp["even_odd"] == "inside" and exp["nonzero"] == "inside"
    # a count that is not whole decides nothing: the answer's verdict stands
    exp = InsideVerdictsTable().expect(0, answer, [{"crossings": F(5, 2), "winding": F(0)}])
    assert exp["even_odd"] == "outside"
    # a point on the boundary keeps the answer's row
    boundary = [{**answer[0], "boundary": "on edge 1"}]
    assert InsideVerdictsTable().expect(0, boundary, own) == boundary[0]


def test_a_row_past_the_end_of_a_table_is_numbered_on_and_costs_one_mark(tmp_path) -> None:
    # the threshold question's four pixels written right, and a fifth row past them: 3 of 4,
    # the fifth numbered 5 and marked extra
    from .test_marking_hand_tables import THRESHOLD, check
    from .test_marking_hand_tables import score as scored_as

    text = (
        "x,y,value,threshold,output\n"
        "0,0,128,128,1\n1,0,200,128,1\n0,1,60,128,0\n1,1,90,128,0\n2,1,90,128,0\n"
    )
    result = check(tmp_path, "threshold-long.csv", text, *THRESHOLD)
    assert scored_as(result) == (3, 4)
    rows = result["tables"][0]["rows"]
    assert [(r[0], r[-1]) for r in rows] == [
        (1, "right"),
        (2, "right"),
        (3, "right"),
        (4, "right"),
        (5, "extra"),
    ]


def test_a_file_of_exactly_the_largest_size_is_read_to_its_last_byte(tmp_path) -> None:
    # Bresenham's pixels from (2, 2) to (10, 6) written right (the module of the hand
    # tables works them out), padded with blank lines above them to exactly the largest size
    # a student file may have: its last byte (the 6 of the last pixel) is read, 8 of 8
    from scanconv.marking.student_table import MAX_TABLE_BYTES

    from .test_marking_hand_tables import BRESENHAM, check
    from .test_marking_hand_tables import score as scored_as

    pixels = [(3, 3), (4, 3), (5, 4), (6, 4), (7, 5), (8, 5), (9, 6), (10, 6)]
    table = "x,y\n" + "\n".join(f"{x},{y}" for x, y in pixels)
    text = "\n" * (MAX_TABLE_BYTES - len(table)) + table
    assert len(text.encode()) == MAX_TABLE_BYTES and text.endswith("10,6")
    assert scored_as(check(tmp_path, "padded.csv", text, *BRESENHAM)) == (8, 8)


def test_a_plain_text_cell_overlapping_two_columns_equally_goes_to_the_nearer_start() -> None:
    # columns under "------" at 0-6 and "-" at 7-8; "abc" written at 5-8 overlaps each by
    # one character: it is read into the column that starts nearer to it, the second (its
    # start is 2 away, the first's 5), though the first column's end is nearer
    from scanconv.marking.student_table import _spread

    assert _spread("     abc", [(0, 6), (7, 8)]) == ["", "abc"]
    assert _spread("ab   cd", [(0, 2), (5, 7)]) == ["ab", "cd"]


def test_a_models_chain_stops_at_the_marking_limit() -> None:
    # Bresenham from (0, 0) to (20000, 0) has 20,001 points; a marking chain reads at most
    # the 10,001 a question of check's largest size (10,000 steps) has, from its start
    from scanconv.marking.models import BresenhamLine, chain

    points = [s.point for s in chain(BresenhamLine(0, 0, 20000, 0))]
    assert len(points) == 10**4 + 1
    assert points[0] == (0, 0) and points[-1] == (10**4, 0)


def test_the_safety_net_takes_an_answer_without_p_by_its_pixels() -> None:
    # the answer's steps written by hand: Bresenham's pixels from (2, 2) to (6, 4) (dx = 4,
    # dy = 2: p0 = 0, NE; -4, E; 0, NE; -4, E), first with the p it prints, then printing no p
    # at all: the model's chain agrees with both; with a pixel or a p changed it agrees with
    # neither
    from types import SimpleNamespace

    from scanconv.marking.mark import _agrees
    from scanconv.marking.models import BresenhamLine, chain

    model = BresenhamLine(2, 2, 6, 4)
    states = list(chain(model))
    pixels = [(2, 2), (3, 3), (4, 3), (5, 4), (6, 4)]
    assert [s.point for s in states] == pixels
    p = [0, -4, 0, -4, 0]

    def answer(points, ps):
        steps = [SimpleNamespace(pixel=pt, p=v) for pt, v in zip(points, ps, strict=True)]
        return SimpleNamespace(steps=lambda: iter(steps))

    assert [s.p for s in states] == p
    assert _agrees(model, states, answer(pixels, p))
    assert _agrees(model, states, answer(pixels, [None] * 5))
    assert not _agrees(model, states, answer(pixels, [0, -4, 0, 4, 0]))
    assert not _agrees(model, states, answer([*pixels[:4], (6, 5)], [None] * 5))


@pytest.mark.slow  # two tables of 10,000 rows answered: about a second each
def test_a_table_question_at_the_row_limit(tmp_path) -> None:
    # a thick line from (0, 0) to (9999, 0) adds pixels in 10,000 steps, check's limit:
    # marked (only the first step written, its three pixels (0, -1), (0, 0), (0, 1)); to
    # (10000, 0) it has 10,001 steps: refused, naming the limit (it once marked them)
    from .helpers import assert_refused, run

    path = tmp_path / "one.csv"
    path.write_text('k,added\n0,"(0, -1), (0, 0), (0, 1)"\n', encoding="utf-8")
    done = run("check", str(path), "--", "thickline", "0", "0", "9999", "0", "--width", "3")
    assert done.code == 0, done.err
    assert "1 of 10000" in done.out or "1/10000" in done.out, done.out[:300]
    too_long = run("check", str(path), "--", "thickline", "0", "0", "10000", "0", "--width", "3")
    assert_refused(too_long, "more than 10000 rows")


def test_a_heading_is_found_under_a_preamble_of_at_most_ten_lines() -> None:
    from scanconv.marking.table_head import without_preamble

    table = ["k,p,x,y", "0,0,2,2"]
    names = [f"Line {n}:,note" for n in range(11)]  # two cells each: they head nothing
    assert without_preamble(names[:10] + table) == table
    assert without_preamble(names + table) == names + table  # an 11th line: kept whole
    # a heading of three columns, two of them named as a table's, under the student's name
    assert without_preamble(["Name:,Gita", "k,x,y", "0,2,2"]) == ["k,x,y", "0,2,2"]
    assert without_preamble(["Name:,Gita", "x,y,comment", "2,2,ok"]) == ["x,y,comment", "2,2,ok"]
    # a line of three cells naming one column is not a heading: the file is kept whole
    odd = ["Name:,Gita", "Group,A,p", "k,p,x,y", "0,0,2,2"]
    assert without_preamble(odd) == odd


def test_the_ellipse_model_moved_to_a_students_pixel_re_decides_its_region() -> None:
    # rx = 8, ry = 6: region 1 while 2 ry^2 x < 2 rx^2 y (72 x < 128 y). From a region-1
    # state, (2, 6) stays in region 1 (144 < 768) with its p; (7, 3) is in region 2
    # (504 >= 384), its p worked out afresh as p2_0 = ry^2 (x + 1/2)^2 + rx^2 (y - 1)^2
    # - rx^2 ry^2 = 36 * 56.25 + 64 * 4 - 2304 = 2025 + 256 - 2304 = -23
    from scanconv.marking.models import MidpointEllipse

    m = MidpointEllipse(8, 6)
    s = m.start()
    assert s.region == 1
    inside = m.at((2, 6), s)
    assert inside.region == 1 and inside.p == s.p
    beyond = m.at((7, 3), s)
    assert beyond.region == 2 and beyond.p == -23


def test_a_textbook_line_question_is_marked_in_the_textbook_layout() -> None:
    from scanconv.marking.diagnose import model_for
    from scanconv.questions.marking import marking_answer, marking_line

    shapes = [
        model_for(marking_answer(marking_line(f"line 2 2 10 6 --layout {layout}"))).shape
        for layout in ("notes", "textbook")
    ]
    assert shapes == ["at", "after"]


def test_a_chains_steps_name_the_state_before_each() -> None:
    from scanconv.marking.diagnose import states_steps
    from scanconv.marking.models import BresenhamLine, chain

    model = BresenhamLine(2, 2, 6, 4)
    states = list(chain(model))
    steps = states_steps(model, states)
    assert [e.point for e in steps] == [(3, 3), (4, 3), (5, 4), (6, 4)]
    assert [e.decision for e in steps] == ["NE", "E", "NE", "E"]
    assert [e.prev for e in steps] == [None, *states[:3]]
    assert [e.state for e in steps] == states[:4]


def test_an_expected_step_names_its_exact_values_and_its_next_p() -> None:
    from scanconv.marking.words import expected_text

    exp = Expected((3, 2), F(1), "E", F(-3), (F(5, 2), F(2)))
    assert expected_text(exp, ("exact", "pixel")) == "x = 2.5, y = 2, (3, 2)"
    assert expected_text(exp, ("p", "decision", "p_next")) == "p = 1, E, next p = -3"


def test_a_table_without_a_marked_column_is_refused_naming_the_ones_marked(tmp_path) -> None:
    # the threshold question marks each pixel's threshold T and its output; a table of the
    # pixels' positions and values alone has neither: refused, naming those two, not the
    # columns it has
    from .helpers import assert_refused, run
    from .test_marking_hand_tables import THRESHOLD

    path = tmp_path / "values.csv"
    path.write_text("x,y,value\n0,0,128\n", encoding="utf-8")
    done = run("check", str(path), "--", *THRESHOLD)
    assert_refused(done, "no column to mark: the answer's table has T, output")
