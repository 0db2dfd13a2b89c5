"""Quiz files with hostile text: a question file's title and wording, a
table's headings and a short answer holding ``{ } ~ = # : ]]> <script>`` reach Moodle XML and
GIFT through the one escaper of each format, and read back (xml.etree and the Cloze reader of
:mod:`tests.test_lms`; the npm parser gift-pegjs) as the text they were, with no blank, tag or
question made of them."""

from __future__ import annotations

import html
import re
import xml.etree.ElementTree as ET

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from scanconv.core.working import visible
from scanconv.render.documents.gift import gift
from scanconv.render.documents.lms import Gap, GapTable, QuizQuestion
from scanconv.render.documents.moodle import cdata, cloze, moodle_text, moodle_xml
from tests.test_lms import GiftReader, cloze_blanks, documents, gift_reader, read_moodle

__all__ = ["gift_reader"]  # the session fixture, used here

HOSTILE = "A {1:NUMERICAL:=5} } ~ = # : ]]> <script>alert(1)</script> & \\ {#1:0} ::x::"


def _first_paragraph(text: str) -> str:
    match = re.match(r"<p>(.*?)</p>", text, re.S)
    assert match
    return html.unescape(match.group(1))


def test_hostile_title_and_wording_in_moodle_xml() -> None:
    xml, _, _ = documents(f"title: {HOSTILE}\n> W {HOSTILE}\nline 2 2 10 6\ntheory dda\n")
    line, theory = read_moodle(xml)  # well-formed, and the structure Moodle imports
    assert line.name == f"{HOSTILE}: Q1 Bresenham's line algorithm: (2, 2) to (10, 6)"
    assert _first_paragraph(line.text) == f"W {HOSTILE}"
    assert _first_paragraph(theory.text).startswith("Describe the DDA")
    for q in (line, theory):
        for text in (q.text, q.feedback, q.element.findtext("graderinfo/text") or ""):
            assert "<script" not in text and "]]>" not in text
        assert "&lt;script&gt;" in q.name or "<script>" in q.name  # a name is plain text
    # only the quiz's own blanks: none made of the user's braces
    assert line.text.count("{") == len(line.blanks) == 43
    assert [b.kind for b in line.blanks[:2]] == ["NUMERICAL", "SHORTANSWER"]
    assert theory.type == "essay" and not theory.blanks


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_hostile_title_and_wording_in_gift(gift_reader: GiftReader) -> None:
    _, text, _ = documents(f"title: {HOSTILE}\n> W {HOSTILE}\nline 2 2 10 6\ntheory dda\n")
    parsed = gift_reader.parse(text)
    assert len(parsed) == 43 + 1  # a question per blank, and the essay
    name = f"{HOSTILE}: Q1 Bresenham's line algorithm: (2, 2) to (10, 6)"
    for q in parsed[:-1]:
        assert q["title"].startswith(name + " [")
        assert q["stem"]["format"] == "html"
        assert _first_paragraph(q["stem"]["text"]) == f"W {HOSTILE}"
        assert "<script" not in q["stem"]["text"] + q["globalFeedback"]["text"]
    assert parsed[-1]["type"] == "Essay" and parsed[-1]["title"].startswith(f"{HOSTILE}: Q2 ")


def test_cdata_splits_its_end() -> None:
    for text in ("]]>", "a]]>b]]>", "]]]]>>", "<p>x</p>"):
        root = ET.fromstring(f"<t>{cdata(text)}</t>")
        assert root.text == text


def test_xml_illegal_characters_are_replaced() -> None:
    text = "a\x0b\x1f\ufffe\uffff\x7fb"
    root = ET.fromstring(f"<t>{moodle_text(text)}</t>")
    assert root.text is not None and root.text.startswith("a") and root.text.endswith("b")
    assert set(root.text[1:-1]) == {"\ufffd"}


def _question(text: str, word: str) -> QuizQuestion:
    """A quiz question whose every text is ``text``: name, wording, given value, table title,
    headings, a shown cell; and a short answer ``word``."""
    gap = Gap("word", (word,), "0", f"{text}, row 1")
    table = GapTable(
        text, (text, text), (((text,), ("(", gap, ", ", Gap("number", ("-8",)), ")")),)
    )
    return QuizQuestion(text or "-", text, (text,), (table,), text, None, (text,))


