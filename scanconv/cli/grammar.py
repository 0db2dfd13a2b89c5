"""The question language as the command line declares it: every answering command's
parameters, read from the typer app, in the form of :mod:`scanconv.questions.grammar`.

The library parses questions without typer from that module's table; this one rebuilds the
table from the command line's own declarations, so a test (``tests/test_questions_files.py``)
fails when the two differ, and ``python -m scanconv.cli.grammar`` prints the module to paste::

    python -m scanconv.cli.grammar > scanconv/questions/grammar_table.py
"""

from __future__ import annotations

import inspect
from enum import Enum
from typing import Any

import typer

from ..questions.grammar import Param, Spec
from .application import app, register
from .command import SHARED, Command


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


def _default(value: Any) -> Any:
    if isinstance(value, Enum):
        return value.value
    if isinstance(value, list | tuple):
        return tuple(_default(v) for v in value)
    return value


def _param(param: Any, ctx: Any) -> Param:
    kind, choices = _kind(param)
    is_option = param.param_type_name == "option"
    return Param(
        name=param.name,
        opts=tuple(param.opts) if is_option else (),
        kind=kind,
        nargs=param.nargs,
        required=param.required,
        default=None if param.default is None else _default(param.default),
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
        own = tuple(inspect.signature(callback.__wrapped__).parameters)
        specs[path] = Spec(
            path=path,
            function=callback.__name__,
            params=params,
            own=own,
            ignore_unknown=bool(command.context_settings.get("ignore_unknown_options")),
            no_args_is_help=bool(command.no_args_is_help),
        )
    return specs, tuple(sorted(others))


def _param_source(p: Param) -> str:
    fields = [repr(p.name), repr(p.opts), repr(p.kind)]
    for field in Param._fields[3:]:
        value = getattr(p, field)
        if value != Param._field_defaults[field]:
            fields.append(f"{field}={value!r}")
    return f"Param({', '.join(fields)})"


def module_text() -> str:
    """The source of :mod:`scanconv.questions.grammar_table`."""
    specs, others = declared()
    common: dict[str, Param] = {}
    for spec in specs.values():  # the shared options as most commands declare them
        for p in spec.params:
            if p.name in SHARED and p.name not in spec.own:
                common.setdefault(p.name, p)
    lines = [
        '"""The grammar of every question command: generated from the command line\'s',
        'declarations by ``python -m scanconv.cli.grammar`` (do not edit: a test compares)."""',
        "",
        "from fractions import Fraction",
        "",
        "from .grammar import Param, Spec",
        "",
        f"NOT_QUESTIONS = {others!r}",
        '"""Commands that write documents or mark: never a question."""',
        "",
        f"SHARED = {SHARED!r}",
        '"""The output options every command shares, in the order they follow its own."""',
        "",
        "# fmt: off",
        "S = {",
        *(f"    {name!r}: {_param_source(p)}," for name, p in common.items()),
        "}",
        '"""The shared output options, as most commands take them."""',
        "",
        "SPECS: dict[tuple[str, ...], Spec] = {",
    ]
    for path, spec in specs.items():
        params = [
            f"S[{p.name!r}]" if common.get(p.name) == p else _param_source(p) for p in spec.params
        ]
        rows: list[list[str]] = []  # in the command's order, the shared ones run on one line
        for s in params:
            if rows and s.startswith("S[") and rows[-1][-1].startswith("S["):
                rows[-1].append(s)
            else:
                rows.append([s])
        flags = f", no_args_is_help={spec.no_args_is_help!r}" if spec.no_args_is_help else ""
        lines += [
            f"    {path!r}: Spec({path!r}, {spec.function!r}, (",
            *(f"        {', '.join(row)}," for row in rows),
            f"    ), own={spec.own!r}, ignore_unknown={spec.ignore_unknown!r}{flags}),",
        ]
    lines += ["}", "# fmt: on"]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    print(module_text(), end="")
