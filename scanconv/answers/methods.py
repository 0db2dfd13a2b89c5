"""One declaration per method: the method records.

Every method of every command is one :class:`Method` record in :data:`METHODS`, keyed
``"command/method"``. A record holds or names (as ``"module:attribute"``, imported on first
use by :meth:`Method.load` through :func:`scanconv.core.lazy.load`, so that reading the
table costs no start-up time):

- ``answer``: the function that builds the worked answer;
- ``generator``: the step generator (an algorithm yielding one step record at a time);
- ``derivation`` and ``pseudocode``: the ``--derive`` and ``--algorithm`` pieces;
- ``model``: the marking model (follow-through marking from any state);
- ``raster``: the bulk rasterizer of :mod:`scanconv.raster`;
- ``costs``: the CPU time of one table row in each format, which the work budget multiplies
  by the number of rows;
- ``knobs``: the conventions that apply (read from
  :data:`scanconv.algorithms.conventions.KNOBS`, where each knob lists its methods).

A piece a method does not have is ``None`` with its reason in ``missing``, so that
``tests/test_methods.py`` can walk every record and fail on a piece that is neither there nor
explained. Asking for a method that has no record raises :class:`InputError` (never a silent
fall-through to another method):

>>> method("line", "dda").title
'DDA line algorithm'
>>> method("line", "midpoint-x")
Traceback (most recent call last):
...
scanconv.core.checks.InputError: unknown line method 'midpoint-x' (choose from basic, dda, bresenham, midpoint, symmetric-dda, wu)
>>> method("circle", "midpoint").knobs
('tie', 'p0', 'loop', 'update')
>>> methods_of("ellipse")
('midpoint',)
"""

from typing import TYPE_CHECKING

from ..core import lazy
from ..core.checks import InputError

if TYPE_CHECKING:
    from ..algorithms import conventions
else:
    conventions = lazy.module("scanconv.algorithms.conventions")  # knobs only

from .record import (
    _NO_MODEL,
    PIECES,
    STEPPED,
    Method,
    checked,
)
from .record import plain_method as _plain

__all__ = ["PIECES", "STEPPED", "Method", "checked", "compared", "method", "methods_of"]

_G = "scanconv.algorithms."

_A = "scanconv.answers.primitives."
_L = _A + "line:"
_LP = _A + "line_pieces:"
_D = "scanconv.answers.theory.derivations:"
_MODELS = "scanconv.marking.models:"
_ERRATA = "scanconv.answers.theory.errata:"

