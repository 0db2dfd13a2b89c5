"""Print-perfect documents: the exam book, an answer key and a worksheet typeset with
pdflatex and read back with pdftotext, as a reader of the paper would see them.

Each PDF fails on: an option printed with an en dash (``–algo``); raw TeX in the text (``ˆ``,
``_{``, ``\\frac``, ``\\text``, a stray ``$``); an overfull box in the log; a spill page (fewer
than 12 words: a grid or a table fragment pushed over alone); a typewriter grid (``| .  #``
rows); and a worksheet without an empty grid to plot on. The HTML pages (a line, a circle, an
ellipse, a Bezier curve, a comparison, the exam book) are checked the same way: their visible
text, without MathML and scripts, holds no raw TeX.
"""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from tests.external import pandoc, pdftotext, typeset
from tests.helpers import run

QUESTIONS = """\
title: Unit 2: lines and circles
section: Lines
> Draw the line from (2, 2) to (10, 6) with the DDA algorithm.
[4] line 2 2 10 6 --algo dda
[4] line 2 2 10 6 --algo bresenham
section: Circles
[5] circle 8 --method midpoint
[5] circle 6 --method general
> Compare DDA and Bresenham's line algorithm.
[6] compare line 2 2 10 6 --theory
"""

RAW_TEX = re.compile(r"ˆ|_\{|\\frac|\\text|\\[a-zA-Z]+\{|\$")
EN_DASH_OPTION = re.compile(r"[–—][a-z]")
TYPEWRITER_ROW = re.compile(r"^\s*-?\d+ \|[ .#o@]+$", re.MULTILINE)


def _compile(folder: Path, tex: str) -> tuple[Path, str]:
    """Two passes (longtable settles its widths on the second): the PDF and the last log."""
    done = typeset(folder, tex, passes=2)
    assert done.code == 0, done.log[-3000:]
    return done.pdf, done.log


def _pages(folder: Path, pdf: Path) -> list[str]:
    """The text of each page, in reading order (``pdftotext -layout`` keeps table rows)."""
    return pdftotext(folder, pdf).split("\f")[:-1]


def _assert_print_clean(folder: Path, pdf: Path, log: str, *, worksheet: bool = False) -> list[str]:
    pages = _pages(folder, pdf)
    assert pages
    text = "\n".join(pages)
    assert "Overfull" not in log, re.findall(r"Overfull.*", log)[:5]
    assert not EN_DASH_OPTION.search(text), EN_DASH_OPTION.findall(text)[:5]
    raw = RAW_TEX.findall(text)
    assert not raw, (raw[:5], [ln for ln in text.splitlines() if RAW_TEX.search(ln)][:5])
    assert not TYPEWRITER_ROW.search(text), TYPEWRITER_ROW.findall(text)[:3]
    for n, page in enumerate(pages, 1):
        words = len(page.split())
        if worksheet and words < 12:  # a worksheet page may hold an empty table and no prose
            assert "Plot the pixels" in page or re.search(r"^\s*\S.*\n\s+\S", page), n
        else:
            assert words >= 12, f"page {n} holds {words} words: a spill page\n{page}"
    return pages


