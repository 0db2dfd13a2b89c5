"""The table of contents is a block of the document: :class:`Contents`, mapped by
every format like any other block, for the exam book and for ``sheet --contents``. The exam
command composes nothing itself."""

from __future__ import annotations

import json
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest
from rich.cells import cell_len

from scanconv.document import Contents, Entry
from scanconv.render import Options
from scanconv.render.documents.sheet import Question, Sheet, contents_block, contents_document
from scanconv.render.mappings.terminal import RICH

from .external import pandoc, pdftotext, typeset
from .helpers import run

ROOT = Path(__file__).resolve().parent.parent

HOSTILE = """\
title: Week <3> & $\\input{/etc/hostname}$
section: Lines & <b>bold</b> $x_1$ % 50
> Draw the line *from* (2, 2) [to](http://example.com) (10, 6) <i>now</i>.
line 2 2 10 6 --algo bresenham
line 0 0 3 1 --algo dda
section: Circles
circle 3 --method midpoint
"""
"""A question file whose section and wording are markup in every format: each must come
out as text."""


@pytest.fixture(scope="module")
def questions(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("contents") / "q.txt"
    path.write_text(HOSTILE, encoding="utf-8")
    return path


def _sheet(questions: Path, fmt: str, *more: str) -> str:
    r = run("sheet", str(questions), "--contents", "-f", fmt, *more)
    assert r.code == 0, r.err
    return r.out


def test_the_exam_command_formats_nothing_itself() -> None:
    source = (ROOT / "scanconv" / "cli" / "exam.py").read_text(encoding="utf-8")
    for markup in ("tableofcontents", "addcontentsline", "<nav", "## Contents", "Contents\\n--"):
        assert markup not in source, markup


def test_the_block_groups_the_questions_by_section_in_order() -> None:
    sheet = Sheet(
        "T",
        (
            Question(1, 1, ("line", "0", "0", "1", "1"), wording="A\n  b", section="S"),
            Question(2, 2, ("circle", "3"), section="S"),
            Question(3, 3, ("circle", "4"), wording="C", section="U"),
        ),
    )
    block = contents_block(sheet, linked=False)
    assert block == Contents(
        (Entry(1, "A b", "S"), Entry(2, "scanconv circle 3", "S"), Entry(3, "C", "U")), False
    )
    assert [(s, [e.number for e in es]) for s, es in block.sections()] == [
        ("S", [1, 2]),
        ("U", [3]),
    ]
    alone = json.loads(contents_document(sheet, "json"))
    assert alone["contents"][1] == {"number": 2, "section": "S", "question": "scanconv circle 3"}
    with pytest.raises(ValueError, match="not available in html"):
        contents_document(sheet, "html")


def test_a_sheet_has_contents_only_when_asked(questions: Path) -> None:
    plain = run("sheet", str(questions), "-f", "plain").out
    assert "Contents\n--------" not in plain
    listed = _sheet(questions, "plain")
    head = listed.split("Contents\n--------\n\n", 1)[1].split("\n\n", 1)[0].splitlines()
    assert head == [
        "Lines & <b>bold</b> $x_1$ % 50",
        "  1. Draw the line *from* (2, 2) [to](http://example.com) (10, 6) <i>now</i>.",
        "  2. Simple DDA line algorithm: (0, 0) to (3, 1). Show your working and complete "
        "the table.",
        "Circles",
        "  3. Midpoint circle algorithm: r = 3, centre (0, 0). Show your working and "
        "complete the tables.",
    ]


def test_a_worksheet_lists_its_own_wording_not_the_commands(questions: Path) -> None:
    out = _sheet(questions, "markdown", "--worksheet")
    contents = out.split("## Contents", 1)[1].split("\n## ", 1)[0]
    assert "scanconv" not in contents and "2. Simple DDA line algorithm" in contents


class _Nav(HTMLParser):
    """The elements inside the contents' ``<nav>`` and its text."""

    def __init__(self) -> None:
        super().__init__()
        self.inside = False
        self.tags: list[str] = []
        self.links: list[str] = []
        self.text: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "nav":
            self.inside = True
        elif self.inside:
            self.tags.append(tag)
            self.links += [v or "" for k, v in attrs if k == "href"]

    def handle_endtag(self, tag: str) -> None:
        self.inside = self.inside and tag != "nav"

    def handle_data(self, data: str) -> None:
        if self.inside:
            self.text.append(data)


def test_html_contents_link_every_question_and_show_markup_as_text(questions: Path) -> None:
    page = _sheet(questions, "html")
    nav = _Nav()
    nav.feed(page)
    assert set(nav.tags) <= {"h2", "ul", "ol", "li", "a"}  # no <b>, no <i> from the file
    assert nav.links == ["#q1", "#q2", "#q3"]
    for link in nav.links:
        assert page.index(f'id="{link[1:]}"') > page.index("</nav>")
    text = "".join(nav.text)
    assert "<b>bold</b>" in text and "<i>now</i>" in text


@pytest.mark.external
def test_markdown_contents_stay_text_through_pandoc(questions: Path, tmp_path: Path) -> None:
    html = pandoc(tmp_path, _sheet(questions, "markdown"), "markdown")
    nav = html.split('id="contents"', 1)[1].split("<h2", 1)[0]
    assert "<b>" not in nav and "<i>" not in nav and "<em>" not in nav
    assert 'href="http://example.com"' not in nav and "&lt;b&gt;bold&lt;/b&gt;" in nav
    assert len(re.findall(r"<li>", nav)) == 5  # two sections, three questions


@pytest.mark.external
@pytest.mark.slow
def test_latex_contents_have_page_numbers_and_markup_as_text(
    questions: Path, tmp_path: Path
) -> None:
    tex = _sheet(questions, "latex", "--standalone")
    assert tex.count("\\addcontentsline{toc}{subsection}") == 3
    assert tex.count("\\addcontentsline{toc}{section}") == 2
    done = typeset(tmp_path, tex, passes=2)
    assert done.code == 0, done.log[-2000:]
    first = pdftotext(tmp_path, done.pdf).split("\f")[0]
    assert "Contents" in first and "/etc/hostname" in first  # the title, as text
    # (pdftotext reads the underscore of the typewriter-less font as a space)
    assert re.search(r"Lines & <b>bold</b> \$x.1\$ % 50\s+\d+\n", first), first
    assert re.search(r"3\. Midpoint circle algorithm.*tables\.\s+\d+\n", first), first


@pytest.mark.parametrize("width", [60, 80, 120])
def test_the_terminal_contents_fit_the_width(width: int) -> None:
    long = "Explain the midpoint circle algorithm and derive its decision parameter " * 2
    block = Contents((Entry(1, long.strip(), "Circle drawing"), Entry(12, "Define it.", "")))
    lines = [t.plain for t in RICH[Contents](block, Options(), width, [])]
    assert lines[0] == "Contents" and lines[1] == "Circle drawing"
    assert all(cell_len(line) <= width for line in lines)
    words = " ".join(line.strip() for line in lines[2:-2])
    assert words == f"1. {long.strip()}"
    assert lines[-2] == "  12. Define it."
