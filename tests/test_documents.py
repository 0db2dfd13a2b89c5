"""The worked-solution documents render for real: markdown through pandoc, LaTeX through pdflatex.

Each check counts what must survive from the :class:`~scanconv.records.Solution` itself (its
given and derived quantities, its columns, its steps, its grid), not from the output:

* markdown -> HTML with pandoc (its own markdown and GitHub's dialect), math as MathML: every
  ``$...$`` becomes one ``<math>`` element (pandoc warns and leaves TeX when a formula does not
  parse), the step table is an HTML table with one row per step, the grid is a ``<pre>`` block;
* the ``latex`` fragment, inside a minimal article, compiles with pdflatex, and long answers
  neither run off the right margin nor lose table rows at the bottom of a page.

pandoc comes from the ``pypandoc_binary`` wheel (the ``test`` extra), pdflatex from Debian's
``texlive-latex-base`` and ``texlive-latex-recommended`` (``.ci/run`` installs them). Without
pdflatex the LaTeX tests skip, except in CI, where they fail.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable
from html.parser import HTMLParser
from pathlib import Path

import pytest
import typer

from scanconv.cli import app
from scanconv.core.records import Solution
from scanconv.render import formats
from scanconv.render.figures import grid as gridmod

from .cli_vocabulary import DOCUMENTS, NOT_WALKED
from .external import Typeset, batch, overfull, pandoc_with_warnings, typeset, typeset_each
from .helpers import run

pytestmark = pytest.mark.external  # pdflatex, pandoc (external tests are slow too: conftest)

COMMANDS = set(typer.main.get_command(app).commands)  # type: ignore[attr-defined]

#: One answer of each kind, by its CLI arguments (kinds whose command is missing are left out).
CASES = {
    "line-bresenham": ["line", "2", "2", "10", "6", "--algo", "bresenham"],
    "line-dda": ["line", "2", "2", "5", "10", "--algo", "dda"],
    "line-basic": ["line", "0", "0", "1.5", "4", "--algo", "basic"],
    "bezier": ["bezier", "0", "0", "1", "2", "3", "3", "4", "0", "--samples", "8"],
    "bspline": ["bspline", "0", "0", "1", "2", "3", "3", "4", "0", "5", "2", "--degree", "2"],
    "circle": ["circle", "10"],
    "ellipse": ["ellipse", "8", "6"],
    "compare-line": ["compare", "line", "2", "8", "10", "4"],
    "compare-circle": ["compare", "circle", "10"],
}


def _solution(name: str) -> Solution:
    """The Solution the CLI renders for ``CASES[name]``, built through the library."""
    from fractions import Fraction

    args = CASES[name]
    if args[0] == "line":  # through the API, as the command builds it (its defaults included)
        from scanconv import _api

        return _api.line(*(Fraction(a) for a in args[1:5]), args[-1])
    if args[0] == "compare":
        from scanconv.answers.compare import compare_lines

        return compare_lines(*(Fraction(a) for a in args[2:6]))
    raise AssertionError(f"no library mapping for {name}")


def _cases() -> list[str]:
    return [n for n, a in CASES.items() if a[0] in COMMANDS]


def _markdown(name: str) -> str:
    result = run(*CASES[name], "--format", "markdown")
    assert result.code == 0, result.err
    return result.out


# --- markdown through pandoc ---------------------------------------------------------------------


class _Html(HTMLParser):
    """What the checks need from pandoc's HTML: math, tables, pre blocks, text outside math."""

    def __init__(self) -> None:
        super().__init__()
        self.math = 0
        self.depth_math = 0
        self.tables: list[dict[str, list]] = []
        self.pre: list[str] = []
        self.text_outside_math: list[str] = []
        self._cell: list[str] | None = None
        self._cell_math = False
        self._in_head = False
        self._in_pre = False

    def handle_starttag(self, tag: str, attrs: list) -> None:
        if tag == "math":
            self.math += 1
            self.depth_math += 1
            self._cell_math = True
        elif tag == "table":
            self.tables.append({"head": [], "rows": []})
        elif tag == "thead":
            self._in_head = True
        elif tag == "tr" and self.tables and not self._in_head:
            self.tables[-1]["rows"].append([])
        elif tag in ("td", "th"):
            self._cell, self._cell_math = [], False
        elif tag == "pre":
            self._in_pre = True
            self.pre.append("")

    def handle_endtag(self, tag: str) -> None:
        if tag == "math":
            self.depth_math -= 1
        elif tag == "thead":
            self._in_head = False
        elif tag in ("td", "th") and self._cell is not None:
            text = "".join(self._cell).strip()
            if tag == "th":
                self.tables[-1]["head"].append((text, self._cell_math))
            else:
                self.tables[-1]["rows"][-1].append(text)
            self._cell = None
        elif tag == "pre":
            self._in_pre = False

    def handle_data(self, data: str) -> None:
        if self._cell is not None:
            self._cell.append(data)
        if self._in_pre:
            self.pre[-1] += data
        if not self.depth_math:
            self.text_outside_math.append(data)


