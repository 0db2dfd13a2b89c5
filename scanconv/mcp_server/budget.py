"""The work budget of a question the server answers, before any work.

Every tool call goes through :func:`check_budget`, the library's one check of a parsed
question in an output format (:func:`scanconv.questions.check_budget`), so the server never
answers a question the command line would refuse. The server checks each answer in every
format it writes (the JSON and the Markdown; the page in html).
"""

from __future__ import annotations

from collections.abc import Iterable

from .. import questions
from ..questions.parser import CommandLine
from ..render import Format


def check_budget(line: CommandLine, formats: Iterable[Format]) -> None:
    """Refuse (a ``ValueError``, one line) a question beyond the budget of any of ``formats``.

    >>> check_budget(questions.parse("line 0 0 1000000000 1"), [Format.json])
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,000,000,001 rows; no format prints more than 2,000,000 (a minute of output)
    >>> check_budget(questions.parse("line 5 5 13 9"), [Format.json, Format.markdown])
    """
    for fmt in formats:
        questions.check_budget(line, fmt)
