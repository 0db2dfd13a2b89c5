"""``scanconv exam``: the whole exam of the course notes, answered, as one book.

The book is the question file shipped in the package (``scanconv/data/exam.txt``: every
TYPICAL EXAM QUESTION of the notes and the seven closing topics, each worded as the notes word
it and answered by a scanconv command line, then a section of its own for the 3D chapter beyond
the notes, the typical questions of the papers, numbered after the notes' 37) run through
:mod:`scanconv.cli.sheet`, with a table of contents. ``--source`` prints the file, so a teacher can copy it, edit it and run it with
``scanconv sheet``. ``--section`` keeps one section.
"""

from __future__ import annotations

import re
from typing import Annotated

import typer

from ..render.documents.sheet import CONTENTS_ALONE, contents_document, sheet_document
from .application import app
from .options import DocumentFormatOpt, OutputOpt
from .output import document_format, fail
from .sheet import Sheet, answer_questions, read_questions, write_document

EXAM_FILE = "exam.txt"
"""The question file, in the package ``scanconv.data``."""

BEYOND_NOTES = "The 3D chapter (beyond the notes)"
"""The book's last section: the 3D chapter's typical questions, which the notes do not ask
(numbered after the notes' questions, so theirs keep their numbers)."""


def exam_text() -> str:
    """The shipped question file.

    >>> exam_text().count("section:")
    8
    """
    from importlib.resources import files

    return (files("scanconv.data") / EXAM_FILE).read_text(encoding="utf-8")


def slug(name: str) -> str:
    """A section's name for ``--section``.

    >>> slug("Bresenham's line algorithm"), slug("The 14-mark topics")
    ('bresenhams-line-algorithm', 'the-14-mark-topics')
    """
    return re.sub(r"[^a-z0-9]+", "-", name.lower().replace("'", "")).strip("-")


def pick_section(sections: list[str], wanted: str) -> str:
    """The section ``wanted`` names: its number (1 ..), its name in any case, or the start
    of its slug (``dda``, ``bresenham``, ``14``); else ``ValueError`` listing them.

    >>> names = ["Line drawing", "Simple DDA algorithm", "The 14-mark topics"]
    >>> pick_section(names, "2"), pick_section(names, "line"), pick_section(names, "14")
    ('Simple DDA algorithm', 'Line drawing', 'The 14-mark topics')
    >>> pick_section(names, "-1")
    Traceback (most recent call last):
    ...
    ValueError: --section '-1' is not a section (1-3 or one of: line-drawing, simple-dda-algorithm, the-14-mark-topics)
    """
    key = slug(wanted)
    if wanted.strip().isdigit() and 1 <= int(wanted) <= len(sections):
        return sections[int(wanted) - 1]
    if re.fullmatch(r"\s*[-+][0-9]+\s*", wanted):
        key = ""  # a signed number is no section (the slug of -1, "1", starts "14")
    found = [s for s in sections if key and slug(s) == key]
    found = found or [
        s for s in sections if key and any(w.startswith(key) for w in _words(slug(s)))
    ]
    if len(found) == 1:
        return found[0]
    names = ", ".join(slug(s) for s in sections)
    what = "matches several sections" if found else "is not a section"
    raise ValueError(f"--section {wanted!r} {what} (1-{len(sections)} or one of: {names})")


def _words(s: str) -> list[str]:
    """The slug and every tail of it that starts a word: ``dda-algorithm``, ``algorithm``."""
    parts = s.split("-")
    return ["-".join(parts[i:]) for i in range(len(parts))]


# --- the command ----------------------------------------------------------------------------------


def exam_sheet(section: str | None = None) -> Sheet:
    """The shipped question file, parsed; with ``section``, that section only."""
    sheet = read_questions(exam_text(), "scanconv/data/exam.txt")._replace(contents=True)
    if section is None:
        return sheet
    names = list(dict.fromkeys(q.section for q in sheet.questions))
    chosen = pick_section(names, section)
    questions = tuple(q for q in sheet.questions if q.section == chosen)
    return sheet._replace(title=f"{sheet.title}: {chosen}", questions=questions)


def contents(section: str | None, fmt: str) -> str:
    """Only the table of contents (nothing is answered): markdown, plain, LaTeX or JSON."""
    if fmt not in (*CONTENTS_ALONE, "json"):
        choices = ", ".join((*CONTENTS_ALONE, "json"))
        raise ValueError(f"--contents is not available in {fmt}: choose from {choices}")
    return contents_document(exam_sheet(section), fmt)


def book(section: str | None, fmt: str, *, standalone: bool = False) -> str:
    """The exam book (or one section of it) as one document in ``fmt``."""
    sheet = exam_sheet(section)
    answered = answer_questions(sheet.questions, sheet.source)
    return sheet_document(sheet, answered, "key", fmt, standalone=standalone)


@app.command()
def exam(
    section: Annotated[
        str | None,
        typer.Option(
            "--section",
            "-s",
            metavar="SECTION",
            help="Only this section: its number (1-8) or name (scan-conversion, "
            "image-representation, line-drawing, dda, bresenham, circle-drawing, 14, 3d).",
        ),
    ] = None,
    fmt: DocumentFormatOpt = "auto",
    output: OutputOpt = None,
    standalone: Annotated[
        bool,
        typer.Option("--standalone", help="LaTeX: a complete document (preamble, contents)."),
    ] = False,
    only_contents: Annotated[
        bool,
        typer.Option("--contents", help="Only the table of contents (nothing is answered)."),
    ] = False,
    source: Annotated[
        bool,
        typer.Option(
            "--source",
            help="Print the book's question file (to copy, edit and run with scanconv sheet).",
        ),
    ] = False,
) -> None:
    """The whole exam of the notes answered, as one book with a table of contents.

    Every typical exam question and the seven 14-mark topics, each answered by the command
    shown under it; then the 3D chapter beyond the notes (projections, visible surfaces).
    Example: scanconv exam --format latex --standalone -o exam.tex
    """
    name = document_format(fmt, output)
    try:
        if source:
            text = exam_text()
        elif only_contents:
            text = contents(section, name)
        else:
            text = book(section, name, standalone=standalone)
    except ValueError as err:
        fail(" ".join(str(err).split()))
    write_document(text, output)
