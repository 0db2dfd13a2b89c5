"""Marking against a question: :func:`check` marks a student's table (the API of
``scanconv check``), and :func:`marking_question` answers the question it is marked against."""

from __future__ import annotations

import os
import shlex
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from ..core import lazy
from ..core.checks import InputError
from ..core.records import Solution
from ..display import Answer
from .answering import answered
from .grammar_table import NOT_QUESTIONS, SPECS
from .parser import HELP, CommandLine, parse, split
from .words import students

if TYPE_CHECKING:
    from ..marking import mark as answers_marking
    from ..marking import tables as marking_table
else:  # only the runs that mark a file
    answers_marking = lazy.module("scanconv.marking.mark")
    marking_table = lazy.module("scanconv.marking.tables")


def marking_question(question: str | Sequence[str]) -> Solution:
    """The answer a student's table is marked against (:func:`marking_line`, then
    :func:`marking_answer`).

    Parameters
    ----------
    question : str or sequence of str
        The question as scanconv's own arguments (``"line 2 2 10 6 --algo dda"`` or the list of
        words), read exactly as ``scanconv check ANSWER -- QUESTION`` reads it.

    Returns
    -------
    Solution
        The question's answer, with its step table.

    Raises
    ------
    InputError
        A question without a step table, asking for a figure or for help, or incomplete.

    Examples
    --------
    >>> marking_question("line 2 2 10 6").title
    "Bresenham's line algorithm: (2, 2) to (10, 6)"
    >>> marking_question("theory symmetry")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: the question 'theory symmetry' has no step table to mark
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


def marking_answer(
    line: CommandLine, formats: Sequence[str] = (), *, document: bool = False
) -> Solution:
    """The answer of a parsed question to mark against (:func:`answered`, its budget that of
    ``formats`` and of a ``document``); one without a step table, or beyond the budget, is an
    :class:`~scanconv.core.checks.InputError` worded ``question: ...``."""
    try:
        _, solution = answered(line, formats, document=document)
    except ValueError as err:
        raise InputError(f"question: {err}", getattr(err, "param", None)) from None
    if not solution.columns and not marking_table.table_models_for(solution):
        raise InputError(f"the question {' '.join(line.words[:3])!r} has no step table to mark")
    return solution


def check(answer: str | os.PathLike[str], question: str | Sequence[str] | Solution) -> Answer:
    """Mark a student's table against a question (``scanconv check ANSWER -- QUESTION``).

    Parameters
    ----------
    answer : str or os.PathLike
        The student's table: a CSV, Markdown or JSON file whose columns are named as the
        answer's (``k, p, x, y``, ...).
    question : str, sequence of str or Solution
        The question as scanconv's own arguments (``"line 2 2 10 6 --algo dda"`` or the list of
        words), read exactly as ``scanconv check ANSWER -- QUESTION`` reads it, or a Solution
        the API made.

    Returns
    -------
    Answer
        The row-by-row marking as its table; ``.data`` holds the ``score`` ``out_of`` the rows,
        the ``first_error``, the ``diagnosis`` (the misconception the errors fit, if any) and
        whether later rows were marked with ``follow_through`` from the first error.

    Examples
    --------
    >>> m = check("tests/data/check/slip.csv", "line 2 2 10 6")
    >>> m.data["score"], m.data["out_of"]
    (7, 8)
    >>> m.data["first_error"]
    'Row 4 (line 5): p should be -8, not -4 (the step from (4, 3) with p = 0).'
    """
    if isinstance(question, Solution):
        solution, text = question, question.title
    else:
        words = split(question)
        solution, text = marking_question(words), shlex.join(words)
    path = Path(answer)
    return Answer.of(
        answers_marking.marking_solution(
            answers_marking.mark_file(path, solution), solution, path.name, text
        )
    )
