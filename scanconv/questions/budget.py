"""The work budget of a question: the library function a command answers with, and the one
check (:func:`scanconv.render.budget.check_work`) on its arguments, before any work.

:func:`library_call` names the library function of a command (``compare line`` is
``compare_lines``) as :mod:`scanconv.render.work` costs it;
:func:`check_budget` refuses a parsed question beyond the budget of the format it is to be
answered in. Everything that answers a question goes through it: :func:`scanconv.questions.answer`,
the site's page (:mod:`scanconv.site.page`), the command line (:mod:`scanconv.cli.budget`, which
adds its ``use --format ...`` to the refusal) and the MCP server.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from ..render import Format
from ..render.budget import check_work

if TYPE_CHECKING:
    from ..render.work import Work
    from .parser import CommandLine

LIBRARY_NAMES = {
    "compare_line": "compare_lines",
    "compare_circle": "compare_circles",
    "image_ramp": "ramp",
    "fill_boundary": "fill",
    "fill_flood": "fill",
}
"""The library function of each command whose name differs (the others share theirs)."""


def library_call(name: str, arguments: Mapping[str, Any]) -> tuple[str, Mapping[str, Any]]:
    """The library function that command ``name`` calls for ``arguments``, and its arguments.

    >>> library_call("image_ramp", {"size": "8"})[0]
    'ramp'
    """
    return LIBRARY_NAMES.get(name, name), arguments


def check_budget(line: CommandLine, fmt: Format | str) -> None:
    """Refuse, before any work, the parsed question ``line`` answered in format ``fmt`` beyond
    the work budget: a :class:`~scanconv.render.budget.BudgetError` (an ``InputError``, so a
    ``ValueError``) whose one-line text states the size and the limit, naming formats, never
    a command-line flag (its ``ways``: the formats that would print it). A value beyond the
    magnitude limit is an ``InputError`` naming its parameter.

    Parameters
    ----------
    line : CommandLine
        The question, parsed (:func:`scanconv.questions.parse`).
    fmt : Format or str
        The format it would be answered in (``"json"``, ``"html"``, ...): each format has a
        budget of its own (rows it prints, CPU time, memory).

    Returns
    -------
    None
        Nothing when the answer is within the budget of ``fmt``; the refusal is raised.

    Examples
    --------
    >>> from scanconv.questions import parse
    >>> check_budget(parse("circle 2800000"), "json")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,979,900 rows; circle/midpoint in json costs about ... us a row, so json prints at most ... in 40 s
    >>> check_budget(parse("circle 2800000"), "csv")
    """
    estimated(line, Format(fmt))


def estimated(line: CommandLine, fmt: Format | None) -> Work | None:
    """:func:`check_budget` for ``fmt`` (``None``: refuse only what no format prints), and
    the answer's estimated size (``None``: not estimated)."""
    return check_work(*library_call(line.function, line.arguments), fmt)
