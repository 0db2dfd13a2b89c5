"""The command line's vocabulary: the parsers, the choices and the option declarations.

A command's own parameters are declared on its library function (:mod:`scanconv.core.declare`,
turned into typer's declarations by :mod:`scanconv.cli.declared`); the few commands not yet
declared there take the ``Annotated`` aliases below (``points: Points``). Numbers are parsed
by click through :func:`number` and :func:`integer`, so a bad one is refused before the
command runs, naming its option. Formulas (``--at``, ``--t-range``,
``--domain``), sizes (``--size``) and knot vectors (``--knots``) are text the library parses
itself; the API (:mod:`scanconv._api`) takes the same text.

The output options every command shares (``--format``, ``--grid``, ``--origin``, ``--output``,
``--brief``, ``--svg``, ``--png``; ``--explain`` is kept, hidden, as a no-op) are declared at the end and added to each command by
:func:`scanconv.cli.command.answers`.
"""

from __future__ import annotations

from enum import Enum
from fractions import Fraction
from pathlib import Path
from typing import Annotated, Any

import typer
from typer._click.exceptions import NoSuchOption  # typer vendors click
from typer._types import TyperChoice

from ..core.checks import looks_like_option
from ..core.numeric import parse_number
from ..questions.declared import PICTURE
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


# --- values -----------------------------------------------------------------------------------


def num_arg(help: str, metavar: str | None = None) -> Any:
    """A positional exact number with its help (``scanconv char storage --help`` lists it)."""
    return typer.Argument(parser=number, show_default=False, help=help, metavar=metavar)


Points = Annotated[
    list[Fraction],
    typer.Argument(parser=number, metavar="X0 Y0 X1 Y1 ...", help="Control points as x y pairs."),
]
"""Control points ``X0 Y0 X1 Y1 ...``, flat: the API pairs them up."""

Segments = Annotated[
    list[Any],
    typer.Argument(
        parser=coordinate,
        metavar="X0 Y0 ... : X0 Y0 ...",
        help="The control points of the first segment, ':', those of the second.",
    ),
]
"""Two point lists separated by ``:`` (split by :func:`segments`)."""


ORIGIN = (Fraction(0), Fraction(0))
"""The default centre or vertex of a parametric curve."""

CurveCenter = Annotated[
    tuple[Fraction, Fraction], num_option("--center", metavar="X Y", help="Centre (xc, yc).")
]


Samples = Annotated[
    int | None,
    typer.Option(
        "--samples",
        "-n",
        parser=integer,
        help="Steps of t: the curve is tabulated at N + 1 values of t, both ends included "
        "(default 16; parametric line: max(|dx|, |dy|)).",
        show_default=False,
    ),
]
TRange = Annotated[
    tuple[str, str] | None,
    typer.Option(
        "--t-range",
        metavar="T0 T1",
        help="Parameter range; numbers or formulas such as 2*pi (default: the curve's own).",
        show_default=False,
    ),
]
Degree = Annotated[
    int,
    typer.Option(
        "--degree", "-p", parser=integer, help="B-spline degree p (1 <= p <= n, at most 10)."
    ),
]
Knots = Annotated[
    str,
    typer.Option(
        "--knots",
        help="open (clamped uniform), uniform, or an explicit comma list of n + p + 2 values.",
    ),
]

# --- the output options, shared by every command (added by ``answers``) ------------------------

FormatOpt = Annotated[
    Format,
    choice("--format", "-f", help="Output format. auto: rich on a terminal, markdown otherwise."),
]
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
GridOpt = Annotated[bool, typer.Option("--grid/--no-grid", help="Draw the text pixel grid.")]
PictureOpt = Annotated[bool, typer.Option("--grid/--no-grid", help=PICTURE)]
OriginOpt = Annotated[
    Origin,
    choice(
        "--origin",
        help="Grid orientation: bottom-left (y up, as in the notes) or top-left (screen, y down).",
    ),
]
OutputOpt = Annotated[
    Path | None,
    typer.Option(
        "--output",
        "-o",
        help="Write to this file (atomically: complete or not at all) instead of stdout.",
        dir_okay=False,
    ),
]
ExactOpt = Annotated[
    bool,
    typer.Option(
        "--exact",
        help="Show the table's non-integer values as exact fractions (34/27) instead of "
        "3 decimals.",
    ),
]
BriefOpt = Annotated[
    bool,
    typer.Option(
        "--brief",
        help="Leave scanconv's notes (conventions, layout, errata) out, in every format; on a "
        "terminal the working too: just the tables, the pixels and the grid.",
    ),
]
ExplainOpt = Annotated[
    bool,
    typer.Option(
        "--explain",
        hidden=True,
        help="Accepted for old scripts; the working is always shown (see --brief).",
    ),
]
SvgOpt = Annotated[
    Path | None,
    typer.Option(
        "--svg",
        help="Also draw the figure (pixels, ideal primitive, step numbers, axes) as SVG into "
        "this file, atomically.",
        dir_okay=False,
    ),
]
PngOpt = Annotated[
    Path | None,
    typer.Option(
        "--png",
        help="Also draw the figure as PNG into this file (needs Pillow: the png extra).",
        dir_okay=False,
    ),
]
