"""The commands of the question language, each answered by one function of
:mod:`scanconv._api` whose signature declares its parameters (:mod:`scanconv.core.declare`).

:data:`COMMANDS` names, for each command, that function and the output options it takes;
everything else (its arguments, options, defaults, choices, help) is read from the function.
The command line registers its commands from here (:mod:`scanconv.cli.declared`), the question
grammar is generated from here (``python -m scanconv.questions.generate``) and a question is
answered by calling the function (:func:`scanconv.questions.answering.solve`).
"""

from __future__ import annotations

import functools
import importlib
from collections.abc import Callable
from typing import Any, NamedTuple

NOT_QUESTIONS = ("check", "exam", "mcp", "practice", "sheet", "site")
"""Commands that write documents or mark: never a question."""

PICTURE = "Draw the shaded text picture."
"""The help of ``--grid/--no-grid`` where the grid is the shaded picture (``sample``)."""

OUTPUTS = ("fmt", "grid", "origin", "output", "brief", "exact", "explain", "svg", "png")
"""The output options every command shares, in the order they follow its own."""


class Command(NamedTuple):
    """One command: its words, the library function that answers it, its output options."""

    path: tuple[str, ...]
    api: str
    """The function: ``"shapes.line"`` is :func:`scanconv._api.shapes.line`."""
    figures: bool = False
    """Whether it draws a figure (``--svg``, ``--png``)."""
    grid: bool = True
    """Whether it shows a grid (``--grid/--no-grid``)."""
    origin: bool = True
    """Whether the grid has an orientation (``--origin``)."""
    picture: bool = False
    """Whether the grid is the shaded text picture."""
    ignore_unknown: bool = True
    """Whether a word that looks like an unknown option is a value (``-3``)."""
    name: str = ""
    """What the work budget knows it by, where that is not its words joined."""
    given: tuple[tuple[str, Any], ...] = ()
    """Arguments the command gives the function itself (``fill boundary``: ``method``)."""

    @property
    def function(self) -> str:
        """What the work budget knows it by: its words joined (``parametric_circle``)."""
        return self.name or "_".join(self.path).replace("-", "_")

    @property
    def outputs(self) -> tuple[str, ...]:
        """Its output options, in :data:`OUTPUTS`' order."""
        shown = {"grid": self.grid, "origin": self.grid and self.origin}
        shown |= {"svg": self.figures, "png": self.figures}
        return tuple(name for name in OUTPUTS if shown.get(name, True))

    def declaration(self) -> Callable[..., Any]:
        """The library function whose signature declares the command (its module imported
        now)."""
        module, _, name = self.api.rpartition(".")
        return getattr(importlib.import_module(f"scanconv._api.{module}"), name)  # type: ignore[no-any-return]

    def answerer(self) -> Callable[..., Any]:
        """The function that answers: the public one, ``scanconv._api.NAME`` (the same
        function, looked up by its public name each time)."""
        fn = getattr(importlib.import_module("scanconv._api"), self.api.rpartition(".")[2])
        return functools.partial(fn, **dict(self.given)) if self.given else fn


_ALL = (
    Command(("line",), "shapes.line", figures=True),
    Command(("circle",), "shapes.circle", figures=True),
    Command(("ellipse",), "shapes.ellipse", figures=True),
    Command(("compare", "line"), "shapes.compare_lines"),
    Command(("compare", "circle"), "shapes.compare_circles"),
    Command(("compare", "curves"), "shapes.compare_curves", grid=False, ignore_unknown=False),
    Command(("parametric", "ellipse"), "parametric.parametric_ellipse", figures=True),
    Command(("parametric", "parabola"), "parametric.parametric_parabola", figures=True),
    Command(("parametric", "line"), "parametric.parametric_line", figures=True),
    Command(("parametric", "custom"), "parametric.parametric_custom", figures=True),
    Command(("viewport",), "process.viewport"),
    Command(("clip", "line"), "process.clip_line"),
    Command(("pipeline", "line"), "process.pipeline_line"),
    Command(("pipeline", "polygon"), "process.pipeline_polygon"),
    Command(("polygon",), "areas.polygon", figures=True),
    Command(("antialias", "line"), "areas.antialias_line", figures=True),
    Command(("antialias", "circle"), "areas.antialias_circle", figures=True),
    Command(("antialias", "polygon"), "areas.antialias_polygon", figures=True),
    Command(("fill", "boundary"), "areas.fill", figures=True, given=(("method", "boundary"),)),
    Command(("fill", "flood"), "areas.fill", figures=True, given=(("method", "flood"),)),
    Command(("storage",), "image.storage", grid=False),
    Command(("sample",), "image.sample", picture=True),
    Command(("dither", "threshold"), "dither.dither_threshold", picture=True, origin=False),
    Command(
        ("dither", "floyd-steinberg"),
        "dither.dither_diffusion",
        picture=True,
        origin=False,
        name="dither_diffusion",
    ),
    Command(("framebuffer",), "syllabus.framebuffer", grid=False),
    Command(("linestyle",), "syllabus.line_style", name="line_style"),
    Command(("thickline",), "syllabus.thick_line", name="thick_line"),
    Command(("char", "bitmap"), "syllabus.char_bitmap"),
    Command(("char", "stroke"), "syllabus.char_stroke"),
    Command(("image", "ramp"), "image.ramp", picture=True, origin=False, ignore_unknown=False),
    Command(("3d", "backface"), "visible.visible_backface", grid=False, name="visible_backface"),
    Command(("3d", "zbuffer"), "visible.visible_zbuffer", grid=False, name="visible_zbuffer"),
    Command(("3d", "warnock"), "visible.visible_warnock", grid=False, name="visible_warnock"),
    Command(("3d", "scanline"), "visible.visible_scanline", grid=False, name="visible_scanline"),
    Command(
        ("3d", "depth-sort"), "visible.visible_depth_sort", grid=False, name="visible_depth_sort"
    ),
)

COMMANDS: dict[tuple[str, ...], Command] = {c.path: c for c in _ALL}
"""Every declared command, by its words."""

BY_FUNCTION: dict[str, Command] = {c.function: c for c in _ALL}
"""Every declared command, by its budget name (:attr:`Command.function`)."""
