"""Hostile text in every output format: what a user types or a file supplies is escaped for
the format it lands in, and never executed.

The corpus (:data:`CORPUS`) goes through every place user text reaches an answer:

* formulas (``sample EXPR``, ``parametric custom --x/--y``): the safe evaluator refuses all
  but arithmetic, so most of the corpus is refused (exit 2, one line, nothing on stdout); the
  formulas it accepts that still hold characters special to some format (``t**2+t**3`` is
  bold in Markdown, a newline inside brackets, a leading ``-`` or ``+``) are checked in every
  answer format;
* a question sheet's title, section headings and question wording (``sheet``), in every sheet
  format;
* student file names in ``check --batch`` (the CSV a teacher opens in a spreadsheet, and
  Markdown).

Each format is checked as its reader sees it: Markdown through pandoc (no table breakage, no
emphasis or raw HTML from user text), LaTeX through pdflatex (compiles; ``\\input`` and
``\\write18`` not executed: the log and a sentinel file tell), CSV through the csv module (no
cell from user text starts a spreadsheet formula), JSON through ``json.loads`` (valid, the text
round-trips), plain and rich without terminal control characters, and HTML (when
:class:`~scanconv.render.Format` has ``html``: the parametrisation picks it up by itself) with
no ``<script>`` element from user text.
"""

from __future__ import annotations

import csv
import functools
import io
import json
import os
import re
import shutil
from collections.abc import Sequence
from html.parser import HTMLParser
from pathlib import Path

import pytest

from scanconv.render import Format, formats

from .external import pandoc, typeset_each
from .helpers import run

pytestmark = pytest.mark.slow

SENTINEL = "/tmp/scanconv-escaping-pwned"
CORPUS = [
    "</script><script>alert(1)</script>",
    "<img src=x onerror=alert(1)>",
    "\\input{/etc/passwd}",
    f"\\write18{{touch {SENTINEL}}}",
    "\\immediate\\write18{rm -rf /}",
    "_ % $ # & { } ~ ^ \\",
    "| a | b |",
    '=HYPERLINK("http://evil","x")',
    "+cmd",
    "-1+1",
    "@SUM(A1)",
    "line one\nline two",
    "tab\there",
    "nul\x00byte",
    "\u202eRTL override\u202c and \u200fmark",
    "\x1b[2J\x1b]0;pwned\x07",
    "**bold** _em_ `code` [link](http://x) ![img](x)",
    "$x$ $$y$$ \\(z\\)",
    "# heading",
    "x" * 5000,
]

#: Formulas the safe evaluator accepts that hold characters special to some format.
FORMULAS = ["t**2+t**3", "(t*t\n+t)", "-1+t", "+t", "t*(t)*t", "1e1*t  -  t"]

#: The formulas whose ``*`` pair up as Markdown emphasis (bold, italics) if left unescaped.
EMPHASIS = ("t**2+t**3", "t*(t)*t")

ANSWER_FORMATS = [f for f in Format if f is not Format.auto]


