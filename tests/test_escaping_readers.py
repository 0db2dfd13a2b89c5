"""Hostile text read back as each output's reader reads it (attack report D3, D4, D8, D9, D19).

Student file names (``check --batch``), question text and formula comments reach every format;
each test feeds one hostile text through the command a teacher runs and reads the output as its
reader would: LaTeX through pdflatex (no file read), Markdown through pandoc (``markdown`` and
``gfm``: no ``<img>``, ``<script>``, link or ``javascript:`` element from user text), the terminal
formats (no escape sequence), and every format for bidirectional overrides.
"""

from __future__ import annotations

import json
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from scanconv.render import formats
from scanconv.render.mappings.latex import _cell
from tests.external import pandoc, typeset
from tests.helpers import run
from tests.test_print import Visible

STUDENT = "k,p_k,x,y\n0,0,2,2\n"
QUESTION = ("--", "line", "2", "2", "10", "6")

TEX_NAMES = ("0\\input{^^2fetc^^2fhostname}.csv", "(\\input{^^2fetc^^2fpasswd}).csv")
HTML_NAMES = (
    "<img src=x onerror=alert(1)>.csv",
    "*bold* [l](javascript:alert(2)).csv",
    "www.a.bc><img src=x onerror=alert(3)>.csv",
    "x@a.bc><img src=x onerror=alert(4)>.csv",
)
ESC = "\x1b"
TERMINAL_NAME = f"a{ESC}[31mRED{ESC}]0;TITLE\x07{ESC}[2J.csv"
BIDI = "\u202e"
BIDI_NAME = f"exam{BIDI}vsc.csv"


def _folder(tmp_path: Path, *names: str) -> Path:
    folder = tmp_path / "c"
    folder.mkdir()
    for name in names:
        (folder / name).write_text(STUDENT)
    return folder


def _batch(folder: Path, fmt: str) -> str:
    r = run("check", "--batch", str(folder), "-f", fmt, *QUESTION)
    assert r.code == 0, r.err
    return r.out


# --- D3: LaTeX ---------------------------------------------------------------------------------


@pytest.mark.parametrize("name", TEX_NAMES)
def test_latex_cell_of_a_file_name_is_text(name: str) -> None:
    tex = _cell(name)
    assert "\\input" not in tex and "^^" not in tex and not tex.startswith("$"), tex


def test_latex_score_table_never_sets_a_name_in_math(tmp_path: Path) -> None:
    out = _batch(_folder(tmp_path, *TEX_NAMES), "latex")
    assert "\\input" not in out and "^^" not in out, out
    assert "\\textbackslash{}input" in out  # the name is shown, as text


@pytest.mark.external
@pytest.mark.slow
def test_latex_score_table_reads_no_file_when_compiled(tmp_path: Path) -> None:
    body = _batch(_folder(tmp_path, *TEX_NAMES), "latex")
    done = typeset(
        tmp_path,
        "\\documentclass{article}\\usepackage{booktabs,amsmath,longtable,tikz}\n"
        f"\\begin{{document}}\n{body}\\end{{document}}\n",
    )
    log = done.log
    assert done.pdf.exists(), log[-2000:]
    assert "/etc/hostname" not in log and "/etc/passwd" not in log, log[-2000:]


# --- D4, D8: Markdown through pandoc ------------------------------------------------------------


