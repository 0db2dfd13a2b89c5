"""The ``latex`` format: a fragment to ``\\input`` into a document.

Needs ``\\usepackage{booktabs, amsmath}`` in the preamble (the fragment says so in its first
line). The table is written by hand rather than with tabulate's ``latex_booktabs``, which
escapes ``$`` and ``_`` and so breaks math headings; every cell that holds a number is set in
math mode so minus signs are real minus signs, and every text cell is escaped.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from ..records import Column, Solution
from . import Notice, Options
from .cells import numeric_column, tex_text
from .text import all_tables, figure_lines, pixel_count, pixel_lines


def _cell(text: str) -> str:
    if text == "-":
        return "--"
    if text and (text[0].isdigit() or text[0] in "-(") and text.isascii():
        return f"${text}$"
    return tex_text(text)


def _tabular(columns: Sequence[Column], rows: Iterator[list[str]]) -> Iterator[str]:
    spec = "".join("r" if numeric_column(c) else "c" for c in columns)
    yield f"\\begin{{tabular}}{{{spec}}}\n\\toprule\n"
    yield " & ".join(f"${c.tex}$" for c in columns) + " \\\\\n\\midrule\n"
    for r in rows:
        yield " & ".join(_cell(c) for c in r) + " \\\\\n"
    yield "\\bottomrule\n\\end{tabular}\n"


def render_latex(solution: Solution, options: Options) -> Iterator[str | Notice]:
    """The worked solution as a LaTeX fragment."""
    yield "% scanconv answer; needs \\usepackage{booktabs,amsmath}\n"
    yield f"\\subsection*{{{tex_text(solution.title)}}}\n\n"
    if solution.given:
        yield "\\paragraph{Given} " + ", ".join(f"${q.tex}$" for q in solution.given) + "\n\n"
    if solution.derived:
        yield "\\paragraph{Working}\n\\begin{itemize}\n"
        for q in solution.derived:
            yield f"  \\item ${q.tex}$\n"
        yield "\\end{itemize}\n\n"
    for note in solution.notes:
        yield f"\\noindent {tex_text(note)}\\par\n"
    if solution.notes:
        yield "\n"
    for title, cols, rows in all_tables(solution):
        yield f"\\paragraph{{{tex_text(title or 'Step table')}}}\\mbox{{}}\\\\[1ex]\n"
        yield from _tabular(cols, rows)
        yield "\n"
    if solution.pixels is not None:
        yield f"\\paragraph{{Pixels plotted ({pixel_count(solution)})}}\n"
        for line in pixel_lines(solution):
            yield f"${line}$\n"
    lines, notices = figure_lines(solution, options)
    yield from notices
    if lines:
        yield "\n\\begin{verbatim}\n"
        for line in lines:
            yield line + "\n"
        yield "\\end{verbatim}\n"
