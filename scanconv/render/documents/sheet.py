"""Sheets: many answers in one document, as an answer key or as a worksheet for students.

:func:`sheet_document` renders a whole sheet in memory (so nothing is written when a question
turns out bad) in any format whose :data:`scanconv.render.FORMATS` entry names a document
writer (its ``sheet``): ``markdown`` and ``plain`` and ``json`` here, ``latex`` (a fragment,
or a complete document with ``standalone``) in :mod:`scanconv.render.documents.sheet_latex`, ``html`` in
:mod:`scanconv.render.documents.sheet_html`, and the quiz files for an LMS, ``moodle`` (Moodle XML) and
``gift`` (:mod:`scanconv.render.documents.lms`). A sheet is a list of documents: a key is, for each
question, its answer's document headed by a :class:`~scanconv.document.Question` block (its
number, marks, wording and command line: :func:`key_document`), rendered by the format's own
mapping, as a single answer is. A worksheet is the question in words, the given values and,
for each table of the answer, an empty table with the answer's columns and number of rows (the
``k`` column, which only numbers the rows, filled in); nothing of the answer itself.

The records :class:`Question`, :class:`Sheet` and :class:`Answered` are what
:mod:`scanconv.cli.sheet` reads a question file into. Text from the question file (the title,
sections, wording, command lines) is escaped for every format.
"""

from __future__ import annotations

import json
import shlex
from collections.abc import Callable, Iterable, Iterator, Sequence
from itertools import chain
from typing import TYPE_CHECKING, Any, NamedTuple

from ...core import lazy
from ...core.records import Column, Quantity, Solution
from ...core.working import ascii_text, json_visible
from ...document import Contents, Document, Entry, Given, Title, as_document
from ...document import Question as QuestionBlock
from .. import FORMATS, Format, Notice, Options, formats, load, render
from ..cells import numeric_column
from ..mappings.text import MARKDOWN, PLAIN, all_tables, md_text, table_lines

if TYPE_CHECKING:
    from ..mappings import data
else:
    data = lazy.module("scanconv.render.mappings.data")  # the json sheet only


class Question(NamedTuple):
    """One question of a sheet."""

    number: int
    """1, 2, ...: the question's number on the sheet."""
    line: int
    """The line of the question file it is written on (1-based)."""
    argv: tuple[str, ...]
    """The command line, without ``scanconv``: ``("line", "2", "2", "10", "6")``."""
    marks: int | None = None
    """The marks it carries (``[4]``), or ``None``."""
    wording: str = ""
    """The question in words (the ``>`` lines before it), or ``""``: worded from the answer."""
    section: str = ""
    """The ``section:`` it is under, or ``""``."""
    quiz: tuple[str, ...] = ()
    """What its quiz asks beyond what the exam asks (a ``quiz:`` line before it in the
    question file, or the sheet's choice): ``("symmetry",)`` also asks the symmetry tables
    (docs/lms.md)."""

    @property
    def command(self) -> str:
        """The command line as a person types it (quoted where needed).

        >>> Question(1, 1, ("sample", "x + y", "--size", "4")).command
        "scanconv sample 'x + y' --size 4"
        """
        return shlex.join(("scanconv", *self.argv))


class Sheet(NamedTuple):
    """A parsed question file."""

    title: str
    questions: tuple[Question, ...]
    source: str = "QUESTIONS"
    """The file's name, for messages."""
    contents: bool = False
    """A table of contents above the questions (:func:`contents_block`; the exam book's)."""

    @property
    def total_marks(self) -> int | None:
        """The sum of the marks, if any question carries marks.

        >>> Sheet("", (Question(1, 1, ("x",), 4), Question(2, 2, ("y",)))).total_marks
        4
        """
        marks = [q.marks for q in self.questions if q.marks is not None]
        return sum(marks) if marks else None


class Answered(NamedTuple):
    """A question, its answer and how the answer is shown."""

    question: Question
    solution: Solution
    options: Options


