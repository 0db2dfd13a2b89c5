"""One format system: every format, single answers and documents (sheets, the exam book,
practice sets, quiz files), is declared once in :data:`scanconv.render.FORMATS`; the CLI's
choices, its extension map and its one rule of format conflicts are read from it."""

from __future__ import annotations

import io
from importlib import import_module
from pathlib import Path

import pytest

from scanconv.cli.sheet import answer_questions, read_questions
from scanconv.render import EXTENSIONS, FORMATS, Format, formats, load
from scanconv.render.documents.sheet import Answered, sheet_document

from .helpers import assert_refused, run


@pytest.mark.parametrize("name", list(FORMATS))
def test_every_format_is_one_entry_whose_extensions_and_writers_map_back_to_it(name: str) -> None:
    spec = FORMATS[name]
    assert spec.serves, f"{name} writes nothing"
    for ext in spec.extensions:
        assert ext.startswith(".") and ext == ext.lower()
        assert EXTENSIONS[ext] == name
    for entry in (spec.renderer, spec.sheet):
        if entry:
            module, function = entry.split(":")
            assert callable(getattr(import_module(f"scanconv.render.{module}"), function))
            assert load(entry) is getattr(import_module(f"scanconv.render.{module}"), function)
    assert ("answer" in spec.serves) == (name in Format.__members__)


def test_the_extension_map_holds_only_the_tables_extensions() -> None:
    declared = [ext for spec in FORMATS.values() for ext in spec.extensions]
    assert len(declared) == len(set(declared)), "an extension names two formats"
    assert set(EXTENSIONS) == set(declared)


def test_the_single_answer_formats_are_the_format_enum() -> None:
    assert [f.value for f in Format] == ["auto", *sorted(formats("answer"), key=_enum_order)]
    assert set(formats("answer")) | set(formats("document")) == set(FORMATS)


def _enum_order(name: str) -> int:
    return list(Format.__members__).index(name)


def test_the_document_commands_offer_the_tables_document_formats() -> None:
    for command in ("sheet", "exam", "practice"):
        r = run(command, "--format", "csv")
        assert_refused(r, "'csv' is not one of", *(f"'{f}'" for f in formats("document")))
        assert "'rich'" not in r.err
    assert_refused(run("line", "0", "0", "3", "1", "--format", "moodle"), "'moodle' is not one")


@pytest.fixture
def questions(tmp_path: Path) -> Path:
    path = tmp_path / "q.txt"
    path.write_text("[2] line 0 0 3 1\n", encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("ext", "fmt"),
    [(".tex", "json"), (".csv", "markdown"), (".json", "latex"), (".html", "plain"),
     (".xml", "json"), (".gift", "latex"), (".htm", "markdown")],
)  # fmt: skip
def test_answers_and_documents_refuse_the_same_conflicts(
    tmp_path: Path, questions: Path, ext: str, fmt: str
) -> None:
    """A --format that contradicts a file whose extension binds is refused by every command,
    with the same one line, and nothing is written."""
    target = tmp_path / f"a{ext}"
    named = EXTENSIONS[ext]
    assert FORMATS[named].binding
    words = f"--output {target} is {named} by its extension, but --format is {fmt}"
    answer = run("line", "0", "0", "3", "1", "-o", str(target), "--format", fmt)
    sheet = run("sheet", str(questions), "-o", str(target), "--format", fmt)
    assert_refused(answer, words)
    assert_refused(sheet, words)
    assert answer.err == sheet.err
    for command in (("exam",), ("practice", "--seed", "1", "-n", "1")):
        assert_refused(run(*command, "-o", str(target), "--format", fmt), words)
    assert not target.exists()


@pytest.mark.parametrize("ext", [".md", ".markdown", ".txt"])
def test_a_text_file_takes_any_format_for_every_command(
    tmp_path: Path, questions: Path, ext: str
) -> None:
    target = tmp_path / f"a{ext}"
    assert run("line", "0", "0", "3", "1", "-o", str(target), "--format", "json").code == 0
    assert target.read_text(encoding="utf-8").startswith("{")
    assert run("sheet", str(questions), "-o", str(target), "--format", "latex").code == 0
    assert target.read_text(encoding="utf-8").startswith("% scanconv sheet")


@pytest.mark.parametrize("name", formats("document"))
def test_each_document_format_is_chosen_by_its_extension(
    tmp_path: Path, questions: Path, name: str
) -> None:
    sheet = read_questions(questions.read_text(encoding="utf-8"), "q.txt")
    expected = sheet_document(sheet, answer_questions(sheet.questions), "key", name)
    for ext in FORMATS[name].extensions:
        target = tmp_path / f"key{ext.upper()}"
        assert run("sheet", str(questions), "-o", str(target)).code == 0
        assert target.read_text(encoding="utf-8") == expected


