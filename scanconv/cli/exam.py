"""``scanconv exam``: the whole exam of the course notes, answered, as one book.

The book is the question file shipped in the package (``scanconv/data/exam.txt``: every
TYPICAL EXAM QUESTION of the notes and the seven closing topics, each worded as the notes word
it and answered by a scanconv command line) run through :mod:`scanconv.cli.sheet`, with a table
of contents. ``--source`` prints the file, so a teacher can copy it, edit it and run it with
``scanconv sheet``. ``--section`` keeps one section.
"""

from __future__ import annotations

import json
import re
from typing import Annotated

import typer

from ..core.working import tex_text
from ..render.sheet import md_text, sheet_document
from .application import app
from .options import DocumentFormatOpt, OutputOpt
from .output import document_format, fail
from .sheet import Answered, Sheet, answer_questions, read_questions, write_document

EXAM_FILE = "exam.txt"
"""The question file, in the package ``scanconv.data``."""


def exam_text() -> str:
    """The shipped question file.

    >>> exam_text().count("section:")
    7
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
    """
    key = slug(wanted)
    if wanted.strip().isdigit() and 1 <= int(wanted) <= len(sections):
        return sections[int(wanted) - 1]
    found = [s for s in sections if slug(s) == key]
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


# --- the table of contents ----------------------------------------------------------------------


def _contents(answered: list[Answered], fmt: str) -> str:
    """The table of contents of the book in ``fmt`` (markdown or plain)."""
    lines = ["## Contents", ""] if fmt == "markdown" else ["Contents", "--------", ""]
    section = None
    for a in answered:
        q = a.question
        if q.section != section:
            section = q.section
            lines.append(f"- {md_text(section)}" if fmt == "markdown" else section)
        text = " ".join(q.wording.split())
        text = md_text(text) if fmt == "markdown" else text
        lines.append(f"    {q.number}. {text}" if fmt == "markdown" else f"  {q.number}. {text}")
    return "\n".join(lines) + "\n\n"


def _html_contents(document: str, answered: list[Answered]) -> str:
    """The HTML book with a linked table of contents after its introduction (each question's
    section has the id ``q<number>``)."""
    from html import escape

    items: list[str] = ['<nav class="sc-contents" aria-label="contents">', "<h2>Contents</h2>"]
    section = None
    for a in answered:
        q = a.question
        if q.section != section:
            if section is not None:
                items.append("</ol></li>")
            section = q.section
            items.append(f"<li>{escape(section or '')}<ol>" if section else "<li><ol>")
        text = escape(" ".join(q.wording.split()) or q.command)
        items.append(f'<li value="{q.number}"><a href="#q{q.number}">{text}</a></li>')
    if section is not None or answered:
        items.append("</ol></li>")
    nav = "\n".join([items[0], items[1], "<ul>", *items[2:], "</ul>", "</nav>"]) + "\n"
    start = document.find('<main class="sc-sheet">')
    at = document.find("</p>\n", start)
    if start < 0 or at < 0:
        return document
    at += len("</p>\n")
    return document[:at] + nav + document[at:]


_SECTION = re.compile(r"\\section\*\{\\raggedright (.*)\}")
_QUESTION = re.compile(r"\\subsection\*\{Question (\d+)\b.*")


def _with_contents(document: str, answered: list[Answered], fmt: str, title: bool) -> str:
    """``document`` (a whole sheet) with its table of contents: in markdown and plain after
    the title and the count of questions, in LaTeX ``\\tableofcontents`` and a contents line
    for every section and question (pdflatex twice fills it in)."""
    if fmt == "html":
        return _html_contents(document, answered)
    lines = document.split("\n")
    if fmt in ("markdown", "plain"):
        at = next((i for i, line in enumerate(lines) if line.startswith("Answer key")), -1)
        contents = _contents(answered, fmt).rstrip("\n").split("\n")
        return "\n".join([*lines[: at + 2], *contents, "", *lines[at + 2 :]])
    if fmt != "latex":
        return document
    wording = {a.question.number: " ".join(a.question.wording.split()) for a in answered}
    out: list[str] = []
    placed = not title  # the title is a \section* too: the contents come after it
    for line in lines:
        section, question = _SECTION.fullmatch(line), _QUESTION.fullmatch(line)
        if section and not placed:
            placed = True
            out.append(line)
            continue
        if section:
            if "\\tableofcontents" not in out:
                out += ["\\tableofcontents", "\\clearpage"]
            out += [line, f"\\addcontentsline{{toc}}{{section}}{{{section.group(1)}}}"]
        elif question:
            entry = f"{question.group(1)}. {tex_text(wording[int(question.group(1))])}"
            out += [line, f"\\addcontentsline{{toc}}{{subsection}}{{{entry}}}"]
        else:
            out.append(line)
    return "\n".join(out)


# --- the command ----------------------------------------------------------------------------------


def exam_sheet(section: str | None = None) -> Sheet:
    """The shipped question file, parsed; with ``section``, that section only."""
    sheet = read_questions(exam_text(), "scanconv/data/exam.txt")
    if section is None:
        return sheet
    names = list(dict.fromkeys(q.section for q in sheet.questions))
    chosen = pick_section(names, section)
    questions = tuple(q for q in sheet.questions if q.section == chosen)
    return sheet._replace(title=f"{sheet.title}: {chosen}", questions=questions)


def contents(section: str | None, fmt: str) -> str:
    """Only the table of contents (nothing is answered): markdown, plain, LaTeX or JSON."""
    sheet = exam_sheet(section)
    entries = [Answered(q, None, None) for q in sheet.questions]  # type: ignore[arg-type]
    if fmt == "json":
        rows = [
            {"number": q.number, "section": q.section, "question": " ".join(q.wording.split())}
            for q in sheet.questions
        ]
        return (
            json.dumps({"title": sheet.title, "contents": rows}, ensure_ascii=False, indent=1)
            + "\n"
        )
    if fmt == "latex":
        lines = ["\\section*{Contents}", "\\begin{itemize}"]
        for q in sheet.questions:
            lines.append(f"  \\item {q.number}. {tex_text(' '.join(q.wording.split()))}")
        return "\n".join([*lines, "\\end{itemize}", ""])
    if fmt not in ("markdown", "plain"):
        raise ValueError(f"--contents is not available in {fmt}: markdown, plain, latex or json")
    return _contents(entries, fmt)


def book(section: str | None, fmt: str, *, standalone: bool = False) -> str:
    """The exam book (or one section of it) as one document in ``fmt``."""
    sheet = exam_sheet(section)
    answered = answer_questions(sheet.questions, sheet.source)
    document = sheet_document(sheet, answered, "key", fmt, standalone=standalone)
    return _with_contents(document, answered, fmt, bool(sheet.title))


@app.command()
def exam(
    section: Annotated[
        str | None,
        typer.Option(
            "--section",
            "-s",
            metavar="SECTION",
            help="Only this section: its number (1-7) or name (scan-conversion, "
            "image-representation, line-drawing, dda, bresenham, circle-drawing, 14).",
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
    shown under it.
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
