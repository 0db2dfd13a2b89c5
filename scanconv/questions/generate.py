"""The generator of :mod:`.grammar_table`: every command's grammar, a declared one's read
from its library function (:mod:`.declared`), written as the table's source::

    python -m scanconv.questions.generate > scanconv/questions/grammar_table.py

(apart from :mod:`.grammar`, whose records the table is made of, so that the two import in
one direction only)."""

from __future__ import annotations

from ..core.declare import declared
from .grammar import Param, Spec, param_of, spec_of
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
    return {
        path: spec_of(COMMANDS[path], common) if path in COMMANDS else spec
        for path, spec in table.SPECS.items()
    }


def _param_source(p: Param) -> str:
    fields = [repr(p.name), repr(p.opts), repr(p.kind)]
    for field in Param._fields[3:]:
        value = getattr(p, field)
        if value != Param._field_defaults[field]:
            fields.append(f"{field}={value!r}")
    return f"Param({', '.join(fields)})"


def module_text() -> str:
    """The source of :mod:`scanconv.questions.grammar_table`."""
    from .declared import NOT_QUESTIONS, OUTPUTS

    common = shared()
    lines = [
        '"""The grammar of every question command: generated from the library\'s declarations',
        'by ``python -m scanconv.questions.generate`` (do not edit: a test compares)."""',
        "",
        "from fractions import Fraction",
        "",
        "from .grammar import Param, Spec",
        "",
        f"NOT_QUESTIONS = {NOT_QUESTIONS!r}",
        '"""Commands that write documents or mark: never a question."""',
        "",
        f"SHARED = {OUTPUTS!r}",
        '"""The output options every command shares, in the order they follow its own."""',
        "",
        "# fmt: off",
        "S = {",
        *(f"    {name!r}: {_param_source(p)}," for name, p in common.items()),
        "}",
        '"""The shared output options, as most commands take them."""',
        "",
        "_ALL = (",
    ]
    for path, spec in specs().items():
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
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    print(module_text(), end="")