def _to_html(scratch: Path, markdown: str, dialect: str) -> tuple[_Html, str]:
    out, warnings = pandoc_with_warnings(scratch, markdown, dialect, "html", "--mathml")
    parser = _Html()
    parser.feed(out)
    return parser, warnings


@pytest.mark.parametrize("dialect", ["markdown", "gfm"])
@pytest.mark.parametrize("name", _cases())
def test_markdown_renders_through_pandoc(tmp_path: Path, name: str, dialect: str) -> None:
    html, warnings = _to_html(tmp_path, _markdown(name), dialect)
    assert "[WARNING]" not in warnings, warnings  # e.g. "Could not convert TeX math"
    assert "$" not in "".join(html.text_outside_math), "a $...$ was not read as math"
    assert html.tables, "the step table did not become an HTML table"
    for table in html.tables:
        assert table["head"] and all(has_math for _, has_math in table["head"])
        assert table["rows"] and all(len(r) == len(table["head"]) for r in table["rows"])
    assert html.pre, "the grid did not survive as a code block"
    assert html.math > 0


@pytest.mark.parametrize("name", ["line-bresenham", "line-dda", "line-basic", "compare-line"])
def test_markdown_survives_exactly(tmp_path: Path, name: str) -> None:
    """Counted from the Solution: one <math> per formula, one row per step, the same grid."""
    solution = _solution(name)
    html, _ = _to_html(tmp_path, _markdown(name), "gfm")
    tables = ([solution.columns] if solution.columns else []) + [t.columns for t in solution.tables]
    from scanconv.render.cells import note_segments

    formulas = len(solution.given) + len(solution.derived) + sum(len(c) for c in tables)
    formulas += sum(math for n in solution.notes for math, _ in note_segments(n))  # $...$
    from scanconv.render.cells import prose_math
    from scanconv.render.mappings.text import all_tables

    cells = (c for _, _, rows in all_tables(solution) for row in rows() for c in row)
    formulas += sum(math for c in cells for math, _ in prose_math(c))  # x_inc in a cell
    assert html.math == formulas
    heads = [len(t["head"]) for t in html.tables]
    assert heads == [len(c) for c in tables]
    if solution.columns:
        assert len(html.tables[0]["rows"]) == sum(1 for _ in solution.steps())
        for row, step in zip(html.tables[0]["rows"], solution.steps(), strict=True):
            assert f"({step.pixel[0]}, {step.pixel[1]})" in row
    if solution.pixels is not None:
        expected = gridmod.render_grid(solution.pixels(), solution.bbox, marks=solution.marks)
        assert html.pre[0].rstrip("\n").splitlines() == expected
    elif solution.figures:
        from scanconv.render.mappings.text import figure_text

        drawn = figure_text(solution.figures[0], "bottom-left")
        assert html.pre[0].rstrip("\n").splitlines()[: len(drawn)] == drawn


# --- LaTeX through pdflatex ---------------------------------------------------------------------

PREAMBLE = r"""\documentclass{article}
\usepackage{booktabs,amsmath,longtable,array,graphicx,tikz}
\begin{document}
"""


def _compile(tmp_path: Path, *fragments: str) -> str:
    """Compile the fragments in a minimal article (two passes: longtable settles its column
    widths on the second); return the log."""
    done = typeset(tmp_path, PREAMBLE + "\n".join(fragments) + "\n\\end{document}\n", passes=2)
    assert done.code == 0, done.log[-3000:]
    assert done.pdf.stat().st_size > 1000
    return done.log


