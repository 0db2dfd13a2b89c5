"""``scanconv sheet``: question files, answers in one process, keys and worksheets.

The answers of a sheet are checked against ``scanconv`` run on each question alone (the JSON
answer and the Markdown answer), so the sheet cannot drift from the commands it runs; the
worksheet against the key (same tables, same row counts, no answer cell); the documents as a
person sees them: LaTeX through pdflatex (no overfull box), Markdown through pandoc.
"""

from __future__ import annotations

import json
import os
import re
import shutil
from html.parser import HTMLParser
from pathlib import Path

import pytest

from scanconv.cli.sheet import QuestionError, answer_questions, read_questions
from scanconv.render.documents.sheet import md_text, sheet_document

from .external import pandoc, typeset
from .helpers import assert_refused, run

ROOT = Path(__file__).resolve().parent.parent
UNIT2 = ROOT / "golden" / "teach" / "unit2.questions"

#: Command lines of every shape: a group's command, points written as students write them,
#: a formula in quotes, a '#' inside quotes, a file-less option of the command itself.
QUESTIONS = [
    ("line", "2", "2", "10", "6", "--algo", "bresenham"),
    ("line", "(2,8)", "10,4", "--algo", "dda"),
    ("circle", "6", "--method", "general", "--center", "2", "3"),
    ("ellipse", "8", "6"),
    ("compare", "line", "2", "2", "10", "6"),
    ("image", "ramp", "--size", "4", "--levels", "4"),
    ("parametric", "circle", "5", "--samples", "8"),
    ("sample", "x + y", "--size", "4x4", "--levels", "4"),
    ("fill", "flood", "--rows", "#####/#...#/#####", "--seed", "1", "1"),
    ("storage", "1024x768", "--levels", "256"),
    ("bezier", "0", "0", "1", "2", "3", "3", "4", "0", "--at", "1/2"),
    ("quantize", "--bits", "3", "--range", "0", "255"),
    ("line", "-3", "4", "5", "-2", "--algo", "dda", "--rounding", "half-even"),
    ("bspline", "2", "3", "5", "0", "3", "0", "2", "5", "--degree", "3", "--at", "3/4"),
    ("circle", "30", "--center", "-5", "7"),
]


def _file(tmp_path: Path, text: str, name: str = "q.txt") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _line(argv: tuple[str, ...]) -> str:
    import shlex

    return shlex.join(argv)


# --- reading ------------------------------------------------------------------------------------


def test_the_question_file_syntax() -> None:
    text = (
        "# a comment\n"
        "title:  Unit 2   test \n"
        "\n"
        "section: Lines\n"
        "> Draw the line\n"
        "> with DDA.\n"
        "[4] line 2 2 10 6 --algo dda  # trailing comment\n"
        "[1 mark] line 1 1 3 2\n"
        "  [12 MARKS]   circle 5\n"
        "fill flood --rows '#..#' --seed 1 1\n"
        "section: Curves\n"
        "bezier 0 0 1 1 2#0\n"
    )
    sheet = read_questions(text, "f.txt")
    assert sheet.title == "Unit 2 test"
    got = [(q.number, q.line, q.marks, q.section, q.argv) for q in sheet.questions]
    assert got == [
        (1, 7, 4, "Lines", ("line", "2", "2", "10", "6", "--algo", "dda")),
        (2, 8, 1, "Lines", ("line", "1", "1", "3", "2")),
        (3, 9, 12, "Lines", ("circle", "5")),
        (4, 10, None, "Lines", ("fill", "flood", "--rows", "#..#", "--seed", "1", "1")),
        (5, 12, None, "Curves", ("bezier", "0", "0", "1", "1", "2#0")),
    ]
    assert sheet.questions[0].wording == "Draw the line with DDA."
    assert sheet.questions[1].wording == ""
    assert sheet.total_marks == 17


@pytest.mark.parametrize(
    ("text", "line", "words"),
    [
        ("line 1 1 2 2\nline 2 2 'x\n", 2, "unbalanced quotes"),
        ("[x] line 1 1 2 2\n", 1, "[N]"),
        ("[4]\n", 1, "marks without a question"),
        ("title: a\ntitle: b\nline 1 1 2 2\n", 2, "second title"),
        ("title:\nline 1 1 2 2\n", 1, "needs a text"),
        ("line 1 1 2 2\n> dangling\n", 2, "without a question"),
    ],
)
def test_a_malformed_line_names_its_line(text: str, line: int, words: str) -> None:
    with pytest.raises(QuestionError) as err:
        read_questions(text, "f.txt")
    assert err.value.line == line and words in str(err.value)
    assert str(err.value).startswith(f"f.txt:{line}: ")


