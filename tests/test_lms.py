"""Quiz files for an LMS: ``sheet``/``practice`` ``--format moodle`` and
``--format gift`` (docs/lms.md).

The Moodle XML is read back by a reader written here with xml.etree (the Cloze blanks
``{1:NUMERICAL:=-8:0}`` parsed by Moodle's multianswer rules, restated below), the GIFT by the independent npm parser
``gift-pegjs`` (installed into a temporary directory once per session); the answers they hold
must be the key: the step table and the tables of scanconv's JSON answer to the same
questions, value by value, in order.
"""

from __future__ import annotations

import html
import json
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from fractions import Fraction
from pathlib import Path
from typing import Any, NamedTuple

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from scanconv.cli.sheet import answer_questions, read_questions
from scanconv.render.documents.lms import MAX_GAPS, TOLERANCE, decimal_text, number_gap
from scanconv.render.documents.sheet import sheet_document

from .external import npm_install

SCANCONV = (sys.executable, "-m", "scanconv")
"""The CLI of the Python running the tests (not whatever ``scanconv`` is first on PATH)."""

# --- the Moodle XML reader ----------------------------------------------------------------------


class Blank(NamedTuple):
    """A Cloze blank as Moodle reads it."""

    kind: str
    """``NUMERICAL``, ``SHORTANSWER``, ..."""
    weight: int
    answers: tuple[tuple[str, str], ...]
    """Each right answer (marked ``=``) with its tolerance (``""`` for a word)."""


# Moodle's multianswer syntax (question/type/multianswer/questiontype.php), restated: an
# answer runs to a ``~``, ``#`` or ``}`` not preceded by ``\``, ``&`` or ``&amp;``; a word
# answer is then HTML-entity-decoded and only ``\}`` and ``\#`` unescaped; a numerical answer
# is ``NUMBER`` or ``NUMBER:TOLERANCE``.
_FRACTION = r"=|%-?[0-9]+(?:[.,][0-9]*)?%"
_ANSWER = r".+?(?<!\\)(?<!&)(?<!&amp;)(?=[~#}]|$)"
_FEEDBACK = r".*?(?<!\\)(?=[~}]|$)"
_ALT = rf"(?:{_FRACTION})?(?:{_ANSWER})(?:#(?:{_FEEDBACK}))?"
_PARTS = re.compile(
    rf"~?(?P<fraction>{_FRACTION})?(?P<answer>{_ANSWER})(?:#(?:{_FEEDBACK}))?", re.S
)
_NUMBER = r"-?(?:[0-9]+[.,]?[0-9]*|[.,][0-9]+)(?:[eE][-+]?[0-9]+)?"
_NUMERICAL = re.compile(rf"^(?P<value>{_NUMBER})(?::(?P<tol>{_NUMBER}))?$", re.S)
_TYPES = "NUMERICAL|NM|MULTICHOICE|MC|SHORTANSWER_C|SAC|MWC|SHORTANSWER|SA|MW"
_BLANK = re.compile(
    rf"\{{(?P<weight>[0-9]*):(?P<type>{_TYPES}):(?P<alts>{_ALT}(?:~{_ALT})*)\}}", re.S
)


def cloze_blanks(text: str) -> list[Blank]:
    """Every blank of a Cloze question's text, as Moodle's multianswer parser reads them."""
    out = []
    for m in _BLANK.finditer(text):
        kind = {"NM": "NUMERICAL", "SA": "SHORTANSWER", "MW": "SHORTANSWER"}.get(
            m["type"], m["type"]
        )
        answers, rest = [], m["alts"]
        while rest and (alt := _PARTS.match(rest)):
            rest = rest[alt.end() :]
            if alt["fraction"] != "=":
                continue  # not a right answer (none are written)
            if kind == "NUMERICAL":
                number = _NUMERICAL.match(alt["answer"])
                assert number, alt["answer"]
                answers.append((number["value"], number["tol"] or "0"))
            else:
                word = html.unescape(alt["answer"]).replace("\\}", "}").replace("\\#", "#")
                answers.append((word, ""))
        out.append(Blank(kind, int(m["weight"] or 1), tuple(answers)))
    return out


class MoodleQuestion(NamedTuple):
    type: str
    name: str
    text: str
    text_format: str
    feedback: str
    blanks: list[Blank]
    element: ET.Element