@functools.cache
def _answer(*args: str) -> str:
    result = run(*args, "--format", "latex")
    assert result.code == 0, result.err
    return result.out


def _latex(name: str) -> str:
    return _answer(*CASES[name])


#: The answers of the tests below that each check one answer's width (typeset with the cases).
WIDE = (("circle", "10"), ("line", "0", "0", "24", "4"), ("circle", "20"))


def _every() -> list[str]:
    """The cases and the wide answers: one document sets them all, each from a new page."""
    return [_latex(n) for n in _cases()] + [_answer(*args) for args in WIDE]


def _fits_within(margin: float | None) -> Callable[[Typeset], None]:
    """The check of a typeset answer: a PDF, and no line more than ``margin`` pt too wide
    (``None``: no overfull line at all)."""

    def fits(done: Typeset) -> None:
        assert done.pdf.stat().st_size > 1000
        wide = overfull(done.log)
        assert not [v for v in wide if margin is None or v > margin], "a line past the margin"

    return fits


def test_latex_fragments_compile(tmp_path: Path) -> None:
    for name in _cases():
        assert _latex(name).startswith("% scanconv answer; needs \\usepackage{booktabs,amsmath")
    log = _compile(tmp_path, batch(_every()))  # the document test_latex_fits_the_page_width sets
    assert "Undefined control sequence" not in log and "Missing $ inserted" not in log


#: Every answer fits an article's text width: a table too wide even in \scriptsize is set in
#: parts (the circle's 9-column symmetry table in two).
FITTING = list(CASES)


@pytest.mark.parametrize("name", [n for n in FITTING if n in _cases()])
def test_latex_fits_the_page_width(tmp_path: Path, name: str) -> None:
    """Every case typeset from a page of its own in one document; a case alone when that
    document has a line past the margin (the failure names it)."""
    typeset_each(tmp_path, PREAMBLE, _latex(name), _every(), _fits_within(1), passes=2)


def test_latex_wide_short_table_is_never_scaled_down_but_set_in_parts(tmp_path: Path) -> None:
    """The circle's 9-column symmetry table is never shrunk below 7 pt (no ``\\resizebox``):
    it is set in parts of its columns, each repeating the octant's (x, y) and every row; it
    fits the page."""
    from scanconv.answers.primitives.circle import circle_solution

    (table,) = circle_solution("midpoint", 10).tables
    out = _answer("circle", "10")
    assert "\\resizebox" not in out and "\\tiny" not in out
    parts = out.split("8-way symmetry about the centre (0, 0), part ")[1:]
    assert len(parts) == 2 and parts[0].startswith("1 of 2") and parts[1].startswith("2 of 2")
    heads = []
    for part in parts:
        body = part.split("\\end{tabular}")[0]
        assert body.count("\\\\\n") == 1 + sum(1 for _ in table.rows())  # heading and rows
        heads += body.split("\\midrule")[0].split("\\toprule")[1].split("&")
    cells = [h.strip().rstrip("\\").strip() for h in heads]
    assert cells.count("$(x, y)$") == 2 and len(set(cells)) == len(table.columns)
    typeset_each(tmp_path, PREAMBLE, out, _every(), _fits_within(1), passes=2)


def test_latex_long_answer_breaks_pixels_and_pages(tmp_path: Path) -> None:
    """A 50-step line: the pixel list wraps between pixels and the table continues on the next
    page (longtable) instead of running off the page's bottom or right edge."""
    result = run("line", "0", "0", "50", "10", "--format", "latex", "--no-grid")
    log = _compile(tmp_path, result.out)
    assert not overfull(log) and "Overfull \\vbox" not in log
    pages = re.search(r"Output written on doc\.pdf \((\d+) pages?", log)
    assert pages and int(pages.group(1)) >= 2


def test_latex_wide_grid_is_drawn_to_fit(tmp_path: Path) -> None:
    """The grid is drawn (TikZ), scaled to the text width, never typewriter text."""
    out = _answer("line", "0", "0", "24", "4")
    assert "\\begin{tikzpicture}" in out and "\\begin{verbatim}" not in out
    typeset_each(tmp_path, PREAMBLE, out, _every(), _fits_within(1), passes=2)


# --- the terminal: the full answer by default, --brief for the answer alone ------------------------


