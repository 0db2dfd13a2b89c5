"""The pseudocode of ``--algorithm`` is a :class:`Pseudocode` block, shown as
a numbered code listing in every format, never as a table: not stepped through, not emptied
into a worksheet's table, not marked, not asked in a quiz."""

from __future__ import annotations

import io
import json
import re
import typing
from collections.abc import Callable
from pathlib import Path

import pytest
from rich.console import Console

from scanconv.answers.methods import METHODS
from scanconv.answers.primitives.circle import circle_solution
from scanconv.answers.primitives.ellipse import ellipse_solution
from scanconv.answers.primitives.line import line_solution
from scanconv.core.records import Code, Solution
from scanconv.document import Document, Pixels, Pseudocode, Table, Title, document
from scanconv.render import Format, Notice, Options, render
from scanconv.render.documents.lms import gap_tables
from scanconv.render.html.stepper import stepping
from scanconv.render.mappings.latex import tt_text

from .external import batch, pandoc, pdftotext, typeset
from .helpers import run

#: How to ask each command that has pseudocode for an answer with it (``--algorithm``); a
#: command whose record names pseudocode and is missing here fails the first test.
ASK: dict[str, Callable[[str], Solution]] = {
    "line": lambda name: line_solution(name, 2, 2, 10, 6, pseudocode=True),
    "circle": lambda name: circle_solution(name, 5, pseudocode=True),
    "ellipse": lambda name: ellipse_solution(8, 6, pseudocode=True),
}

WITH_CODE = sorted(key for key, m in METHODS.items() if m.pseudocode is not None)

#: Questions with pseudocode in other shapes: a steep line, a negative slope walked from P1
#: (a swap line first), the Foley circle (its own update), the theory answers' examples.
MORE = {
    "line dda steep": lambda: line_solution("dda", 2, 2, 5, 10, pseudocode=True),
    "line bresenham backward": lambda: line_solution(
        "bresenham", 10, 6, 2, 2, start="given", pseudocode=True
    ),
    "circle foley": lambda: circle_solution("midpoint", 7, convention="foley", pseudocode=True),
}


def _answer(key: str) -> Solution:
    if key in MORE:
        return MORE[key]()
    command, name = key.split("/")
    return ASK[command](name)


CASES = [*WITH_CODE, *MORE]


def _listing(doc: Document) -> Pseudocode:
    listings: list[Pseudocode] = doc.every(Pseudocode)
    assert len(listings) == 1, [type(b).__name__ for b in doc.blocks]
    return listings[0]


@pytest.mark.parametrize("key", WITH_CODE)
def test_every_method_with_pseudocode_gives_the_block(key: str) -> None:
    """Walk the method records: each that names pseudocode has an answer with one listing, in
    reading order after the further tables and before the pixels, and no table of it."""
    record = METHODS[key]
    assert typing.get_type_hints(record.load("pseudocode"))["return"] in (Code, Code | None)
    assert record.command in ASK, f"{key}: add its command to ASK"
    doc = document(_answer(key))
    listing = _listing(doc)
    assert listing.title.startswith("Algorithm") and len(listing.lines) >= 4
    assert all(line.isascii() and line == line.rstrip() for line in listing.lines)
    assert any(line.startswith("    ") for line in listing.lines)  # a loop's body, indented
    kinds = [type(b) for b in doc.blocks]
    at = kinds.index(Pseudocode)
    assert Table not in kinds[at:] and kinds[at + 1] is Pixels
    assert not any(t.title.startswith("Algorithm") for t in doc.every(Table))
    assert not document(_bare(_answer(key))).every(Pseudocode)


def _bare(sol: Solution) -> Solution:
    """The same answer without its pseudocode."""
    return Solution(**{**sol.fields(), "theory": sol.theory._replace(code=())})


def _rich(doc: Document, width: int) -> str:
    console = Console(width=width, file=io.StringIO(), color_system=None, legacy_windows=False)
    for chunk in render(doc, Format.rich, Options(width=width)):
        if not isinstance(chunk, Notice):
            console.print(chunk)
    out = console.file.getvalue()  # type: ignore[attr-defined]
    assert isinstance(out, str)
    return out


def _text(doc: Document, fmt: Format) -> str:
    return "".join(c for c in render(doc, fmt, Options()) if isinstance(c, str))