# --- answering ----------------------------------------------------------------------------------


@pytest.mark.parametrize("argv", QUESTIONS, ids=[" ".join(q[:2]) for q in QUESTIONS])
def test_each_answer_is_the_commands_own_json_answer(argv: tuple[str, ...], tmp_path: Path) -> None:
    alone = run(*argv, "--format", "json")
    assert alone.code == 0, alone.err
    path = _file(tmp_path, f"[3] {_line(argv)}\n")
    sheet = run("sheet", str(path), "--format", "json")
    assert sheet.code == 0, sheet.err
    (question,) = json.loads(sheet.out)["questions"]
    assert question["answer"] == json.loads(alone.out)
    assert question["marks"] == 3 and question["line"] == 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_markdown_key_holds_each_answer_as_the_command_writes_it(tmp_path: Path) -> None:
    path = _file(tmp_path, "".join(_line(q) + "\n" for q in QUESTIONS))
    key = run("sheet", str(path))
    assert key.code == 0, key.err
    for argv in QUESTIONS:
        alone = run(*argv, "--format", "markdown").out
        assert alone.startswith("## ")
        assert "\n### " + alone[3:] in key.out, argv  # the heading one level down
    numbers = re.findall(r"^## Question (\d+)$", key.out, re.M)
    assert numbers == [str(i) for i in range(1, len(QUESTIONS) + 1)]


def test_a_question_keeps_its_display_options() -> None:
    sheet = read_questions("circle 5 --no-grid --exact\ncircle 5 --origin top-left\n")
    (a, b) = answer_questions(sheet.questions)
    assert (a.options.grid, a.options.exact, a.options.origin) == (False, True, "bottom-left")
    assert (b.options.grid, b.options.origin) == (True, "top-left")


#: Bad questions, and for each one the command line scanconv refuses the same way (``None``:
#: the refusal is the sheet's own).
BAD = [
    ("circle 2.5", ("circle", "2.5")),
    ("line 1 2 3", ("line", "1", "2", "3")),
    ("line 0 0 1e10 1", ("line", "0", "0", "1e10", "1")),
    ("line 2 2 10 6 --algo zzz", ("line", "2", "2", "10", "6", "--algo", "zzz")),
    ("line 2 2 10 6 --bogus", ("line", "2", "2", "10", "6", "--bogus")),
    ("circle 5 --center 1", ("circle", "5", "--center", "1")),
    ("bspline 0 0 1 2 3 3 --degree 5", ("bspline", "0", "0", "1", "2", "3", "3", "--degree", "5")),
    ("lin 2 2 10 6", None),
    ("image", None),
    ("line 2 2 10 6 --help", None),
    ("line 2 2 10 6 -o x.md", None),
    ("line 2 2 10 6 --format latex", None),
    ("line 2 2 10 6 --svg x.svg", None),
    ("sheet other.txt", None),
    ("practice --seed 1", None),
    ("--version", None),
]


@pytest.mark.parametrize(("text", "alone"), BAD, ids=[b[0] for b in BAD])
def test_a_bad_question_is_refused_with_its_line_and_scanconvs_message(
    text: str, alone: tuple[str, ...] | None, tmp_path: Path
) -> None:
    path = _file(tmp_path, f"title: T\n\nline 2 2 10 6\n{text}\n")
    target = tmp_path / "key.md"
    r = run("sheet", str(path), "-o", str(target))
    assert_refused(r, f"{path}:4: ")
    assert not target.exists() and sorted(p.name for p in tmp_path.iterdir()) == ["q.txt"]
    if alone is not None:
        expected = run(*alone).err
        assert expected.startswith("scanconv: error: ")
        assert r.err == expected.replace("scanconv: error: ", f"scanconv: error: {path}:4: ")


def test_an_answer_too_long_for_a_sheet_is_refused_quickly(tmp_path: Path) -> None:
    r = run("sheet", str(_file(tmp_path, "line 1 1 3 2\nline 0 0 100000000 1\n")))
    assert_refused(r, "q.txt:2: ", "100,000,001 table rows", "at most 200,000")