# fmt: off
_LINE = (
    Method(
        command="line", name="basic", title="basic line algorithm (y = mx + c)",
        answer=_L + "basic_answer", generator=_G + "lines:basic",
        derivation=_LP + "basic_derivation", pseudocode=_LP + "basic_pseudocode",
        raster=_G + "raster:line", errata=_ERRATA + "none", rows=_L + "rows",
        cost=16.2, short="basic",
        facts=(("work", "{mnr} = {mnr}1 + m({maj} - {maj}1)"), ("arithmetic", "fractions, rounding")),
        missing=(("model", _NO_MODEL), ("practice", "the practice topic line draws dda and bresenham")),
    ),
    Method(
        command="line", name="dda", title="DDA line algorithm",
        answer=_L + "dda_answer", generator=_G + "lines:dda",
        derivation=_LP + "dda_derivation", pseudocode=_LP + "dda_pseudocode",
        model=_MODELS + "dda_line", raster=_G + "raster:line", errata=_ERRATA + "dda_line",
        practice=_LP + "dda_practice", rows=_L + "rows", cost=20.7, short="DDA",
        facts=(
            ("work", "x += x_inc, y += y_inc"), ("arithmetic", "fractions, rounding"),
            ("heading", "Simple DDA line algorithm"),
        ),
    ),
    Method(
        command="line", name="bresenham", title="Bresenham's line algorithm",
        answer=_L + "bresenham_answer", generator=_G + "lines:bresenham",
        derivation=_LP + "bresenham_derivation", pseudocode=_LP + "bresenham_pseudocode",
        model=_MODELS + "bresenham_line", raster=_G + "raster:line",
        errata=_ERRATA + "bresenham_line", practice=_LP + "bresenham_practice", rows=_L + "rows",
        cost=9.8, short="Bresenham",
        facts=(("work", "p += 2{d} or 2{d} - 2d{maj}"), ("arithmetic", "integers only")),
    ),
    Method(
        command="line", name="midpoint", title="midpoint line algorithm",
        answer=_A + "midpoint_line:midpoint_answer", generator=_G + "midpoint_line:midpoint_line",
        derivation=_A + "midpoint_line:midpoint_derivation", model=_MODELS + "midpoint_line",
        errata=_ERRATA + "none", rows=_L + "rows", cost=9.8,
        missing=(
            ("pseudocode", "Bresenham's loop with d for p (the bresenham method's pseudocode)"),
            ("raster", "raster.line's bresenham gives the same pixels (the default tie)"),
            ("practice", "the practice topic midpoint-line words it itself"),
        ),
    ),
    Method(
        command="line", name="symmetric-dda", title="symmetric DDA line algorithm",
        answer=_L + "dda_answer", generator=_G + "lines:symmetric_dda",
        model=_MODELS + "dda_line", errata=_ERRATA + "none", practice=_LP + "practice",
        rows=_G + "lines:symmetric_dda_rows", cost=28.7, short="sym. DDA",
        facts=(
            ("work", "x += eps d{maj}, y += eps d{mnr}"), ("arithmetic", "fractions 1/2^n, rounding"),
            ("tag", "SDDA"), ("heading", "Symmetric DDA line algorithm"),
            ("steps", r"\text{{steps}} = 2^n,\ 2^{{n-1}} \le \max(|\Delta x|, |\Delta y|) = "
             r"\max({adx}, {ady}) = {longest} < 2^n:\ n = {n},\ \text{{steps}} = 2^{{{n}}} = {steps}"),
        ),
        missing=(
            ("derivation", "the notes give no symmetric DDA line: the steps and increments are its working"),
            ("pseudocode", "the notes give no symmetric DDA line (the DDA's loop, steps = 2^n)"),
            ("raster", "raster.line draws bresenham, dda and basic"),
        ),
    ),
    Method(
        command="line", name="wu", title="Xiaolin Wu's anti-aliased line",
        answer="scanconv.answers.process.antialias.wu:wu_answer", generator=_G + "wu:wu",
        raster="scanconv.raster:line_aa", errata=_ERRATA + "none", rows=_L + "rows", cost=63.3,
        missing=(
            ("derivation", "the notes derive bresenham, dda and basic, not wu"),
            ("pseudocode", "the notes give pseudocode for bresenham, dda and basic, not wu"),
            ("model", "an intensity table: marked on its pixels only"),
            ("practice", "the practice topic antialias words it"),
        ),
    ),
)
# fmt: on

_C = _A + "circle:"
_CP = _A + "circle_pieces:"
_CIRCLE_TITLES = {
    "midpoint": "midpoint circle algorithm (the notes' Bresenham's circle, p0 = 1 - r)",
    "bresenham": "Bresenham's circle algorithm (d0 = 3 - 2r)",
    "polynomial": "polynomial method (y = sqrt(r^2 - x^2))",
    "general": "general method of circle drawing",
    "trig": "trigonometric method (x = r cos t, y = r sin t)",
    "symmetric-dda": "symmetric DDA circle",
}
_CIRCLE_SHORT = {
    "midpoint": "midpoint",
    "bresenham": "Bresenham",
    "polynomial": "polynomial",
    "general": "general",  # the notes' general method: question 30 compares it (issue 39)
    "trig": "trig",
    "symmetric-dda": "sym. DDA",
}
_CIRCLE_TAGS = {
    "general": "general",
    "bresenham": "Bresenham",
    "polynomial": "poly",
    "trig": "trig",
    "symmetric-dda": "SDDA",
}
_CIRCLE_COSTS = {
    "midpoint": 8.7,
    "bresenham": 7.5,
    "polynomial": 10.6,
    "general": 9.1,
    "trig": 24,
    "symmetric-dda": 66.9,
}
_DERIVED = ("midpoint", "general", "bresenham")
"""The circle methods the notes derive (the others' ``--derive`` is the equation's two lines)."""
_MODELLED = ("midpoint", "bresenham", "general")
_NOTED = ("midpoint", "bresenham", "general", "polynomial", "symmetric-dda")
"""The circle methods whose notes' examples have an erratum (docs/errata.md)."""
_PRACTISED = ("midpoint", "bresenham")


