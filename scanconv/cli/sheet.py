"""``scanconv sheet QUESTIONS``: a numbered answer key or a worksheet from a file of questions.

The API (what other commands, the exam book and the tests build on)::

    read_questions(text, source) -> Sheet
        Parse a question file (below). A malformed line raises QuestionError, whose text is
        "SOURCE:LINE: message".
    answer_questions(questions) -> list[Answered]
        Run each question's command line in this process, through the same click command
        objects (and so the same parsing, defaults and messages) as ``scanconv ...`` itself,
        and return (question, Solution, render Options) triples. Any scanconv command line is
        a question: a topic added later (``theory``, ``color``) needs nothing here. The first
        bad question raises QuestionError with its line and the error scanconv would give for
        that command line.
    sheet_document(sheet, answered, kind, fmt, standalone=False) -> str
        (:mod:`scanconv.render.sheet`) the whole key or worksheet, rendered in memory, so a bad
        question never leaves a partial file.

The question file, one question per line, written as scanconv's own arguments::

    title: Unit 2 test: scan conversion        (optional, once)
    section: Lines                             (optional: a heading for the questions after it)
    # a comment; blank lines are ignored
    > Draw the line from (2, 2) to (10, 6) with the DDA algorithm.   (optional wording)
    [4] line 2 2 10 6 --algo dda               ([N] or [N marks]: the marks, optional)
    circle 8 --center 2 3   # a comment after a question

Words are split as a shell splits them (quote a formula: ``sample 'x + y' --size 4``), and ``#``
starts a comment where a shell's does (at the start of a word, outside quotes). A question may
carry the options that change how its answer is shown (``--no-grid``, ``--brief``, ``--exact``,
``--origin``); the format and the output file are the sheet's.
"""

from __future__ import annotations

import copy
import re
from collections.abc import Iterable
from enum import Enum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from ..render import Options
from ..render.sheet import Answered, Question, Sheet
from .application import app, register
from .budget import check_question
from .command import Command, error_message
from .output import PROG, fail, note, write_atomic

if TYPE_CHECKING:
    from ..core.records import Solution

__all__ = ["Answered", "Question", "QuestionError", "Sheet", "answer", "answer_questions"]
__all__ += ["read_file", "read_questions", "sheet"]

MAX_QUESTIONS = 1000
"""The most questions one sheet takes (a 200-question key is the benchmark)."""
MAX_FILE_BYTES = 1_000_000
"""The largest question file read."""


class QuestionError(ValueError):
    """A bad line of a question file: ``str()`` is ``SOURCE:LINE: message``."""

    def __init__(self, source: str, line: int, message: str) -> None:
        super().__init__(f"{source}:{line}: {message}")
        self.source, self.line, self.message = source, line, message


# --- reading --------------------------------------------------------------------------------

_MARKS = re.compile(r"^\[\s*(\d{1,4})\s*(?:marks?)?\s*\]\s*", re.IGNORECASE)
_KEYWORD = re.compile(r"^(title|section)\s*:\s*(.*)$", re.IGNORECASE)


def strip_comment(line: str) -> str:
    """``line`` without its comment: ``#`` at the start of a word, outside quotes, as in a
    shell.

    >>> strip_comment("fill flood --rows '#..#' --seed 1 1  # the notes' example")
    "fill flood --rows '#..#' --seed 1 1  "
    >>> strip_comment("line 2 2#3")
    'line 2 2#3'
    """
    quote = ""
    escaped = False
    for i, ch in enumerate(line):
        if escaped:
            escaped = False
        elif ch == "\\" and quote != "'":
            escaped = True
        elif quote:
            if ch == quote:
                quote = ""
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i]
    return line