def test_unknown_commands_get_a_suggestion(tmp_path: Path) -> None:
    r = run("sheet", str(_file(tmp_path, "lin 2 2 10 6\n")))
    assert_refused(r, "No such command 'lin'", "did you mean 'line'?")
    r = run("sheet", str(_file(tmp_path, "image\n")))
    assert_refused(r, "'image' needs one of its commands", "ramp")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_one_bad_line_in_200_writes_nothing(tmp_path: Path) -> None:
    lines = [f"[2] line 0 0 {8 + i % 5} {i % 7} --algo dda" for i in range(200)]
    lines[136] = "circle 5 --method sideways"
    path = _file(tmp_path, "title: Big\n" + "\n".join(lines) + "\n")
    target = tmp_path / "key.out"
    target.write_text("precious\n")
    for extra in ((), ("--worksheet",), ("--format", "json"), ("--format", "latex")):
        r = run("sheet", str(path), "--output", str(target), *extra)
        assert_refused(r, f"{path}:138: ", "'sideways'")
    assert target.read_text() == "precious\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["key.out", "q.txt"]


def test_every_bad_line_of_a_file_is_reported_at_once(tmp_path: Path) -> None:
    """``sheet`` named only the first bad line, so a teacher fixed a file one
    run at a time. Now each bad line, of the file's syntax or of its question, has its own
    line on stderr, in the file's order; exit 2, nothing on stdout, nothing written."""
    text = (
        "title: T\n"
        "line 2 2 10 6\n"
        "line 2 2\n"  # 3: a missing argument
        "[x] circle 5\n"  # 4: marks misspelt
        "circle 5 --method sideways\n"  # 5: an unknown method
        "circle 8\n"
        "line 1 1 'x\n"  # 7: unbalanced quotes
        "title: again\n"  # 8: a second title
    )
    path = _file(tmp_path, text)
    target = tmp_path / "key.md"
    r = run("sheet", str(path), "-o", str(target))
    assert r.code == 2 and r.out == "" and "Traceback" not in r.err
    lines = r.err.splitlines()
    assert all(ln.startswith(f"scanconv: error: {path}:") for ln in lines), lines
    assert [int(ln.split(f"{path}:")[1].split(":")[0]) for ln in lines] == [3, 4, 5, 7, 8]
    assert "Missing argument 'X2'" in lines[0] and "'sideways'" in lines[2]
    assert "unbalanced quotes" in lines[3] and "second title" in lines[4]
    assert not target.exists() and sorted(p.name for p in tmp_path.iterdir()) == ["q.txt"]


def test_unreadable_question_files(tmp_path: Path) -> None:
    assert_refused(run("sheet", str(tmp_path / "missing.txt")), "missing.txt", "No such file")
    assert_refused(run("sheet", str(tmp_path)), "is a directory")
    assert_refused(run("sheet", ""), "empty", "''")
    binary = tmp_path / "b.txt"
    binary.write_bytes(b"line 2 2\x00\xff 10 6\n")
    assert_refused(run("sheet", str(binary)), "not a text file")
    latin = tmp_path / "l.txt"
    latin.write_bytes("title: caf\xe9\nline 2 2 10 6\n".encode("latin-1"))
    assert_refused(run("sheet", str(latin)), "not UTF-8")
    empty = _file(tmp_path, "# nothing\n\n", "e.txt")
    assert_refused(run("sheet", str(empty)), "holds no question")


def test_questions_from_standard_input(monkeypatch: pytest.MonkeyPatch) -> None:
    import io

    monkeypatch.setattr("sys.stdin", io.StringIO("[5] circle 3\n"))
    r = run("sheet", "-", "--format", "json")
    assert r.code == 0, r.err
    assert json.loads(r.out)["questions"][0]["marks"] == 5


def test_the_output_format_follows_the_file_name(tmp_path: Path) -> None:
    path = _file(tmp_path, "circle 3\n")
    for name, start in (("k.tex", "% scanconv sheet"), ("k.json", "{"), ("k.md", "## Question 1")):
        assert run("sheet", str(path), "-o", str(tmp_path / name)).code == 0
        assert (tmp_path / name).read_text().startswith(start), name
    assert_refused(run("sheet", str(path), "-f", "json", "-o", str(tmp_path / "x.tex")), "latex")
    assert not (tmp_path / "x.tex").exists()


