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

import re
from html import escape

from ..questions.grammar import Param, Spec
from ..questions.grammar_table import SPECS

SHOWN = ("grid", "exact", "origin")
"""The shared display options a form offers (the format and the files are the page's)."""


def _flag(spec: Spec, p: Param) -> str:
    """The flag a field stands for (``--algo``), or a positional argument's name (``X1``)."""
    if not p.opts:
        return p.metavar or p.name.upper()
    return next((o for o in p.opts if o.startswith("--")), p.opts[0])


_SCOPE = re.compile(r"([a-z][\w-]*(?:, [a-z][\w-]*)*): (.+)")
"""A help text that starts with the methods it is for: ``midpoint: p0 printed as ...``."""

_FORMULA = re.compile(r"\S+ = ")
_KEEP_BRACKETS = ("to", "at", "of", "in", "from", "is")
"""Words a bracket that ends the sentence completes (``Move control point P_I to (X, Y).``)."""


def _last(text: str, i: int) -> bool:
    """The bracket opened at ``text[i]`` ends the sentence."""
    depth = 0
    for j in range(i, len(text)):
        depth += (text[j] == "(") - (text[j] == ")")
        if depth == 0:
            return text[j + 1 :].strip() in ("", ".")
    return False


def _first_clause(text: str) -> str:
    """``text`` up to its first ``:``, ``;``, ``.`` or ``,`` outside brackets (a comma before
    a digit is a list: ``order 2, 4, 8``), without the brackets that add to it (``The octant
    (region-1) loop``: "The octant loop").

    >>> _first_clause("f(x, y), e.g. 'x + y'"), _first_clause("The octant (region-1) loop: strict")
    ('f(x, y)', 'The octant loop')
    """
    out, aside = "", 0
    for i, c in enumerate(text):
        kept = out.rstrip().rsplit(" ", 1)[-1] in _KEEP_BRACKETS and _last(text, i)
        if not aside and c == "(" and out.endswith(" ") and not kept:
            aside = 1
            continue
        if aside:
            aside += (c == "(") - (c == ")")
            continue
        ends = text[i + 1 : i + 2] in (" ", "")
        if (
            out.count("(") == out.count(")")
            and ends
            and (c in ":;." or (c == "," and not text[i + 2 : i + 3].isdigit()))
        ):
            break
        out += c
    return " ".join(out.split())


def _name(p: Param) -> str:
    return (p.opts[0].lstrip("-") if p.opts else p.name).replace("-", " ").replace("_", " ")


def words(spec: Spec, p: Param) -> str:
    """A field's label in words, read off the command line's help text for it: its first
    clause (``Line algorithm.``: "Line algorithm"); where the help starts with the methods it
    is for (``midpoint: p0 printed as ...``), starts with a formula or a choice (``d = 2F(M)``,
    ``even-odd, nonzero winding``) or is only the letter, the option's name ("p0, for
    midpoint"), or the clause after the letter (``N, the halftone cell's width``); ``""``
    without a help text.

    >>> from scanconv.questions.grammar_table import SPECS
    >>> circle = SPECS[("circle",)]
    >>> [words(circle, q) for q in circle.params if q.name in ("r", "center", "method", "p0", "loop")]
    ['The radius r', 'Centre', 'Circle method', 'p0, for midpoint', 'The octant loop']
    >>> words(SPECS[("halftone",)], SPECS[("halftone",)].params[0])
    "The halftone cell's width"
    """
    if not p.help:
        return ""
    text, scope = p.help, ""
    m = _SCOPE.fullmatch(text)
    if m is not None:
        named = set(m.group(1).split(", "))
        others = {c for q in spec.params if q is not p for c in q.choices}
        scope, text = (m.group(1) if named <= others else ""), ""
    first = _first_clause(text)
    if (len(first) <= 2 or first in (p.metavar, p.name)) and ", " in text:
        first = _first_clause(text.split(", ", 1)[1])
    choice = first.split(" ", 1)[0].lower() in p.choices or (first.islower() and " " not in first)
    if not first or _FORMULA.match(first) or choice or len(first) <= 2:
        first = _name(p)
    if first.split(" ", 1)[0].isalpha() and len(first.split(" ", 1)[0]) > 1:
        first = first[0].upper() + first[1:]
    return f"{first}, for {scope}" if scope else first


def _label(spec: Spec, p: Param) -> str:
    """A field's label: its words and its flag (``Line algorithm (--algo)``)."""
    said = words(spec, p)
    flag = f"<code>{escape(_flag(spec, p))}</code>"
    return f"{escape(said)} ({flag})" if said else flag


def _field(spec: Spec, p: Param, index: int) -> str:
    """One parameter's field, labelled with its flag (or its name, if positional)."""
    ident = escape(f"f-{'-'.join(spec.path)}-{index}")
    label = _label(spec, p)
    attrs = [f'id="{ident}"', f'name="{escape(p.name)}"']
    if p.help:
        attrs.append(f'title="{escape(p.help)}"')
    if p.opts:
        attrs.append(f'data-flag="{escape(_flag(spec, p))}"')
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
