"""Moodle XML: a sheet as a quiz file for Moodle's question bank (Import, Moodle XML format).

Each question is a ``cloze`` (Embedded answers) question: its wording, the given values and
the answer's tables as an HTML table whose answer cells are blanks that stock Moodle marks
(:mod:`.lms` says which): ``{1:NUMERICAL:=-8:0}`` for a number (tolerance 0 when it has at most
3 decimals, else 0.0005), ``{1:SHORTANSWER:=NE~=north-east~...}`` for a decision or a word
(case-insensitive; an answer's special characters as character references, :func:`_cloze_answer`). The worked answer is the general feedback. A question with no table is an
``essay`` question with the key as its feedback and the grader's information.

Every text from the question file and every value goes through :func:`moodle_text`, the one
escaper of the format: HTML-escaped, ``{`` and ``}`` as character references (so that no user
text is read as a blank), characters XML forbids shown as U+FFFD. HTML goes into the XML as
CDATA, a ``]]>`` in it split (:func:`cdata`).

>>> from scanconv.render.documents.lms import Gap
>>> cloze(Gap("number", ("-8",), "0"))
'{1:NUMERICAL:=-8:0}'
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from ...core.working import UNSAFE
from .. import Notice
from ..html.mathml import esc
from .lms import INSTRUCTIONS, Gap, GapTable, Piece, QuizQuestion, gaps, quiz

if TYPE_CHECKING:
    from .sheet import Answered, Sheet

_XML_ILLEGAL = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def moodle_text(text: str) -> str:
    """User text as Moodle's question HTML: the one escaper of this format.

    >>> moodle_text("a {1:NUMERICAL:=5} <b> & ]]>")
    'a &#123;1:NUMERICAL:=5&#125; &lt;b&gt; &amp; ]]&gt;'
    """
    text = esc(_XML_ILLEGAL.sub("\ufffd", text))
    return text.replace("{", "&#123;").replace("}", "&#125;")


def cdata(html: str) -> str:
    """``html`` as XML CDATA, a ``]]>`` in it split across two sections.

    >>> cdata("a]]>b")
    '<![CDATA[a]]]]><![CDATA[>b]]>'
    """
    return "<![CDATA[" + html.replace("]]>", "]]]]><![CDATA[>") + "]]>"


_CLOZE_SPECIAL = re.compile(r"""[&<>"'{}~#\\]""")


def _cloze_answer(text: str) -> str:
    r"""An answer inside a blank, as Moodle's Cloze parser reads it back: an answer ends at a
    ``~``, ``#`` or ``}`` not preceded by ``\``, ``&`` or ``&amp;``, and is then
    HTML-entity-decoded (with only ``\}`` and ``\#`` unescaped). So every character that
    could end it, escape it or start an entity is written as a character reference, which
    ends in ``;`` and holds no terminator: the answer is read back as it was (but for a
    backslash before ``#`` or ``}``, which Moodle drops; no answer scanconv writes holds a
    backslash).

    >>> _cloze_answer('a}b~c#d&e\\f')
    'a&#125;b&#126;c&#35;d&#38;e&#92;f'
    """
    clean = UNSAFE.sub("\ufffd", _XML_ILLEGAL.sub("\ufffd", text))
    return _CLOZE_SPECIAL.sub(lambda m: f"&#{ord(m.group())};", clean)


def cloze(gap: Gap, weight: int = 1) -> str:
    """A blank in Moodle's Cloze syntax, of ``weight`` marks.

    >>> cloze(Gap("number", ("2.5",), "0"), 3)
    '{3:NUMERICAL:=2.5:0}'
    """
    if gap.kind == "number":
        return f"{{{weight}:NUMERICAL:={gap.answers[0]}:{gap.tolerance}}}"
    answers = "~".join("=" + _cloze_answer(a) for a in gap.answers)
    return f"{{{weight}:SHORTANSWER:{answers}}}"


def weights(blanks: int, marks: int | None) -> list[int]:
    """Each blank's weight, so that the blanks share the question's marks: Moodle scores a
    Cloze question out of the sum of its blanks' weights (its XML import reads no
    ``defaultgrade`` for one), so ``marks`` reach it when there are at least as many marks as
    blanks (the remainder to the first blanks); with more blanks than marks (or no marks),
    every blank weighs 1 and the quiz's maximum mark for the question is set in Moodle
    (:func:`marks_notice` says so).

    >>> weights(3, 7), weights(4, 2), weights(2, None)
    ([3, 2, 2], [1, 1, 1, 1], [1, 1])
    """
    if not _carried(blanks, marks):
        return [1] * blanks
    assert marks is not None
    base, extra = divmod(marks, blanks)
    return [base + (i < extra) for i in range(blanks)]


def _carried(blanks: int, marks: int | None) -> bool:
    """Whether the blanks' weights can sum to the question's marks (at least one mark a
    blank)."""
    return marks is not None and 0 < blanks <= marks


def _blanks(q: QuizQuestion) -> int:
    return sum(1 for _ in gaps(q.tables))


