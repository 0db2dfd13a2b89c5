"""``scanconv sheet QUESTIONS``: a numbered answer key or a worksheet from a file of questions.

The API (what other commands, the exam book and the tests build on)::

    read_questions(text, source) -> Sheet
        Parse a question file (below). A malformed line raises QuestionError, whose text is
        "SOURCE:LINE: message".
    answer_questions(questions) -> list[Answered]
        Answer each question's command line in this process with the library's question
        language (:mod:`scanconv.questions`: the same words, defaults and messages as
        ``scanconv ...`` itself, without the command line's parser), and return (question,
        Solution, render Options) triples. The first bad question raises QuestionError with
        its line and the error scanconv would give for that command line.
    sheet_document(sheet, answered, kind, fmt, standalone=False) -> str
        (:mod:`scanconv.render.documents.sheet`) the whole key or worksheet, rendered in memory, so a bad
        question never leaves a partial file.

The question file (one question per line, written as scanconv's own arguments) is read by
:mod:`scanconv.questions.files`. A question may carry the options that change how its answer
is shown (``--no-grid``, ``--brief``, ``--exact``, ``--origin``); the format and the output
file are the sheet's.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from ..questions import answered, parse, shown_with
from ..questions.files import (
    MAX_FILE_BYTES,
    MAX_QUESTIONS,
    QuestionError,
    every,
    read_file,
    read_questions,
    strip_comment,
)
from ..render import Options
from ..render.budget import document
from ..render.documents.sheet import Answered, Question, Sheet, sheet_document
from .application import app
from .budget import DocumentTooLarge, check_question
from .options import DocumentFormatOpt, OutputOpt
from .output import Pending, check_paths, document_format, fail, note, write_all, write_atomic

if TYPE_CHECKING:
    from ..core.records import Solution

__all__ = ["Answered", "Question", "QuestionError", "Sheet", "answer", "answer_questions"]
__all__ += ["read_file", "read_questions", "sheet", "strip_comment"]
__all__ += ["MAX_FILE_BYTES", "MAX_QUESTIONS"]

# --- answering ------------------------------------------------------------------------------


def answer(argv: Iterable[str]) -> tuple[Solution, Options]:
    """The answer of one command line, as ``scanconv ARGV`` would give it, computed by the
    library (:mod:`scanconv.questions`): ``(solution, options)``. Bad input is a
    ``ValueError`` worded as scanconv words it.

    >>> solution, options = answer(["line", "2", "2", "10", "6", "--algo", "dda", "--no-grid"])
    >>> solution.algorithm, options.grid
    ('dda', False)
    >>> answer(["line", "2", "2", "10"])
    Traceback (most recent call last):
    ...
    scanconv.questions.words.UsageError: Missing argument 'Y2'.
    """
    line = parse(list(argv))
    options = shown_with(line)
    # the document's budget (alone and with the questions before it) before any work: beyond
    # it, the questions after this one are not read on (DocumentTooLarge); then the library's
    # one pipeline (each format's budget, the answer)
    check_question(line.function, line.arguments)
    return answered(line)[1], options


def answer_questions(
    questions: Iterable[Question], source: str = "QUESTIONS", outputs: Sequence[str] = ()
) -> list[Answered]:
    """Answer every question in this process (see the module docstring); the first bad one
    raises :class:`QuestionError` with its line, and so does the first question beyond the
    work budget of a document, alone or with the questions before it
    (:func:`scanconv.render.budget.document`: ``outputs`` names the formats it is written
    in, ``"pdf"`` for a PDF, each with the rows it holds).

    >>> sheet = read_questions("line 2 2 10 6 --algo dda\\n\\ncircle 0.5\\n", "q.txt")
    >>> answer_questions(sheet.questions, sheet.source)
    Traceback (most recent call last):
    ...
    scanconv.questions.files.QuestionError: q.txt:3: radius must be an integer, got 0.500
    """
    with document(outputs):
        return _answer_all(questions, source)


def _answer_all(questions: Iterable[Question], source: str) -> list[Answered]:
    """Every question answered; every bad one named (:func:`~scanconv.questions.files.every`)."""
    out, errors = [], []
    for q in questions:
        try:
            solution, options = answer(q.argv)
        except DocumentTooLarge as err:  # the document, not this line: the rest not read on
            errors.append(QuestionError(source, q.line, " ".join(str(err).split())))
            break
        except ValueError as err:
            errors.append(QuestionError(source, q.line, " ".join(str(err).split())))
        except RecursionError:
            errors.append(QuestionError(source, q.line, "input too deeply nested"))
        else:
            out.append(Answered(q, solution, options))
    if errors:
        raise every(errors)
    return out


# --- the command ----------------------------------------------------------------------------


def build(path: str, outputs: Sequence[str] = ()) -> tuple[Sheet, list[Answered]]:
    """Read and answer the question file ``path`` for a document written in ``outputs``
    (:func:`answer_questions`); a ``ValueError`` for any bad input."""
    try:
        sheet = read_file(path)
    except QuestionError as bad:  # its good questions are answered too: every bad line named
        if bad.sheet is not None:
            try:
                answer_questions(bad.sheet.questions, bad.sheet.source, outputs)
            except QuestionError as more:
                raise every([bad, more]) from None
        raise
    return sheet, answer_questions(sheet.questions, sheet.source, outputs)


def write_document(text: str, output: Path | None) -> None:
    """``text`` to stdout, or atomically to ``output`` (exit 1 when it cannot be written)."""
    import sys

    if output is None:
        sys.stdout.write(text)
        sys.stdout.flush()
        return
    write_atomic(output, lambda f: f.write(text))


def text_file(path: str | Path, text: str) -> Pending:
    """``text`` to be written to ``path`` by :func:`~scanconv.cli.output.write_all`."""
    return Path(path), lambda f: f.write(text), False


def pdf_file(path: str | Path, latex: str) -> Pending:
    """The PDF of ``latex`` (typeset now) to be written to ``path`` by
    :func:`~scanconv.cli.output.write_all`."""
    data = typeset(latex)
    return Path(path), lambda f: f.write(data), True


def write_pdf(latex: str, path: Path) -> None:
    """Compile ``latex`` and write the PDF to ``path`` atomically (:func:`typeset`)."""
    write_all([pdf_file(path, latex)])


def typeset(latex: str) -> bytes:
    """The PDF of ``latex`` (a complete document), compiled with pdflatex in a temporary
    directory. No pdflatex, or a failed run: one line, exit 1."""
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
        return (Path(tmp) / "sheet.pdf").read_bytes()


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
    fmt: DocumentFormatOpt = "auto",
    output: OutputOpt = None,
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
    contents: Annotated[
        bool,
        typer.Option(
            "--contents",
            help="A table of contents under the title, each question under its section "
            "(LaTeX and PDF: with page numbers; HTML: linked).",
        ),
    ] = False,
    quiz_symmetry: Annotated[
        bool,
        typer.Option(
            "--quiz-symmetry",
            help="Moodle and GIFT: also ask each circle's and ellipse's symmetry table (the "
            "mirrored points), not only the octant's steps the exam asks (one question: a "
            "'quiz: symmetry' line before it).",
        ),
    ] = False,
) -> None:
    """Answer every question of a question file in one document."""
    kind = "worksheet" if worksheet else "key"
    if pdf == "":
        fail("--pdf needs a file name")
    output, pdf = pdf_output(output, pdf)
    check_paths([("QUESTIONS", questions)], [("--output", output), ("--pdf", pdf)])
    name = document_format(fmt, output)
    try:
        sheet, answered = build(questions, (name, "pdf") if pdf is not None else (name,))
        sheet = sheet._replace(contents=contents)
        if quiz_symmetry:
            answered = [asking(a, "symmetry") for a in answered]
        notices: list[str] = []
        text = sheet_document(sheet, answered, kind, name, standalone=standalone, notices=notices)
        latex = None
        if pdf is not None:
            latex = sheet_document(sheet, answered, kind, "latex", standalone=True)
    except QuestionError as err:  # a line on stderr for each bad line of the file
        for line in err.lines[:-1]:
            note(f"error: {line}")
        fail(err.lines[-1])
    except ValueError as err:
        fail(" ".join(str(err).split()))
    write_outputs(text, output, latex, pdf, quiet=fmt == "auto")
    for message in dict.fromkeys(notices):
        note(message)


def asking(a: Answered, what: str) -> Answered:
    """``a`` whose quiz also asks ``what`` (``symmetry``: a question file's ``quiz:`` word)."""
    q = a.question
    return a._replace(question=q._replace(quiz=tuple(dict.fromkeys((*q.quiz, what)))))


def pdf_output(output: Path | None, pdf: str | None) -> tuple[Path | None, str | None]:
    """``-o FILE.pdf`` as ``--pdf FILE.pdf`` (a document's PDF, typeset by pdflatex), so that
    no other format is written under a PDF's name; with ``--pdf`` as well it is refused
    later (:func:`~scanconv.cli.output.named_format`).

    >>> pdf_output(Path("key.pdf"), None), pdf_output(Path("key.md"), None)
    ((None, 'key.pdf'), (PosixPath('key.md'), None))
    """
    if output is not None and output.suffix.lower() == ".pdf" and pdf is None:
        return None, str(output)
    return output, pdf


def write_outputs(
    text: str, output: Path | None, latex: str | None, pdf: str | None, *, quiet: bool
) -> None:
    """The PDF and the document's file, all or none (so a failure to typeset or to write
    leaves stdout empty and no file), then the document to stdout unless it went to
    ``output`` or only the PDF was asked for (``quiet``: no --format)."""
    files = [pdf_file(pdf, latex)] if latex is not None and pdf is not None else []
    if output is not None:
        files.append(text_file(output, text))
    write_all(files)
    if output is None and not (files and quiet):
        write_document(text, None)