class _Elements(HTMLParser):
    """The elements and link targets of an HTML fragment."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.urls: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        self.urls += [v or "" for k, v in attrs if k in ("href", "src", "onerror", "onload")]


def _pandoc_html(scratch: Path, markdown: str, flavour: str) -> _Elements:
    html = pandoc(scratch, markdown, flavour)
    parsed = _Elements()
    parsed.feed(html)
    return parsed


def _assert_inert(scratch: Path, markdown: str) -> None:
    for flavour in ("gfm", "markdown"):
        page = _pandoc_html(scratch, markdown, flavour)
        bad = {"img", "script", "a", "link", "iframe", "style", "svg", "math", "object", "embed"}
        assert not bad & set(page.tags), (flavour, page.tags, markdown[:600])
        assert not any("javascript:" in u or "alert" in u for u in page.urls), (flavour, page.urls)


@pytest.mark.external
def test_markdown_score_sheet_is_inert_through_pandoc(tmp_path: Path) -> None:
    _assert_inert(tmp_path, _batch(_folder(tmp_path, *HTML_NAMES), "markdown"))


@pytest.mark.external
@pytest.mark.parametrize("name", HTML_NAMES)
def test_markdown_single_marking_is_inert_through_pandoc(tmp_path: Path, name: str) -> None:
    folder = _folder(tmp_path, name)
    r = run("check", str(folder / name), "-f", "markdown", *QUESTION)
    assert r.code == 0, r.err
    _assert_inert(tmp_path, r.out)


@pytest.mark.external
def test_markdown_question_comment_is_inert_through_pandoc(tmp_path: Path) -> None:
    (tmp_path / "p.csv").write_text("k,x,y\n0,0,0\n1,1,1\n")
    r = run(
        "check", str(tmp_path / "p.csv"), "-f", "markdown", "--", "parametric", "custom",
        "--x", "t # <img src=x onerror=alert(7)> http://a.b/><img src=x>", "--y", "t",
        "--samples", "2",
    )  # fmt: skip
    assert r.code == 0, r.err
    _assert_inert(tmp_path, r.out)


AUTOLINKS = (
    "T http://a.b/><img src=x onerror=alert(document.domain)//>",
    "T https://a.b/><link rel=stylesheet href=http://c.d/x.css>",
    "T www.a.b/><img src=x onerror=alert(5)//>",
    "T mailto:x@a.b/><img src=x onerror=alert(6)//>",
)


@pytest.mark.external
@pytest.mark.parametrize("title", AUTOLINKS)
def test_markdown_sheet_title_autolink_is_inert(tmp_path: Path, title: str) -> None:
    q = tmp_path / "q.txt"
    q.write_text(f"title: {title}\nsection: {title}\n> {title}\nline 2 2 10 6\n")
    for kind in ("key", "worksheet"):
        r = run("sheet", str(q), "-f", "markdown", f"--{kind}")
        assert r.code == 0, r.err
        _assert_inert(tmp_path, r.out)


@pytest.mark.external
@pytest.mark.parametrize("title", AUTOLINKS[:1])
def test_markdown_formula_comment_autolink_is_inert(tmp_path: Path, title: str) -> None:
    for argv in (
        ("sample", f"x + y # {title}", "--size", "3", "-L", "2"),
        ("parametric", "custom", "--x", f"t # {title}", "--y", "t", "--samples", "2"),
    ):
        r = run(*argv, "-f", "markdown")
        assert r.code == 0, r.err
        _assert_inert(tmp_path, r.out)


# --- D9: terminal escape sequences ----------------------------------------------------------


@pytest.mark.parametrize("fmt", ("csv", "plain", "rich", "markdown", "json", "latex"))
def test_score_sheet_carries_no_control_character(tmp_path: Path, fmt: str) -> None:
    out = _batch(_folder(tmp_path, TERMINAL_NAME, BIDI_NAME), fmt)
    assert not re.search("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]", out), out
    assert "RED" in out  # the file is still named


# --- D19: bidirectional overrides and formula comments ----------------------------------------

SHEET_FORMATS = tuple(f for f in formats("document") if f in formats("answer"))


@pytest.mark.parametrize("fmt", SHEET_FORMATS)
@pytest.mark.parametrize("kind", ("key", "worksheet"))
def test_bidi_override_never_reaches_a_sheet(tmp_path: Path, fmt: str, kind: str) -> None:
    q = tmp_path / "q.txt"
    q.write_text(f"title: Unit 2 {BIDI}fdp.exe\n> Draw {BIDI}it\nline 2 2 10 6\n")
    r = run("sheet", str(q), "-f", fmt, f"--{kind}")
    assert r.code == 0, r.err
    assert BIDI not in r.out
    if fmt == "json":
        assert BIDI in json.loads(r.out)["title"]  # escaped, the data unchanged


@pytest.mark.parametrize("fmt", formats("answer"))
def test_bidi_override_in_a_formula_comment(fmt: str) -> None:
    r = run("sample", f"x + y # {BIDI}abc", "--size", "3", "-L", "2", "-f", fmt)
    assert r.code == 0, r.err
    assert BIDI not in r.out


def test_formula_comment_in_html_math_is_shown_as_typed() -> None:
    typed = "x + y # <b>{a}</b> --z"
    r = run("sample", typed, "--size", "3", "-L", "2", "-f", "html")
    assert r.code == 0, r.err
    page = Visible(hide=("script", "style"))
    page.feed(r.out)
    text = "".join(page.parts)
    assert "# <b>{a}</b> --z" in text
    for raw in ("\\textless", "\\textgreater", "\\#", "\\{", "-{}"):
        assert raw not in text, raw