def read_questions(text: str, source: str = "QUESTIONS") -> Sheet:
    """Parse a question file (the syntax is in this module's docstring).

    >>> sheet = read_questions("title: Test\\n# c\\n[4] line 2 2 10 6 --algo dda\\ncircle 8\\n")
    >>> sheet.title, [(q.number, q.line, q.marks, q.argv[0]) for q in sheet.questions]
    ('Test', [(1, 3, 4, 'line'), (2, 4, None, 'circle')])
    >>> read_questions("line 2 2 'x")
    Traceback (most recent call last):
    ...
    scanconv.cli.sheet.QuestionError: QUESTIONS:1: unbalanced quotes: No closing quotation

    Control characters (a terminal escape sequence) become U+FFFD, so no output echoes them:

    >>> read_questions("title: A\\x1b[31mB\\nline 0 0 1 1").title
    'A\\ufffd[31mB'
    """
    import shlex

    title = ""
    section = ""
    wording: list[str] = []
    questions: list[Question] = []
    import re

    control = re.compile("[\x01-\x08\x0b-\x1f\x7f-\x9f]")  # ESC, BEL, ...: never echoed
    for number, raw in enumerate(text.splitlines(), 1):
        stripped = control.sub("\ufffd", raw).strip()
        if not stripped or stripped.startswith("#"):
            continue
        if stripped.startswith(">"):
            wording.append(stripped[1:].strip())
            continue
        keyword = _KEYWORD.match(stripped)
        if keyword:
            name, value = keyword.group(1).lower(), " ".join(keyword.group(2).split())
            if not value:
                raise QuestionError(source, number, f"'{name}:' needs a text after it")
            if name == "title":
                if title:
                    raise QuestionError(source, number, "a second title line (one per sheet)")
                title = value
            else:
                section = value
            continue
        marks = None
        found = _MARKS.match(stripped)
        if found:
            marks = int(found.group(1))
            stripped = stripped[found.end() :]
        elif stripped.startswith("["):
            raise QuestionError(
                source, number, "marks are written [N] or [N marks] before the question, e.g. [4]"
            )
        try:
            argv = tuple(shlex.split(strip_comment(stripped)))
        except ValueError as err:
            raise QuestionError(source, number, f"unbalanced quotes: {err}") from None
        if not argv:
            raise QuestionError(source, number, "marks without a question")
        if len(questions) == MAX_QUESTIONS:
            raise QuestionError(source, number, f"at most {MAX_QUESTIONS} questions in one sheet")
        questions.append(
            Question(len(questions) + 1, number, argv, marks, " ".join(wording), section)
        )
        wording = []
    if wording:
        raise QuestionError(source, number, "'>' wording without a question after it")
    return Sheet(title, tuple(questions), source)


def read_file(path: str) -> Sheet:
    """Read and parse the question file ``path`` (``-``: standard input); a file that cannot
    be read is a ``ValueError`` naming it."""
    import sys

    if path == "":
        raise ValueError("QUESTIONS is empty (''): give the name of a question file")
    try:
        if path == "-":
            text = sys.stdin.read(MAX_FILE_BYTES + 1)
        else:
            with open(path, "rb") as f:
                data = f.read(MAX_FILE_BYTES + 1)
            if b"\x00" in data:
                raise ValueError(f"{path} is not a text file (it holds NUL bytes)")
            text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise ValueError(f"{path} is not UTF-8 text") from None
    except IsADirectoryError:
        raise ValueError(f"{path!r} is a directory, not a question file") from None
    except OSError as err:
        raise ValueError(f"cannot read {path!r}: {err.strerror or err}") from None
    if len(text) > MAX_FILE_BYTES:
        raise ValueError(f"{path} is larger than {MAX_FILE_BYTES:,} bytes")
    sheet = read_questions(text, "<stdin>" if path == "-" else path)
    if not sheet.questions:
        raise ValueError(f"{path} holds no question (one per line: line 2 2 10 6 --algo dda)")
    return sheet


# --- answering ------------------------------------------------------------------------------


class _Capture(Command):
    """A command that returns its answer instead of writing it: the same signature (so click
    parses a question exactly as ``scanconv`` would), the shared display options kept."""

    def __call__(self, **kwargs: Any) -> Any:
        import inspect

        own = inspect.signature(self.__wrapped__).parameters
        shown = {k: kwargs.pop(k) for k in ("grid", "origin", "brief", "exact") if k in kwargs}
        for name in ("output", "svg", "png"):
            if kwargs.pop(name, None) is not None:
                raise ValueError(
                    f"--{name} in a question: the sheet writes one document (give it -o)"
                )
        fmt = kwargs.pop("fmt", None)
        if fmt is not None and getattr(fmt, "value", fmt) != "auto":
            raise ValueError("--format in a question: the sheet's --format applies to every answer")
        kwargs.pop("explain", None)
        for name in ("grid", "origin", "brief", "exact"):  # declared by the command itself
            if name in own and name in shown:
                kwargs[name] = shown[name]
        try:
            check_question(self.__name__, kwargs)  # alone and with the questions before it
            solution = self.__wrapped__(**kwargs)
        except ValueError as err:
            raise _Refused(error_message(err, self.parameters)) from None
        origin = shown.get("origin")
        options = Options(
            grid=shown.get("grid", True),
            origin=getattr(origin, "value", origin) or "bottom-left",
            brief=shown.get("brief", False),
            exact=shown.get("exact", False),
        )
        return solution, options