def read_moodle(xml: str) -> list[MoodleQuestion]:
    """The questions of a Moodle XML quiz file: it must be well-formed, its root ``quiz``, and
    every question carry what Moodle's importer needs (a known type, a name, an HTML question
    text and general feedback)."""
    root = ET.fromstring(xml.encode("utf-8"))
    assert root.tag == "quiz"
    out = []
    for q in root:
        assert q.tag == "question"
        kind = q.get("type", "")
        assert kind in ("cloze", "essay"), kind
        name = q.findtext("name/text")
        assert name, "every question has a name"
        text_el = q.find("questiontext")
        assert text_el is not None and text_el.get("format") == "html"
        text = text_el.findtext("text") or ""
        feedback_el = q.find("generalfeedback")
        assert feedback_el is not None and feedback_el.get("format") == "html"
        blanks = cloze_blanks(text)
        if kind == "cloze":
            assert blanks, "a Cloze question has blanks"
        else:
            assert not blanks and q.findtext("graderinfo/text")
            assert q.findtext("responseformat") == "editor"
        out.append(
            MoodleQuestion(kind, name, text, "html", feedback_el.findtext("text") or "", blanks, q)
        )
    return out


# --- the GIFT reader: gift-pegjs on node ---------------------------------------------------------

_READER = """
const gift = require(process.argv[2]);
const rl = require('readline').createInterface({input: process.stdin});
rl.on('line', line => {
  let out;
  try { out = {ok: gift.parse(JSON.parse(line))}; }
  catch (e) { out = {error: String(e.message)}; }
  process.stdout.write(JSON.stringify(out) + '\\n');
});
"""


