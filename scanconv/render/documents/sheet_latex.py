r"""The LaTeX writer of a sheet (:func:`scanconv.render.documents.sheet.sheet_document` with ``latex``).

A key is each question's number, marks, wording and command line (typewriter type, every
hyphen kept: an option is never an en dash), then its worked answer as the ``latex`` format
writes it (tables, the drawn pixel grid). A worksheet is the question, the given values, a
ruled box for the working, each table of the answer empty (the right shape: its columns and
rows, the row numbers filled in) and, for a drawing question, the empty pixel grid of the
answer's extent with its axes numbered.

Pages: a question starts on a new page when what is estimated of its height does not fit in
what is left of the page (``\scneed``, the ``needspace`` idea), or, for a long question, when
less than :data:`NEED_SHARE` of a page is left. A grid is never split from its caption, and a table too wide for the
page is set whole when it can be (:func:`scanconv.render.mappings.latex._tables`).
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence

from ...core.records import Column
from ...core.working import tex_text
from ...document import Pixels, as_document
from ...document import Question as QuestionBlock
from .. import Notice
from ..figures.tikz import tikz_grid
from ..mappings.latex import KEEP_ROWS, LATEX, NEED, math_cell
from .sheet import (
    Answered,
    Blank,
    Sheet,
    _answer_chunks,
    _blank_rows,
    _blank_tables,
    _Guard,
    _intro,
    _room,
    contents_chunks,
    given_of,
    key_document,
    question_block,
    wording,
)

PREAMBLE = (
    r"""\RequirePackage{fix-cm}
\documentclass[a4paper]{article}
\usepackage[margin=25mm]{geometry}
\usepackage{booktabs,amsmath,longtable,array,graphicx,tikz}
\setlength{\parindent}{0pt}
\emergencystretch=3em
\tolerance=2000
"""
    + NEED
    + "\\begin{document}\n"
)

PACKAGES = "booktabs,amsmath,longtable,array,graphicx,tikz"
"""What a sheet's fragment needs in the preamble."""

TEXT_HEIGHT = 690.0
"""An A4 page's text height with 25 mm margins, in points."""

NEED_SHARE = 0.45
"""A question starts on a new page when less than its estimated height is left of the page,
or less than this share of a page for a question that cannot fit beside another anyway."""

WORKING_LINES = 8
"""The height of a worksheet's box for the working, in lines."""


def height(tex: str) -> float:
    r"""About how tall a question's LaTeX is set, in points: its lines, table rows, list
    items and pictures (each picture says its height in a ``% height`` comment).

    >>> height("a\\par\nb & c \\\\\n% height 100pt\n")
    126.0
    """
    rows = tex.count("\\\\\n") + tex.count("\\par") + tex.count("\\item")
    pictures = sum(float(h) for h in re.findall(r"% height ([0-9.]+)pt", tex))
    return 13.0 * rows + pictures


def latex_sheet(
    sheet: Sheet, answered: Sequence[Answered], kind: str, standalone: bool
) -> Iterator[str | Notice]:
    """The sheet in LaTeX: a fragment, or a complete article with ``standalone``."""
    yield PREAMBLE if standalone else f"% scanconv sheet; needs \\usepackage{{{PACKAGES}}}\n" + NEED
    if sheet.title:
        yield f"\\section*{{\\raggedright {tex_text(' '.join(sheet.title.split()))}}}\n"
        yield f"{_intro(sheet, kind)}\n\n"
    yield contents_chunks(sheet, answered, LATEX)
    section = ""
    for n, a in enumerate(answered):
        q = a.question
        with _Guard(sheet, q):
            body: list[str] = []
            notices: list[Notice] = []
            if q.section and q.section != section:
                section = q.section
                body.append(f"\\section*{{\\raggedright {tex_text(section)}}}\n")
                if sheet.contents:
                    body.append(f"\\addcontentsline{{toc}}{{section}}{{{tex_text(section)}}}\n")
            head = question_block(a, key=kind == "key", listed=sheet.contents)
            doc = as_document(a.solution)
            heading = LATEX[QuestionBlock](head, a.options, doc)
            body.extend(c for c in heading if isinstance(c, str))
            for chunk in _key(a) if kind == "key" else _worksheet(a):
                (notices if isinstance(chunk, Notice) else body).append(chunk)  # type: ignore[arg-type]
            if n:
                need = min(height("".join(body)) + 60, NEED_SHARE * TEXT_HEIGHT)
                yield f"\n\\scneed{{{need:.0f}pt}}\n"
            yield from notices
            yield "".join(body)
    if standalone:
        yield "\\end{document}\n"


def _key(a: Answered) -> Iterator[str | Notice]:
    """A key's answer through the ``latex`` mapping, its title a ``\\subsubsection*`` under
    the question's heading (the fragment's header comment left out)."""
    for chunk in _answer_chunks(a, "latex", key_document(a, question=False)):
        if isinstance(chunk, str) and chunk.startswith("% scanconv answer"):
            continue
        yield chunk


