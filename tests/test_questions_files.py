"""Question files read as an editor reads them, and outputs that never destroy an input or
leave part of a set (attack report D5, D6, D11, D12, D13, D15)."""

from __future__ import annotations

import inspect
import io
import json
import os
import stat
import subprocess
import sys
from pathlib import Path
from typing import Annotated

import pytest

from scanconv.algorithms.circle_choices import Loop
from scanconv.core.declare import Opt
from scanconv.questions.files import QuestionError, read_questions, split_lines
from scanconv.questions.grammar import Param

from .helpers import assert_refused, run

QUESTIONS = "title: T\nline 2 2 10 6\n"


def _file(tmp_path: Path, text: str | bytes, name: str = "q.txt") -> Path:
    path = tmp_path / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text, encoding="utf-8", newline="")
    return path


# --- D11: lines end at \n, \r\n and \r only --------------------------------------------------


@pytest.mark.parametrize("sep", ["\u2028", "\u2029", "\x85", "\x0c", "\x0b", "\x1c", "\x1e"])
def test_other_line_separators_smuggle_no_question(sep: str) -> None:
    sheet = read_questions(f"title: Unit 2{sep}line 0 0 5 1\n> Draw it{sep}circle 3\ncircle 2\n")
    assert [q.argv for q in sheet.questions] == [("circle", "2")]
    assert sheet.title == "Unit 2\ufffdline 0 0 5 1"
    assert sheet.questions[0].wording == "Draw it\ufffdcircle 3"
    assert sheet.questions[0].line == 3


@pytest.mark.parametrize("end", ["\n", "\r\n", "\r"])
def test_line_numbers_agree_with_an_editor(end: str) -> None:
    lines = ["title: a\x0cb", "", "line 2 2 10 6\u2028x", "circle 3", "[x] circle 4"]
    with pytest.raises(QuestionError) as err:
        read_questions(end.join(lines) + end, "q.txt")
    assert err.value.line == 5 and str(err.value).startswith("q.txt:5: marks are written")
    sheet = read_questions(end.join(lines[:4]) + end)
    assert [(q.line, q.argv) for q in sheet.questions] == [
        (3, ("line", "2", "2", "10", "6\ufffdx")),
        (4, ("circle", "3")),
    ]


def test_a_form_feed_in_a_title_is_not_a_new_line(tmp_path: Path) -> None:
    r = run("sheet", str(_file(tmp_path, "title: a\x0cb\nline 2 2 10 6\n")), "-f", "json")
    assert r.code == 0, r.err
    assert json.loads(r.out)["title"] == "a\ufffdb"
    assert json.loads(r.out)["questions"][0]["line"] == 2


def test_split_lines_only_at_line_ends() -> None:
    assert split_lines("a\r\nb\rc\u2028d\x85e\n\nf") == ["a", "b", "c\u2028d\x85e", "", "f"]


# --- D12, D13: a BOM; standard input read as strictly as a file ------------------------------


def test_a_utf8_bom_is_accepted(tmp_path: Path) -> None:
    path = _file(tmp_path, b"\xef\xbb\xbf" + QUESTIONS.encode())
    r = run("sheet", str(path), "-f", "json")
    assert r.code == 0, r.err
    assert '"title": "T"' in r.out


class _Stdin(io.TextIOWrapper):
    """Standard input holding ``data`` (bytes underneath, as a real one)."""

    def __init__(self, data: bytes) -> None:
        super().__init__(io.BytesIO(data), encoding="utf-8", errors="surrogateescape")