class _Refused(Exception):
    """Bad input found by the library, already worded as scanconv words it."""


def _capture_info(info: Any) -> Any:
    """The command ``info`` with a callback that returns the answer instead of writing it;
    a command that gives no answer (``sheet`` itself, ``check``) is refused."""
    callback = info.callback
    if not isinstance(callback, Command):
        raise _Refused(f"'{_command_name(info)}' cannot be a question of a sheet")
    new = copy.copy(info)
    new.callback = _Capture(callback.__wrapped__, callback._shared)
    return new


def _command_name(info: Any) -> str:
    return info.name or typer.main.get_command_name(info.callback.__name__)


def _capturing(group: typer.Typer, argv: tuple[str, ...]) -> tuple[typer.Typer, tuple[str, ...]]:
    """A copy of ``group`` holding only the command ``argv`` names, which returns its answer;
    with the names of the command's path. An unknown name is a ``_Refused``."""
    name = argv[0] if argv else ""
    for info in group.registered_commands:
        if info.callback is not None and _command_name(info) == name:
            one = copy.copy(group)
            one.registered_commands, one.registered_groups = [_capture_info(info)], []
            return one, (name,)
    for sub in group.registered_groups:
        if sub.name == name and sub.typer_instance is not None:
            if len(argv) < 2 or argv[1].startswith("-"):
                names = sorted(_command_name(c) for c in sub.typer_instance.registered_commands)
                raise _Refused(f"'{name}' needs one of its commands: {', '.join(names)}")
            inner, path = _capturing(sub.typer_instance, argv[1:])
            sub = copy.copy(sub)
            sub.typer_instance = inner
            one = copy.copy(group)
            one.registered_commands, one.registered_groups = [], [sub]
            return one, (name, *path)
    known = [_command_name(c) for c in group.registered_commands if c.callback is not None]
    known += [g.name for g in group.registered_groups if g.name]
    import difflib

    close = difflib.get_close_matches(name, known, n=1)
    hint = f"; did you mean '{close[0]}'?" if close else ""
    raise _Refused(f"No such command '{name}'{hint}")


_COMMANDS: dict[tuple[str, ...], Any] = {}
"""Click commands already built, by command path: a sheet of 200 lines builds each once."""

_NOT_QUESTIONS = {"--help", "-h", "--version"}


def _click_command(argv: tuple[str, ...]) -> Any:
    top = argv[0] if argv else ""
    if not top or top.startswith("-"):
        raise _Refused("a question starts with a command name (line, circle, ...)")
    if top in ("sheet", "practice", "check", "exam"):
        raise _Refused(f"'{top}' cannot be a question of a sheet")
    key = argv[:2]
    if key not in _COMMANDS and argv[:1] not in _COMMANDS:
        group, path = _capturing(register(list(argv)), argv)
        _COMMANDS[path] = typer.main.get_command(group)
    return _COMMANDS.get(key) or _COMMANDS[argv[:1]]


def answer(argv: Iterable[str]) -> tuple[Solution, Options]:
    """The answer of one command line, as ``scanconv ARGV`` would give it (in this process):
    ``(solution, options)``. Bad input is a ``ValueError`` worded as scanconv words it.

    >>> solution, options = answer(["line", "2", "2", "10", "6", "--algo", "dda", "--no-grid"])
    >>> solution.algorithm, options.grid
    ('dda', False)
    >>> answer(["line", "2", "2", "10"])
    Traceback (most recent call last):
    ...
    ValueError: Missing argument 'Y2'.
    """
    import contextlib
    import io
    import sys

    from typer._click import exceptions as click_exc  # typer vendors click

    from .entry import _MINUS, _NONFINITE, _usage_message, students

    args = [_MINUS + a[1:] if a.lower() in _NONFINITE else a for a in students(list(argv))]
    bad = next((a for a in args if a in _NOT_QUESTIONS), None)
    said = io.StringIO()
    try:
        if bad is not None:
            raise _Refused(f"{bad} is not a question")
        command = _click_command(tuple(args))
        with contextlib.redirect_stderr(said):  # what a command's own fail() says
            with command.make_context(PROG, args) as ctx:
                result = command.invoke(ctx)
    except _Refused as err:
        raise ValueError(str(err)) from None
    except click_exc.UsageError as err:
        raise ValueError(_usage_message(err)) from None
    except click_exc.ClickException as err:
        raise ValueError(" ".join(err.format_message().split())) from None
    except (typer.Exit, typer.Abort):
        lines = said.getvalue().splitlines()
        message = lines[-1].split("error: ", 1)[-1] if lines else "it stops without an answer"
        raise ValueError(message) from None
    if said.getvalue():  # a remark of the command's own, passed on
        sys.stderr.write(said.getvalue())
    if not (isinstance(result, tuple) and len(result) == 2):
        raise ValueError(f"'{args[0]}' gives no answer that a sheet can show")
    return result[0], result[1]


