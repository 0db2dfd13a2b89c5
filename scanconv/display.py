"""What the Python API returns: a :class:`~scanconv.core.records.Solution` that shows itself.

:class:`Answer` adds to the inert ``Solution`` record (which lives in the bottom layer and
must not know about formats) the ways a person looks at an answer from Python: ``to(fmt)``
(the very text the CLI prints), a short ``repr``, ``_repr_markdown_`` for Jupyter (rich's
``JupyterMixin`` idea: the object renders itself through the one :func:`~scanconv.render.render`
dispatch), ``rows()`` as dictionaries, and pickling. This module sits above the renderers and
below the API (:func:`answers` makes each API function return an Answer), so the layers
below never import a renderer.

>>> import scanconv
>>> sol = scanconv.line(0, 0, 3, 1)
>>> sol
<Answer line/bresenham: Bresenham's line algorithm: (0, 0) to (3, 1)>
>>> print(sol.to("csv"), end="")
k,p,decision,x,y,p_next
0,-1,E,0,0,1
1,1,NE,1,0,-3
2,-3,E,2,1,-1
3,-1,,3,1,
>>> sol.rows()[0]
{'k': 0, 'p': -1, 'decision': 'E', 'pixel': (0, 0), 'p_next': 1}
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, ParamSpec

from .core import declare, lazy
from .core.checks import InputError
from .core.records import Solution, step_getter
from .render import Format, Notice, Options, render
from .render.budget import check_rows_in_memory, check_work

if TYPE_CHECKING:
    from .render.figures import grid as text_grid
    from .render.mappings import html
else:  # the text grid and the notebook's page: only when asked for
    text_grid = lazy.module("scanconv.render.figures.grid")
    html = lazy.module("scanconv.render.mappings.html")

P = ParamSpec("P")

Recipe = tuple[Callable[..., "Answer"], tuple[Any, ...], tuple[tuple[str, Any], ...]]
"""How an answer was asked for: the API function (pickled by its name), its positional and
keyword arguments."""


class Answer(Solution):
    """A :class:`~scanconv.core.records.Solution` with ways to show itself (see the module)."""

    __slots__ = ("recipe",)

    recipe: Recipe | None
    """The API call that made it, so that it pickles (steps and pixels are generator
    factories, rebuilt by calling the API again: the algorithms are deterministic)."""

    def __init__(self, *args: Any, recipe: Recipe | None = None, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.recipe = recipe

    @classmethod
    def of(cls, solution: Solution, recipe: Recipe | None = None) -> Answer:
        """``solution`` as an Answer (the same fields and question, nothing computed)."""
        answer = cls(**solution.fields(), recipe=recipe)
        answer.question = solution.question
        return answer

    def __repr__(self) -> str:
        return f"<Answer {self.primitive}/{self.algorithm}: {self.title}>"

    def __reduce__(self) -> tuple[Callable[..., Answer], tuple[Any, ...]]:
        if self.recipe is None:
            raise TypeError("only answers made by the scanconv API functions can be pickled")
        return _rebuild, (self.recipe,)

    def to(
        self,
        fmt: str = "markdown",
        *,
        grid: bool = True,
        origin: str = "bottom-left",
    ) -> str:
        """The answer as text in ``fmt`` (``markdown``, ``latex``, ``plain``, ``csv``,
        ``json``): the same text ``scanconv ... --format fmt`` prints."""
        try:
            chosen = Format(fmt)
        except ValueError:
            names = ", ".join(f.value for f in Format if f not in (Format.auto, Format.rich))
            raise ValueError(f"unknown format {fmt!r} (choose from {names})") from None
        if chosen in (Format.auto, Format.rich):
            raise ValueError("the rich format is for a terminal: use markdown or plain")
        self.check_budget(chosen)
        options = Options(grid=grid, origin=origin)
        return "".join(c for c in render(self, chosen, options) if not isinstance(c, Notice))

    def grid(self, origin: str = "bottom-left") -> str:
        """The text pixel grid (empty if the answer plots no pixels or the grid is too large)."""
        if self.pixels is None or text_grid.too_large(self.bbox):
            return ""
        lines = text_grid.render_grid(self.pixels(), self.bbox, origin=origin, marks=self.marks)
        return "\n".join(lines) + "\n"

    def rows(self) -> list[dict[str, Any]]:
        """The step table as dictionaries keyed by column key, exact values as computed
        (decisions as their names)."""
        self.check_budget(Format.json, in_memory=True)
        get = step_getter(self.columns, self.extra_keys)
        keys = [c.key for c in self.columns]
        return [
            {
                k: (str(v) if k == "decision" and v is not None else v)
                for k, v in zip(keys, get(s), strict=True)
            }
            for s in self.steps()
        ]

    def _repr_markdown_(self) -> str:
        return self.to("markdown")

    def check_budget(self, fmt: Any = None, *, in_memory: bool = False) -> None:
        """Refuse (:class:`~scanconv.core.checks.InputError` naming the parameter and the
        limit) to show this answer in ``fmt`` (``None``: in any format) beyond the work budget
        of :mod:`scanconv.render.budget`, before any row is computed; ``in_memory``: as a
        list of rows (:data:`~scanconv.render.budget.ROWS_IN_MEMORY`).

        >>> import scanconv
        >>> scanconv.line(0, 0, 500_000, 1, algo="wu").to("html")  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        scanconv.render.budget.BudgetError: the table has about 500,001 rows; ...
        """
        if self.recipe is not None:
            check_recipe(self.recipe, fmt, in_memory=in_memory)

    def _repr_html_(self) -> str:
        """The interactive step-through page as a notebook fragment: its own unique id, its
        style scoped to it, its keys bound to it (see :func:`scanconv.render.mappings.html.notebook_html`)."""
        self.check_budget(Format.html)
        return html.notebook_html(self)


def answers(fn: Callable[P, Solution]) -> Callable[P, Answer]:
    """Make an API function return an :class:`Answer` that remembers the call (so that it
    pickles), with the function's own signature, its return shown as ``Answer``. Bad input
    is always an :class:`~scanconv.core.checks.InputError` (a ``ValueError`` with ``.param``:
    the parameter, or ``None`` when no single one is at fault)."""

    @functools.wraps(fn)
    def ask(*args: P.args, **kwargs: P.kwargs) -> Answer:
        recipe = (ask, args, tuple(sorted(kwargs.items())))
        check_recipe(recipe, None)  # the one budget, before any work (scanconv.render.budget)
        try:
            solution = fn(*args, **kwargs)
        except InputError:
            raise
        except ValueError as err:
            raise InputError(str(err)) from err
        return Answer.of(solution, recipe)

    # help() reads the signature through __wrapped__: the wrapped function (reached only
    # through this one) is annotated as the API returns, its declarations left out
    # (scanconv.core.declare: kept for the command line and the questions; no signature is
    # built at import time)
    setattr(fn, declare.DECLARATION, fn.__annotations__)
    shown = {name: declare.plain(a) for name, a in fn.__annotations__.items()}
    fn.__annotations__ = ask.__annotations__ = {**shown, "return": "Answer"}
    return ask


def check_recipe(recipe: Recipe, fmt: Any, *, in_memory: bool = False) -> None:
    """Refuse the API call ``recipe`` beyond the work budget of ``fmt`` (``None``: of every
    format): :func:`scanconv.render.budget.check_work` on its arguments by name.

    >>> import scanconv
    >>> check_recipe((scanconv.line, (0, 0, 10**9, 1), ()), None)
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,000,000,001 rows; no format prints more than 2,000,000 (a minute of output)
    """
    call, args, kwargs = recipe
    try:
        bound = inspect.signature(call).bind(*args, **dict(kwargs))
    except TypeError:
        return  # the call itself raises it
    work = check_work(call.__name__, bound.arguments, fmt)
    if in_memory and work is not None:
        check_rows_in_memory(work)


def _rebuild(recipe: Recipe) -> Answer:
    """Unpickle: ask the API again."""
    fn, args, kwargs = recipe
    return fn(*args, **dict(kwargs))
