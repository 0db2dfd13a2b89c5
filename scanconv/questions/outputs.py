"""The output options every command shares, declared once (:mod:`scanconv.core.declare`).

:func:`outputs` is a declaration, not a command: its signature is each shared option's type,
flags, help and default. The command line turns it into typer's options
(:mod:`scanconv.cli.options`) and the grammar's generator into the table's shared parameters
(:mod:`.generate`), so a flag, a help text or a default is written here alone; ``--format``
takes the :class:`~scanconv.render.Format` enum's values (``auto`` and every format of
:data:`scanconv.render.FORMATS` that writes a single answer: a test holds the two together).

(Its annotations are evaluated once, at import: no ``from __future__ import annotations``, so
reading the declaration at start-up evaluates nothing.)

>>> OUTPUTS
('fmt', 'grid', 'origin', 'output', 'brief', 'exact', 'explain', 'svg', 'png')
"""

from pathlib import Path
from typing import Annotated, Literal

from ..core.declare import Opt
from ..render import Format

PICTURE = "Draw the shaded text picture."
"""The help of ``--grid/--no-grid`` where the grid is the shaded picture (``sample``)."""


def outputs(
    fmt: Annotated[
        Format,
        Opt("--format", "-f", help="Output format. auto: rich on a terminal, markdown otherwise."),
    ] = Format.auto,
    grid: Annotated[bool, Opt("--grid/--no-grid", help="Draw the text pixel grid.")] = True,
    origin: Annotated[
        Literal["bottom-left", "top-left"],
        Opt(
            "--origin",
            help="Grid orientation: bottom-left (y up, as in the notes) or top-left (screen, "
            "y down).",
            choices=("bottom-left", "top-left"),
        ),
    ] = "bottom-left",
    output: Annotated[
        Path | None,
        Opt(
            "--output",
            "-o",
            help="Write to this file (atomically: complete or not at all) instead of stdout.",
        ),
    ] = None,
    brief: Annotated[
        bool,
        Opt(
            "--brief",
            help="Leave scanconv's notes (conventions, layout, errata) out, in every format; "
            "on a terminal the working too: just the tables, the pixels and the grid.",
        ),
    ] = False,
    exact: Annotated[
        bool,
        Opt(
            "--exact",
            help="Show the table's non-integer values as exact fractions (34/27) instead of "
            "3 decimals.",
        ),
    ] = False,
    explain: Annotated[
        bool,
        Opt(
            "--explain",
            hidden=True,
            help="Accepted for old scripts; the working is always shown (see --brief).",
        ),
    ] = False,
    svg: Annotated[
        Path | None,
        Opt(
            "--svg",
            help="Also draw the figure (pixels, ideal primitive, step numbers, axes) as SVG "
            "into this file, atomically.",
        ),
    ] = None,
    png: Annotated[
        Path | None,
        Opt(
            "--png",
            help="Also draw the figure as PNG into this file (needs Pillow: the png extra).",
        ),
    ] = None,
) -> None:
    """The shared output options: a declaration to read, never called."""


OUTPUTS: tuple[str, ...] = outputs.__code__.co_varnames[: outputs.__code__.co_argcount]
"""The output options every command shares, in the order they follow its own."""