# --- worksheets ---------------------------------------------------------------------------------


def _tables(markdown: str) -> list[list[list[str]]]:
    """The pipe tables of a Markdown document, as rows of stripped cells (no rule line)."""
    tables: list[list[list[str]]] = []
    current: list[list[str]] | None = None
    fenced = False
    for line in markdown.splitlines():
        fenced ^= line.startswith("```")
        if line.startswith("|") and not fenced:
            if current is None:
                current = []
                tables.append(current)
            if not re.fullmatch(r"\|[-:|]+\|", line):
                current.append([c.strip() for c in line.strip("|").split(" | ")])
        else:
            current = None
    return tables


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_worksheet_has_the_keys_tables_emptied(tmp_path: Path) -> None:
    path = _file(tmp_path, "".join(_line(q) + "\n" for q in QUESTIONS))
    key = run("sheet", str(path), "--key").out
    sheet = run("sheet", str(path), "--worksheet").out
    key_tables = _tables(key)
    blank_tables = _tables(sheet)
    assert len(key_tables) == len(blank_tables) > len(QUESTIONS)
    for full, blank in zip(key_tables, blank_tables, strict=True):
        assert full[0] == blank[0]  # the same headings
        assert len(full) == len(blank)  # the same number of rows
        for answer_row, blank_row in zip(full[1:], blank[1:], strict=True):
            assert blank_row[0] in ("", answer_row[0])  # a row's label (k) is given
            assert blank_row[0] == answer_row[0] or full[0][0] != "$k$"
            assert all(c == "" for c in blank_row[1:])
    for hidden in ("Pixels plotted", "Working", "```"):
        assert hidden not in sheet
    assert "scanconv line" not in sheet  # the command would give the answer away


def test_the_worksheet_words_the_question_and_states_the_given_values(tmp_path: Path) -> None:
    path = _file(tmp_path, "> Draw it with DDA.\n[4] line 2 2 10 6 --algo dda\ncircle 5\n")
    sheet = run("sheet", str(path), "--worksheet").out
    assert "## Question 1 (4 marks)\n\nDraw it with DDA.\n\n**Given:** $P_1 = (2, 2)$" in sheet
    assert "Midpoint circle algorithm: r = 5, centre (0, 0). Show your working" in sheet


def test_a_worksheet_in_json_gives_the_row_counts(tmp_path: Path) -> None:
    path = _file(tmp_path, "line 2 2 10 6\nstorage 8 8 --bits 1\n")
    doc = json.loads(run("sheet", str(path), "--worksheet", "-f", "json").out)
    line, storage = doc["questions"]
    assert line["tables"] == [
        {"title": "Step table", "columns": ["k", "p", "decision", "pixel", "p_next"], "rows": 9}
    ]
    assert "answer" not in line and "command" not in line
    assert storage["tables"][0]["columns"][0] == "unit"


# --- escaping -----------------------------------------------------------------------------------

HOSTILE = r"A|B <script>alert(1)</script> \input{/etc/passwd} \write18{rm} $x$ 50% #1 & {_} ~ ^"


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_user_text_is_escaped_in_every_format(tmp_path: Path) -> None:
    path = _file(tmp_path, f"title: {HOSTILE}\nsection: {HOSTILE}\n> {HOSTILE}\nline 2 2 5 4\n")
    tex = run("sheet", str(path), "-f", "latex", "--standalone").out
    assert "\\input{" not in tex and "\\write18" not in tex
    assert "A\\textbar{}B \\textless{}script\\textgreater{}" in tex
    assert "50\\% \\#1 \\& \\{\\_\\} \\textasciitilde{} \\textasciicircum{}" in tex
    md = run("sheet", str(path)).out
    assert md.startswith("# " + md_text(HOSTILE) + "\n")
    assert "<script>" not in md and "A\\|B" in md
    plain = run("sheet", str(path), "-f", "plain").out
    assert plain.isascii()
    doc = json.loads(run("sheet", str(path), "-f", "json").out)
    assert doc["title"] == " ".join(HOSTILE.split())


