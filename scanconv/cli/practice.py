"""``scanconv practice``: seeded practice questions, as a worksheet and its answer key.

The questions come from :func:`scanconv.practice.notes.practice` and are run through
``sheet`` (:mod:`scanconv.cli.sheet`): the worksheet goes to stdout (or ``-o FILE``, or
``--pdf FILE``), the key to ``--key FILE`` and the question file itself to ``--questions
FILE``, so the teacher can hand out one, keep the other, and edit and re-run the questions::

    scanconv practice --topic line --count 8 --seed 7 -o worksheet.md --key key.md
    scanconv practice --seed 7 --pdf worksheet.pdf --key key.pdf --questions questions.txt

Everything is worked out and rendered before the first file is written.
"""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, NamedTuple

import typer

from ..core import lazy
from ..render import EXTENSIONS, FORMATS, formats
from ..render.documents.sheet import sheet_document
from .application import app
from .options import DocumentFormatOpt, OutputOpt, integer
from .output import check_paths, document_format, fail, note, write_all
from .sheet import answer_questions, pdf_file, pdf_output, read_questions, text_file, write_document

if TYPE_CHECKING:
    from ..practice import notes as answers_practice
else:  # the generator: not for --help
    answers_practice = lazy.module("scanconv.practice.notes")


class Topic(str, Enum):
    """What the practice questions are about."""

    line = "line"
    circle = "circle"
    ellipse = "ellipse"
    bezier = "bezier"
    bspline = "bspline"
    storage = "storage"
    quantize = "quantize"
    dither = "dither"
    inside = "inside"
    clip = "clip"
    framebuffer = "framebuffer"
    attributes = "attributes"
    characters = "characters"
    midpoint_line = "midpoint-line"
    antialias = "antialias"
    line_methods = "line-methods"
    visible = "visible"
    three_d = "3d"
    all = "all"


class Difficulty(str, Enum):
    """How hard the questions are."""

    easy = "easy"
    exam = "exam"
    hard = "hard"


SEED_RANGE = 10**9
"""Seeds run 0 .. 10**9 (the command line's number limit, ``core.numeric.COORD_LIMIT``)."""

_HELP = (
    "Practice questions from a seed (the same seed, the same questions): a worksheet on "
    "stdout or -o FILE, its answer key with --key FILE.\n\n"
    "Every octant, steep and negative slopes, right-to-left end points, ties and centres "
    "away from the origin come up by construction (docs/teaching.md). The --key file's format "
    "is taken from its extension (.md, .tex, .html, .json, .txt, .pdf; .xml and .gift: "
    "a quiz for Moodle, docs/lms.md).\n\n"
    "Example: scanconv practice --topic line --count 8 --seed 7 -o worksheet.md --key key.md"
)


@app.command(help=_HELP)
def practice(
    topic: Annotated[
        Topic, typer.Option("--topic", "-t", case_sensitive=False, help="The topic.")
    ] = Topic.all,
    count: Annotated[
        int, typer.Option("--count", "-n", parser=integer, help="How many questions (1-200).")
    ] = 10,
    seed: Annotated[
        int | None,
        typer.Option(
            "--seed",
            parser=integer,
            help="The seed (default: a new one, printed on stderr).",
            show_default=False,
        ),
    ] = None,
    difficulty: Annotated[
        Difficulty,
        typer.Option(
            "--difficulty",
            "-d",
            case_sensitive=False,
            help="easy (3-6 steps), exam (the notes' 14-mark questions: 6-12 steps, small "
            "integers) or hard (13-20 steps, negative coordinates).",
        ),
    ] = Difficulty.exam,
    fmt: DocumentFormatOpt = "auto",
    output: OutputOpt = None,
    key: Annotated[
        str | None,
        typer.Option(
            "--key",
            metavar="FILE",
            help="Write the answer key to FILE (.md, .tex, .html, .json, .txt, .pdf, .xml "
            "or .gift).",
            show_default=False,
        ),
    ] = None,
    questions: Annotated[
        str | None,
        typer.Option(
            "--questions",
            metavar="FILE",
            help="Write the question file to FILE (edit it and run scanconv sheet FILE).",
            show_default=False,
        ),
    ] = None,
    standalone: Annotated[
        bool, typer.Option("--standalone", help="LaTeX: complete documents.")
    ] = False,
    pdf: Annotated[
        str | None,
        typer.Option(
            "--pdf",
            metavar="FILE",
            help="Also typeset the worksheet as a PDF into FILE (needs pdflatex).",
            show_default=False,
        ),
    ] = None,
) -> None:
    """Practice questions from a seed, as a worksheet and its answer key."""
    output, pdf = pdf_output(output, pdf)
    seed, name = _checked(count, seed, fmt, output, key, questions, pdf)
    docs = _documents(topic, count, seed, difficulty, name, output, key, pdf, standalone)
    files = [pdf_file(pdf, docs.worksheet_tex)] if docs.worksheet_tex is not None and pdf else []
    if key is not None and docs.key_text is not None:
        files.append(
            pdf_file(key, docs.key_text) if docs.key_pdf else text_file(key, docs.key_text)
        )
    if questions is not None:
        files.append(text_file(questions, docs.questions))
    if output is not None:
        files.append(text_file(output, docs.worksheet))
    write_all(files)  # every file or none
    if output is None and not (pdf is not None and fmt == "auto"):
        write_document(docs.worksheet, None)  # unless only the PDF of the worksheet was asked for