def _circle(name: str) -> Method:
    """A circle method's record: every piece named ``<piece>_<method>`` in the circle answer
    (its own derivation and model only where the notes give one)."""
    gen = name.replace("-", "_")
    missing: list[tuple[str, str]] = []
    if name not in _MODELLED:
        missing.append(("model", _NO_MODEL))
    if name not in _PRACTISED:
        missing.append(("practice", "the practice topic circle draws midpoint and bresenham"))
    if name != "midpoint":
        missing.append(("raster", "raster.circle is the midpoint circle"))
    return Method(
        command="circle",
        name=name,
        title=_CIRCLE_TITLES[name],
        answer=_C + f"{gen}_parts",
        generator=_G + f"circles:{gen}",
        derivation=_CP + (f"{gen}_derivation" if name in _DERIVED else "equation_derivation"),
        pseudocode=_CP + f"{gen}_pseudocode",
        model=_MODELS + f"{gen}_circle" if name in _MODELLED else None,
        raster=_G + "raster_conic:circle" if name == "midpoint" else None,
        errata=_ERRATA + (f"{gen}_circle" if name in _NOTED else "none"),
        practice=_CP + f"{gen}_practice" if name in _PRACTISED else None,
        rows=_CP + (f"{gen}_rows" if name in ("trig", "symmetric-dda") else "rows"),
        cost=_CIRCLE_COSTS[name],
        missing=tuple(missing),
        short=_CIRCLE_SHORT.get(name, ""),
        facts=(("tag", _CIRCLE_TAGS[name]),) if name in _CIRCLE_TAGS else (),
    )


_CIRCLE = tuple(_circle(n) for n in _CIRCLE_TITLES)

_E = _A + "ellipse:"
_ELLIPSE = (
    Method(
        command="ellipse",
        name="midpoint",
        title="midpoint ellipse algorithm",
        answer=_E + "midpoint_answer",
        generator=_G + "ellipses:midpoint_ellipse",
        derivation=_E + "midpoint_derivation",
        pseudocode=_E + "midpoint_pseudocode",
        model=_MODELS + "midpoint_ellipse",
        raster=_G + "raster_conic:ellipse",
        errata=_ERRATA + "none",
        practice=_E + "midpoint_practice",
        rows=_E + "rows",
        cost=14,
    ),
)


_CURVES = (
    _plain("bezier", "bernstein", "Bezier curve (Bernstein form)", "scanconv.answers.curves.bezier:bezier_solution",
           _G + "bezier:bezier"),
    _plain("bezier", "de-casteljau", "de Casteljau's construction",
           "scanconv.answers.curves.bezier:bezier_at_solution", _G + "bezier:de_casteljau"),
    _plain("bspline", "cox-de-boor", "B-spline curve (Cox-de Boor)",
           "scanconv.answers.curves.bspline:bspline_solution", _G + "bspline:bspline"),
    _plain("continuity", "bezier-joins", "continuity of joined Bezier segments",
           "scanconv.answers.curves.continuity:continuity_solution", _G + "bezier:bezier"),
    _plain("local-control", "bezier-vs-bspline", "local control: Bezier against B-spline",
           "scanconv.answers.curves.local_control:local_control_solution", _G + "bspline:bspline"),
    *(
        _plain("parametric", kind, f"parametric {kind}", "scanconv.answers.primitives.parametric:parametric_solution",
               _G + "parametric:parametric")
        for kind in ("line", "circle", "ellipse", "parabola", "custom")
    ),
)  # fmt: skip

_CLIP = "scanconv.answers.process.clip."

