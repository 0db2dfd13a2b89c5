"""Sheets: many answers in one document, as an answer key or as a worksheet for students.

:func:`sheet_document` renders a whole sheet in memory (so nothing is written when a question
turns out bad) in ``markdown``, ``plain``, ``latex`` (a fragment, or a complete document with
``standalone``; written by :mod:`scanconv.render.sheet_latex`), ``json`` and ``html``, and as
a quiz file for an LMS, ``moodle`` (Moodle XML) or ``gift`` (:mod:`scanconv.render.lms`). A key is each question's number,
marks, wording and command line, then its full worked answer, as the single-answer renderers
write it. A worksheet is the question in words, the given values and, for each table of the
answer, an empty table with the answer's columns and number of rows (the ``k`` column, which
only numbers the rows, filled in); nothing of the answer itself.

The records :class:`Question`, :class:`Sheet` and :class:`Answered` are what
:mod:`scanconv.cli.sheet` reads a question file into. Text from the question file (the title,
sections, wording, command lines) is escaped for every format.
"""

from __future__ import annotations

import json
import re
import shlex
from collections.abc import Iterator, Sequence
from typing import NamedTuple

from ..core.records import Column, Quantity, Solution
from ..core.working import ascii_text, json_visible, visible
from ..document import Given, as_document
from . import Notice, Options
from .cells import numeric_column
from .text import md_text


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
FORMATS = ("markdown", "plain", "latex", "json", "html", "moodle", "gift")


def sheet_document(
    sheet: Sheet,
    answered: Sequence[Answered],
    kind: str = "key",
    fmt: str = "markdown",
    *,
    standalone: bool = False,
    notices: list[str] | None = None,
) -> str:
    """The whole sheet as one string. A ``ValueError`` raised while an answer is worked out
    names the question's line (``SOURCE:LINE: ...``). Notices (a grid left out) are added to
    ``notices``, prefixed with the question's number.
    """
    if kind not in KINDS:
        raise ValueError(f"unknown sheet kind {kind!r}: key or worksheet")
    if fmt in ("moodle", "gift"):  # a quiz file for an LMS: scanconv.render.lms
        from .lms import quiz_document

        return quiz_document(sheet, answered, fmt, notices)
    if fmt == "json":
        return _json(sheet, answered, kind)
    if fmt == "html":
        return _html(sheet, answered, kind, notices)
    if fmt == "latex":
        from .sheet_latex import latex_sheet

        writer = latex_sheet
    elif fmt in ("markdown", "plain"):
        writer = _markdown if fmt == "markdown" else _plain
    else:
        raise ValueError(f"unknown sheet format {fmt!r}: one of {', '.join(FORMATS)}")
    out: list[str] = []
    for chunk in writer(sheet, answered, kind, standalone):
        if isinstance(chunk, Notice):
            if notices is not None:
                notices.append(chunk.message)
        else:
            out.append(chunk)
    return "".join(out)


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


def _answer_chunks(a: Answered, fmt: str) -> Iterator[str | Notice]:
    from . import Format, render

    for chunk in render(a.solution, Format(fmt), a.options):
        if isinstance(chunk, Notice):
            yield Notice(f"question {a.question.number}: {chunk.message}", chunk.ways)
        else:
            yield chunk


def _marks(marks: int | None) -> str:
    if marks is None:
        return ""
    return f" ({marks} mark{'' if marks == 1 else 's'})"


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
    labels: tuple[str, ...] = ()
    """The first column's cells when they only number or name the rows (:data:`LABELS`)."""
    sample: tuple[tuple[str, ...], ...] = ()
    """The first rows of the answer's table, to split a wide table as the key splits it
    (never shown)."""


LABELS = frozenset({"k", "r", "i", "decimal", "unit", "method"})
"""Keys of a first column that only numbers or names the rows (the step ``k``, de Casteljau's
level ``r``, an image's row ``i``, a quantization level's number, a storage unit): a worksheet fills it in."""


def _blank_tables(solution: Solution, count: bool = True) -> list[Blank]:
    """The tables of the answer, emptied: title, columns, row count and cell widths."""
    from .text import all_tables

    out = []
    for title, columns, rows in all_tables(solution):
        n = 0
        widths = [len(c.text) for c in columns]
        labels: list[str] = []
        sample: list[tuple[str, ...]] = []
        numbered = bool(columns) and columns[0].key in LABELS
        if count:
            for row in rows():
                n += 1
                widths = [max(w, len(c)) for w, c in zip(widths, row, strict=True)]
                if numbered:
                    labels.append(row[0])
                if n <= 100:
                    sample.append(tuple(row))
        out.append(
            Blank(
                title or "Step table",
                tuple(columns),
                n,
                tuple(widths),
                tuple(labels),
                tuple(sample),
            )
        )
    return out


