"""The HTML writer of a sheet (:func:`scanconv.render.documents.sheet.sheet_document` with ``html``).

One self-contained page: the sheet's title, its questions (a page break before each when
printed) and, for a key, each answer as the ``html`` format writes it, with its own stepper;
for a worksheet, the question, the given values and each table of the answer empty.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from ...core import lazy
from ...document import Question as QuestionBlock
from .. import Notice
from ..html.mathml import esc as escape
from ..mappings.html import answer_section, contents_html, page_head, question_html
from .sheet import (
    Answered,
    Sheet,
    _blank_rows,
    _blank_tables,
    _intro,
    _levels,
    _room,
    contents_block,
    each_question,
    given_of,
    question_block,
    wording,
)

if TYPE_CHECKING:
    from ..html import page_assets
else:
    page_assets = lazy.module("scanconv.render.html.page_assets")


def html_sheet(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str | Notice]:
    """The sheet as one self-contained HTML page: every text from the question file and every
    value escaped; a page break before each question when printed. The key's answers are the
    stepping answers of :mod:`scanconv.render.mappings.html` (each with its own stepper): the ``html``
    format's mapping."""
    title = " ".join(sheet.title.split()) or ("Answer key" if kind == "key" else "Worksheet")
    style = f"<style>\n{page_assets.SHEET_CSS}</style>\n"
    if kind == "key":
        head = page_head(title).replace("</head>", style + "</head>", 1)
    else:
        head = (
            '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
            '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
            f"<title>{escape(title)}</title>\n{style}</head>\n"
        )
    yield head + '<body>\n<main class="sc-sheet">\n'
    if sheet.title:
        yield f"<h1>{escape(title)}</h1>\n"
    yield f"<p>{escape(_intro(sheet, kind))}</p>\n"
    if sheet.contents:
        yield contents_html(contents_block(sheet, answered))
    level = _levels(sheet)[1]

    def body(a: Answered) -> Iterator[str | Notice]:
        q = a.question
        yield f'<section class="sc-question" id="q{q.number}">\n'
        if kind == "key":
            yield question_html(question_block(a, level))
            found: list[str] = []
            yield answer_section(
                a.solution, f"sc{q.number}", a.options, level=level + 1, notices=found
            )
            yield "\n"
            yield from (Notice(f"question {q.number}: {n}") for n in found)
        else:
            yield question_html(QuestionBlock(q.number, q.marks, wording(a), level=level))
            yield from _html_blank(a)
        yield "</section>\n"

    yield from each_question(
        sheet, answered, lambda s: f'<h2 class="sc-section">{escape(s)}</h2>\n', body
    )
    yield "</main>\n"
    if kind == "key":
        yield f"<script>{page_assets.JS}</script>\n"
    yield "</body>\n</html>\n"


def _html_blank(a: Answered) -> Iterator[str]:
    """A worksheet question's given values and empty tables, in HTML."""
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