def _count_lines(text: str, line: str) -> int:
    return sum(1 for x in text.splitlines() if x.rstrip() == line or x.rstrip() == "  " + line)


@pytest.mark.slow  # over 50 ms a case
@pytest.mark.parametrize("key", CASES)
def test_each_format_shows_every_line_once_with_its_indentation(key: str) -> None:
    doc = document(_answer(key))
    listing = _listing(doc)
    numbered = listing.numbered()
    assert [x[len(str(len(numbered))) + 2 :] for x in numbered] == list(listing.lines)
    plain, markdown = _text(doc, Format.plain), _text(doc, Format.markdown)
    latex, page = _text(doc, Format.latex), _text(doc, Format.html)
    for line in numbered:
        assert _count_lines(plain, line) == 1, line
        assert _count_lines(markdown, line) == 1, line
        assert _count_lines(latex.replace("\\\\\n", "\n"), "\\mbox{}" + tt_text(line)) == 1, line
        escaped = line.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
        assert page.count(escaped) == 1, line
    for width in (80, 120):
        shown = _rich(doc, width)
        for line in numbered:
            assert _count_lines(shown, line) == 1, (width, line)
    assert "pseudocode" not in plain + markdown + latex  # no column headed so
    assert "\\begin{tabular}{rc}" not in latex


@pytest.mark.slow
@pytest.mark.parametrize("key", CASES)
def test_rich_fits_60_columns_and_keeps_every_word(key: str) -> None:
    doc = document(_answer(key))
    listing = _listing(doc)
    for width in (60, 80, 120):
        shown = _rich(doc, width)
        assert max(len(x) for x in shown.splitlines()) <= width
        start = shown.index(listing.title[:20])
        end = shown.index("Pixels plotted", start)
        words = " ".join(shown[start:end].split())
        assert " ".join(" ".join(listing.numbered()).split()) in words, width


@pytest.mark.external  # pandoc
def test_markdown_is_a_code_block_through_pandoc(tmp_path: Path) -> None:
    docs = [document(_answer(key)) for key in CASES]
    text = "\n".join(_text(doc, Format.markdown) for doc in docs)
    ast = json.loads(pandoc(tmp_path, text, "markdown", "json"))
    blocks = [b["c"] for b in ast["blocks"] if b["t"] == "CodeBlock"]
    codes = {code: attr[1] for attr, code in blocks}
    for doc in docs:
        listing = "\n".join(_listing(doc).numbered())
        assert listing in codes, listing
        assert codes[listing] == ["text"]
    tables = json.dumps([b for b in ast["blocks"] if b["t"] == "Table"])
    assert "dx = x2 - x1" not in tables and "symmetric points" not in tables


PREAMBLE = (
    "\\documentclass{article}\n\\usepackage{booktabs,amsmath,longtable,array,graphicx,tikz}\n"
    "\\begin{document}\n"
)


@pytest.mark.external  # pdflatex, pdftotext
def test_latex_compiles_and_pdftotext_reads_every_line_back(tmp_path: Path) -> None:
    """One batched document (every case from a new page); each listing is read back whole,
    its lines on one page under its title, each line's indentation kept."""
    docs = [document(_answer(key)) for key in CASES]
    body = batch([_text(doc, Format.latex) for doc in docs])
    done = typeset(tmp_path, PREAMBLE + body + "\n\\end{document}\n")
    assert done.code == 0, done.log[-3000:]
    pages = [p.replace("\u2019", "'") for p in pdftotext(tmp_path, done.pdf).split("\f")]
    for doc in docs:
        listing = _listing(doc)
        numbered = listing.numbered()
        want = [" ".join(line.split()) for line in numbered]
        found = [p for p in pages if all(w in _collapsed(p) for w in want)]
        assert found, numbered  # every line, on one page
        page = found[0]
        for w in want:
            assert _collapsed(page).count(w) == 1, w
        assert " ".join(listing.title.split())[:40] in " ".join(page.split())
        # indentation: a line indented further starts its code further right
        column = {n: _code_column(page, w) for n, w in enumerate(want)}
        depth = [len(line) - len(line.lstrip(" ")) for line in listing.lines]
        for n in range(1, len(want)):
            if depth[n] != depth[0]:
                assert (column[n] > column[0]) == (depth[n] > depth[0]), numbered[n]


