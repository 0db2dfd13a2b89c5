"""The work budget of a question the server answers, before any work.

Every tool call goes through :func:`check_budget`: the library's one check of a question in
an output format, ``scanconv.questions.check_budget`` where the library has it, else the
same check spelled out here (:func:`scanconv.render.budget.check_work` for the question's
library function), so the server never answers a question the command line would refuse.
"""

from __future__ import annotations

from typing import Any

from .. import questions
from ..questions.parser import CommandLine
from ..render import Format
from ..render.budget import check_work

#: The library function of each command whose name differs (``scanconv.cli.budget``'s
#: table, which the command line words its refusals with).
_LIBRARY_NAMES = {
    "compare_line": "compare_lines",
    "compare_circle": "compare_circles",
    "image_ramp": "ramp",
    "fill_boundary": "fill",
    "fill_flood": "fill",
}


def check_budget(line: CommandLine, fmt: Format | str) -> None:
    """Refuse (a ``ValueError``, one line) a question beyond the budget of ``fmt``.

    >>> check_budget(questions.parse("line 0 0 1000000000 1"), "json")
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,000,000,001 rows; no format prints more than 2,000,000 (a minute of output)
    >>> check_budget(questions.parse("line 5 5 13 9"), "json")
    """
    library: Any = getattr(questions, "check_budget", None)
    if library is not None:
        library(line, fmt)
        return
    check_work(*_library_call(line.function, line.arguments), Format(fmt))


def _library_call(name: str, arguments: dict[str, Any]) -> tuple[str, dict[str, Any]]:
    """The library function a command calls for ``arguments`` (``bezier --at``:
    ``bezier_at``), and its arguments."""
    if name in ("bezier", "bspline") and arguments.get("t") is not None:
        return name + "_at", arguments
    if name == "bspline" and arguments.get("basis"):
        return "bspline_basis", arguments
    if name == "continuity" and arguments.get("values") is not None:
        return name, {**arguments, "first": arguments["values"]}
    return _LIBRARY_NAMES.get(name, name), arguments