def _checked(
    count: int,
    seed: int | None,
    fmt: str,
    output: Path | None,
    key: str | None,
    questions: str | None,
    pdf: str | None,
) -> tuple[int, str]:
    """The seed (a new one, announced, when none is given) and the worksheet's format, once
    the outputs, their formats and the count are checked: every refusal before any work."""
    for name, value in (("--key", key), ("--questions", questions), ("--pdf", pdf)):
        if value == "":
            fail(f"{name} needs a file name")
    outputs = [("--output", output), ("--key", key), ("--questions", questions), ("--pdf", pdf)]
    check_paths([], outputs)
    name = document_format(fmt, output)
    try:
        _key_format(key or "")
    except ValueError as err:
        fail(str(err))
    # checked before a seed is chosen and announced
    if not 1 <= count <= answers_practice.MAX_COUNT:
        fail(f"--count must be 1 to {answers_practice.MAX_COUNT} (got {count})")
    if seed is None:
        import secrets

        seed = secrets.randbelow(1_000_000)
        note(f"seed {seed} (give --seed {seed} for the same questions)")
    elif not 0 <= seed <= SEED_RANGE:
        fail(f"--seed must be 0 to {SEED_RANGE:,} (got {seed})")
    return seed, name


class _Documents(NamedTuple):
    questions: str
    worksheet: str
    worksheet_tex: str | None
    key_text: str | None
    key_pdf: bool


def _documents(
    topic: Topic,
    count: int,
    seed: int,
    difficulty: Difficulty,
    name: str,
    output: Path | None,
    key: str | None,
    pdf: str | None,
    standalone: bool,
) -> _Documents:
    """The question file, the worksheet (and its LaTeX for --pdf) and the key."""
    try:
        chosen = answers_practice.practice(topic.value, count, seed, difficulty.value)
        title = f"Practice: {topic.value}, {difficulty.value}, seed {seed}"
        text = answers_practice.question_file(chosen, title)
        sheet = read_questions(text, "practice")
        outputs = [name, *(["pdf"] if pdf is not None else [])]
        outputs += [_key_format(key)] if key is not None else []
        answered = answer_questions(sheet.questions, "practice", outputs)
        worksheet = sheet_document(sheet, answered, "worksheet", name, standalone=standalone)
        worksheet_tex = None
        if pdf is not None:
            worksheet_tex = sheet_document(sheet, answered, "worksheet", "latex", standalone=True)
        key_text, as_pdf = None, False
        if key is not None:
            key_fmt = _key_format(key)
            as_pdf = key_fmt == "pdf"
            key_text = sheet_document(
                sheet,
                answered,
                "key",
                "latex" if as_pdf else key_fmt,
                standalone=standalone or as_pdf,
            )
    except ValueError as err:
        fail(" ".join(str(err).split()))
    return _Documents(text, worksheet, worksheet_tex, key_text, as_pdf)


def _key_format(path: str) -> str:
    """The format of the ``--key`` file, by its extension (:data:`scanconv.render.EXTENSIONS`;
    markdown if it has none).

    >>> _key_format("key.tex"), _key_format("KEY.PDF"), _key_format("key")
    ('latex', 'pdf', 'markdown')
    """
    suffix = Path(path).suffix.lower()
    if suffix == ".pdf":
        return "pdf"
    named = EXTENSIONS.get(suffix)
    if suffix and (named is None or not FORMATS[named].sheet):
        known = ", ".join(e for f in formats("document") for e in FORMATS[f].extensions[:1])
        raise ValueError(f"--key {path}: unknown extension {suffix} ({known}, .pdf)")
    return named or "markdown"
