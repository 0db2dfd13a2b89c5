"""A quiz keeps its answers hidden: no value a blank asks for is printed beside it.

Random sheets (lines, circles, ellipses, clipping by every method, transformations, polygon
fills and inside tests) are written as Moodle XML and as GIFT, parsed as the LMS reads them
(the XML by ElementTree, the GIFT question by question), and in every table row the text shown
outside the blanks is searched for the numbers the row's blanks ask: a number may be shown only
as a row's label (its first cell, a step ``k``) or as a given value of the question (its
"Given" line). Before the column roles, the clipping's working (``... = 7.8`` beside the
blank for 7.8) and the transform's ``0*0 + (-1)*0 + 3 = 3`` were there.
"""

from __future__ import annotations

import html
import re
import xml.etree.ElementTree as ET
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from scanconv.algorithms.process_choices import LineClipMethod
from scanconv.cli.sheet import answer_questions, read_questions
from scanconv.render.documents.sheet import sheet_document

pytestmark = pytest.mark.slow

CLOZE = re.compile(r"\{(\d+):(NUMERICAL|SHORTANSWER):(.*?)\}")
NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?(?:/\d+)?(?![\w.])")


def numbers(text: str) -> set[Fraction]:
    return {Fraction(t) for t in NUMBER.findall(text)}


def plain(fragment: str) -> str:
    return html.unescape(re.sub(r"<[^>]+>", " ", fragment))


def moodle_leaks(xml: str) -> list[tuple[str, str, set[Fraction]]]:
    """(question, shown cell, the blank values it shows) for every leak of a Moodle quiz."""
    found = []
    for q in ET.fromstring(xml).iter("question"):
        if q.get("type") != "cloze":
            continue
        body = q.findtext("questiontext/text") or ""
        given = re.search(r"<strong>Given:</strong>(.*?)</p>", body, re.S)
        givens = numbers(plain(given.group(1))) if given else set()
        for table in re.findall(r"<table.*?</table>", body, re.S):
            heads = [plain(h).strip() for h in re.findall(r"<th>(.*?)</th>", table, re.S)]
            for row in re.findall(r"<tr>(.*?)</tr>", table, re.S):
                cells = re.findall(r"<td>(.*?)</td>", row, re.S)
                asked = {
                    Fraction(body_.split("~")[0].lstrip("=").rsplit(":", 1)[0])
                    for c in cells
                    for _, kind, body_ in CLOZE.findall(c)
                    if kind == "NUMERICAL"
                }
                for head, cell in zip(heads[1:], cells[1:], strict=False):
                    if head == "k":
                        continue
                    shown = numbers(plain(CLOZE.sub(" ", cell))) & asked
                    if shown - givens:
                        name = q.findtext("name/text") or ""
                        found.append((name, plain(cell).strip(), shown))
    return found


_GIFT_BLANK = re.compile(r"(?<!\\)\{")


def gift_leaks(text: str) -> list[tuple[str, str, set[Fraction]]]:
    """The same search in a GIFT quiz: each blank is a question whose row is shown as
    ``title: heading = cell, ...`` with the blank asked as ``?`` and the others as ``_``."""
    found = []
    for block in text.split("\n\n"):
        if not block.startswith("::"):
            continue
        head, _, rest = _GIFT_BLANK.split(block, 1)[0], None, _GIFT_BLANK.split(block, 1)
        if len(rest) < 2 or not rest[1].startswith("#"):
            continue
        answer = Fraction(rest[1][1:].split(":", 1)[0])
        paragraphs = [html.unescape(p) for p in re.findall(r"<p>(.*?)</p>", head, re.S)]
        given = next((p for p in paragraphs if p.startswith("<strong>Given")), "")
        givens = numbers(plain(given.replace("\\", "")))
        asked = next((p for p in paragraphs if "= ?" in p), "")
        pairs = asked.replace("\\", "").split(": ", 1)[-1].split(", ")
        for pair in pairs[1:]:  # the first names the row
            name, _, cell = pair.partition(" = ")
            if name.strip() == "k" or cell.strip() in ("?", "_"):
                continue
            if answer in numbers(cell) - givens:
                found.append((head[:60], cell, {answer}))
    return found


coord = st.integers(0, 12)
METHODS = tuple(m.value for m in LineClipMethod)
"""Every line clipping method of ``clip line -m``."""


