"""The score sheet of ``scanconv check --batch``: one CSV row per student file.

Every text cell that a spreadsheet would read as a formula (starting with ``=``, ``+``, ``-``,
``@``, a tab or a carriage return: a student's file name can be anything) is prefixed with
``'``, the usual neutralisation; numbers stay numbers. Control characters and bidirectional
overrides are shown as U+FFFD (:func:`~scanconv.core.working.visible`): a terminal that shows
the CSV runs no escape sequence.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterable, Iterator

from ...core.working import json_visible, visible

HEADER = ("name", "score", "out_of", "first_error", "diagnosis")

_FORMULA = ("=", "+", "-", "@", "\t", "\r")


def neutral(text: str) -> str:
    """A text cell a spreadsheet shows as text, never runs.

    >>> neutral("=HYPERLINK(1)"), neutral("-2"), neutral("alice.csv")
    ("'=HYPERLINK(1)", "'-2", 'alice.csv')
    """
    text = visible(text)
    return "'" + text if text.startswith(_FORMULA) else text


ScoreRow = tuple[str, int | None, int | None, str, str]
"""A score sheet's row: the file's name, its score and out of (``None``: not marked), the
first error (or why it was not marked) and the diagnosis."""


def batch_csv(rows: Iterable[ScoreRow]) -> Iterator[str]:
    """The score sheet, header first.

    >>> print("".join(batch_csv([("=bob.csv", 8, 9, "Row 2: ...", "")])), end="")
    name,score,out_of,first_error,diagnosis
    '=bob.csv,8,9,Row 2: ...,
    """
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(HEADER)
    for name, score, total, first, diagnosis in rows:
        writer.writerow((neutral(name), score, total, neutral(first), neutral(diagnosis)))
        yield buf.getvalue()
        buf.seek(0)
        buf.truncate()
    yield buf.getvalue()


def batch_json(rows: Iterable[ScoreRow], question: str) -> Iterator[str]:
    """The score sheet as one JSON object: the question and a row object per student.

    >>> print("".join(batch_json([("a.csv", 9, 9, "", "")], "line 2 2 10 6")), end="")
    {"question": "line 2 2 10 6", "students": [
      {"name": "a.csv", "score": 9, "out_of": 9, "first_error": "", "diagnosis": ""}
    ]}
    """
    yield f'{{"question": {json_visible(json.dumps(question, ensure_ascii=False))}, "students": ['
    first = True
    for row in rows:
        obj = dict(zip(HEADER, row, strict=True))
        yield ("\n  " if first else ",\n  ") + json_visible(json.dumps(obj, ensure_ascii=False))
        first = False
    yield "\n]}\n"