def test_rich_shows_the_derivation_unless_brief() -> None:
    from scanconv.answers.primitives.line import line_solution
    from scanconv.render.cells import note_unicode

    solution = line_solution("bresenham", 2, 2, 10, 6)
    full = run("line", "2", "2", "10", "6", "--format", "rich")
    brief = run("line", "2", "2", "10", "6", "--format", "rich", "--brief")
    assert full.code == brief.code == 0
    for out in (full.out, brief.out):
        assert solution.title in out and "Step table" in out and "Pixels plotted (9)" in out
    assert "Working:" not in brief.out and "Given:" not in brief.out
    for q in solution.derived:
        assert q.text in full.out and q.text not in brief.out
    assert "Notes:" in full.out and "Notes:" not in brief.out
    assert note_unicode("$p_k < 0$") in full.out


@pytest.mark.parametrize("fmt", formats("answer"))
def test_explain_is_a_no_op_kept_for_old_scripts(fmt: str) -> None:
    base = run("line", "2", "2", "10", "6", "--format", fmt)
    assert run("line", "2", "2", "10", "6", "--format", fmt, "--explain").out == base.out


@pytest.mark.parametrize("fmt", ["markdown", "latex", "plain", "csv", "json"])
def test_brief_leaves_only_the_notes_out_of_the_documents(fmt: str) -> None:
    """In a document format --brief drops scanconv's notes and nothing else (the working
    stays: it is the answer a student hands in); csv has no notes to drop."""
    base = run("line", "2", "2", "10", "6", "--format", fmt).out
    brief = run("line", "2", "2", "10", "6", "--format", fmt, "--brief").out
    if fmt == "csv":
        assert brief == base
        return
    assert brief != base and len(brief) < len(base)
    kept = set(brief.splitlines())
    assert all(line in base.splitlines() for line in kept if "notes" not in line)


def _leaves(command, prefix=()):
    if hasattr(command, "commands"):
        for name, sub in command.commands.items():
            yield from _leaves(sub, (*prefix, name))
    else:
        yield " ".join(prefix), command


LEAVES = dict(_leaves(typer.main.get_command(app)))
DRAWING = (
    "line",
    "circle",
    "ellipse",
    "bezier",
    "bspline",
    "continuity",
    "parametric",
    "polygon",
    "fill",
    "antialias",
)


@pytest.mark.parametrize(
    "name",
    sorted(
        n
        for n in LEAVES
        if (n,) not in DOCUMENTS | {("check",)} and tuple(n.split()) not in NOT_WALKED
    ),
)
def test_every_command_takes_brief_and_explain(name: str) -> None:
    """Every answer takes them (``check`` writes a marking, the documents whole files)."""
    assert {"brief", "explain"} <= {p.name for p in LEAVES[name].params}


@pytest.mark.parametrize("name", sorted(n for n in LEAVES if n.split()[0] in DRAWING))
def test_drawing_commands_take_svg_and_png(name: str) -> None:
    assert {"svg", "png"} <= {p.name for p in LEAVES[name].params}


def test_every_golden_latex_answer_in_one_document_sets_cleanly(tmp_path: Path) -> None:
    """All the golden LaTeX answers, one after another: no line past the margin (no overfull
    box at all) and every grid kept on one page (each is set in a minipage)."""
    from .test_golden import FILES, read_case

    fragments = []
    for path in [
        p
        for p in FILES
        if p.suffix == ".tex" and "\\documentclass" not in p.read_text(encoding="utf-8")
    ]:  # complete documents (sheets, the exam book) compile in their own tests
        result = run(*read_case(path)[0])
        assert result.code == 0, result.err
        fragments.append(result.out)
        grids = result.out.count("\\begin{verbatim}") + result.out.count("\\begin{tikzpicture}")
        listings = result.out.count("\\begin{minipage}{\\linewidth}\\ttfamily")  # pseudocode
        assert result.out.count("\\begin{minipage}{\\linewidth}") == grids + listings, path.name
    log = _compile(tmp_path, *fragments)
    assert overfull(log) == [], "overfull boxes"


def test_latex_radius_20_grid_fits_the_margin(tmp_path: Path) -> None:
    out = _answer("circle", "20")
    assert "\\begin{minipage}" in out
    typeset_each(tmp_path, PREAMBLE, out, _every(), _fits_within(None), passes=2)
