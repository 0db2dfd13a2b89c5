"""The exam book's 3D section (``scanconv exam --section 3d``, questions 38-52, after the notes'
37): each question answered with what its own command gives when run alone, a few values
against numbers worked by hand, its contents in every contents format, the book in every
document format, and its PDF read back."""

from __future__ import annotations

import json
import re
from fractions import Fraction
from pathlib import Path

import pytest

from scanconv.cli.exam import BEYOND_NOTES, exam_sheet

from .external import pdftotext, typeset
from .helpers import run
from .test_print import _assert_print_clean, _visible

QUESTIONS = [q for q in exam_sheet().questions if q.section == BEYOND_NOTES]
NUMBERS = list(range(38, 53))


def _words(text: str) -> str:
    return " ".join(text.split())


def test_the_3d_section_is_the_papers_typical_questions_after_the_notes() -> None:
    assert [q.number for q in QUESTIONS] == NUMBERS
    commands = " ".join(q.command for q in QUESTIONS)
    for asked in (
        "--rotate-axis",
        "--perspective one-point --d 2",
        "--parallel cavalier",
        "--parallel cabinet",
        "--parallel isometric",
        "3d backface --solid pyramid",
        "3d backface --solid cube",
        "3d zbuffer",
        "3d scanline",
        "3d depth-sort",
        "3d warnock",
        "theory projections",
        "theory rotation-arbitrary-axis",
        "theory z-buffer",
        "theory object-image-space",
    ):
        assert asked in commands, asked


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_each_answer_is_its_command_s_answer_run_alone() -> None:
    book = json.loads(run("exam", "--section", "3d", "--format", "json").out)
    assert [q["number"] for q in book["questions"]] == NUMBERS
    markdown = run("exam", "--section", "3d", "--format", "markdown").out
    flat = re.sub(r"^#+ ", "", markdown, flags=re.M)
    for entry, q in zip(book["questions"], QUESTIONS, strict=True):
        assert entry["section"] == BEYOND_NOTES and entry["question"] == q.wording
        alone = run(*q.argv, "--format", "json")
        assert alone.code == 0, alone.err
        assert entry["answer"] == json.loads(alone.out), q.number
        shown = run(*q.argv, "--format", "markdown").out
        body = re.sub(r"^#+ ", "", shown, flags=re.M).split("\n", 1)[1]
        assert body.strip() in flat, q.number


def _answer(book: dict[str, list[dict[str, object]]], number: int) -> dict[str, object]:
    entry = next(q for q in book["questions"] if q["number"] == number)
    answer = entry["answer"]
    assert isinstance(answer, dict)
    return answer


def test_values_against_numbers_worked_by_hand() -> None:
    book = json.loads(run("exam", "--section", "3d", "--format", "json").out)
    # 41: the centre of projection at (0, 0, d), d = 2, the view plane z = 0:
    # x' = x d/(d - z); G = (1, 1, 1) goes to (1*2/1, 1*2/1) = (2, 2), B = (1, 0, 0) stays
    projected = _answer(book, 41)["projected"]
    assert projected[6] == [2, 2] and projected[1] == [1, 0]  # type: ignore[index]
    # 43: cabinet, L1 = 1/2, phi = 30: E = (0, 0, 1) to (L1 cos 30, L1 sin 30) = (sqrt3/4, 1/4)
    e = _answer(book, 43)["projected"][4]  # type: ignore[index]
    assert e[0] == "sqrt(3)/4" and Fraction(e[1]) == Fraction(1, 4)
    # 45: the pyramid's front face (0, 0, 2), (2, 0, 2), apex (1, 2, 1):
    # N = (2, 0, 0) x (1, 2, -1) = (0*(-1) - 0*2, 0*1 - 2*(-1), 2*2 - 0*1) = (0, 2, 4);
    # V = (0, 0, -1): V.N = -4 < 0, visible; its back face (0, 2, -4): V.N = 4, hidden
    pyramid = run("3d", "backface", "--solid", "pyramid", "--format", "json").out
    by_name = {f["name"]: f for f in json.loads(pyramid)["faces"]}
    assert by_name["front"]["normal"] == [0, 2, 4] and by_name["front"]["dot"] == -4
    assert not by_name["front"]["back"] and by_name["back"]["dot"] == 4
    assert _answer(book, 45) == json.loads(pyramid)
    # 48: B in x + y + z = 6 at (1, 1) is z = 4, nearer than A's 2: the frame shows B there
    zb = _answer(book, 48)
    assert zb["frame"]["1,1"] == "B" and zb["depth"]["1,1"] == 4  # type: ignore[index]
    assert zb["frame"]["3,1"] == "A"  # B's z = 2 there, equal: A, drawn first, keeps it  # type: ignore[index]


