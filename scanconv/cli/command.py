"""``@answers``: what every command shares, in one place.

A command declares only its own arguments and options and returns the
:class:`~scanconv.core.records.Solution` that :mod:`scanconv._api` builds for them.
:func:`answers` adds the shared output options to the signature typer reads, takes their
values out into an :class:`~scanconv.cli.output.Output`, calls the command and writes the
answer. It is also the one place where bad input found by the library (a ``ValueError``, or an
:class:`~scanconv.core.checks.InputError` naming its parameter) becomes one line on stderr and
exit status 2; the line names the command's flag for the parameter (:func:`flag_for`).
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any, get_args, get_type_hints

from typer.models import OptionInfo, ParameterInfo

from ..core import lazy
from ..core.records import Solution
from ..questions.declared import OUTPUTS
from ..questions.declared import Command as Declaration
from .budget import check as check_budget
from .options import shared
from .output import Output, check_paths, emit, fail

if TYPE_CHECKING:
    from ..questions import grammar
else:
    grammar = lazy.module("scanconv.questions.grammar")  # its aliases: bad input only

SHARED = OUTPUTS
"""The shared output options, in the order they are listed after a command's own."""

_KEYWORD = inspect.Parameter.KEYWORD_ONLY


def _shared(
    *, figures: bool, grid: bool, origin: bool, picture: bool
) -> dict[str, inspect.Parameter]:
    """The output options a command takes, as typer takes them."""
    taken = Declaration((), "", figures=figures, grid=grid, origin=origin).outputs
    return {name: p for name, p in shared(picture).items() if name in taken}


def answers(
    *, figures: bool = False, grid: bool = True, origin: bool = True, picture: bool = False
) -> Callable[[Callable[..., Solution]], Callable[..., None]]:
    """Make a function that returns a ``Solution`` into a command that writes it.

    The command gets ``--format``, ``--output``, ``--brief`` (and the hidden no-op
    ``--explain``); ``--grid/--no-grid`` and
    ``--origin`` unless ``grid`` is false (``--origin`` also unless ``origin`` is false; the
    grid is the shaded picture with ``picture``); and ``--svg`` and ``--png`` with
    ``figures``. A shared option the function declares itself (``sample`` has its own
    ``--origin``) keeps its declaration and is passed to the function too.
    """

    def decorate(fn: Callable[..., Solution]) -> Callable[..., None]:
        return Command(fn, _shared(figures=figures, grid=grid, origin=origin, picture=picture))

    return decorate


class Command:
    """A command as typer sees it: the function's own parameters and the shared ones.

    The signature is worked out when typer first asks for it (``__signature__``), so a run
    pays only for the one command it builds (start-up time); calling the command splits the
    shared options off into an :class:`~scanconv.cli.output.Output`, runs the function and
    writes its answer.
    """

    def __init__(self, fn: Callable[..., Solution], shared: dict[str, inspect.Parameter]) -> None:
        self.__wrapped__ = fn
        self.__name__ = fn.__name__
        self.__qualname__ = fn.__qualname__
        self.__module__ = fn.__module__
        self.__doc__ = fn.__doc__
        self._shared = shared

    @functools.cached_property
    def parameters(self) -> list[inspect.Parameter]:
        """The function's own parameters, then the shared ones, annotations evaluated."""
        fn = self.__wrapped__
        hints = get_type_hints(fn, include_extras=True)
        own = {
            name: p.replace(annotation=hints[name])
            for name, p in inspect.signature(fn).parameters.items()
        }
        return [p for name, p in own.items() if name not in SHARED] + [
            own[name].replace(kind=_KEYWORD) if name in own else self._shared[name]
            for name in SHARED
            if name in own or name in self._shared
        ]

    @property
    def __signature__(self) -> inspect.Signature:
        return inspect.Signature(self.parameters)

    @property
    def __annotations__(self) -> dict[str, Any]:  # type: ignore[override]  # get_type_hints
        return {p.name: p.annotation for p in self.parameters}

    @property
    def own(self) -> Iterable[str]:
        """The names of the parameters the function takes."""
        return inspect.signature(self.__wrapped__).parameters

    def __call__(self, **kwargs: Any) -> None:
        own = set(self.own)
        values = {name: kwargs[name] for name in SHARED if name in kwargs}
        for name in values.keys() - own:
            del kwargs[name]
        out = Output(**values)
        # two outputs naming one file (-o f.svg --svg f.svg): one would be lost (N9)
        check_paths([], [("--output", out.output), ("--svg", out.svg), ("--png", out.png)])
        try:
            emit(self.answer(kwargs, out), Output(**values))
        except ValueError as err:  # InputError included
            fail(error_message(err, self.parameters))

    def answer(self, kwargs: dict[str, Any], out: Output) -> Solution:
        """The answer, its work weighed against the budget of ``out``'s format first."""
        check_budget(self.__name__, kwargs, out)  # before any work
        return self.__wrapped__(**kwargs)


def error_message(err: ValueError, params: Iterable[inspect.Parameter]) -> str:
    """The one-line message for bad input: the library's text, after the flag it concerns."""
    message = " ".join(str(err).split())
    flag = flag_for(getattr(err, "param", None), params)
    if flag is not None and not message.startswith(flag):
        message = f"{flag}: {message}"
    return message


def flag_for(param: str | None, params: Iterable[inspect.Parameter]) -> str | None:
    """The command's option for the library parameter ``param``, or ``None`` (no parameter,
    or a positional argument, which the message already names by its value).

    >>> from scanconv._api.shapes import circle
    >>> from scanconv.cli.options import typer_parameter
    >>> from scanconv.core.declare import declared
    >>> params = [typer_parameter(d) for d in declared(circle)]
    >>> flag_for("xc", params), flag_for("r", params)
    ('--center', None)
    """
    if param is None:
        return None
    by_name = {p.name: p for p in params}
    found = by_name.get(param) or by_name.get(grammar.ALIASES.get(param, ""))
    if found is None:
        return None
    info = next((m for m in get_args(found.annotation)[1:] if isinstance(m, ParameterInfo)), None)
    if not isinstance(info, OptionInfo):
        return None
    # In ``Annotated``, typer keeps an option's first name in ``default``.
    names = [d for d in (info.default, *(info.param_decls or ())) if isinstance(d, str)]
    long = [d.split("/")[0] for d in names if d.startswith("--")]
    return long[0] if long else "--" + found.name.replace("_", "-")