def _worksheet(a: Answered) -> Iterator[str]:
    yield tex_text(wording(a)) + "\\par\\medskip\n"
    if given_of(a):
        given = ", ".join(f"${g.tex}$" for g in given_of(a))
        yield f"\\paragraph{{Given}} {given}\n\n"
    blanks = _blank_tables(a.solution)
    drawing = as_document(a.solution).get(Pixels) is not None
    lines = WORKING_LINES if blanks or drawing else 2 * WORKING_LINES
    yield (
        "\\paragraph{Working}\\mbox{}\\par\\nopagebreak\n\\noindent\\fbox{\\parbox[t]"
        f"[{lines}\\baselineskip]{{\\dimexpr\\linewidth-2\\fboxsep-2\\fboxrule\\relax}}{{\\mbox{{}}}}}}"
        f"\\par\n% height {lines * 12}pt\n"
    )
    for blank in blanks:
        yield from _latex_blank(blank)
    if drawing:
        grid = tikz_grid(a.solution, a.options.origin, empty=True)
        if grid is not None:
            yield "\\paragraph{Pixel grid}\\mbox{}\\par\\nopagebreak\n" + grid


def _tex_label(text: str) -> str:
    r"""A row label in LaTeX: a number in math, a word as text.

    >>> _tex_label("-3"), _tex_label("KB_2")
    ('$-3$', 'KB\\_2')
    """
    return f"${text}$" if math_cell(text) else tex_text(text)


def blank_widths(blank: Blank) -> list[float]:
    """The width of each column of an empty table in points (room to write each answer
    cell by hand): the natural widths when they fit the text width, else all narrowed in
    proportion (the headings are not shrunk with them: :func:`_column_heading`); the table is
    never split into parts.

    >>> from scanconv.core.records import Column
    >>> cols = tuple(Column(str(i), "x", "x") for i in range(9))
    >>> round(sum(blank_widths(Blank("t", cols, 3, (18,) * 9))) + 12 * 9)
    335
    """
    natural = [5.0 * (_room(w) + 2) for w in blank.widths]
    room = 0.97 * 345 - 12 * len(natural)
    if sum(natural) <= room:
        return natural
    factor = room / sum(natural)
    return [w * factor for w in natural]


_WORDS = re.compile(r"\\text\{([^{}$\\]*)\}")
MIN_HEADING_PT = 7.0
"""The smallest size of any part of a worksheet's heading (a subscript of a 10 pt formula):
a heading is never shrunk to fit its column (printed and read on paper: issue 39, headings
shrunk to 2 pt)."""


def _word_width(word: str) -> float:
    """A word's width in points at 10 pt, about: 5.5 a character, 7.5 a capital (``DDA`` is
    about 22 pt, not 16.5).

    >>> _word_width("DDA"), _word_width("basic")
    (22.5, 27.5)
    """
    return sum(7.5 if c.isupper() else 5.5 for c in word)


def _column_heading(column: Column, width: float) -> str:
    r"""A worksheet column's heading, set at the text's own size (its subscripts at 7 pt, so
    never below :data:`MIN_HEADING_PT`): words wrap in their column; a formula wider than its
    column is set on its side instead of being shrunk.

    >>> from scanconv.core.records import Column
    >>> _column_heading(Column("e", "new end point", r"\text{new end point}"), 30.0)
    'new end point'
    >>> _column_heading(Column("e", "new end point", r"\text{new end point}"), 20.0)
    '\\rotatebox{90}{new end point}'
    >>> _column_heading(Column("p", "p_k", "p_k"), 40.0)
    '$p_k$'
    >>> _column_heading(Column("q", "(x_c+x, y_c+y)", "(x_c+x, y_c+y)"), 20.0)
    '\\rotatebox{90}{$(x_c+x, y_c+y)$}'
    """
    words = _WORDS.fullmatch(column.tex.strip())
    if words:  # they wrap between words; a word wider than the column is set on its side
        text = tex_text(words.group(1))
        longest = max((_word_width(w) for w in words.group(1).split()), default=0.0)
        return text if width >= longest else f"\\rotatebox{{90}}{{{text}}}"
    if width >= 5.0 * len(column.text):  # about 5 pt a character at 10 pt
        return f"${column.tex}$"
    return f"\\rotatebox{{90}}{{${column.tex}$}}"


def _latex_blank(blank: Blank) -> Iterator[str]:
    """An empty table, ruled for writing in, whole: each column as wide as its widest
    answer cell and a little more, narrowed to the text width when too wide (a longtable:
    a table of many rows continues on the next page, its heading repeated)."""
    widths = blank_widths(blank)
    need = 60 + 26 * (blank.rows if blank.rows <= KEEP_ROWS else 5)  # rows 8 mm high, ruled
    yield f"\\scneed{{{need}pt}}\\paragraph{{{tex_text(blank.title)}}}\\mbox{{}}\\\\[1ex]\n"
    spec = "|" + "|".join(f">{{\\centering\\arraybackslash}}p{{{w:.1f}pt}}" for w in widths) + "|"
    short = blank.rows <= KEEP_ROWS  # a tabular never breaks: its heading made room for it
    env = "tabular" if short else "longtable"
    yield ("\\par{\\centering" if short else "") + f"\\begin{{{env}}}{{{spec}}}\n\\hline\n"
    heads = (_column_heading(c, w) for c, w in zip(blank.columns, widths, strict=True))
    yield " & ".join(heads) + " \\\\\n\\hline\n" + ("" if short else "\\endhead\n")
    for row in _blank_rows(blank):
        cells = [_tex_label(c) if c else "" for c in row]  # labels and given values
        yield "\\rule[-2.5mm]{0pt}{8mm}" + " & ".join(cells) + " \\\\\n\\hline\n"
    yield "\\end{tabular}\\par}\\medskip\n" if short else "\\end{longtable}\n"