@pytest.mark.parametrize("fmt", ["markdown", "plain", "latex", "json"])
def test_the_contents_of_the_3d_section(fmt: str) -> None:
    r = run("exam", "--contents", "--section", "3d", "--format", fmt)
    assert r.code == 0, r.err
    for q in QUESTIONS:
        assert str(q.number) in r.out
    if fmt == "json":
        listed = json.loads(r.out)["contents"]
        assert [e["number"] for e in listed] == NUMBERS
        assert {e["section"] for e in listed} == {BEYOND_NOTES}
    else:
        assert "1. Define scan conversion" not in r.out  # the section alone


def test_the_whole_book_lists_the_3d_section_last_without_renumbering() -> None:
    listed = json.loads(run("exam", "--contents", "--format", "json").out)["contents"]
    assert [e["number"] for e in listed] == list(range(1, 53))
    assert [e["section"] for e in listed[37:]] == [BEYOND_NOTES] * 15
    assert BEYOND_NOTES not in {e["section"] for e in listed[:37]}


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("fmt", ["markdown", "plain", "html", "moodle", "gift"])
def test_the_3d_section_in_every_document_format(fmt: str) -> None:
    r = run("exam", "--section", "3d", "--format", fmt)
    assert r.code == 0, r.err
    for q in QUESTIONS[2:]:  # the wordings with a command of their own (every one has numbers)
        assert q.command.removeprefix("scanconv ").split()[1] in r.out
    if fmt == "html":
        nav = r.out.split('<nav class="sc-contents"', 1)[1].split("</nav>", 1)[0]
        assert re.findall(r'href="#(q\d+)"', nav) == [f"q{n}" for n in NUMBERS]
        text = _visible(r.out)
        assert not re.findall(r"\^|_\{|\\frac|\\text|\$", text)
        assert "Question 48" in text and "preset hearn-baker" in text


@pytest.mark.external
@pytest.mark.slow
def test_the_3d_section_prints_clean_and_reads_back(tmp_path: Path) -> None:
    r = run("exam", "--section", "3d", "--format", "latex", "--standalone")
    assert r.code == 0, r.err
    assert "\\begin{verbatim}" not in r.out
    done = typeset(tmp_path, r.out, passes=2)
    assert done.code == 0, done.log[-2000:]
    pages = _assert_print_clean(tmp_path, done.pdf, done.log)  # no overfull box, no raw TeX
    toc = (done.folder / "doc.toc").read_text(encoding="utf-8")
    assert toc.count("{subsection}") == 15 and toc.count("{section}") == 1
    text = _words("\n".join(pages))
    assert "?" not in re.sub(r"nearer\?|\?\)", "", text)  # no letter the fonts lack
    for q in QUESTIONS:
        assert f"Question {q.number}" in text
        assert _words(q.command) in text, q.command
    assert "α" in text or "alpha" in text.lower()
    again = _words(pdftotext(tmp_path, done.pdf))
    assert "Depth buffer (0 where never written)" in again
    assert "preset hearn-baker" in again
