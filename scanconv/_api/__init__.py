"""The Python API: one function per command of the command line, each returning an
:class:`~scanconv.display.Answer` (a :class:`~scanconv.core.records.Solution` that shows
itself).

The keywords are the library's parameter names; the choices are strings or the library's enums
(:class:`LineAlgorithm`, :class:`CircleMethod`, :class:`Rounding`). A number may be an ``int``,
a :class:`~fractions.Fraction`, a ``float`` (read as the decimal it prints as, so ``0.1`` is
exactly 1/10, as on the command line) or a string (``"5/2"``, ``"-3"``, ``"1e3"``); a formula
parameter (``t``, ``t_range``, ``domain``, ``value_range`` of :func:`sample`) also takes a
constant expression such as ``"2*pi"``. Bad input raises
:class:`~scanconv.core.checks.InputError` (a ``ValueError``) naming the parameter where this
module finds it, and the library's ``ValueError`` otherwise.

Render a solution with :func:`scanconv.render.render`, or read it directly:

>>> sol = circle(5, method="bresenham")
>>> [step.pixel for step in sol.steps()]
[(0, 5), (1, 5), (2, 5), (3, 4)]

The library modules are imported inside the functions: importing this module stays cheap.
"""

from __future__ import annotations

from typing import Any

from ..algorithms.choices import LineAlgorithm, Rounding
from .areas import antialias_circle, antialias_line, antialias_polygon, fill, polygon
from .curves import (
    bezier,
    bezier_at,
    bspline,
    bspline_at,
    bspline_basis,
    continuity,
    local_control,
    parametric_circle,
    parametric_custom,
    parametric_ellipse,
    parametric_line,
    parametric_parabola,
)
from .image import quantize, ramp, sample, storage
from .process import (
    clip_convex,
    clip_line,
    clip_polygon,
    pipeline_line,
    pipeline_polygon,
    transform,
    viewport,
)
from .shapes import circle, compare_circles, compare_curves, compare_lines, ellipse, line
from .syllabus import (
    char_bitmap,
    char_storage,
    char_stroke,
    dither_diffusion,
    dither_ordered,
    dither_threshold,
    framebuffer,
    halftone,
    inside,
    line_style,
    thick_line,
)
from .values import FormulaLike as FormulaLike
from .values import NumberLike as NumberLike
from .values import PointLike as PointLike
from .values import PointsLike as PointsLike
from .values import TRangeLike as TRangeLike

__all__ = [
    "CircleMethod",
    "LineAlgorithm",
    "LineClipMethod",
    "PolygonClipMethod",
    "Rounding",
    "antialias_circle",
    "antialias_line",
    "antialias_polygon",
    "bezier",
    "bezier_at",
    "bspline",
    "bspline_at",
    "bspline_basis",
    "char_bitmap",
    "char_storage",
    "char_stroke",
    "circle",
    "clip_convex",
    "clip_line",
    "clip_polygon",
    "compare_circles",
    "compare_curves",
    "compare_lines",
    "continuity",
    "dither_diffusion",
    "dither_ordered",
    "dither_threshold",
    "ellipse",
    "fill",
    "framebuffer",
    "halftone",
    "inside",
    "line",
    "line_style",
    "local_control",
    "parametric_circle",
    "parametric_custom",
    "parametric_ellipse",
    "parametric_line",
    "parametric_parabola",
    "pipeline_line",
    "pipeline_polygon",
    "polygon",
    "quantize",
    "ramp",
    "sample",
    "storage",
    "thick_line",
    "transform",
    "viewport",
]


#: API functions defined in this package's submodules, by name -> submodule; loaded on first
#: use (start-up time). One line per function, grouped by submodule. A submodule is never named
#: after a function it holds: importing ``scanconv._api.color`` would bind the module, not the
#: function, to ``_api.color`` (hence ``color_theory``). ``check``, which takes a question in
#: scanconv's own words, is :func:`scanconv.questions.check`, a layer above.
SUBMODULE_OF: dict[str, str] = {
    "color": "color_theory",
    "theory": "color_theory",
}

__all__ += sorted(SUBMODULE_OF)


def __getattr__(name: str) -> Any:
    """The circle, clipping and filling choices and the submodules' functions, loaded on first
    use (start-up time)."""
    if name in SUBMODULE_OF:
        import importlib

        return getattr(importlib.import_module(f"{__name__}.{SUBMODULE_OF[name]}"), name)
    if name in ("LineClipMethod", "PolygonClipMethod", "AAMethod", "FillRule", "Order"):
        from ..algorithms import process_choices

        return getattr(process_choices, name)
    if name in ("CircleMethod", "P0", "Loop", "Update"):
        from ..algorithms import circle_choices

        return getattr(circle_choices, name)
    raise AttributeError(f"module 'scanconv._api' has no attribute {name!r}")