def _blank_rows(blank: Blank) -> Iterator[list[str]]:
    """The rows of an empty table: the row labels filled in (:data:`LABELS`), the rest empty."""
    for i in range(blank.rows):
        yield [
            blank.labels[i] if j == 0 and blank.labels else "" for j in range(len(blank.columns))
        ]


# --- markdown and plain -------------------------------------------------------------------------


def md_code(text: str) -> str:
    """``text`` as an inline code span, fenced with more backticks than it holds.

    >>> md_code("a ` b")
    '`` a ` b ``'
    """
    runs = [len(r) for r in re.findall(r"`+", text)]
    fence = "`" * (max(runs, default=0) + 1)
    pad = " " if runs or text.startswith("`") else ""
    return f"{fence}{pad}{visible(text)}{pad}{fence}"


def _levels(sheet: Sheet) -> tuple[int, int]:
    """The heading level of a section and of a question (questions under sections go one
    deeper)."""
    sections = any(q.section for q in sheet.questions)
    return 2, 3 if sections else 2


def _parts(blank: Blank) -> list[tuple[list[int], str]]:
    """The columns and the label of a Markdown worksheet table: whole, as the key's table is
    (:func:`scanconv.render.text._parts`) and as the PDF sets it."""
    return [(list(range(len(blank.columns))), blank.title)]


def _markdown(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str | Notice]:
    section_level, level = _levels(sheet)
    if sheet.title:
        yield f"# {md_text(' '.join(sheet.title.split()))}\n\n{_intro(sheet, kind)}\n\n"
    section = ""
    for a in answered:
        q = a.question
        with _Guard(sheet, q):
            if q.section and q.section != section:
                section = q.section
                yield f"{'#' * section_level} {md_text(section)}\n\n"
            yield f"{'#' * level} Question {q.number}{_marks(q.marks)}\n\n"
            if kind == "key":
                yield from _md_key(a, level)
            else:
                yield from _md_worksheet(a)


def _md_key(a: Answered, level: int) -> Iterator[str | Notice]:
    """A key's question in Markdown: its wording, its command, its answer (the ``markdown``
    format's mapping, the answer's title one level under the question's)."""
    if a.question.wording:
        yield f"> {md_text(a.question.wording)}\n\n"
    yield md_code(a.question.command) + "\n\n"
    first = True
    for chunk in _answer_chunks(a, "markdown"):
        if first and isinstance(chunk, str) and chunk.startswith("## "):
            chunk = "#" * (level + 1) + chunk[2:]
        first = False
        yield chunk


def _md_worksheet(a: Answered) -> Iterator[str]:
    """A worksheet's question in Markdown: its wording, the given values, empty tables."""
    from .text import table_lines

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


def _plain(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str | Notice]:
    from .text import table_lines

    if sheet.title:
        title = ascii_text(" ".join(sheet.title.split()))
        yield f"{title}\n{'#' * len(title)}\n\n{_intro(sheet, kind)}\n\n"
    section = ""
    for a in answered:
        q = a.question
        with _Guard(sheet, q):
            if q.section and q.section != section:
                section = q.section
                yield f"{ascii_text(section)}\n{'*' * len(ascii_text(section))}\n\n"
            head = f"Question {q.number}{_marks(q.marks)}"
            yield f"{head}\n{'-' * len(head)}\n\n"
            if kind == "key":
                if q.wording:
                    yield ascii_text(q.wording) + "\n\n"
                yield f"$ {ascii_text(q.command)}\n\n"
                yield from _answer_chunks(a, "plain")
                yield "\n"
                continue
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


# --- latex: scanconv.render.sheet_latex ---------------------------------------------------


