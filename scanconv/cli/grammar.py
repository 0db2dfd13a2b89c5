"""The question language as the command line reads it: every answering command's
parameters, read back from the click commands typer builds, in the form of
:mod:`scanconv.questions.grammar`.

The library parses questions without typer from its table (generated from the library's
declarations: ``python -m scanconv.questions.generate``); this module reads the same table out
of the command line as it is built, so a test (``tests/test_questions_files.py``) fails when
the command line and the questions would read a word differently.
"""

from __future__ import annotations

from typing import Any

import typer

from ..questions.grammar import Param, Spec, default_text
from .application import app, register
from .command import Command


def _kind(param: Any) -> tuple[str, tuple[str, ...]]:
    """The grammar's kind of a click parameter, and its choices."""
    kind_of = {"number": "number", "integer": "integer", "coordinate": "coordinate"}
    ptype = param.type
    if type(ptype).__name__ == "Tuple":
        ptype = ptype.types[0]
    name = type(ptype).__name__
    if name == "FuncParamType":
        return kind_of[ptype.func.__name__], ()
    if name == "TyperChoice":
        return "choice", tuple(ptype.choices)
    if getattr(param, "is_flag", False):
        return "flag", ()
    return "text", ()


def _param(param: Any, ctx: Any) -> Param:
    kind, choices = _kind(param)
    is_option = param.param_type_name == "option"
    return Param(
        name=param.name,
        opts=tuple(param.opts) if is_option else (),
        kind=kind,
        nargs=param.nargs,
        required=param.required,
        default=None if param.default is None else default_text(param.default),
        choices=choices,
        secondary=tuple(param.secondary_opts) if is_option else (),
        multiple=bool(getattr(param, "multiple", False)),
        metavar="" if is_option else param.get_error_hint(ctx)[1:-1],
        help=" ".join((getattr(param, "help", None) or "").split()),
    )


def _walk(group: typer.Typer, path: tuple[str, ...]) -> Any:
    """``(path, command info)`` of every command under ``group``."""
    for info in group.registered_commands:
        name = info.name or typer.main.get_command_name(info.callback.__name__)  # type: ignore[union-attr]
        yield (*path, name), info
    for sub in group.registered_groups:
        if sub.typer_instance is not None and sub.name:
            yield from _walk(sub.typer_instance, (*path, sub.name))


def declared() -> tuple[dict[tuple[str, ...], Spec], tuple[str, ...]]:
    """The answering commands' grammar, by command path, and the commands that are not
    questions (they write documents or mark: ``sheet``, ``check``, ...)."""
    register(None)
    specs: dict[tuple[str, ...], Spec] = {}
    others: list[str] = []
    for path, info in _walk(app, ()):
        callback = info.callback
        if not isinstance(callback, Command):
            others.append(path[0])
            continue
        command = typer.main.get_command_from_info(
            info, pretty_exceptions_short=True, rich_markup_mode=None
        )
        ctx = command.make_context(path[-1], ["--help"], resilient_parsing=True)
        params = tuple(_param(p, ctx) for p in command.params if p.name != "help")
        own = tuple(callback.own)
        specs[path] = Spec(
            path=path,
            function=callback.__name__,
            params=params,
            own=own,
            ignore_unknown=bool(command.context_settings.get("ignore_unknown_options")),
            no_args_is_help=bool(command.no_args_is_help),
        )
    return specs, tuple(sorted(others))
