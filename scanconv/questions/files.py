"""Question files: one question per line, written as scanconv's own arguments.

::

    title: Unit 2 test: scan conversion        (optional, once)
    section: Lines                             (optional: a heading for the questions after it)
    # a comment; blank lines are ignored
    > Draw the line from (2, 2) to (10, 6) with the DDA algorithm.   (optional wording)
    quiz: symmetry                             (optional: its quiz also asks the mirrored points)
    [4] line 2 2 10 6 --algo dda               ([N] or [N marks]: the marks, optional)
    circle 8 --center 2 3   # a comment after a question

Words are split as a shell splits them (quote a formula: ``sample 'x + y' --size 4``), and ``#``
starts a comment where a shell's does (at the start of a word, outside quotes). Lines end at
``\\n``, ``\\r\\n`` or ``\\r`` only, as an editor counts them: any other separator (U+2028,
U+0085, a form feed) is a character of its line, replaced like every control character, so it
can neither start a question nor shift a line number. A UTF-8 byte-order mark is skipped.
"""

from __future__ import annotations

import os
import re
import stat
from collections.abc import Sequence

from ..render.documents.sheet import Question, Sheet
from .limits import MAX_FILE_BYTES, MAX_LINE_CHARS, check_text_size

__all__ = ["MAX_FILE_BYTES", "MAX_LINE_CHARS", "MAX_QUESTIONS", "QuestionError"]
__all__ += ["every", "read_file", "read_questions", "split_lines", "strip_comment"]

MAX_QUESTIONS = 1000
"""The most questions one sheet takes (a 200-question key is the benchmark)."""


class QuestionError(ValueError):
    """A bad line of a question file: ``str()`` is ``SOURCE:LINE: message``. The error of a
    file with several bad lines (:func:`every`) holds them all in ``errors``, its ``str()``
    a line each, and ``sheet`` holds the file's good questions (issue 39: every bad line is
    reported at once, not the first alone)."""

    def __init__(self, source: str, line: int, message: str) -> None:
        super().__init__(f"{source}:{line}: {message}")
        self.source, self.line, self.message = source, line, message
        self.errors: tuple[QuestionError, ...] = (self,)
        self.sheet: Sheet | None = None

    @property
    def lines(self) -> list[str]:
        """One line per bad line: ``SOURCE:LINE: message``, its spaces collapsed."""
        return [f"{e.source}:{e.line}: {' '.join(e.message.split())}" for e in self.errors]


def every(errors: Sequence[QuestionError], sheet: Sheet | None = None) -> QuestionError:
    """The bad lines of one file as one error, in the order of their lines.

    >>> err = every([QuestionError("q", 5, "b"), QuestionError("q", 2, "a")])
    >>> str(err).splitlines(), err.line, err.lines
    (['q:2: a', 'q:5: b'], 2, ['q:2: a', 'q:5: b'])
    """
    ordered = sorted((e for err in errors for e in err.errors), key=lambda e: e.line)
    first = QuestionError(ordered[0].source, ordered[0].line, ordered[0].message)
    first.args = ("\n".join(str(e) for e in ordered),)
    first.errors, first.sheet = tuple(ordered), sheet
    return first


_MARKS = re.compile(r"^\[\s*(\d{1,4})\s*(?:marks?\s*)?\]\s*", re.IGNORECASE)
_KEYWORD = re.compile(r"^(title|section|quiz)\s*:\s*(.*)$", re.IGNORECASE)
QUIZ_ASKS = ("symmetry",)
"""What a ``quiz:`` line may ask beyond the exam's own question (docs/lms.md): ``symmetry``,
the symmetry tables (a circle's 8-way, an ellipse's 4-way mirrored points)."""
_LINE_END = re.compile(r"\r\n|\r|\n")
#: ESC, BEL, NEL, FF, VT, the line and paragraph separators...: never echoed, never a line end
_CONTROL = re.compile("[\x01-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029]")


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