_PROCESS = (
    _plain("polygon", "scan-line", "scan-line polygon fill", "scanconv.answers.process.fill.scanline:polygon_solution",
           _G + "polygon:scanline_fill", raster="scanconv.raster:polygon"),
    _plain("fill", "boundary", "boundary fill", "scanconv.answers.process.fill.seed:boundary_answer",
           _G + "seedfill:seed_fill"),
    _plain("fill", "flood", "flood fill", "scanconv.answers.process.fill.seed:flood_answer", _G + "seedfill:seed_fill"),
    _plain("antialias", "area", "area sampling", "scanconv.answers.process.antialias.sampling:area_answer",
           _G + "coverage:area_coverage")._replace(facts=(
        ("practice", "anti-aliased by {title} (the line one pixel thick)"),
        ("asks", "the intensity of each pixel the line covers"))),
    _plain("antialias", "supersample", "supersampling", "scanconv.answers.process.antialias.sampling:supersample_answer",
           _G + "coverage:supersample_coverage"),
    _plain("antialias", "wu", "Xiaolin Wu's anti-aliased line", "scanconv.answers.process.antialias.sampling:wu_answer",
           _G + "wu:wu", raster="scanconv.raster:line_aa")._replace(facts=(
        ("practice", "with {title} algorithm"), ("asks", "each column's two pixels and their intensities"))),
    _plain("antialias", "subpixel", "supersampling on a sub-pixel grid (Hearn & Baker)",
           "scanconv.answers.process.antialias.sampling:subpixel_answer", _G + "subpixel:walk")._replace(facts=(
        ("practice", "anti-aliased by supersampling on a 3 x 3 sub-pixel grid (Hearn & Baker)"),
        ("asks", "the sub-pixel decision table and each pixel's count and intensity"))),
    _plain("clip", "cohen-sutherland", "Cohen-Sutherland line clipping",
           _CLIP + "rectangle:cohen_sutherland_answer", _G + "clipping:cohen_sutherland")._replace(
        short="Cohen-Sutherland", stage=_CLIP + "rectangle:cohen_sutherland_clipped"),
    _plain("clip", "liang-barsky", "Liang-Barsky line clipping", _CLIP + "rectangle:liang_barsky_answer",
           _G + "clipping:liang_barsky")._replace(
        short="Liang-Barsky", stage=_CLIP + "rectangle:liang_barsky_clipped"),
    _plain("clip", "cyrus-beck", "Cyrus-Beck line clipping (any convex window)",
           _CLIP + "cyrus_beck:rectangle_solution", _G + "cyrus_beck:cyrus_beck",
           model="cyrus_beck")._replace(
        short="Cyrus-Beck", options=("normals", "ends"), stage=_CLIP + "cyrus_beck:rectangle_clipped"),
    _plain("clip", "midpoint-subdivision", "midpoint subdivision line clipping",
           _CLIP + "midpoint:midpoint_answer", _G + "midpoint_clip:subdivide",
           model="midpoint_clip")._replace(options=("midpoint", "stop")),
    _plain("clip", "nicholl-lee-nicholl", "Nicholl-Lee-Nicholl line clipping",
           _CLIP + "nll:nll_answer", _G + "nll:nicholl_lee_nicholl", model="nll")._replace(
        short="Nicholl-Lee-Nicholl", stage=_CLIP + "nll:nll_clipped"),
    _plain("clip", "weiler-atherton", "Weiler-Atherton polygon clipping (concave polygons)",
           _CLIP + "weiler_atherton:polygon_answer", _G + "weiler_atherton:weiler_atherton"),
    _plain("clip", "sutherland-hodgman", "Sutherland-Hodgman polygon clipping",
           _CLIP + "sutherland_hodgman:polygon_answer", None,
           no_generator="the answer builds its four passes directly"),
    _plain("transform", "composite", "composite 2D transformation",
           "scanconv.answers.process.transform:transform_solution", _G + "transform:compose"),
    _plain("viewport", "window-to-viewport", "window-to-viewport mapping",
           "scanconv.answers.process.viewport:viewport_solution", _G + "transform:map_to_viewport"),
    _plain("pipeline", "line", "the scan-conversion process for a line",
           "scanconv.answers.process.pipeline:pipeline_line_solution", None,
           no_generator="clips, maps and then runs the line's own method"),
    _plain("pipeline", "polygon", "the scan-conversion process for a polygon",
           "scanconv.answers.process.pipeline:pipeline_polygon_solution", None,
           no_generator="clips, maps and then fills with the polygon's own method"),
)  # fmt: skip