class _Tags(HTMLParser):
    """Tags and text of an HTML page."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.heading = False
        self.in_headings: list[str] = []
        """Tags inside headings (emphasis there came from user text)."""
        self.attributes: list[str] = []
        self.text: list[str] = []
        self.scripts: list[str] = []
        self.rows: list[int] = []

    def handle_starttag(self, tag: str, attrs: list) -> None:
        if self.heading:
            self.in_headings.append(tag)
        if tag in ("h1", "h2", "h3", "h4"):
            self.heading = True
        self.tags.append(tag)
        self.attributes.extend(f"{k}={v}" for k, v in attrs)
        if tag == "tr":
            self.rows.append(0)
        if tag in ("td", "th") and self.rows:
            self.rows[-1] += 1

    def handle_endtag(self, tag: str) -> None:
        if tag in ("h1", "h2", "h3", "h4"):
            self.heading = False

    def handle_data(self, data: str) -> None:
        self.text.append(data)
        if self.tags and self.tags[-1] == "script":
            self.scripts.append(data)


def _no_injected_html(page: _Tags, baseline: _Tags) -> None:
    """The page's own scripts only: as many as a page of harmless text has, none of them
    holding user text, and no event-handler attribute from it."""
    assert page.tags.count("script") == baseline.tags.count("script"), "a <script> from user text"
    assert not any("alert" in s for s in page.scripts), "user text inside a script"
    assert not any(a.startswith("onerror") for a in page.attributes), "an event handler"


def _html(page: str) -> _Tags:
    parser = _Tags()
    parser.feed(page)
    return parser


def _markdown_html(scratch: Path, markdown: str) -> _Tags:
    """The Markdown through pandoc (once per text in a run: each sheet case compares its page
    with the same harmless sheet's), parsed."""
    return _html(pandoc(scratch, markdown, "markdown", "html"))


ARTICLE = "\\documentclass{article}\n\\usepackage{booktabs,amsmath,longtable,array,tikz}\n"
ARTICLE += "\\begin{document}\n"


def _typeset_not_executed(tmp_path: Path, preamble: str, body: str, every: Sequence[str]) -> None:
    """``body`` compiles after ``preamble`` and reads or runs nothing: checked on one document
    of all the test's cases (``every``), and on ``body`` alone when that one fails."""
    typeset_each(tmp_path, preamble, body, every, lambda done: _not_executed(done.log), pdf=False)


def _not_executed(log: str) -> None:
    assert "(/etc/passwd" not in log and "root:x:0:0" not in log, "\\input{/etc/passwd} was read"
    assert "runsystem" not in log, "\\write18 was run"
    assert not os.path.exists(SENTINEL)


_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")


def _no_control_characters(text: str) -> None:
    found = _CONTROL.findall(text)
    assert not found, f"control characters reach the output: {found[:5]!r}"


def _check_format(
    fmt: Format, out: str, tmp_path: Path, table_rows: int | None, baseline: str | None = None
) -> None:
    """The format-specific checks of an accepted answer."""
    _no_control_characters(out)
    if fmt is Format.markdown:
        page = _markdown_html(tmp_path, out)
        assert not page.in_headings, f"markup from user text in a heading: {page.in_headings}"
        assert "script" not in page.tags
        if table_rows is not None:
            cells = [n for n in page.rows if n]
            assert len(set(cells)) == 1 and len(cells) >= table_rows, page.rows
    elif fmt is Format.latex:
        _typeset_not_executed(tmp_path, ARTICLE, out, _formula_latex())
    elif fmt is Format.json:
        json.loads(out)
    elif fmt is Format.csv:
        rows = list(csv.reader(io.StringIO(out)))
        assert len({len(r) for r in rows}) == 1
    elif fmt.value == "html":
        assert baseline is not None
        _no_injected_html(_html(out), _html(baseline))
    elif fmt in (Format.rich, Format.plain):
        assert out.splitlines()[0].strip()
    else:
        pytest.fail(f"no reader here for the format {fmt.value}: add one")


# --- formulas ----------------------------------------------------------------------------------


@pytest.mark.parametrize("text", CORPUS, ids=lambda t: repr(t)[:30])
def test_hostile_formulas_are_refused_in_one_line(text):
    """Refused, except the arithmetic ``-1+1`` (checked with the accepted formulas)."""
    for args in (
        ["sample", text, "--size", "3", "-L", "2"],
        ["parametric", "custom", "--x", text, "--y", "t"],
    ):
        r = run(*args, "-f", "csv")
        if text == "-1+1":
            assert r.code == 0, r.err
            continue
        assert r.code == 2 and r.out == "", (args, r.out[:200])
        assert r.err.count("\n") == 1 and r.err.startswith("scanconv: error: ")
        _no_control_characters(r.err.rstrip("\n"))


def _formula_cases() -> list:
    """Every accepted formula in every answer format; the Markdown heading bug where a
    formula pairs ``*`` (bold or italics in the heading)."""
    return [
        pytest.param(
            formula,
            fmt,
            marks=[],
            id=f"{fmt.value}-{formula[:12]!r}",
        )
        for formula in FORMULAS
        for fmt in ANSWER_FORMATS
    ]


def _formula_args(formula: str, fmt: str) -> tuple[list[str], list[str]]:
    """The two commands that take a formula: a parametric curve and a sampled field."""
    parametric = ["parametric", "custom", "--x", formula, "--y", "t", "-n", "4", "--no-grid"]
    sample = ["sample", formula.replace("t", "x"), "--size", "3", "-L", "2"]
    return [*parametric, "-f", fmt], [*sample, "-f", fmt]


@functools.cache
def _formula_latex() -> tuple[str, ...]:
    """Every accepted formula's LaTeX answers (typeset together)."""
    return tuple(run(*a).out for f in FORMULAS for a in _formula_args(f, "latex"))


@pytest.mark.parametrize(("formula", "fmt"), _formula_cases())
def test_accepted_formulas_are_escaped_in_every_format(formula, fmt, tmp_path):
    parametric, sample = _formula_args(formula, fmt.value)
    r = run(*parametric)
    assert r.code == 0, r.err
    harmless = run(*_formula_args("t", fmt.value)[0])
    _check_format(fmt, r.out, tmp_path, table_rows=5, baseline=harmless.out)
    if fmt is Format.json:
        assert json.loads(r.out)["x_formula"] == formula
    r = run(*sample)
    assert r.code == 0, r.err
    harmless = run(*_formula_args("x", fmt.value)[1])
    _check_format(fmt, r.out, tmp_path, table_rows=None, baseline=harmless.out)


# --- a question sheet: title, sections, wording --------------------------------------------------

SHEET_FORMATS = [f for f in formats("document") if f in formats("answer")]
"""The formats of a document of answers (the quiz files: tests/test_lms_escaping.py)."""


def _sheet_file(tmp_path: Path, text: str) -> Path:
    one = " ".join(text.split("\n"))  # each directive is one line of the file
    path = tmp_path / "questions.txt"
    path.write_text(
        f"title: {one}\nsection: {one}\n> {one}\n[4] line 2 2 10 6\n> {one}\n[2] circle 5\n",
        encoding="utf-8",
    )
    return path


def _document(tex: str) -> tuple[str, str]:
    """A standalone document's preamble (to ``\\begin{document}``) and body."""
    preamble, rest = tex.split("\\begin{document}\n", 1)
    return preamble + "\\begin{document}\n", rest.rsplit("\\end{document}", 1)[0]


@functools.cache
def _sheet_latex(base: Path) -> tuple[str, ...]:
    """The body of every sheet case's standalone LaTeX (typeset together); ``base`` is this
    process's base temporary folder."""
    bodies = []
    for n, text in enumerate(CORPUS):
        folder = base / "escaping-sheets"
        (folder / str(n)).mkdir(parents=True)
        r = run("sheet", str(_sheet_file(folder / str(n), text)), "-f", "latex", "--standalone")
        if r.code == 0:  # a NUL byte is refused
            bodies.append(_document(r.out)[1])
    return tuple(bodies)


def _sheet_cases():
    for text in CORPUS:
        for fmt in SHEET_FORMATS:
            yield pytest.param(text, fmt, id=f"{fmt}-{text[:20]!r}")


@pytest.mark.parametrize(("text", "fmt"), list(_sheet_cases()))
def test_sheet_titles_sections_and_wording_are_escaped(text, fmt, tmp_path, tmp_path_factory):
    path = _sheet_file(tmp_path, text)
    args = ["sheet", str(path), "-f", fmt]
    r = run(*args, *(["--standalone"] if fmt in ("latex", "html") else []))
    if r.code == 2:  # refused (a NUL byte: not a text file): one line, nothing written
        assert r.out == "" and r.err.count("\n") == 1
        return
    assert r.code == 0, r.err
    _no_control_characters(r.out)
    if fmt == "markdown":
        page = _markdown_html(tmp_path, r.out)
        assert "script" not in page.tags and "img" not in page.tags and "a" not in page.tags
        plain = run("sheet", str(_sheet_file(tmp_path, "plain words")), "-f", fmt)
        assert page.rows == _markdown_html(tmp_path, plain.out).rows  # the same tables, none broken
        assert page.tags.count("h1") == 1 and page.tags.count("h2") == 1
    elif fmt == "latex":
        preamble, body = _document(r.out)
        every = _sheet_latex(tmp_path_factory.getbasetemp())
        _typeset_not_executed(tmp_path, preamble, body, every)
    elif fmt == "json":
        data = json.loads(r.out)
        assert isinstance(data["title"], str) and data["questions"][0]["command"].startswith(
            "scanconv"
        )
    elif fmt == "html":
        harmless = run(
            "sheet", str(_sheet_file(tmp_path, "plain words")), "-f", fmt, "--standalone"
        )
        _no_injected_html(_html(r.out), _html(harmless.out))
    else:
        assert fmt == "plain", f"no reader here for the format {fmt}: add one"


# --- student files: names in check --batch ------------------------------------------------------

HOSTILE_NAMES = [
    '=HYPERLINK("http:evil","x")',
    "+cmd",
    "-1+1",
    "@SUM(A1)",
    "| a | b |",
    "\u202ertl",
]


def test_batch_csv_neutralises_formula_cells_from_file_names(tmp_path):
    source = Path(__file__).parent / "data" / "check" / "batch" / "alice.csv"
    folder = tmp_path / "batch"
    folder.mkdir()
    for name in HOSTILE_NAMES:
        shutil.copy(source, folder / f"{name}.csv")
    r = run("check", "--batch", str(folder), "-f", "csv", "--", "line", "2", "2", "10", "6")
    assert r.code == 0, r.err
    rows = list(csv.reader(io.StringIO(r.out)))
    names = [row[0] for row in rows[1:]]
    assert len(names) == len(HOSTILE_NAMES)
    for cell in names:
        assert not cell.startswith(("=", "+", "-", "@", "\t", "\r")), cell
    r = run("check", "--batch", str(folder), "-f", "markdown", "--", "line", "2", "2", "10", "6")
    assert r.code == 0, r.err
    page = _markdown_html(tmp_path, r.out)
    assert len({n for n in page.rows if n}) == 1, page.rows  # '|' in a name breaks no row
