r"""GIFT: a sheet as a quiz file in Moodle's GIFT text format (Question bank, Import, GIFT).

GIFT holds one answer per question, so a question of the sheet with tables becomes one GIFT
question per blank (:mod:`.lms` says which cells are blanks), named ``Q1.3 ...`` and asking
for that cell (the question's wording, the given values and the cell's place in its table):
a number as ``{#value:tolerance}`` (tolerance 0 when it has at most 3 decimals, else 0.0005),
a decision or a word as a short answer ``{=NE =north-east ...}`` (case-insensitive). The
worked answer is every such question's general feedback (``####``). A question with no
table is an essay question ``{####key}``.

Texts are HTML (``[html]``); every text from the question file and every value goes through
:func:`gift_text`, the one escaper of the format: HTML-escaped, then GIFT's special
characters ``\ ~ = # { } :`` backslash-escaped and a line break written ``\n`` (a blank line
would end the question).

>>> gift_text("a: {b} ~ =c #d <e>")
'a\\: \\{b\\} \\~ \\=c \\#d &lt;e&gt;'
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from ...core.working import visible
from ..html.mathml import esc
from .lms import Gap, GapTable, Piece, QuizQuestion, quiz

if TYPE_CHECKING:
    from .. import Notice
    from .sheet import Answered, Sheet

HINTS = {
    "number": "A decimal (to 3 decimals or more where it is not exact).",
    "word": "A word (a decision: the move's compass letters, E, NE, N, ...).",
}
"""What each blank asks for, under its question."""

_SPECIAL = re.compile(r"([\\~=#{}:])")


def gift_plain(text: str) -> str:
    r"""Plain text (a question's name, a short answer) on one line, control characters and
    bidirectional overrides shown as U+FFFD, GIFT's special characters escaped.

    >>> gift_plain("Q1: a::b")
    'Q1\\: a\\:\\:b'
    """
    one_line = " ".join(visible(text).split())
    return _SPECIAL.sub(r"\\\1", one_line)


def gift_text(text: str) -> str:
    """User text as GIFT's HTML text: the one escaper of this format."""
    escaped = _SPECIAL.sub(r"\\\1", esc(text.replace("\r\n", "\n").replace("\t", " ")))
    return escaped.replace("\n", "\\n")


def _answer(gap: Gap) -> str:
    """A blank's answers: a short answer is compared with what the student types, so it is
    plain text (GIFT-escaped, not HTML)."""
    if gap.kind == "number":
        return f"#{gap.answers[0]}:{gap.tolerance}"
    return " ".join("=" + gift_plain(a) for a in gap.answers)


def _shown(pieces: Sequence[Piece], asked: Gap) -> str:
    """A cell as the question shows it: the blank asked for as ``?``, others as ``_``."""
    return "".join(("?" if p is asked else "_") if isinstance(p, Gap) else p for p in pieces)


def _filled(pieces: Sequence[Piece]) -> str:
    """A cell with its blanks filled in (the key's value)."""
    return "".join(p.answers[0] if isinstance(p, Gap) else p for p in pieces)


def _rows(table: GapTable) -> Iterator[tuple[Gap, str, str]]:
    """Each gap of ``table`` with its row as ``heading = cell`` pairs, asked (the gap a
    ``?``, the others ``_``) and answered (every cell filled in)."""
    for row in table.rows:
        filled = ", ".join(f"{h} = {_filled(c)}" for h, c in zip(table.headings, row, strict=True))
        for cell in row:
            for gap in (p for p in cell if isinstance(p, Gap)):
                shown = (
                    f"{h} = {_shown(c, gap)}" for h, c in zip(table.headings, row, strict=True)
                )
                yield gap, f"{table.title}: {', '.join(shown)}", f"{table.title}: {filled}"


def _stem(q: QuizQuestion) -> str:
    parts = [f"<p>{gift_text(q.wording)}</p>"]
    if q.given:
        given = gift_text(", ".join(q.given))
        parts.append(f"<p><strong>{gift_text('Given:')}</strong> {given}</p>")
    return "".join(parts)


def _blank_questions(q: QuizQuestion) -> Iterator[str]:
    """One question per blank; its feedback the derivation and the row filled in (the whole
    key on each of a question's many blanks would make the file hundreds of times larger)."""
    stem = _stem(q)
    working = "\n".join(q.working)
    i = 0
    for table in q.tables:
        for gap, asked, answered in _rows(table):
            i += 1
            name = gift_plain(f"{q.name} [{i}] {gap.label}"[:250])
            ask = gift_text(f"What is {gap.label.rpartition(', ')[2]} (the ?)?")
            feedback = f"<pre>{gift_text(working + chr(10) * 2 + answered)}</pre>"
            yield (
                f"::{name}::[html]{stem}<p>{gift_text(asked)}</p><p>{ask}</p>"
                f"<p><em>{gift_text(HINTS[gap.kind])}</em></p>"
                f"{{{_answer(gap)}\n####[html]{feedback}}}\n\n"
            )


def gift(questions: Sequence[QuizQuestion]) -> str:
    """The quiz file: every question, in order, separated by blank lines."""
    out = ["// scanconv quiz (GIFT): import with Question bank, Import, GIFT format\n\n"]
    for q in questions:
        if q.tables:
            out.extend(_blank_questions(q))
        else:
            feedback = f"<pre>{gift_text(q.feedback)}</pre>"
            out.append(f"::{gift_plain(q.name)}::[html]{_stem(q)}{{\n####[html]{feedback}}}\n\n")
    return "".join(out)


def gift_sheet(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str | Notice]:
    """The ``gift`` document writer (:data:`scanconv.render.FORMATS`): the sheet as a GIFT
    quiz (a key and a worksheet are the same quiz)."""
    return quiz(sheet, answered, gift)