def _collapsed(page: str) -> list[str]:
    return [" ".join(x.split()) for x in page.splitlines()]


def _code_column(page: str, row: str) -> int:
    """Where the code (after the line number) starts on the page's line reading ``row``."""
    for x in page.splitlines():
        if " ".join(x.split()) == row:
            m = re.match(r"\s*\d+\s+", x)
            assert m is not None
            return m.end()
    raise AssertionError(row)


def test_html_escapes_the_listing_and_does_not_step_through_it() -> None:
    hostile = Document(
        "line",
        "test",
        "t",
        (
            Title("t"),
            Pseudocode("A <b>&</b>", ("if p < 0 && q > 1:", "    </pre><script>x</script>")),
        ),
        {},
    )
    page = _text(hostile, Format.html)
    assert "<script>x" not in page and "<b>&" not in page
    assert "<h3>A &lt;b&gt;&amp;&lt;/b&gt;</h3>" in page
    assert (
        "1  if p &lt; 0 &amp;&amp; q &gt; 1:\n2      &lt;/pre&gt;&lt;script&gt;x&lt;/script&gt;"
        in page
    )
    doc = document(line_solution("bresenham", 2, 2, 10, 6, pseudocode=True))
    page = _text(doc, Format.html)
    pre = re.search(r'<pre class="sc-code"><code>(.*?)</code></pre>', page, re.S)
    assert pre is not None and "data-pos" not in pre.group(1)
    without = stepping(document(line_solution("bresenham", 2, 2, 10, 6)))
    with_code = stepping(doc)
    assert with_code is not None and without is not None
    assert (with_code.n, with_code.captions, with_code.table) == (
        without.n,
        without.captions,
        without.table,
    )


def test_json_keeps_the_lines_and_csv_leaves_them_out() -> None:
    for key in CASES:
        doc = document(_answer(key))
        data = json.loads(_text(doc, Format.json))
        listing = _listing(doc)
        assert data["pseudocode"] == [{"title": listing.title, "lines": list(listing.lines)}]
        assert not any(t["title"].startswith("Algorithm") for t in data.get("tables", []))
    plain = document(line_solution("dda", 2, 2, 10, 6))
    coded = document(line_solution("dda", 2, 2, 10, 6, pseudocode=True))
    assert "pseudocode" not in json.loads(_text(plain, Format.json))
    assert _text(plain, Format.csv) == _text(coded, Format.csv)


QUESTIONS = """title: Pseudocode
[4] line 2 2 10 6 --algorithm
[4] line 2 2 5 10 --algo dda --algorithm
[4] circle 5 --method general --algorithm
[6] ellipse 8 6 --algorithm
"""


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["markdown", "plain", "latex", "html", "json"])
def test_a_worksheet_has_no_pseudocode_table(fmt: str, tmp_path: Path) -> None:
    path = tmp_path / "q.questions"
    path.write_text(QUESTIONS, encoding="utf-8")
    sheet = run("sheet", str(path), "--worksheet", "-f", fmt)
    assert sheet.code == 0, sheet.err
    assert "Algorithm" not in sheet.out and "pseudocode" not in sheet.out
    key = run("sheet", str(path), "-f", fmt)
    assert key.code == 0, key.err
    said = key.out.replace("~", " ")  # latex: fixed spaces
    assert "repeat dx times:" in said  # the key shows it (json: its "pseudocode" lines)
    # the line's question asks for its one table (the pseudocode was counted as a second)
    assert "(10, 6). Show your working and complete the table." in sheet.out


@pytest.mark.slow
def test_the_quiz_and_the_marking_ignore_it() -> None:
    for key in CASES:
        sol = _answer(key)
        assert gap_tables(document(sol)) == gap_tables(document(_bare(sol)))
    data = str(Path(__file__).parent / "data" / "check" / "batch" / "alice.csv")
    marked = run("check", data, "-f", "json", "--", "line", "2", "2", "10", "6", "--algorithm")
    bare_marks = run("check", data, "-f", "json", "--", "line", "2", "2", "10", "6")
    assert marked.code == bare_marks.code == 0, marked.err
    for field in ("derived", "columns", "steps"):
        assert json.loads(marked.out)[field] == json.loads(bare_marks.out)[field], field
    assert "Algorithm" not in marked.out
