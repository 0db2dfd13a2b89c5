# The public names of scanconv, for type checkers and at run time: ``scanconv/__init__.py``
# reads this stub to load each name on first use (as skimage's ``lazy.attach_stub`` does), so
# it is the one list of the exports.
from . import questions as questions
from . import raster as raster
from ._api import antialias_circle as antialias_circle
from ._api import antialias_line as antialias_line
from ._api import antialias_polygon as antialias_polygon
from ._api import bezier as bezier
from ._api import bezier_at as bezier_at
from ._api import bspline as bspline
from ._api import bspline_at as bspline_at
from ._api import bspline_basis as bspline_basis
from ._api import char_bitmap as char_bitmap
from ._api import char_storage as char_storage
from ._api import char_stroke as char_stroke
from ._api import circle as circle
from ._api import clip_convex as clip_convex
from ._api import clip_line as clip_line
from ._api import clip_polygon as clip_polygon
from ._api import compare_circles as compare_circles
from ._api import compare_curves as compare_curves
from ._api import compare_lines as compare_lines
from ._api import continuity as continuity
from ._api import dither_diffusion as dither_diffusion
from ._api import dither_lookup as dither_lookup
from ._api import dither_ordered as dither_ordered
from ._api import dither_threshold as dither_threshold
from ._api import ellipse as ellipse
from ._api import fill as fill
from ._api import framebuffer as framebuffer
from ._api import halftone as halftone
from ._api import inside as inside
from ._api import line as line
from ._api import line_style as line_style
from ._api import local_control as local_control
from ._api import parametric_circle as parametric_circle
from ._api import parametric_custom as parametric_custom
from ._api import parametric_ellipse as parametric_ellipse
from ._api import parametric_line as parametric_line
from ._api import parametric_parabola as parametric_parabola
from ._api import pipeline_line as pipeline_line
from ._api import pipeline_polygon as pipeline_polygon
from ._api import polygon as polygon
from ._api import printer as printer
from ._api import project3d as project3d
from ._api import quantize as quantize
from ._api import ramp as ramp
from ._api import sample as sample
from ._api import storage as storage
from ._api import thick_line as thick_line
from ._api import transform as transform
from ._api import transform3d as transform3d
from ._api import viewport as viewport
from ._api import visible_backface as visible_backface
from ._api import visible_depth_sort as visible_depth_sort
from ._api import visible_scanline as visible_scanline
from ._api import visible_warnock as visible_warnock
from ._api import visible_zbuffer as visible_zbuffer
from ._api.color_theory import color as color
from ._api.color_theory import theory as theory
from ._api.generators import basic_line as basic
from ._api.generators import basic_line as basic_line
from ._api.generators import bresenham_circle as bresenham_circle
from ._api.generators import bresenham_line as bresenham
from ._api.generators import bresenham_line as bresenham_line
from ._api.generators import dda_line as dda
from ._api.generators import dda_line as dda_line
from ._api.generators import midpoint_circle as midpoint_circle
from ._api.generators import midpoint_ellipse as midpoint_ellipse
from .algorithms.choices import LineAlgorithm as LineAlgorithm
from .algorithms.choices import Rounding as Rounding
from .algorithms.circle_choices import CircleMethod as CircleMethod
from .algorithms.process_choices import LineClipMethod as LineClipMethod
from .algorithms.process_choices import PolygonClipMethod as PolygonClipMethod
from .answers.primitives.line import line_solution as line_solution
from .core.checks import InputError as InputError
from .core.numeric import round_half_up as round_half_up
from .core.records import Column as Column
from .core.records import Move as Move
from .core.records import Quantity as Quantity
from .core.records import Solution as Solution
from .core.records import Step as Step
from .core.records import Table as Table
from .display import Answer as Answer
from .questions import check as check

__version__: str

__all__ = [
    "Answer",
    "CircleMethod",
    "Column",
    "InputError",
    "LineAlgorithm",
    "LineClipMethod",
    "Move",
    "PolygonClipMethod",
    "Quantity",
    "Rounding",
    "Solution",
    "Step",
    "Table",
    "__version__",
    "antialias_circle",
    "antialias_line",
    "antialias_polygon",
    "basic",
    "basic_line",
    "bezier",
    "bezier_at",
    "bresenham",
    "bresenham_circle",
    "bresenham_line",
    "bspline",
    "bspline_at",
    "bspline_basis",
    "char_bitmap",
    "char_storage",
    "char_stroke",
    "check",
    "circle",
    "clip_convex",
    "clip_line",
    "clip_polygon",
    "color",
    "compare_circles",
    "compare_curves",
    "compare_lines",
    "continuity",
    "dda",
    "dda_line",
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
    "line_solution",
    "line_style",
    "local_control",
    "midpoint_circle",
    "midpoint_ellipse",
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
    "questions",
    "ramp",
    "raster",
    "round_half_up",
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
