"""Print that reads on paper: every golden case's LaTeX sets without a line past the margin,
a pixel grid is never parted from its table by a page break, and the notes are a bulleted
list. Typeset with pdflatex and read back with pdftotext, as a reader of the paper sees them.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest

from .external import batch, overfull, pdftotext, typeset
from .helpers import run
from .test_golden import FILES, GOLDEN, read_case
from .test_print import QUESTIONS
from .test_terminal_width import _as_rich

pytestmark = pytest.mark.external  # pdflatex, pdftotext (external tests are slow too: conftest)

PREAMBLE = (
    "\\documentclass{article}\n\\usepackage{booktabs,amsmath,longtable,array,graphicx,tikz}\n"
    "\\begin{document}\n"
)


def _as_latex(args: list[str]) -> list[str]:
    """A golden case's arguments asking for LaTeX (its format and output options left out)."""
    return [*_as_rich(args)[:-1], "latex"]


def _golden_latex() -> dict[str, str]:
    """The LaTeX of every golden case (whatever format its file holds), by its command."""
    cwd = Path.cwd()
    os.chdir(GOLDEN.parent)
    try:
        answers: dict[str, str] = {}
        for path in FILES:
            args = _as_latex(read_case(path)[0])
            if "-" in args or " ".join(args) in answers:  # standard input; the same case
                continue
            result = run(*args)
            assert result.code == 0, (args, result.err)
            answers[" ".join(args)] = result.out
        return answers
    finally:
        os.chdir(cwd)


@pytest.mark.slow
def test_every_golden_cases_latex_sets_without_an_overfull_box(tmp_path: Path) -> None:
    """35 golden cases' LaTeX had a line past the margin (up to 140 pt: a
    working line of points, a formula's words, a long heading). Every case, in any format
    its golden file holds, is asked for as LaTeX and typeset from a page of its own; a case
    that fails is named by compiling it alone."""
    answers = _golden_latex()
    fragments = {k: v for k, v in answers.items() if "\\documentclass" not in v}
    whole = typeset(tmp_path, PREAMBLE + batch(list(fragments.values())) + "\n\\end{document}\n")
    assert whole.code == 0, whole.log[-3000:]
    wide = overfull(whole.log)
    documents = [v for v in answers.values() if "\\documentclass" in v]
    for doc in documents:  # complete documents (a sheet with --standalone): each alone
        done = typeset(tmp_path, doc, passes=2)
        assert done.code == 0, done.log[-3000:]
        wide += overfull(done.log)
    if wide:
        named = []
        for command, tex in fragments.items():
            alone = typeset(tmp_path, PREAMBLE + tex + "\n\\end{document}\n")
            if overfull(alone.log):
                named.append((command, overfull(alone.log)))
        pytest.fail(f"overfull boxes: {named or wide}")


_TABLE = re.compile(r"Step table|8-way symmetry about")


@pytest.mark.slow
def test_a_grid_is_on_the_page_of_its_table(tmp_path: Path) -> None:
    """The key's first question had its step table on page 1 and its pixel
    list and grid alone on page 2 (and the general circle's the same on pages 5 and 6). Every
    page that shows a grid shows, above it, the table it draws (the heading of the step
    table or of the symmetry table set right before the pixel list), and each grid's page
    holds the last row of that table: for the DDA line, the row of k = 8 ending at (10, 6)."""
    (tmp_path / "q.txt").write_text(QUESTIONS, encoding="utf-8")
    pdf = tmp_path / "key.pdf"
    done = run("sheet", str(tmp_path / "q.txt"), "-o", str(pdf))
    assert done.code == 0, done.err
    pages = pdftotext(tmp_path, pdf).split("\f")[:-1]
    grids = [n for n, page in enumerate(pages) if "Pixels plotted" in page]
    assert len(grids) == 4, [p[:200] for p in pages]  # the two lines and the two circles
    for n in grids:
        page = pages[n]
        table, grid = _TABLE.search(page), page.index("Pixels plotted")
        assert table and table.start() < grid, f"page {n + 1}: a grid without its table\n{page}"
    first = pages[grids[0]]
    assert re.search(r"^\s*8\s+10\.000\s+6\.000\s+10\s+6\s+\(10, 6\)", first, re.MULTILINE), first


def test_notes_are_a_bulleted_list(tmp_path: Path) -> None:
    """The LaTeX notes ran together as paragraphs. Each note of the answer
    (the Solution's own notes) starts its own bullet in the PDF."""
    from scanconv import _api

    solution = _api.line(2, 2, 10, 6, "bresenham")
    tex = run("line", "2", "2", "10", "6", "--format", "latex").out
    done = typeset(tmp_path, PREAMBLE + tex + "\n\\end{document}\n")
    assert done.code == 0, done.log[-3000:]
    text = " ".join(pdftotext(tmp_path, done.pdf).split())
    notes = text.split(" Notes ", 1)[1].split("Step table", 1)[0]
    assert len(solution.notes) >= 3
    bullets = re.findall(r"[•\x88] (\S+)", notes)  # pdftotext reads cmsy's bullet as \x88
    assert len(bullets) == len(solution.notes), notes
    assert bullets[0] == "Row" and "Conventions" in bullets, bullets