def test_a_format_that_writes_no_documents_leaves_a_sheet_in_markdown(
    tmp_path: Path, questions: Path
) -> None:
    target = tmp_path / "key.csv"  # csv names a format a sheet is not written in
    assert run("sheet", str(questions), "-o", str(target)).code == 0
    assert target.read_text(encoding="utf-8").startswith("## Question 1 (2 marks)")


def test_an_unknown_document_format_names_the_tables_formats() -> None:
    sheet = read_questions("line 0 0 3 1\n", "q.txt")
    answered = answer_questions(sheet.questions)
    for name in ("csv", "rich", "docx"):
        with pytest.raises(ValueError, match="unknown sheet format") as err:
            sheet_document(sheet, answered, "key", name)
        assert ", ".join(formats("document")) in str(err.value)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_key_file_of_practice_goes_by_the_same_extension_map(tmp_path: Path) -> None:
    for ext in [e for f in formats("document") for e in FORMATS[f].extensions]:
        key = tmp_path / f"key{ext}"
        assert run("practice", "--seed", "2", "-n", "1", "--key", str(key)).code == 0
        assert key.stat().st_size > 0
    r = run("practice", "--seed", "2", "-n", "1", "--key", str(tmp_path / "key.csv"))
    assert_refused(r, "unknown extension .csv", *FORMATS["gift"].extensions)


# --- the Question block: a sheet's question through each format's mapping ----------------------


def _answered(text: str = "> Draw <it> & *show* `DDA` {x}.\n[3] line 0 0 3 1\n") -> list[Answered]:
    sheet = read_questions(text, "q.txt")
    return answer_questions(sheet.questions)


@pytest.mark.parametrize("fmt", [Format.markdown, Format.plain, Format.latex, Format.rich])
def test_a_key_document_renders_its_question_then_its_answer(fmt: Format) -> None:
    from rich.console import Console

    from scanconv.document import Question, Title
    from scanconv.render import Options, render
    from scanconv.render.documents.sheet import key_document

    (a,) = _answered()
    doc = key_document(a, 3)
    assert isinstance(doc.blocks[0], Question) and doc.blocks[0].heading == "Question 1 (3 marks)"
    assert doc.get(Title).level == 4
    chunks = list(render(doc, fmt, Options(width=100)))
    if fmt is Format.rich:
        console = Console(width=100, record=True, file=io.StringIO())
        for c in chunks:
            console.print(c)
        text = console.export_text()
    else:
        text = "".join(c for c in chunks if isinstance(c, str))
    heading, title = text.index("Question 1 (3 marks)"), text.index("Bresenham")
    assert heading < text.index("scanconv line 0 0 3 1") < title
    assert "Draw <it>" not in text or fmt in (Format.plain, Format.rich)  # escaped where it must be


def test_the_sheet_key_is_the_question_blocks_through_the_mappings() -> None:
    """A markdown key is, question by question, the key document rendered by the markdown
    format: the same bytes, so a format's sheet adds only its sections and title."""
    from scanconv.render import Options, render
    from scanconv.render.documents.sheet import key_document

    answered = _answered("[2] line 0 0 3 1\ncircle 2\n")
    sheet = read_questions("[2] line 0 0 3 1\ncircle 2\n", "q.txt")
    whole = sheet_document(sheet, answered, "key", "markdown")
    parts = [
        "".join(
            c for c in render(key_document(a), Format.markdown, Options()) if isinstance(c, str)
        )
        for a in answered
    ]
    assert whole == "".join(parts)
    assert whole.count("## Question ") == 2 and whole.count("### ") >= 2


def test_the_question_heading_is_escaped_by_each_format() -> None:
    from scanconv.document import Question
    from scanconv.render.mappings.html import question_html
    from scanconv.render.mappings.latex import LATEX
    from scanconv.render.mappings.text import MARKDOWN, PLAIN

    block = Question(2, 1, "a <b> & $c$ _d_ \u202e", "scanconv line 0 0 3 1 --algo dda", 2)
    html = question_html(block)
    assert "&lt;b&gt; &amp;" in html and "<b>" not in html and "Question 2 (1 mark)" in html
    tex = "".join(str(c) for c in LATEX[Question](block, None, None))  # type: ignore[arg-type]
    assert "\\$c\\$" in tex and "\\_d\\_" in tex and "-{}-algo" in tex
    md = "".join(MARKDOWN[Question](block, None, []))  # type: ignore[arg-type]
    assert "\\<b\\>" in md and "\\$c\\$" in md and "`scanconv line 0 0 3 1 --algo dda`" in md
    plain = "".join(PLAIN[Question](block, None, []))  # type: ignore[arg-type]
    assert plain.isascii() and "Question 2 (1 mark)\n-------------------\n" in plain