KINDS = ("key", "worksheet")


CONTENTS_ALONE = {
    name: f"scanconv.render.{spec.mapping}" for name, spec in FORMATS.items() if spec.mapping
}
"""The formats that write a sheet's contents alone (and json), each by its mapping (read from
:data:`scanconv.render.FORMATS`, its ``mapping``)."""


def contents_document(sheet: Sheet, fmt: str) -> str:
    """The sheet's table of contents alone, nothing answered (``exam --contents``): in
    ``fmt``'s mapping of a :class:`~scanconv.document.Contents` block, or as JSON."""
    block = contents_block(sheet, linked=False)
    if fmt == "json":
        rows = [{"number": e.number, "section": e.section, "question": e.wording}
                for e in block.entries]  # fmt: skip
        text = json.dumps({"title": sheet.title, "contents": rows}, ensure_ascii=False, indent=1)
        return json_visible(text) + "\n"
    if fmt not in CONTENTS_ALONE:
        raise ValueError(
            f"the contents alone are not available in {fmt}: markdown, plain, latex or json"
        )
    return _contents_text(lazy.load(CONTENTS_ALONE[fmt]), block)


def sheet_document(
    sheet: Sheet,
    answered: Sequence[Answered],
    kind: str = "key",
    fmt: str = "markdown",
    *,
    standalone: bool = False,
    notices: list[str] | None = None,
) -> str:
    """The whole sheet as one string, in the document format ``fmt`` (its writer is its
    :data:`scanconv.render.FORMATS` entry's ``sheet``). A ``ValueError`` raised while an
    answer is worked out names the question's line (``SOURCE:LINE: ...``). Notices (a grid
    left out) are added to ``notices``, prefixed with the question's number.
    """
    if kind not in KINDS:
        raise ValueError(f"unknown sheet kind {kind!r}: key or worksheet")
    spec = FORMATS.get(fmt)
    if spec is None or not spec.sheet:
        raise ValueError(f"unknown sheet format {fmt!r}: one of {', '.join(formats('document'))}")
    writer: SheetWriter = load(spec.sheet)
    out: list[str] = []
    for chunk in writer(sheet, answered, kind, standalone):
        if isinstance(chunk, Notice):
            if notices is not None:
                notices.append(chunk.message)
        else:
            out.append(chunk)
    return "".join(out)


SheetWriter = Callable[[Sheet, Sequence[Answered], str, bool], Iterator["str | Notice"]]
"""A document format's writer (its :data:`scanconv.render.FORMATS` entry's ``sheet``):
``(sheet, answered, kind, standalone)`` to text chunks and notices."""


class _Guard:
    """Names the question whose answer failed while it was rendered."""

    def __init__(self, sheet: Sheet, question: Question) -> None:
        self.where = f"{sheet.source}:{question.line}"
        self.number = question.number

    def __enter__(self) -> _Guard:
        return self

    def __exit__(self, kind: object, err: BaseException | None, tb: object) -> None:
        if isinstance(err, ValueError) and not str(err).startswith(self.where):
            raise ValueError(f"{self.where}: {' '.join(str(err).split())}") from None


def question_block(
    a: Answered, level: int = 2, *, key: bool = True, listed: bool = False
) -> QuestionBlock:
    """The :class:`~scanconv.document.Question` block of ``a``: its number and marks and, on a
    key, its wording and command line (a worksheet words the question its own way);
    ``listed``: with its entry in the sheet's contents (:func:`entry_text`)."""
    q = a.question
    entry = entry_text(a) if listed else ""
    if not key:
        return QuestionBlock(q.number, q.marks, level=level, entry=entry)
    return QuestionBlock(q.number, q.marks, q.wording, q.command, level, entry)


def entry_text(a: Answered | Question) -> str:
    """A question's line in the contents: its wording on one line (an answered question
    without wording: as :func:`wording` words it; else its command line).

    >>> entry_text(Question(1, 1, ("line", "0", "0", "1", "1"), wording=" Draw   it. "))
    'Draw it.'
    """
    if isinstance(a, Answered):
        return " ".join(wording(a).split())
    return " ".join(a.wording.split()) or a.command