@pytest.fixture(scope="module")
def questions(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("print")
    path = folder / "q.txt"
    path.write_text(QUESTIONS, encoding="utf-8")
    return path


@pytest.mark.external
@pytest.mark.slow
def test_exam_book_prints_clean(tmp_path: Path) -> None:
    r = run("exam", "--format", "latex", "--standalone")
    assert r.code == 0, r.err
    assert "\\begin{verbatim}" not in r.out  # every grid and figure drawn
    pdf, log = _compile(tmp_path, r.out)
    pages = _assert_print_clean(tmp_path, pdf, log)
    text = "\n".join(pages)
    assert "--window" in text and "--algo" in text  # options as typed, hyphens kept
    assert "1. Geometric description" in text  # the five stages as text, not math


@pytest.mark.external
@pytest.mark.slow
def test_answer_key_prints_clean(tmp_path: Path, questions: Path) -> None:
    r = run("sheet", str(questions), "--key", "--format", "latex", "--standalone")
    assert r.code == 0, r.err
    assert r.out.count("\\begin{tikzpicture}") >= 5  # a drawn grid for every drawing question
    pdf, log = _compile(tmp_path, r.out)
    text = "\n".join(_assert_print_clean(tmp_path, pdf, log))
    assert "scanconv line 2 2 10 6 --algo dda" in text
    # The comparison is one table: its DDA and Bresenham columns side by side.
    assert ", part 1 of" not in text
    assert re.search(r"arithmetic\s+floating point.*integer additions only", text)


@pytest.mark.external
@pytest.mark.slow
def test_worksheet_prints_with_empty_grids_and_tables(tmp_path: Path, questions: Path) -> None:
    r = run("sheet", str(questions), "--worksheet", "--format", "latex", "--standalone")
    assert r.code == 0, r.err
    pdf, log = _compile(tmp_path, r.out)
    text = "\n".join(_assert_print_clean(tmp_path, pdf, log, worksheet=True))
    drawing = 4  # the two lines and the two circles; the comparison has no grid of its own
    assert text.count("Plot the pixels on this grid.") == drawing
    assert text.count("Working") == 5
    assert ", part 1 of" not in text  # every empty table whole
    # An empty grid has no pixels in it: no step numbers, no "filled" legend.
    grids = r.out.split("\\paragraph{Pixel grid}")[1:]
    assert len(grids) == drawing
    assert all("scpixel" not in g.split("\\end{tikzpicture}")[0] for g in grids)
    assert all(
        re.search(r"\\node\[sctick[^]]*\] at \([0-9.]+,[0-9.]+\) \{-?\d+\}", g) for g in grids
    )


# --- HTML: the visible text holds no raw TeX -------------------------------------------------


class Visible(HTMLParser):
    """The text of a page a reader sees: the content of the ``hide`` elements left out
    (by default <math>, <script> and <style>)."""

    def __init__(self, hide: tuple[str, ...] = ("math", "script", "style")) -> None:
        super().__init__()
        self.hide = hide
        self.hidden = 0
        self.parts: list[str] = []

    def handle_starttag(self, tag: str, attrs: object) -> None:
        self.hidden += tag in self.hide

    def handle_endtag(self, tag: str) -> None:
        self.hidden -= tag in self.hide

    def handle_data(self, data: str) -> None:
        if not self.hidden:
            self.parts.append(data)


HTML_PAGES = {
    "line": ("line", "2", "2", "10", "6"),
    "circle": ("circle", "8", "--method", "midpoint"),
    "circle-foley": ("circle", "8", "--convention", "foley"),
    "general": ("circle", "6", "--method", "general"),
    "ellipse": ("ellipse", "8", "6"),
    "bezier": ("bezier", "0,0", "1,2", "3,3", "4,0"),
    "compare": ("compare", "line", "2", "2", "10", "6", "--theory"),
    "symmetric-dda": ("theory", "symmetric-dda"),
    "process": ("theory", "scan-conversion-process"),
}


def _visible(html: str) -> str:
    page = Visible()
    page.feed(html)
    return "".join(page.parts)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("name", HTML_PAGES)
def test_html_page_shows_no_raw_tex(name: str) -> None:
    r = run(*HTML_PAGES[name], "--format", "html")
    assert r.code == 0, r.err
    text = _visible(r.out)
    raw = re.findall(r"\^|_\{|\\frac|\\text|\\[a-zA-Z]+\{|\$|[a-z]_[a-z0-9]\b", text)
    assert not raw, (raw[:5], [ln for ln in text.splitlines() if re.search(r"\^|_\{", ln)][:3])


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_exam_book_html_shows_no_raw_tex() -> None:
    r = run("exam", "--format", "html", "--section", "circle")
    assert r.code == 0, r.err
    text = _visible(r.out)
    assert not re.findall(r"\^|_\{|\\frac|\\text|\$", text)


@pytest.mark.external
@pytest.mark.parametrize("name", ["line", "circle-foley", "general", "compare", "symmetric-dda"])
@pytest.mark.parametrize("flavour", ["markdown", "gfm"])
def test_markdown_through_pandoc_shows_no_raw_tex(tmp_path: Path, name: str, flavour: str) -> None:
    """The Markdown homework through ``pandoc --mathml`` reads like the PDF: math as math."""
    r = run(*HTML_PAGES[name], "--format", "markdown")
    assert r.code == 0, r.err
    html = pandoc(tmp_path, r.out, flavour, "html", "--mathml")
    text = _visible(html)
    assert not re.findall(r"\^|_\{|\\frac|\\text|\$|\\[a-zA-Z]+", text)
