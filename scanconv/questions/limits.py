"""The size limits of the question language, applied where a question comes in, before any
work: a question file's bytes (:data:`MAX_FILE_BYTES`) and a question's characters
(:data:`MAX_LINE_CHARS`, the longest line of a question file). :func:`scanconv.questions.parse`,
:func:`~scanconv.questions.answer` and :func:`~scanconv.questions.read_questions` call these
checks first, so an oversized question is refused in a few calls, whatever its size (a
400 KB polygon was parsed for 28 s before its vertices were counted).
"""

from __future__ import annotations

from collections.abc import Sequence

from .words import UsageError

MAX_FILE_BYTES = 1_000_000
"""The largest question file read."""
MAX_LINE_CHARS = 10_000
"""The longest line of a question file, and the longest question: a question with a
1,000-vertex polygon is under 10,000 characters (splitting a line into words takes time
growing with its square)."""


def question_chars(question: str | Sequence[str]) -> int:
    """The length of a question as one line: its characters, or its words joined by spaces
    (counted word by word only up to the limit: a list of a million words stops early).

    >>> question_chars("line 2 2 10 6"), question_chars(["line", "2", "2", "10", "6"])
    (13, 13)
    """
    if isinstance(question, str):
        return len(question)
    total = -1
    for word in question:
        total += len(str(word)) + 1
        if total > MAX_LINE_CHARS:
            break
    return max(total, 0)


def check_question_size(question: str | Sequence[str]) -> None:
    """Refuse (:class:`~scanconv.questions.words.UsageError`) a question longer than a line
    of a question file may be.

    >>> check_question_size("circle " + "9" * 10_000)
    Traceback (most recent call last):
    ...
    scanconv.questions.words.UsageError: a question of 10,007 characters; at most 10,000 characters
    """
    size = question_chars(question)
    if size > MAX_LINE_CHARS:
        shown = f"{size:,}" if isinstance(question, str) else f"over {MAX_LINE_CHARS:,}"
        raise UsageError(f"a question of {shown} characters; at most {MAX_LINE_CHARS:,} characters")


def check_text_size(text: str, source: str) -> None:
    """Refuse (``ValueError``) a question file's text beyond :data:`MAX_FILE_BYTES` bytes of
    UTF-8, as :func:`~scanconv.questions.read_file` refuses the file.

    >>> check_text_size("\\r" * 1_000_001, "QUESTIONS")
    Traceback (most recent call last):
    ...
    ValueError: QUESTIONS is larger than 1,000,000 bytes
    """
    # a character is 1 to 4 bytes: count the bytes only where the characters cannot decide
    if len(text) > MAX_FILE_BYTES or (
        4 * len(text) > MAX_FILE_BYTES
        and len(text.encode("utf-8", "surrogatepass")) > MAX_FILE_BYTES
    ):
        raise ValueError(f"{source} is larger than {MAX_FILE_BYTES:,} bytes")
