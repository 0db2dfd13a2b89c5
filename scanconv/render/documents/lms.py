"""A sheet as quiz questions for a learning-management system: what :mod:`.moodle` (Moodle
XML, Cloze questions) and :mod:`.gift` (GIFT) write.

Each question of the sheet becomes one :class:`QuizQuestion`: its wording, the given values and
the answer's tables with every answer cell a :class:`Gap` (a blank the LMS marks), and the
worked answer (the ``plain`` key) as the general feedback. Which cells are gaps (see
docs/lms.md):

* the step table (every column of it, even when the text formats show it split into regions,
  as the ellipse's) and each secondary table (the symmetry table, a clipping's parameters, ...);
  a secondary table the step table is split into (headed by ``k`` when the text formats leave
  the step table out) is not asked twice;
* in a table, the columns that number or name the rows or that the question gives (their
  role is ``label`` or ``given``: the step ``k``, a level, a unit, a point's name) are shown,
  as a worksheet shows them, and so is the first column of any secondary table (it names
  the row: an edge, a method);
* a number is a numerical gap (:func:`number_gap`: exact when it has at most 3 decimals, else
  within :data:`TOLERANCE`); a pixel or point is a gap per coordinate; a decision (a move) is a
  short-answer gap taking its compass letters or words (:data:`MOVE_WORDS`); a text cell that
  is a number (``"2073.6"``, ``"16/3"``, ``"~0.05722"``) or a point is a gap as the number or
  point is, a one-word text cell (``"inside"``, ``"leaving"``) a short-answer gap; other text
  (a sentence of working) and empty cells are shown as they are.

A question with no table, a theory question, or one of more than :data:`MAX_GAPS` gaps is an
essay question with the key as its feedback (the last with a notice).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator, Sequence
from decimal import Decimal
from fractions import Fraction
from typing import Any, NamedTuple

from ...core.records import Column, Move, Solution, step_getter
from ...document import Document, Given, StepTable, Table, Working, as_document
from .. import Format, Notice, render
from .sheet import Answered, Sheet, _Guard, wording

TOLERANCE = "0.0005"
"""The tolerance of a number gap whose value has more than 3 decimals: any answer within it of
the value is right, so the 3-decimal rounding the key's tables print is."""

CENTRE_PLACES = 6
"""The decimals such a gap's value is written with (the 3-decimal rounding is within
:data:`TOLERANCE` of it; see :func:`number_gap`)."""

MAX_GAPS = 400
"""The most gaps one quiz question holds; a larger answer becomes an essay question."""

MOVE_WORDS = {
    "E": ("east",),
    "NE": ("north-east", "northeast", "north east"),
    "N": ("north",),
    "NW": ("north-west", "northwest", "north west"),
    "W": ("west",),
    "SW": ("south-west", "southwest", "south west"),
    "S": ("south",),
    "SE": ("south-east", "southeast", "south east"),
}
"""The spellings a decision gap takes besides the move's letters (the LMS compares them
without regard to case)."""


class Gap(NamedTuple):
    """A blank the LMS marks."""

    kind: str
    """``"number"`` or ``"word"``."""
    answers: tuple[str, ...]
    """A number gap: its value as a decimal (one); a word gap: every accepted spelling."""
    tolerance: str = "0"
    """A number gap's tolerance, a decimal (``"0"``: exact)."""
    label: str = ""
    """What the gap asks for, in words (``row k = 2, p_k``): GIFT's one question per gap."""


Piece = str | Gap
"""A table cell is a run of pieces: shown text and gaps (``(``, gap, ``, ``, gap, ``)``)."""


class GapTable(NamedTuple):
    """A table of the answer with its answer cells as gaps."""

    title: str
    headings: tuple[str, ...]
    rows: tuple[tuple[tuple[Piece, ...], ...], ...]


class QuizQuestion(NamedTuple):
    """One question of the quiz."""

    name: str
    """The question's name in the question bank (plain text)."""
    wording: str
    """The question in words."""
    given: tuple[str, ...]
    """The given values, as text."""
    tables: tuple[GapTable, ...]
    """The tables to fill in; empty: an essay question."""
    feedback: str
    """The worked answer (the plain key) and the command line that computes it."""
    marks: int | None
    working: tuple[str, ...] = ()
    """The command line and the working alone (the derived values with the numbers
    substituted, as text): with a row of a table filled in, the feedback of one blank
    (GIFT, which asks each blank on its own)."""


# --- numbers ------------------------------------------------------------------------------------


def decimal_text(value: Fraction | int) -> str | None:
    """``value`` as a decimal with at most 3 decimals, or ``None`` when it needs more.

    >>> decimal_text(Fraction(-63, 4)), decimal_text(Fraction(1, 256)), decimal_text(7)
    ('-15.75', None, '7')
    """
    scaled = Fraction(value) * 1000
    if scaled.denominator != 1:
        return None
    return _fixed(scaled.numerator, 3)