@pytest.mark.external
def test_markdown_through_pandoc_shows_user_text_literally(tmp_path: Path) -> None:
    path = _file(tmp_path, f"title: {HOSTILE}\n[2] line 2 2 10 6\n")
    for kind in ("--key", "--worksheet"):
        html = pandoc(tmp_path, run("sheet", str(path), kind).out, "markdown")
        assert "<script>" not in html and "&lt;script&gt;alert(1)&lt;/script&gt;" in html
        assert html.count("<table") == 1
        body = html.split("<tbody>")[1].split("</tbody>")[0]
        assert body.count("<tr") == 9  # (2, 2) to (10, 6): 9 rows


# --- HTML ---------------------------------------------------------------------------------------


class _Page(HTMLParser):
    """What the HTML checks need: the tags seen, the text, the rows of each table."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.text: list[str] = []
        self.tables: list[list[list[str]]] = []
        self._row: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: list) -> None:
        self.tags.append(tag)
        if tag == "table":
            self.tables.append([])
        elif tag == "tr":
            self._row = []
        elif tag in ("td", "th") and self._row is not None:
            self._row.append("")

    def handle_endtag(self, tag: str) -> None:
        if tag == "tr" and self._row is not None:
            self.tables[-1].append(self._row)
            self._row = None

    def handle_data(self, data: str) -> None:
        self.text.append(data)
        if self._row:
            self._row[-1] += data.strip()


def test_the_html_worksheet_escapes_user_text_and_has_the_keys_row_counts(tmp_path: Path) -> None:
    path = _file(tmp_path, f"title: {HOSTILE}\n> {HOSTILE}\n[2] line 2 2 10 6\ncircle 5\n")
    r = run("sheet", str(path), "--worksheet", "-f", "html")
    assert r.code == 0, r.err
    page = _Page()
    page.feed(r.out)
    assert "script" not in page.tags
    assert HOSTILE in "".join(page.text).replace("\n", "")
    key = json.loads(run("sheet", str(path), "-f", "json").out)
    expected = [len(key["questions"][0]["answer"]["steps"])]
    expected += [len(key["questions"][1]["answer"]["steps"])]
    expected += [len(t["rows"]) for t in key["questions"][1]["answer"]["tables"]]
    assert [len(t) - 1 for t in page.tables] == expected  # a heading row, then the rows
    assert all(c == "" for t in page.tables for row in t[1:] for c in row[1:])


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_html_key_holds_each_answers_section_and_escapes_user_text(tmp_path: Path) -> None:
    from scanconv.render.mappings.html import answer_section

    path = _file(tmp_path, f"title: {HOSTILE}\n> {HOSTILE}\n[2] line 2 2 10 6\ncircle 5\n")
    r = run("sheet", str(path), "-f", "html")
    assert r.code == 0, r.err
    assert "<script>alert" not in r.out and r.out.count("<h1>") == 1
    page = _Page()
    page.feed(r.out)
    assert HOSTILE in "".join(page.text).replace("\n", "")
    sheet = read_questions(path.read_text(), str(path))
    for a in answer_questions(sheet.questions):
        section = answer_section(a.solution, f"sc{a.question.number}", a.options, level=3)
        assert section in r.out  # the HTML renderer's own answer, whole


@pytest.mark.external
def test_the_html_key_steps_each_answer_on_its_own_in_chromium(tmp_path: Path, browser) -> None:
    page_file = tmp_path / "k.html"
    assert run("sheet", str(UNIT2), "-f", "html", "-o", str(page_file)).code == 0
    # the session's browser (tests/conftest.py)
    page = browser.new_page(viewport={"width": 1300, "height": 1000})
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(page_file.as_uri())
    sections = page.locator("section.scanconv").count()
    page.locator("#sc2").click()
    page.keyboard.press("ArrowRight")
    page.keyboard.press("ArrowRight")
    positions = [page.get_attribute(f"#sc{i}", "data-pos") for i in (1, 2)]
    page.screenshot(path=str(tmp_path / "k.png"))
    page.close()
    assert sections == 5 and not errors
    assert positions == ["0", "2"]


@pytest.mark.external
def test_the_html_worksheet_in_chromium(tmp_path: Path, browser) -> None:
    page_file = tmp_path / "w.html"
    path = _file(tmp_path, f"title: {HOSTILE}\n[2] line 2 2 10 6\n")
    assert run("sheet", str(path), "--worksheet", "-o", str(page_file)).code == 0
    # the session's browser (tests/conftest.py)
    page = browser.new_page(viewport={"width": 900, "height": 1000})
    dialogs: list[str] = []
    page.on("dialog", lambda d: (dialogs.append(d.message), d.dismiss()))
    page.goto(page_file.as_uri())
    rows = page.locator("table.sc-blank tbody tr").count()
    heading = page.locator("h1").inner_text()
    width = page.evaluate("document.documentElement.scrollWidth")
    page.screenshot(path=str(tmp_path / "w.png"))
    page.close()
    assert rows == 9 and not dialogs
    assert heading == " ".join(HOSTILE.split())
    assert width <= 900  # nothing runs off the side


# --- LaTeX and PDF ------------------------------------------------------------------------------


def _pdflatex() -> str:
    found = shutil.which("pdflatex")
    if not found:
        pytest.skip("pdflatex not installed")
    return found


def _compile(tmp_path: Path, tex: str) -> str:
    """Two passes (longtable's widths); the last log."""
    done = typeset(tmp_path, tex, passes=2)
    assert done.code == 0, done.log[-3000:]
    return done.log


@pytest.mark.external
@pytest.mark.parametrize("kind", ["--key", "--worksheet"])
def test_latex_sheets_compile_paginated_per_question_with_no_overfull_box(
    kind: str, tmp_path: Path
) -> None:
    path = _file(
        tmp_path,
        f"title: {HOSTILE}\n" + "".join(f"[2] {_line(q)}\n" for q in QUESTIONS),
    )
    r = run("sheet", str(path), kind, "--format", "latex", "--standalone")
    assert r.code == 0, r.err
    # A question starts on a new page when it does not fit (\\scneed), not always.
    starts = re.findall(r"\\scneed\{\d+pt\}\n\\(?:sub)?section\*", r.out)
    assert len(starts) == len(QUESTIONS) - 1
    log = _compile(tmp_path, r.out)
    assert "Overfull \\hbox" not in log and "Overfull \\vbox" not in log
    pages = re.search(r"Output written on doc\.pdf \((\d+) pages?", log)
    assert pages and int(pages.group(1)) >= 1


@pytest.mark.external
def test_pdf_is_written_atomically(tmp_path: Path) -> None:
    _pdflatex()
    target = tmp_path / "key.pdf"
    r = run("sheet", str(UNIT2), "--pdf", str(target))
    assert r.code == 0 and r.out == "", r.err
    assert target.read_bytes().startswith(b"%PDF")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["key.pdf"]
    r = run("sheet", str(UNIT2), "--pdf", str(tmp_path / "missing" / "key.pdf"))
    assert r.code == 1 and r.err.startswith("scanconv: error: cannot write") and r.out == ""
    assert sorted(p.name for p in tmp_path.iterdir()) == ["key.pdf"]


def test_pdf_without_pdflatex_is_one_line_and_exit_1(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("PATH", str(tmp_path / "nowhere"))
    target = tmp_path / "key.pdf"
    r = run("sheet", str(UNIT2), "--pdf", str(target))
    assert r.code == 1 and r.out == ""
    assert r.err.startswith("scanconv: error: --pdf needs pdflatex") and r.err.count("\n") == 1
    assert not target.exists()


def test_a_failing_pdflatex_is_exit_1_and_leaves_the_old_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    fake = tmp_path / "bin"
    fake.mkdir()
    script = fake / "pdflatex"
    script.write_text("#!/bin/sh\necho '! Emergency stop.' > sheet.log\nexit 1\n")
    script.chmod(0o755)
    monkeypatch.setenv("PATH", f"{fake}{os.pathsep}{os.environ['PATH']}")
    target = tmp_path / "key.pdf"
    target.write_bytes(b"old")
    r = run("sheet", str(UNIT2), "--pdf", str(target))
    assert r.code == 1 and "pdflatex failed: Emergency stop." in r.err, r.err
    assert target.read_bytes() == b"old"


# --- the library ----------------------------------------------------------------------------


def test_the_library_renders_a_sheet_without_the_cli() -> None:
    sheet = read_questions("title: T\n[3] line 2 2 10 6\n", "lib")
    answered = answer_questions(sheet.questions, sheet.source)
    text = sheet_document(sheet, answered, "key", "markdown")
    assert text.startswith("# T\n\nAnswer key: 1 question, 3 marks.\n")
    assert "(10, 6)" in text
    with pytest.raises(ValueError, match="unknown sheet format"):
        sheet_document(sheet, answered, "key", "docx")
