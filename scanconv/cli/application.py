"""The typer application: the root group, its sub-groups and ``--version``.

The commands are defined by topic in :mod:`.lines`, :mod:`.image`, :mod:`.curves`,
:mod:`.circles` and :mod:`.compare`, which register themselves here (imported at the end, in
the order of the command list of ``scanconv --help``).
"""

from __future__ import annotations

from typing import Annotated, Any

import typer

from .. import __version__
from .output import PROG

_SETTINGS: dict[str, Any] = {
    "add_completion": False,
    "rich_markup_mode": None,
    "no_args_is_help": True,
    "context_settings": {"help_option_names": ["-h", "--help"]},
}

app = typer.Typer(
    name=PROG,
    help="Scan-conversion algorithms as exam-style worked solutions: the derivation, the step "
    "table, the pixels and a pixel grid. Coordinates are (x, y) with y up.",
    pretty_exceptions_enable=False,
    **_SETTINGS,
)


def _subapp(name: str, help: str) -> typer.Typer:
    """A group of commands under ``scanconv NAME``."""
    sub = typer.Typer(help=help, **_SETTINGS)
    app.add_typer(sub, name=name)
    return sub


image_app = _subapp("image", "Image representation examples from the notes.")
compare_app = _subapp(
    "compare", "Every method for one primitive side by side, with the reason wherever they differ."
)
parametric_app = _subapp(
    "parametric",
    "Parametric curves x(t), y(t): line, circle, ellipse, parabola or your own formulas.",
)


def _version(value: bool) -> None:
    if value:
        print(f"{PROG} {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: Annotated[
        bool,
        typer.Option("--version", callback=_version, is_eager=True, help="Show the version."),
    ] = False,
) -> None:
    """Scan-conversion algorithms as exam-style worked solutions."""


# Register the commands (each module adds its own to ``app`` and the groups above).
from . import lines, image, curves, circles, compare  # noqa: E402, F401, I001