def split_lines(text: str) -> list[str]:
    """The lines of ``text`` as an editor numbers them: split at ``\\n``, ``\\r\\n`` and
    ``\\r`` only (``str.splitlines`` also splits at U+2028, U+0085, FF, VT...).

    >>> split_lines("a\\r\\nb\\rc\\u2028d\\x0ce\\n")
    ['a', 'b', 'c\\u2028d\\x0ce']
    """
    lines = _LINE_END.split(text)
    return lines[:-1] if lines and lines[-1] == "" else lines


def read_questions(text: str, source: str = "QUESTIONS") -> Sheet:
    """Parse the text of a question file (the syntax is in this module's docstring).
    A text beyond :data:`MAX_FILE_BYTES` is refused (``ValueError``) before any line is
    read, as :func:`read_file` refuses the file, and a line beyond :data:`MAX_LINE_CHARS`
    before it is split into words.

    Parameters
    ----------
    text : str
        The file's text: one question a line, with optional ``title:``, ``section:``,
        ``> wording`` and ``[N]`` marks.
    source : str, default "QUESTIONS"
        The file's name, in the errors (``SOURCE:LINE: message``).

    Returns
    -------
    Sheet
        The ``title`` and the ``questions``, each with its number, line, words (``argv``), marks,
        wording and section.

    Raises
    ------
    QuestionError
        A bad line (a ``ValueError``): unbalanced quotes, a line too long, too many questions.

    Examples
    --------
    >>> sheet = read_questions("title: Test\\n# c\\n[4] line 2 2 10 6 --algo dda\\ncircle 8\\n")
    >>> sheet.title, [(q.number, q.line, q.marks, q.argv[0]) for q in sheet.questions]
    ('Test', [(1, 3, 4, 'line'), (2, 4, None, 'circle')])
    >>> read_questions("line 2 2 'x")
    Traceback (most recent call last):
    ...
    scanconv.questions.files.QuestionError: QUESTIONS:1: unbalanced quotes: No closing quotation

    Control characters (a terminal escape sequence) become U+FFFD, so no output echoes them:

    >>> read_questions("title: A\\x1b[31mB\\nline 0 0 1 1").title
    'A\\ufffd[31mB'
    """
    check_text_size(text, source)
    title = ""
    section = ""
    wording: list[str] = []
    quiz: tuple[str, ...] = ()  # the next question's quiz: what it asks beyond the exam's
    questions: list[Question] = []
    errors: list[QuestionError] = []
    number = 0
    for number, raw in enumerate(split_lines(text.removeprefix("\ufeff")), 1):
        try:
            if len(raw) > MAX_LINE_CHARS:
                raise QuestionError(
                    source, number, f"a line of {len(raw):,} characters; at most {MAX_LINE_CHARS:,}"
                )
            stripped = _CONTROL.sub("\ufffd", raw).strip()
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
                if name == "quiz":
                    quiz = _quiz_asks(value, source, number)
                elif name == "title":
                    if title:
                        raise QuestionError(source, number, "a second title line (one per sheet)")
                    title = value
                else:
                    section = value
                continue
            marks, argv = _question(stripped, source, number)
            if len(questions) == MAX_QUESTIONS:
                raise QuestionError(
                    source, number, f"at most {MAX_QUESTIONS} questions in one sheet"
                )
            questions.append(
                Question(len(questions) + 1, number, argv, marks, " ".join(wording), section, quiz)
            )
            wording, quiz = [], ()
        except QuestionError as err:  # the next lines are read on: every bad line is named
            errors.append(err)
            wording, quiz = [], ()
            if len(questions) == MAX_QUESTIONS:
                # a sheet over the limit is refused at once: its questions are not weighed
                # one by one for their own errors (a thousand of them would be answered)
                raise every(errors) from None
    if wording:
        errors.append(QuestionError(source, number, "'>' wording without a question after it"))
    if quiz:
        errors.append(QuestionError(source, number, "'quiz:' without a question after it"))
    if errors:
        raise every(errors, Sheet(title, tuple(questions), source))
    return Sheet(title, tuple(questions), source)


