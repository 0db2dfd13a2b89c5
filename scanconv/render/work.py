"""The work of an answer, estimated from its arguments alone, and what a row of it costs.

:func:`estimate` reads the arguments of a library function (:mod:`scanconv._api`, by its name
and its parameter names) and returns the :class:`Work` of its answer: the rows of its step
table (or the cells of its matrix), the method whose row cost applies and the parameter that
makes it large. Every library function is either in :data:`ESTIMATES` or in :data:`BOUNDED`
with the reason its answer is small whatever its arguments (``tests/test_budget_entry_points.py``
walks every command and function). The estimates only need to be close and never much below
(an ellipse's rows are counted from its region boundary); an argument the estimate cannot read
is left to the function's own validation.

:data:`COSTS` holds the CPU time of one row, in microseconds, per ``command/method`` and per
format, measured by ``benchmarks/bench_budget.py`` (which prints this table again) on the
project's shared 2-CPU machine under load; :mod:`scanconv.render.budget` turns them into limits.

>>> estimate("line", {"x1": 0, "y1": 0, "x2": 10**6, "y2": 1, "algo": "wu"})
Work(kind='rows', rows=1000001, cols=None, key='line/wu', param='x2', weight=1.0)
>>> estimate("sample", {"size": "4096"}).cols
4096
"""

import math
from collections.abc import Callable, Iterable, Mapping
from fractions import Fraction
from typing import TYPE_CHECKING, Any, NamedTuple

from ..answers.methods import METHODS, method
from ..core import lazy
from ..core.checks import InputError
from ..core.numeric import COORD_LIMIT

if TYPE_CHECKING:
    from ..algorithms import coverage as algorithms_coverage
    from ..algorithms import curve_limits as algorithms_curve_limits
    from ..algorithms import image_limits as algorithms_image_limits
    from ..algorithms import polygon as algorithms_polygon
    from ..answers import asked
    from ..answers import compare as answers_compare
else:  # each estimate's own limits, loaded by its first use
    asked = lazy.module("scanconv.answers.asked")
    algorithms_coverage = lazy.module("scanconv.algorithms.coverage")
    algorithms_curve_limits = lazy.module("scanconv.algorithms.curve_limits")
    algorithms_image_limits = lazy.module("scanconv.algorithms.image_limits")
    algorithms_polygon = lazy.module("scanconv.algorithms.polygon")
    answers_compare = lazy.module("scanconv.answers.compare")


class Work(NamedTuple):
    """The size of an answer: ``rows`` of a step table, or a ``rows`` x ``cols`` matrix."""

    kind: str
    """``"rows"`` or ``"matrix"``."""
    rows: int
    cols: int | None = None
    key: str = ""
    """The ``command/method`` of :data:`COSTS` whose row cost applies."""
    param: str | None = None
    """The parameter that makes the answer this large (for :class:`InputError`)."""
    weight: float = 1.0
    """How many measured rows one row is worth (control points, samples per pixel)."""

    @property
    def size(self) -> int:
        """Rows, or cells of a matrix."""
        return self.rows * (self.cols or 1)


Args = Mapping[str, Any]


class _Beyond(Exception):
    """An argument beyond the function's own input limit: the function refuses it itself,
    naming that limit (a better message than the budget's)."""


def _within(value: float | Fraction, limit: int) -> None:
    if abs(Fraction(value)) > limit:
        raise _Beyond


def _num(a: Args, name: str) -> Fraction:
    """Argument ``name`` as an exact number within the magnitude limit (else InputError)."""
    v = a[name]
    value = Fraction(str(v)) if isinstance(v, (float, str)) else Fraction(v)
    if abs(value) > COORD_LIMIT:
        raise InputError(f"{name} = {v} is out of range (|value| <= {COORD_LIMIT:.0e})", name)
    return value


def _flat(values: Iterable[Any]) -> list[Any]:
    """``[(x, y), ...]`` or ``[x, y, ...]`` as a flat list."""
    out: list[Any] = []
    for v in values:
        if isinstance(v, (tuple, list)):
            out.extend(v)
        else:
            out.append(v)
    return out


def _coords(a: Args, name: str) -> list[Fraction]:
    flat = _flat(a[name])
    return [_num({name: v}, name) for v in flat]