def answer_questions(questions: Iterable[Question], source: str = "QUESTIONS") -> list[Answered]:
    """Answer every question in this process (see the module docstring); the first bad one
    raises :class:`QuestionError` with its line, and so does the first question beyond the
    work budget of a document, alone or with the questions before it
    (:func:`scanconv.render.budget.document`).

    >>> sheet = read_questions("line 2 2 10 6 --algo dda\\n\\ncircle 0.5\\n", "q.txt")
    >>> answer_questions(sheet.questions, sheet.source)
    Traceback (most recent call last):
    ...
    scanconv.cli.sheet.QuestionError: q.txt:3: radius must be an integer, got 0.500
    """
    from ..render.budget import document

    with document():
        return _answer_all(questions, source)


def _answer_all(questions: Iterable[Question], source: str) -> list[Answered]:
    out = []
    for q in questions:
        try:
            solution, options = answer(q.argv)
        except ValueError as err:
            raise QuestionError(source, q.line, str(err)) from None
        except RecursionError:
            raise QuestionError(source, q.line, "input too deeply nested") from None
        out.append(Answered(q, solution, options))
    return out


# --- the command ----------------------------------------------------------------------------


class SheetFormat(str, Enum):
    """The formats of a sheet."""

    auto = "auto"
    markdown = "markdown"
    latex = "latex"
    html = "html"
    json = "json"
    plain = "plain"


SheetFormatOpt = Annotated[
    SheetFormat,
    typer.Option(
        "--format",
        "-f",
        case_sensitive=False,
        help="Output format; auto: from the --output file's extension, else markdown.",
    ),
]
"""``--format`` of every document command (sheet, exam, practice), declared once."""

SheetOutputOpt = Annotated[
    Path | None,
    typer.Option(
        "--output",
        "-o",
        dir_okay=False,
        help="Write to this file (atomically: complete or not at all) instead of stdout.",
    ),
]
"""``--output`` of every document command, declared once."""

#: The format a file's extension names.
SHEET_EXTENSIONS = {
    ".md": "markdown",
    ".markdown": "markdown",
    ".tex": "latex",
    ".html": "html",
    ".htm": "html",
    ".json": "json",
    ".txt": "plain",
}


def sheet_format(fmt: SheetFormat, output: Path | None) -> str:
    """The format of the sheet: ``--format``, else the output file's extension, else
    markdown. A ``--format`` that contradicts a ``.tex``, ``.html`` or ``.json`` file is
    refused.

    >>> sheet_format(SheetFormat.auto, Path("key.tex")), sheet_format(SheetFormat.json, None)
    ('latex', 'json')
    """
    named = SHEET_EXTENSIONS.get(output.suffix.lower()) if output is not None else None
    if fmt is SheetFormat.auto:
        return named or "markdown"
    if named in ("latex", "html", "json") and named != fmt.value:
        raise ValueError(
            f"--output {output} is {named} by its extension, but --format is {fmt.value}"
        )
    return fmt.value


def build(path: str) -> tuple[Sheet, list[Answered]]:
    """Read and answer the question file ``path``; a ``ValueError`` for any bad input."""
    sheet = read_file(path)
    return sheet, answer_questions(sheet.questions, sheet.source)


def write_document(text: str, output: Path | None) -> None:
    """``text`` to stdout, or atomically to ``output`` (exit 1 when it cannot be written)."""
    import sys

    if output is None:
        sys.stdout.write(text)
        sys.stdout.flush()
        return
    write_atomic(output, lambda f: f.write(text))


