"""The typer application: the root group, its sub-groups and ``--version``.

The commands are defined by topic in :mod:`.lines`, :mod:`.image`, :mod:`.curves`,
:mod:`.circles` and :mod:`.compare`, which register themselves here (imported at the end, in
the order of the command list of ``scanconv --help``).
"""

from __future__ import annotations

import re
from typing import Annotated, Any

import typer
from typer.core import TyperGroup

from .. import __version__
from ..core import lazy
from .output import PROG

_SETTINGS: dict[str, Any] = {
    "add_completion": False,
    "rich_markup_mode": None,
    "no_args_is_help": True,
    "context_settings": {"help_option_names": ["-h", "--help"]},
}

#: The panels of ``scanconv --help``: each command under the topic of the notes it answers.
PANELS = (
    (
        "Lines, circles and ellipses",
        ("line", "circle", "ellipse", "parametric", "linestyle", "thickline", "char"),
    ),
    ("Curves", ("bezier", "bspline", "continuity", "local-control")),
    (
        "Image representation",
        ("image", "storage", "quantize", "sample", "dither", "halftone", "printer", "framebuffer"),
    ),
    ("Comparisons", ("compare",)),
    ("Teaching", ("sheet", "practice", "check", "mcp")),
    (
        "The process: clip, transform, fill, anti-alias",
        (
            "clip",
            "transform",
            "viewport",
            "pipeline",
            "polygon",
            "inside",
            "fill",
            "antialias",
        ),
    ),
    ("Theory and exam", ("color", "theory", "exam", "site")),
    ("3D: transformations, projections, visible surfaces", ("3d",)),
)

EXAMPLES = """\b
Examples:
  scanconv line 2 2 10 6 --algo bresenham      the worked answer on the terminal
  scanconv line 2,2 10,6 -f md >> homework.md  append it to your Markdown homework
  scanconv circle 8 -o circle.tex              LaTeX, the format taken from the name
  scanconv ellipse 8 6 --brief                 tables, pixels and grid only
  scanconv compare circle 10                   every circle method side by side
  scanconv COMMAND --help                      the options of one command"""


def _first_sentence(text: str) -> str:
    """The first sentence of a command's help, whole (click would cut it at 45 characters).

    >>> _first_sentence("Draw the line. Then more.")
    'Draw the line.'
    """
    flat = " ".join(text.split("\n\n")[0].split())
    end = re.search(r"(?<!\.)\.\s", flat)
    return flat if end is None else flat[: end.start() + 1]


class PanelGroup(TyperGroup):
    """The root group, listing its commands in :data:`PANELS`, one full sentence each."""

    def format_commands(self, ctx: Any, formatter: Any) -> None:
        commands = {
            name: cmd
            for name in self.list_commands(ctx)
            if (cmd := self.get_command(ctx, name)) is not None and not cmd.hidden
        }
        placed: set[str] = set()
        for title, names in (*PANELS, ("Other commands", tuple(commands))):
            rows = [
                (n, _first_sentence(commands[n].help or commands[n].short_help or ""))
                for n in names
                if n in commands and n not in placed
            ]
            placed.update(n for n, _ in rows)
            if rows:
                with formatter.section(title):
                    formatter.write_dl(rows)


app = typer.Typer(
    name=PROG,
    cls=PanelGroup,
    epilog=EXAMPLES,
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
clip_app = _subapp(
    "clip", "Clip a line or a polygon against a rectangular window, or a line against a convex one."
)
dither_app = _subapp(
    "dither", "Two-level images by thresholding, ordered dither or error diffusion."
)
char_app = _subapp(
    "char", "Character generation: a bitmap glyph, a stroke character, a bitmap font's storage."
)
pipeline_app = _subapp(
    "pipeline", "The scan-conversion process end to end: clip, map to the viewport, scan convert."
)
three_d_app = _subapp(
    "3d",
    "The 3D chapter: transformations in homogeneous coordinates (4 x 4), projections and "
    "visible-surface detection (back faces, z-buffer, scan line, depth sort, Warnock).",
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


#: The command modules, in the order of ``scanconv --help``; each registers its commands on
#: ``app`` and the groups above when it is imported.
TOPIC_MODULES: tuple[str, ...] = (
    "lines",
    "image",
    "curves",
    "circles",
    "compare",
    "process",
    "fill",
    "syllabus",
    "halftone",
    "color",
    "theory",
    "exam",
    "sheet",
    "practice",
    "check",
    "site",
    "serve",
    "three_d",
)

#: Which module defines each top-level command or group.
TOPIC_OF = {
    "line": "lines",
    "image": "image",
    "storage": "image",
    "quantize": "image",
    "sample": "image",
    "parametric": "curves",
    "bezier": "curves",
    "bspline": "curves",
    "continuity": "curves",
    "local-control": "curves",
    "circle": "circles",
    "ellipse": "circles",
    "compare": "compare",
    "clip": "process",
    "transform": "process",
    "viewport": "process",
    "pipeline": "process",
    "polygon": "fill",
    "fill": "fill",
    "antialias": "fill",
    "dither": "syllabus",
    "halftone": "halftone",
    "printer": "halftone",
    "inside": "syllabus",
    "framebuffer": "syllabus",
    "linestyle": "syllabus",
    "thickline": "syllabus",
    "char": "syllabus",
    "sheet": "sheet",
    "check": "check",
    "practice": "practice",
    "color": "color",
    "theory": "theory",
    "exam": "exam",
    "site": "site",
    "mcp": "serve",
    "3d": "three_d",
}


def register(argv: list[str] | None = None) -> typer.Typer:
    """Import the command modules ``argv`` needs and return :data:`app`: only the one that
    defines ``argv[0]`` (start-up time: a run loads no other command's options), every one
    for help, ``--version`` or a name that is not a command (``None``: every one).

    >>> register(["line", "2", "2", "10", "6"]) is app
    True
    """
    named = TOPIC_OF.get(argv[0]) if argv else None
    for module in TOPIC_MODULES if named is None else (named,):
        lazy.load(f"{__package__}.{module}")
    return app
