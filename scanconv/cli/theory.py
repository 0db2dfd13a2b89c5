"""``scanconv theory``: the model answer to a define / explain / describe question of the notes,
with a live example."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from .. import _api as api
from ..core import lazy
from ..core.records import Solution
from .application import app
from .command import answers

if TYPE_CHECKING:
    from ..answers.theory import topics
else:
    topics = lazy.module("scanconv.answers.theory.topics")  # --list only


def _list(value: bool) -> None:
    if value:
        found = topics.topics()
        width = max(len(t.name) for t in found)
        for t in found:
            typer.echo(f"{t.name.ljust(width)}  {t.title}")
        raise typer.Exit()


@app.command(no_args_is_help=True)
@answers(grid=True)
def theory(
    topic: Annotated[
        str,
        typer.Argument(
            metavar="TOPIC",
            help="The question's topic: scan-conversion, raster-display, rgb-model, dda, "
            "symmetry, bezier, ... (--list names them all).",
        ),
    ],
    list_: Annotated[
        bool,
        typer.Option(
            "--list",
            callback=_list,
            is_eager=True,
            help="List the topics, one a line (name, then the question), and stop.",
        ),
    ] = False,
) -> Solution:
    """The model answer to a theory question of the notes, with a live example.

    Definition, key points, the notes' tables, advantages and limitations, and an example
    computed by scanconv (a grid, a step table, a pixel's bits).
    Example: scanconv theory raster-display
    """
    return api.theory(topic)