def write_pdf(latex: str, path: Path) -> None:
    """Compile ``latex`` (a complete document) with pdflatex in a temporary directory and
    move the PDF to ``path`` atomically. No pdflatex, or a failed run: one line, exit 1."""
    import os
    import shutil
    import subprocess
    import tempfile

    exe = shutil.which("pdflatex")
    if exe is None:
        fail(
            "--pdf needs pdflatex (TeX Live: apt install texlive-latex-recommended); or use -o FILE.tex",
            1,
        )
    with tempfile.TemporaryDirectory(prefix="scanconv-sheet-") as tmp:
        tex = Path(tmp) / "sheet.tex"
        tex.write_text(latex, encoding="utf-8")
        for _ in range(3):  # longtable settles its column widths in a second run
            try:
                done = subprocess.run(
                    [exe, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape",
                     "sheet.tex"],
                    cwd=tmp, capture_output=True, timeout=300,
                    env={**os.environ, "openout_any": "p"},
                )  # fmt: skip
            except (OSError, subprocess.TimeoutExpired) as err:
                fail(f"--pdf: pdflatex did not run: {err}", 1)
            if done.returncode != 0:
                log = (Path(tmp) / "sheet.log").read_text(encoding="utf-8", errors="replace")
                first = next((x for x in log.splitlines() if x.startswith("!")), "see its log")
                fail(f"--pdf: pdflatex failed: {first.lstrip('! ')}", 1)
            if b"Rerun" not in (Path(tmp) / "sheet.log").read_bytes():
                break
        data = (Path(tmp) / "sheet.pdf").read_bytes()
    write_atomic(path, lambda f: f.write(data), binary=True)


_HELP = (
    "Answer every question of a question file in one document: a numbered answer key "
    "(the default) or a worksheet for students.\n\n"
    "QUESTIONS holds one question per line, written as scanconv's own arguments "
    "(line 2 2 10 6 --algo dda); '[4]' before a question gives its marks, 'title: ...' the "
    "sheet's title, '> ...' the question's wording, 'section: ...' a heading; '#' starts a "
    "comment. See docs/teaching.md.\n\n"
    "Example: scanconv sheet questions.txt --format latex --standalone -o key.tex"
)


@app.command(help=_HELP)
def sheet(
    questions: Annotated[
        str,
        typer.Argument(
            metavar="QUESTIONS", help="The question file ('-': standard input).", show_default=False
        ),
    ],
    worksheet: Annotated[
        bool,
        typer.Option(
            "--worksheet/--key",
            help="A worksheet for students (the questions, the given values and empty tables) "
            "or the answer key (the default).",
        ),
    ] = False,
    fmt: SheetFormatOpt = SheetFormat.auto,
    output: SheetOutputOpt = None,
    standalone: Annotated[
        bool,
        typer.Option(
            "--standalone", help="LaTeX: a complete document (preamble, a page per question)."
        ),
    ] = False,
    pdf: Annotated[
        str | None,
        typer.Option(
            "--pdf",
            metavar="FILE",
            help="Also typeset the sheet as a PDF into FILE, atomically (needs pdflatex).",
            show_default=False,
        ),
    ] = None,
) -> None:
    """Answer every question of a question file in one document."""
    from ..render.sheet import sheet_document

    kind = "worksheet" if worksheet else "key"
    try:
        if pdf == "":
            raise ValueError("--pdf needs a file name")
        name = sheet_format(fmt, output)
        sheet, answered = build(questions)
        notices: list[str] = []
        text = sheet_document(sheet, answered, kind, name, standalone=standalone, notices=notices)
        latex = None
        if pdf is not None:
            latex = sheet_document(sheet, answered, kind, "latex", standalone=True)
    except ValueError as err:
        fail(" ".join(str(err).split()))
    write_outputs(text, output, latex, pdf, quiet=fmt is SheetFormat.auto)
    for message in dict.fromkeys(notices):
        note(message)


def write_outputs(
    text: str, output: Path | None, latex: str | None, pdf: str | None, *, quiet: bool
) -> None:
    """The PDF first (so a failure to typeset leaves stdout empty), then the document: to
    ``output``, or to stdout unless only the PDF was asked for (``quiet``: no --format)."""
    if latex is not None and pdf is not None:
        write_pdf(latex, Path(pdf))
        if output is None and quiet:
            return
    write_document(text, output)
