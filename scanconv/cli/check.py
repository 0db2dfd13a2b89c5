"""``scanconv check``: mark a student's table against a question, one file or a folder.

The question is another scanconv command line (``line 2 2 10 6 --algo bresenham``), parsed and
answered by the library's question language (:mod:`scanconv.questions`), so the question means
exactly what it means on the command line, flags, conventions and error messages included.
"""

from __future__ import annotations

import shlex
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from ..core import lazy
from ..core.records import Solution
from ..questions.marking import marking_answer, marking_line
from ..render import Format
from ..render.budget import check_batch
from .application import app
from .options import BriefOpt, ExactOpt, FormatOpt, OutputOpt
from .output import Output, check_paths, emit, fail, format_for_file, write_atomic

if TYPE_CHECKING:
    from ..marking import mark as marking
    from ..render.documents import scores as marking_formats
else:  # what marking a file needs: only the runs that mark one
    marking = lazy.module("scanconv.marking.mark")
    marking_formats = lazy.module("scanconv.render.documents.scores")

#: Output options written after the question still belong to ``check`` (the question's own
#: answer is never written): ``check a.csv -- line 2 2 10 6 -f md`` is markdown.
_OWN_VALUED = {"-f": "fmt", "--format": "fmt", "-o": "output", "--output": "output"}
_OWN_FLAGS = {"--brief": "brief", "--exact": "exact"}


def solve(question: list[str]) -> Solution:
    """The Solution of a scanconv command line, computed by the library's question language
    (:mod:`scanconv.questions.marking`).

    >>> solve(["line", "2", "2", "10", "6"]).title
    "Bresenham's line algorithm: (2, 2) to (10, 6)"
    """
    # the library's one pipeline, with the document's budget before any work
    return marking_answer(marking_line(question), document=True)


def _split_own(tail: list[str], own: dict[str, Any]) -> list[str]:
    """Take ``check``'s own output options out of the question's words."""
    out: list[str] = []
    i = 0
    while i < len(tail):
        a = tail[i]
        key, _, value = a.partition("=")
        if key in _OWN_VALUED and (value or i + 1 < len(tail)):
            if not value:
                i += 1
                value = tail[i]
            own[_OWN_VALUED[key]] = value
        elif a in _OWN_FLAGS:
            own[_OWN_FLAGS[a]] = True
        else:
            out.append(a)
        i += 1
    return out


@app.command(context_settings={"ignore_unknown_options": True, "allow_interspersed_args": False})
def check(
    args: Annotated[
        list[str],
        typer.Argument(
            help="The student's table (CSV, Markdown or JSON), then -- and the question as "
            "scanconv's own arguments. With --batch, only -- and the question.",
            metavar="ANSWER -- COMMAND...",
            show_default=False,
        ),
    ],
    batch: Annotated[
        str | None,
        typer.Option(
            "--batch",
            metavar="DIR",
            help="Mark every file in this folder; write a CSV of name, score, first error and "
            "diagnosis.",
        ),
    ] = None,
    fmt: FormatOpt = Format.auto,
    output: OutputOpt = None,
    brief: BriefOpt = False,
    exact: ExactOpt = False,
) -> None:
    """Mark a student's step table row by row against a question, with follow-through.

    Example: scanconv check alice.csv -- line 2 2 10 6 --algo bresenham
    """
    own: dict[str, Any] = {}
    words = [a for a in args if a != "--"]
    answer: Path | None = None
    if batch is None:
        if not words:
            fail("Missing argument 'ANSWER': give the student's file, then -- and the question")
        answer, words = Path(words[0]), words[1:]
    question = _split_own(words, own)
    try:
        fmt = Format(own.get("fmt", fmt.value))
    except ValueError:
        fail(f"--format: {own['fmt']!r} is not one of {', '.join(f.value for f in Format)}")
    output = Path(own["output"]) if "output" in own else output
    check_paths([("ANSWER", answer), ("--batch", batch)], [("--output", output)])
    brief = own.get("brief", brief)
    exact = own.get("exact", exact)
    try:
        solution = solve(question)
        text = shlex.join(question)  # the words as typed: quotes kept around "10 200; 30 5"
        if batch is not None:
            _batch(Path(batch), solution, text, fmt, output)
            return
        assert answer is not None
        marked = marking.mark_file(answer, solution)
        result = marking.marking_solution(marked, solution, answer.name, text)
    except ValueError as err:
        fail(" ".join(str(err).split()))
    emit(result, Output(fmt=fmt, output=output, brief=brief, exact=exact))


def _regular(path: Path) -> bool:
    """A regular file of the folder itself: a link is never followed out of it."""
    return not path.is_symlink() and path.is_file()


def _shown(name: str) -> str:
    """A file name as a score sheet shows it: bytes that are not UTF-8, control and bidi
    characters each shown as U+FFFD (a name never moves the terminal's cursor or reorders
    the text), so every format can write it."""
    text = name.encode("utf-8", "surrogateescape").decode("utf-8", "replace")
    return "".join(c if c.isprintable() else "\ufffd" for c in text)


def _mark_one(
    path: Path, solution: Solution, mark_file: Any
) -> tuple[str, int | None, int | None, str, str]:
    """One file's row of the score sheet; a file that cannot be marked gets a row saying why
    (the rest of the class is still marked)."""
    name = _shown(path.name)
    if not _regular(path):
        why = "a link (links are not followed)" if path.is_symlink() else "not a regular file"
        return (name, None, None, f"not marked: {why}", "")
    try:
        m = mark_file(path, solution)
    except ValueError as err:
        message = _shown(" ".join(str(err).split()))
        return (name, None, None, f"not marked: {message}", "")
    return (name, m.right, m.total, m.first_error, m.diagnosis)


def _output_apart(folder: Path, files: list[Path], output: Path | None) -> None:
    """Refuse (exit 2) a score sheet written over one of the batch's files (a student's
    submission: the same file by any name, a link or a hard link) or into the folder marked
    (the next run would mark it as a student's file)."""
    check_paths([("the student's file", p) for p in files], [("--output", output)])
    if output is not None and output.parent.resolve() == folder.resolve():
        fail(f"--output {output}: inside the --batch folder {folder}; write the scores elsewhere")


def _batch(
    folder: Path, solution: Solution, question: str, fmt: Format, output: Path | None
) -> None:
    """Mark every file of ``folder`` and write one row each (exit 0 whatever the marks): CSV
    (the default, also on a terminal), JSON, or a table in the text formats."""
    chosen = format_for_file(fmt, output)
    try:
        files = sorted(p for p in folder.iterdir() if not p.name.startswith("."))
    except OSError as err:
        fail(f"--batch {folder}: cannot read the folder: {err.strerror or err}")
    if not files:
        fail(f"--batch {folder}: no files to mark")
    _output_apart(folder, files, output)
    sizes = [p.lstat().st_size for p in files if _regular(p)]
    check_batch(sizes, solution)  # before any file is read
    results = [_mark_one(path, solution, marking.mark_file) for path in files]
    if chosen not in (Format.auto, Format.csv, Format.json):  # a table to read, not a sheet
        emit(marking.batch_solution(results, solution, question), Output(fmt=chosen, output=output))
        return
    if chosen is Format.json:
        rows = marking_formats.batch_json(results, question)
    else:
        rows = marking_formats.batch_csv(results)
    text = "".join(rows)
    if output is None:
        sys.stdout.write(text)
        sys.stdout.flush()
    else:
        write_atomic(output, lambda f: f.write(text))