_IMAGE = (
    _plain("sample", "uniform", "sampling and quantization", "scanconv.answers.image.sample:sample_solution",
           _G + "sample:sample_levels"),
    _plain("quantize", "uniform", "uniform quantization", "scanconv.answers.image.quantize:quantize_solution", None,
           no_generator="one closed-form row per level"),
    _plain("image", "ramp", "the notes' grayscale ramp", "scanconv.answers.image.ramp:ramp_solution",
           _G + "ramp:ramp"),
    _plain("storage", "formula", "storage requirement", "scanconv.answers.image.storage:storage_solution",
           _G + "storage:storage_bits"),
    *(
        _plain("color", model, f"{model.upper()} colour model", "scanconv.answers.image.color:color_solution",
               None, no_generator="a conversion, worked in one table")._replace(
                   spec=f"scanconv.answers.image.color_models:{model.upper()}")
        for model in ("rgb", "cmy", "hsv", "hsi", "grey")
    ),
)  # fmt: skip

_DITHER = (
    _plain("dither", "threshold", "thresholding", "scanconv.answers.image.dither:threshold_solution",
           _G + "dither:threshold", model="dither_threshold"),
    _plain("dither", "ordered", "ordered dither (Bayer matrix)", "scanconv.answers.image.dither:ordered_solution",
           _G + "dither:ordered", model="dither_ordered"),
    _plain("dither", "lookup", "dither threshold looked up by screen position",
           "scanconv.answers.image.dither:lookup_solution", None,
           no_generator="one closed-form lookup per pixel (algorithms.dither.lookup)", model="dither_lookup"),
    _plain("dither", "floyd-steinberg", "Floyd-Steinberg error diffusion",
           "scanconv.answers.image.dither:diffusion_solution", _G + "dither:error_diffusion",
           model="diffusion"),
    _plain("halftone", "pattern", "halftone patterns", "scanconv.answers.image.dither:pattern_solution", None,
           no_generator="one pattern per level, from the Bayer matrix", model="halftone_patterns", answered_as=("dither", "pattern")),
)  # fmt: skip

_PRINTER = (
    _plain("printer", "halftone", "halftone printing arithmetic (dpi, lpi, cell, levels)",
           "scanconv.answers.image.halftone:printer_solution", None,
           no_generator="arithmetic, worked in one pass", model="printer"),
)  # fmt: skip

_INSIDE = tuple(
    _plain("inside", rule_name, f"inside-outside test ({title})", "scanconv.answers.process.fill.inside:inside_solution",
           _G + "inside:edge_tests", model="inside")._replace(facts=(("practice", wording),))
    for rule_name, title, wording in (("even-odd", "even-odd rule", "the odd-even rule"),
                                      ("nonzero", "nonzero winding rule", "the nonzero winding rule"))
)  # fmt: skip

_FRAMEBUFFER = (
    _plain("framebuffer", "arithmetic", "frame-buffer arithmetic",
           "scanconv.answers.image.framebuffer:framebuffer_solution", None,
           no_generator="arithmetic, worked in one pass", model="framebuffer"),
)  # fmt: skip

_ATTRIBUTES = (
    _plain("linestyle", "mask", "line style from a pixel mask",
           "scanconv.answers.primitives.attributes:line_style_solution", _G + "attributes:styled",
           model="line_style", answered_as=("line", "style")),
    _plain("thickline", "replication", "thick line by pixel replication",
           "scanconv.answers.primitives.attributes:thick_line_solution", _G + "attributes:thick",
           model="thick_line", answered_as=("line", "replication"))._replace(
        facts=(("practice", "pixel replication"),)),
    _plain("thickline", "brush", "thick line by a rectangular brush",
           "scanconv.answers.primitives.attributes:thick_line_solution", _G + "attributes:thick",
           model="thick_line", answered_as=("line", "brush"))._replace(
        facts=(("practice", "a {width} x {width} square brush"), ("words", "--brush"))),
)  # fmt: skip

