"""The work budget on the command line: the library's one check, worded with this CLI's flags.

:func:`check` runs :func:`scanconv.render.budget.check_work` for a command before it does any
work, in the output format the command will write, and words a refusal as one line naming the
size, the limit and the formats that would print it, as options of this command line
(``use --format plain, csv or json``). :func:`check_question` checks a question of a sheet,
practice set, exam or ``check`` against the document budget
(:func:`scanconv.render.budget.check_question`). Both go through the library's
:func:`~scanconv.questions.budget.library_call`, which names the library function a command
calls (the one the site and :func:`scanconv.questions.check_budget` use; the estimates and the
costs are :mod:`scanconv.render.work`'s).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from ..core import lazy
from ..questions.budget import LIBRARY_NAMES, library_call
from ..render.budget import BudgetError, check_work
from ..render.budget import check_question as check_in_document
from ..render.work import ESTIMATES, Work
from ..render.work import estimate as library_estimate
from .output import Output, format_for_file, resolve

if TYPE_CHECKING:
    from ..core.records import Solution
    from ..questions import answering, declared, grammar
    from ..render import Format
else:  # the question pipeline, loaded by the first declared command that answers
    answering = lazy.module("scanconv.questions.answering")
    declared = lazy.module("scanconv.questions.declared")
    grammar = lazy.module("scanconv.questions.grammar")

__all__ = ["DOCUMENT_COMMANDS", "ESTIMATES", "LIBRARY_NAMES", "check", "check_question"]
__all__ += ["DocumentTooLarge", "estimate", "library_call"]

DOCUMENT_COMMANDS = {
    "sheet": "each question (check_question) and their total (render.budget.document)",
    "practice": "its questions go through the sheet's answer_questions, like a sheet's",
    "exam": "the exam book's questions go through the sheet's answer_questions",
    "site": "a fixed build: the pinned runtime, three wheels and the exam book (exam's bound); "
    "each question the page answers goes through scanconv.questions, which checks the budget",
    "check": "the question (check_question); --batch: render.budget.check_batch",
    "mcp": "a server: each tool call's question goes through scanconv.questions.check_budget "
    "in every format the answer is written in (scanconv.questions.answered), a practice call "
    "holds at most mcp_server.answers.MAX_PRACTICE questions",
}
"""The commands that run other commands as questions, and how their work is bounded."""


def estimate(name: str, arguments: Mapping[str, Any]) -> Work | None:
    """The estimated size of command ``name``'s answer (``None``: not estimated).

    >>> estimate("sample", {"size": "4096"}).cols
    4096
    """
    return library_estimate(*library_call(name, arguments))


def answered(path: tuple[str, ...], arguments: Mapping[str, Any], out: Output) -> Solution:
    """The answer of the declared command ``path`` for the values the command line read,
    through the library's one question pipeline (:func:`scanconv.questions.answered`) in
    the format ``out`` writes; a refusal by the budget worded as :func:`check` words it."""
    command = declared.COMMANDS[path]  # the table the questions read is not needed here
    spec = grammar.Spec(path, command.function, (), tuple(arguments))
    line = grammar.CommandLine(spec, dict(arguments), {}, ())
    try:
        return answering.answered(line, [_format(out)])[1]
    except BudgetError as err:
        raise ValueError(_worded(err, library_call(line.function, line.arguments)[0])) from None


def _format(out: Output) -> Format:
    return resolve(format_for_file(out.fmt, out.output), out.output is not None)


def check(name: str, arguments: Mapping[str, Any], out: Output) -> None:
    """Refuse (``ValueError``, one line) a request beyond its output format's budget.

    >>> from scanconv.render import Format
    >>> check("sample", {"size": "4096"}, Output(fmt=Format.latex))
    Traceback (most recent call last):
    ...
    ValueError: a 4096 x 4096 matrix is 16,777,216 cells; the rich, latex and markdown formats print at most 65,536: use --format csv or json
    >>> check("sample", {"size": "4096"}, Output(fmt=Format.csv))
    """
    function, args = library_call(name, arguments)
    try:
        check_work(function, args, _format(out))
    except BudgetError as err:
        raise ValueError(_worded(err, function)) from None


class DocumentTooLarge(ValueError):
    """A question beyond the budget of a document (alone or with the questions before it):
    the questions after it are not read on, as each would be refused for the same reason."""


def check_question(name: str, arguments: Mapping[str, Any]) -> None:
    """Refuse (:class:`DocumentTooLarge`, one line) a question beyond the budget of a
    document, alone or with the questions before it (:func:`scanconv.render.budget.document`)."""
    try:
        check_in_document(*library_call(name, arguments))
    except BudgetError as err:
        raise DocumentTooLarge(str(err)) from None


def _worded(err: Any, function: str) -> str:
    """The refusal with its way out as options of this command line."""
    if err.ways == ("raster",):
        hint = {"line": "line", "circle": "circle", "antialias_line": "line_aa"}.get(function)
        if function == "line" and "line/wu" in str(err):
            hint = "line_aa"
        if hint is None:
            return str(err)
        return (
            f"{err}; for the pixels alone use scanconv.raster in Python (raster.{hint}, "
            "docs/library-numpy.md)"
        )
    if not err.ways:
        return str(err)
    ways = list(err.ways)
    words = ways[0] if len(ways) == 1 else ", ".join(ways[:-1]) + " or " + ways[-1]
    return f"{err}: use --format {words}"