def marks_notice(q: QuizQuestion) -> str | None:
    """What a teacher sets by hand: a question of fewer marks than blanks.

    >>> from scanconv.render.documents.lms import GapTable
    >>> t = GapTable("t", ("a",), (((Gap("number", ("1",)),), (Gap("number", ("2",)),)),))
    >>> marks_notice(QuizQuestion("Q1 line", "w", (), (t,), "", 1))
    'Q1 (line) to 1 (it has 2 blanks)'
    >>> marks_notice(QuizQuestion("Q3 2D transformation: rotate by 90 degrees about (2, 1)",
    ...                           "w", (), (t,), "", 1))
    'Q3 (2D transformation: rotate by 90 degrees about ...) to 1 (it has 2 blanks)'
    """
    blanks = _blanks(q)
    if q.marks is None or not blanks or _carried(blanks, q.marks):
        return None
    number, _, title = q.name.partition(" ")
    return f"{number} ({_shortened(title)}) to {q.marks} (it has {blanks} blanks)"


def _shortened(title: str, most: int = 48) -> str:
    """A question's title in a notice: whole, or cut at a word (never inside one) with "...",
    so that it never reads as other words ("rotate by 9" for "rotate by 90")."""
    if len(title) <= most:
        return title
    cut = title[: most + 1].rsplit(" ", 1)[0] if " " in title[:most] else title[:most]
    return cut.rstrip(" ,;:") + " ..."


def _cell(pieces: Sequence[Piece], weight: Iterator[int]) -> str:
    return "".join(cloze(p, next(weight)) if isinstance(p, Gap) else moodle_text(p) for p in pieces)


def _table(table: GapTable, weight: Iterator[int]) -> Iterator[str]:
    yield f"<p><strong>{moodle_text(table.title)}</strong></p>\n"
    yield '<table border="1" cellpadding="4" style="border-collapse:collapse">\n<thead><tr>'
    yield "".join(f"<th>{moodle_text(h)}</th>" for h in table.headings)
    yield "</tr></thead>\n<tbody>\n"
    for row in table.rows:
        yield "<tr>" + "".join(f"<td>{_cell(c, weight)}</td>" for c in row) + "</tr>\n"
    yield "</tbody>\n</table>\n"


def question_html(q: QuizQuestion) -> str:
    """A question's text: wording, given values, instructions and the tables with blanks,
    each blank weighted so that they share the question's marks (:func:`weights`)."""
    parts = [f"<p>{moodle_text(q.wording)}</p>\n"]
    if q.given:
        given = ", ".join(moodle_text(g) for g in q.given)
        parts.append(f"<p><strong>Given:</strong> {given}</p>\n")
    if q.tables:
        parts.append(f"<p><em>{moodle_text(INSTRUCTIONS)}</em></p>\n")
    weight = iter(weights(_blanks(q), q.marks))
    for table in q.tables:
        parts.extend(_table(table, weight))
    return "".join(parts)


def feedback_html(q: QuizQuestion) -> str:
    """The worked answer as HTML: the plain key, preformatted."""
    return f"<pre>{moodle_text(q.feedback)}</pre>"


def _text(tag: str, html: str, attrs: str = ' format="html"') -> str:
    return f"    <{tag}{attrs}>\n      <text>{cdata(html)}</text>\n    </{tag}>\n"


def _question(q: QuizQuestion) -> str:
    kind = "cloze" if q.tables else "essay"
    name = moodle_text(q.name)  # plain text, escaped for XML
    parts = [
        f'  <question type="{kind}">\n',
        f"    <name>\n      <text>{name}</text>\n    </name>\n",
        _text("questiontext", question_html(q)),
        _text("generalfeedback", feedback_html(q)),
    ]
    if kind == "essay" or q.marks is not None:  # a Cloze question's marks: its blanks' weights
        parts.append(f"    <defaultgrade>{q.marks if q.marks is not None else 1}</defaultgrade>\n")
    parts.append("    <penalty>0.3333333</penalty>\n    <hidden>0</hidden>\n")
    parts.append("    <idnumber></idnumber>\n")
    if kind == "essay":
        parts.append(
            "    <responseformat>editor</responseformat>\n"
            "    <responserequired>1</responserequired>\n"
            "    <responsefieldlines>15</responsefieldlines>\n"
            "    <attachments>0</attachments>\n"
            "    <attachmentsrequired>0</attachmentsrequired>\n"
        )
        parts.append(_text("graderinfo", feedback_html(q)))
        parts.append('    <responsetemplate format="html">\n      <text></text>\n')
        parts.append("    </responsetemplate>\n")
    parts.append("  </question>\n")
    return "".join(parts)


def moodle_xml(questions: Sequence[QuizQuestion]) -> str:
    """The quiz file: every question, in order."""
    head = '<?xml version="1.0" encoding="UTF-8"?>\n<quiz>\n'
    return head + "".join(_question(q) for q in questions) + "</quiz>\n"


def moodle_sheet(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str | Notice]:
    """The ``moodle`` document writer (:data:`scanconv.render.FORMATS`): the sheet as a
    Moodle XML quiz (a key and a worksheet are the same quiz), then a notice for each question
    whose marks Moodle cannot carry (:func:`marks_notice`)."""
    questions: list[QuizQuestion] = []

    def write(qs: Sequence[QuizQuestion]) -> str:
        questions.extend(qs)
        return moodle_xml(qs)

    yield from quiz(sheet, answered, write)
    by_hand = [m for m in map(marks_notice, questions) if m is not None]
    if by_hand:
        yield Notice(
            "Moodle scores a Cloze question out of its blanks' weights: set the maximum mark "
            "in the quiz of " + "; ".join(by_hand)
        )