printable = st.text(
    st.characters(blacklist_categories=("Cs", "Cc", "Cf", "Zl", "Zp", "Co", "Cn")), max_size=40
)
words = st.text(st.sampled_from(list('{}~=#:\\/"&<>ab;')), min_size=1, max_size=12).filter(
    lambda w: "\\#" not in w and "\\}" not in w  # Moodle unescapes these after decoding: no
)  # word of scanconv holds a backslash (lms.cell_pieces), so they cannot come up
hostile = st.one_of(printable, st.text(st.sampled_from(list("{}~=#:]>[<&\\/\"' x%")), max_size=30))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(hostile, words)
def test_any_text_reads_back(gift_reader: GiftReader, text: str, word: str) -> None:
    """Whatever the text: Moodle XML stays well-formed with exactly the quiz's blanks, and
    gift-pegjs reads one question per blank, each text as it was."""
    q = _question(text, word)
    (back,) = read_moodle(moodle_xml([q]))
    assert back.name == (text or "-")
    assert _first_paragraph(back.text) == text
    assert [b.kind for b in back.blanks] == ["SHORTANSWER", "NUMERICAL"]
    assert back.blanks[0].answers == ((word, ""),)
    assert cloze_blanks(cloze(Gap("word", (word,)))) == [back.blanks[0]]
    parsed = gift_reader.parse(gift([q]))
    assert [p["type"] for p in parsed] == ["Short", "Numerical"]
    assert parsed[0]["title"] == " ".join(f"{text or '-'} [1] {text}, row 1".split())
    assert _first_paragraph(parsed[0]["stem"]["text"]) == text
    assert [c["text"]["text"] for c in parsed[0]["choices"]] == [" ".join(word.split())]
    assert parsed[1]["choices"] == {"type": "range", "number": -8, "range": 0}


def _corpus() -> list[str]:
    from tests.test_escaping import CORPUS

    return [t for t in CORPUS if "\x00" not in t]  # a NUL byte: not a text file, refused


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("text", _corpus(), ids=lambda t: repr(t[:16]))
def test_the_escaping_corpus_in_both_quiz_formats(gift_reader: GiftReader, text: str) -> None:
    """The corpus every format is tried with (tests/test_escaping.py) as a sheet's title,
    section and wording: both quiz files read back, no control character or bidirectional
    override in them, the title there as the other formats show it (visible)."""
    one = " ".join(text.split("\n"))
    questions = f"title: {one}\nsection: {one}\n> {one}\n[4] line 2 2 10 6\n> {one}\ncircle 5\n"
    xml, gift_text, _ = documents(questions)
    unsafe = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")
    for out in (xml, gift_text):
        assert not unsafe.search(out)
    title = " ".join(visible(one).split())
    moodle = read_moodle(xml)
    assert [q.type for q in moodle] == ["cloze", "cloze"]
    assert all(q.name.startswith(title[:200]) for q in moodle)
    assert all("<script" not in q.text for q in moodle)
    parsed = gift_reader.parse(gift_text)
    assert {q["type"] for q in parsed} == {"Numerical", "Short"}
    assert all(q["title"].startswith(title[:200]) for q in parsed)


def test_a_cloze_answer_writes_quotes_as_references() -> None:
    # every character that could end, escape or quote the answer, or start an entity, is a
    # character reference: " is &#34;, ' is &#39;, & is &#38;, < and > are &#60; and &#62;
    from scanconv.render.documents.moodle import _cloze_answer

    assert _cloze_answer("say \"E\" or 'NE' <b>&") == (
        "say &#34;E&#34; or &#39;NE&#39; &#60;b&#62;&#38;"
    )


@pytest.mark.parametrize(
    ("text", "gift"),
    [
        ("a\tb", "a b"),  # a tab is a space
        ("a\r\nb", "a\\nb"),  # a Windows line break is one line break, written \n
        ("a\nb", "a\\nb"),
        ("<b> & x=1 {y} ~z #w: \\", "&lt;b&gt; &amp; x\\=1 \\{y\\} \\~z \\#w\\: \\\\"),
    ],
)
def test_gift_text_by_hand(text: str, gift: str) -> None:
    from scanconv.render.documents.gift import gift_text

    assert gift_text(text) == gift


@pytest.mark.parametrize(
    ("text", "html"),
    [
        ("a\x01b", "a\ufffdb"),  # a character XML cannot hold
        ("{1:NUMERICAL:=5}", "&#123;1:NUMERICAL:=5&#125;"),  # no blank can be smuggled in
        ("<i>&'\"", "&lt;i&gt;&amp;&#x27;&quot;"),
    ],
)
def test_moodle_text_by_hand(text: str, html: str) -> None:
    assert moodle_text(text) == html


def test_a_cloze_answer_shows_unsafe_characters_as_replacement() -> None:
    from scanconv.render.documents.moodle import _cloze_answer

    # a control character and a bidirectional override are U+FFFD, never written as they are
    assert _cloze_answer("a\x01b\u202ec") == "a\ufffdb\ufffdc"
