"""What a valid question can say, listed for a model forming one: the commands with their
arguments and options, the methods, the conventions and the presets (each read from the
library's own tables: the grammar, :data:`scanconv.algorithms.conventions.KNOBS` and
:data:`~scanconv.algorithms.conventions.PRESETS`)."""

from __future__ import annotations

from typing import Any

from ..algorithms.conventions import KNOBS, PRESETS, SOURCES
from ..practice.notes import DIFFICULTIES, TOPICS
from ..questions.grammar import Param, Spec
from ..questions.grammar_table import SHARED, SPECS
from ..site.page import EXAMPLES

GRAMMAR = (
    "A question is a scanconv command line without 'scanconv': the command's words, its "
    "positional arguments in order, then options (--algo bresenham). Numbers may be "
    "integers, decimals or fractions (5/2); a point is two numbers (2 2 or 2,2). The "
    "conventions (--tie, --start, --rounding, ...) and --convention PRESET choose a "
    "textbook's rules; the defaults are the course notes'."
)

_TAKES = {"number": "a number", "integer": "an integer", "coordinate": "a number or ':'"}
_METHOD_PARAMS = ("algo", "method")
_SHOWN_SHARED = ("grid", "brief", "exact")
"""The shared options that change what an answer shows (the others choose a format or a
file, which the server's answers do not take)."""


def _takes(p: Param) -> str:
    if p.kind == "flag":
        return "nothing (a flag)"
    if p.kind == "choice":
        return "a choice"
    one = _TAKES.get(p.kind, "a word")
    if p.nargs == -1:
        return f"any number of words: {one} each"
    return one if p.nargs == 1 else f"{p.nargs} words: {one} each"


def _option(p: Param) -> dict[str, Any]:
    option: dict[str, Any] = {"flags": list(p.opts + p.secondary), "takes": _takes(p)}
    if p.choices:
        option["choices"] = list(p.choices)
    if p.default is not None and p.kind != "flag":
        option["default"] = p.default if isinstance(p.default, (int, str)) else str(p.default)
    return option


def _command(spec: Spec) -> dict[str, Any]:
    positional = [
        (p.metavar or p.name.upper()) + ("..." if p.nargs == -1 else "")
        for p in spec.params
        if not p.opts
    ]
    options = [
        _option(p)
        for p in spec.params
        if p.opts and (p.name not in SHARED or p.name in spec.own or p.name in _SHOWN_SHARED)
    ]
    usage = " ".join([*spec.path, *positional])
    return {"command": " ".join(spec.path), "usage": f"{usage} [OPTIONS]", "options": options}


def vocabulary() -> dict[str, Any]:
    """The commands, methods, conventions and presets of the question language.

    >>> v = vocabulary()
    >>> v["methods"]["line"][:3]  # the line records' names, in the enum's order
    ['bresenham', 'dda', 'basic']
    >>> next(k for k in v["conventions"] if k["name"] == "tie")["default"]
    'step'
    """
    methods = {
        " ".join(spec.path): list(p.choices)
        for spec in SPECS.values()
        for p in spec.params
        if p.name in _METHOD_PARAMS and p.choices
    }
    theory = SPECS[("theory",)]
    return {
        "grammar": GRAMMAR,
        "examples": list(EXAMPLES),
        "commands": [_command(spec) for spec in SPECS.values()],
        "methods": methods,
        "conventions": [
            {
                "name": k.name,
                "flag": f"--{k.name}",
                "values": dict(k.values),
                "default": k.default,
                "applies_to": list(k.applies),
            }
            for k in KNOBS.values()
        ],
        "presets": [
            {"name": name, "source": SOURCES[name], "values": values}
            for name, values in PRESETS.items()
        ],
        "theory_topics": list(next(p.choices for p in theory.params if p.name == "topic")),
        "practice_topics": [*TOPICS, "all"],
        "practice_difficulties": list(DIFFICULTIES),
    }


def vocabulary_text(v: dict[str, Any]) -> str:
    """:func:`vocabulary` as Markdown, for a host that reads only text."""
    out = ["# scanconv's question language", "", v["grammar"], "", "## Examples", ""]
    out += [f"- `{e}`" for e in v["examples"]]
    out += ["", "## Commands", ""]
    for c in v["commands"]:
        flags = ", ".join(
            o["flags"][0] + (f" {'|'.join(o['choices'])}" if "choices" in o else "")
            for o in c["options"]
        )
        out.append(f"- `{c['usage']}`" + (f": {flags}" if flags else ""))
    out += ["", "## Conventions (the notes' default first)", ""]
    for k in v["conventions"]:
        values = "; ".join(f"{name}: {meaning}" for name, meaning in k["values"].items())
        out.append(f"- `{k['flag']}` (default {k['default']}): {values}")
    out += ["", "## Presets (`--convention NAME`)", ""]
    out += [f"- `{p['name']}`: {p['source']}" for p in v["presets"]]
    out += ["", "Theory topics: " + ", ".join(v["theory_topics"])]
    out += ["Practice topics: " + ", ".join(v["practice_topics"])]
    return "\n".join(out) + "\n"