def _fixed(n: int, places: int) -> str:
    """The integer ``n`` scaled by ``10**-places``, in fixed notation without trailing zeros
    (exact at any size: no decimal context).

    >>> _fixed(-1500, 3), _fixed(7, 6), _fixed(0, 6), _fixed(10**40, 3)[:5]
    ('-1.5', '0.000007', '0', '10000')
    """
    whole, part = divmod(abs(n), 10**places)
    digits = f"{part:0{places}d}".rstrip("0")
    text = f"{whole}.{digits}" if digits else str(whole)
    return f"-{text}" if n < 0 else text


def _plain(d: Decimal) -> str:
    """A decimal in fixed notation, no exponent and no trailing zeros (GIFT's parser reads
    digits only)."""
    text = f"{d:f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def number_gap(value: Fraction | int | float, label: str = "") -> Gap:
    """The gap of a number: its exact decimal with tolerance 0 when it has at most 3 decimals;
    otherwise the value to :data:`CENTRE_PLACES` decimals with tolerance :data:`TOLERANCE`,
    which takes the 3-decimal rounding a table prints (a multiple of 0.001 within 0.0005 of
    the value is within 0.0005 of its 6-decimal rounding too) and the value to more decimals.

    >>> number_gap(-8), number_gap(Fraction(3, 7))[:3], number_gap(Fraction(1, 16))[:3]
    (Gap(kind='number', answers=('-8',), tolerance='0', label=''), ('number', ('0.428571',), '0.0005'), ('number', ('0.0625',), '0.0005'))
    """
    exact = Fraction(repr(value)) if isinstance(value, float) else Fraction(value)
    text = decimal_text(exact)
    if text is not None:
        return Gap("number", (text,), "0", label)
    scaled = abs(exact) * 10**CENTRE_PLACES
    rounded = (scaled + Fraction(1, 2)).__floor__()  # half up, away from zero
    return Gap(
        "number", (_fixed(-rounded if exact < 0 else rounded, CENTRE_PLACES),), TOLERANCE, label
    )


_NUMBER = re.compile(r"^(~?)(-?\d+(?:\.\d+)?|-?\d+/\d+)$")
_POINT = re.compile(r"^\((-?[\d./]+), (-?[\d./]+)\)$")
_WORD = re.compile(r"^[A-Za-z][A-Za-z-]{0,15}$")
_CODE = re.compile(r"^-?0\d")
"""The start of a binary code (``010``, ``0010``): digits, but not a number."""


def _text_pieces(text: str, label: str) -> tuple[Piece, ...]:
    """A text cell: a number, a point or one word as gaps; anything else shown."""
    s = text.strip()
    number = _NUMBER.match(s)
    if number and not _CODE.match(number.group(2)):  # "010" is a code, not ten
        about, digits = number.groups()
        if about:  # "~0.05722": within half a unit of its last digit
            places = len(digits.partition(".")[2])
            half = _plain(Decimal(5).scaleb(-places - 1))
            return (Gap("number", (_plain(Decimal(digits)),), half, label),)
        return (number_gap(Fraction(digits), label),)
    point = _POINT.match(s)
    if point and all(_NUMBER.match(v) for v in point.groups()):
        return _point(tuple(Fraction(v) for v in point.groups()), label)
    if _WORD.match(s) or re.match(r"^-?0\d+$", s):
        return (Gap("word", (s,), "0", label),)
    return (text,)


def _point(values: Sequence[Any], label: str) -> tuple[Piece, ...]:
    names = ("x", "y", "z") if len(values) <= 3 else tuple(str(i + 1) for i in range(len(values)))
    out: list[Piece] = ["("]
    for i, v in enumerate(values):
        out.extend((", ",) if i else ())
        out.extend(cell_pieces(v, f"{label}, {names[i]}"))
    out.append(")")
    return tuple(out)


def cell_pieces(value: Any, label: str = "") -> tuple[Piece, ...]:
    """A table cell as shown text and gaps (the rules of the module docstring).

    >>> [p if isinstance(p, str) else p.answers for p in cell_pieces((3, Fraction(1, 2)))]
    ['(', ('3',), ', ', ('0.5',), ')']
    >>> cell_pieces(Move.NE)[0].answers[:2], cell_pieces(None), cell_pieces("two words")
    (('NE', 'north-east'), ('–',), ('two words',))
    """
    if isinstance(value, Move):
        return (Gap("word", (value.value, *MOVE_WORDS[value.value]), "0", label),)
    if value is None:
        return ("–",)
    if isinstance(value, bool):
        return ("yes" if value else "no",)
    if isinstance(value, (int, Fraction)) or (
        isinstance(value, float) and value == value and abs(value) != float("inf")
    ):
        return (number_gap(value, label),)
    if isinstance(value, (tuple, list)) and value:
        return _point(value, label)
    if isinstance(value, str):
        return _text_pieces(value, label)
    return (str(value),)