_CHARACTERS = (
    _plain("char", "bitmap", "bitmap character generation",
           "scanconv.answers.primitives.characters:bitmap_solution", _G + "characters:draw_bitmap",
           model="bitmap_char", answered_as=("characters", "bitmap")),
    _plain("char", "stroke", "stroke character generation",
           "scanconv.answers.primitives.characters:stroke_solution", _G + "characters:draw_strokes",
           model="stroke_char", answered_as=("characters", "stroke")),
    _plain("char", "storage", "bitmap font storage",
           "scanconv.answers.primitives.characters:font_storage_solution", None,
           no_generator="arithmetic, worked in one pass", model="font_storage", answered_as=("characters", "storage")),
)  # fmt: skip

_SPACE = (
    _plain("3d", "transform", "composite 3D transformation (4 x 4 homogeneous)",
           "scanconv.answers.space.transform:transform_solution", _G + "space:compose"),
    *(
        _plain("3d", kind, f"{kind} {'perspective ' if kind.endswith('-point') else ''}projection",
               "scanconv.answers.space.project:project_solution",
               "scanconv.answers.space.project:" + kind.replace("-", "_"))
        for kind in ("orthographic", "oblique", "cavalier", "cabinet", "isometric", "dimetric", "trimetric",
                     "one-point", "two-point", "three-point")
    ),
)  # fmt: skip

_VISIBLE = tuple(  # scanconv 3d: answers.visible.<module>:<fn>_solution, algorithms.<gen>:<fn>
    _plain("3d", name, title, f"scanconv.answers.visible.{mod}:{fn}_solution", f"{_G}{gen}:{fn}")
    for name, title, mod, fn, gen in (
        ("backface", "back-face detection", "backface", "backface", "visible"),
        ("zbuffer", "depth-buffer (z-buffer) method", "zbuffer", "zbuffer", "visible_zbuffer"),
        ("warnock", "Warnock's area subdivision", "warnock", "warnock", "visible_warnock"),
        ("scanline", "scan-line method (visible surfaces)", "scanline", "scanline", "visible_scanline"),
        ("depth-sort", "depth-sort (painter's) method", "depthsort", "depth_sort", "visible_depthsort"),
    )
)  # fmt: skip

# fmt: off
_COSTS: dict[str, dict[str, float]] = {
    "line/basic": {"csv": 16.2, "json": 37.4, "plain": 53.5, "markdown": 41.7, "latex": 61.6, "html": 107.3, "rich": 695.7},
    "line/dda": {"csv": 20.7, "json": 38.7, "plain": 68.1, "markdown": 64.6, "latex": 56, "html": 178.5, "rich": 1072.5},
    "line/bresenham": {"csv": 9.8, "json": 17.5, "plain": 19.5, "markdown": 24, "latex": 15.4, "html": 87.3, "rich": 814.8},
    "line/midpoint": {"csv": 9.8, "json": 17.5, "plain": 19.5, "markdown": 24, "latex": 24.7, "html": 100.5, "rich": 839.9},
    "line/wu": {"csv": 63.3, "json": 79.6, "plain": 102, "markdown": 105.9, "latex": 118.4, "html": 303, "rich": 1339},
    "circle/midpoint": {"csv": 8.7, "json": 66, "plain": 62.2, "markdown": 85.6, "latex": 126.7, "html": 133.5, "rich": 3444.2},
    "circle/bresenham": {"csv": 7.5, "json": 51.7, "plain": 61.9, "markdown": 104.7, "latex": 86.8, "html": 75.4, "rich": 2330.4},
    "circle/polynomial": {"csv": 10.6, "json": 73.7, "plain": 78.1, "markdown": 107.9, "latex": 125.4, "html": 124.5, "rich": 3062.2},
    "circle/general": {"csv": 9.1, "json": 67.4, "plain": 60.9, "markdown": 100.5, "latex": 87.7, "html": 136.2, "rich": 2457.6},
    "circle/trig": {"csv": 24, "json": 81.4, "plain": 123.9, "markdown": 161.5, "latex": 167.3, "html": 214.4, "rich": 3153.1},
    "circle/symmetric-dda": {"csv": 66.9, "json": 162.7, "plain": 256.9, "markdown": 350, "latex": 352, "html": 304, "rich": 2940},
    "ellipse/midpoint": {"csv": 14, "json": 58.3, "plain": 59, "markdown": 45.5, "latex": 50.4, "html": 192.9, "rich": 1753.4},
    "polygon/scan-line": {"csv": 0.5, "json": 192.3, "plain": 258.7, "markdown": 235.5, "latex": 444.4, "html": 83.2, "rich": 1560.5},
}
# fmt: on
"""Each method's measured row costs (see :attr:`Method.costs`), in microseconds: the largest
of two runs of ``benchmarks/bench_budget.py`` on the project's shared 2-CPU machine under
load; the midpoint line takes the larger of its and Bresenham's (the same walk)."""