def contents_block(
    sheet: Sheet, answered: Sequence[Answered] | None = None, *, linked: bool = True
) -> Contents:
    """The sheet's table of contents: each question's number and :func:`entry_text`, under
    its section; ``linked``: above the questions, each entry leading to its question
    (``False``: the list alone)."""
    items: Sequence[Answered | Question] = answered if answered is not None else sheet.questions
    entries = []
    for item in items:
        q = item.question if isinstance(item, Answered) else item
        entries.append(Entry(q.number, entry_text(item), q.section))
    return Contents(tuple(entries), linked)


def contents_chunks(
    sheet: Sheet, answered: Sequence[Answered], mapping: dict[type, Callable[..., Iterator[Any]]]
) -> str:
    """The sheet's contents through a text format's ``mapping`` (``""`` without
    :attr:`Sheet.contents`)."""
    if not sheet.contents:
        return ""
    return _contents_text(mapping, contents_block(sheet, answered))


def _contents_text(mapping: dict[type, Callable[..., Iterator[Any]]], block: Contents) -> str:
    """``block`` through a text format's mapping (its handlers' third argument, the rest of
    the document, is not read for a Contents block)."""
    return "".join(c for c in mapping[Contents](block, Options(), []) if isinstance(c, str))


def key_document(a: Answered, level: int = 2, *, question: bool = True) -> Document:
    """The answer's document as a key shows it: its :class:`~scanconv.document.Question`
    block first (with ``question``) and its title one level under the question's."""
    doc = as_document(a.solution)
    blocks = tuple(b._replace(level=level + 1) if isinstance(b, Title) else b for b in doc.blocks)
    head = (question_block(a, level),) if question else ()
    return doc._replace(blocks=head + blocks)


def _answer_chunks(a: Answered, fmt: str, document: Document) -> Iterator[str | Notice]:
    """``document`` (a key's answer) through the mapping of ``fmt``, its notices naming the
    question."""
    for chunk in render(document, Format(fmt), a.options):
        if isinstance(chunk, Notice):
            yield Notice(f"question {a.question.number}: {chunk.message}", chunk.ways)
        else:
            yield chunk


def each_question(
    sheet: Sheet,
    answered: Sequence[Answered],
    section: Callable[[str], str],
    body: Callable[[Answered], Iterable[str | Notice]],
) -> Iterator[str | Notice]:
    """The questions in order: the ``section`` heading where a section starts, then each
    question's ``body``; an error in it names the question's line (:class:`_Guard`)."""
    current = ""
    for a in answered:
        q = a.question
        with _Guard(sheet, q):
            if q.section and q.section != current:
                current = q.section
                yield section(current)
            yield from body(a)


def _intro(sheet: Sheet, kind: str) -> str:
    """The line under the title: how many questions and marks.

    >>> _intro(Sheet("", (Question(1, 1, ("x",), 4),)), "key")
    'Answer key: 1 question, 4 marks.'
    """
    n = len(sheet.questions)
    total = sheet.total_marks
    what = "Answer key" if kind == "key" else "Worksheet"
    marks = "" if total is None else f", {total} mark{'' if total == 1 else 's'}"
    return f"{what}: {n} question{'' if n == 1 else 's'}{marks}."


def wording(a: Answered) -> str:
    """The question in words: the file's ``>`` wording, else the answer's title and what to
    do."""
    if a.question.wording:
        return a.question.wording
    tables = bool(_blank_tables(a.solution, count=False))
    todo = "Show your working and complete the table" if tables else "Show your working"
    title = as_document(a.solution).title.rstrip(".")
    return f"{title}. {todo}{'s' if len(_blank_tables(a.solution, False)) > 1 else ''}."


