"""Marking against a question: :func:`check` marks a student's table (the API of
``scanconv check``), and :func:`marking_question` answers the question it is marked against."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from ..core import lazy
from ..core.checks import InputError
from ..core.records import Solution
from ..display import Answer
from .answering import solve
from .grammar_table import NOT_QUESTIONS, SPECS
from .parser import HELP, CommandLine, parse, split
from .words import students

if TYPE_CHECKING:
    from ..answers import marking as answers_marking
    from ..answers import marking_table
else:  # only the runs that mark a file
    answers_marking = lazy.module("scanconv.answers.marking")
    marking_table = lazy.module("scanconv.answers.marking_table")


def marking_question(question: str | Sequence[str]) -> Solution:
    """The answer a student's table is marked against: the question as scanconv's own
    arguments (:func:`marking_line`, then :func:`marking_answer`).

    >>> marking_question("line 2 2 10 6").title
    "Bresenham's line algorithm: (2, 2) to (10, 6)"
    """
    return marking_answer(marking_line(question))


def marking_line(question: str | Sequence[str]) -> CommandLine:
    """A question to mark against, parsed. One that asks for a figure or for help, or names
    no command with an answer, is an :class:`~scanconv.core.checks.InputError`, its words
    ``question: ...``."""
    words = split(question)
    if not words:
        raise InputError("no question after --: give a scanconv command, e.g. -- line 2 2 10 6")
    argv = students(words)
    top = argv[0]
    if top in NOT_QUESTIONS or top.startswith("-"):
        raise InputError(f"the question must be a scanconv command with a step table, not {top!r}")
    if any(a in HELP for a in argv):
        raise InputError("the question cannot ask for --help")
    figure = next((a for a in argv if a.split("=")[0] in ("--svg", "--png")), None)
    if figure is not None:
        raise InputError(
            f"{figure.split('=')[0]}: check draws no figure; leave it out of the question"
        )
    group = any(len(p) == 2 and p[0] == top for p in SPECS)
    if group and (len(argv) < 2 or argv[1].startswith("-")):
        raise InputError(f"question: {' '.join(words)!r} is incomplete (see scanconv {top} --help)")
    try:
        return parse(words)
    except ValueError as err:
        raise InputError(f"question: {err}", getattr(err, "param", None)) from None


def marking_answer(line: CommandLine) -> Solution:
    """The answer of a parsed question to mark against; one without a step table is an
    :class:`~scanconv.core.checks.InputError`."""
    try:
        solution = solve(line)
    except ValueError as err:
        raise InputError(f"question: {err}", getattr(err, "param", None)) from None
    if not solution.columns and marking_table.table_model_for(solution) is None:
        raise InputError(f"the question {' '.join(line.words[:3])!r} has no step table to mark")
    return solution


def check(answer: str | os.PathLike[str], question: str | Sequence[str] | Solution) -> Answer:
    """Mark the student's table in the file ``answer`` (CSV, Markdown or JSON) against
    ``question``: scanconv's own arguments (``"line 2 2 10 6 --algo dda"`` or a list of
    words, read exactly as ``scanconv check ANSWER -- QUESTION`` reads them) or a Solution the
    API made. The result's table is the row-by-row marking; ``data`` holds the score, the
    first error and the diagnosis.

    >>> m = check("tests/data/check/slip.csv", "line 2 2 10 6")
    >>> m.data["score"], m.data["out_of"]
    (7, 8)
    """
    if isinstance(question, Solution):
        solution, text = question, question.title
    else:
        words = split(question)
        solution, text = marking_question(words), " ".join(words)
    path = Path(answer)
    return Answer.of(
        answers_marking.marking_solution(
            answers_marking.mark_file(path, solution), solution, path.name, text
        )
    )