def _choice(a: Args, name: str, default: str) -> str:
    v = a.get(name)
    return default if v is None else str(getattr(v, "value", v))


def _line_rows(a: Args, names: tuple[str, str, str, str]) -> tuple[int, str]:
    x1, y1, x2, y2 = (_num(a, k) for k in names)
    dx, dy = abs(x2 - x1), abs(y2 - y1)
    return math.ceil(max(dx, dy)) + 1, names[2] if dx >= dy else names[3]


def _rows(command: str, name: str, question: Any) -> int:
    """The rows of ``command``'s method ``name`` for ``question``: its record's estimate."""
    return int(method(command, name).load("rows")(question))


def _line(a: Args) -> Work:
    _, param = _line_rows(a, ("x1", "y1", "x2", "y2"))
    algo = _choice(a, "algo", "bresenham")
    x1, y1, x2, y2 = (_num(a, k) for k in ("x1", "y1", "x2", "y2"))
    q = asked.LineQuestion(algo, x1, y1, x2, y2)
    return Work("rows", _rows("line", algo, q), None, "line/" + algo, param)


def _circle(a: Args) -> Work:
    method_name = _choice(a, "method", "midpoint")
    rows = _rows("circle", method_name, asked.CircleQuestion(method_name, int(_num(a, "r"))))
    key = "circle/" + method_name
    weight = max(1.0, rows / GROWING[key]) if key in GROWING else 1.0
    return Work("rows", rows, None, key, "r", weight)


def _ellipse(a: Args) -> Work:
    rx, ry = int(abs(_num(a, "rx"))), int(abs(_num(a, "ry")))
    rows = _rows("ellipse", "midpoint", asked.EllipseQuestion("midpoint", rx, ry))
    return Work("rows", rows, None, "ellipse/midpoint", "rx" if rx >= ry else "ry")


def _wu_rows(a: Args, columns: int) -> int:
    """Two pixels a column, both ends a little more."""
    return 2 * columns + 4


def _subpixel_rows(a: Args, columns: int) -> int:
    """``n`` sub-pixel rows per pixel column (``samples``, 3 by default)."""
    n = int(_num(a, "samples")) if a.get("samples") is not None else 3
    return n * columns + n


_LINE_WALKS: dict[str, Callable[[Args, int], int]] = {
    "antialias_line/wu": _wu_rows,
    "antialias_line/subpixel": _subpixel_rows,
}
"""The antialiased line's methods that walk along the line, by their costs key: their rows from
the line's columns. The others sample the cells of the line's box (:func:`_aa_cells`)."""


def _aa_line(a: Args) -> Work:
    rows, param = _line_rows(a, ("x1", "y1", "x2", "y2"))
    key = "antialias_line/" + _choice(a, "method", "area")
    walk = _LINE_WALKS.get(key)
    if walk is not None:
        return Work("rows", walk(a, rows), None, key, param)
    x1, y1, x2, y2 = (_num(a, k) for k in ("x1", "y1", "x2", "y2"))
    # a strip wider than the one pixel the margin of _aa_cells allows for widens the box
    w = abs(_num(a, "width")) - 1 if a.get("width") is not None else Fraction(0)
    w = w if w > 0 else Fraction(0)
    return _aa_cells(a, "antialias_line", param, abs(x2 - x1) + w, abs(y2 - y1) + w)


def _aa_cells(a: Args, command: str, param: str, width: Fraction, height: Fraction) -> Work:
    """Area sampling and supersampling: a row per pixel of the shape's box (the command
    refuses a box beyond :data:`~scanconv.algorithms.coverage.MAX_AA_CELLS`); a row of N x N
    supersampling costs N^2 samples (measured at N = 16)."""
    key = f"{command}/{_choice(a, 'method', 'area')}"
    cells = min((math.ceil(width) + 2) * (math.ceil(height) + 2), algorithms_coverage.MAX_AA_CELLS)
    weigh = _CELL_WEIGHTS.get(key)
    return Work("rows", cells, None, key, param, 1.0 if weigh is None else weigh(a))


def _supersample_weight(a: Args) -> float:
    """A row of N x N supersampling is N^2 samples (``samples``, 4 by default), measured at
    N = 16."""
    n = int(_num(a, "samples")) if a.get("samples") is not None else 4
    return max(n * n / 256, 1 / 16)


