# The names of scanconv._api, for type checkers and at run time: ``_api/__init__.py`` reads this
# stub to load each name on first use (the mechanism of ``scanconv/__init__.py``), so importing
# one command's function does not import every other command's module.
from ..algorithms.choices import LineAlgorithm as LineAlgorithm
from ..algorithms.choices import Rounding as Rounding
from ..algorithms.circle_choices import P0 as P0
from ..algorithms.circle_choices import CircleMethod as CircleMethod
from ..algorithms.circle_choices import Loop as Loop
from ..algorithms.circle_choices import Update as Update
from ..algorithms.process_choices import AAMethod as AAMethod
from ..algorithms.process_choices import FillRule as FillRule
from ..algorithms.process_choices import LineClipMethod as LineClipMethod
from ..algorithms.process_choices import Order as Order
from ..algorithms.process_choices import PolygonClipMethod as PolygonClipMethod
from .areas import antialias_circle as antialias_circle
from .areas import antialias_line as antialias_line
from .areas import antialias_polygon as antialias_polygon
from .areas import fill as fill
from .areas import polygon as polygon
from .color_theory import color as color
from .color_theory import theory as theory
from .curves import bezier as bezier
from .curves import bezier_at as bezier_at
from .curves import bspline as bspline
from .curves import bspline_at as bspline_at
from .curves import bspline_basis as bspline_basis
from .curves import continuity as continuity
from .curves import local_control as local_control
from .dither import dither_diffusion as dither_diffusion
from .dither import dither_lookup as dither_lookup
from .dither import dither_ordered as dither_ordered
from .dither import dither_threshold as dither_threshold
from .dither import halftone as halftone
from .dither import printer as printer
from .font import char_storage as char_storage
from .image import quantize as quantize
from .image import ramp as ramp
from .image import sample as sample
from .image import storage as storage
from .parametric import parametric_circle as parametric_circle
from .parametric import parametric_custom as parametric_custom
from .parametric import parametric_ellipse as parametric_ellipse
from .parametric import parametric_line as parametric_line
from .parametric import parametric_parabola as parametric_parabola
from .process import clip_convex as clip_convex
from .process import clip_line as clip_line
from .process import clip_polygon as clip_polygon
from .process import pipeline_line as pipeline_line
from .process import pipeline_polygon as pipeline_polygon
from .process import transform as transform
from .process import viewport as viewport
from .shapes import circle as circle
from .shapes import compare_circles as compare_circles
from .shapes import compare_curves as compare_curves
from .shapes import compare_lines as compare_lines
from .shapes import ellipse as ellipse
from .shapes import line as line
from .space import project3d as project3d
from .space import transform3d as transform3d
from .syllabus import char_bitmap as char_bitmap
from .syllabus import char_stroke as char_stroke
from .syllabus import framebuffer as framebuffer
from .syllabus import inside as inside
from .syllabus import line_style as line_style
from .syllabus import thick_line as thick_line
from .values import FormulaLike as FormulaLike
from .values import NumberLike as NumberLike
from .values import PointLike as PointLike
from .values import PointsLike as PointsLike
from .values import TRangeLike as TRangeLike
from .visible import visible_backface as visible_backface
from .visible import visible_depth_sort as visible_depth_sort
from .visible import visible_scanline as visible_scanline
from .visible import visible_warnock as visible_warnock
from .visible import visible_zbuffer as visible_zbuffer

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
    "color",
    "compare_circles",
    "compare_curves",
    "compare_lines",
    "continuity",
    "dither_diffusion",
    "dither_lookup",
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
    "printer",
    "project3d",
    "quantize",
    "ramp",
    "sample",
    "storage",
    "theory",
    "thick_line",
    "transform",
    "transform3d",
    "viewport",
    "visible_backface",
    "visible_depth_sort",
    "visible_scanline",
    "visible_warnock",
    "visible_zbuffer",
]