class Blank(NamedTuple):
    """An empty table of a worksheet: the answer's columns and its number of rows."""

    title: str
    columns: tuple[Column, ...]
    rows: int
    widths: tuple[int, ...]
    """The widest answer cell of each column, in characters (the space to leave)."""
    filled: tuple[tuple[str, ...], ...] = ()
    """Each row's cells a worksheet fills in, the others ``""``: every column whose role is
    ``label`` or ``given`` (:data:`scanconv.core.records.ROLES`: the step ``k``, de Casteljau's
    level ``r``, an image's row ``i``, a storage unit, a point's name and coordinates)."""
    sample: tuple[tuple[str, ...], ...] = ()
    """The first rows of the answer's table, to split a wide table as the key splits it
    (never shown)."""


def _blank_tables(solution: Solution, count: bool = True) -> list[Blank]:
    """The tables of the answer, emptied: title, columns, row count and cell widths."""
    out = []
    for title, columns, rows in all_tables(solution):
        n = 0
        widths = [len(c.text) for c in columns]
        filled: list[tuple[str, ...]] = []
        sample: list[tuple[str, ...]] = []
        shown = [c.role in ("label", "given") for c in columns]
        if count:
            for row in rows():
                n += 1
                widths = [max(w, len(c)) for w, c in zip(widths, row, strict=True)]
                if any(shown):
                    filled.append(tuple(c if s else "" for c, s in zip(row, shown, strict=True)))
                if n <= 100:
                    sample.append(tuple(row))
        out.append(
            Blank(
                title or "Step table",
                tuple(columns),
                n,
                tuple(widths),
                tuple(filled),
                tuple(sample),
            )
        )
    return out


def _blank_rows(blank: Blank) -> Iterator[list[str]]:
    """The rows of an empty table: the row labels and given values filled in
    (:attr:`Blank.filled`), the rest empty."""
    for i in range(blank.rows):
        yield list(blank.filled[i]) if blank.filled else [""] * len(blank.columns)


# --- markdown and plain -------------------------------------------------------------------------


def _levels(sheet: Sheet) -> tuple[int, int]:
    """The heading level of a section and of a question (questions under sections go one
    deeper)."""
    sections = any(q.section for q in sheet.questions)
    return 2, 3 if sections else 2


def _parts(blank: Blank) -> list[tuple[list[int], str]]:
    """The columns and the label of a Markdown worksheet table: whole, as the key's table is
    (:func:`scanconv.render.mappings.text._parts`) and as the PDF sets it."""
    return [(list(range(len(blank.columns))), blank.title)]


def markdown_sheet(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str | Notice]:
    """The sheet in Markdown: each question and its answer through the ``markdown`` mapping
    (the answer's title one level under the question's)."""
    section_level, level = _levels(sheet)
    if sheet.title:
        yield f"# {md_text(' '.join(sheet.title.split()))}\n\n{_intro(sheet, kind)}\n\n"
    yield contents_chunks(sheet, answered, MARKDOWN)

    def body(a: Answered) -> Iterator[str | Notice]:
        if kind == "key":
            return _answer_chunks(a, "markdown", key_document(a, level))
        head = MARKDOWN[QuestionBlock](question_block(a, level, key=False), a.options, [])
        return chain(head, _md_worksheet(a))

    yield from each_question(
        sheet, answered, lambda s: f"{'#' * section_level} {md_text(s)}\n\n", body
    )


def _md_worksheet(a: Answered) -> Iterator[str]:
    """A worksheet's question in Markdown: its wording, the given values, empty tables."""
    yield md_text(wording(a)) + "\n\n"
    if given_of(a):
        yield f"**Given:** {', '.join(f'${g.tex}$' for g in given_of(a))}\n\n"
    for blank in _blank_tables(a.solution):
        for part, label in _parts(blank):
            yield f"**{md_text(label)}:**\n\n"
            cells = (
                [r[i] or " " * max(3, blank.widths[i]) for i in part] for r in _blank_rows(blank)
            )
            for line in table_lines(
                [f"${blank.columns[i].tex}$" for i in part],
                [numeric_column(blank.columns[i]) for i in part],
                cells,
                markdown=True,
            ):
                yield line + "\n"
            yield "\n"
    if not _blank_tables(a.solution, count=False):
        yield "**Answer:**\n\n" + "&nbsp;\n\n" * 6


