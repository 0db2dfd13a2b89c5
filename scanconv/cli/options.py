"""The command line's vocabulary: the parsers, the choices and the option declarations.

A command's own parameters are declared on its library function (:mod:`scanconv.core.declare`),
each turned into typer's declaration by :func:`typer_parameter` (:mod:`scanconv.cli.declared`
registers the command); the few commands not yet declared there write typer's declarations
with the helpers below (:func:`num_option`, :func:`choice`). Numbers are parsed
by click through :func:`number` and :func:`integer`, so a bad one is refused before the
command runs, naming its option. Formulas (``--at``, ``--t-range``,
``--domain``), sizes (``--size``) and knot vectors (``--knots``) are text the library parses
itself; the API (:mod:`scanconv._api`) takes the same text.

The output options every command shares (``--format``, ``--grid``, ``--origin``, ``--output``,
``--brief``, ``--exact``, ``--svg``, ``--png``; ``--explain`` is kept, hidden, as a no-op) are
declared once in the library (:func:`scanconv.questions.outputs.outputs`), read by
:func:`shared` and added to each command by :func:`scanconv.cli.command.answers`.
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from enum import Enum
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from typer._click.exceptions import NoSuchOption  # typer vendors click
from typer._types import TyperChoice

from ..core import lazy
from ..core.checks import looks_like_option
from ..core.declare import Arg, Declared, Opt, declared
from ..core.numeric import parse_number
from ..questions.outputs import PICTURE, outputs
from ..render import Format, formats

#: Commands that take numbers as positional arguments accept negative ones (``-3``) too.
NUMERIC_ARGS: dict[str, Any] = {"ignore_unknown_options": True}

# --- parsers ----------------------------------------------------------------------------------


def number(text: str | Fraction | int) -> Fraction:
    """typer parser for an exact number (integer, decimal or a/b); defaults pass through.

    A value that looks like an option (``--bogus`` where a number belongs, which
    ``ignore_unknown_options`` hands over as a value) is click's "No such option".
    """
    if isinstance(text, Fraction | int):  # a default value
        return Fraction(text)
    try:
        return parse_number(text)
    except ValueError as err:
        if looks_like_option(text):
            raise NoSuchOption(text.strip()) from None
        raise typer.BadParameter(str(err)) from None


def integer(text: str | int) -> int:
    """typer parser for a whole number (``16``, ``1e3``); the error names the bad value."""
    if isinstance(text, int):  # a default value
        return text
    value = number(text)
    if value.denominator != 1:
        raise typer.BadParameter(f"{text!r} is not an integer")
    return value.numerator


def coordinate(text: str) -> Fraction | str:
    """typer parser for one value of ``continuity``'s points: a number, or the ``:`` between
    the two segments."""
    return ":" if text.strip() == ":" else number(text)


def choice(*names: str, help: str) -> Any:
    """An option holding one of an enum's values, in any case."""
    return typer.Option(*names, case_sensitive=False, help=help)


def num_option(*names: str, help: str, metavar: str | None = None) -> Any:
    """An option holding exact numbers (one, or a tuple of them)."""
    return typer.Option(*names, parser=number, metavar=metavar, help=help)


# --- choices that only the command line has (the methods are the library's enums) -------------


class Origin(str, Enum):
    """Where the grid's origin is drawn."""

    bottom_left = "bottom-left"
    top_left = "top-left"


def num_arg(help: str, metavar: str | None = None) -> Any:
    """A positional exact number with its help (``scanconv char storage --help`` lists it)."""
    return typer.Argument(parser=number, show_default=False, help=help, metavar=metavar)


# --- a declared parameter as typer takes it ---------------------------------------------------

_PARSERS = {"number": number, "integer": integer, "coordinate": coordinate}
_TYPES: dict[str, Any] = {"number": Fraction, "integer": int, "coordinate": Any}
_TYPES |= {"flag": bool, "text": str}


def _lister(entry: str) -> Callable[[bool], None]:
    """The callback of a flag that lists rows and stops (``Opt(lists=...)``: ``theory
    --list``): each ``(name, description)`` row of ``entry`` on a line, the names aligned."""

    def callback(value: bool) -> None:
        if value:
            rows = lazy.load(entry)()
            width = max(len(name) for name, _ in rows)
            for name, text in rows:
                typer.echo(f"{name.ljust(width)}  {text}")
            raise typer.Exit()

    return callback


def typer_parameter(d: Declared) -> inspect.Parameter:
    """The parameter typer reads for the declared one: its type, its typer declaration and
    the library's default."""
    texts = d.choices if isinstance(d.choices, tuple) else None
    base: Any = d.choices if d.kind == "choice" and not texts else _TYPES.get(d.kind, str)
    options: dict[str, Any] = {"help": d.meta.help or None, "metavar": d.meta.metavar}
    if d.file:  # a file to write: click refuses a folder
        base, options["dir_okay"] = Path, False
    if d.nargs == -1 or getattr(d.meta, "multiple", False):
        base = list[base]
    elif d.nargs > 1:
        base = tuple[(base,) * d.nargs]  # type: ignore[misc]
    if d.optional:
        base = base | None
    if d.kind in _PARSERS:
        options["parser"] = _PARSERS[d.kind]
    if isinstance(d.meta, Arg):
        info = typer.Argument(show_default=False, **options)
    else:
        if texts:
            options["click_type"] = TyperChoice(texts, case_sensitive=False)
        elif d.kind == "choice":
            options["case_sensitive"] = False
        if d.meta.hidden:
            options["hidden"] = True
        if d.meta.lists:
            options |= {"callback": _lister(d.meta.lists), "is_eager": True}
        info = typer.Option(*d.meta.names, show_default=d.meta.show_default, **options)
    return inspect.Parameter(
        d.name,
        inspect.Parameter.KEYWORD_ONLY,
        default=d.default,
        annotation=Annotated[base, info],
    )


# --- the output options, shared by every command (added by ``answers``) ------------------------


@functools.cache
def shared(picture: bool = False) -> dict[str, inspect.Parameter]:
    """The output options every command shares, as typer takes them, read from their one
    declaration (:func:`scanconv.questions.outputs.outputs`); with ``picture``, the grid is
    the shaded text picture."""
    found = {}
    for d in declared(outputs):
        if picture and d.name == "grid" and isinstance(d.meta, Opt):
            d.meta = Opt(*d.meta.names, help=PICTURE)  # a fresh record: declared() builds it
        found[d.name] = typer_parameter(d)
    return found


if TYPE_CHECKING:  # what a hand-written command's parameter holds
    FormatOpt = Format
    OutputOpt = Path | None
    BriefOpt = bool
    ExactOpt = bool
else:  # its typer declaration, the declared one
    FormatOpt, OutputOpt, BriefOpt, ExactOpt = (
        shared()[name].annotation for name in ("fmt", "output", "brief", "exact")
    )

DocumentFormatOpt = Annotated[
    str,
    typer.Option(
        "--format",
        "-f",
        click_type=TyperChoice(("auto", *formats("document")), case_sensitive=False),
        help="Output format; auto: from the --output file's extension, else markdown.",
    ),
]
"""``--format`` of every document command (sheet, exam, practice), declared once: ``auto`` and
the formats :data:`scanconv.render.FORMATS` gives a document writer."""