@pytest.mark.parametrize(
    ("data", "word"),
    [(b"title: caf\xe9\nline 2 2 10 6\n", "not UTF-8"), (b"line 2 2 10 6\x00\n", "NUL")],
)
def test_stdin_refuses_what_a_file_refuses(
    data: bytes, word: str, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setattr("sys.stdin", _Stdin(data))
    assert_refused(run("sheet", "-", "-f", "json"), "<stdin>", word)
    assert_refused(run("sheet", str(_file(tmp_path, data))), word)


def test_stdin_with_a_bom_is_read(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("sys.stdin", _Stdin(b"\xef\xbb\xbf" + QUESTIONS.encode()))
    r = run("sheet", "-", "-f", "json")
    assert r.code == 0, r.err


# --- D5: an output naming an input or another output ----------------------------------------


def test_sheet_output_onto_its_question_file_is_refused(tmp_path: Path) -> None:
    path = _file(tmp_path, QUESTIONS)
    for args in (["-o", str(path)], ["--pdf", str(path)], ["-o", "q.txt"], ["--pdf=./q.txt"]):
        cwd = os.getcwd()
        os.chdir(tmp_path)
        try:
            assert_refused(run("sheet", "q.txt", *args), "the same file as QUESTIONS")
        finally:
            os.chdir(cwd)
        assert path.read_text(encoding="utf-8") == QUESTIONS


def test_sheet_pdf_and_output_naming_one_file_are_refused(tmp_path: Path) -> None:
    path = _file(tmp_path, QUESTIONS)
    key = tmp_path / "key.pdf"
    assert_refused(run("sheet", str(path), "-o", str(key), "--pdf", str(key)), "same file as")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["q.txt"]


def test_sheet_output_through_a_symlink_to_its_question_file_is_refused(tmp_path: Path) -> None:
    path = _file(tmp_path, QUESTIONS)
    (tmp_path / "key.md").symlink_to(path)
    assert_refused(run("sheet", str(path), "-o", str(tmp_path / "key.md")), "same file")
    assert path.read_text(encoding="utf-8") == QUESTIONS


@pytest.mark.parametrize(
    "args",
    [
        ["--key", "k.md", "-o", "k.md"],
        ["--questions", "x.txt", "--key", "x.txt"],
        ["--pdf", "w.pdf", "--key", "w.pdf"],
        ["--questions", "x.txt", "-o", "./x.txt"],
    ],
)
def test_practice_outputs_naming_one_file_are_refused(
    args: list[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "k.md").write_text("the old key", encoding="utf-8")
    assert_refused(run("practice", "--seed", "3", *args), "the same file as")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["k.md"]
    assert (tmp_path / "k.md").read_text(encoding="utf-8") == "the old key"


# --- D15: a directory as an output -----------------------------------------------------------


@pytest.mark.parametrize(
    "args",
    [
        ["sheet", "Q", "--pdf", "D"],
        ["sheet", "Q", "-o", "D"],
        ["practice", "--seed", "1", "--key", "D"],
        ["practice", "--seed", "1", "--questions", "D"],
        ["practice", "--seed", "1", "--pdf", "D"],
        ["practice", "--seed", "1", "-o", "D"],
        ["exam", "-o", "D"],
    ],
)
def test_a_directory_output_is_refused_before_any_work(
    args: list[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("PATH", str(tmp_path / "nowhere"))  # no pdflatex: refused before it
    question = _file(tmp_path, QUESTIONS)
    folder = tmp_path / "out"
    folder.mkdir()
    argv = [str(question) if a == "Q" else str(folder) if a == "D" else a for a in args]
    assert_refused(run(*argv), "directory")
    assert list(folder.iterdir()) == []


# --- D6: several outputs, all or none --------------------------------------------------------


@pytest.fixture
def fake_pdflatex(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A ``pdflatex`` on PATH that writes a small PDF (the real one is not needed here)."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    exe = bin_dir / "pdflatex"
    exe.write_text("#!/bin/sh\nprintf '%%PDF-1.4\\n' > sheet.pdf\n: > sheet.log\n")
    exe.chmod(exe.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setenv("PATH", f"{bin_dir}{os.pathsep}{os.environ['PATH']}")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.usefixtures("fake_pdflatex")
def test_sheet_pdf_and_output_are_written_together_or_not_at_all(tmp_path: Path) -> None:
    question = _file(tmp_path, QUESTIONS)
    pdf = tmp_path / "a.pdf"
    r = run("sheet", str(question), "--pdf", str(pdf), "-o", str(tmp_path / "missing" / "x.md"))
    assert r.code == 1 and r.out == "" and r.err.startswith("scanconv: error: cannot write")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bin", "q.txt"]
    r = run("sheet", str(question), "--pdf", str(pdf), "-o", str(tmp_path / "x.md"))
    assert r.code == 0, r.err
    assert pdf.read_bytes().startswith(b"%PDF") and (tmp_path / "x.md").exists()


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.usefixtures("fake_pdflatex")
def test_practice_writes_every_file_or_none(tmp_path: Path) -> None:
    out = [
        "--key",
        str(tmp_path / "k.pdf"),
        "--questions",
        str(tmp_path / "qs.txt"),
        "--pdf",
        str(tmp_path / "w.pdf"),
    ]
    r = run("practice", "--seed", "3", *out, "-o", str(tmp_path / "missing" / "w.md"))
    assert r.code == 1 and r.err.startswith("scanconv: error: cannot write"), r.err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bin"]
    r = run("practice", "--seed", "3", *out, "-o", str(tmp_path / "w.md"))
    assert r.code == 0, r.err
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "bin",
        "k.pdf",
        "qs.txt",
        "w.md",
        "w.pdf",
    ]


# --- the question language in the library ------------------------------------------------------

#: Questions, right and wrong, that the library must read exactly as the command line does.
PARITY = [
    "line 2 2 10 6 --algo dda",
    "line (2,2) 10,6 -a BRESENHAM --tie keep",
    "line -3 -2 4 5 --start given",
    "line 1/2 0 7/2 1 -adda",
    "circle 5 -c1 2 --method=bresenham",
    "circle 8 --p0 5/4-r --loop inclusive",
    "ellipse 8 6 -c 1 1 --derive",
    "storage 1024x768 --levels 256",
    "quantize --bits 2 --input real --recon lower",
    "sample 'x+y' --size 4x4 -L 4 --domain 0 1 0 1",
    "image ramp --size 4 --levels 4",
    "bezier 0 0 1 2 3 3 --at 1/2",
    "bspline 0 0 1 2 3 3 4 0 -p 2 --knots uniform",
    "bspline --basis --degree 2 --knots 0,0,0,1,1,1",
    "continuity 0 0 1 1 2 0 : 2 0 3 -1 4 0",
    "local-control 0 0 1 2 3 3 4 0 5 1 --move 2 3 4 -p 2",
    "parametric circle --radius 3 -n 4",
    "parametric ellipse --a 3 --b 2 --t-range 0 pi",
    "parametric custom --x t --y 't*t' --samples 3",
    "compare circle 5",
    "transform 1 1 2 2 --translate 1 1 --rotate 90",
    "viewport -w 0 0 10 10 --viewport 0 0 100 100 5 5",
    "clip line 0 0 10 10 -w 2 2 8 8 -m liang-barsky",
    "pipeline polygon 0 0 4 0 2 3 -w 0 0 4 4 --viewport 0 0 8 8 --outline",
    "fill flood --rows '#####/#...#/#####' --seed 2 1 --connectivity 8",
    "antialias circle 3 -c 1 1",
    "color rgb 255 0 0 --to hsv --to cmy",
    "color hsv 210 2/3 0.6 --to rgb",
    "theory symmetry",
    # refused: each message as the command line words it
    "circle 2.5",
    "line 1 2 3",
    "line 0 0 1e10 1",
    "line 2 2 10 6 --algo zzz",
    "line 2 2 10 6 --algo=",
    "line 2 2 10 6 --bogus",
    "line --bogus 2 2 10 6",
    "line 2 2 10 6 -x",
    "line 2 2 10 6 -- 7",
    "line 2 2 10 6 --derive=1",
    "line 2 2 10 6 -a",
    "line x 2 10 6 --algo q",
    "circle -inf",
    "circle 5 --center 1",
    "circle 5 --center 1 b",
    "circle 5 6",
    "bspline 0 0 1 2 3 3 --degree 5",
    "bezier 0 0 1 1 -n 2.5",
    "quantize",
    "quantize --bits 3 --recon low",
    "fill flood",
    "fill flood --seed 1.5 2 --rows '...'",
    "image ramp --siz 4",
    "image ramp --origin top-left",
    "compare curves 3",
    "clip line 0 0 1 1 -w 0 0 1",
    "clip polygon 0 0 1 0 1 1 -w 0 0 1 1 -m x",
    "color rgb x y z",
    "color rgb 1 2 3 --to",
    "transform 1 1 --bogus 3",
    "continuity 0 0 1 1 2 0 2 0 3 -1 4 0",
    "theory bogus",
    "lin 2 2 10 6",
]


def _library(question: str) -> tuple[int, str]:
    from scanconv.questions import parse, solve
    from scanconv.render import Format, Options, render

    try:
        solution = solve(parse(question))
    except ValueError as err:
        return 2, f"scanconv: error: {err}\n"
    return 0, "".join(c for c in render(solution, Format.json, Options()) if isinstance(c, str))


@pytest.mark.parametrize("question", PARITY)
def test_the_library_reads_a_question_as_the_command_line_does(question: str) -> None:
    import shlex

    argv = shlex.split(question)
    cli = run(*argv)
    if cli.code == 0:
        cli = run(*argv, "--format", "json")
    code, text = _library(question)
    expected = cli.out if cli.code == 0 else cli.err
    if question.startswith("lin "):  # the sheet's word for an unknown command, with a hint
        expected = "scanconv: error: No such command 'lin'; did you mean 'line'?\n"
    assert (code, text) == (cli.code, expected)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_grammar_is_the_command_lines_declarations() -> None:
    from scanconv.cli.command import SHARED as CLI_SHARED
    from scanconv.cli.grammar import declared
    from scanconv.questions.grammar_table import NOT_QUESTIONS, SHARED, SPECS

    specs, others = declared()
    assert SPECS == specs, "the command line and the question grammar differ"
    assert NOT_QUESTIONS == others and SHARED == CLI_SHARED
    assert len(SPECS) >= 33


def test_the_grammar_is_generated_from_the_librarys_declarations() -> None:
    from scanconv.questions import generate
    from scanconv.questions.declared import COMMANDS, NOT_QUESTIONS, OUTPUTS
    from scanconv.questions.grammar_table import NOT_QUESTIONS as TABLE_OTHERS
    from scanconv.questions.grammar_table import SHARED, SPECS, S
    from scanconv.render import Format

    assert generate.specs() == SPECS and generate.shared() == S, (
        "run: python -m scanconv.questions.generate > scanconv/questions/grammar_table.py"
    )
    # --format's choices are the formats' enum, read when the table is generated
    assert S["fmt"].choices == tuple(f.value for f in Format)
    assert (TABLE_OTHERS, SHARED) == (NOT_QUESTIONS, OUTPUTS)
    assert COMMANDS.keys() <= SPECS.keys()


def test_a_declaration_is_the_grammar_the_command_line_and_the_answer() -> None:
    """A default, a flag's spelling and a choice changed on the library function change the
    question grammar and the typer command read from it (not a copy of either)."""
    from scanconv.cli.options import typer_parameter
    from scanconv.core.declare import declared
    from scanconv.questions.grammar import param_of

    def spin(
        turns: Annotated[int, Opt("--turns", "-t", help="How many.")] = 3,
        loop: Annotated[Loop | None, Opt("--loop", help="The loop.")] = None,
        fast: bool = False,
    ) -> None:
        """Not a command: a declaration to read."""

    turns, loop = declared(spin)  # fast has no declaration: the library's alone
    assert param_of(turns) == Param(
        "turns", ("--turns", "-t"), "integer", default=3, help="How many."
    )
    assert param_of(loop).choices == ("strict", "inclusive") and param_of(loop).default is None
    option = typer_parameter(turns)
    assert option.default == 3 and option.annotation.__metadata__[0].param_decls == ("-t",)


def test_every_command_of_the_grammar_is_declared_by_its_library_function() -> None:
    from scanconv.questions.declared import BY_FUNCTION
    from scanconv.questions.grammar_table import SPECS

    assert {spec.function for spec in SPECS.values()} == set(BY_FUNCTION)
    for spec in SPECS.values():
        body = BY_FUNCTION[spec.function].answerer()
        inspect.signature(body).bind(**dict.fromkeys(spec.own))  # takes them all


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_questions_are_answered_without_the_command_line() -> None:
    code = (
        "import sys, scanconv\n"
        "from scanconv import questions\n"
        "assert questions.answer('line 2 2 10 6 --algo dda').algorithm == 'dda'\n"
        "assert questions.answer(['circle', '5', '--no-grid']).primitive == 'circle'\n"
        "m = scanconv.check('tests/data/check/slip.csv', 'line 2 2 10 6')\n"
        "assert m.data['score'] == 7\n"
        "s = questions.read_questions('[2] line 2 2 10 6\\ncircle 5 --origin top-left\\n')\n"
        "lines = [questions.parse(q.argv) for q in s.questions]\n"
        "assert [questions.shown_with(x).origin for x in lines] == ['bottom-left', 'top-left']\n"
        "try:\n"
        "    questions.answer('line 2 2 10')\n"
        "except questions.UsageError as err:\n"
        "    assert str(err) == \"Missing argument 'Y2'.\"\n"
        "bad = sorted(m for m in sys.modules if m.split('.')[0] in ('typer', 'click')\n"
        "             or m.startswith('scanconv.cli'))\n"
        "print(bad)\n"
    )
    root = Path(__file__).resolve().parent.parent
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=root, timeout=120
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout == "[]\n"


def test_a_theory_question_without_a_topic_is_one_short_line(tmp_path: Path) -> None:
    r = run("sheet", str(_file(tmp_path, "theory\n")))
    assert_refused(r, "q.txt:1: Missing argument 'TOPIC'.")
    r = run("sheet", str(_file(tmp_path, "theory --list\n")))
    assert_refused(r, "q.txt:1: --list is not a question")


def test_an_answered_question_pickles_as_the_api_call_it_made() -> None:
    import pickle

    from scanconv.questions import answer

    got = answer("circle 5 -c 1 2 --method bresenham")
    back = pickle.loads(pickle.dumps(got))
    assert back.to("csv") == got.to("csv") and back.title == got.title