def given_of(a: Answered) -> tuple[Quantity, ...]:
    """The given values of the answer's :class:`~scanconv.document.Given` block (none: ``()``)."""
    given: Given | None = as_document(a.solution).get(Given)
    return given.quantities if given is not None else ()


def plain_sheet(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str | Notice]:
    """The sheet in plain text: each question and its answer through the ``plain`` mapping."""
    if sheet.title:
        title = ascii_text(" ".join(sheet.title.split()))
        yield f"{title}\n{'#' * len(title)}\n\n{_intro(sheet, kind)}\n\n"
    yield contents_chunks(sheet, answered, PLAIN)

    def body(a: Answered) -> Iterator[str | Notice]:
        if kind == "key":
            return chain(_answer_chunks(a, "plain", key_document(a)), "\n")
        head = PLAIN[QuestionBlock](question_block(a, key=False), a.options, [])
        return chain(head, _plain_worksheet(a))

    def section(name: str) -> str:
        return f"{ascii_text(name)}\n{'*' * len(ascii_text(name))}\n\n"

    yield from each_question(sheet, answered, section, body)


def _plain_worksheet(a: Answered) -> Iterator[str]:
    """A worksheet's question in plain text: its wording, the given values, empty tables."""
    yield ascii_text(wording(a)) + "\n\n"
    if given_of(a):
        given = ", ".join(ascii_text(g.text) for g in given_of(a))
        yield f"Given: {given}\n\n"
    for blank in _blank_tables(a.solution):
        yield f"{ascii_text(blank.title)}:\n"
        cells = ([c or "_" * max(3, w) for c, w in zip(r, blank.widths, strict=True)]
                 for r in _blank_rows(blank))  # fmt: skip
        for line in table_lines(
            [ascii_text(c.text) for c in blank.columns],
            [numeric_column(c) for c in blank.columns],
            cells,
            markdown=False,
        ):
            yield line + "\n"
        yield "\n"
    if not _blank_tables(a.solution, count=False):
        yield "Answer:\n" + "\n" * 6


# --- latex: scanconv.render.documents.sheet_latex ---------------------------------------------------


def _room(chars: int) -> int:
    """The width of an empty cell, in digits: handwriting takes more room than type.

    >>> _room(1), _room(10)
    (5, 15)
    """
    return max(5, chars + (chars + 1) // 2)


# --- json ---------------------------------------------------------------------------------------


def json_sheet(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str]:
    """One JSON object: the sheet's title, kind and total marks, and its questions: each
    question's :class:`~scanconv.document.Question` block (with its line in the file, its
    section and its wording as :func:`wording` gives it) and the key's answer through the
    ``json`` format."""
    questions = []
    for a in answered:
        q = a.question
        with _Guard(sheet, q):
            head = question_block(a, key=kind == "key")
            entry: dict[str, object] = {
                "number": head.number,
                "line": q.line,
                "marks": head.marks,
                "section": q.section or None,
                "question": wording(a),
            }
            if head.command:
                entry["command"] = head.command
                entry["answer"] = json.loads("".join(data.render_json(a.solution)))
            else:
                entry["given"] = [g.text for g in given_of(a)]
                entry["tables"] = [
                    {"title": b.title, "columns": [c.key for c in b.columns], "rows": b.rows}
                    for b in _blank_tables(a.solution)
                ]
            questions.append(entry)
    document = {
        "title": sheet.title or None,
        "kind": kind,
        "total_marks": sheet.total_marks,
        "questions": questions,
    }
    yield json_visible(json.dumps(document, ensure_ascii=False, indent=1)) + "\n"