# --- tables -------------------------------------------------------------------------------------


class _TooMany(Exception):
    """More gaps than a question holds."""


def _gap_table(
    title: str,
    columns: Sequence[Column],
    rows: Iterable[Sequence[Any]],
    labelled: bool,
    room: list[int],
) -> GapTable:
    """A table with its answer cells as gaps, read from each column's role
    (:data:`scanconv.core.records.ROLES`): ``label`` and ``given`` columns shown (and the
    first column when ``labelled``), ``working`` columns left out (shown beside a blank they
    would give it away: the feedback holds them), ``answer`` columns as gaps, every number of a text answer a gap of its own
    (:func:`answer_pieces`). ``room[0]`` is how many more gaps may be made (:class:`_TooMany`
    past it)."""
    kept = [j for j, c in enumerate(columns) if c.role != "working"]
    shown = {
        j for j, c in enumerate(columns) if c.role in ("label", "given") or (j == 0 and labelled)
    }
    out = []
    for row in rows:
        head = str(row[0]) if row else ""
        cells: list[tuple[Piece, ...]] = []
        for j in kept:
            column, value = columns[j], row[j]
            if j in shown:
                cells.append((shown_text(value),))
                continue
            pieces = answer_pieces(value, f"{title}, {columns[0].text} = {head}, {column.text}")
            room[0] -= sum(isinstance(p, Gap) for p in pieces)
            if room[0] < 0:
                raise _TooMany
            cells.append(pieces)
        out.append(tuple(cells))
    return GapTable(title, tuple(columns[j].text for j in kept), tuple(out))


def shown_text(value: Any) -> str:
    """A shown cell (a label or a given value) as the key's tables write it.

    >>> shown_text((7, Fraction(1, 2))), shown_text("P1"), shown_text(None)
    ('(7, 0.5)', 'P1', '–')
    """
    return "".join(p if isinstance(p, str) else p.answers[0] for p in cell_pieces(value))


_NUMBER_IN_TEXT = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?(?:/\d+)?(?![\w.])")
"""A number standing alone in a text answer (not part of a name such as ``P1`` or ``x2``)."""


def answer_pieces(value: Any, label: str = "") -> tuple[Piece, ...]:
    """An answer cell as gaps: :func:`cell_pieces`, and a text answer that is not one number,
    point or word (``[1, 5) [5, 9)``, ``1..4, 6..8``) with each of its numbers a gap and the
    rest shown, so that no answer is shown beside the blanks.

    >>> [p if isinstance(p, str) else p.answers[0] for p in answer_pieces("[1, 5) [5, 9)")]
    ['[', '1', ', ', '5', ') [', '5', ', ', '9', ')']
    >>> answer_pieces("inside (boundary)")[0].answers
    ('inside (boundary)', 'inside')
    """
    pieces = cell_pieces(value, label)
    if len(pieces) != 1 or not isinstance(pieces[0], str) or not isinstance(value, str):
        return pieces
    words = re.findall(r"[A-Za-z][A-Za-z-]*", value)
    if words and not _NUMBER_IN_TEXT.search(value):  # an answer in words: the text or its word
        return (Gap("word", tuple(dict.fromkeys((value.strip(), words[0]))), "0", label),)
    out: list[Piece] = []
    at = 0
    for m in _NUMBER_IN_TEXT.finditer(value):
        if _CODE.match(m.group()):  # "0010" is a code: a word
            continue
        out.extend((value[at : m.start()],) if m.start() > at else ())
        out.append(number_gap(Fraction(m.group()), label))
        at = m.end()
    if not out:
        return pieces
    out.extend((value[at:],) if at < len(value) else ())
    return tuple(out)


def gap_tables(
    answer: Solution | Document, limit: int = MAX_GAPS, asks: Sequence[str] = ()
) -> tuple[GapTable, ...] | None:
    """The answer's tables (its document's :class:`~scanconv.document.StepTable` and
    :class:`~scanconv.document.Table` blocks) with their answer cells as gaps (the module
    docstring's rules); ``None`` when they would hold more than ``limit`` gaps (found out
    without building more). ``asks``: what the quiz asks beyond the exam's question
    (``symmetry``: the tables whose columns are all working, :func:`symmetry_table`)."""
    doc = as_document(answer)
    room = [limit]
    tables = []
    step: StepTable | None = doc.get(StepTable)
    try:
        if step is not None and step.columns:
            get = step_getter(step.columns, step.extra_keys)
            rows = (get(s) for s in step.steps())
            tables.append(_gap_table("Step table", step.columns, rows, False, room))
        for table in doc.every(Table):
            split = step is not None and not step.shown
            if split and table.columns and table.columns[0].key == "k":
                continue  # the step table, split (the ellipse's regions): asked once
            if all(c.role == "working" for c in table.columns):
                if "symmetry" in asks and table.columns:
                    tables.append(symmetry_table(table.title, table.columns, table.rows(), room))
                continue  # all of it follows from the answers asked (a symmetry table)
            tables.append(_gap_table(table.title, table.columns, table.rows(), True, room))
    except _TooMany:
        return None
    return tuple(tables)


