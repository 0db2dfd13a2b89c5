"""A quiz that asks more than the exam: the symmetry tables, by choice.

A circle's quiz asks what the exam asks, the octant's steps; ``quiz: symmetry`` before a
question in the question file (or ``sheet --quiz-symmetry`` for every question) also asks its
symmetry table: each octant point and its seven mirror images, every cell a blank, the rows
numbered. The quiz is parsed as Moodle reads it (the XML by ElementTree) and as GIFT (question
by question); the images a blank asks are worked out here from the octant point's blanks,
(xc ± x, yc ± y) and (xc ± y, yc ± x), and no blank's value is printed in the question.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from fractions import Fraction

import pytest

from scanconv.cli.sheet import answer_questions, read_questions
from scanconv.questions.files import QuestionError
from scanconv.render.documents.sheet import sheet_document

from .helpers import assert_refused, run
from .test_quiz_hides_answers import CLOZE, gift_leaks, moodle_leaks, plain

pytestmark = pytest.mark.slow

CIRCLE = "[5] circle 3 --center 2 1\n"


def quizzes(text: str) -> tuple[str, str]:
    sheet = read_questions(text, "q.txt")
    answered = answer_questions(sheet.questions, sheet.source)
    return (
        sheet_document(sheet, answered, "key", "moodle"),
        sheet_document(sheet, answered, "key", "gift"),
    )


def tables(xml: str) -> list[list[str]]:
    """Each cloze question's tables (their HTML)."""
    return [
        re.findall(r"<table.*?</table>", q.findtext("questiontext/text") or "", re.S)
        for q in ET.fromstring(xml).iter("question")
        if q.get("type") == "cloze"
    ]


def blanks(cell: str) -> list[Fraction]:
    return [Fraction(body.lstrip("=").rsplit(":", 1)[0]) for _, _, body in CLOZE.findall(cell)]


def test_a_circle_quiz_asks_the_octant_unless_told_to_ask_the_symmetry_too() -> None:
    xml, gift = quizzes(CIRCLE)
    assert [len(t) for t in tables(xml)] == [1]  # the step table alone
    assert "symmetry" not in gift.lower().split("::[html]")[0]
    xml, gift = quizzes("quiz: symmetry\n" + CIRCLE + CIRCLE)
    assert [len(t) for t in tables(xml)] == [2, 1]  # the next question only
    assert moodle_leaks(xml) == [] and gift_leaks(gift) == []


def test_the_symmetry_table_asked_holds_the_mirror_images_of_each_octant_point() -> None:
    xml, _ = quizzes("quiz: symmetry\n" + CIRCLE)
    table = tables(xml)[0][1]
    heads = [plain(h).strip() for h in re.findall(r"<th>(.*?)</th>", table, re.S)]
    assert heads[:2] == ["row", "(x, y)"] and len(heads) == 10
    rows = re.findall(r"<tr>(.*?)</tr>", table, re.S)[1:]
    assert len(rows) >= 3  # r = 3: (0, 3), (1, 3), (2, 2)
    xc, yc = 2, 1
    for n, row in enumerate(rows, 1):
        cells = re.findall(r"<td>(.*?)</td>", row, re.S)
        assert plain(cells[0]).strip() == str(n)  # the row's number, shown
        assert all(plain(CLOZE.sub("", c)).strip() in ("(, )", "( , )") for c in cells[1:]), row
        x, y = blanks(cells[1])
        want = [
            (xc + x, yc + y), (xc - x, yc + y), (xc + x, yc - y), (xc - x, yc - y),
            (xc + y, yc + x), (xc - y, yc + x), (xc + y, yc - x), (xc - y, yc - x),
        ]  # fmt: skip
        assert [tuple(blanks(c)) for c in cells[2:]] == want
    # the first rows are the octant's points from (0, r): the circle's top
    assert blanks(re.findall(r"<td>(.*?)</td>", rows[0], re.S)[1]) == [0, 3]


def test_the_gift_quiz_asks_each_mirrored_coordinate_as_a_question() -> None:
    _, plain_gift = quizzes(CIRCLE)
    _, gift = quizzes("quiz: symmetry\n" + CIRCLE)
    count = lambda text: sum(b.startswith("::") for b in text.split("\n\n"))  # noqa: E731
    rows = 3  # r = 3: three octant points, each 9 points of 2 coordinates
    assert count(gift) - count(plain_gift) == rows * 9 * 2
    assert gift_leaks(gift) == []


def test_sheet_quiz_symmetry_asks_every_questions_symmetry(tmp_path) -> None:
    path = tmp_path / "q.txt"
    path.write_text(CIRCLE + "[4] ellipse 4 2\n", encoding="utf-8")
    done = run("sheet", str(path), "-f", "moodle", "--quiz-symmetry")
    assert done.code == 0, done.err
    assert [len(t) for t in tables(done.out)] == [2, 2]  # the circle's 8-way, the ellipse's 4-way
    assert moodle_leaks(done.out) == []
    asked, _ = quizzes("quiz: symmetry\n" + CIRCLE + "quiz: symmetry\n[4] ellipse 4 2\n")
    assert done.out == asked


def test_a_quiz_line_asks_only_what_it_may(tmp_path) -> None:
    with pytest.raises(QuestionError, match="'quiz:' takes symmetry, not 'everything'"):
        read_questions("quiz: everything\n" + CIRCLE, "q.txt")
    with pytest.raises(QuestionError, match="'quiz:' without a question after it"):
        read_questions(CIRCLE + "quiz: symmetry\n", "q.txt")
    path = tmp_path / "q.txt"
    path.write_text("quiz: all\n" + CIRCLE, encoding="utf-8")
    assert_refused(run("sheet", str(path), "-f", "moodle"), "q.txt:1", "'quiz:' takes symmetry")
