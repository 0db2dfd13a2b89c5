"""A form per command, written from the question grammar (:mod:`scanconv.questions.grammar_table`),
for those who do not know the syntax: the page's script turns a filled form into the question
(``line 2 2 10 6 --algo dda``) and answers it as if it had been typed.

Each field carries what the script needs in ``data-`` attributes: ``data-flag`` (an option's
flag; none for a positional argument), ``data-off`` (the flag that turns a flag off:
``--no-grid``), ``data-split`` (the value is several words) and ``data-repeat`` (each word
takes the flag again: ``color --to``). Every text from the grammar goes through
:func:`html.escape`.
"""

from __future__ import annotations

from html import escape

from ..questions.grammar import Param, Spec
from ..questions.grammar_table import SPECS

SHOWN = ("grid", "exact", "origin")
"""The shared display options a form offers (the format and the files are the page's)."""


def _label(spec: Spec, p: Param) -> str:
    if not p.opts:
        return p.metavar or p.name.upper()
    return next((o for o in p.opts if o.startswith("--")), p.opts[0])


def _field(spec: Spec, p: Param, index: int) -> str:
    """One parameter's field, labelled with its flag (or its name, if positional)."""
    ident = escape(f"f-{'-'.join(spec.path)}-{index}")
    label = escape(_label(spec, p))
    attrs = [f'id="{ident}"', f'name="{escape(p.name)}"']
    if p.opts:
        attrs.append(f'data-flag="{escape(_label(spec, p))}"')
    if p.kind == "flag":
        attrs.append('type="checkbox"')
        if p.secondary:
            attrs.append(f'data-off="{escape(p.secondary[0])}"')
        if p.default:
            attrs.append("checked data-default")
        return f'<label class="sc-check"><input {" ".join(attrs)}> {label}</label>'
    if p.multiple or p.nargs != 1:
        attrs.append("data-split")
    if p.multiple:
        attrs.append("data-repeat")
    if p.kind == "choice" and not p.multiple:
        default = f"(default: {p.default})" if p.default is not None else "(not given)"
        choices = "".join(f"<option>{escape(c)}</option>" for c in p.choices)
        return (
            f'<label for="{ident}">{label}</label><select {" ".join(attrs)}>'
            f'<option value="">{escape(default)}</option>{choices}</select>'
        )
    hint = _hint(p)
    if p.required:
        attrs.append("required")
    attrs.append(f'placeholder="{escape(hint)}"')
    return (
        f'<label for="{ident}">{label}</label>'
        f'<input type="text" autocomplete="off" spellcheck="false" {" ".join(attrs)}>'
    )


def _hint(p: Param) -> str:
    """The placeholder of a text field: what to type, and the default."""
    if p.multiple and p.choices:
        words = "any of: " + " ".join(p.choices)
    elif p.nargs == -1:
        words = "values separated by spaces"
    elif p.nargs > 1:
        words = f"{p.nargs} values"
    else:
        words = {"number": "a number", "integer": "an integer", "coordinate": "a number"}.get(
            p.kind, "text"
        )
    if p.default is not None and p.default != () and not p.required:
        shown = " ".join(str(v) for v in p.default) if isinstance(p.default, tuple) else p.default
        words += f" (default: {shown})"
    return words


def form(spec: Spec) -> str:
    """The form of one command: a fieldset with a field per parameter it takes.

    >>> html = form(SPECS[("circle",)])
    >>> 'data-command="circle"' in html, 'data-flag="--method"' in html, 'data-off="--no-grid"' in html
    (True, True, True)
    """
    fields = [
        _field(spec, p, i)
        for i, p in enumerate(spec.params)
        if p.name in spec.own or p.name in SHOWN
    ]
    command = escape(" ".join(spec.path))
    return (
        f'<fieldset class="sc-form" data-command="{command}" hidden>'
        f"<legend>{command}</legend>" + "".join(f"<div>{f}</div>" for f in fields) + "</fieldset>"
    )


def forms() -> str:
    """Every command's form, after a list to choose the command from."""
    options = "".join(
        f'<option value="{escape(" ".join(path))}">{escape(" ".join(path))}</option>'
        for path in SPECS
    )
    return (
        '<label for="sc-command">Command</label>'
        f'<select id="sc-command">{options}</select>'
        + "".join(form(spec) for spec in SPECS.values())
    )