def _quiz_asks(value: str, source: str, number: int) -> tuple[str, ...]:
    """A ``quiz:`` line's words (``symmetry``), each one of :data:`QUIZ_ASKS`.

    >>> _quiz_asks("Symmetry", "q.txt", 3)
    ('symmetry',)
    >>> _quiz_asks("all", "q.txt", 3)
    Traceback (most recent call last):
    ...
    scanconv.questions.files.QuestionError: q.txt:3: 'quiz:' takes symmetry, not 'all'
    """
    words = tuple(dict.fromkeys(value.lower().replace(",", " ").split()))
    bad = [w for w in words if w not in QUIZ_ASKS]
    if bad:
        raise QuestionError(source, number, f"'quiz:' takes {', '.join(QUIZ_ASKS)}, not {bad[0]!r}")
    return words


def _question(line: str, source: str, number: int) -> tuple[int | None, tuple[str, ...]]:
    """A question line's marks (``None``: none given) and its words."""
    import shlex

    marks = None
    found = _MARKS.match(line)
    if found:
        marks = int(found.group(1))
        line = line[found.end() :]
    elif line.startswith("["):
        raise QuestionError(
            source, number, "marks are written [N] or [N marks] before the question, e.g. [4]"
        )
    try:
        argv = tuple(shlex.split(strip_comment(line)))
    except ValueError as err:
        raise QuestionError(source, number, f"unbalanced quotes: {err}") from None
    if not argv:
        raise QuestionError(source, number, "marks without a question")
    return marks, argv


def _read_bytes(path: str) -> bytes:
    """At most :data:`MAX_FILE_BYTES` + 1 bytes of ``path`` (``-``: standard input)."""
    import sys

    if path != "-":
        mode = os.stat(path).st_mode
        if not stat.S_ISREG(mode) and not stat.S_ISDIR(mode):
            # a FIFO or a device: opening one blocks until a writer comes (N11)
            raise ValueError(
                f"{path}: not a regular file (give - to read the questions from standard input)"
            )
        with open(path, "rb") as f:
            return f.read(MAX_FILE_BYTES + 1)
    stream = getattr(sys.stdin, "buffer", None)
    if stream is not None:
        return bytes(stream.read(MAX_FILE_BYTES + 1))
    # a text stream without bytes (a test's StringIO): its undecodable bytes come back
    return sys.stdin.read(MAX_FILE_BYTES + 1).encode("utf-8", "surrogateescape")


def read_file(path: str) -> Sheet:
    """Read and parse a question file.

    Parameters
    ----------
    path : str
        The file's name; ``"-"``: standard input, read as strictly as a named file (UTF-8, no NUL
        byte, at most 1,000,000 bytes).

    Returns
    -------
    Sheet
        As :func:`read_questions` returns it, with at least one question.

    Raises
    ------
    ValueError
        A file that cannot be read, is not UTF-8 text, or holds no question, named.

    Examples
    --------
    >>> from importlib.resources import files
    >>> sheet = read_file(str(files("scanconv.data") / "exam.txt"))  # scanconv exam's book
    >>> sheet.title, len(sheet.questions), sheet.questions[0].argv
    ('Scan conversion: the whole exam, answered', 52, ('theory', 'scan-conversion'))
    >>> read_file("no-such-file.txt")
    Traceback (most recent call last):
    ...
    ValueError: cannot read 'no-such-file.txt': No such file or directory
    """
    if path == "":
        raise ValueError("QUESTIONS is empty (''): give the name of a question file")
    name = "<stdin>" if path == "-" else path
    try:
        data = _read_bytes(path)
        if b"\x00" in data:
            raise ValueError(f"{name} is not a text file (it holds NUL bytes)")
        text = data.decode("utf-8")
    except UnicodeError:
        raise ValueError(f"{name} is not UTF-8 text") from None
    except IsADirectoryError:
        raise ValueError(f"{path!r} is a directory, not a question file") from None
    except OSError as err:
        raise ValueError(f"cannot read {path!r}: {err.strerror or err}") from None
    if len(data) > MAX_FILE_BYTES:
        raise ValueError(f"{name} is larger than {MAX_FILE_BYTES:,} bytes")
    sheet = read_questions(text, name)
    if not sheet.questions:
        raise ValueError(f"{name} holds no question (one per line: line 2 2 10 6 --algo dda)")
    return sheet
