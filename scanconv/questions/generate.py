"""The generator of :mod:`.grammar_table`: every command's grammar, a declared one's read
from its library function (:mod:`.declared`), written as the table's source::

    python -m scanconv.questions.generate > scanconv/questions/grammar_table.py

(apart from :mod:`.grammar`, whose records the table is made of, so that the two import in
one direction only)."""

from __future__ import annotations

from .grammar import Param, Spec, spec_of


def specs() -> dict[tuple[str, ...], Spec]:
    """Every command's grammar: a declared one's read from its function (the others', not
    yet declared, as the table holds them)."""
    from . import grammar_table as table
    from .declared import COMMANDS

    known = {
        path: spec_of(COMMANDS[path], table.S) if path in COMMANDS else spec
        for path, spec in table.SPECS.items()
    }
    new = {path: spec_of(c, table.S) for path, c in COMMANDS.items() if path not in known}
    return known | new  # a command declared since the table was written comes last


def _param_source(p: Param) -> str:
    fields = [repr(p.name), repr(p.opts), repr(p.kind)]
    for field in Param._fields[3:]:
        value = getattr(p, field)
        if value != Param._field_defaults[field]:
            fields.append(f"{field}={value!r}")
    return f"Param({', '.join(fields)})"


def module_text() -> str:
    """The source of :mod:`scanconv.questions.grammar_table`."""
    from . import grammar_table as table
    from .declared import NOT_QUESTIONS, OUTPUTS

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
        *(f"    {name!r}: {_param_source(p)}," for name, p in table.S.items()),
        "}",
        '"""The shared output options, as most commands take them."""',
        "",
        "SPECS: dict[tuple[str, ...], Spec] = {",
    ]
    for path, spec in specs().items():
        params = [
            f"S[{p.name!r}]" if table.S.get(p.name) == p else _param_source(p) for p in spec.params
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
