"""The typer command of a declared library function (:mod:`scanconv.core.declare`).

A command the question language lists (:data:`scanconv.questions.declared.COMMANDS`) is
registered by :func:`command` with its help alone: its arguments and options are the
``Arg`` and ``Opt`` records of its :mod:`scanconv._api` function, turned into typer's
declarations when typer first asks for its signature (only the command a run names is
built), its defaults the function's; the body is the function.
"""

from __future__ import annotations

import functools
import inspect
from fractions import Fraction
from typing import Annotated, Any

import typer
from typer._types import TyperChoice

from ..core.declare import Arg, Declared
from ..questions.declared import COMMANDS
from .budget import answered
from .command import SHARED, Command, _shared
from .options import NUMERIC_ARGS, coordinate, integer, number
from .output import Output

_PARSERS = {"number": number, "integer": integer, "coordinate": coordinate}
_TYPES: dict[str, Any] = {"number": Fraction, "integer": int, "coordinate": Any}
_TYPES |= {"flag": bool, "text": str}


def typer_parameter(d: Declared) -> inspect.Parameter:
    """The parameter typer reads for the declared one: its type, its typer declaration and
    the library's default."""
    texts = d.choices if isinstance(d.choices, tuple) else None
    base: Any = d.choices if d.kind == "choice" and not texts else _TYPES.get(d.kind, str)
    if d.nargs == -1 or getattr(d.meta, "multiple", False):
        base = list[base]
    elif d.nargs > 1:
        base = tuple[(base,) * d.nargs]  # type: ignore[misc]
    if d.optional:
        base = base | None
    options: dict[str, Any] = {"help": d.meta.help or None, "metavar": d.meta.metavar}
    if d.kind in _PARSERS:
        options["parser"] = _PARSERS[d.kind]
    if isinstance(d.meta, Arg):
        info = typer.Argument(show_default=False, **options)
    else:
        if texts:
            options["click_type"] = TyperChoice(texts, case_sensitive=False)
        elif d.kind == "choice":
            options["case_sensitive"] = False
        if d.meta.hidden:
            options["hidden"] = True
        info = typer.Option(*d.meta.names, show_default=d.meta.show_default, **options)
    return inspect.Parameter(
        d.name,
        inspect.Parameter.KEYWORD_ONLY,
        default=d.default,
        annotation=Annotated[base, info],
    )


class DeclaredCommand(Command):
    """A :class:`~scanconv.cli.command.Command` whose function is read (and imported) only
    when typer builds it or a run calls it."""

    def __init__(self, path: tuple[str, ...], help: str) -> None:
        self.spec = COMMANDS[path]
        shared = _shared(
            figures=self.spec.figures,
            grid=self.spec.grid,
            origin=self.spec.origin,
            picture=self.spec.picture,
        )
        self.__name__ = self.__qualname__ = self.spec.function
        self.__module__ = __name__
        self.__doc__ = help
        self._shared = shared

    @functools.cached_property
    def declared(self) -> tuple[Declared, ...]:
        return self.spec.parameters()

    @property
    def own(self) -> list[str]:
        return [d.name for d in self.declared]

    def answer(self, kwargs: dict[str, Any], out: Output) -> Any:
        """The answer through the library's one question pipeline
        (:func:`scanconv.cli.budget.answered`)."""
        return answered(self.spec.path, kwargs, out)

    @functools.cached_property
    def parameters(self) -> list[inspect.Parameter]:
        own = {d.name: typer_parameter(d) for d in self.declared}
        return [p for name, p in own.items() if name not in SHARED] + [
            own.get(name) or self._shared[name]
            for name in SHARED
            if name in own or name in self._shared
        ]


def command(group: typer.Typer, path: tuple[str, ...], help: str) -> None:
    """Register the declared command ``path`` on ``group`` (``help``: its text in
    ``--help``)."""
    callback = DeclaredCommand(path, help)
    settings = NUMERIC_ARGS if callback.spec.ignore_unknown else {}
    group.command(path[-1], context_settings=settings, help=help)(callback)
