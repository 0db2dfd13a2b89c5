"""The API of ``scanconv check``: :func:`check` marks a student's table against a question.
Library modules are imported inside the function (start-up time)."""

from __future__ import annotations

import os
import shlex
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.records import Solution


def check(answer: str | os.PathLike[str], question: str | Sequence[str] | Solution) -> Solution:
    """Mark the student's table in the file ``answer`` (CSV, Markdown or JSON) against
    ``question``: scanconv's own arguments (``"line 2 2 10 6 --algo dda"`` or a list of
    words, read exactly as ``scanconv check ANSWER -- QUESTION`` reads them) or a Solution the
    API made. The result's table is the row-by-row marking; ``data`` holds the score, the
    first error and the diagnosis.

    >>> m = check("tests/data/check/slip.csv", "line 2 2 10 6")
    >>> m.data["score"], m.data["out_of"]
    (7, 8)
    """
    from ..answers.marking import mark, marking_solution
    from ..core.records import Solution
    from ..core.student_table import read_table

    if isinstance(question, Solution):
        solution, text = question, question.title
    else:
        from ..cli.check import solve

        words = shlex.split(question) if isinstance(question, str) else list(question)
        solution, text = solve(words), " ".join(words)
    path = Path(answer)
    return marking_solution(mark(read_table(path), solution), solution, path.name, text)
