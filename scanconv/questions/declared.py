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
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any, NamedTuple

if TYPE_CHECKING:
    from ..core.declare import Declared

from ..core.checks import InputError
from ..core.declare import WORDS, Words
from .outputs import OUTPUTS as OUTPUTS
from .outputs import PICTURE as PICTURE
from .words import UsageError

NOT_QUESTIONS = ("check", "exam", "mcp", "practice", "sheet", "site")
"""Commands that write documents or mark: never a question."""


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
    spread: tuple[str, ...] = ()
    """The function's positional parameters up to its ``*values``, which the command passes
    by position (``color``: ``model``, then the values)."""
    first: tuple[str, ...] = ()
    """Parameters its ``--help`` and grammar list first, where the function's positional
    order differs (``dither ordered``: ``--top`` before ``--matrix``)."""
    no_args_is_help: bool = False
    """Whether the command given no words shows its help (``theory``)."""

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

    def parameters(self) -> tuple[Declared, ...]:
        """The declared parameters of its function (:func:`scanconv.core.declare.declared`),
        :attr:`first` moved ahead of the others after the first."""
        from ..core.declare import declared

        found = declared(self.declaration())
        if not self.first:
            return found
        moved = [d for d in found if d.name in self.first]
        rest = [d for d in found[1:] if d.name not in self.first]
        return (found[0], *moved, *rest)

    def answerer(self) -> Callable[..., Any]:
        """The function that answers: the public one, ``scanconv._api.NAME`` (the same
        function, looked up by its public name each time)."""
        fn = getattr(importlib.import_module("scanconv._api"), self.api.rpartition(".")[2])
        reads = getattr(fn, WORDS, None)  # a free word list first (core.declare.words)
        fn = fn if reads is None else _reading(fn, reads)
        fn = functools.partial(fn, **dict(self.given)) if self.given else fn
        if not self.spread:
            return fn
        *before, star = self.spread

        def spread(**arguments: Any) -> Any:  # ``color MODEL VALUES...``: ``*values``
            head = [arguments.pop(name) for name in before]
            return fn(*head, *arguments.pop(star), **arguments)

        return spread


def _reading(fn: Callable[..., Any], reads: Words) -> Callable[..., Any]:
    """``fn`` called with a command's arguments, its words read by the function's reader
    first: words that do not fit are a :class:`~.words.UsageError`, as the parser's are."""

    def call(words: Sequence[str], **given: Any) -> Any:
        try:
            arguments = reads.read(words, given)
        except InputError as err:
            raise UsageError(str(err), err.param) from None
        return fn(**arguments)

    return call


_ALL = (
    Command(("line",), "shapes.line", figures=True),
    Command(("circle",), "shapes.circle", figures=True),
    Command(("ellipse",), "shapes.ellipse", figures=True),
    Command(("compare", "line"), "shapes.compare_lines"),
    Command(("compare", "circle"), "shapes.compare_circles"),
    Command(("compare", "curves"), "shapes.compare_curves", grid=False, ignore_unknown=False),
    Command(("parametric", "circle"), "parametric.parametric_circle", figures=True),
    Command(("parametric", "ellipse"), "parametric.parametric_ellipse", figures=True),
    Command(("parametric", "parabola"), "parametric.parametric_parabola", figures=True),
    Command(("parametric", "line"), "parametric.parametric_line", figures=True),
    Command(("parametric", "custom"), "parametric.parametric_custom", figures=True),
    Command(("transform",), "process.transform"),
    Command(("bezier",), "curves.bezier", figures=True),
    Command(("bspline",), "curves.bspline", figures=True),
    Command(("continuity",), "curves.continuity", figures=True),
    Command(("local-control",), "curves.local_control"),
    Command(("theory",), "color_theory.theory", ignore_unknown=False, no_args_is_help=True),
    Command(("viewport",), "process.viewport"),
    Command(("clip", "line"), "process.clip_line"),
    Command(("clip", "convex"), "process.clip_convex"),
    Command(("clip", "polygon"), "process.clip_polygon"),
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
    Command(("inside",), "syllabus.inside"),
    Command(("framebuffer",), "syllabus.framebuffer", grid=False),
    Command(("linestyle",), "syllabus.line_style", name="line_style"),
    Command(("thickline",), "syllabus.thick_line", name="thick_line"),
    Command(("char", "bitmap"), "syllabus.char_bitmap"),
    Command(("char", "stroke"), "syllabus.char_stroke"),
    Command(("image", "ramp"), "image.ramp", picture=True, origin=False, ignore_unknown=False),
    Command(("quantize",), "image.quantize", grid=False),
    Command(("color",), "color_theory.color", grid=False, spread=("model", "values")),
    Command(
        ("dither", "ordered"), "dither.dither_ordered", picture=True, origin=False, first=("top",)
    ),
    Command(("dither", "lookup"), "dither.dither_lookup", grid=False),
    Command(("halftone",), "dither.halftone", grid=False),
    Command(("printer",), "dither.printer", grid=False),
    Command(("char", "storage"), "font.char_storage", grid=False),
    # the 3D chapter (answers/space)
    Command(("3d", "transform"), "space.transform3d", grid=False, name="transform3d"),
    Command(("3d", "project"), "space.project3d", figures=True, name="project3d"),
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
