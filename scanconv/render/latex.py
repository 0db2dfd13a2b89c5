"""The ``latex`` format: a fragment to ``\\input`` into a document.

Needs ``\\usepackage{booktabs, amsmath}`` in the preamble (the fragment says so in its first
line). The table is written by hand rather than with tabulate's ``latex_booktabs``, which
escapes ``$`` and ``_`` and so breaks math headings; every cell that holds a number is set in
math mode so minus signs are real minus signs, and every text cell is escaped.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from ..numeric import fmt_pixel
from ..records import Column, Solution
from . import Notice, Options
from .cells import numeric_column, tex_text, wrap_items
from .text import grid_block, step_rows, table_rows


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
    yield "\\paragraph{Step table}\\mbox{}\\\\[1ex]\n"
    yield from _tabular(solution.columns, step_rows(solution, solution.columns))
    for table in solution.tables:
        yield f"\n\\paragraph{{{tex_text(table.title)}}}\\mbox{{}}\\\\[1ex]\n"
        yield from _tabular(table.columns, table_rows(table))
    count = sum(1 for _ in solution.pixels())
    yield f"\n\\paragraph{{Pixels plotted ({count})}}\n"
    for line in wrap_items(fmt_pixel(p) for p in solution.pixels()):
        yield f"${line}$\n"
    chunks = list(grid_block(solution, options))
    yield from (c for c in chunks if isinstance(c, Notice))
    lines = [c for c in chunks if isinstance(c, str)]
    if lines:
        yield "\n\\begin{verbatim}\n"
        for line in lines:
            yield line + "\n"
        yield "\\end{verbatim}\n"
