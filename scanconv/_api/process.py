"""The Python API: the scan-conversion process (``scanconv transform``, ``viewport``, ``clip``, ``pipeline``). See :mod:`scanconv._api`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Annotated, cast

from ..algorithms.choices import LineAlgorithm, LineAlgorithmName
from ..algorithms.process_choices import FillRule, LineClipMethod, PolygonClipMethod
from ..core import lazy
from ..core.checks import InputError
from ..core.declare import Arg, Opt, words
from ..display import answers
from .params import ENDS, NORMALS, VERTICES, VIEWPORT, WINDOW
from .values import NumberLike, PointsLike, _choice, _flat, _numbers, _rect
from .words import clip_convex_words, clip_polygon_words, transform_words

POLYGON_CLIP_METHODS = tuple(m.value for m in PolygonClipMethod)
"""The polygon clipping methods, by name."""

if TYPE_CHECKING:
    from ..answers import asked, methods
    from ..answers.process import pipeline as answers_pipeline
    from ..answers.process import transform as answers_transform
    from ..answers.process import viewport as answers_viewport
    from ..answers.process.clip import cyrus_beck as answers_cyrus_beck
    from ..answers.process.clip import rectangle as answers_clip
    from ..core.choices import (
        ClipEndsName,
        FillRuleName,
        LineClipMethodName,
        MidpointName,
        MidpointStopName,
        NormalsName,
        PolygonClipMethodName,
    )
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    asked = lazy.module("scanconv.answers.asked")
    methods = lazy.module("scanconv.answers.methods")
    answers_clip = lazy.module("scanconv.answers.process.clip.rectangle")
    answers_cyrus_beck = lazy.module("scanconv.answers.process.clip.cyrus_beck")
    answers_pipeline = lazy.module("scanconv.answers.process.pipeline")
    answers_transform = lazy.module("scanconv.answers.process.transform")
    answers_viewport = lazy.module("scanconv.answers.process.viewport")


@answers
@words(
    "The points, then the transformations in the order they are applied.",
    "X1 Y1 ... --TRANSFORMATION ARGS ...",
    transform_words,
)
def transform(
    points: PointsLike,
    transforms: str | Sequence[str],
    inverse: Annotated[
        bool, Opt("--inverse", help="Also show the inverse of the composite matrix.")
    ] = False,
) -> Solution:
    """The composite of 2D transformations applied to points, in homogeneous coordinates
    (``scanconv transform``).

    Parameters
    ----------
    points : sequence of (x, y), or flat numbers
        The points transformed.
    transforms : str or sequence of str
        The transformations in the order applied, as words: ``translate TX TY``,
        ``scale S [SY]``, ``rotate ANGLE``, ``shear SHX SHY`` (each may add ``about X Y``),
        ``reflect x-axis | y-axis | origin | y=x | y=-x | line X1 Y1 X2 Y2``; one string
        separated by commas, or a list. An angle is in degrees (``90``, ``-30``) or radians
        (``pi/4``, ``1.2rad``).
    inverse : bool, default False
        Also show the inverse matrix M⁻¹.

    Returns
    -------
    Answer
        Each matrix with its numbers, the composite ``M = Mn···M1`` (column vectors,
        ``P' = M·P``), and every point before and after (``.data["after"]``).

    Notes
    -----
    sin and cos are exact at multiples of 15 degrees (``√2/2``), otherwise rounded to 6
    decimals (:mod:`scanconv.answers.process.transform`).

    Examples
    --------
    >>> sol = transform([(0, 0), (4, 0)], "rotate 90 about 2 1, translate 3 0")
    >>> sol.data["matrix"]
    [[0, -1, 6], [1, 0, -1], [0, 0, 1]]
    >>> sol.data["after"]
    [[6, -1], [6, 3]]
    """
    return answers_transform.transform_solution(
        _flat(points, "points"), transforms, inverse_too=bool(inverse)
    )


@answers
def viewport(
    window: Annotated[Sequence[NumberLike], WINDOW],
    viewport: Annotated[Sequence[NumberLike], VIEWPORT],
    points: Annotated[
        PointsLike,
        Arg("World points to map (default: the window's four corners).", "[X1 Y1 ...]"),
    ] = (),
) -> Solution:
    """The window-to-viewport mapping of points (``scanconv viewport``).

    Parameters
    ----------
    window : (xmin, ymin, xmax, ymax)
        The window in world coordinates.
    viewport : (xmin, ymin, xmax, ymax)
        The viewport in device coordinates.
    points : sequence of (x, y), or flat numbers, default ()
        The points mapped; none: the window's corners.

    Returns
    -------
    Answer
        The scale ``sx = (xvmax - xvmin) / (xwmax - xwmin)`` (and sy), the translation, the
        composite matrix, and each point mapped (``.data["mapped"]``).

    Examples
    --------
    >>> sol = viewport((0, 0, 10, 10), (100, 100, 150, 200), [(5, 5)])
    >>> sol.data["scale"], sol.data["mapped"]
    ([Fraction(5, 1), Fraction(10, 1)], [[125, 150]])
    """
    return answers_viewport.viewport_solution(
        _flat(points, "points"), _rect(window, "window"), _rect(viewport, "viewport")
    )


@answers
def clip_line(
    x1: Annotated[NumberLike, Arg()],
    y1: Annotated[NumberLike, Arg()],
    x2: Annotated[NumberLike, Arg()],
    y2: Annotated[NumberLike, Arg()],
    window: Annotated[Sequence[NumberLike], WINDOW],
    method: Annotated[
        LineClipMethod | LineClipMethodName, Opt("--method", "-m", help="Line clipping method.")
    ] = "cohen-sutherland",
    *,
    normals: Annotated[NormalsName | None, NORMALS] = None,
    ends: Annotated[ClipEndsName | None, ENDS] = None,
    midpoint: Annotated[
        MidpointName | None,
        Opt(
            "--midpoint",
            help="midpoint-subdivision: each midpoint rounded (default), floored or exact.",
            choices=("rounded", "floor", "exact"),
        ),
    ] = None,
    stop: Annotated[
        MidpointStopName | None,
        Opt(
            "--stop",
            help="midpoint-subdivision: split until one unit long (length, default), or also "
            "stop where a midpoint lands on the window's edge (edge).",
            choices=("length", "edge"),
        ),
    ] = None,
) -> Solution:
    """A segment clipped against a rectangular window (``scanconv clip line``).

    Parameters
    ----------
    x1, y1, x2, y2 : number
        The segment's end points P1 and P2, exact numbers.
    window : (xmin, ymin, xmax, ymax)
        The clipping window, four numbers.
    method : {"cohen-sutherland", "liang-barsky", "cyrus-beck", "midpoint-subdivision", "nicholl-lee-nicholl"} or LineClipMethod, default "cohen-sutherland"
        ``"cohen-sutherland"`` (region codes, bit order T B R L), ``"liang-barsky"`` (the
        parameters u1, u2), ``"cyrus-beck"`` (the rectangle as a convex window),
        ``"midpoint-subdivision"`` or ``"nicholl-lee-nicholl"`` (P1's region, the slope tests).
    normals : {"outward", "inward"}, optional
        Cyrus-Beck only: the edge normals (default outward).
    ends : {"exact", "truncated"}, optional
        Cyrus-Beck only: the clipped end points exact (default) or truncated to integers.
    midpoint : {"rounded", "floor", "exact"}, optional
        Midpoint subdivision only: the midpoint rounded half up (default), floored (the hardware
        shift) or exact.
    stop : {"length", "edge"}, optional
        Midpoint subdivision only: split until a piece is decided or one unit long (default),
        or also stop where a midpoint lands on the window's edge (the piece beyond it is
        outside but for that point, the clipped end), as many published answers do.

    Returns
    -------
    Answer
        The method's working (the region codes and iterations, or the parameter table) and the
        clipped segment, ``.data["clipped"]`` (``None`` when the segment is outside).

    Raises
    ------
    InputError
        A convention given to a method it does not apply to.

    Notes
    -----
    Cohen & Sutherland (1967, in Newman & Sproull), Liang & Barsky (ACM TOG 3(1), 1984),
    Cyrus & Beck (Computers & Graphics 3(1), 1978), midpoint subdivision (Sproull &
    Sutherland's clipping divider, AFIPS FJCC 1968) and Nicholl, Lee & Nicholl (SIGGRAPH '87),
    as Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 6-7, work them, in exact
    fractions.

    Examples
    --------
    >>> clip_line(7, 9, 11, 4, (4, 4, 10, 8)).data["clipped"]
    [[Fraction(39, 5), 8], [10, Fraction(21, 4)]]
    >>> clip_line(7, 9, 11, 4, (4, 4, 10, 8), "liang-barsky").data["clipped"]
    [[Fraction(39, 5), 8], [10, Fraction(21, 4)]]
    >>> clip_line(0, 0, 3, 1, (4, 4, 10, 8)).data["clipped"] is None  # outside
    True
    """
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    rect = _rect(window, "window")
    return answers_clip.clip_line_solution(
        a, b, c, d, rect, _choice(method, "method"),
        normals=normals, ends=ends, midpoint=midpoint, stop=stop,
    )  # fmt: skip


@answers
@words(
    "The segment's end points, then --window-vertices and the convex window's vertices in order.",
    "X1 Y1 X2 Y2 --window-vertices X Y X Y X Y ...",
    clip_convex_words,
)
def clip_convex(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    window: PointsLike,
    *,
    normals: Annotated[NormalsName | None, NORMALS] = None,
    ends: Annotated[ClipEndsName | None, ENDS] = None,
) -> Solution:
    """Cyrus-Beck clipping of a segment against any convex window given by its vertices
    (``scanconv clip convex``).

    Parameters
    ----------
    x1, y1, x2, y2 : number
        The segment's end points P1 and P2, exact numbers.
    window : sequence of (x, y), or flat numbers
        The convex window's vertices, in order.
    normals : {"outward", "inward"}, optional
        The edge normals N (default outward; inward normals flip the sign of every ``N·D``).
    ends : {"exact", "truncated"}, optional
        The clipped end points exact (default) or truncated to integers.

    Returns
    -------
    Answer
        Each edge with its normal N and first vertex E, the values ``N·D``, ``N·(P1 - E)`` and
        t, the entering and leaving t, and ``.data["clipped"]``.

    Notes
    -----
    Cyrus & Beck, "Generalized two- and three-dimensional clipping", Computers & Graphics 3(1),
    1978; Foley, van Dam, Feiner & Hughes, *Computer Graphics*, 2nd ed., §3.12.4.

    Examples
    --------
    >>> clip_convex(-1, 2, 9, 2, [(0, 0), (8, 0), (0, 8)]).data["clipped"]
    [[0, 2], [6, 2]]
    """
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return answers_cyrus_beck.cyrus_beck_solution(
        a, b, c, d, _flat(window, "window"), normals=normals or "outward", ends=ends or "exact"
    )


@answers
@words(
    "The polygon's vertices in order; then, for a window of any shape, --window-vertices and "
    "its vertices in order (convex for Sutherland-Hodgman).",
    "X1 Y1 X2 Y2 X3 Y3 ... [--window-vertices X Y X Y X Y ...]",
    clip_polygon_words,
)
def clip_polygon(
    vertices: PointsLike,
    window: Annotated[
        Sequence[NumberLike] | PointsLike | None,
        Opt(
            "--window",
            "-w",
            metavar="XMIN YMIN XMAX YMAX",
            show_default=False,
            help="A rectangular clipping window in world coordinates (closed: its edges are "
            "inside); or give --window-vertices after the polygon.",
            nargs=4,
        ),
    ] = None,
    method: Annotated[
        PolygonClipMethod | PolygonClipMethodName,
        Opt("--method", "-m", help="Polygon clipping method."),
    ] = "sutherland-hodgman",
) -> Solution:
    """A polygon clipped against a rectangular window, or a polygon window
    (``scanconv clip polygon``).

    Parameters
    ----------
    vertices : sequence of (x, y), or flat numbers
        The polygon's vertices in order.
    window : (xmin, ymin, xmax, ymax), or a polygon's vertices
        The clipping window: four numbers, a rectangle; or three or more vertices (pairs, or
        six or more flat numbers) in order: any convex window for Sutherland-Hodgman (a
        triangle, a hexagon), any simple polygon for Weiler-Atherton.
    method : {"sutherland-hodgman", "weiler-atherton"} or PolygonClipMethod, default "sutherland-hodgman"
        Sutherland-Hodgman (against each edge in turn: left, right, bottom, top; a polygon
        window's edges C1C2, C2C3, ... in order) or Weiler-Atherton (walking the polygon and
        the window, one polygon per piece).

    Returns
    -------
    Answer
        Each stage's input and output vertices; ``.data["clipped"]`` (Sutherland-Hodgman) or
        ``.data["polygons"]`` (Weiler-Atherton).

    Notes
    -----
    Sutherland & Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974; Weiler & Atherton,
    SIGGRAPH 1977; both as Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 6-8.

    Examples
    --------
    >>> clip_polygon([(0, 0), (4, 0), (0, 4)], (1, 1, 3, 3)).data["clipped"]
    [[1, 3], [1, 1], [3, 1]]
    >>> clip_polygon([(0, 0), (8, 0), (8, 8)], (2, 1, 9, 3), "weiler-atherton").data["polygons"]
    [[[8, 1], [8, 3], [3, 3], [2, 2], [2, 1]]]
    >>> clip_polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [(1, -1), (6, 4), (1, 4)]).data["clipped"]
    [[4, 4], [1, 4], [1, 0], [2, 0], [4, 2]]
    """
    name = _choice(method, "method")
    flat = _flat(vertices, "vertices")
    if window is None:
        raise InputError("give the window: four numbers, or a polygon's vertices", "window")
    polygon = isinstance(window, str) or not (
        len(window) == 4 and not isinstance(window[0], tuple | list)
    )
    shape = _flat(window, "window") if polygon else _rect(window, "window")  # type: ignore[arg-type]
    if name not in POLYGON_CLIP_METHODS:
        raise InputError(
            f"unknown polygon clipping method {name!r} ({', '.join(POLYGON_CLIP_METHODS)})",
            "method",
        )
    checked = cast("PolygonClipMethodName", name)  # one of POLYGON_CLIP_METHODS
    q = asked.ClipPolygonQuestion(checked, tuple(flat), tuple(shape), polygon)
    sol: Solution = methods.method("clip", name).load("answer")(q)
    sol.question = q
    return sol


@answers
def pipeline_line(
    x1: Annotated[NumberLike, Arg()],
    y1: Annotated[NumberLike, Arg()],
    x2: Annotated[NumberLike, Arg()],
    y2: Annotated[NumberLike, Arg()],
    window: Annotated[Sequence[NumberLike], WINDOW],
    viewport: Annotated[Sequence[NumberLike], VIEWPORT],
    algo: Annotated[
        LineAlgorithm | LineAlgorithmName, Opt("--algo", "-a", help="Line algorithm.")
    ] = LineAlgorithm.bresenham,
    clip: Annotated[
        LineClipMethod | LineClipMethodName, Opt("--clip", help="Line clipping method.")
    ] = "cohen-sutherland",
) -> Solution:
    """A world-coordinate line through the process: clipped, mapped to the viewport, rounded and
    scan converted (``scanconv pipeline line``).

    Parameters
    ----------
    x1, y1, x2, y2 : number
        The segment's end points P1 and P2, exact numbers.
    window : (xmin, ymin, xmax, ymax)
        The world window.
    viewport : (xmin, ymin, xmax, ymax)
        The device viewport.
    algo : {"bresenham", "dda", "basic", "midpoint"} or LineAlgorithm, default "bresenham"
        The line algorithm of the last stage (not ``"wu"``).
    clip : {"cohen-sutherland", "liang-barsky", "cyrus-beck", "nicholl-lee-nicholl"}, default "cohen-sutherland"
        The clipping method of the first stage (not midpoint subdivision, whose rounded
        midpoints may leave several pieces).

    Returns
    -------
    Answer
        Each stage's working; ``.data`` holds the ``clipped`` segment, its ``device`` coordinates
        and the ``rounded`` end points scan converted.

    Examples
    --------
    >>> sol = pipeline_line(-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10))
    >>> sol.data["clipped"], sol.data["rounded"]
    ([[0, Fraction(5, 2)], [10, Fraction(15, 2)]], [[0, 3], [20, 8]])
    >>> list(sol.pixels())[:4]
    [(0, 3), (1, 3), (2, 4), (3, 4)]
    """
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return answers_pipeline.pipeline_line_solution(
        a,
        b,
        c,
        d,
        _rect(window, "window"),
        _rect(viewport, "viewport"),
        algo=_choice(algo, "algo"),
        clip=_choice(clip, "clip"),
    )


@answers
def pipeline_polygon(
    vertices: Annotated[PointsLike, VERTICES],
    window: Annotated[Sequence[NumberLike], WINDOW],
    viewport: Annotated[Sequence[NumberLike], VIEWPORT],
    fill: Annotated[
        bool, Opt("--fill/--outline", help="Scan-line fill the polygon, or draw its edges.")
    ] = False,
    rule: Annotated[FillRule | FillRuleName, Opt("--rule", help="Fill rule (with --fill).")] = (
        "even-odd"
    ),
) -> Solution:
    """A world-coordinate polygon through the process: clipped by Sutherland-Hodgman, mapped to the
    viewport, then outlined (Bresenham) or scan-line filled (``scanconv pipeline polygon``).

    Parameters
    ----------
    vertices : sequence of (x, y), or flat numbers
        The polygon's vertices in order.
    window : (xmin, ymin, xmax, ymax)
        The world window.
    viewport : (xmin, ymin, xmax, ymax)
        The device viewport.
    fill : bool, default False
        Scan-line fill the polygon instead of drawing its edges.
    rule : {"even-odd", "nonzero"} or FillRule, default "even-odd"
        The fill rule (with ``fill``).

    Returns
    -------
    Answer
        Each stage's working; ``.data`` holds the ``clipped`` and the ``device`` vertices.

    Examples
    --------
    >>> sol = pipeline_polygon([(-2, 0), (6, 0), (2, 6)], (0, 0, 4, 4), (0, 0, 8, 8))
    >>> sol.data["clipped"]
    [[Fraction(10, 3), 4], [Fraction(2, 3), 4], [0, 3], [0, 0], [4, 0], [4, 3]]
    >>> sol.data["device"]
    [[Fraction(20, 3), 8], [Fraction(4, 3), 8], [0, 6], [0, 0], [8, 0], [8, 6]]
    """
    return answers_pipeline.pipeline_polygon_solution(
        _flat(vertices, "vertices"),
        _rect(window, "window"),
        _rect(viewport, "viewport"),
        fill=bool(fill),
        rule=_choice(rule, "rule"),
    )