def _room(chars: int) -> int:
    """The width of an empty cell, in digits: handwriting takes more room than type.

    >>> _room(1), _room(10)
    (5, 15)
    """
    return max(5, chars + (chars + 1) // 2)


# --- json ---------------------------------------------------------------------------------------


def _json(sheet: Sheet, answered: Sequence[Answered], kind: str) -> str:
    """One JSON object: the sheet's title, kind and total marks, and its questions."""
    from .data import render_json

    questions = []
    for a in answered:
        q = a.question
        with _Guard(sheet, q):
            entry: dict[str, object] = {
                "number": q.number,
                "line": q.line,
                "marks": q.marks,
                "section": q.section or None,
                "question": wording(a),
            }
            if kind == "key":
                entry["command"] = q.command
                entry["answer"] = json.loads("".join(render_json(a.solution)))
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
    return json_visible(json.dumps(document, ensure_ascii=False, indent=1)) + "\n"


# --- html ---------------------------------------------------------------------------------------

_SHEET_CSS = """\
.sc-sheet{font-family:"DejaVu Sans",system-ui,sans-serif;color:#1b1b1b;line-height:1.45}
.sc-sheet h1{font-size:1.6em;margin:.2em 0 .3em 0}
.sc-sheet h2.sc-section{font-size:1.35em;margin:1.2em 0 .4em 0}
.sc-sheet h2.sc-q,.sc-sheet h3.sc-q{font-size:1.2em;margin:1.2em 0 .3em 0}
.sc-sheet .sc-wording{font-style:italic}
.sc-sheet code{font-family:"DejaVu Sans Mono",monospace;background:#f4f4f4;padding:0 .25em}
.sc-sheet table.sc-blank{border-collapse:collapse;margin:.4em 0 1em 0}
.sc-sheet table.sc-blank th,.sc-sheet table.sc-blank td{border:1px solid #555;\
padding:.2em .5em;height:1.9em;text-align:center}
.sc-sheet .sc-answer-space{height:12em;border:1px dashed #999;margin:.4em 0 1em 0}
@media print{.sc-sheet>.sc-question~.sc-question{break-before:page}}
"""


def _html(sheet: Sheet, answered: Sequence[Answered], kind: str, notices: list[str] | None) -> str:
    """The sheet as one self-contained HTML page: every text from the question file and every
    value escaped; a page break before each question when printed. The key's answers are the
    stepping answers of :mod:`scanconv.render.html` (each with its own stepper)."""
    from .mathml import esc as escape

    title = " ".join(sheet.title.split()) or ("Answer key" if kind == "key" else "Worksheet")
    style = f"<style>\n{_SHEET_CSS}</style>\n"
    if kind == "key":
        from .html import answer_section, page_head
        from .page_assets import JS

        head = page_head(title).replace("</head>", style + "</head>", 1)
    else:
        head = (
            '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
            '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
            f"<title>{escape(title)}</title>\n{style}</head>\n"
        )
    parts = [head, '<body>\n<main class="sc-sheet">\n']
    if sheet.title:
        parts.append(f"<h1>{escape(title)}</h1>\n")
    parts.append(f"<p>{escape(_intro(sheet, kind))}</p>\n")
    section = ""
    level = 3 if any(q.section for q in sheet.questions) else 2
    for a in answered:
        q = a.question
        with _Guard(sheet, q):
            if q.section and q.section != section:
                section = q.section
                parts.append(f'<h2 class="sc-section">{escape(section)}</h2>\n')
            parts.append(f'<section class="sc-question" id="q{q.number}">\n')
            marks = escape(_marks(q.marks))
            parts.append(f'<h{level} class="sc-q">Question {q.number}{marks}</h{level}>\n')
            if kind == "key":
                if q.wording:
                    parts.append(f'<p class="sc-wording">{escape(q.wording)}</p>\n')
                parts.append(f"<p><code>{escape(q.command)}</code></p>\n")
                found: list[str] = []
                parts.append(
                    answer_section(
                        a.solution, f"sc{q.number}", a.options, level=level + 1, notices=found
                    )
                )
                parts.append("\n")
                if notices is not None:
                    notices.extend(f"question {q.number}: {n}" for n in found)
            else:
                parts.append(f'<p class="sc-wording">{escape(wording(a))}</p>\n')
                parts.extend(_html_blank(a))
            parts.append("</section>\n")
    parts.append("</main>\n")
    if kind == "key":
        parts.append(f"<script>{JS}</script>\n")
    parts.append("</body>\n</html>\n")
    return "".join(parts)


def _html_blank(a: Answered) -> Iterator[str]:
    """A worksheet question's given values and empty tables, in HTML."""
    from .mathml import esc as escape

    if given_of(a):
        given = ", ".join(escape(g.text) for g in given_of(a))
        yield f"<p><strong>Given:</strong> {given}</p>\n"
    blanks = _blank_tables(a.solution)
    for blank in blanks:
        yield f"<p><strong>{escape(blank.title)}:</strong></p>\n"
        yield '<table class="sc-blank">\n<thead><tr>'
        yield "".join(f"<th>{escape(c.text)}</th>" for c in blank.columns)
        yield "</tr></thead>\n<tbody>\n"
        for row in _blank_rows(blank):
            cells = (
                f'<td style="min-width:{_room(w) * 0.6:.1f}em">{escape(c)}</td>'
                for c, w in zip(row, blank.widths, strict=True)
            )
            yield "<tr>" + "".join(cells) + "</tr>\n"
        yield "</tbody>\n</table>\n"
    if not blanks:
        yield '<p><strong>Answer:</strong></p>\n<div class="sc-answer-space"></div>\n'
