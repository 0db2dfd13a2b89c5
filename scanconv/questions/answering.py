"""Answering a question: the one pipeline every reader of questions goes through
(:func:`answered`: parse, weigh the work against the budget, answer), the options an answer
is shown with (:func:`shown_with`), and the answer from the words in one call
(:func:`answer`).

The command line's sheets and ``check``, the site's page, the MCP server and this package's
:func:`answer` and :func:`~scanconv.questions.marking.marking_question` all answer through
:func:`answered`; :func:`solve` is its last step and weighs the work itself (what no format
prints is refused), so nothing answers a question without passing the budget.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

from ..core import lazy
from ..core.checks import InputError
from ..display import Answer
from ..render import Format, Options
from ..render.budget import check_question as check_in_document
from .budget import estimated, library_call
from .declared import BY_FUNCTION
from .grammar import CommandLine, error_message
from .words import UsageError

if TYPE_CHECKING:
    from ..core.records import Solution
    from ..display import Answer
    from . import parser
else:  # a declared command read by the command line needs neither
    parser = lazy.module("scanconv.questions.parser")


def answered(
    question: str | Sequence[str] | CommandLine,
    formats: Iterable[Format | str] = (),
    *,
    document: bool = False,
) -> tuple[CommandLine, Solution]:
    """The one question pipeline: the question parsed, its work weighed against the budget
    before any is done, then answered.

    Parameters
    ----------
    question : str, sequence of str or CommandLine
        The question as scanconv's own arguments, or already parsed (:func:`parse`).
    formats : iterable of Format or str, default ()
        The formats the answer will be written in: each has a budget of its own
        (:func:`~scanconv.questions.budget.check_budget`). Whatever they are, what no format
        prints is refused.
    document : bool, default False
        The question is one of a document's (a sheet, practice set, exam or ``check``): the
        document's budget, for it alone and with the questions before it
        (:func:`scanconv.render.budget.check_question`).

    Returns
    -------
    (CommandLine, Solution)
        The parsed question and its answer.

    Raises
    ------
    UsageError
        Bad words.
    InputError
        Bad values, or work beyond a budget (a :class:`~scanconv.render.budget.BudgetError`).

    Examples
    --------
    >>> line, solution = answered("circle 5 --method bresenham", ["json"])
    >>> line.function, solution.primitive
    ('circle', 'circle')
    >>> answered("circle 2800000", ["json"])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,979,900 rows; circle/midpoint in json ...
    """
    line = question if isinstance(question, CommandLine) else parser.parse(question)
    if document:
        check_in_document(*library_call(line.function, line.arguments))
    for fmt in (*formats,) or (None,):  # none given: what no format prints
        estimated(line, None if fmt is None else Format(fmt))
    return line, _solve(line)


def solve(line: CommandLine) -> Solution:
    """The answer of a parsed question, computed by the library: the last step of
    :func:`answered`, which refuses first what no format prints (the budget of a format the
    answer is written in is :func:`answered`'s).

    Parameters
    ----------
    line : CommandLine
        The question, as :func:`parse` reads it.

    Returns
    -------
    Solution
        The command's answer (its API function's, with the arguments of the question).

    Raises
    ------
    InputError
        Bad input found while answering, its text naming the command's flag for it
        (``--degree: degree must satisfy ...``), as the command line says it.

    Examples
    --------
    >>> from scanconv.questions import parse
    >>> solve(parse("circle 5 --method bresenham")).title
    "Bresenham's circle algorithm: r = 5, centre (0, 0)"
    >>> solve(parse("bspline 0 0 1 1 --degree 3"))
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: --degree: degree must satisfy 1 <= p <= n = 1 (n + 1 = 2 control points), got p = 3
    """
    estimated(line, None)  # before any work
    return _solve(line)


def _solve(line: CommandLine) -> Solution:
    """:func:`solve` once the work is weighed."""
    body = BY_FUNCTION[line.function].answerer()
    try:
        solution: Solution = body(**line.arguments)
        return solution
    except UsageError:
        raise
    except ValueError as err:
        param = getattr(err, "param", None)
        raise InputError(error_message(err, line.spec.params), param) from None


def shown_with(line: CommandLine, where: str = "the sheet") -> Options:
    """The display options a question asks its answer to be shown with (``--no-grid``,
    ``--origin``, ``--brief``, ``--exact``).

    Parameters
    ----------
    line : CommandLine
        The question, as :func:`parse` reads it.
    where : str, default "the sheet"
        What writes the answers, named in the error for an output option.

    Returns
    -------
    Options
        The display options (:class:`scanconv.render.options.Options`).

    Raises
    ------
    UsageError
        An output option in a question (``-o``, ``--svg``, ``--png``, ``--format``): ``where``
        writes the one document.

    Examples
    --------
    >>> from scanconv.questions import parse
    >>> shown_with(parse("circle 5 --no-grid --exact"))
    Options(grid=False, origin='bottom-left', brief=False, exact=True, width=None)
    >>> shown_with(parse("circle 5 -o a.md"))
    Traceback (most recent call last):
    ...
    scanconv.questions.words.UsageError: --output in a question: the sheet writes one document (give it -o)
    """
    shown = line.display
    for name in ("output", "svg", "png"):
        if shown.get(name) is not None:
            raise UsageError(f"--{name} in a question: {where} writes one document (give it -o)")
    if shown.get("fmt", "auto") != "auto":
        raise UsageError(f"--format in a question: {where}'s --format applies to every answer")
    return Options(
        grid=shown.get("grid", True),
        origin=shown.get("origin") or "bottom-left",
        brief=shown.get("brief", False),
        exact=shown.get("exact", False),
    )


def answer(question: str | Sequence[str]) -> Answer:
    """The answer of a question written as scanconv's own arguments, computed by the library (no
    command line involved): :func:`solve` of :func:`parse`.
    Before any work, the question's length is checked
    (:data:`~scanconv.questions.limits.MAX_LINE_CHARS`) and its work budget
    (:func:`~scanconv.questions.budget.check_budget`: what no format prints is refused; the
    answer's ``to(fmt)`` checks the budget of ``fmt``).

    Parameters
    ----------
    question : str or sequence of str
        The question as scanconv's own arguments: one string, split as a shell splits it
        (``"line 2 2 10 6 --algo dda"``), or the list of words.

    Returns
    -------
    Answer
        The worked answer, as the API function of the command returns it.

    Raises
    ------
    UsageError
        Bad words, worded as the command line words them.
    InputError
        Bad values.

    Examples
    --------
    >>> answer("line 2 2 10 6 --algo dda").algorithm
    'dda'
    >>> [s.pixel for s in answer(["circle", "5"]).steps()][:2]
    [(0, 5), (1, 5)]
    >>> answer("line 2 2 10 6 --tie zzz")
    Traceback (most recent call last):
    ...
    scanconv.questions.words.UsageError: Invalid value for '--tie': 'zzz' is not one of 'step', 'keep'.
    >>> answer("line 0 0 1000000000 1")
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,000,000,001 rows; no format prints more than 2,000,000 (a minute of output)
    """
    _, solution = answered(question)
    return solution if isinstance(solution, Answer) else Answer.of(solution)