def _with_costs(m: Method) -> Method:
    """``m`` with its measured row costs; its csv cost is its base cost (stated once)."""
    costs = _COSTS.get(m.key)
    if costs is None:
        return checked(m)
    if m.cost and m.cost != costs["csv"]:
        raise TypeError(f"method record {m.key}: cost {m.cost} is not its csv cost")
    return checked(m._replace(cost=costs["csv"], costs=tuple(costs.items())))


METHODS: dict[str, Method] = {
    m.key: _with_costs(m)
    for m in (
        *_LINE, *_CIRCLE, *_ELLIPSE, *_CURVES, *_PROCESS, *_IMAGE, *_DITHER, *_PRINTER, *_INSIDE,
        *_FRAMEBUFFER, *_ATTRIBUTES, *_CHARACTERS, *_SPACE, *_VISIBLE,
    )
}  # fmt: skip
"""Every method record, by ``"command/method"``."""

_ANSWERED = {m.answered_as or (m.command, m.name): m for m in reversed(METHODS.values())}


DOCUMENTS = {
    "compare": "sets the records of one command's methods side by side",
    "sheet": "a list of questions, each answered by its command's method",
    "practice": "seeded questions over the methods' records",
    "check": "marks a student's table against a method's answer",
    "theory": "the notes' written answers (answers/topics: one Topic record each)",
    "exam": "the notes' exam as a sheet",
    "site": "a static site whose page answers any question with the methods' records",
    "mcp": "a server whose tools answer and mark questions with the methods' records",
}
"""The commands that have no method of their own: they assemble other answers."""


def methods_of(command: str) -> tuple[str, ...]:
    """The method names of ``command``, in declaration order."""
    return tuple(m.name for m in METHODS.values() if m.command == command)


def compared(command: str) -> tuple[str, ...]:
    """The methods ``scanconv compare`` sets side by side, in column order.

    >>> compared("line")
    ('basic', 'dda', 'bresenham', 'symmetric-dda')
    """
    return tuple(m.name for m in METHODS.values() if m.command == command and m.short)


def answered_by(primitive: str, algorithm: str) -> Method | None:
    """The record of an answer labelled ``(primitive, algorithm)`` (``None``: no record's).

    >>> answered_by("line", "replication").key, answered_by("clip", "cyrus-beck").key
    ('thickline/replication', 'clip/cyrus-beck')
    """
    return _ANSWERED.get((primitive, algorithm))


def method(command: str, name: str) -> Method:
    """The record of ``command``'s method ``name``; :class:`InputError` if there is none."""
    record = METHODS.get(f"{command}/{name}")
    if record is None:
        names = methods_of(command)
        if not names:
            raise InputError(f"unknown command {command!r}", "command")
        raise InputError(
            f"unknown {command} method {name!r} (choose from {', '.join(names)})", "method"
        )
    return record
