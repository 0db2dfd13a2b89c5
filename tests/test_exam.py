"""``scanconv exam``: the shipped question file answers every exam question of the notes, and
the book comes out whole, with its contents, in every format."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from scanconv.cli.exam import BEYOND_NOTES, exam_sheet, exam_text, pick_section
from scanconv.cli.sheet import answer_questions
from scanconv.render import Format, render

from .external import typeset
from .helpers import assert_refused, run
from .notes_questions import NOTES, notes_questions

ROOT = Path(__file__).resolve().parents[1]


def _key(text: str) -> str:
    """A question's words, for matching: no maths markup, case or punctuation."""
    return re.sub(r"[^a-z0-9|>]+", " ", text.replace("$", "").lower()).strip()


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_every_exam_question_of_the_notes_is_answered_in_the_shipped_file() -> None:
    if not NOTES.exists():
        pytest.skip(f"the course notes are not here ({NOTES}): nothing to cover")
    asked = notes_questions(NOTES.read_text(encoding="utf-8"))
    assert len(asked) == 30 + 7
    sheet = exam_sheet()
    answered = answer_questions(sheet.questions, sheet.source)
    by_wording = {_key(a.question.wording): a for a in answered}
    for section, question in asked:
        key = _key(question)
        # the wording is the notes' question, then what the answer chose, if anything
        found = by_wording.get(key) or next(
            (a for w, a in by_wording.items() if w.startswith(key)), None
        )
        assert found is not None, f"no entry for {question!r} ({section})"
        sol = found.solution
        assert sol.notes or sol.derived or sol.tables, question
        assert "".join(c for c in render(sol, Format.markdown) if isinstance(c, str)).strip()
        if section == "14 MARKS":
            assert found.question.marks == 14


def test_the_shipped_file_is_the_notes_37_questions_then_the_3d_chapter_s() -> None:
    sheet = exam_sheet()
    assert len(sheet.questions) == 37 + 15
    sections = list(dict.fromkeys(q.section for q in sheet.questions))
    assert len(sections) == 8 and all(q.wording for q in sheet.questions)
    # the notes' questions keep their numbers 1-37; the 3D chapter comes after, on its own
    assert sections[-1] == BEYOND_NOTES
    assert [q.number for q in sheet.questions if q.section == BEYOND_NOTES] == list(range(38, 53))
    assert run("exam", "--source").out == exam_text()
    assert exam_text() == (ROOT / "scanconv" / "data" / "exam.txt").read_text(encoding="utf-8")


def test_the_question_file_ships_as_package_data() -> None:
    tomllib = pytest.importorskip("tomllib")
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert "*.txt" in config["tool"]["setuptools"]["package-data"]["scanconv.data"]


def test_sections_are_picked_by_number_name_or_word() -> None:
    names = list(dict.fromkeys(q.section for q in exam_sheet().questions))
    assert pick_section(names, "2") == "Image representation"
    assert pick_section(names, "bresenham") == "Bresenham's line algorithm"
    assert pick_section(names, "dda") == "Simple DDA algorithm"
    assert pick_section(names, "14") == "The 14-mark topics"
    assert pick_section(names, "CIRCLE DRAWING") == "Circle drawing"
    assert pick_section(names, "3d") == pick_section(names, "8") == BEYOND_NOTES
    with pytest.raises(ValueError, match="several sections"):
        pick_section(names, "line")  # line drawing and Bresenham's line algorithm
    out = run("exam", "--section", "circle", "--format", "markdown").out
    assert out.count("### Question") == 5 and "Question 26" in out and "Question 25" not in out


@pytest.mark.parametrize(
    ("argv", "word"),
    [
        (("--section", "nope"), "is not a section"),
        (("--section", "9"), "is not a section"),
        (("--section", "line"), "several sections"),
        (("--contents", "--format", "html"), "not available in html: choose from latex, markdown"),
    ],
)
def test_bad_sections_are_one_line_exit_2(argv: tuple[str, ...], word: str) -> None:
    r = run("exam", *argv)
    assert_refused(r)
    assert word in r.err


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_markdown_book_opens_with_its_contents() -> None:
    out = run("exam", "--format", "markdown").out
    head, _, body = out.partition("\n## Scan conversion\n")
    listed = re.findall(r"^ {4}(\d+)\. ", head, re.M)
    assert listed == [str(n) for n in range(1, 53)]
    assert body.count("### Question") == 52
    assert head.index("## Contents") < len(head)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_html_book_links_its_contents_to_every_question() -> None:
    r = run("exam", "--section", "4", "-f", "html")
    assert r.code == 0, r.err
    nav = r.out.split('<nav class="sc-contents"', 1)[1].split("</nav>", 1)[0]
    links = re.findall(r'href="#(q\d+)"', nav)
    numbers = [q.number for q in exam_sheet("4").questions]
    assert links == [f"q{n}" for n in numbers]
    for target in links:  # every link lands on that question's answer, after the contents
        assert r.out.index(f'id="{target}"') > r.out.index("</nav>")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_json_book_has_question_section_and_answer() -> None:
    book = json.loads(run("exam", "--format", "json").out)
    assert len(book["questions"]) == 52
    for q in book["questions"]:
        assert q["question"] and q["section"] and q["answer"]["title"]


def test_the_plain_book_is_ascii() -> None:
    out = run("exam", "--section", "1", "--format", "plain").out
    assert out.isascii() and "Contents\n--------" in out


@pytest.mark.external
@pytest.mark.slow
def test_the_latex_book_compiles_with_contents_and_no_overfull_box(tmp_path: Path) -> None:
    r = run("exam", "--format", "latex", "--standalone", "-o", str(tmp_path / "exam.tex"))
    assert r.code == 0, r.err
    # the second pass reads the contents the first one wrote; the same document (and so the
    # same cached run) as tests/test_print.py's, which reads its PDF
    done = typeset(tmp_path, (tmp_path / "exam.tex").read_text(encoding="utf-8"), passes=2)
    assert done.code == 0, done.log[-2000:]
    assert "Overfull" not in done.log, re.findall(r"Overfull.*", done.log)[:5]
    toc = (done.folder / "doc.toc").read_text(encoding="utf-8")
    assert toc.count("{subsection}") == 52 and toc.count("{section}") == 8


def test_the_cheat_sheets_point_every_question_to_its_command() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    cheats = (ROOT / "docs" / "cheatsheet.md").read_text(encoding="utf-8")
    for q in exam_sheet().questions:
        row = f"| {q.number}. "
        for text in (readme, cheats):
            line = next((x for x in text.splitlines() if x.startswith(row)), "")
            assert f"`{q.command}`" in line, (q.number, q.command)
