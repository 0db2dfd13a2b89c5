"""The typer command of a declared library function (:mod:`scanconv.core.declare`).

A command the question language lists (:data:`scanconv.questions.declared.COMMANDS`) is
registered by :func:`command` with its help alone: its arguments and options are the
``Arg`` and ``Opt`` records of its :mod:`scanconv._api` function, turned into typer's
declarations (:func:`scanconv.cli.options.typer_parameter`) when typer first asks for its
signature (only the command a run names is built), its defaults the function's; the body is
the function.
"""

from __future__ import annotations

import functools
import inspect
from typing import Any

import typer

from ..core.declare import Declared
from ..questions.declared import COMMANDS
from .budget import answered
from .command import SHARED, Command, _shared
from .options import NUMERIC_ARGS, typer_parameter
from .output import Output


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
    spec = callback.spec
    settings = NUMERIC_ARGS if spec.ignore_unknown else {}
    group.command(
        path[-1], context_settings=settings, help=help, no_args_is_help=spec.no_args_is_help
    )(callback)