@st.composite
def question(draw: st.DrawFn) -> str:
    kind = draw(st.sampled_from(["line", "dda", "circle", "ellipse", "clip", "transform", "fill"]))
    a, b, c, d = (draw(coord) for _ in range(4))
    if kind in ("line", "dda"):
        if (a, b) == (c, d):
            c += 3
        return f"line {a} {b} {c} {d}" + (" --algo dda" if kind == "dda" else "")
    more = "quiz: symmetry\n" if draw(st.booleans()) else ""  # the symmetry tables asked too
    if kind == "circle":
        return f"{more}circle {draw(st.integers(2, 9))} --center {a} {b}"
    if kind == "ellipse":
        return f"{more}ellipse {draw(st.integers(2, 8))} {draw(st.integers(2, 8))}"
    if kind == "clip":
        if (a, b) == (c, d):
            d += 5
        method = draw(st.sampled_from(METHODS))
        return f"clip line {a} {b} {c + 3} {d} --window 2 2 9 8 --method {method}"
    if kind == "transform":
        angle = draw(st.sampled_from([90, 180, 270, 45, 30]))
        return f"transform {a} {b} {c} {d} 4 3 --rotate {angle} --about 2 1"
    return "polygon 1 1 9 1 9 7 5 3 1 7"


def quiz_files(lines: list[str]) -> tuple[str, str]:
    text = "".join(  # a "quiz:" line stays above its question's marks
        f"{q.rpartition(chr(10))[0]}\n[{i + 3}] {q.rpartition(chr(10))[2]}\n".lstrip("\n")
        for i, q in enumerate(lines)
    )
    sheet = read_questions(text, "q.txt")
    answered = answer_questions(sheet.questions, sheet.source)
    return (
        sheet_document(sheet, answered, "key", "moodle"),
        sheet_document(sheet, answered, "key", "gift"),
    )


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(question(), min_size=1, max_size=3))
def test_no_blank_is_answered_beside_it(lines: list[str]) -> None:
    xml, gift = quiz_files(lines)
    assert moodle_leaks(xml) == []
    assert gift_leaks(gift) == []


def test_clip_polygon_and_transform_questions_hide_their_working() -> None:
    """The three questions whose working once showed the answer: it stays in the feedback."""
    xml, gift = quiz_files(
        [
            "clip line 7 9 11 4 --window 4 4 10 8",
            "polygon 1 1 9 1 9 7 5 3 1 7",
            "transform 0 0 4 0 4 3 --rotate 90 --about 2 1",
        ]
    )
    assert moodle_leaks(xml) == [] and gift_leaks(gift) == []
    root = ET.fromstring(xml)
    texts = [q.findtext("questiontext/text") or "" for q in root.iter("question")]
    feedback = [q.findtext("generalfeedback/text") or "" for q in root.iter("question")]
    assert "(-1.25) = 7.8" not in texts[0] and "(-1.25) = 7.8" in html.unescape(feedback[0])
    assert "0*0 + (-1)*0 + 3 = 3" not in texts[2]
    assert "0*0 + (-1)*0 + 3 = 3" in html.unescape(feedback[2])
    assert "EA: 1, 0, 7" not in texts[1]  # the active edge table: working
    # the given end points are shown, not asked back as blanks
    assert re.search(r"<td>P1</td><td>\(7, 9\)</td>", texts[0])


def test_the_checker_sees_a_leak() -> None:
    """The checker itself finds the working of a Cohen-Sutherland row shown beside its blank
    (a quiz written as before the column roles)."""
    leaky = (
        '<quiz><question type="cloze"><name><text>Q1</text></name><questiontext><text>'
        "<![CDATA[<p><strong>Given:</strong> P1 = (7, 9)</p><table><thead><tr><th>k</th>"
        "<th>intersection</th><th>new</th></tr></thead><tbody><tr><td>1</td>"
        "<td>x = 7 + (8 - 9)/(-1.25) = 7.8</td><td>({1:NUMERICAL:=7.8:0}, "
        "{1:NUMERICAL:=8:0})</td></tr></tbody></table>]]></text></questiontext></question></quiz>"
    )
    assert moodle_leaks(leaky) == [
        ("Q1", "x = 7 + (8 - 9)/(-1.25) = 7.8", {Fraction(39, 5), Fraction(8)})
    ]


def test_the_gift_checker_sees_a_leak() -> None:
    _, gift = quiz_files(["line 2 2 10 6"])
    blocks = [b for b in gift.split("\n\n") if b.startswith("::")]
    assert len(blocks) > 20 and gift_leaks(gift) == []
    leaky = (
        "::Q1 [1] k = 1, x::[html]<p>Given: P1 = (2, 2)</p><p>Step table: k = 1, p = 7.8, "
        "x = ?</p>{#7.8:0\n####[html]<pre>key</pre>}"
    )
    assert [(cell, shown) for _, cell, shown in gift_leaks(leaky)] == [("7.8", {Fraction(39, 5)})]
