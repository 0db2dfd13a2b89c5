"""The generator of :mod:`.grammar_table`: every command's grammar, a declared one's read
from its library function (:mod:`.declared`), written as the table's source::

    python -m scanconv.questions.generate > scanconv/questions/grammar_table.py

(apart from :mod:`.grammar`, whose records the table is made of, so that the two import in
one direction only)."""

from __future__ import annotations

from collections.abc import Callable

from ..core.declare import declared
from .grammar import Param, Spec, param_of, spec_of, values
from .outputs import outputs


def shared() -> dict[str, Param]:
    """The shared output options as the grammar takes them, read from their declaration
    (:func:`scanconv.questions.outputs.outputs`)."""
    return {d.name: param_of(d) for d in declared(outputs)}


def specs() -> dict[tuple[str, ...], Spec]:
    """Every command's grammar: a declared one's read from its function (the others', not
    yet declared, as the table holds them)."""
    from . import grammar_table as table
    from .declared import COMMANDS

    common = shared()
    out = {
        path: spec_of(COMMANDS[path], common) if path in COMMANDS else spec
        for path, spec in table.SPECS.items()
    }
    # a command declared since the table was last written joins it at the end
    return out | {path: spec_of(c, common) for path, c in COMMANDS.items() if path not in out}


def _enums(path: tuple[str, ...]) -> dict[str, str]:
    """A declared command's parameters that the library types by an enum: ``name`` to the
    enum as ``"module:Class"`` (the table reads their choices from it, :func:`values`)."""
    from .declared import COMMANDS

    if path not in COMMANDS:
        return {}
    return _enum_names(COMMANDS[path].declaration())


def _enum_names(fn: Callable[..., object]) -> dict[str, str]:
    """``fn``'s parameters typed by an enum: ``name`` to the enum as ``"module:Class"``."""
    from enum import Enum

    return {
        d.name: f"{d.choices.__module__}:{d.choices.__qualname__}"
        for d in declared(fn)
        if isinstance(d.choices, type) and issubclass(d.choices, Enum)
    }


def _param_source(p: Param, enum: str | None = None) -> str:
    fields = [repr(p.name), repr(p.opts), repr(p.kind)]
    for field in Param._fields[3:]:
        value = getattr(p, field)
        if field == "choices" and enum is not None and value == values(enum):
            fields.append(f"choices=values({enum!r})")
        elif value != Param._field_defaults[field]:
            fields.append(f"{field}={value!r}")
    return f"Param({', '.join(fields)})"


def module_text() -> str:
    """The source of :mod:`scanconv.questions.grammar_table`."""
    from .declared import NOT_QUESTIONS, OUTPUTS

    common = shared()
    shared_enums = _enum_names(outputs)  # --format: render.Format, read when the table loads
    lines = [
        '"""The grammar of every question command: generated from the library\'s declarations',
        'by ``python -m scanconv.questions.generate`` (do not edit: a test compares)."""',
        "",
        "from fractions import Fraction",
        "",
        "from .grammar import Param, Spec, values",
        "",
        f"NOT_QUESTIONS = {NOT_QUESTIONS!r}",
        '"""Commands that write documents or mark: never a question."""',
        "",
        f"SHARED = {OUTPUTS!r}",
        '"""The output options every command shares, in the order they follow its own."""',
        "",
        "# fmt: off",
        "S = {",
        *(
            f"    {name!r}: {_param_source(p, shared_enums.get(name))},"
            for name, p in common.items()
        ),
        "}",
        '"""The shared output options, as most commands take them."""',
        "",
        "_ALL = (",
    ]
    for path, spec in specs().items():
        enums = _enums(path)
        params = [
            f"S[{p.name!r}]" if common.get(p.name) == p else _param_source(p, enums.get(p.name))
            for p in spec.params
        ]
        rows: list[list[str]] = []  # in the command's order, the shared ones run on one line
        for s in params:
            if rows and s.startswith("S[") and rows[-1][-1].startswith("S["):
                rows[-1].append(s)
            else:
                rows.append([s])
        flags = f", no_args_is_help={spec.no_args_is_help!r}" if spec.no_args_is_help else ""
        lines += [
            f"    Spec({path!r}, {spec.function!r}, (",
            *(f"        {', '.join(row)}," for row in rows),
            f"    ), own={spec.own!r}, ignore_unknown={spec.ignore_unknown!r}{flags}),",
        ]
    lines += [
        ")",
        "# fmt: on",
        "",
        "SPECS: dict[tuple[str, ...], Spec] = {spec.path: spec for spec in _ALL}",
        '"""Every question command\'s grammar, by its words."""',
    ]
    text = "\n".join(lines) + "\n"
    if "Fraction(" not in text:  # no default is a fraction: the import would be unused
        text = text.replace("from fractions import Fraction\n\n", "", 1)
    return text


if __name__ == "__main__":
    print(module_text(), end="")