ROW_COLUMN = Column("row", "row", "\\text{row}", role="label")
"""The column that numbers the rows of a symmetry table asked in a quiz."""


def symmetry_table(
    title: str, columns: Sequence[Column], rows: Iterable[Sequence[Any]], room: list[int]
) -> GapTable:
    """A table whose columns are all working (a circle's 8-way, an ellipse's 4-way symmetry:
    each octant point and its mirror images) asked all the same, when the quiz asks for more
    than the exam (``quiz: symmetry``): every cell a blank, the octant's point too (shown,
    it would answer the step table's pixel), each row named by its number alone."""
    asked = [ROW_COLUMN, *(c._replace(role="answer") for c in columns)]
    numbered = ((n, *row) for n, row in enumerate(rows, 1))
    return _gap_table(title, asked, numbered, True, room)


def gaps(tables: Iterable[GapTable]) -> Iterator[Gap]:
    """Every gap of ``tables``, row by row."""
    for table in tables:
        for row in table.rows:
            for cell in row:
                yield from (p for p in cell if isinstance(p, Gap))


# --- questions ----------------------------------------------------------------------------------


def quiz(
    sheet: Sheet, answered: Sequence[Answered], write: Callable[[Sequence[QuizQuestion]], str]
) -> Iterator[str | Notice]:
    """The sheet as a quiz file written by ``write`` (:func:`scanconv.render.documents.moodle.moodle_xml`
    or :func:`scanconv.render.documents.gift.gift`), then the notices: what the ``moodle`` and ``gift``
    document writers share (a key and a worksheet are the same quiz: the LMS holds the
    answers and shows them after the attempt)."""
    notices: list[str] = []
    questions = quiz_questions(sheet, answered, notices)
    yield write(questions)
    yield from (Notice(n) for n in notices)


def quiz_questions(
    sheet: Sheet, answered: Sequence[Answered], notices: list[str] | None = None
) -> list[QuizQuestion]:
    """The quiz questions of ``sheet`` with its ``answered`` questions. Notices (an answer
    too large for gaps, a grid left out of the feedback) are added to ``notices``; a
    ``ValueError`` while an answer is worked out names the question's line."""
    out = []
    for a in answered:
        with _Guard(sheet, a.question):
            out.append(_quiz_question(sheet.title, a, notices))
    return out


def _quiz_question(title: str, a: Answered, notices: list[str] | None) -> QuizQuestion:
    """One quiz question, from the answer's document: its title, Given and Working blocks,
    its tables (:func:`gap_tables`) and the ``plain`` mapping's key as the feedback."""
    q = a.question
    doc = as_document(a.solution)
    key: list[str] = []
    for chunk in render(doc, Format("plain"), a.options):
        if isinstance(chunk, Notice):
            if notices is not None:
                notices.append(f"question {q.number}: {chunk.message}")
        else:
            key.append(chunk)
    tables: tuple[GapTable, ...] | None = ()
    if doc.primitive != "theory":
        tables = gap_tables(doc, MAX_GAPS, q.quiz)
    if tables is None:
        if notices is not None:
            notices.append(
                f"question {q.number}: more than {MAX_GAPS} blanks, more than a quiz "
                "question holds: an essay question with the key as its feedback"
            )
        tables = ()
    if not any(True for _ in gaps(tables)):
        tables = ()
    name = f"Q{q.number} {doc.title}"
    if title:
        name = f"{' '.join(title.split())}: {name}"
    given: Given | None = doc.get(Given)
    working: Working | None = doc.get(Working)
    return QuizQuestion(
        name=name[:250],
        wording=wording(a),
        given=tuple(g.text for g in given.quantities) if given is not None else (),
        tables=tables,
        feedback=f"$ {q.command}\n\n" + "".join(key).rstrip("\n") + "\n",
        marks=q.marks,
        working=(f"$ {q.command}", *(d.text for d in (working.lines if working else ()))),
    )


INSTRUCTIONS = (
    "Fill in every blank. Numbers as decimals (a value that is not exact to 3 decimals: "
    "to 3 decimals or more); a decision as its compass letters (E, NE, N, ...); "
    "a pixel's x and y each in its own blank."
)
"""The line under every quiz question with blanks."""