_CELL_WEIGHTS: dict[str, Callable[[Args], float]] = {
    f"antialias_{shape}/supersample": _supersample_weight for shape in ("line", "circle", "polygon")
}
"""The weight of a row of the sampling methods whose row is more than one sample, by costs key
(area sampling: 1)."""


def _aa_circle(a: Args) -> Work:
    d = 2 * abs(_num(a, "r"))
    return _aa_cells(a, "antialias_circle", "r", d, d)


def _aa_polygon(a: Args) -> Work:
    v = _coords(a, "vertices")
    xs, ys = v[0::2], v[1::2]
    return _aa_cells(a, "antialias_polygon", "vertices", max(xs) - min(xs), max(ys) - min(ys))


def _pipeline_line(a: Args) -> Work:
    # the line is clipped and mapped into the viewport: at most the viewport's diagonal, as
    # the line method's record counts its rows (the longer side's, plus one), plus one
    vx0, vy0, vx1, vy1 = _coords(a, "viewport")[:4]
    algo = _choice(a, "algo", "bresenham")
    rows = _rows("line", algo, asked.LineQuestion(algo, vx0, vy0, vx1, vy1)) + 1
    return Work("rows", rows, None, "pipeline_line/" + algo, "viewport")


def _pipeline_polygon(a: Args) -> Work:
    # filled: one row per scan line of the viewport
    vy = _coords(a, "viewport")[1:4:2]
    return Work("rows", math.ceil(abs(vy[1] - vy[0])) + 2, None, "polygon/scan-line", "viewport")


def _samples(
    key: str, default: int = 16, points: str | None = None
) -> Callable[[Args], Work | None]:
    def rows(a: Args) -> Work | None:
        if a.get("t") is not None:  # the curve at one t (``bezier --at``): as BOUNDED's *_at
            return None
        n = a.get("samples")
        count = default if n is None else int(_num(a, "samples"))
        _within(count, algorithms_curve_limits.MAX_SAMPLES)
        weight = 1.0
        if points is not None and a.get(points) is not None:  # a row has a weight per point
            weight = max(1.0, len(_flat(a[points])) / 8)
        return Work("rows", count + 1, None, key, "samples", weight)

    return rows


def _parametric_line(a: Args) -> Work | None:
    if a.get("samples") is None:
        rows, param = _line_rows(a, ("x0", "y0", "x1", "y1"))
        return Work("rows", rows, None, "parametric", param)
    return _samples("parametric")(a)


def _polygon(a: Args) -> Work:
    # one row per scan line of the vertices' y extent (and a few for the edge table)
    v = _coords(a, "vertices")
    xs, ys = v[0::2], v[1::2]
    _within((max(xs) - min(xs) + 1) * (max(ys) - min(ys) + 1), algorithms_polygon.MAX_FILL_CELLS)
    return Work("rows", math.ceil(max(ys) - min(ys)) + 1, None, "polygon/scan-line", "vertices")


def _quantize(a: Args) -> Work:
    bits = int(_num(a, "bits"))
    _within(bits, algorithms_image_limits.MAX_BITS)
    ranged = "/range" if a.get("value_range") else ""
    return Work("rows", 1 << bits if 0 < bits <= 64 else 0, None, "quantize" + ranged, "bits")


def _matrix(default: str) -> Callable[[Args], Work]:
    def cells(a: Args) -> Work:
        size = a.get("size") or default
        if isinstance(size, (tuple, list)):
            m, n = (int(v) for v in size)
        else:
            m, n = algorithms_image_limits.parse_size(str(size))
        return Work("matrix", m, n, "matrix", "size")

    return cells


def _compare_line(a: Args) -> Work:
    rows, param = _line_rows(a, ("x1", "y1", "x2", "y2"))
    _within(rows - 1, answers_compare.MAX_LENGTH)
    return Work("rows", rows, None, "compare_lines", param)


def _line_style(a: Args) -> Work:
    rows, param = _line_rows(a, ("x1", "y1", "x2", "y2"))
    return Work("rows", rows, None, "linestyle/mask", param)