class GiftReader:
    """gift-pegjs in one node process: one GIFT text in, its questions out."""

    def __init__(self, module: Path, script: Path) -> None:
        self.proc = subprocess.Popen(
            ["node", str(script), str(module)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            encoding="utf-8",
        )

    def parse(self, text: str) -> list[dict[str, Any]]:
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self.proc.stdin.write(json.dumps(text) + "\n")
        self.proc.stdin.flush()
        got = json.loads(self.proc.stdout.readline())
        assert "error" not in got, got.get("error")
        return list(got["ok"])

    def close(self) -> None:
        assert self.proc.stdin is not None
        self.proc.stdin.close()
        self.proc.wait(timeout=60)


@pytest.fixture(scope="session")
def gift_reader(tmp_path_factory: pytest.TempPathFactory) -> Iterator[GiftReader]:
    """gift-pegjs 1.x installed with npm into a temporary directory (needs node, npm and the
    registry: CI has them)."""
    where = tmp_path_factory.mktemp("gift-pegjs")
    module = npm_install(where, "gift-pegjs@1")
    script = where / "reader.js"
    script.write_text(_READER, encoding="utf-8")
    reader = GiftReader(module, script)
    yield reader
    reader.close()


def gift_answers(question: dict[str, Any]) -> tuple[str, tuple[tuple[float | str, float], ...]]:
    """A parsed GIFT question's type and right answers: ``(number, range)`` or ``(text, 0)``."""
    kind = question["type"]
    choices = question.get("choices")
    if kind == "Numerical":
        items = choices if isinstance(choices, list) else [{"isCorrect": True, "text": choices}]
        out = []
        for c in items:
            assert c["isCorrect"]
            n = c["text"]
            assert n["type"] in ("simple", "range"), n
            out.append((float(n["number"]), float(n.get("range", 0))))
        return kind, tuple(out)
    if kind == "Short":
        return kind, tuple((c["text"]["text"], 0.0) for c in choices if c["isCorrect"])
    return kind, ()


# --- the key --------------------------------------------------------------------------------------


_NUMBER = r"~?-?\d+(\.\d+)?|-?\d+/\d+"


def _flat(value: Any) -> list[Any]:
    """A key's cell as the values its blanks hold: none for an empty cell or a text of
    working (shown as it is), each coordinate of a point (a list, or text ``(a, b)``)."""
    if value is None:
        return []
    if isinstance(value, list):
        return [x for v in value for x in _flat(v)]
    if isinstance(value, str):
        point = re.fullmatch(rf"\(({_NUMBER}), ({_NUMBER})\)", value)
        if point:
            return [point.group(1), point.group(3)]
        if re.fullmatch(rf"{_NUMBER}|[A-Za-z][A-Za-z-]{{0,15}}|-?0\d+", value):
            return [value]
        # a longer text answer: each number standing alone a blank ("[1, 5) [5, 9)"), or, in
        # words only, the text itself
        numbers = re.findall(r"(?<![\w.])-?\d+(?:\.\d+)?(?:/\d+)?(?![\w.])", value)
        numbers = [n for n in numbers if not re.fullmatch(r"-?0\d+", n)]
        if numbers:
            return numbers
        return [value.strip()] if re.search("[A-Za-z]", value) else []
    return [value]


WORKING = {
    ("Region codes", "reason"),  # why a code bit is set
    ("Cohen-Sutherland iterations", "work"),  # the intersection's arithmetic
    ("Cohen-Sutherland iterations", "method"),  # the OR/AND test
    ("Points before and after", "work"),  # x' = m11*x + ...
    ("Points before and after", "arithmetic"),
    ("Scan lines", "aet"),  # the active edge table
}
"""The key's columns a quiz keeps for the feedback, by (table title, column): the working
that would give a blank away (written here from the notes' tables, not from scanconv's
column roles)."""

SHOWN = {
    ("Region codes", "point_xy"),  # the given end points
    ("Cohen-Sutherland iterations", "point_end"),
    ("Points before and after", "point_before"),  # the given points
    ("Comparisons", "test"),  # the question each comparison asks
}
"""The key's columns a quiz shows as given, by (table title, column)."""


def _asked(title: str, column: str) -> bool:
    return not any(title.startswith(t) and column == c for t, c in WORKING | SHOWN)


LABELS = frozenset({"k", "r", "i", "decimal", "unit", "method"})
"""Keys of a first column that numbers or names the rows (the step ``k``, de Casteljau's level
``r``, an image's row ``i``, a quantization level's number, a storage unit): shown, not asked."""


def key_cells(answer: dict[str, Any], *, split_steps: bool = False) -> list[Any]:
    """The key's answer cells, in the quiz's order, from scanconv's JSON answer: each step's
    cells (the row label ``k`` left out), then each table's rows (the first column, which
    names the row, left out); with ``split_steps`` the tables that split the step table
    (headed ``k``, the ellipse's regions) are left out, as the quiz asks them once."""
    out: list[Any] = []
    columns = answer["columns"]
    for step in answer["steps"]:
        for j, c in enumerate(columns):
            if not (j == 0 and c in LABELS) and c not in ("k", "region"):  # region: a label
                out.extend(_flat(step[c]))
    for table in answer.get("tables", []):
        if split_steps and table["columns"][0] == "k":
            continue
        if "-way symmetry" in table["title"]:
            continue  # the images of the octant's points: the feedback's, not asked
        for row in table["rows"]:
            for j, v in enumerate(row):
                column = table["columns"][j]
                if j and column != "k" and _asked(table["title"], column):
                    out.extend(_flat(v))
    return out


def holds(kind: str, answers: tuple[tuple[Any, Any], ...], value: Any) -> bool:
    """Whether a blank holds the key's ``value``: a word among its spellings; a number its
    value within its tolerance, the tolerance 0 exactly when the value has at most 3
    decimals, and the 3-decimal rounding a table prints accepted."""
    if isinstance(value, str) and value.startswith("~"):  # an approximation: its digits
        digits = value[1:]
        half = Fraction(5, 10 ** (len(digits.partition(".")[2]) + 1))
        return answers == ((float(digits), float(half)),) or answers == ((digits, str(half)),)
    code = isinstance(value, str) and re.fullmatch(r"-?0\d+", value)  # "010": a code
    if code or (isinstance(value, str) and not re.fullmatch(r"-?\d+(\.\d+)?|-?\d+/\d+", value)):
        return kind in ("SHORTANSWER", "Short") and value.lower() in (
            str(a).lower() for a, _ in answers
        )
    if kind not in ("NUMERICAL", "Numerical") or len(answers) != 1:
        return False
    exact = Fraction(value) if isinstance(value, (int, str)) else Fraction(repr(value))
    centre, tol = Fraction(str(answers[0][0])), Fraction(str(answers[0][1]))
    if (exact * 1000).denominator == 1:
        return tol == 0 and centre == exact
    if isinstance(value, float):  # JSON's float of a fraction: within 1e-15 of it
        return tol == Fraction(TOLERANCE) and abs(centre - exact) <= Fraction(1, 10**6)
    return tol == Fraction(TOLERANCE) and abs(round(exact, 3) - centre) <= tol


def documents(questions: str) -> tuple[str, str, list[dict[str, Any]]]:
    """The Moodle XML, the GIFT and the JSON key's answers of a question file's text."""
    sheet = read_questions(questions, "q.txt")
    answered = answer_questions(sheet.questions, sheet.source)
    key = json.loads(sheet_document(sheet, answered, "key", "json"))
    answers = [q["answer"] for q in key["questions"]]
    return (
        sheet_document(sheet, answered, "key", "moodle"),
        sheet_document(sheet, answered, "key", "gift"),
        answers,
    )


def assert_moodle_key(xml: str, answers: list[dict[str, Any]], split: bool = False) -> None:
    questions = read_moodle(xml)
    assert len(questions) == len(answers)
    for q, answer in zip(questions, answers, strict=True):
        cells = key_cells(answer, split_steps=split)
        assert q.type == "cloze"
        assert len(q.blanks) == len(cells)
        for blank, value in zip(q.blanks, cells, strict=True):
            assert holds(blank.kind, blank.answers, value), (blank, value)
        marks = re.search(r"<defaultgrade>(\d+)</defaultgrade>", ET.tostring(q.element, "unicode"))
        weights = [b.weight for b in q.blanks]
        if marks is not None and int(marks[1]) >= len(weights):
            assert sum(weights) == int(marks[1])  # Moodle scores a Cloze question so
            assert max(weights) - min(weights) <= 1
        else:
            assert set(weights) <= {1}


def assert_gift_key(
    reader: GiftReader, text: str, answers: list[dict[str, Any]], split: bool = False
) -> None:
    parsed = reader.parse(text)
    cells = [c for a in answers for c in key_cells(a, split_steps=split)]
    assert len(parsed) == len(cells)
    for question, value in zip(parsed, cells, strict=True):
        kind, right = gift_answers(question)
        assert holds(kind, right, value), (question["title"], right, value)
        assert question["globalFeedback"]["format"] == "html"
        assert "<pre>$ scanconv " in question["globalFeedback"]["text"]


# --- the tests ------------------------------------------------------------------------------------

EXAMPLES = """\
title: Unit 2
[14] line 2 2 10 6
line 0 0 3 7 --algo dda
line 9 11 3 3 --algo midpoint
circle 10 --method bresenham --center 7 9
circle 8 --method midpoint
bspline 7 4 8 3 3 7 8 8 7 6 --degree 3 --samples 8
dither floyd-steinberg --image '98 240 243 203; 77 118 77 199' --top 255
"""


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_moodle_cloze_blanks_hold_the_json_key() -> None:
    xml, _, answers = documents(EXAMPLES)
    assert_moodle_key(xml, answers)
    first = read_moodle(xml)[0]
    assert first.name == "Unit 2: Q1 Bresenham's line algorithm: (2, 2) to (10, 6)"
    # the notes' worked example, row by row: p_k, the decision, the pixel, p_{k+1}
    assert [b.answers[0][0] for b in first.blanks[:5]] == ["0", "NE", "2", "2", "-8"]
    assert first.blanks[1].answers == (("NE", ""), ("north-east", ""), ("northeast", ""),
                                       ("north east", ""))  # fmt: skip
    assert "<pre>$ scanconv line 2 2 10 6\n" in first.feedback  # the worked answer
    assert "Step table:" in first.feedback and "#" in first.feedback  # its table and grid
    dda = read_moodle(xml)[1]
    assert dda.blanks[6] == Blank("NUMERICAL", 1, (("0.428571", TOLERANCE),))  # x_1 = 3/7


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_gift_read_back_by_gift_pegjs_holds_the_json_key(gift_reader: GiftReader) -> None:
    _, text, answers = documents(EXAMPLES)
    assert_gift_key(gift_reader, text, answers)
    first = gift_reader.parse(text)[0]
    assert (
        first["title"]
        == "Unit 2: Q1 Bresenham's line algorithm: (2, 2) to (10, 6) [1] Step table, k = 0, pₖ"
    )
    assert first["choices"] == {"type": "range", "number": 0, "range": 0}


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_ellipse_asks_its_step_table_once() -> None:
    """The ellipse's region tables split the step table: asked once, with the regions as
    row labels; the 4-way symmetry table's images follow from the quadrant's points: they
    are in the feedback, not asked (an exam asks the quadrant's steps)."""
    xml, _, answers = documents("ellipse 7 8\nellipse 4 5 --center 9 3\n")
    assert_moodle_key(xml, answers, split=True)
    first = read_moodle(xml)[0]
    assert first.text.count("<table") == 1  # the step table
    assert "<th>region</th><th>k</th>" in first.text
    assert "<tr><td>1</td><td>0</td>" in first.text  # region 1, k = 0: shown
    assert "symmetry" not in first.text
    assert "4-way symmetry" in html.unescape(ET.tostring(first.element, "unicode"))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_other_tables_are_blanks_too(gift_reader: GiftReader) -> None:
    """Secondary tables: clipping parameters given as text ("2/47"), a storage table's
    sizes ("~0.05722"), verdict words, points written as text."""
    questions = (
        "clip line 8 27 55 18 --window 10 10 50 40 --method liang-barsky\n"
        "bezier 9 8 2 5 9 7 --at 3/4\n"
        "quantize --bits 3 --range 0 100\n"
    )
    xml, text, answers = documents(questions)
    assert_moodle_key(xml, answers)
    assert_gift_key(gift_reader, text, answers)
    xml, _, _ = documents("storage 800 600 --binary\n")
    sizes = [b.answers[0] for b in read_moodle(xml)[0].blanks]
    assert ("0.05722", "0.000005") in sizes and ("480000", "0") in sizes


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_questions_without_tables_are_essays(gift_reader: GiftReader) -> None:
    """A theory question, and one with more blanks than a question holds: an essay question
    whose general feedback and grader's information are the key."""
    xml, text, _ = documents("[5] theory dda\nline 0 0 200 3\n")
    theory, long = read_moodle(xml)
    assert theory.type == long.type == "essay"
    assert theory.element.findtext("defaultgrade") == "5"
    assert "DDA" in (theory.element.findtext("graderinfo/text") or "")
    assert "(200, 3)" in long.feedback
    parsed = gift_reader.parse(text)
    assert [q["type"] for q in parsed] == ["Essay", "Essay"]
    assert "Definition" in parsed[0]["globalFeedback"]["text"]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_notice_for_an_essay_fallback(tmp_path: Path) -> None:
    """The CLI: -o quiz.xml chooses Moodle XML by the one extension map; an answer too large
    for blanks is said on stderr."""
    questions = tmp_path / "q.txt"
    questions.write_text("line 0 0 200 3\nline 2 2 10 6\n", encoding="utf-8")
    out = tmp_path / "quiz.xml"
    done = subprocess.run(
        [*SCANCONV, "sheet", str(questions), "-o", str(out)], capture_output=True, text=True
    )
    assert done.returncode == 0 and done.stdout == ""
    assert f"more than {MAX_GAPS} blanks" in done.stderr
    assert [q.type for q in read_moodle(out.read_text(encoding="utf-8"))] == ["essay", "cloze"]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_marks_notice_names_each_question_in_whole_words(tmp_path: Path) -> None:
    """A question of fewer marks than blanks is named on stderr by its number, its title cut
    at a word (never "rotate by 9" for "rotate by 90") and its blank count, the number of
    Cloze blanks Moodle reads in that question."""
    questions = tmp_path / "q.txt"
    questions.write_text(
        "[3] transform 0 0 4 0 4 3 --rotate 90 --about 2 1\n[4] circle 5\n", encoding="utf-8"
    )
    out = tmp_path / "quiz.xml"
    done = subprocess.run(
        [*SCANCONV, "sheet", str(questions), "-o", str(out)], capture_output=True, text=True
    )
    assert done.returncode == 0 and done.stdout == "", done.stderr
    quiz = read_moodle(out.read_text(encoding="utf-8"))
    named = re.findall(r"(Q\d+) \((.*?)\) to (\d+) \(it has (\d+) blanks\)", done.stderr)
    assert [n[0] for n in named] == ["Q1", "Q2"]
    for (_, shown, marks, blanks), question, want in zip(named, quiz, (3, 4), strict=True):
        assert (int(marks), int(blanks)) == (want, len(question.blanks))
        title = question.name.partition(" ")[2]
        words = shown.removesuffix(" ...").split(" ")
        assert title.split(" ")[: len(words)] == words, (shown, title)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_practice_writes_both_quiz_files(tmp_path: Path, gift_reader: GiftReader) -> None:
    """practice: the worksheet as GIFT, the key as Moodle XML, from the same questions."""
    gift_file, xml_file = tmp_path / "quiz.gift", tmp_path / "quiz.xml"
    qfile = tmp_path / "q.txt"
    done = subprocess.run(
        [*SCANCONV, "practice", "--topic", "line", "-n", "3", "--seed", "4",
         "-o", str(gift_file), "--key", str(xml_file), "--questions", str(qfile)],
        capture_output=True, text=True,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    _, _, answers = documents(qfile.read_text(encoding="utf-8"))
    assert_moodle_key(xml_file.read_text(encoding="utf-8"), answers)
    assert_gift_key(gift_reader, gift_file.read_text(encoding="utf-8"), answers)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_contradicting_format_is_refused(tmp_path: Path) -> None:
    questions = tmp_path / "q.txt"
    questions.write_text("line 2 2 10 6\n", encoding="utf-8")
    out = tmp_path / "quiz.xml"
    done = subprocess.run(
        [*SCANCONV, "sheet", str(questions), "--format", "gift", "-o", str(out)],
        capture_output=True, text=True,
    )  # fmt: skip
    assert done.returncode == 2 and done.stdout == "" and not out.exists()
    assert done.stderr.count("\n") == 1 and "moodle" in done.stderr


# --- properties -----------------------------------------------------------------------------------

coordinate = st.integers(-12, 12)
lines = st.builds(
    lambda x1, y1, x2, y2, algo: f"line {x1} {y1} {x2} {y2} --algo {algo}",
    coordinate, coordinate, coordinate, coordinate,
    st.sampled_from(["bresenham", "dda", "midpoint", "basic"]),
)  # fmt: skip
circles = st.builds(
    lambda r, xc, yc, method: f"circle {r} --center {xc} {yc} --method {method}",
    st.integers(1, 14), coordinate, coordinate,
    st.sampled_from(["midpoint", "bresenham", "general", "symmetric-dda"]),
)  # fmt: skip


@pytest.mark.slow  # 20 examples: each is read back by node's gift-pegjs
@settings(
    max_examples=20, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(st.lists(st.one_of(lines, circles), min_size=1, max_size=3))
def test_random_lines_and_circles_hold_the_key(
    gift_reader: GiftReader, questions: list[str]
) -> None:
    xml, text, answers = documents("\n".join(questions) + "\n")
    assume(all(key_cells(a) for a in answers))
    assert_moodle_key(xml, answers)
    assert_gift_key(gift_reader, text, answers)


fractions = st.fractions(min_value=-(10**6), max_value=10**6, max_denominator=10**4)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=300, deadline=None)
@given(fractions)
def test_the_tolerance_rule(value: Fraction) -> None:
    """Exact with tolerance 0 when the value has at most 3 decimals; else the value to 6
    decimals within 0.0005, which holds the value and its 3-decimal rounding (either way a
    tie is broken)."""
    gap = number_gap(value)
    centre, tol = Fraction(gap.answers[0]), Fraction(gap.tolerance)
    if (value * 1000).denominator == 1:
        assert (tol, centre, decimal_text(value)) == (0, value, gap.answers[0])
    else:
        assert tol == Fraction(TOLERANCE) and abs(centre - value) <= Fraction(1, 2 * 10**6)
        scaled = value * 1000
        for rounded in (Fraction(scaled.__floor__(), 1000), Fraction(scaled.__ceil__(), 1000)):
            if abs(rounded - value) <= Fraction(1, 2000):  # a 3-decimal rounding of it
                assert abs(rounded - centre) <= tol
        assert "e" not in gap.answers[0].lower()


def test_docs_state_the_rules_the_code_uses() -> None:
    """docs/lms.md states the tolerance, the most blanks of a question and the spellings of
    a decision as the code has them."""
    from scanconv.render.documents.lms import MOVE_WORDS

    doc = (Path(__file__).resolve().parent.parent / "docs" / "lms.md").read_text(encoding="utf-8")
    assert f"tolerance {TOLERANCE}" in doc and f"more than {MAX_GAPS} blanks" in doc
    assert "`E`/`east`, `NE`/`north-east`/`northeast`/`north east`" in doc
    assert MOVE_WORDS["E"] == ("east",)
    assert MOVE_WORDS["NE"] == ("north-east", "northeast", "north east")
    assert set(MOVE_WORDS) == {"E", "NE", "N", "NW", "W", "SW", "S", "SE"}
    assert "N NW W SW S SE" in doc


def test_numbers_of_any_size_are_written_exactly() -> None:
    """No decimal context rounds a large value (an ellipse's p with large radii)."""
    big = 10**40
    assert number_gap(big).answers == (str(big),)
    assert number_gap(Fraction(-big - 1, 8)).answers == (f"-{(big + 1) // 8}.125",)
    gap = number_gap(Fraction(big + 1, 3))
    assert gap.answers[0] == "3" * 40 + ".666667" and gap.tolerance == TOLERANCE


@pytest.mark.slow
def test_the_whole_exam_as_a_quiz(gift_reader: GiftReader) -> None:
    """The notes' exam (``scanconv exam --source``): its theory questions are essays, every
    other question a Cloze question whose blanks hold the key, and gift-pegjs reads the
    GIFT of the same questions with the same answers."""
    from scanconv.cli.exam import BEYOND_NOTES, exam_text

    notes = exam_text().split(f"section: {BEYOND_NOTES}", 1)[0]  # the 3D section: below
    xml, text, answers = documents(notes)
    questions = read_moodle(xml)
    marked = [(q, a) for q, a in zip(questions, answers, strict=True) if q.type == "cloze"]
    assert {a["primitive"] for q, a in zip(questions, answers, strict=True)
            if q.type == "essay"} == {"theory"}  # fmt: skip
    assert len(marked) >= 10
    assert_moodle_key(
        "<quiz>"
        + "".join(ET.tostring(q.element, encoding="unicode") for q, _ in marked)
        + "</quiz>",
        [a for _, a in marked],
    )
    parsed = gift_reader.parse(text)
    assert sum(q["type"] == "Essay" for q in parsed) == len(questions) - len(marked)
    cells = [c for _, a in marked for c in key_cells(a)]
    blanks = [q for q in parsed if q["type"] != "Essay"]
    assert len(blanks) == len(cells)
    for question, value in zip(blanks, cells, strict=True):
        assert holds(*gift_answers(question), value), (question["title"], value)


def test_the_exam_s_3d_section_as_a_quiz(gift_reader: GiftReader) -> None:
    """The book's 3D section: its theory questions are essays, every other question a Cloze
    question whose blanks are key cells in the key's order (its tables' given and working
    columns shown, not asked), the back faces' verdicts among them; the GIFT holds as many
    blanks."""
    from scanconv.cli.exam import BEYOND_NOTES, exam_text

    section = exam_text().split(f"section: {BEYOND_NOTES}", 1)[1]
    xml, text, answers = documents(f"section: {BEYOND_NOTES}{section}")
    questions = read_moodle(xml)
    assert len(questions) == 15
    every = []
    for q, answer in zip(questions, answers, strict=True):
        if answer["primitive"] == "theory":
            assert q.type == "essay"
            continue
        assert q.type == "cloze" and q.blanks, answer["title"]
        cells = iter(key_cells(answer))
        for blank in q.blanks:  # each blank holds a later key cell than the blank before
            assert any(holds(blank.kind, blank.answers, c) for c in cells), (answer["title"], blank)
        every += q.blanks
        if answer["algorithm"] == "backface":
            asked = [str(b.answers[0][0]) for b in q.blanks]
            verdicts = [row[-1] for row in answer["tables"][0]["rows"]]
            assert [a for a in asked if not re.fullmatch(r"-?\d+", a)] == verdicts
    parsed = [g for g in gift_reader.parse(text) if g["type"] != "Essay"]
    assert len(parsed) == len(every)