def _thick_line(a: Args) -> Work:
    # a row lists the pixels it adds: the width (replication) or the brush's square
    rows, param = _line_rows(a, ("x1", "y1", "x2", "y2"))
    width = max(1.0, float(_num(a, "width")))
    brush = bool(a.get("brush"))
    weight = width * width / 4 if brush else width / 2
    method = "brush" if brush else "replication"
    return Work("rows", rows, None, "thickline/" + method, param, max(1.0, weight))


def _inside(a: Args) -> Work:
    # an edge table per point: points x edges rows (the command line's words hold both)
    if "words" in a:
        n = len(list(a["words"])) // 2
        rows = (n // 2) * (n - n // 2)
    else:
        rows = (len(list(a["vertices"])) // 2) * (len(list(a["points"])) // 2)
    return Work("rows", max(rows, 1), None, "inside", "points")


def _char_bitmap(a: Args) -> Work:
    # a row per set bit, each listing scale^2 pixels
    rows_text = a.get("rows")
    bits = 35 if rows_text is None else str(rows_text).count("1") + str(rows_text).count("#")
    scale = max(1.0, float(_num(a, "scale") if a.get("scale") is not None else 1))
    return Work("rows", max(bits, 1), None, "char/bitmap", "scale", max(1.0, scale * scale / 8))


# keyword arguments: the keys are library functions' names, and one of them (ramp) is also a
# method's name (image ramp), which tests/test_methods.py would count as a test of a method name
ESTIMATES: dict[str, Callable[[Args], Work | None]] = dict(
    line_style=_line_style,
    thick_line=_thick_line,
    inside=_inside,
    char_bitmap=_char_bitmap,
    line=_line,
    circle=_circle,
    ellipse=_ellipse,
    antialias_line=_aa_line,
    antialias_circle=_aa_circle,
    antialias_polygon=_aa_polygon,
    pipeline_line=_pipeline_line,
    pipeline_polygon=_pipeline_polygon,
    compare_lines=_compare_line,
    quantize=_quantize,
    polygon=_polygon,
    sample=_matrix("8"),
    ramp=_matrix("8"),
    parametric_circle=_samples("parametric"),
    parametric_ellipse=_samples("parametric"),
    parametric_parabola=_samples("parametric"),
    parametric_custom=_samples("parametric"),
    parametric_line=_parametric_line,
    bezier=_samples("curve", points="points"),
    bspline=_samples("curve", points="points"),
    bspline_basis=_samples("curve", points="points"),
    continuity=_samples("curve", points="first"),
    local_control=_samples("curve", points="points"),
)
"""How the size of each library function's answer is estimated, by the function's name."""

BOUNDED: dict[str, str] = {
    "bezier_at": "de Casteljau's levels: at most algorithms.curve_limits.MAX_POINTS rows",
    "bspline_at": "one evaluation: at most algorithms.curve_limits.MAX_POINTS rows",
    "clip_line": "a row per clipping step of one line: a handful of rows",
    "clip_polygon": "four passes over at most answers.process.clip.sutherland_hodgman.MAX_VERTICES edges",
    "compare_curves": "a fixed comparison of the notes' curves",
    "compare_circles": "an octant of r <= answers.compare.MAX_RADIUS = 2000: at most 1,415 rows",
    "transform": "at most answers.process._shared.MAX_POINTS points and answers.process.transform.MAX_TRANSFORMS",
    "viewport": "at most answers.process._shared.MAX_POINTS points",
    "fill": "a row per pixel taken, at most algorithms.seedfill.MAX_SEED_CELLS = 10,000",
    "storage": "closed-form arithmetic on exact integers",
    "color": "one conversion in one table",
    "theory": "a fixed text of the notes",
    "check": "marking: bounded by marking.student_table and marking.mark limits",
    "dither_threshold": "a row per pixel, at most algorithms.dither.MAX_CELLS = 4,096",
    "dither_ordered": "a row per pixel, at most algorithms.dither.MAX_CELLS = 4,096",
    "dither_diffusion": "a row per pixel, at most algorithms.dither.MAX_CELLS = 4,096",
    "dither_lookup": "a row per pixel, at most answers.image.dither.MAX_LOOKUPS = 64",
    "halftone": "n <= algorithms.dither.MAX_ORDER = 16: at most 257 patterns",
    "framebuffer": "closed-form arithmetic on exact integers",
    "printer": "closed-form arithmetic on exact numbers",
    "char_stroke": "at most 4 strokes on a 5 x 7 grid, scaled at most 16 times",
    "char_storage": "closed-form arithmetic on exact integers",
    "clip_convex": "one line against at most algorithms.cyrus_beck.MAX_EDGES = 64 edges",
    "transform3d": "at most answers.process._shared.MAX_POINTS vertices and answers.process.transform.MAX_TRANSFORMS",
    "project3d": "at most answers.process._shared.MAX_POINTS vertices, MAX_TRANSFORMS and one projection",
    "visible_zbuffer": "at most algorithms.visible_zbuffer.MAX_POLYGONS = 8 polygons on MAX_SIDE = 32 squared pixels: 8,192 rows, under rich's 10,000 (4.4 s)",
    "visible_depth_sort": "at most 8 polygons: at most 8 x 8 x 7 pair rows",
    "visible_scanline": "a row per interval of each of at most 32 scan lines, 8 polygons: a few hundred rows",
    "visible_warnock": "a 2^n grid of at most 32 x 32 pixels: at most 1,365 windows",
    "visible_backface": "at most algorithms.visible.MAX_FACES = 24 faces of 16 vertices, a row each",
}
"""The library functions whose answer is small whatever their arguments, and why."""

# The row costs of the commands without a method record, measured in every format of today.
# Each row's csv cost is its base (BASE_COSTS): a format a row does not measure (a new one)
# costs the base times the format's one Spec.row_factor, so a new format adds that one number,
# not one here per row. The measurements of today's formats are kept: the ratio model (csv x
# factor, the factors being the largest ratios of the stepped methods, 8 to 400) costs these
# rows 2 to 320 times what they measure, because their cost is computing, not text (a
# supersampled circle's row: 3,324 us in csv, 4,165 in rich, where the model says 1,330,000),
# and the budget would refuse what it prints today (that circle at 30 rows in rich instead of
# 9,602; a Wu antialiased line at 186,000 rows in json instead of 1,136,000).
# fmt: off
_OTHER_COSTS: dict[str, dict[str, float]] = {
    "antialias_line/wu": {"csv": 26.9, "json": 35.2, "plain": 38.8, "markdown": 41.9, "latex": 37.7, "html": 120.1, "rich": 558},
    # subpixel: timed as scanconv antialias line 0 0 3000 1000 --method subpixel per format
    # (9,003 sub-pixel rows and the pixel table, start-up subtracted); rich estimated
    "antialias_line/subpixel": {"csv": 150, "json": 215, "plain": 385, "markdown": 590, "latex": 490, "html": 1100, "rich": 4000},
    "antialias_line/area": {"csv": 11.2, "json": 9.9, "plain": 8.7, "markdown": 10.6, "latex": 5.1, "html": 17.8, "rich": 75.2},
    "antialias_line/supersample": {"csv": 31.7, "json": 91.7, "plain": 127.8, "markdown": 58.8, "latex": 198, "html": 198, "rich": 3960},
    "antialias_circle/area": {"csv": 7.8, "json": 21.7, "plain": 28.6, "markdown": 23.5, "latex": 22.6, "html": 23.3, "rich": 155.9},
    "pipeline_line/basic": {"csv": 13.5, "json": 47.3, "plain": 48.8, "markdown": 52.9, "latex": 45.8, "html": 112.2, "rich": 721.1},
    "pipeline_line/dda": {"csv": 14.6, "json": 53.4, "plain": 45.9, "markdown": 41.8, "latex": 47.2, "html": 167.6, "rich": 792.6},
    "pipeline_line/bresenham": {"csv": 6.7, "json": 20.8, "plain": 13.7, "markdown": 16.1, "latex": 19.5, "html": 71.6, "rich": 874.4},
    "quantize": {"csv": 0.8, "json": 0.7, "plain": 7.7, "markdown": 19.5, "latex": 19.5, "html": 19.5, "rich": 517.5},
    "quantize/range": {"csv": 19, "json": 22.2, "plain": 33.5, "markdown": 41.2, "latex": 47.6, "html": 4.4, "rich": 1025.6},
    "parametric": {"csv": 50.1, "json": 78.2, "plain": 124.9, "markdown": 100, "latex": 108.5, "html": 167.9, "rich": 1005.3},
    "curve": {"csv": 52.9, "json": 79.9, "plain": 109.3, "markdown": 109.3, "latex": 0.1, "html": 109.3, "rich": 1142.7},
    "compare_lines": {"csv": 132.3, "json": 158.2, "plain": 146.6, "markdown": 193.6, "latex": 144.3, "html": 197, "rich": 931},
    "matrix": {"csv": 1.7, "json": 0.3, "plain": 1.8, "markdown": 14.9, "latex": 22.9, "html": 2.5, "rich": 143.5},
    "antialias_circle/supersample": {"csv": 3323.9, "json": 3015.6, "plain": 3134.8, "markdown": 3131.6, "latex": 3697.6, "html": 2484.7, "rich": 4165.4},
    "antialias_polygon/area": {"csv": 31.5, "json": 13.3, "plain": 41.9, "markdown": 26.8, "latex": 41.8, "html": 49.3, "rich": 305},
    "antialias_polygon/supersample": {"csv": 140.9, "json": 48, "plain": 63.3, "markdown": 20.7, "latex": 61.2, "html": 85.8, "rich": 562.9},
}
# fmt: on
COSTS: dict[str, dict[str, float]] = {
    **{m.key: dict(m.costs) for m in METHODS.values() if m.costs},
    **_OTHER_COSTS,
}
"""CPU microseconds of one row (or matrix cell), per ``command/method`` and format: measured by
``benchmarks/bench_budget.py`` on the project's shared 2-CPU machine under load (the largest
of two runs where there were two; a run that failed, such as a curve beyond its weight limit in
the slower formats, takes the costliest text format's value). A polygon's csv is its edge
table alone (0 us measured: 0.5). The midpoint line, measured in one run, takes the larger of
its and Bresenham's cost (the same walk)."""


BASE_COSTS: dict[str, float] = {
    **{m.key: m.cost for m in METHODS.values() if m.cost},
    **{key: costs["csv"] for key, costs in _OTHER_COSTS.items()},
}
"""Every costs key's base cost (csv microseconds a row: a method record's
:attr:`~scanconv.answers.methods.Method.cost`, the csv column of the other rows): a format its
:data:`COSTS` do not measure costs this times the format's
:attr:`~scanconv.render.Spec.row_factor`."""


GROWING: dict[str, int] = {"circle/symmetric-dda": 1000}
"""Methods whose rows grow as the table goes on, by costs key: beyond this many rows a row
costs in proportion to the rows before it. The symmetric DDA's exact values gain about 2 bits
a step (r = 16383: 15 s and 1.4 GB as html)."""


BYTES: dict[str, dict[str, float]] = {
    "circle/symmetric-dda": {"html": 20_000.0},
}
"""Bytes held in memory per row of weight 1, where a format holds its rows (the html page,
up to :data:`~scanconv.render.html.stepper.MAX_STEPS` of them): measured as the peak resident
size over the rows (``benchmarks/bench_budget.py`` prints the peaks). Other rows: about
3 KB in html (a line's 20,000 rows: 63 MB), and nothing held in the streamed formats."""


def estimate(name: str, arguments: Args) -> Work | None:
    """The size of the answer of library function ``name``, or ``None`` if it is not
    estimated (a function of :data:`BOUNDED`, or arguments the function refuses itself).
    A number beyond the magnitude limit is an :class:`InputError` naming its parameter.

    >>> estimate("ellipse", {"rx": 20000, "ry": 20000}).rows
    28287
    >>> estimate("line", {"x1": "junk"}) is None
    True
    >>> estimate("line", {"x1": 0, "y1": 0, "x2": 10**12, "y2": 1})
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: x2 = 1000000000000 is out of range (|value| <= 1e+09)
    """
    how = ESTIMATES.get(name)
    if how is None:
        return None
    try:
        return how(arguments)
    except InputError as err:
        if "out of range" in str(err):
            raise
        return None
    except (_Beyond, ArithmeticError, KeyError, TypeError, ValueError, IndexError):
        return None  # the function refuses it itself
